//! Limits, special values and bad input.

use hockle::Error;
use hockle::special::{
    Modulus, ellip_e, ellip_e_inc, ellip_f, ellip_k, jacobi, jacobi_epsilon, jacobi_zeta,
};
use std::f64::consts::{FRAC_PI_2, PI};

const EPS: f64 = f64::EPSILON;

#[test]
fn invalid_moduli_are_errors() {
    for x in [
        f64::NAN,
        -0.1,
        1.1,
        f64::INFINITY,
        f64::NEG_INFINITY,
        -1e-300,
    ] {
        for r in [
            Modulus::from_k(x),
            Modulus::from_m(x),
            Modulus::from_complement(x),
        ] {
            match r {
                Err(Error::InvalidModulus { value, .. }) => {
                    assert!(value.is_nan() && x.is_nan() || value == x)
                }
                other => panic!("{x}: expected InvalidModulus, got {other:?}"),
            }
        }
    }
    let msg = Modulus::from_m(2.0).unwrap_err().to_string();
    assert!(msg.contains("m = 2") && msg.contains("[0, 1]"), "{msg}");
}

#[test]
fn modulus_views_agree() {
    let a = Modulus::from_k(0.5).unwrap();
    assert_eq!((a.k(), a.m(), a.complement()), (0.5, 0.25, 0.75));
    let b = Modulus::from_complement(0.75).unwrap();
    assert_eq!(a, b);
    let c = a.complementary();
    assert_eq!((c.m(), c.complement()), (0.75, 0.25));
    assert_eq!(a.to_string(), "k = 0.5, m = 0.25, m1 = 0.75");
    // k → 1 keeps m₁ exactly.
    let d = Modulus::from_complement(1e-300).unwrap();
    assert_eq!((d.m(), d.complement(), d.k_prime()), (1.0, 1e-300, 1e-150));
}

#[test]
fn complete_limits() {
    let zero = Modulus::from_m(0.0).unwrap();
    let one = Modulus::from_m(1.0).unwrap();
    assert_eq!(ellip_k(zero), FRAC_PI_2);
    assert_eq!(ellip_e(zero), FRAC_PI_2);
    assert_eq!(ellip_k(one), f64::INFINITY);
    assert_eq!(ellip_e(one), 1.0);
    // K ~ ½ ln(16/m₁) + O(m₁ ln m₁) (DLMF 19.12.1): at m₁ = 1e-300 the
    // remainder is far below ε.
    let tiny = Modulus::from_complement(1e-300).unwrap();
    let asym = 0.5 * (16.0f64.ln() - 1e-300f64.ln());
    assert!((ellip_k(tiny) - asym).abs() <= 2.0 * EPS * asym);
    // The smallest subnormal m₁ is still finite.
    let sub = Modulus::from_complement(f64::from_bits(1)).unwrap();
    assert!(ellip_k(sub).is_finite() && ellip_e(sub) == 1.0);
}

#[test]
fn non_finite_arguments_give_nan() {
    let md = Modulus::from_m(0.5).unwrap();
    for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(ellip_f(x, md).is_nan());
        assert!(ellip_e_inc(x, md).is_nan());
        let j = jacobi(x, md);
        assert!(j.sn.is_nan() && j.cn.is_nan() && j.dn.is_nan() && j.am.is_nan());
        assert!(jacobi_epsilon(x, md).is_nan());
        assert!(jacobi_zeta(x, md).is_nan());
    }
}

#[test]
fn incomplete_limits() {
    let zero = Modulus::from_m(0.0).unwrap();
    let one = Modulus::from_m(1.0).unwrap();
    for phi in [-7.0f64, -1.0, 0.0, 0.3, 1.5, 4.0, 100.0] {
        // F(φ, 0) = E(φ, 0) = φ: the reduction φ = jπ + r, then 2jK + r,
        // each step within an ulp.
        assert!((ellip_f(phi, zero) - phi).abs() <= 2.0 * EPS * phi.abs());
        assert!((ellip_e_inc(phi, zero) - phi).abs() <= 2.0 * EPS * phi.abs());
    }
    // m = 1: F = atanh(sin φ) on |φ| < π/2 (DLMF 19.6.8), ±∞ beyond; E = sin φ.
    // The reference is the same function as asinh(tan φ) (the inverse
    // Gudermannian, DLMF 4.23.41): atanh(sin φ) in floating point is off by
    // 3.7 ulp at φ = 1.5 (sin's half ulp times atanh's condition number
    // s/((1 − s²) atanh s) ≈ 60), asinh(tan φ) by ≤ 1.5 (tan and asinh
    // each ≤ 1 ulp, asinh's condition number < 1 here); 4 ulp leaves F
    // 2.5 (measured ≤ 1.2 on these points against mpmath).
    for phi in [-1.2f64, 0.4, 1.0, 1.5] {
        let f = phi.tan().asinh();
        assert!(
            (ellip_f(phi, one) - f).abs() <= 4.0 * EPS * f.abs(),
            "{phi}"
        );
        assert!((ellip_e_inc(phi, one) - phi.sin()).abs() <= 2.0 * EPS);
    }
    assert_eq!(ellip_f(2.0, one), f64::INFINITY);
    assert_eq!(ellip_f(-2.0, one), f64::NEG_INFINITY);
    // At fl(π/2) exactly: F = K − tiny, E = E − tiny.
    let md = Modulus::from_m(0.7).unwrap();
    assert!((ellip_f(FRAC_PI_2, md) - ellip_k(md)).abs() <= 2.0 * EPS * ellip_k(md));
    assert!((ellip_e_inc(FRAC_PI_2, md) - ellip_e(md)).abs() <= 2.0 * EPS);
}

#[test]
fn jacobi_limits() {
    let zero = Modulus::from_m(0.0).unwrap();
    let one = Modulus::from_m(1.0).unwrap();
    for u in [-3.0f64, 0.0, 0.5, 2.0, 40.0, 800.0] {
        let j = jacobi(u, zero);
        assert_eq!((j.sn, j.cn, j.dn, j.am), (u.sin(), u.cos(), 1.0, u));
        assert_eq!(jacobi_epsilon(u, zero), u);
        let j = jacobi(u, one);
        assert_eq!(
            (j.sn, j.cn, j.dn),
            (u.tanh(), 1.0 / u.cosh(), 1.0 / u.cosh())
        );
        assert_eq!(j.am, u.sinh().atan());
        assert_eq!(jacobi_epsilon(u, one), u.tanh());
    }
    let j = jacobi(0.0, Modulus::from_m(0.3).unwrap());
    assert_eq!((j.sn, j.cn, j.dn, j.am), (0.0, 1.0, 1.0, 0.0));
}

/// am is continuous and increasing through many periods, also for m → 1.
#[test]
fn amplitude_is_continuous() {
    for md in [
        Modulus::from_m(0.5).unwrap(),
        Modulus::from_complement(1e-12).unwrap(),
        Modulus::from_complement(1e-300).unwrap(),
    ] {
        let k = ellip_k(md);
        let n = 4000;
        let mut prev = jacobi(-3.0 * k, md).am;
        for i in 1..=n {
            let u = -3.0 * k + 6.0 * k * f64::from(i) / f64::from(n);
            let am = jacobi(u, md).am;
            // am′ = dn ≤ 1: a step h moves am by at most h (plus rounding).
            let h = 6.0 * k / f64::from(n);
            assert!(
                am >= prev - 8.0 * EPS * am.abs().max(1.0),
                "{md}: not increasing at {u}"
            );
            assert!(am - prev <= h * (1.0 + 1e-12) + 8.0 * EPS * am.abs().max(1.0));
            prev = am;
        }
        assert!((prev - 1.5 * PI).abs() <= 1e-12 * PI, "am(3K) = {prev}");
    }
}

#[test]
fn zeta_and_helpers() {
    let md = Modulus::from_m(0.8).unwrap();
    let k = ellip_k(md);
    // Z(K) = 0 and Z(u) odd; Z's absolute error is that of ε (≤ few ulp of ε(K) = E).
    assert!(jacobi_zeta(k, md).abs() <= 8.0 * EPS * ellip_e(md));
    assert_eq!(jacobi_zeta(-0.4, md), -jacobi_zeta(0.4, md));
    let j = jacobi(0.9, md);
    assert_eq!(j.nd(), 1.0 / j.dn);
    assert_eq!(j.cd(), j.cn / j.dn);
    assert_eq!(j.sd(), j.sn / j.dn);
    assert_eq!(j.sc(), j.sn / j.cn);
    assert_eq!(j.ns(), 1.0 / j.sn);
    assert_eq!(j.nc(), 1.0 / j.cn);
    assert_eq!(j.cs(), j.cn / j.sn);
    assert_eq!(j.ds(), j.dn / j.sn);
    assert_eq!(j.dc(), j.dn / j.cn);
    assert!(j.to_string().starts_with("sn = "));
}

/// Finite u of any size and m₁ down to the smallest subnormal give finite
/// values in range (no NaN): for |u| beyond ~2⁵³·2K the result carries no
/// information about u, but it stays a valid point of the functions.
#[test]
fn huge_arguments_and_extreme_moduli_stay_finite() {
    let mcs = [
        5e-324, 1e-310, 1e-300, 1e-200, 1e-20, 9.3e-10, 1e-3, 0.5, 1.0,
    ];
    let us = [
        0.0,
        -0.0,
        1e-310,
        1e-20,
        0.3,
        10.0,
        1e4,
        1e6,
        1e15,
        1e20,
        1e300,
        -1e300,
        f64::MAX,
    ];
    for mc in mcs {
        let md = Modulus::from_complement(mc).unwrap();
        for u in us {
            let j = jacobi(u, md);
            assert!(j.sn.abs() <= 1.0 && j.cn.abs() <= 1.0, "{md}, u = {u}: {j}");
            assert!(
                (0.0..=1.0).contains(&j.dn) && j.am.is_finite(),
                "{md}, u = {u}: {j}"
            );
            assert!(jacobi_epsilon(u, md).is_finite(), "{md}, u = {u}");
            assert!(jacobi_zeta(u, md).is_finite(), "{md}, u = {u}");
            assert!(ellip_e_inc(u, md).is_finite(), "{md}, φ = {u}");
            assert!(!ellip_f(u, md).is_nan(), "{md}, φ = {u}");
        }
    }
}

/// The slice API refuses an output of the wrong length (and writes nothing).
#[test]
fn fixed_modulus_slices_check_lengths() {
    use hockle::special::{FixedModulus, Jacobi};
    let fixed = FixedModulus::new(Modulus::from_m(0.5).unwrap());
    let mut out = [Jacobi::default(); 2];
    let err = fixed.jacobi_slice(&[0.1, 0.2, 0.3], &mut out).unwrap_err();
    assert!(matches!(
        err,
        hockle::Error::LengthMismatch {
            found: 2,
            expected: 3,
            ..
        }
    ));
    assert_eq!(out, [Jacobi::default(); 2]);
    let mut eps = [0.0; 4];
    assert!(fixed.epsilon_slice(&[0.1], &mut eps).is_err());
    assert!(fixed.jacobi_slice(&[], &mut []).is_ok());
}

/// FixedModulus takes the same special cases as the single-call functions.
#[test]
fn fixed_modulus_special_cases() {
    use hockle::special::{FixedModulus, jacobi, jacobi_epsilon};
    for mc in [0.0, 1.0, 1e-300, 5e-324] {
        let md = Modulus::from_complement(mc).unwrap();
        let fixed = FixedModulus::new(md);
        for u in [0.0, 0.7, -3.0, 1e300, f64::NAN, f64::INFINITY] {
            let (a, b) = (fixed.jacobi(u), jacobi(u, md));
            let same = |x: f64, y: f64| x == y || (x.is_nan() && y.is_nan());
            assert!(
                same(a.sn, b.sn) && same(a.cn, b.cn) && same(a.dn, b.dn),
                "{md} u = {u}"
            );
            assert!(
                same(fixed.epsilon(u), jacobi_epsilon(u, md)),
                "{md} u = {u}"
            );
        }
    }
}
