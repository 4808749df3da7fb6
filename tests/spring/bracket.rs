//! The bracket (`src/spring/bracket.rs`): for small pulls `Spring::answer`
//! answers with the rod's tangent at rest and the gap to the exact helix as
//! its error. Checked here against the converged rod on scenes drawn at
//! random (a fixed xorshift seed, not the grid of `choice.rs`, not tuned):
//! both sides of the bracket at 200 forces, and the answer's true error
//! (both ways, `measure.rs`) below its estimate.

use hockle::Stiffness;
use hockle::helix::Helix;
use hockle::spring::{Choice, Model, Question, Reason, RodModel, Spring, Value};

use crate::measure::{both_ways, drawn};

/// As in `choice.rs`: the rod on a fixed mesh of 10 intervals per coil
/// with m = 7 at tolerance 1e-8 (converged to ~1e-11).
fn reference(spring: &Spring, target: hockle::Target) -> hockle::spring::Response {
    let r = RodModel::default()
        .tolerance(1e-8)
        .intervals(10 * spring.coils() as usize)
        .points(7)
        .pull_to(spring, target)
        .unwrap();
    assert!(r.reached_target(), "reference: {r}");
    r
}

/// Scenes n ∈ [2, 12], θ0 ∈ [10°, 89.95°], A/B ∈ [0.05, 100] (log-uniform),
/// ν ∈ [0, 0.49] (C by the Nikolai equality).
fn random_scenes(mut seed: u64, count: usize) -> Vec<Spring> {
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 1_000_000) as f64 / 1e6
    };
    (0..count)
        .map(|_| {
            let n = 2 + (rnd() * 11.0) as u32;
            let theta0 = 10.0 + rnd() * 79.95;
            let a_over_b = 10f64.powf(-1.3 + rnd() * 3.3);
            let nu = rnd() * 0.49;
            let stiffness = Stiffness::nikolai(a_over_b, nu).unwrap();
            Spring::from_degrees(n, theta0, stiffness).unwrap()
        })
        .collect()
}

/// The load at which the first-order gap f (1/k − 1/k_helix) is `gap`
/// (both constants in units of (2πn)²B).
fn load_for_gap(s: &Spring, gap: f64) -> f64 {
    let k = s.spring_constant().unwrap();
    let helix = Helix::new(s.coils(), s.helix_angle(), s.stiffness()).unwrap();
    let k_helix = helix.spring_constant().unwrap();
    gap / (s.force_scale() * (1.0 / k - 1.0 / k_helix))
}

#[test]
fn small_pulls_are_answered_by_the_tangent_within_the_gap() {
    let mut linear = 0;
    for (i, s) in random_scenes(0x05ee_d14b, 10).iter().enumerate() {
        // the tolerance alternates; the load is set where the first-order
        // gap is half of it, so the bracket answers unless the helix
        // softens or the second-order gap doubles it
        let tol = if i % 2 == 0 { 1e-2 } else { 1e-3 };
        let max_force = load_for_gap(s, 0.5 * tol);
        let answer = s.answer(&Question::Curve { max_force }, tol).unwrap();
        if answer.choice() != Choice::LinearResponse {
            continue;
        }
        linear += 1;
        let Reason::Bracketed { gap } = answer.reason() else {
            panic!("{answer}");
        };
        assert_eq!(gap, answer.estimated_error());
        assert!(answer.meets_tolerance(), "{answer}");
        assert!(
            answer.why().starts_with("linear response: "),
            "{}",
            answer.why()
        );
        let Value::Curve(line) = answer.value() else {
            panic!("{answer}");
        };
        let rod = reference(s, hockle::Target::Force(max_force));
        assert!(
            rod.pop_outs().is_empty(),
            "{s}: a pop-out inside the bracket"
        );
        let truth = both_ways(&drawn(line), &drawn(&rod));
        println!(
            "{s} to f = {max_force:.3e} at {tol:e}: gap {:.2e}, true {truth:.2e}, {:.1} ms",
            answer.estimated_error(),
            answer.elapsed().as_secs_f64() * 1e3
        );
        assert!(
            truth <= answer.estimated_error(),
            "{s} to {max_force}: true {truth:e} above the gap {:e}",
            answer.estimated_error()
        );
        // both sides at 200 forces: the helix left of the rod, the rod left
        // of its tangent (to the reference's 1e-11, with a margin of 10)
        let scale = s.force_scale();
        let helix = Helix::new(s.coils(), s.helix_angle(), s.stiffness()).unwrap();
        let k = s.spring_constant().unwrap() / scale;
        let rest = s.helix_angle().cos();
        // (the last point, at the load itself, is the curve's end)
        for j in 1..=200 {
            let f = max_force * f64::from(j) / 200.0;
            let z_rod = if j == 200 {
                vec![rod.curve().points().last().unwrap().extension]
            } else {
                rod.curve().extension_at(f * scale)
            };
            assert_eq!(z_rod.len(), 1, "{s}: the rod not a graph over f");
            let z_line = rest + f / k;
            let theta = bisect_helix(&helix, f * scale);
            let z_helix = theta.cos();
            assert!(
                z_helix <= z_rod[0] + 1e-10 && z_rod[0] <= z_line + 1e-10,
                "{s} at f = {f}: helix {z_helix}, rod {}, tangent {z_line}",
                z_rod[0]
            );
        }
    }
    // at half the tolerance the first-order gap leaves room for the second
    // order in most scenes; every scene must not fall back to the rod
    assert!(linear >= 5, "only {linear} of 10 answered by the tangent");
}

/// The first helix angle below θ0 at which the helix carries the physical
/// `force`: a scan of 4000 steps down from θ0 to the first bracket, then
/// bisection.
fn bisect_helix(helix: &Helix, force: f64) -> f64 {
    let steps = 4000;
    let (mut lo, mut hi) = (0.0, helix.theta0());
    for i in 1..steps {
        let theta = helix.theta0() * (1.0 - f64::from(i) / f64::from(steps));
        if helix.force(theta).unwrap() >= force {
            lo = theta;
            break;
        }
        hi = theta;
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if helix.force(mid).unwrap() >= force {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn values_read_off_the_tangent_are_within_the_gap() {
    let s = Spring::from_degrees(3, 70.0, Stiffness::nikolai(2.0, 0.3).unwrap()).unwrap();
    let f = load_for_gap(&s, 2e-3);
    let scale = s.force_scale();
    let rod = reference(&s, hockle::Target::Force(f));
    // extensions at forces: the bracket bounds the gap in Δz at each force
    let forces = vec![0.25 * f, 0.5 * f, f];
    let answer = s
        .answer(&Question::ExtensionsAt(forces.clone()), 1e-2)
        .unwrap();
    assert_eq!(answer.choice(), Choice::LinearResponse, "{answer}");
    let Value::Extensions(z) = answer.value() else {
        panic!("{answer}");
    };
    for (force, z) in forces.iter().zip(z) {
        let exact = rod.curve().extension_at(force * scale);
        assert_eq!((z.len(), exact.len()), (1, 1));
        assert!((z[0] - exact[0]).abs() <= answer.estimated_error());
    }
    // the pop-outs are the rod's to show, even inside the bracket
    let answer = s.answer(&Question::PopOuts { max_force: f }, 1e-2).unwrap();
    assert_eq!(answer.choice().name(), "rod", "{answer}");
    let Value::PopOuts { pop_outs, .. } = answer.value() else {
        panic!("{answer}");
    };
    assert!(pop_outs.is_empty() && rod.pop_outs().is_empty());
    // forces at extensions under extension control: the returned point
    // (Δz, f) is within the gap in Δz of the rod's point at the same force
    let last = rod.curve().points().last().unwrap().extension;
    let extensions = vec![0.5 * (s.helix_angle().cos() + last), last];
    let answer = s
        .answer(&Question::ForcesAt(extensions.clone()), 1e-2)
        .unwrap();
    assert_eq!(answer.choice(), Choice::LinearResponse, "{answer}");
    let Value::Forces(fs) = answer.value() else {
        panic!("{answer}");
    };
    for (dz, fs) in extensions.iter().zip(fs) {
        let z_rod = rod.curve().extension_at(fs[0] * scale);
        assert!(
            (dz - z_rod[0]).abs() <= answer.estimated_error(),
            "{dz}: {z_rod:?}"
        );
    }
}

#[test]
fn the_bracket_steps_aside_for_tight_tolerances_pushes_one_coil_and_loose_tolerances() {
    let s = Spring::from_degrees(3, 70.0, Stiffness::nikolai(2.0, 0.3).unwrap()).unwrap();
    let f = load_for_gap(&s, 2e-3);
    // the gap is first order in the load: 1e-6 needs the rod
    let a = s.answer(&Question::Curve { max_force: f }, 1e-6).unwrap();
    assert_eq!(a.choice().name(), "rod", "{a}");
    let a = s.answer(&Question::Curve { max_force: -f }, 1e-2).unwrap();
    assert_eq!(a.choice().name(), "rod", "{a}");
    let one = Spring::from_degrees(1, 70.0, Stiffness::nikolai(2.0, 0.3).unwrap()).unwrap();
    let a = one.answer(&Question::Curve { max_force: f }, 1e-2).unwrap();
    assert_eq!(a.choice().name(), "rod", "{a}");
    // the bracket takes tolerances up to the rod's own limit, 0.1: above
    // it the rod answers (run at half the tolerance) or, from 0.2 on where
    // half is above its limit too, the question is refused
    let a = s.answer(&Question::Curve { max_force: f }, 0.15).unwrap();
    assert_eq!(a.choice().name(), "rod", "{a}");
    let a = s.answer(&Question::Curve { max_force: f }, 0.5);
    assert!(a.is_err(), "{a:?}");
    // the paper's spring to its pop-outs: far outside the bracket
    let a = Spring::paper()
        .answer(&Question::Curve { max_force: 1.0 }, 1e-1)
        .unwrap();
    assert_eq!(a.choice().name(), "rod", "{a}");
}
