//! Going on at a looser tolerance where the corrector fails
//! (`Pull::relax_to`): loops left in the rod that slide along it stall
//! Newton above the default corrector's tolerance; the pull goes on from its
//! last point at ten times the tolerance, keeping every point before it.
//!
//! The scene: n = 6 at (89.5°, A/B = 100, ν = 0.05) stretched to
//! Δz = 0.99. The default ends with `CorrectorDrifted` after four pop-outs;
//! the committed n = 6 diagram (fold continuation to cusps, another method)
//! counts five there.

use std::cell::RefCell;
use std::ops::ControlFlow;
use std::rc::Rc;

use hockle::continuation::{Continuation, Observer, Point, Termination};
use hockle::rod::{PhaseDiagram, Pull, Rod};
use hockle::spring::RodModel;
use hockle::{Error, Stiffness, Target};

fn sliding_scene() -> Rod {
    Rod::new(
        6,
        89.5_f64.to_radians(),
        Stiffness::nikolai(100.0, 0.05).unwrap(),
    )
    .unwrap()
}

/// What the hooks of a run saw.
#[derive(Default)]
struct Seen {
    starts: usize,
    finishes: usize,
    points: usize,
    arclengths: Vec<f64>,
}

/// Counts the hooks a run calls (the run takes its observer by value).
struct Hooks(Rc<RefCell<Seen>>);

impl Observer for Hooks {
    fn start(&mut self, _: &Continuation, _: &Point) -> ControlFlow<()> {
        self.0.borrow_mut().starts += 1;
        ControlFlow::Continue(())
    }
    fn point(&mut self, p: &Point) -> ControlFlow<()> {
        let mut seen = self.0.borrow_mut();
        seen.points += 1;
        seen.arclengths.push(p.arclength());
        ControlFlow::Continue(())
    }
    fn finish(&mut self, _: &Termination) {
        self.0.borrow_mut().finishes += 1;
    }
}

#[test]
fn a_stretch_goes_on_past_sliding_loops_and_keeps_what_it_had() {
    let stretch = || Pull::new(sliding_scene(), Target::Extension(0.99)).max_steps(2000);
    let plain = stretch().run(()).unwrap();
    assert!(
        matches!(
            plain.termination().error(),
            Some(Error::CorrectorDrifted { .. })
        ),
        "{}",
        plain.termination()
    );
    let seen = Rc::new(RefCell::new(Seen::default()));
    let relaxed = stretch()
        .relax_to(1e-4)
        .run(Hooks(Rc::clone(&seen)))
        .unwrap();
    let hooks = seen.borrow();
    assert!(relaxed.reached_target(), "{relaxed}");
    // the first resumption is where the plain run ended, for its reason
    let first = &relaxed.relaxations()[0];
    assert_eq!(first.from_point, plain.curve().len() - 1);
    assert_eq!(Some(&first.because), plain.termination().error());
    assert!(first.tolerance > 1e-6 && first.tolerance <= 1e-4);
    // every point up to it is the plain run's, bit for bit
    assert_eq!(
        &relaxed.curve().points()[..plain.curve().len()],
        plain.curve().points()
    );
    assert_eq!(&relaxed.folds()[..plain.folds().len()], plain.folds());
    // the pop-outs the diagram counts, the stretch ending below the last
    let d =
        PhaseDiagram::from_csv(6, include_str!("../../docs/data/phase_diagram_n6.csv")).unwrap();
    let predicted = d.pop_outs(89.5_f64.to_radians(), 100.0, 0.05).unwrap();
    let response = RodModel::response(relaxed.clone()).unwrap();
    // the spring's answer says where the rod went on, and how loosely
    assert_eq!(response.relaxations(), relaxed.relaxations());
    assert!(response.to_string().contains(&format!(
        "relaxed from point {} to tolerance",
        first.from_point
    )));
    let scale = response.curve().scale();
    let maxima: Vec<f64> = response
        .pop_outs()
        .iter()
        .map(|p| p.max.point.force_scaled(scale))
        .collect();
    assert_eq!(maxima.len(), predicted, "{maxima:?}");
    let end = response
        .curve()
        .points()
        .last()
        .unwrap()
        .force_scaled(scale);
    assert!(end < maxima[predicted - 1], "ends at {end}: {maxima:?}");
    // the observer sees one run: one start, one finish, every point once
    // (the curve's and the located folds'), in increasing arclength
    assert_eq!((hooks.starts, hooks.finishes), (1, 1));
    assert_eq!(
        hooks.points,
        relaxed.curve().len() + relaxed.folds().len(),
        "points observed"
    );
    assert!(hooks.arclengths.windows(2).all(|w| w[1] > w[0]));
}

#[test]
fn a_pull_that_does_not_fail_is_not_relaxed() {
    let rod = Rod::new(
        4,
        89.8_f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let pull = Pull::new(rod, Target::Force(3.0)).tolerance(1e-2);
    let plain = pull.clone().run(()).unwrap();
    let relaxed = pull.relax_to(1e-1).run(()).unwrap();
    assert!(relaxed.reached_target());
    assert!(relaxed.relaxations().is_empty());
    assert_eq!(relaxed.curve().points(), plain.curve().points());
    assert_eq!(relaxed.folds(), plain.folds());
    assert_eq!(relaxed.estimate(), plain.estimate());
}

#[test]
fn relax_to_outside_the_pulls_tolerance_and_1e_1_is_refused() {
    let pull = || Pull::new(sliding_scene(), Target::Extension(0.99)).tolerance(1e-5);
    for loosest in [1e-6, 0.2, f64::NAN, f64::INFINITY, -1e-4] {
        assert!(
            matches!(
                pull().relax_to(loosest).check(),
                Err(Error::InvalidArgument {
                    name: "relax_to",
                    ..
                })
            ),
            "{loosest}"
        );
    }
    assert!(pull().relax_to(1e-5).check().is_ok());
    assert!(pull().relax_to(1e-1).check().is_ok());
    // the scene's rod model hands it to its pull
    let spring =
        hockle::spring::Spring::from_degrees(6, 89.5, Stiffness::nikolai(100.0, 0.05).unwrap())
            .unwrap();
    assert!(matches!(
        RodModel::default()
            .relax_to(0.5)
            .driver(&spring, Target::Extension(0.99)),
        Err(Error::InvalidArgument {
            name: "relax_to",
            ..
        })
    ));
}
