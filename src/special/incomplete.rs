//! Incomplete elliptic integrals F(φ, k) and E(φ, k) for any real φ.

use super::Modulus;
use super::carlson::{rf_rd_roots, rf_roots};
use super::complete::{ellip_e, ellip_k};

/// π split as a double-double: `PI_HI + PI_LO` = π to ~1e-32.
pub(crate) const PI_HI: f64 = core::f64::consts::PI;
pub(crate) const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

/// x rounded to the nearest integer, ties to even, by the 1.5·2⁵² trick for
/// |x| < 2⁵¹ (without SSE4.1 `f64::round_ties_even` is a library call).
#[inline(always)]
pub(crate) fn round_ties_even(x: f64) -> f64 {
    const MAGIC: f64 = 6_755_399_441_055_744.0;
    if x.abs() < 2_251_799_813_685_248.0 {
        (x + MAGIC) - MAGIC
    } else {
        x.round_ties_even()
    }
}

/// π in three parts (Cody–Waite): `PI_A` and `PI_B` have 33 significant
/// bits, so j·PI_A and j·PI_B are exact for |j| < 2²⁰; the sum is π to
/// 2e-37.
const PI_A: f64 = 3.141_592_653_468_251_2;
const PI_B: f64 = 1.215_420_101_260_793_2e-10;
const PI_C: f64 = 4.044_532_497_591_901e-21;

/// φ = jπ + r with |r| ≤ π/2 (up to rounding), r accurate to ~1 ulp of r:
/// φ − j·PI_A is exact (Sterbenz), the later parts only round once each.
/// Beyond |j| = 2²⁰ the products are formed exactly with FMA instead.
pub(crate) fn reduce_pi(phi: f64) -> (f64, f64) {
    // j may be off by one at half-way points; the caller fixes c < 0.
    let j = round_ties_even(phi * core::f64::consts::FRAC_1_PI);
    if j == 0.0 {
        return (0.0, phi);
    }
    if j.abs() < 1_048_576.0 {
        return (j, ((phi - j * PI_A) - j * PI_B) - j * PI_C);
    }
    let p = j * PI_HI;
    let e = j.mul_add(PI_HI, -p); // exact error of j·PI_HI
    (j, (phi - p) - e - j * PI_LO)
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

/// F and E on 0 ≤ r ≤ π/2 from s = sin r, c = cos r ≥ 0, without folding.
///
/// ```text
/// Δ² = c² + m₁ s²                        (never 1 − m s², which cancels)
/// F  = s R_F(c², Δ², 1)                  DLMF 19.25.5
/// E  = m₁ F + (m m₁/3) s³ R_D(c², 1, Δ²) + m s c / Δ      DLMF 19.25.9
/// ```
#[inline]
fn f_direct(s: f64, c: f64, mc: f64) -> f64 {
    let c2 = c * c;
    let d2 = c2 + mc * s * s;
    s * rf_roots(c2, d2, 1.0, c, d2.sqrt(), 1.0)
}

#[inline]
fn e_direct(s: f64, c: f64, m: f64, mc: f64) -> f64 {
    let c2 = c * c;
    let d2 = c2 + mc * s * s;
    let d = d2.sqrt();
    let (rf, rd) = rf_rd_roots(c2, 1.0, d2, c, 1.0, d);
    mc * (s * rf) + m * mc * (1.0 / 3.0) * (s * s * s) * rd + m * s * c / d
}

/// Near π/2 (c² < m₁ s²/4) the complementary amplitude ψ, tan ψ = cot r / k′
/// (DLMF 19.11.2 with ψ + r "adding up" to K), is small:
///
/// ```text
/// sin ψ = c/Δ,  cos ψ = k′ s/Δ,  F(r) = K − F(ψ),  E(r) = E − E(ψ) + m s sin ψ
/// ```
/// so E(r) near E is the complete E minus a small correction instead of an
/// R_D term of size ~1 (its ~2-ulp error would show, as r → π/2 and m → 1
/// leave E(r) with condition number ~0).
fn folds(s: f64, c: f64, mc: f64) -> bool {
    c * c < 0.25 * mc * (s * s)
}

fn psi(s: f64, c: f64, mc: f64) -> (f64, f64) {
    let d = (c * c + mc * s * s).sqrt();
    (c / d, mc.sqrt() * s / d)
}

/// F on 0 ≤ r ≤ π/2 from sin r, cos r ≥ 0.
pub(crate) fn f_reduced(s: f64, c: f64, modulus: Modulus) -> f64 {
    let mc = modulus.complement();
    if folds(s, c, mc) {
        let (sp, cp) = psi(s, c, mc);
        ellip_k(modulus) - f_direct(sp, cp, mc)
    } else {
        f_direct(s, c, mc)
    }
}

/// E on 0 ≤ r ≤ π/2 from sin r, cos r ≥ 0.
pub(crate) fn e_reduced(s: f64, c: f64, modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if folds(s, c, mc) {
        let (sp, cp) = psi(s, c, mc);
        let ep = e_direct(sp, cp, m, mc);
        (ellip_e(modulus) - ep) + m * s * sp
    } else {
        e_direct(s, c, m, mc)
    }
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
/// # Accuracy
/// Max 1.83 ulp (1.18 ulp normalised by 1 + the condition number in φ)
/// over 2120 points, |φ| ≤ 100, m₁ down to 1e-300.
/// See the [module docs](crate::special#accuracy) for the table.
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
#[inline]
pub fn ellip_f(phi: f64, modulus: Modulus) -> f64 {
    if !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r, s, c) = reduce_pi_sin_cos(phi);
    let f = f_reduced(s, c, modulus).copysign(r);
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
/// # Accuracy
/// Max 2.76 ulp (1.38 normalised by 1 + the condition number in φ) over 2120 points, |φ| ≤ 100, m₁ down
/// to 1e-300.
/// See the [module docs](crate::special#accuracy) for the table.
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
#[inline]
pub fn ellip_e_inc(phi: f64, modulus: Modulus) -> f64 {
    if !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r, s, c) = reduce_pi_sin_cos(phi);
    let e = e_reduced(s, c, modulus).copysign(r);
    if j == 0.0 {
        e
    } else {
        2.0 * j * ellip_e(modulus) + e
    }
}
