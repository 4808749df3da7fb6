//! Bad input is an error, never a panic; a stopped or failed pull keeps its
//! points.

use std::ops::ControlFlow;

use hockle::Error;
use hockle::rod::{Equilibrium, Pull, PullPoint, PullTermination, Rod};

#[test]
fn invalid_rods_are_errors() {
    assert!(matches!(
        Rod::new(0, 1.0, 1.0, 1.0, 1.0),
        Err(Error::InvalidCount { name: "coils", .. })
    ));
    for theta0 in [0.0, -0.1, 1.6, f64::NAN] {
        assert!(matches!(
            Rod::new(4, theta0, 1.0, 1.0, 1.0),
            Err(Error::InvalidArgument { name: "theta0", .. })
        ));
    }
    for bad in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        assert!(Rod::new(4, 1.0, bad, 1.0, 1.0).is_err());
        assert!(Rod::new(4, 1.0, 1.0, bad, 1.0).is_err());
        assert!(Rod::new(4, 1.0, 1.0, 1.0, bad).is_err());
    }
    assert!(Rod::nikolai(4, 1.0, 10.0, 0.6).is_err());
    assert!(Rod::nikolai(4, 1.0, -10.0, 0.05).is_err());
}

#[test]
fn bad_pull_settings_end_the_run_with_the_reason() {
    let rod = Rod::nikolai(4, 89.8_f64.to_radians(), 10.0, 0.05).unwrap();
    let run = Pull::new(rod).intervals(0).run(());
    assert!(matches!(
        run.termination,
        PullTermination::StartFailed(Error::InvalidCount { .. })
    ));
    assert!(run.points.is_empty());
    let run = Pull::new(rod).step(1.0, 1e-7, 0.02).run(());
    assert!(matches!(
        run.termination,
        PullTermination::StartFailed(Error::InvalidArgument { name: "ds", .. })
    ));
}

#[test]
fn a_stopped_pull_keeps_its_points() {
    let rod = Rod::nikolai(4, 89.8_f64.to_radians(), 10.0, 0.05).unwrap();
    let mut seen = 0;
    let run = Pull::new(rod).run(|_: &Equilibrium, _: &PullPoint| {
        seen += 1;
        if seen == 25 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    });
    assert_eq!(run.termination, PullTermination::Stopped);
    assert_eq!(run.points.len(), 25);
    assert_eq!(run.curve().len(), 25);
    // The step limit is a termination too.
    let run = Pull::new(rod).max_steps(10).run(());
    assert_eq!(run.termination, PullTermination::MaxSteps(10));
    assert_eq!(run.points.len(), 12); // the start, the first secant point, 10 steps
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
    let rod = Rod::nikolai(4, 1.0, 10.0, 0.05).unwrap();
    assert!(matches!(
        Equilibrium::new(rod, sol),
        Err(Error::InvalidCount { .. })
    ));
}
