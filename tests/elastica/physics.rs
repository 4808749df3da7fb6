//! Independent checks of the closed forms: direct integration of the planar
//! Kirchhoff equations, the energy derivative, and bad input.
use crate::common::rel_err;
use hockle::Error;
use hockle::elastica::{Arm, Elastica, bifurcation, secondary_fold};
use hockle::special::{Modulus, jacobi};
use proptest::prelude::*;

/// Integrates ϑ' = κ, κ' = −F sin ϑ, x' = −sin ϑ, z' = cos ϑ (the planar
/// Kirchhoff rod with B = 1 under the tension F along z; ϑ the tangent angle
/// to the force) by classical RK4 with `steps` steps from ϑ(0) = 2 am u1 and
/// κ(0) = 2πn (the zero-moment condition), and returns (κ(1), x(1), −z(1)).
/// Nothing of eq5–eq8 enters except the start angle.
fn integrate(e: &Elastica, steps: usize) -> (f64, f64, f64) {
    let f = e.force();
    let theta0 = 2.0 * jacobi(e.start() * e.omega(), e.elliptic_modulus()).am;
    let kappa0 = 2.0 * core::f64::consts::PI * f64::from(e.coils());
    let rhs = |y: [f64; 4]| [y[1], -f * y[0].sin(), -y[0].sin(), y[0].cos()];
    let mut y = [theta0, kappa0, 0.0, 0.0];
    let h = 1.0 / steps as f64;
    for _ in 0..steps {
        let k1 = rhs(y);
        let k2 = rhs(core::array::from_fn(|i| y[i] + 0.5 * h * k1[i]));
        let k3 = rhs(core::array::from_fn(|i| y[i] + 0.5 * h * k2[i]));
        let k4 = rhs(core::array::from_fn(|i| y[i] + h * k3[i]));
        for i in 0..4 {
            y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    }
    (y[1], y[2], -y[3])
}

fn cases() -> Vec<Elastica> {
    let mut v = Vec::new();
    for n in [1, 4] {
        for k in [0.3, 0.9, 0.999] {
            let s = Elastica::symmetric(n, k).unwrap();
            v.push(s.upsilon);
            v.push(s.alpha);
        }
    }
    v.extend(Elastica::nonsymmetric(3, 3, 0.9).unwrap());
    v.extend(Elastica::nonsymmetric(4, 2, 0.99).unwrap());
    // (the fold of j = 1 is at m₁ = 6.5e-5)
    for (j, arm, mc) in [
        (3, Arm::Lower, 1e-4),
        (3, Arm::Upper, 1e-4),
        (5, Arm::Lower, 1e-4),
        (5, Arm::Upper, 1e-4),
        (1, Arm::Lower, 1e-5),
    ] {
        let md = Modulus::from_complement(mc).unwrap();
        v.push(Elastica::secondary_arm(4, j, arm, md).unwrap());
    }
    v.push(bifurcation(4, 2).unwrap().solution());
    v
}

/// RK4's global error is O(h⁴); one Richardson step on 20000 and 40000
/// steps, (16 y(h/2) − y(h))/15, removes it, leaving O(h⁶) ≈ (Ω_max h)⁶ with
/// Ω ≤ 60, h = 2.5e-5: ≈ 1e-17 relative times the growth of the pendulum
/// flow. Forward shooting near k = 1 is ill-conditioned (an error in the
/// start grows by the pendulum's hyperbolic factor along the straight parts):
/// κ(1), the most sensitive output, agrees to ≤ 1.1e-9 relative (secondary
/// α, F = 4512), x(1) and Δz to ≤ 6e-12. Tolerances: 1e-8 for κ(1), 1e-10
/// for x(1) and Δz.
#[test]
fn closed_forms_agree_with_direct_integration() {
    for e in cases() {
        let a = integrate(&e, 20_000);
        let b = integrate(&e, 40_000);
        let r = |x: f64, y: f64| (16.0 * y - x) / 15.0;
        let (kappa1, x1, dz) = (r(a.0, b.0), r(a.1, b.1), r(a.2, b.2));
        let kappa0 = 2.0 * core::f64::consts::PI * f64::from(e.coils());
        assert!(rel_err(kappa1, kappa0) < 1e-8, "{e}: κ(1) = {kappa1}");
        assert!(x1.abs() < 1e-10, "{e}: x(1) = {x1}");
        assert!(
            (dz - e.extension()).abs() < 1e-10,
            "{e}: Δz {dz} vs {}",
            e.extension()
        );
        // the closed-form end curvatures (eq6) to rounding
        for kap in e.end_curvatures() {
            assert!(rel_err(kap, kappa0) < 1e-11, "{e}: {kap}");
        }
        // the centreline ends on the force line at the extension
        let c = e.centreline(257).unwrap();
        let end = c[256];
        assert!(
            end.x.abs() < 1e-11 && (end.y - e.extension()).abs() < 1e-11,
            "{e}: {end}"
        );
    }
}

fn fd_force(at: impl Fn(f64) -> Elastica, x: f64, h: f64) -> f64 {
    let (a, b) = (at(x + h), at(x - h));
    (a.energy() - b.energy()) / (a.extension() - b.extension())
}

/// F = dU/dΔz by central differences in the branch parameter: truncation
/// O(h²) ≈ 1e-10 for a relative step 1e-5, rounding ε·U/(h·dU/dx) ≈ 1e-10;
/// tolerance 1e-7.
#[test]
fn force_is_the_energy_derivative_on_every_branch() {
    for n in [1u32, 3, 4] {
        for k in [0.2, 0.6, 0.95] {
            let s = Elastica::symmetric(n, k).unwrap();
            let fu = fd_force(|k| Elastica::symmetric(n, k).unwrap().upsilon, k, 1e-5 * k);
            let fa = fd_force(|k| Elastica::symmetric(n, k).unwrap().alpha, k, 1e-5 * k);
            assert!(
                rel_err(fu, s.upsilon.force()) < 1e-7,
                "υ n={n} k={k}: {fu} vs {}",
                s.upsilon.force()
            );
            assert!(
                rel_err(fa, s.alpha.force()) < 1e-7,
                "α n={n} k={k}: {fa} vs {}",
                s.alpha.force()
            );
            let t = Elastica::nonsymmetric(n, n, k).unwrap()[0];
            let ft = fd_force(|k| Elastica::nonsymmetric(n, n, k).unwrap()[0], k, 1e-5 * k);
            assert!(
                rel_err(ft, t.force()) < 1e-7,
                "ϑ n={n} k={k}: {ft} vs {}",
                t.force()
            );
        }
    }
    // secondary arms and k → 1, stepping in ln m₁
    for (j, arm) in [
        (1, Arm::Lower),
        (1, Arm::Upper),
        (3, Arm::Lower),
        (3, Arm::Upper),
        (6, Arm::Lower),
        (6, Arm::Upper),
    ] {
        for lm in [-12.0_f64, -25.0] {
            let at = |x: f64| {
                Elastica::secondary_arm(4, j, arm, Modulus::from_complement(x.exp()).unwrap())
                    .unwrap()
            };
            let f = fd_force(at, lm, 1e-5);
            let e = at(lm);
            assert!(rel_err(f, e.force()) < 1e-7, "{e}: {f}");
        }
    }
}

#[test]
fn secondary_branches_meet_theta_at_the_bifurcation_and_fold_below_it() {
    for n in [2u32, 4, 7] {
        for j in 1..=7u32 {
            if j == n {
                continue;
            }
            let b = bifurcation(n, j).unwrap();
            let e = Elastica::secondary_arm(n, j, Arm::bifurcating(n, j), b.elliptic_modulus())
                .unwrap();
            // at k_b the arm's t = 0: its Ω is 2jK (eq81's double root)
            assert!(
                rel_err(e.omega(), 2.0 * f64::from(j) * e.quarter_period()) < 1e-12,
                "n={n} j={j}"
            );
            assert!(
                rel_err(e.force(), b.force()) < 1e-12
                    && rel_err(e.extension(), b.extension()) < 1e-11
            );
            let f = secondary_fold(n, j).unwrap();
            assert!(f.modulus() < b.modulus(), "n={n} j={j}");
            // both arms coincide at the fold (√ε ≈ 1e-8 there)
            let lo =
                Elastica::secondary_arm(n, j, Arm::Lower, f.solution().elliptic_modulus()).unwrap();
            let hi =
                Elastica::secondary_arm(n, j, Arm::Upper, f.solution().elliptic_modulus()).unwrap();
            assert!(
                rel_err(lo.omega(), hi.omega()) < 1e-6,
                "n={n} j={j}: {} {}",
                lo.omega(),
                hi.omega()
            );
            assert_eq!(
                e.shape(),
                if j < n {
                    hockle::elastica::Shape::Upsilon
                } else {
                    hockle::elastica::Shape::Alpha
                }
            );
        }
    }
}

/// At the bifurcation points the ends sit at curvature extrema, so the end
/// tangents are along the force (the paper: "along the end-to-end distance
/// and the z-axis"): ϑ = 2 am u ∈ πℤ at both ends, i.e. x′ = −sin ϑ = 0.
#[test]
fn bifurcation_shapes_have_end_tangents_along_the_force() {
    for (n, j) in [(4u32, 3u32), (4, 5), (7, 2), (2, 6)] {
        let e = bifurcation(n, j).unwrap().solution();
        let md = e.elliptic_modulus();
        for s in [0.0, 1.0] {
            let theta = 2.0 * jacobi(e.omega() * (e.start() + s), md).am;
            // am at u ≈ 2jK carries the rounding of u (ε·Ω): |sin ϑ| ≲ 1e-13
            assert!(theta.sin().abs() < 1e-12, "n={n} j={j} s={s}: ϑ = {theta}");
        }
        let c = e.centreline(2001).unwrap();
        // the first chord is along z: x changes only at second order,
        // x ≈ ½κ0h² with h = 1/2000, while |Δz| ≈ h
        let d = c[1] - c[0];
        let (h, kappa0) = (1.0 / 2000.0, 2.0 * core::f64::consts::PI * f64::from(n));
        assert!(
            (d.x.abs() - 0.5 * kappa0 * h * h).abs() < 1e-3 * kappa0 * h * h,
            "n={n} j={j}: {d}"
        );
        assert!((d.y.abs() - h).abs() < 1e-3 * h, "n={n} j={j}: {d}");
    }
}

#[test]
fn k_prime_down_to_1e_150() {
    // Modulus keeps m₁ exact: F ≈ (2nK)² with K ≈ ½ ln(16/m₁) ≈ 346
    let md = Modulus::from_complement(1e-300).unwrap();
    let s = Elastica::symmetric_with(4, md).unwrap();
    for e in [s.upsilon, s.alpha] {
        assert!(e.force().is_finite() && e.force() > 1e5);
        assert!(e.extension() > 0.99 && e.extension() < 1.0, "{e}");
        for kap in e.end_curvatures() {
            assert!(
                rel_err(kap, 8.0 * core::f64::consts::PI) < 1e-10,
                "{e}: {kap}"
            );
        }
    }
    let t = Elastica::nonsymmetric_with(4, 4, md).unwrap();
    assert_eq!(t.len(), 2);
    let e = Elastica::secondary_arm(4, 3, Arm::Lower, md).unwrap();
    assert!(e.extension() < 1.0 && e.force().is_finite());
}

#[test]
fn bad_input_is_a_typed_error() {
    assert!(matches!(
        Elastica::symmetric(0, 0.5),
        Err(Error::InvalidCount { name: "n", .. })
    ));
    for k in [-0.1, 1.5, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(Elastica::symmetric(2, k), Err(Error::InvalidModulus { .. })),
            "{k}"
        );
    }
    assert!(matches!(
        Elastica::symmetric(2, 1.0),
        Err(Error::ModulusNotBelowOne { .. })
    ));
    assert!(matches!(
        Elastica::nonsymmetric(2, 0, 0.5),
        Err(Error::InvalidCount { name: "j", .. })
    ));
    assert!(matches!(
        Elastica::secondary(4, 4, 0.9),
        Err(Error::SecondaryNeedsOtherPeriods { n: 4 })
    ));
    assert!(matches!(
        bifurcation(3, 3),
        Err(Error::SecondaryNeedsOtherPeriods { n: 3 })
    ));
    match Elastica::secondary(4, 3, 0.5) {
        Err(Error::BelowFold {
            n: 4, j: 3, fold, ..
        }) => assert!((fold - 0.828_428_829_573_529).abs() < 1e-12),
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        Elastica::symmetric(1, 0.5).unwrap().upsilon.centreline(1),
        Err(Error::InvalidCount { .. })
    ));
    // the message says what is allowed
    let msg = Elastica::secondary(4, 3, 0.5).unwrap_err().to_string();
    assert!(msg.contains("k >="), "{msg}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]
    #[test]
    fn nothing_panics(n in any::<u32>(), j in any::<u32>(), k in any::<f64>(), mc in any::<f64>()) {
        let small = n % 12;
        let js = j % 12;
        let _ = Elastica::symmetric(n, k);
        let _ = Elastica::nonsymmetric(n, j, k);
        let _ = Elastica::secondary(small, js, k);
        let _ = bifurcation(n, j);
        let _ = bifurcation(small, js);
        if let Ok(md) = Modulus::from_complement(mc) {
            let _ = Elastica::symmetric_with(small, md);
            let _ = Elastica::secondary_arm(small, js, Arm::Upper, md);
            if let Ok(v) = Elastica::nonsymmetric_with(small, js, md) {
                for e in v {
                    let _ = (e.energy(), e.curvature(k), e.centreline(3));
                }
            }
        }
        if let Ok(s) = Elastica::symmetric(small, k) {
            let _ = (s.upsilon.energy(), s.alpha.curvature(mc), s.alpha.centreline(4));
        }
    }
}

/// Extension on a branch (given as a function of ln m₁) at the force `f`,
/// by bisection in ln m₁ (the force grows along each branch towards k = 1).
fn extension_at(branch: impl Fn(f64) -> Option<Elastica>, f: f64, mut lo: f64) -> f64 {
    let mut hi = -200.0_f64;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        match branch(mid) {
            Some(e) if e.force() < f => lo = mid,
            _ => hi = mid,
        }
    }
    branch(lo).map_or(f64::NAN, |e| e.extension())
}

/// The paper's asymptotic claims (Section 3.2.2), at equal force: the gap
/// in extension to the claimed neighbour shrinks (by ≥ 2× from
/// F/(8π)² = 3 to 30) and at F/(8π)² = 30 is below 5 % of the gap to the
/// other candidate (every branch tends to Δz → 1, so shrinking alone would
/// not discriminate):
/// - α_n approaches υ_(n+1) (not υ_n), and ϑ_j approaches υ_(j+1);
/// - the υ secondary arms approach ϑ_(j−1) (lower arm, a coil lost) and
///   ϑ_(j+1) (upper arm, a coil gained); both α arms approach ϑ_j.
#[test]
fn asymptotics_of_the_branches_as_the_paper_states() {
    type B = Box<dyn Fn(f64) -> Option<Elastica>>;
    let scale = (8.0 * core::f64::consts::PI).powi(2);
    let md = |x: f64| Modulus::from_complement(x.exp()).unwrap();
    let gap = |a: &B, b: &B, f: f64| {
        (extension_at(a.as_ref(), f * scale, -1e-9) - extension_at(b.as_ref(), f * scale, -1e-9))
            .abs()
    };
    let theta = |j: u32| -> B {
        Box::new(move |x: f64| {
            Elastica::nonsymmetric_with(j, j, md(x))
                .ok()?
                .first()
                .copied()
        })
    };
    let alpha = |n: u32| -> B {
        Box::new(move |x: f64| Some(Elastica::symmetric_with(n, md(x)).ok()?.alpha))
    };
    let upsilon = |n: u32| -> B {
        Box::new(move |x: f64| Some(Elastica::symmetric_with(n, md(x)).ok()?.upsilon))
    };
    let arm = |j: u32, a: Arm| -> B {
        Box::new(move |x: f64| Elastica::secondary_arm(4, j, a, md(x)).ok())
    };
    let cases: Vec<(&str, B, B, B)> = vec![
        ("α_4 → υ_5 (not υ_4)", alpha(4), upsilon(5), upsilon(4)),
        ("ϑ_3 → υ_4 (not υ_3)", theta(3), upsilon(4), upsilon(3)),
        (
            "υ secondary j=3 lower → ϑ_2 (not ϑ_4)",
            arm(3, Arm::Lower),
            theta(2),
            theta(4),
        ),
        (
            "υ secondary j=3 upper → ϑ_4 (not ϑ_2)",
            arm(3, Arm::Upper),
            theta(4),
            theta(2),
        ),
        (
            "υ secondary j=2 lower → ϑ_1 (not ϑ_3)",
            arm(2, Arm::Lower),
            theta(1),
            theta(3),
        ),
        (
            "α secondary j=5 lower → ϑ_5 (not ϑ_6)",
            arm(5, Arm::Lower),
            theta(5),
            theta(6),
        ),
        (
            "α secondary j=5 upper → ϑ_5 (not ϑ_4)",
            arm(5, Arm::Upper),
            theta(5),
            theta(4),
        ),
    ];
    for (name, a, near, far) in &cases {
        let (g3, g30, other) = (gap(a, near, 3.0), gap(a, near, 30.0), gap(a, far, 30.0));
        eprintln!("{name}: gap {g3:.2e} → {g30:.2e}, other {other:.2e}");
        assert!(
            g30 < 0.5 * g3 && g30 < 0.05 * other,
            "{name}: {g3} → {g30}, other {other}"
        );
    }
}
