//! Bad input is an error, never a panic; a stopped or failed pull keeps its
//! points.

use std::ops::ControlFlow;

use hockle::continuation::{Point, Termination};
use hockle::rod::{Pull, Rod};
use hockle::{Error, Stiffness, Target};

fn paper() -> Rod {
    Rod::new(
        4,
        89.8_f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap()
}

#[test]
fn invalid_rods_are_errors() {
    let k = Stiffness::new(1.0, 1.0, 1.0).unwrap();
    assert!(matches!(
        Rod::new(0, 1.0, k),
        Err(Error::InvalidCount { name: "coils", .. })
    ));
    for theta0 in [0.0, -0.1, 1.6, f64::NAN] {
        assert!(matches!(
            Rod::new(4, theta0, k),
            Err(Error::InvalidArgument {
                name: "helix_angle",
                ..
            })
        ));
    }
    // (2πn)²B must be finite.
    let huge = Stiffness::new(1.0, 1e306, 1.0).unwrap();
    assert!(Rod::new(u32::MAX, 1.0, huge).is_err());
    for bad in [f64::NAN, f64::INFINITY] {
        assert!(
            paper()
                .with_intrinsic_strains(hockle::nalgebra::Vector3::new(0.0, bad, 1.0))
                .is_err()
        );
    }
}

#[test]
fn bad_pull_settings_are_typed_errors_before_any_work() {
    let target = Target::Force(3.0);
    assert!(matches!(
        Pull::new(paper(), target).intervals(0).run(()),
        Err(Error::InvalidCount { .. })
    ));
    assert!(matches!(
        Pull::new(paper(), target).points(8).run(()),
        Err(Error::InvalidCount { name: "points", .. })
    ));
    assert!(matches!(
        Pull::new(paper(), target).step(1.0, 1e-7, 0.02).run(()),
        Err(Error::InvalidArgument { name: "step", .. })
    ));
    assert!(matches!(
        Pull::new(paper(), target).max_angle(f64::NAN).run(()),
        Err(Error::InvalidArgument {
            name: "max_angle",
            ..
        })
    ));
    // Unreachable targets: the rest state itself, Δz ≥ 1, NaN.
    let rest = 89.8_f64.to_radians().cos();
    for t in [
        Target::Force(0.0),
        Target::Force(f64::NAN),
        Target::Extension(1.0),
        Target::Extension(rest),
        Target::Extension(f64::INFINITY),
    ] {
        assert!(
            matches!(
                Pull::new(paper(), t).run(()),
                Err(Error::UnreachableTarget { .. })
            ),
            "{t}"
        );
    }
    // θ0 = 90°: the ring closes on itself; a typed error, not an empty run.
    let ring = Rod::new(
        4,
        90_f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    assert!(matches!(
        Pull::new(ring, target).run(()),
        Err(Error::OutsideModel { model: "rod", .. })
    ));
}

#[test]
fn small_targets_are_met_exactly() {
    // Below the load that sets the first step (1e-4): the old pull stepped
    // past such targets and ran to the step limit.
    for f in [5e-5, 1e-7] {
        let run = Pull::new(paper(), Target::Force(f)).run(()).unwrap();
        assert!(
            matches!(run.termination(), Termination::ParameterValue(_)),
            "{run}"
        );
        let last = run.curve().points().last().unwrap();
        // Located to 1e-9 in arclength, where F/((2πn)²B) has weight 1.
        assert!(
            (last.force_scaled(paper().scale()) - f).abs() < 1e-9,
            "{run}"
        );
        assert!(run.steps() < 20, "{run}");
    }
    let dz = 89.8_f64.to_radians().cos() + 1e-6;
    let run = Pull::new(paper(), Target::Extension(dz)).run(()).unwrap();
    assert!(
        matches!(run.termination(), Termination::ParameterValue(_)),
        "{run}"
    );
    assert!((run.curve().points().last().unwrap().extension - dz).abs() < 1e-9);
}

#[test]
fn a_stopped_pull_keeps_its_points() {
    let mut seen = 0;
    let run = Pull::new(paper(), Target::Force(3.0))
        .run(|_: &Point| {
            seen += 1;
            if seen == 25 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        })
        .unwrap();
    assert_eq!(run.termination(), &Termination::Stopped);
    assert_eq!(run.curve().len(), 25);
    assert_eq!(run.loops().len(), 25);
    // The step limit is a termination too.
    let run = Pull::new(paper(), Target::Force(3.0))
        .max_steps(10)
        .run(())
        .unwrap();
    assert_eq!(run.termination(), &Termination::MaxSteps(10));
    assert_eq!(run.curve().len(), 11); // the rest state and 10 steps
}

#[test]
fn equilibrium_rejects_foreign_solutions() {
    use hockle::bvp::{Collocation, Problem};
    struct Scalar;
    impl Problem for Scalar {
        fn dim(&self) -> usize {
            1
        }
        fn parameter_count(&self) -> usize {
            0
        }
        fn boundary_count(&self) -> usize {
            1
        }
        fn rhs(&self, _s: f64, _y: &[f64], _p: &[f64], f: &mut [f64]) {
            f[0] = 0.0;
        }
        fn boundary(&self, y0: &[f64], _y1: &[f64], _p: &[f64], g: &mut [f64]) {
            g[0] = y0[0] - 1.0;
        }
    }
    let sol = Collocation::new()
        .intervals(2)
        .solve(&Scalar, |_s: f64| [1.0], &[])
        .unwrap();
    let rod = paper();
    assert!(matches!(
        hockle::rod::Equilibrium::new(rod, sol),
        Err(Error::InvalidCount { .. })
    ));
}

#[test]
fn huge_sample_counts_are_refused_not_allocated() {
    let run = Pull::new(paper(), Target::Force(1e-3)).run(()).unwrap();
    assert!(run.reached_target());
    let start = Pull::new(paper(), Target::Force(1e-3)).start().unwrap();
    let e = hockle::rod::Equilibrium::new(paper(), start.rest().clone()).unwrap();
    for n in [0, usize::MAX, hockle::error::MAX_POINTS] {
        assert!(matches!(
            e.centreline_samples(n),
            Err(Error::InvalidCount {
                name: "samples",
                ..
            })
        ));
    }
    assert_eq!(e.centreline_samples(4).unwrap().len(), 5);
    // Mesh counts past the bvp's limit are refused before any work.
    assert!(matches!(
        Pull::new(paper(), Target::Force(1.0))
            .intervals(usize::MAX)
            .run(()),
        Err(Error::InvalidCount { .. })
    ));
}

/// Every model, setting and result type can cross threads.
#[test]
fn rod_and_spring_types_are_send_and_sync() {
    fn check<T: Send + Sync>() {}
    check::<Rod>();
    check::<Pull>();
    check::<hockle::rod::PullRun>();
    check::<hockle::rod::Start>();
    check::<hockle::rod::Equilibrium>();
    check::<hockle::spring::Spring>();
    check::<hockle::spring::RodModel>();
    check::<hockle::spring::HelixModel>();
    check::<hockle::spring::ElasticaModel>();
    check::<hockle::spring::Response>();
    check::<hockle::Target>();
    check::<hockle::ForceScale>();
    check::<hockle::ForceExtension>();
    check::<hockle::Stiffness>();
    check::<hockle::Error>();
    check::<hockle::stability::Stability>();
    check::<hockle::stability::IndexCrossing>();
    check::<hockle::rod::SecondVariation>();
    check::<hockle::rod::Contact>();
}

#[test]
fn the_direct_stability_test_rejects_bad_segment_counts() {
    let rod = paper();
    let start = Pull::new(rod, Target::Force(1.0)).start().unwrap();
    let rest = hockle::rod::Equilibrium::new(rod, start.rest().clone()).unwrap();
    for segments in [0, 15, 1001, usize::MAX] {
        assert!(matches!(
            rest.second_variation(hockle::Control::Force, segments),
            Err(Error::InvalidCount {
                name: "segments",
                ..
            })
        ));
    }
    // 16 segments are allowed: four coils turn neighbouring frames by
    // 2π·4/16 = π/2 < 2π/3, so it answers; seven coils turn them by
    // 2π·7/16 > 2π/3, too few segments for the shape, a typed error.
    assert!(rest.second_variation(hockle::Control::Force, 16).is_ok());
    let tight = Rod::new(
        7,
        89.8_f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let start = Pull::new(tight, Target::Force(1.0)).start().unwrap();
    let rest = hockle::rod::Equilibrium::new(tight, start.rest().clone()).unwrap();
    assert!(matches!(
        rest.second_variation(hockle::Control::Extension, 16),
        Err(Error::InvalidCount {
            name: "segments",
            ..
        })
    ));
}
