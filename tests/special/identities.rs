//! Identities as property tests (DLMF 22.6.1, 22.4.3, 19.7.1, 22.16.20).
//!
//! Tolerances follow from the accuracy bars: each function is within
//! 4 ulp·(1 + cond) of the truth (measured max ≤ 4, see `accuracy`), i.e. an
//! absolute error ≤ 4ε(|f| + |u f′|). A shifted argument u + P is also
//! rounded, adding |f′|·ε|u + P|/2. With |sn|, |cn|, |dn|, |f′| ≤ 1 that
//! sums to the `10ε(1 + |u|)`-type bounds below.

use hockle::special::{Modulus, ellip_e, ellip_e_inc, ellip_f, ellip_k, jacobi, jacobi_epsilon};
use proptest::prelude::*;

const EPS: f64 = f64::EPSILON;

/// Moduli: m uniform in [0, 1] (`from_m`) or m₁ log-uniform in
/// [1e-300, 1] (`from_complement`).
fn modulus() -> impl Strategy<Value = Modulus> {
    prop_oneof![
        (0.0f64..=1.0).prop_map(|m| Modulus::from_m(m).unwrap()),
        (0.0f64..300.0).prop_map(|e| Modulus::from_complement(10f64.powf(-e)).unwrap()),
    ]
}

/// Arguments up to |u| = 1e4, log-uniform in magnitude, either sign.
fn arg() -> impl Strategy<Value = f64> {
    (-3.0f64..4.0, any::<bool>()).prop_map(|(e, neg)| {
        let u = 10f64.powf(e);
        if neg { -u } else { u }
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// sn² + cn² = 1 and dn² + m sn² = 1 (DLMF 22.6.1): sums of two terms
    /// each within ~4 ulp (relative) of the truth: ≤ 8ε, plus rounding.
    #[test]
    fn pythagoras(md in modulus(), u in arg()) {
        let j = jacobi(u, md);
        let one = j.sn * j.sn + j.cn * j.cn;
        prop_assert!((one - 1.0).abs() <= 10.0 * EPS, "sn²+cn²−1 = {:e}", one - 1.0);
        let one = j.dn * j.dn + md.m() * j.sn * j.sn;
        prop_assert!((one - 1.0).abs() <= 10.0 * EPS, "dn²+m sn²−1 = {:e}", one - 1.0);
    }

    /// Legendre's relation E K′ + E′ K − K K′ = π/2 (DLMF 19.7.1). Each
    /// product carries ≤ 2 ulp (K, E ≤ 1 ulp each, measured), so the sum
    /// carries ≤ 3ε·(E K′ + E′ K + K K′) plus the final roundings.
    #[test]
    fn legendre(md in modulus()) {
        prop_assume!(md.m() > 0.0 && md.complement() > 0.0);
        let (k, e) = (ellip_k(md), ellip_e(md));
        let (kp, ep) = (ellip_k(md.complementary()), ellip_e(md.complementary()));
        let lhs = e * kp + ep * k - k * kp;
        let scale = e * kp + ep * k + k * kp;
        prop_assert!(
            (lhs - std::f64::consts::FRAC_PI_2).abs() <= 4.0 * EPS * scale,
            "Legendre: {lhs} (scale {scale})"
        );
    }

    /// sn, cn have period 4K, dn period 2K; sn(u+2K) = −sn u, cn(u+2K) = −cn u;
    /// am(u + 2K) = am u + π (DLMF 22.4.1, 22.16.2).
    #[test]
    fn periods(md in modulus(), u in arg()) {
        prop_assume!(md.complement() > 0.0);
        let k = ellip_k(md);
        let u2 = u + 2.0 * k;
        let u4 = u + 4.0 * k;
        let (a, b, c) = (jacobi(u, md), jacobi(u2, md), jacobi(u4, md));
        // |f′| ≤ 1 for sn, cn, dn, am′ = dn ≤ 1: bar 4ε(1 + |x|) for the
        // value at x, once at u and once at the shifted x, plus ε|x|/2 for
        // rounding x = u + P.
        let tol = |x: f64| 10.0 * EPS * (1.0 + x.abs() + u.abs());
        prop_assert!((c.sn - a.sn).abs() <= tol(u4), "sn 4K: {} vs {}", c.sn, a.sn);
        prop_assert!((c.cn - a.cn).abs() <= tol(u4), "cn 4K: {} vs {}", c.cn, a.cn);
        prop_assert!((b.sn + a.sn).abs() <= tol(u2), "sn 2K: {} vs {}", b.sn, a.sn);
        prop_assert!((b.cn + a.cn).abs() <= tol(u2), "cn 2K: {} vs {}", b.cn, a.cn);
        prop_assert!((b.dn - a.dn).abs() <= tol(u2), "dn 2K: {} vs {}", b.dn, a.dn);
        let pi = std::f64::consts::PI;
        prop_assert!(
            (b.am - a.am - pi).abs() <= tol(u2) + 4.0 * EPS * (a.am.abs() + pi),
            "am 2K: {} vs {}", b.am, a.am
        );
    }

    /// Quarter period (DLMF 22.4.3): sn(u+K) = cd u, cn(u+K) = −k′ sd u,
    /// dn(u+K) = k′ nd u. The quotients divide by dn ≥ k′, so the bound
    /// is the period bound over k′²; m ≤ 0.99 keeps k′² ≥ 0.01.
    #[test]
    fn quarter_period(m in 0.0f64..0.99, u in arg()) {
        let md = Modulus::from_m(m).unwrap();
        let k = ellip_k(md);
        let (a, b) = (jacobi(u, md), jacobi(u + k, md));
        let kp = md.k_prime();
        let tol = 10.0 * EPS * (1.0 + u.abs() + (u + k).abs()) / md.complement();
        prop_assert!((b.sn - a.cd()).abs() <= tol, "sn(u+K) {} vs cd {}", b.sn, a.cd());
        prop_assert!((b.cn + kp * a.sd()).abs() <= tol, "cn(u+K) {} vs −k′sd {}", b.cn, -kp * a.sd());
        prop_assert!((b.dn - kp * a.nd()).abs() <= tol, "dn(u+K) {} vs k′nd {}", b.dn, kp * a.nd());
    }

    /// ε(u + 2K) = ε(u) + 2E (DLMF 22.16.20, ε′ = dn² ≤ 1) and
    /// F(φ + π) = F(φ) + 2K, E(φ + π) = E(φ) + 2E (DLMF 19.2.10).
    #[test]
    fn quasi_periods(md in modulus(), u in arg()) {
        prop_assume!(md.complement() > 0.0);
        let (k, e) = (ellip_k(md), ellip_e(md));
        let u2 = u + 2.0 * k;
        let (a, b) = (jacobi_epsilon(u, md), jacobi_epsilon(u2, md));
        let tol = 10.0 * EPS * (1.0 + u.abs() + u2.abs() + a.abs() + 2.0 * e);
        prop_assert!((b - a - 2.0 * e).abs() <= tol, "ε: {b} vs {a} + 2E");
        // F′ = 1/Δ ≤ 1/k′ and F ~ φ/k′ in size: scale the bound by 1/k′
        // (the normalised bar is ≤ 2 ulp of (1 + cond), cond·F = φ/Δ).
        let phi = u.clamp(-100.0, 100.0);
        let p2 = phi + std::f64::consts::PI;
        let (f1, f2) = (ellip_f(phi, md), ellip_f(p2, md));
        let tolf = 10.0 * EPS * (f1.abs() + f2.abs() + 2.0 * k + p2.abs() / md.k_prime());
        prop_assert!((f2 - f1 - 2.0 * k).abs() <= tolf, "F: {f2} vs {f1} + 2K");
        let (e1, e2) = (ellip_e_inc(phi, md), ellip_e_inc(p2, md));
        let tole = 10.0 * EPS * (e1.abs() + e2.abs() + 2.0 * e + p2.abs());
        prop_assert!((e2 - e1 - 2.0 * e).abs() <= tole, "E(φ): {e2} vs {e1} + 2E");
    }
}
