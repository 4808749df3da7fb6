//! The small-k series against the exact branches: residual / k⁸ bounded.
//!
//! The expansion parameter is πnk, so k is drawn from [0.03/n, 0.1/n]. The
//! measured k⁸ coefficients (mpmath, n = 1..10) divided by the quantity's
//! scale (πn for Ω, π²n² for F, 1 for Δz) are at most 0.18 n² (α Ω) and
//! 1.6 n² (υ F, n = 1..10 fitted as 1.5n⁴/π²n²): the bound
//! BOUND(n) = 1 + 1.6 n² has room for the k¹⁰ term at k ≤ 0.1/n. Rounding
//! in the exact values (≈ 3ε relative, Ω − πn to ε·k²) contributes at most
//! 3ε·k²/k⁸ ≤ 0.5 at k = 0.003. A wrong k⁶ coefficient δ adds δ/k² ≥
//! 100 n² δ, e.g. 2.1 n² for the paper's misprint δ = 175/8192 in eq9/eq10:
//! the last test checks that the printed coefficients do fail.
use hockle::elastica::{Elastica, series};
use proptest::prelude::*;

fn bound(n: u32) -> f64 {
    1.0 + 1.6 * f64::from(n * n)
}

fn scaled_residuals(n: u32, k: f64) -> [f64; 8] {
    let s = Elastica::symmetric(n, k).unwrap();
    let t = Elastica::nonsymmetric(n, n, k).unwrap()[0];
    let pn = core::f64::consts::PI * f64::from(n);
    let k8 = k.powi(8);
    [
        // Ω − πn against its series, both without cancellation
        (s.upsilon.omega_excess() - series::upsilon_omega_excess(n, k)) / (pn * k8),
        (s.upsilon.force() - series::upsilon_force(n, k)) / (pn * pn * k8),
        (s.upsilon.extension() - series::upsilon_extension(n, k)) / k8,
        (s.alpha.omega_excess() - series::alpha_omega_excess(n, k)) / (pn * k8),
        (s.alpha.force() - series::alpha_force(n, k)) / (pn * pn * k8),
        (s.alpha.extension() - series::alpha_extension(n, k)) / k8,
        (t.extension() - series::theta_extension(k)) / k8,
        (t.force() - series::theta_force(n, k)) / (pn * pn * k8),
    ]
}

proptest! {
    #[test]
    fn each_series_is_good_to_k8(n in 1u32..=10, x in 0.03f64..0.1) {
        let k = x / f64::from(n);
        let r = scaled_residuals(n, k);
        for (i, v) in r.iter().enumerate() {
            prop_assert!(v.abs() < bound(n), "n = {}, k = {}, series #{}: residual/k⁸ = {}", n, k, i, v);
        }
    }
}

#[test]
fn the_printed_extension_coefficients_fail_the_same_check() {
    // eq9 and eq10 as printed (1225/8192 and 457/8192)
    let printed_u = |n: u32, k: f64| {
        let p = core::f64::consts::PI * f64::from(n);
        let m = k * k;
        m * (3.0 / 8.0 + m * (15.0 / 64.0 + m * (1225.0 / 8192.0 - p * p / 96.0)))
    };
    let printed_a = |n: u32, k: f64| {
        let p = core::f64::consts::PI * f64::from(n);
        let m = k * k;
        m * (3.0 / 8.0 + m * (9.0 / 64.0 + m * (457.0 / 8192.0 - p * p / 96.0)))
    };
    for n in 1..=10u32 {
        let k = 0.03 / f64::from(n);
        let s = Elastica::symmetric(n, k).unwrap();
        let ru = (s.upsilon.extension() - printed_u(n, k)) / k.powi(8);
        let ra = (s.alpha.extension() - printed_a(n, k)) / k.powi(8);
        assert!(
            ru.abs() > bound(n) && ra.abs() > bound(n),
            "n = {n}: {ru}, {ra}"
        );
    }
}

#[test]
fn linear_responses_and_the_factor_three() {
    for n in 1..=10u32 {
        let k = 1e-4;
        let s = Elastica::symmetric(n, k).unwrap();
        let t = Elastica::nonsymmetric(n, n, k).unwrap()[0];
        // F/Δz at k = 1e-4 differs from the slope by O(k²) = 1e-8 relative
        for e in [s.upsilon, s.alpha] {
            let slope = e.force() / e.extension();
            assert!(
                (slope / series::symmetric_stiffness(n) - 1.0).abs() < 1e-7,
                "{slope}"
            );
        }
        let slope = t.force() / t.extension();
        assert!((slope / series::nonsymmetric_stiffness(n) - 1.0).abs() < 1e-7);
        assert!(
            (series::nonsymmetric_stiffness(n) / series::symmetric_stiffness(n) - 3.0).abs()
                < 1e-15
        );
    }
}
