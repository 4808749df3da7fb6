//! Settings are validated before any work: every bad setting is a typed
//! error from `run`, `steps` and `distance`, and the problem is never called.

use std::sync::atomic::{AtomicUsize, Ordering};

use hockle::Error;
use hockle::bvp::{Collocation, Problem, Solution};
use hockle::continuation::Continuation;

use super::problems::Bratu;

/// Bratu counting its right-hand-side and boundary calls.
struct Counted {
    calls: AtomicUsize,
}

impl Problem for Counted {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        self.calls.fetch_add(1, Ordering::Relaxed);
        Bratu::default().rhs(s, y, p, f);
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        self.calls.fetch_add(1, Ordering::Relaxed);
        Bratu::default().boundary(y0, y1, p, g);
    }
}

fn start(p: &Counted) -> Solution {
    let s = Collocation::new()
        .intervals(10)
        .solve(p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    p.calls.store(0, Ordering::Relaxed);
    s
}

/// Every bad setting, with the name its error must carry.
fn bad_settings() -> Vec<(&'static str, Continuation, &'static str)> {
    let c = || Continuation::new(0);
    vec![
        (
            "locate_tolerance NaN",
            c().locate_tolerance(f64::NAN),
            "locate_tolerance",
        ),
        (
            "locate_tolerance < 0",
            c().locate_tolerance(-1e-10),
            "locate_tolerance",
        ),
        (
            "locate_tolerance 0",
            c().locate_tolerance(0.0),
            "locate_tolerance",
        ),
        (
            "locate_tolerance ∞",
            c().locate_tolerance(f64::INFINITY),
            "locate_tolerance",
        ),
        ("stop_at ∞", c().stop_at(f64::INFINITY), "stop_at"),
        (
            "stop_at −∞",
            c().stop_at(1.0).stop_at(f64::NEG_INFINITY),
            "stop_at",
        ),
        ("stop_at NaN", c().stop_at(f64::NAN), "stop_at"),
        ("step NaN", c().step(f64::NAN), "ds"),
        ("step 0", c().step(0.0), "ds"),
        ("step −0", c().step(-0.0), "ds"),
        ("step ∞", c().step(f64::INFINITY), "ds"),
        ("ds_min 0", c().step_bounds(0.0, 0.5), "ds_min"),
        ("ds_min < 0", c().step_bounds(-1e-8, 0.5), "ds_min"),
        ("ds_min NaN", c().step_bounds(f64::NAN, 0.5), "ds_min"),
        ("ds_min > ds_max", c().step_bounds(0.6, 0.5), "ds_max"),
        ("ds_max ∞", c().step_bounds(1e-8, f64::INFINITY), "ds_max"),
        ("ds_max NaN", c().step_bounds(1e-8, f64::NAN), "ds_max"),
        ("max_angle 0", c().max_angle(0.0), "max_angle"),
        ("max_angle < 0", c().max_angle(-0.1), "max_angle"),
        ("max_angle > π", c().max_angle(3.2), "max_angle"),
        ("max_angle NaN", c().max_angle(f64::NAN), "max_angle"),
        ("weight NaN", c().weights(&[1.0, f64::NAN]), "weight"),
        ("weight < 0", c().weights(&[1.0, -1.0]), "weight"),
        ("weight ∞", c().weights(&[f64::INFINITY, 1.0]), "weight"),
        ("weights too short", c().weights(&[1.0]), "weights"),
        ("weights too long", c().weights(&[1.0; 3]), "weights"),
        (
            "parameter_weight 0",
            c().parameter_weight(0.0),
            "parameter_weight",
        ),
        (
            "parameter_weight NaN",
            c().parameter_weight(f64::NAN),
            "parameter_weight",
        ),
        ("max_newton 0", c().max_newton(0), "max_newton"),
        (
            "parameter out of range",
            Continuation::new(1),
            "continuation parameter",
        ),
    ]
}

fn name_of(e: &Error) -> &'static str {
    match e {
        Error::InvalidArgument { name, .. }
        | Error::InvalidCount { name, .. }
        | Error::LengthMismatch { name, .. } => name,
        _ => "(another error)",
    }
}

#[test]
fn bad_settings_fail_before_any_work() {
    let p = Counted {
        calls: AtomicUsize::new(0),
    };
    let s = start(&p);
    for (what, cont, name) in bad_settings() {
        let e = match cont.run(&p, &s, ()) {
            Ok(run) => panic!("{what}: run gave Ok ({})", run.termination()),
            Err(e) => e,
        };
        assert_eq!(name_of(&e), name, "{what}: run gave {e}");
        let e = cont.steps(&p, &s).expect_err("steps gave Ok");
        assert_eq!(name_of(&e), name, "{what}: steps gave {e}");
        let e = cont.distance(&s, &s).expect_err("distance gave Ok");
        assert_eq!(name_of(&e), name, "{what}: distance gave {e}");
        assert_eq!(
            p.calls.load(Ordering::Relaxed),
            0,
            "{what}: the problem was called"
        );
    }
}

#[test]
fn the_error_says_what_was_given_and_what_is_allowed() {
    let p = Counted {
        calls: AtomicUsize::new(0),
    };
    let s = start(&p);
    let e = Continuation::new(0)
        .locate_tolerance(-1e-10)
        .steps(&p, &s)
        .expect_err("a negative tolerance");
    assert_eq!(
        e,
        Error::InvalidArgument {
            name: "locate_tolerance",
            value: -1e-10,
            allowed: "finite and > 0 (an arclength)",
        }
    );
    let e = Continuation::new(0)
        .step_bounds(0.6, 0.5)
        .steps(&p, &s)
        .expect_err("ds_min > ds_max");
    assert!(e.to_string().contains("ds_max = 0.5"), "{e}");
}

#[test]
fn good_settings_at_the_edges_of_their_domains_run() {
    let p = Counted {
        calls: AtomicUsize::new(0),
    };
    let s = start(&p);
    // max_angle = π, ds_min = ds_max, zero weights on the solution (the
    // parameter weight keeps the norm definite), a step larger than ds_max
    // (clamped), no steps at all.
    let c = || Continuation::new(0).max_steps(3);
    for cont in [
        c().max_angle(std::f64::consts::PI),
        c().step(0.05).step_bounds(0.05, 0.05),
        c().weights(&[0.0, 0.0]),
        c().step(10.0),
        c().max_steps(0),
    ] {
        let run = cont.run(&p, &s, ()).unwrap();
        assert!(
            run.termination().error().is_none(),
            "{cont}: {}",
            run.termination()
        );
    }
}
