//! Pinning sliding loops (`Pull::pin_slides`, experimental): at negative ν
//! the loops left in the paper's spring at high tension slide along the
//! rod at an exponentially small cost, the Jacobian has near-null modes and
//! the unpinned pull crawls there with an estimate of ∞ (or fails); pinned,
//! it reaches F/((2πn)²B) = 14 within its tolerance. At ν = 0.05 and
//! A/B = 100 the loops left past the last pop-out slide too; there
//! Newton's corrections stall at their rounding floor: such points are kept
//! without shortening the step, and where, at the shortest step, they lie
//! more than a step from their predictor the run ends with a typed failure.
//!
//! The reference: the unpinned pull to F/((2πn)²B) = 10 on fixed uniform
//! meshes of 128 and 192 intervals with m = 6 (no adaptivity, no pinning;
//! their halved-mesh checks fail on the slides, but their last points, at
//! the load exactly, are solutions of their meshes, and the two agree).

use hockle::continuation::Termination;
use hockle::rod::{Pull, PullRun, Rod};
use hockle::{Error, FoldKind, Stiffness, Target};

/// The two uniform meshes' Δz at the load agree to this: their
/// discretisation error is O((n/N)^2m), far below it (measured: 9e-12
/// apart), so 1e-9 bounds the reference's own error with room.
const REFERENCE_AGREEMENT: f64 = 1e-9;

/// The paper's spring (n = 4, θ0 = 89.8°, A/B = 10) at Poisson's ratio `nu`.
fn spring(nu: f64) -> Rod {
    Rod::new(
        4,
        89.8_f64.to_radians(),
        Stiffness::nikolai(10.0, nu).unwrap(),
    )
    .unwrap()
}

fn reference(intervals: usize) -> f64 {
    let run = Pull::new(spring(-0.5), Target::Force(10.0))
        .tolerance(1e-6)
        .intervals(intervals)
        .points(6)
        .run(())
        .unwrap();
    assert!(run.reached_target(), "{run}");
    run.curve().points().last().unwrap().extension
}

fn extension_at(run: &PullRun, force: f64) -> Vec<f64> {
    let curve = run.curve();
    curve.extension_at(force * curve.force_scale())
}

#[test]
fn a_pinned_pull_past_sliding_loops_is_within_its_estimate() {
    let tol = 1e-6;
    let run = Pull::new(spring(-0.5), Target::Force(14.0))
        .tolerance(tol)
        .pin_slides(true)
        .run(())
        .unwrap();
    let estimate = run.estimate();
    assert!(
        run.reached_target() && run.meets_tolerance() && estimate.pinned > 0.0,
        "{run}"
    );
    let (a, b) = (reference(128), reference(192));
    assert!((a - b).abs() <= REFERENCE_AGREEMENT, "{a} {b}");
    let at = extension_at(&run, 10.0);
    assert_eq!(at.len(), 1, "{at:?}");
    let error = (at[0] - b).abs();
    // measured: 3.8e-9 against an estimate of 9.1e-7
    assert!(
        error <= estimate.curve(),
        "{error:e} > {:e}",
        estimate.curve()
    );
}

#[test]
fn pinning_is_off_by_default_and_says_nothing() {
    // the paper's spring never pins: its estimate has no pinned part
    let rod = spring(0.05);
    let run = Pull::new(rod, Target::Force(1.0))
        .tolerance(1e-3)
        .run(())
        .unwrap();
    let pinned = Pull::new(rod, Target::Force(1.0))
        .tolerance(1e-3)
        .pin_slides(true)
        .run(())
        .unwrap();
    assert_eq!(run.estimate().pinned, 0.0);
    // where nothing stalls, asking for pinning changes nothing
    assert_eq!(run.curve().points(), pinned.curve().points());
    assert!(!run.to_string().contains("pinned"));
}

/// A rod of `coils` at θ0 = 89.5°, A/B = 100, ν = 0.05 (C by Nikolai's
/// equality), where the loops left past the cascade slide.
fn stiff_at_89_5(coils: u32) -> Rod {
    Rod::new(
        coils,
        89.5_f64.to_radians(),
        Stiffness::nikolai(100.0, 0.05).unwrap(),
    )
    .unwrap()
}

/// Past its sixth pop-out, n = 8 at (89.5°, A/B = 100, ν = 0.05) has loops
/// in the rod that slide nearly freely, and Newton's corrections stall at
/// their rounding floor, within a hundred times the tolerance (1e-10). Such
/// points were kept but counted as Newton's most iterations, so each halved
/// the step: the pull crawled to the shortest step and kept its last points
/// by the last resort (`ErrorEstimate::stalled`), its estimate 2.1e-4. Now
/// a point at the floor does not shorten the step, and the pull reaches the
/// load within the tolerance, with the seven pop-outs the phase diagram
/// counts there (docs/data/phase_diagram_n8.csv).
#[test]
fn a_pull_past_sliding_loops_reaches_its_load_within_the_tolerance() {
    let tol = 1e-6;
    let run = Pull::new(stiff_at_89_5(8), Target::Force(8.0))
        .tolerance(tol)
        .run(())
        .unwrap();
    assert!(run.reached_target() && run.folds().len() == 14, "{run}");
    assert!(run.estimate().overall() <= tol, "{run}");
}

/// n = 7 at (89.5°, A/B = 100, ν = 0.05) pulled to F/((2πn)²B) = 30: past
/// its sixth pop-out's maximum force the loops left in the rod slide, and
/// at the shortest step Newton stops at its rounding floor ever farther
/// from its predictor (20 steps away). Such points were kept (the run's
/// interpolation estimate reached 3.3e-3 before its Newton diverged at the
/// shortest step); now the run ends there with a typed failure
/// (`Error::CorrectorDrifted`), keeping its points. The six maxima are
/// the diagram's six pop-outs (docs/data/phase_diagram_n7.csv).
#[test]
fn a_pull_whose_loops_slide_freely_ends_past_its_maxima_with_a_typed_failure() {
    let run = Pull::new(stiff_at_89_5(7), Target::Force(30.0))
        .tolerance(1e-6)
        .run(())
        .unwrap();
    let maxima = run
        .folds()
        .iter()
        .filter(|f| f.kind == FoldKind::MaxForce)
        .count();
    assert!(maxima >= 6, "{run}");
    assert!(
        run.reached_target()
            || matches!(
                run.termination(),
                Termination::Failed {
                    error: Error::CorrectorDrifted { .. },
                    ..
                }
            ),
        "{run}"
    );
}
