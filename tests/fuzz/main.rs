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
//! To add a layer, write `tests/fuzz/<layer>.rs` with a `fuzz(g, r, calls)`
//! and a CI test and a `long_run` line below.
#[path = "../common/mod.rs"]
mod common;

mod bvp;
mod elastica;
mod helix;
mod hostile;
mod special;

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

/// Issue 10, not in this helper's layers: `Mesh::uniform(usize::MAX)` aborts
/// the process on the allocation (bvp is being rewritten in another branch).
/// Enable once bvp refuses counts above `error::MAX_POINTS`.
#[test]
#[ignore = "aborts today: bvp::Mesh::uniform has no count limit yet"]
fn bvp_huge_counts() {
    run("bvp (huge counts)", 5, 1, bvp::huge_counts);
}

/// The long run documented in docs/ACCURACY.md (call counts printed).
#[test]
#[ignore = "long: about 30× the CI budget (minutes)"]
fn long_run() {
    const FACTOR: u64 = 30;
    for (i, (name, calls, f)) in [
        (
            "special",
            special::CI_CALLS,
            special::fuzz as fn(&mut Gen, &mut Report, u64),
        ),
        ("elastica", elastica::CI_CALLS, elastica::fuzz),
        ("helix", helix::CI_CALLS, helix::fuzz),
        ("bvp", bvp::CI_CALLS, bvp::fuzz),
    ]
    .into_iter()
    .enumerate()
    {
        run(name, 1000 + i as u64, calls * FACTOR, f);
    }
}

/// Every value type of the `special` layer can cross threads (the
/// elastica and helix types are asserted in their modules).
const _: fn() = || {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<hockle::special::Modulus>();
    send_sync::<hockle::special::Jacobi>();
    send_sync::<hockle::bvp::Mesh>();
    send_sync::<hockle::Error>();
};
