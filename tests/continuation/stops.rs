//! Stops: a requested parameter value or user event ends the run on a
//! located point, and the termination says which.

use hockle::Error;
use hockle::bvp::{Collocation, Solution};
use hockle::continuation::{Continuation, PointKind, Termination};

use super::problems::Bratu;

fn start(intervals: usize, lambda: f64) -> Solution {
    Collocation::new()
        .intervals(intervals)
        .solve(&Bratu::default(), |_s: f64| [0.0, 0.0], &[lambda])
        .unwrap()
}

/// y'(0) on the lower Bratu branch at λ, from the closed form
/// λ = θ²/(2 cosh²(θ/4)), y'(0) = θ tanh(θ/4) (tests/data/bvp_references.py
/// derives it), θ by bisection on the lower branch θ ∈ (0, θ*), where
/// θ* solves θ tanh(θ/4) = 4 (the fold).
fn lower_branch_slope(lambda: f64) -> f64 {
    let lam = |t: f64| t * t / (2.0 * (t / 4.0).cosh().powi(2));
    let slope = |t: f64| t * (t / 4.0).tanh();
    let (mut lo, mut hi) = (0.0, 10.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if slope(mid) < 4.0 { lo = mid } else { hi = mid }
    }
    let fold = lo;
    let (mut lo, mut hi) = (0.0, fold);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if lam(mid) < lambda {
            lo = mid
        } else {
            hi = mid
        }
    }
    slope(0.5 * (lo + hi))
}

#[test]
fn a_stop_value_is_met_exactly_and_named() {
    for (from, step, target) in [(0.0, 0.1, 2.0), (2.0, -0.1, 0.5)] {
        let run = Continuation::new(0)
            .solver(Collocation::new().intervals(20))
            .step(step)
            .stop_at(target)
            .run(&Bratu::default(), &start(20, from), ())
            .unwrap();
        assert_eq!(run.termination(), &Termination::ParameterValue(target));
        let last = run.last().unwrap();
        assert_eq!(last.kind(), PointKind::ParameterValue);
        // The last point is the target itself, not a point near it.
        assert_eq!(last.parameter(), target);
        // And it is the solution there: m = 4, N = 20 gives O(h^8) ≈ 1e-11
        // relative discretisation error on the lower branch; 1e-9.
        let exact = lower_branch_slope(target);
        let got = last.solution().at_mesh(0)[1];
        assert!((got / exact - 1.0).abs() < 1e-9, "{got} vs {exact}");
        // A plain solve at the target agrees to the Newton tolerance (the
        // same discretisation; 1e-10 scaled corrections).
        let plain = start(20, target).at_mesh(0)[1];
        assert!((got - plain).abs() < 1e-9, "{got} vs {plain}");
    }
}

#[test]
fn a_value_a_step_passes_twice_over_a_fold_is_met() {
    // Large steps over the Bratu fold: find the step that contains it, and
    // ask for a λ above both its ends and below the fold. That value is
    // reached twice inside one step, so the signs at the step's ends agree.
    let cont = Continuation::new(0)
        .solver(Collocation::new().intervals(10))
        .step(0.5)
        .step_bounds(1e-8, 1.0)
        .max_angle(1.5)
        .stop_when(|s| s.at_mesh(0)[1] - 10.0);
    let s0 = start(10, 0.0);
    let free = cont.run(&Bratu::default(), &s0, ()).unwrap();
    let pts = free.points();
    let f = pts
        .iter()
        .position(|p| p.kind() == PointKind::Fold)
        .unwrap();
    let (before, fold, after) = (&pts[f - 1], &pts[f], &pts[f + 1]);
    assert_eq!(after.kind(), PointKind::Regular);
    let ends = before.parameter().max(after.parameter());
    assert!(ends < fold.parameter());
    let target = 0.5 * (ends + fold.parameter());
    let run = cont
        .clone()
        .stop_at(target)
        .run(&Bratu::default(), &s0, ())
        .unwrap();
    assert_eq!(run.termination(), &Termination::ParameterValue(target));
    let last = run.last().unwrap();
    assert_eq!(last.parameter(), target);
    // The first time: before the fold.
    assert!(last.arclength() < fold.arclength());
    assert!(last.dparameter_ds() > 0.0);
}

#[test]
fn an_event_is_located_and_the_termination_names_it() {
    // Event 0 never fires; event 1 fires where y(½) = 1, which on the lower
    // branch is θ = 4 acosh(e^½), λ = θ²/(2e) (closed form above with
    // y(½) = 2 ln cosh(θ/4)).
    let run = Continuation::new(0)
        .solver(Collocation::new().intervals(20))
        .step(0.1)
        .stop_when(|s| s.at_mesh(0)[1] - 100.0)
        .stop_when(|s| s.eval(0.5)[0] - 1.0)
        .run(&Bratu::default(), &start(20, 0.0), ())
        .unwrap();
    assert_eq!(run.termination(), &Termination::Event(1));
    let last = run.last().unwrap();
    assert_eq!(last.kind(), PointKind::Event(1));
    // Located to 1e-10 in arclength; |d y(½)/ds| ≤ 1 in the unit norm.
    let miss = last.solution().eval(0.5)[0] - 1.0;
    assert!(miss.abs() < 1e-10, "{miss:e}");
    let theta = 4.0 * (0.5_f64.exp()).acosh();
    let lambda = theta * theta / (2.0 * 1.0_f64.exp());
    // Discretisation O(h^8) and the location above: 1e-9.
    assert!(
        (last.parameter() - lambda).abs() < 1e-9,
        "{}",
        last.parameter() - lambda
    );
}

#[test]
fn a_non_finite_event_is_a_typed_failure() {
    let s0 = start(10, 0.0);
    // NaN from λ = 1 on: the run fails there and keeps its points.
    let run = Continuation::new(0)
        .step(0.1)
        .stop_when(|s| {
            if s.parameters()[0] > 1.0 {
                f64::NAN
            } else {
                1.0
            }
        })
        .run(&Bratu::default(), &s0, ())
        .unwrap();
    assert!(
        matches!(
            run.termination().error(),
            Some(Error::NonFinite {
                what: "stop_when event",
                ..
            })
        ),
        "{}",
        run.termination()
    );
    assert!(run.points().len() > 5);
    assert!(run.points().iter().all(|p| p.parameter() <= 1.0));
    // NaN at the start: an error before the first step.
    let e = Continuation::new(0)
        .stop_when(|_| f64::NAN)
        .steps(&Bratu::default(), &s0)
        .expect_err("a NaN event at the start");
    assert!(matches!(e, Error::NonFinite { .. }), "{e}");
}
