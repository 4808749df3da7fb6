//! The closed forms at extreme stiffnesses, angles and counts: against the
//! 700-digit mpmath table `tests/data/helix_extremes.csv`
//! (`python3 tests/data/gen_helix_extremes.py`) and the scaling invariance
//! of the equations.

use hockle::Error;
use hockle::Stiffness;
use hockle::error::MAX_POINTS;
use hockle::helix::Helix;

use crate::common::rel_err;

const TABLE: &str = include_str!("../data/helix_extremes.csv");

/// The same bound as the main table away from θ0: a handful of correctly
/// rounded operations on O(1) sines and cosines and the exact stiffness
/// ratios; the exponents are carried apart, so the extremes of B and C add
/// no rounding. A result in the subnormal range is rounded to 2^−1074
/// absolute once more.
const EXTREME_TOL: f64 = 1e-14;

fn close(x: f64, r: f64) -> bool {
    (x - r).abs() <= EXTREME_TOL * r.abs() + f64::from_bits(1)
}

#[test]
fn extreme_stiffnesses_match_the_mpmath_closed_forms() {
    let mut rows = 0;
    for line in TABLE.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let p = |i: usize| -> f64 { f[i].parse().unwrap() };
        let s = Stiffness::new(p(3), p(4), p(5)).unwrap();
        let h = Helix::new(f[1].parse().unwrap(), p(2), s).unwrap();
        let got = match f[0] {
            "force" => h.force(p(6)),
            _ => h.spring_constant(),
        };
        if f[7] == "overflow" {
            assert!(
                matches!(got, Err(Error::Overflow { .. })),
                "{line}: {got:?}"
            );
        } else {
            let got = got.unwrap_or_else(|e| panic!("{line}: {e}"));
            assert!(
                close(got, p(7)),
                "{line}: got {got:e}, rel err {:e}",
                rel_err(got, p(7))
            );
        }
        rows += 1;
    }
    assert_eq!(rows, 24);
}

/// Scaling A, B, C by one factor scales the energy, the force and the spring
/// constant by it and leaves the shape alone. For powers of two the scaled
/// evaluation performs the very same mantissa operations, so the results are
/// equal bit for bit (while the results stay normal).
#[test]
fn scaling_the_stiffness_scales_the_response_exactly() {
    let base = Stiffness::new(10.0, 1.0, 1.7316).unwrap();
    for th0 in [0.2, 1.0, core::f64::consts::FRAC_PI_2] {
        let h = Helix::new(4, th0, base).unwrap();
        for e in [-1000, -600, -100, 100, 600, 1000] {
            let f = 2f64.powi(e.clamp(-1000, 1000));
            let scaled = Stiffness::new(10.0 * f, f, 1.7316 * f).unwrap();
            let hs = Helix::new(4, th0, scaled).unwrap();
            for theta in [0.05, 0.5 * th0, 0.9 * th0, 1.3] {
                assert_eq!(hs.force(theta).unwrap(), f * h.force(theta).unwrap());
                assert_eq!(hs.radius(theta).unwrap(), h.radius(theta).unwrap());
                assert_eq!(hs.twist_rate(theta).unwrap(), h.twist_rate(theta).unwrap());
                let (u, us) = (h.energy(theta).unwrap(), hs.energy(theta).unwrap());
                assert!(rel_err(us, f * u) < 4.0 * f64::EPSILON, "{us} vs {f}·{u}");
            }
            assert_eq!(
                hs.spring_constant().unwrap(),
                f * h.spring_constant().unwrap()
            );
            // the curve: same extensions and parameters, forces times f
            let (c, cs) = (
                h.curve_to(20, 0.99).unwrap(),
                hs.curve_to(20, 0.99).unwrap(),
            );
            for (p, q) in c.points().iter().zip(cs.points()) {
                assert_eq!((p.extension, p.parameter), (q.extension, q.parameter));
                assert_eq!(q.force, f * p.force);
            }
        }
    }
}

#[test]
fn the_issue_cases_are_finite() {
    // issue 10: NaN before
    let h = Helix::new(4, 1.0, Stiffness::new(10.0, 1.0, 1e200).unwrap()).unwrap();
    assert!(h.force(0.5).unwrap().is_finite());
    for (b, c) in [
        (1e-200, 1e-200),
        (1.0, 1e300),
        (1e300, 1e-300),
        (5e-324, 5e-324),
    ] {
        let h = Helix::new(4, 1.0, Stiffness::new(10.0, b, c).unwrap()).unwrap();
        let curve = h.curve(50).unwrap();
        assert!(
            curve.points().iter().all(|p| p.force.is_finite()),
            "B = {b}, C = {c}"
        );
    }
    let h = Helix::new(4, 1e-300, Stiffness::new(10.0, 1e-300, 1.0).unwrap()).unwrap();
    assert!(h.spring_constant().unwrap().is_finite());
}

#[test]
fn huge_sample_counts_are_refused_before_any_work() {
    let h = Helix::new(4, 1.0, Stiffness::nikolai(10.0, 0.05).unwrap()).unwrap();
    for samples in [MAX_POINTS + 1, u32::MAX as usize, usize::MAX] {
        assert!(matches!(
            h.curve(samples),
            Err(Error::InvalidCount {
                name: "samples",
                ..
            })
        ));
    }
}

/// C = 2AB/((1 + ν)(A + B)) with B = 1 tends to 2/(1 + ν) as A → ∞ and to
/// 2A/(1 + ν) as A → 0: both limits are reached to rounding at the ends of
/// the double range (before: NaN from 2A = ∞ and a message about C).
#[test]
fn nikolai_at_the_ends_of_the_double_range() {
    for nu in [-0.5, 0.0, 0.3, 0.5] {
        let s = Stiffness::nikolai(f64::MAX, nu).unwrap();
        assert!(rel_err(s.c(), 2.0 / (1.0 + nu)) < 2.0 * f64::EPSILON, "{s}");
    }
    let s = Stiffness::nikolai(5e-324, 0.0).unwrap();
    assert_eq!(s.c(), 1e-323);
    let s = Stiffness::nikolai(1e-300, 0.0).unwrap();
    assert!(rel_err(s.c(), 2e-300) < 2.0 * f64::EPSILON);
}

/// Found by the fuzz suite: `curve_to(n, 1 − 2⁻⁵³)` rounded its last
/// extension to 1 and failed with "theta = 0 is not allowed". The last point
/// is now at the requested extension (θ ≈ 1.5e-8), or the force there is an
/// overflow.
#[test]
fn curve_to_the_last_double_below_one() {
    let zmax = 1.0 - f64::EPSILON / 2.0;
    // angles from the fuzz failures (they fail at 73eae45 for every count)
    for (th0_deg, s) in [
        (
            67.117_430_803_161_04_f64,
            Stiffness::new(3.0, 1.0, 1.01).unwrap(),
        ),
        (
            61.004_308_461_792_085,
            Stiffness::new(1e3, 1e3, 853.5).unwrap(),
        ),
        (
            81.679_417_523_746_92,
            Stiffness::new(1e-200, 1e3, 1e-77).unwrap(),
        ),
    ] {
        let h = Helix::new(5, th0_deg.to_radians(), s).unwrap();
        for samples in [2, 15, 100] {
            let c = h.curve_to(samples, zmax).unwrap();
            let last = c.points()[samples - 1];
            assert!(last.parameter > 0.0 && last.force.is_finite());
            assert!(last.extension <= zmax);
        }
    }
}
