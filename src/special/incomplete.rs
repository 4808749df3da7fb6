//! Incomplete elliptic integrals F(φ, k) and E(φ, k) for any real φ.

use super::Modulus;
use super::carlson::{rd, rf};
use super::complete::{ellip_e, ellip_k};

/// π split as a double-double: `PI_HI + PI_LO` = π to ~1e-32.
pub(crate) const PI_HI: f64 = core::f64::consts::PI;
pub(crate) const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

/// φ = jπ + r with |r| ≤ π/2 (up to rounding), r accurate to ~1 ulp of r
/// for |j| < 2⁵³: j·π is formed as a double-double, and φ − fl(jπ) is exact
/// by Sterbenz's lemma.
pub(crate) fn reduce_pi(phi: f64) -> (f64, f64) {
    let j = (phi / PI_HI).round_ties_even();
    if j == 0.0 {
        return (0.0, phi);
    }
    let p = j * PI_HI;
    let e = j.mul_add(PI_HI, -p); // exact error of j·PI_HI
    let r = (phi - p) - e - j * PI_LO;
    (j, r)
}

/// φ = jπ + r as [`reduce_pi`], with s = sin|r|, c = cos|r| ≥ 0: when
/// rounding leaves |r| a hair above π/2 (c < 0), the period count moves by
/// one so that the reduced angle π − |r| has c > 0.
fn reduce_pi_sin_cos(phi: f64) -> (f64, f64, f64, f64) {
    let (mut j, mut r) = reduce_pi(phi);
    let (s, mut c) = r.abs().sin_cos();
    if c < 0.0 {
        j += 1.0f64.copysign(r);
        r = -r;
        c = -c;
    }
    (j, r, s, c)
}

/// F and E on 0 ≤ r ≤ π/2 from sin r, cos r (c = cos r ≥ 0).
///
/// ```text
/// Δ² = c² + m₁ s²                        (never 1 − m s², which cancels)
/// F  = s R_F(c², Δ², 1)                  DLMF 19.25.5
/// E  = m₁ F + (m m₁/3) s³ R_D(c², 1, Δ²) + m s c / Δ      DLMF 19.25.9
/// ```
pub(crate) fn f_e_reduced(s: f64, c: f64, modulus: Modulus) -> (f64, f64) {
    let (m, mc) = (modulus.m(), modulus.complement());
    let c2 = c * c;
    let d2 = c2 + mc * s * s;
    let f = s * rf(c2, d2, 1.0);
    let e = mc * f + m * mc / 3.0 * s * s * s * rd(c2, 1.0, d2) + m * s * c / d2.sqrt();
    (f, e)
}

/// Incomplete elliptic integral of the first kind F(φ, k), any real φ.
///
/// ```text
/// F(φ, k) = ∫0^φ dθ / √(1 − m sin²θ)                          DLMF 19.2.4
///         = 2jK + sgn(r) sin|r| R_F(cos²r, cos²r + m₁ sin²r, 1),  φ = jπ + r, |r| ≤ π/2
/// ```
/// (DLMF 19.25.5 and the quasi-periodicity F(φ + jπ) = F(φ) + 2jK, 19.2.10).
/// φ is reduced modulo π with π carried in double-double; 1 − m sin²φ is
/// formed as cos²φ + m₁ sin²φ so that φ → π/2, m → 1 loses nothing.
///
/// # Special cases
/// NaN or infinite φ gives NaN. F(0, k) = 0; F(φ, 0) = φ; F is odd in φ.
/// For k = 1 (m₁ = 0), F = atanh(sin φ) for |φ| < π/2 and ±∞ beyond.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_f, ellip_k};
/// let k = Modulus::from_m(0.5)?;
/// let f = ellip_f(1.0, k);
/// assert!((f - 1.083_216_772_845_168_8).abs() < 1e-15); // mpmath ellipf(1, 0.5)
/// assert!((ellip_f(1.0 + 3.0 * std::f64::consts::PI, k) - (f + 6.0 * ellip_k(k))).abs() < 1e-14);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §19.2, §19.25; B. C. Carlson, Numer. Algorithms 10 (1995) 13–26.
#[must_use]
pub fn ellip_f(phi: f64, modulus: Modulus) -> f64 {
    if !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r, s, c) = reduce_pi_sin_cos(phi);
    let f = f_e_reduced(s, c, modulus).0.copysign(r);
    if j == 0.0 {
        f
    } else {
        2.0 * j * ellip_k(modulus) + f
    }
}

/// Incomplete elliptic integral of the second kind E(φ, k), any real φ.
///
/// ```text
/// E(φ, k) = ∫0^φ √(1 − m sin²θ) dθ                            DLMF 19.2.5
///         = 2jE + sgn(r) E(|r|, k),   φ = jπ + r, |r| ≤ π/2     DLMF 19.2.10
/// E(r, k) = m₁ F(r, k) + (m m₁/3) s³ R_D(c², 1, Δ²) + m s c/Δ,  s = sin r, c = cos r,
///           Δ² = c² + m₁ s²                                     DLMF 19.25.9
/// ```
/// All three terms are non-negative on [0, π/2], so nothing cancels even as
/// m → 1 (the textbook s R_F − (m/3) s³ R_D loses digits there).
///
/// # Special cases
/// NaN or infinite φ gives NaN. E(0, k) = 0; E(φ, 0) = φ; E(φ, 1) = sin φ on
/// [−π/2, π/2]; E is odd in φ.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_e_inc};
/// let k = Modulus::from_m(0.5)?;
/// assert!((ellip_e_inc(1.0, k) - 0.927_329_883_624_440_1).abs() < 1e-15); // mpmath ellipe(1, 0.5)
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §19.2, §19.25.
#[must_use]
pub fn ellip_e_inc(phi: f64, modulus: Modulus) -> f64 {
    if !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r, s, c) = reduce_pi_sin_cos(phi);
    let e = f_e_reduced(s, c, modulus).1.copysign(r);
    if j == 0.0 {
        e
    } else {
        2.0 * j * ellip_e(modulus) + e
    }
}
