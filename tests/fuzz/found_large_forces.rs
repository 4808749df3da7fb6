//! Pulls to large forces (session of 29 Nov, probing `examples/models
//! --max-force`): a fixed step cap made them crawl, and the rounding floor
//! of the force made them stall until the step limit.

use hockle::Error;
use hockle::Target;
use hockle::continuation::Termination;
use hockle::rod::{Pull, Rod};
use hockle::spring::{RodModel, Spring};

fn paper_rod() -> Rod {
    RodModel::rod(&Spring::paper()).unwrap()
}

/// A pull to F/((2πn)²B) = 3e5 took steps of at most Δs = 1 (the cap, in
/// units of F/((2πn)²B)), so over 3·10⁵ steps. Now the cap under force
/// control is a hundredth of the target (`Pull::largest_step`) and the
/// tolerance sets the steps below it: the paper's spring reaches 3e5 in
/// about 300 steps. The last point is the target.
#[test]
fn a_large_force_is_reached_in_few_steps() {
    let run = Pull::new(paper_rod(), Target::Force(3e5))
        .tolerance(1e-4)
        .max_steps(1_000)
        .run(())
        .unwrap();
    assert!(run.reached_target(), "{}", run.termination());
    let last = run.curve().points().last().unwrap();
    let f = last.force_scaled(run.curve().scale());
    // the stop is met to the location tolerance, far below 1e-9 relative
    assert!((f / 3e5 - 1.0).abs() < 1e-9, "{f}");
    // an inextensible rod: 0 < Δz ≤ 1 + tol (here 1 − 1.5e-7)
    assert!(last.extension > 0.99 && last.extension <= 1.0 + 1e-4);
}

/// A pull to F/((2πn)²B) = 1e10 at tolerance 1e-4 reaches F/((2πn)²B) ≈ 1e9,
/// where the force's last digits are the tolerance's order (an absolute
/// 1e-4 on 1e9 is 10⁻¹³ relative) and steps stop moving the point: it
/// stepped there 20 000 times (65 s) until the step limit. Now it ends
/// `Failed` with `NoProgress`, every point so far kept.
#[test]
fn a_force_beyond_the_rounding_floor_ends_with_no_progress() {
    let run = Pull::new(paper_rod(), Target::Force(1e10))
        .tolerance(1e-4)
        .run(())
        .unwrap();
    assert!(
        matches!(
            run.termination(),
            Termination::Failed {
                error: Error::NoProgress { .. },
                ..
            }
        ),
        "{}",
        run.termination()
    );
    // far fewer than the step limit (about 300 here)
    assert!(run.curve().len() < 2_000, "{}", run.curve().len());
    let last = run.curve().points().last().unwrap();
    assert!(last.force_scaled(run.curve().scale()) > 1e6);
}
