//! `helix`: the Appendix's helical response against the mpmath energy
//! derivative (tests/data/gen_elastica.py), finite differences of the energy,
//! the spring constant and bad input.
#[path = "../common/mod.rs"]
mod common;

mod extremes;

use common::rel_err;
use hockle::Error;
use hockle::Stiffness;
use hockle::helix::Helix;
use proptest::prelude::*;

const TABLE: &str = include_str!("../data/helix.csv");

/// Each closed-form value is a handful of correctly rounded operations on
/// sin/cos of arguments of order 1 and a difference θ − θ0 that is exact when
/// the two are within a factor 2 (Sterbenz); the mpmath reference is exact to
/// 30 digits. Near θ0 the relative error of F is that of sin(θ − θ0) where θ
/// and θ0 each carry half an ulp: |θ|ε/|θ − θ0|, bounded by ≈ 2e-13 at the
/// table's closest point θ = 0.999 θ0; the tolerance is 1e-12 there and 1e-14
/// elsewhere.
#[test]
fn force_radius_match_the_mpmath_energy_derivative() {
    let mut rows = 0;
    let mut worst = 0.0_f64;
    for line in TABLE.lines().skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        let n: u32 = f[0].parse().unwrap();
        let th0: f64 = f[2].parse().unwrap();
        let ab: f64 = f[3].parse().unwrap();
        let nu: f64 = f[4].parse().unwrap();
        let theta: f64 = f[5].parse().unwrap();
        let (force, ext, radius): (f64, f64, f64) = (
            f[6].parse().unwrap(),
            f[7].parse().unwrap(),
            f[8].parse().unwrap(),
        );
        let h = Helix::new(n, th0, Stiffness::nikolai(ab, nu).unwrap()).unwrap();
        // θ0 and θ are exact doubles in the table, so both sides evaluate at the
        // same arguments.
        let fh = h.force(theta).unwrap();
        if force.abs() < 1e-20 {
            assert!(fh.abs() < 1e-9, "F(θ0) = {fh}");
        } else {
            let tol = if (theta / th0 - 1.0).abs() < 0.01 {
                1e-12
            } else {
                1e-14
            };
            let e = rel_err(fh, force);
            worst = worst.max(e);
            assert!(e < tol, "{line}: F = {fh}, rel err {e:e}");
        }
        // cos is correctly rounded to within an ulp
        assert!(rel_err(h.extension(theta).unwrap(), ext) < 3e-16);
        assert!(rel_err(h.radius(theta).unwrap(), radius) < 1e-14, "{line}");
        rows += 1;
    }
    assert!(rows >= 120, "table too short: {rows}");
    eprintln!("helix force: worst relative error {worst:e} over {rows} rows");
}

#[test]
fn force_vanishes_at_rest_and_is_the_energy_derivative() {
    for &(th0d, ab) in &[(89.8, 10.0), (88.0, 1.0), (60.0, 0.1), (45.0, 3.0)] {
        let th0 = f64::to_radians(th0d);
        let h = Helix::new(4, th0, Stiffness::nikolai(ab, 0.05).unwrap()).unwrap();
        assert_eq!(h.force(th0).unwrap(), 0.0);
        assert_eq!(h.energy(th0).unwrap(), 0.0);
        for frac in [0.3, 0.6, 0.9] {
            let t = th0 * frac;
            // central difference in θ: truncation h²·U'''/6 ≈ 1e-10 relative
            // for h = 1e-5, rounding ε·U/h ≈ 1e-11 relative.
            let d = 1e-5;
            let du = h.energy(t + d).unwrap() - h.energy(t - d).unwrap();
            let dz = (t + d).cos() - (t - d).cos();
            let fd = du / dz;
            let f = h.force(t).unwrap();
            assert!(rel_err(fd, f) < 1e-8, "θ0 {th0d}°, θ {t}: {fd} vs {f}");
        }
    }
}

#[test]
fn spring_constant_is_the_slope_at_rest() {
    for &(th0d, ab) in &[(89.8, 10.0), (60.0, 1.0), (30.0, 0.1)] {
        let th0 = f64::to_radians(th0d);
        let h = Helix::new(3, th0, Stiffness::nikolai(ab, 0.05).unwrap()).unwrap();
        // one-sided slope over δθ = 1e-6: first-order error ≈ δθ·|F''/F'| ≲ 1e-5
        let t = th0 - 1e-6;
        let slope = h.force(t).unwrap() / (t.cos() - th0.cos());
        assert!(rel_err(slope, h.spring_constant().unwrap()) < 1e-4);
    }
    // flat ring limit: the classical close-coiled spring constant C (2πn)²
    let s = Stiffness::new(10.0, 1.0, 1.7).unwrap();
    let h = Helix::new(4, core::f64::consts::FRAC_PI_2, s).unwrap();
    let expect = 1.7 * (8.0 * core::f64::consts::PI).powi(2);
    assert!(rel_err(h.spring_constant().unwrap(), expect) < 1e-15);
}

#[test]
fn nikolai_matches_the_paper() {
    let s = Stiffness::nikolai(10.0, 0.05).unwrap();
    // C/B = 1.7316 is printed with 5 significant digits
    assert!((s.c() - 1.7316).abs() < 5e-5, "{}", s.c());
    assert_eq!(s.b(), 1.0);
    assert_eq!(s.a(), 10.0);
}

#[test]
fn curve_runs_from_rest_to_the_requested_extension() {
    let h = Helix::new(
        4,
        f64::to_radians(60.0),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let c = h.curve_to(101, 0.9).unwrap();
    assert_eq!(c.len(), 101);
    let p = c.points();
    assert!((p[0].extension - 0.5).abs() < 1e-15);
    assert!((p[100].extension - 0.9).abs() < 1e-15);
    assert!(
        p.windows(2)
            .all(|w| w[1].force > w[0].force && w[1].extension > w[0].extension)
    );
    assert!(h.curve(1).is_err());
    assert!(h.curve_to(10, 0.4).is_err());
}

#[test]
fn bad_input_is_a_typed_error() {
    let s = Stiffness::nikolai(10.0, 0.05).unwrap();
    assert!(matches!(
        Helix::new(0, 1.0, s),
        Err(Error::InvalidCount { name: "coils", .. })
    ));
    for t in [0.0, -1.0, 1.6, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Helix::new(4, t, s),
            Err(Error::InvalidArgument {
                name: "helix_angle",
                ..
            })
        ));
    }
    let h = Helix::new(4, 1.0, s).unwrap();
    for t in [0.0, core::f64::consts::PI, f64::NAN, -0.5] {
        assert!(matches!(
            h.force(t),
            Err(Error::InvalidArgument { name: "theta", .. })
        ));
    }
    assert!(Stiffness::new(0.0, 1.0, 1.0).is_err());
    assert!(Stiffness::new(1.0, f64::NAN, 1.0).is_err());
    assert!(Stiffness::nikolai(1.0, -1.0).is_err());
    assert!(Stiffness::nikolai(1.0, 0.6).is_err());
    assert!(Stiffness::nikolai(-1.0, 0.3).is_err());
}

proptest! {
    #[test]
    fn nothing_panics(n in any::<u32>(), th0 in any::<f64>(), t in any::<f64>(),
                      a in any::<f64>(), b in any::<f64>(), c in any::<f64>(), nu in any::<f64>(),
                      samples in 0usize..5, zmax in any::<f64>()) {
        let _ = Stiffness::nikolai(a, nu);
        if let Ok(s) = Stiffness::new(a, b, c)
            && let Ok(h) = Helix::new(n % 8, th0, s)
        {
            // every Ok is finite (B, C = 1e200 gave NaN forces before)
            for v in [h.force(t), h.radius(t), h.energy(t), h.extension(t),
                      h.twist_rate(t), h.spring_constant()].into_iter().flatten() {
                prop_assert!(v.is_finite(), "{}: θ = {}: {}", h, t, v);
            }
            let _ = h.curve_to(samples, zmax);
        }
    }
}

#[test]
fn force_scaled_divides_by_the_whole_force_scale() {
    // F/((2πn)²B): the same number for (A, B, C) and (2A, 2B, 2C), and the
    // physical force over (2πn)²B to a few roundings.
    let h1 = Helix::new(4, 1.2, Stiffness::new(10.0, 1.0, 1.7).unwrap()).unwrap();
    let h2 = Helix::new(4, 1.2, Stiffness::new(20.0, 2.0, 3.4).unwrap()).unwrap();
    let scale = (8.0 * std::f64::consts::PI).powi(2) * 2.0;
    for t in [0.3, 0.7, 1.1] {
        let (f1, f2) = (h1.force_scaled(t).unwrap(), h2.force_scaled(t).unwrap());
        assert!(rel_err(f1, f2) < 1e-14, "{f1} vs {f2}");
        assert!(rel_err(f2, h2.force(t).unwrap() / scale) < 1e-14);
    }
}
