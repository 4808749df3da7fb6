//! `Spring::answer(Question::Shape)`: the shape's true error, against the
//! rest helix's closed form and against a converged rod computed here, is
//! below its reported estimate, and its loop count is the reference's.
//!
//! The converged reference (`measure::shape_reference`): the rod pulled to
//! the same load on a fixed mesh of 10 intervals per coil with m = 7 at
//! tolerance 1e-8 (as in `choice.rs`), its last point then solved again at
//! that load on a uniform mesh of 40 intervals per coil with m = 7 (a mesh
//! the answer never uses). Distances are between centrelines, in units of
//! the rod's length, after the best rigid turn about the force line (the
//! rod's equilibria are defined up to one).

use hockle::Stiffness;
use hockle::spring::{Choice, LoadedShape, Question, Reason, SetAside, Spring, Target, Value};

use crate::measure::{
    SAMPLES, SHAPE_REFERENCE_CONVERGED, SHAPE_REFERENCE_INTERVALS_PER_COIL, centreline,
    distance_up_to_a_turn, shape_reference as reference,
};

fn spring(n: u32, theta0_deg: f64, a_over_b: f64, nu: f64) -> Spring {
    Spring::from_degrees(n, theta0_deg, Stiffness::nikolai(a_over_b, nu).unwrap()).unwrap()
}

fn shape_of(answer: &hockle::spring::Answer) -> &LoadedShape {
    let Value::Shape(shape) = answer.value() else {
        panic!("a shape question answered without a shape: {answer}");
    };
    shape
}

#[test]
fn the_reference_is_converged() {
    let s = Spring::paper();
    let at = Target::Force(1.0);
    let a = reference(&s, at, SHAPE_REFERENCE_INTERVALS_PER_COIL);
    let b = reference(&s, at, 2 * SHAPE_REFERENCE_INTERVALS_PER_COIL);
    let d = distance_up_to_a_turn(&centreline(&a), &centreline(&b));
    assert!(d < SHAPE_REFERENCE_CONVERGED, "{d:e}");
}

#[test]
fn shapes_are_within_their_estimates() {
    // a steep slinky pulled hard, a spring pushed, a mid-pitch spring under
    // extension control, and the paper's spring past its two pop-outs below
    // 1 (0.60, 0.85: two loops left)
    for (s, at, loops) in [
        (spring(2, 60.0, 0.1, 0.0), Target::Force(1.0), None),
        (spring(4, 70.0, 3.0, 0.2), Target::Force(-0.05), Some(4)),
        (spring(3, 80.0, 2.0, 0.3), Target::Extension(0.6), None),
        (Spring::paper(), Target::Force(1.0), Some(2)),
    ] {
        let exact = reference(&s, at, SHAPE_REFERENCE_INTERVALS_PER_COIL);
        let r = centreline(&exact);
        if let Some(loops) = loops {
            assert_eq!(exact.loops(), Some(loops), "{s}");
        }
        for tol in [1e-2, 1e-4, 1e-6] {
            let answer = s.answer(&Question::Shape { at }, tol).unwrap();
            let shape = shape_of(&answer);
            let truth = distance_up_to_a_turn(&centreline(shape.equilibrium()), &r);
            println!(
                "{s} at {at:?}, tolerance {tol:e}: estimated {:.2e}, true {truth:.2e}, {:?}",
                answer.estimated_error(),
                answer.elapsed()
            );
            assert!(answer.meets_tolerance(), "{s} at {tol:e}: {answer}");
            assert!(
                truth <= answer.estimated_error(),
                "{s} at {tol:e}: true {truth:e} above the estimate {:e}",
                answer.estimated_error()
            );
            assert_eq!(shape.loops(), exact.loops(), "{s} at {tol:e}");
            assert!(matches!(answer.choice(), Choice::Rod { .. }));
        }
    }
}

#[test]
fn a_shape_barely_loaded_is_the_rest_helix() {
    // the closed form of the unstressed helix (r = (R0 sin φ, R0 (1 − cos φ),
    // s cos θ0), φ = 2πn s, R0 = sin θ0/(2πn)); at F/((2πn)²B) = 1e-9 the
    // exact shape is within ~f/k of it (k = dF/dΔz in the same units, ≥ 0.3
    // on these springs), and 1e-8 bounds that ten times over
    for (s, at) in [
        (spring(4, 70.0, 3.0, 0.2), Target::Force(1e-9)),
        (
            spring(2, 89.0, 10.0, 0.05),
            Target::Extension(89f64.to_radians().cos() + 1e-9),
        ),
    ] {
        let n = f64::from(s.coils());
        let (st, ct) = s.helix_angle().sin_cos();
        let r0 = st / (2.0 * std::f64::consts::PI * n);
        let rest: Vec<[f64; 3]> = (0..=SAMPLES)
            .map(|i| {
                let t = i as f64 / SAMPLES as f64;
                let phi = 2.0 * std::f64::consts::PI * n * t;
                [r0 * phi.sin(), r0 * (1.0 - phi.cos()), ct * t]
            })
            .collect();
        for tol in [1e-4, 1e-7] {
            let answer = s.answer(&Question::Shape { at }, tol).unwrap();
            let shape = shape_of(&answer);
            let truth = distance_up_to_a_turn(&centreline(shape.equilibrium()), &rest);
            assert!(answer.meets_tolerance(), "{s}: {answer}");
            assert!(
                truth <= answer.estimated_error() + 1e-8,
                "{s} at {tol:e}: {truth:e} vs {answer}"
            );
            assert_eq!(shape.loops(), Some(s.coils()), "{s}");
        }
    }
}

#[test]
fn why_a_shape_needs_the_rod() {
    let s = Spring::paper();
    let a = s
        .answer(
            &Question::Shape {
                at: Target::Force(0.3),
            },
            1e-3,
        )
        .unwrap();
    let Reason::RodNeeded {
        helix, elastica, ..
    } = a.reason()
    else {
        panic!("{a}");
    };
    // the loaded helix's radius is below R0 = sin θ0/(8π) = 0.0398
    let SetAside::MissesTheEnds { lower_bound } = helix else {
        panic!("{a}");
    };
    assert!(lower_bound > 1e-3 && lower_bound < 0.0398, "{a}");
    assert_eq!(elastica, SetAside::NotAnswered);
    assert!(a.why().contains("off the force line"), "{}", a.why());
}

#[test]
fn bad_shape_questions_are_typed_errors() {
    let s = Spring::paper();
    let rest = s.helix_angle().cos();
    for at in [
        Target::Force(f64::NAN),
        Target::Force(0.0),
        Target::Force(f64::INFINITY),
        Target::Extension(1.5),
        Target::Extension(rest),
        Target::Extension(f64::NAN),
    ] {
        let r = s.answer(&Question::Shape { at }, 1e-4);
        assert!(r.is_err(), "{at:?}: {r:?}");
    }
    let at = Target::Force(0.3);
    for tol in [0.0, -1e-4, f64::NAN, 0.5] {
        let r = s.answer(&Question::Shape { at }, tol);
        assert!(r.is_err(), "tolerance {tol}: {r:?}");
    }
}

/// Fresh scenes (n 2–8, θ0 60–89.9°, A/B 0.1–20 log-uniform, ν 0–0.4) at
/// a random load (F/((2πn)²B) in 0.05–1.5, or an extension a fraction
/// 0.1–0.9 of the way from rest to 1), from a seed chosen once, not tuned:
/// (spring, target).
fn random_scenes(seed: u64, count: usize) -> Vec<(Spring, Target)> {
    let mut rnd = crate::common::uniform(seed);
    (0..count)
        .map(|i| {
            let n = 2 + (rnd() * 7.0) as u32;
            let theta0 = 60.0 + rnd() * 29.9;
            let a_over_b = 10f64.powf(-1.0 + rnd() * (1.0 + 20f64.log10()));
            let nu = rnd() * 0.4;
            let s = spring(n, theta0, a_over_b, nu);
            let u = rnd();
            let at = if i % 2 == 0 {
                Target::Force(0.05 + 1.45 * u)
            } else {
                let rest = s.helix_angle().cos();
                Target::Extension(rest + (0.1 + 0.8 * u) * (1.0 - rest))
            };
            (s, at)
        })
        .collect()
}

#[test]
#[ignore = "slow: about 2 minutes; run with --ignored --nocapture random_shapes"]
fn random_shapes_are_within_their_estimates() {
    let mut worst: f64 = 0.0;
    for (s, at) in random_scenes(0x5a_9e14c, 12) {
        let exact = reference(&s, at, SHAPE_REFERENCE_INTERVALS_PER_COIL);
        let r = centreline(&exact);
        for tol in [1e-2, 1e-4, 1e-6] {
            let answer = s.answer(&Question::Shape { at }, tol).unwrap();
            let shape = shape_of(&answer);
            let truth = distance_up_to_a_turn(&centreline(shape.equilibrium()), &r);
            let ratio = truth / answer.estimated_error();
            worst = worst.max(ratio);
            println!(
                "{s} at {at:?}, tolerance {tol:e}: estimated {:.2e}, true {truth:.2e} ({ratio:.3}), loops {:?} ({:?}), {:?}",
                answer.estimated_error(),
                shape.loops(),
                exact.loops(),
                answer.elapsed()
            );
            assert!(answer.meets_tolerance(), "{s} at {tol:e}: {answer}");
            assert!(
                truth <= answer.estimated_error(),
                "{s} at {tol:e}: true {truth:e}"
            );
            assert_eq!(shape.loops(), exact.loops(), "{s} at {tol:e}");
        }
    }
    println!("largest true/estimated: {worst:.3}");
}

/// The grid (`measure::grid_scenes`), each spring's shape at
/// F/((2πn)²B) = 1 at tolerances 1e-2, 1e-4, 1e-6 (run with the curve
/// grid of `choice.rs` by the same command).
#[test]
#[ignore = "slow: about 3 minutes; run with --ignored --nocapture grid"]
fn grid_shapes() {
    let at = Target::Force(1.0);
    let tolerances = [1e-2, 1e-4, 1e-6];
    let mut seconds = vec![Vec::new(); tolerances.len()];
    let (mut worst, mut failures) = (0.0_f64, Vec::new());
    for (n, theta0, a_over_b, nu) in crate::measure::grid_scenes() {
        let s = spring(n, theta0, a_over_b, nu);
        let exact = reference(&s, at, SHAPE_REFERENCE_INTERVALS_PER_COIL);
        let r = centreline(&exact);
        for (t, tol) in tolerances.iter().enumerate() {
            let answer = s.answer(&Question::Shape { at }, *tol).unwrap();
            let shape = shape_of(&answer);
            let truth = distance_up_to_a_turn(&centreline(shape.equilibrium()), &r);
            let estimated = answer.estimated_error();
            seconds[t].push(answer.elapsed().as_secs_f64());
            worst = worst.max(truth / estimated);
            println!(
                "| {n} | {theta0} | {a_over_b} | {nu} | {tol:.0e} | {estimated:.2e} | {truth:.2e} | {:?} ({:?}) | {:.3} |",
                shape.loops(),
                exact.loops(),
                answer.elapsed().as_secs_f64()
            );
            if !(answer.meets_tolerance() && truth <= estimated && shape.loops() == exact.loops()) {
                failures.push(format!(
                    "({n}, {theta0}°, {a_over_b}, {nu}) at {tol:e}: {answer}, true {truth:e}, loops {:?} vs {:?}",
                    shape.loops(),
                    exact.loops()
                ));
            }
        }
    }
    for (t, tol) in tolerances.iter().enumerate() {
        let mut v = seconds[t].clone();
        v.sort_by(f64::total_cmp);
        println!(
            "tolerance {tol:e}: median / max seconds {:.3} / {:.3}",
            v[v.len() / 2],
            v[v.len() - 1]
        );
    }
    println!("largest true/estimated: {worst:.3}");
    assert!(failures.is_empty(), "{failures:#?}");
}
