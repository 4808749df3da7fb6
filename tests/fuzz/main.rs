//! Hostile input for every public constructor and numerical entry (issue 10).
//!
//! A seeded generator ([`hostile::Gen`]) draws each argument from NaN, ±∞, ±0,
//! subnormals, ±1e±300, `f64::MAX`, huge integers, values one ulp outside
//! each documented domain and ordinary values; every call runs under
//! `catch_unwind` ([`hostile::Report::call`]). The oracles: no panic, no
//! non-finite value in an `Ok` from a documented-valid input, no `Ok` from an
//! input outside the documented domain (and for the total functions of
//! `special`, the documented value on non-finite input).
//!
//! One function per module (`special::fuzz`, `elastica::fuzz`, …), each
//! taking a call budget; the CI tests below run every module at its
//! `CI_CALLS` (well under a minute in release), and the ignored `long_run`
//! runs 30× more with other seeds:
//!
//! ```text
//! cargo test --release --test fuzz                       # CI
//! cargo test --release --test fuzz -- --ignored --nocapture long_run
//! ```
//!
//! `found` holds the regression tests of the bugs this suite found in the
//! upper layers.
//!
//! To add a layer, write `tests/fuzz/<layer>.rs` with a `fuzz(g, r, calls)`
//! and a CI test and a `long_run` line below.
#[path = "../common/mod.rs"]
mod common;

mod bvp;
mod continuation;
mod curve;
mod elastica;
mod found;
mod found_audit15;
mod found_extremes;
mod found_large_forces;
mod helix;
mod hostile;
mod phase_diagram;
mod rod;
mod special;
mod spring;

use hostile::{Gen, Report};

/// Runs one module's fuzz function with `calls` calls from `seed` and
/// asserts that no oracle failed.
/// `HOCKLE_FUZZ_CALLS` overrides the budget (for bisecting a failure).
fn run(name: &str, seed: u64, calls: u64, f: fn(&mut Gen, &mut Report, u64)) -> Report {
    let calls = std::env::var("HOCKLE_FUZZ_CALLS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(calls);
    let mut g = Gen::new(seed);
    let mut r = Report::new(name);
    f(&mut g, &mut r, calls);
    r.finish();
    r
}

#[test]
fn special_entries() {
    run("special", 1, special::CI_CALLS, special::fuzz);
}

#[test]
fn elastica_entries() {
    run("elastica", 2, elastica::CI_CALLS, elastica::fuzz);
}

#[test]
fn helix_entries() {
    run("helix", 3, helix::CI_CALLS, helix::fuzz);
}

#[test]
fn bvp_entries() {
    run("bvp", 4, bvp::CI_CALLS, bvp::fuzz);
}

#[test]
fn continuation_entries() {
    run(
        "continuation",
        6,
        continuation::CI_CALLS,
        continuation::fuzz,
    );
}

#[test]
fn rod_entries() {
    run("rod", 7, rod::CI_CALLS, rod::fuzz);
}

#[test]
fn spring_entries() {
    run("spring", 8, spring::CI_CALLS, spring::fuzz);
}

#[test]
fn curve_entries() {
    run("curve", 9, curve::CI_CALLS, curve::fuzz);
}

#[test]
fn phase_diagram_entries() {
    run(
        "phase_diagram",
        10,
        phase_diagram::CI_CALLS,
        phase_diagram::fuzz,
    );
}

/// Issue 10: `Mesh::uniform(usize::MAX)` aborted the process on the
/// allocation; bvp now refuses more than `Mesh::MAX_INTERVALS` intervals
/// (in `Mesh` and in every `Collocation` count) and systems past 2 GiB of
/// workspace, before the problem is called.
#[test]
fn bvp_huge_counts() {
    run("bvp (huge counts)", 5, 1, bvp::huge_counts);
}

/// The long run documented in docs/ACCURACY.md (call counts printed):
/// every module runs even when an earlier one fails; the test fails at the
/// end if any did. `HOCKLE_FUZZ_ONLY=<module>` runs one module (with its
/// long-run seed), `HOCKLE_FUZZ_FACTOR=k` k× the CI budget instead of 30×.
#[test]
#[ignore = "long: about 30× the CI budget (minutes)"]
fn long_run() {
    let factor: u64 = std::env::var("HOCKLE_FUZZ_FACTOR")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(30);
    let only = std::env::var("HOCKLE_FUZZ_ONLY").ok();
    let mut failed = Vec::new();
    for (i, (name, calls, f)) in [
        (
            "special",
            special::CI_CALLS,
            special::fuzz as fn(&mut Gen, &mut Report, u64),
        ),
        ("elastica", elastica::CI_CALLS, elastica::fuzz),
        ("helix", helix::CI_CALLS, helix::fuzz),
        ("bvp", bvp::CI_CALLS, bvp::fuzz),
        ("continuation", continuation::CI_CALLS, continuation::fuzz),
        ("rod", rod::CI_CALLS, rod::fuzz),
        ("spring", spring::CI_CALLS, spring::fuzz),
        ("curve", curve::CI_CALLS, curve::fuzz),
        (
            "phase_diagram",
            phase_diagram::CI_CALLS,
            phase_diagram::fuzz,
        ),
    ]
    .into_iter()
    .enumerate()
    {
        if only.as_ref().is_some_and(|o| o != name) {
            continue;
        }
        let one = std::panic::catch_unwind(|| run(name, 1000 + i as u64, calls * factor, f));
        if one.is_err() {
            failed.push(name);
        }
    }
    assert!(failed.is_empty(), "long run: failures in {failed:?}");
}

/// Every value type of the `special` layer can cross threads (the
/// elastica and helix types are asserted in their modules, the
/// continuation's runs in tests/continuation/observer.rs, the rod's and
/// the spring's models and the stability and contact types in
/// tests/rod/input.rs), and the bvp, fold-curve, error-estimate and result
/// types asserted nowhere else (issue 10).
const _: fn() = || {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<hockle::special::Modulus>();
    send_sync::<hockle::special::Jacobi>();
    send_sync::<hockle::special::JacobiDm>();
    send_sync::<hockle::special::FixedModulus>();
    send_sync::<hockle::bvp::classic::Linear>();
    send_sync::<hockle::bvp::classic::Bratu>();
    send_sync::<hockle::bvp::classic::BratuLength>();
    send_sync::<hockle::bvp::classic::Troesch>();
    send_sync::<hockle::bvp::classic::Quadratic>();
    send_sync::<hockle::bvp::classic::Euler>();
    send_sync::<hockle::bvp::classic::Eigen>();
    send_sync::<hockle::bvp::classic::Coupled13>();
    send_sync::<hockle::continuation::ErrorEstimate>();
    send_sync::<hockle::continuation::Output>();
    send_sync::<hockle::continuation::FoldContinuation>();
    send_sync::<hockle::continuation::FoldCurve>();
    send_sync::<hockle::continuation::FoldPoint>();
    send_sync::<hockle::continuation::FoldPointKind>();
    send_sync::<hockle::curve::Slope>();
    send_sync::<hockle::ForceExtension>();
    send_sync::<hockle::ForceScale>();
    send_sync::<hockle::Target>();
    send_sync::<hockle::stability::Stability>();
    send_sync::<hockle::stability::IndexCrossing>();
    send_sync::<hockle::rod::SecondVariation>();
    send_sync::<hockle::rod::Contact>();
    send_sync::<hockle::rod::Start>();
    send_sync::<hockle::bvp::Mesh>();
    send_sync::<hockle::bvp::Collocation>();
    send_sync::<hockle::bvp::Solution>();
    send_sync::<hockle::bvp::NewtonStats>();
    send_sync::<hockle::bvp::LinearSolver>();
    send_sync::<hockle::continuation::Every<()>>();
    send_sync::<hockle::continuation::Steps<'static, hockle::rod::Rod>>();
    send_sync::<hockle::spring::PopOut>();
    send_sync::<hockle::spring::Jump>();
    send_sync::<hockle::spring::Stretch>();
    send_sync::<hockle::spring::BranchMatch>();
    send_sync::<hockle::spring::Direction>();
    send_sync::<hockle::Control>();
    send_sync::<hockle::ForcePoint>();
    send_sync::<hockle::Fold>();
    send_sync::<hockle::FoldKind>();
    send_sync::<hockle::Error>();
};
