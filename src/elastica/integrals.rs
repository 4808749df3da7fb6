//! Cancellation-free pieces for small m: K − π/2 and the integral
//! I(φ) = ∫ sin²2ψ / Δ³(ψ) dψ, Δ = √(1 − m sin²ψ), that carries the
//! extension once the O(1) parts of eq8 are integrated by parts.

use core::f64::consts::{FRAC_PI_2, PI};
use std::sync::OnceLock;

use crate::quadrature::GaussLegendre;

/// Below this m the cancellation-free forms are used; above it the closed
/// forms lose at most a factor 2/m ≤ 8 to cancellation (measured ≤ 2e-14).
pub(crate) const SMALL_M: f64 = 0.25;

/// K(m) − π/2 without cancellation for m < ½:
/// (π/2) Σ_{i≥1} ((2i−1)!!/(2i)!!)² mⁱ (DLMF 19.5.1), summed until the terms
/// are below ε of the sum; `big_k` − π/2 otherwise.
pub(crate) fn k_minus_half_pi(m: f64, big_k: f64) -> f64 {
    if m >= 0.5 {
        return big_k - FRAC_PI_2;
    }
    let mut c = 1.0_f64; // (2i−1)!!/(2i)!!
    let mut mp = 1.0_f64;
    let mut sum = 0.0_f64;
    for i in 1..200 {
        let fi = f64::from(i);
        c *= (2.0 * fi - 1.0) / (2.0 * fi);
        mp *= m;
        let term = c * c * mp;
        sum += term;
        if term <= 1e-17 * sum {
            break;
        }
    }
    FRAC_PI_2 * sum
}

fn integrand(m: f64, psi: f64) -> f64 {
    let (s, c) = psi.sin_cos();
    let s2 = 2.0 * s * c;
    let d2 = 1.0 - m * s * s;
    s2 * s2 / (d2 * d2.sqrt())
}

/// I_π = ∫_0^π sin²2ψ/Δ³ dψ by the 24-point trapezoidal rule on the period.
/// The integrand is π-periodic, even about 0 and π/2 and vanishes there, so
/// 11 evaluations suffice; it is analytic in the strip |Im ψ| < acosh(1/√m)
/// (≥ 1.31 for m < ¼), so the error is below e^(−2·24·1.31) ≈ 1e-27.
pub(crate) fn i_period(m: f64) -> f64 {
    const N: usize = 24;
    let h = PI / N as f64;
    let half: f64 = (1..N / 2).map(|i| integrand(m, i as f64 * h)).sum();
    2.0 * half * h
}

/// 10-point Gauss–Legendre on [lo, hi] (length ≤ π/4: Bernstein ratio
/// ≥ 6.8 for m < ¼, error ≲ 6.8^−20 ≈ 1e-17 relative), with the crate's one
/// rule ([`GaussLegendre`]).
fn gl10(m: f64, lo: f64, hi: f64) -> f64 {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    let rule = RULE.get_or_init(|| GaussLegendre::new(10));
    let h = hi - lo;
    let acc: f64 = rule
        .nodes
        .iter()
        .zip(&rule.weights)
        .map(|(x, w)| w * integrand(m, lo + h * x))
        .sum();
    acc * h
}

/// ∫_0^r sin²2ψ/Δ³ dψ for |r| ≤ π/2 (odd in r), from the shorter of [0, r]
/// and [r, π/2] (the integrand is symmetric about π/2, ∫_0^{π/2} = I_π/2).
fn partial(m: f64, r: f64, per: f64) -> f64 {
    let a = r.abs();
    let v = if a <= 0.25 * PI {
        gl10(m, 0.0, a)
    } else {
        0.5 * per - gl10(m, a, FRAC_PI_2)
    };
    v.copysign(r)
}

/// ∫_{φ1}^{φ2} sin²2ψ/Δ³ dψ for m < [`SMALL_M`].
pub(crate) fn i_between(m: f64, phi1: f64, phi2: f64) -> f64 {
    let per = i_period(m);
    let j = |phi: f64| {
        let q = (phi / PI).round();
        q * per + partial(m, phi - q * PI, per)
    };
    j(phi2) - j(phi1)
}
