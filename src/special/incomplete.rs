//! Incomplete elliptic integrals F(φ, k) and E(φ, k) for any real φ.

use super::Modulus;
use super::complete::{ellip_e, ellip_k};
use super::half_argument::{e_half_argument, f_half_argument};
use super::near_one_coeffs::{
    A, ALPHA, BETA, Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8, R1, R2, R3, R4, R5, R6, R7,
};

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

/// sin a and cos a for 0 ≤ a ≤ π/2 (up to rounding), inline and without
/// branches: above π/4 the kernels run on t = (π/2)_hi − a + (π/2)_lo (the
/// subtraction is exact by Sterbenz) and sin and cos swap. The kernels are
/// fdlibm's minimax polynomials on [−π/4, π/4] (`__kernel_sin`,
/// `__kernel_cos` with the tail y of t). Measured against mpmath on 27 000
/// points of [0, π/2] (uniform, near π/2, tiny): ≤ 0.81 ulp for sin and
/// 0.78 ulp for cos (glibc: 0.51); the two libm calls they replace took
/// ~15 ns of a ~40 ns `ellip_f`, as they hardly overlap with the rest.
#[inline(always)]
fn sin_cos_half_pi(a: f64) -> (f64, f64) {
    const PIO2_HI: f64 = core::f64::consts::FRAC_PI_2;
    const PIO2_LO: f64 = 6.123_233_995_736_766e-17;
    // fdlibm k_sin.c S1–S6 and k_cos.c C1–C6 (shortest round-trip digits).
    const S: [f64; 6] = [
        -0.16666666666666632,
        0.00833333333332249,
        -0.0001984126982985795,
        2.7557313707070068e-06,
        -2.5050760253406863e-08,
        1.58969099521155e-10,
    ];
    const C: [f64; 6] = [
        0.0416666666666666,
        -0.001388888888887411,
        2.480158728947673e-05,
        -2.7557314351390663e-07,
        2.087572321298175e-09,
        -1.1359647557788195e-11,
    ];
    // |r| from `reduce_pi` is ≤ π/2 up to rounding, except for |φ| beyond
    // ~1e16 where r is noise anyway: keep the polynomials in range.
    let a = a.min(2.0);
    let swap = a > core::f64::consts::FRAC_PI_4;
    // t + y = π/2 − a to ~1e-32 (y the exact rounding error of t), or a.
    let th = PIO2_HI - a;
    let t = if swap { th + PIO2_LO } else { a };
    let y = if swap { (th - t) + PIO2_LO } else { 0.0 };
    let z = t * t;
    let z2 = z * z;
    let v = z * t;
    // sin(t + y) = t + y + t³ (S1 + z R(z)) − z y/2 …, polynomials by Estrin in z².
    let rs = (S[1] + z * S[2]) + z2 * ((S[3] + z * S[4]) + z2 * S[5]);
    let sin_t = t - ((z * (0.5 * y - v * rs) - y) - v * S[0]);
    let rc = z * ((C[0] + z * C[1]) + z2 * ((C[2] + z * C[3]) + z2 * (C[4] + z * C[5])));
    // fdlibm's split of 1 − z/2: for |t| ≥ 0.3 take qx ≈ t/4 (20 bits, so
    // 1 − qx is exact) out of it.
    let ta = t.abs();
    let qx = if ta < 0.3 {
        0.0
    } else if ta > 0.781_25 {
        0.281_25
    } else {
        f64::from_bits((0.25 * ta).to_bits() & 0xffff_ffff_0000_0000)
    };
    let cos_t = (1.0 - qx) - ((0.5 * z - qx) - (z * rc - t * y));
    if swap { (cos_t, sin_t) } else { (sin_t, cos_t) }
}

/// φ = jπ + r as [`reduce_pi`], with s = sin|r|, c = cos|r| ≥ 0: when
/// rounding leaves |r| a hair above π/2 (c < 0), the period count moves by
/// one so that the reduced angle π − |r| has c > 0.
#[inline(always)]
pub(crate) fn reduce_pi_sin_cos(phi: f64) -> (f64, f64, f64, f64) {
    let (mut j, mut r) = reduce_pi(phi);
    let (s, mut c) = sin_cos_half_pi(r.abs());
    if c < 0.0 {
        j += 1.0f64.copysign(r);
        r = -r;
        c = -c;
    }
    (j, r, s, c)
}

/// Near π/2 (c² < m₁ s²/4) the complementary amplitude ψ, tan ψ = cot r / k′
/// (DLMF 19.11.2 with ψ + r "adding up" to K), is small:
///
/// ```text
/// sin ψ = c/Δ,  cos ψ = k′ s/Δ,  F(r) = K − F(ψ),  E(r) = E − E(ψ) + m s sin ψ
/// ```
/// so F(r) and E(r) near K and E are the complete integrals minus a small
/// correction, and the duplication (F) or halving (E) starts from a small
/// amplitude instead of one whose argument u is near K (many more steps).
#[inline(always)]
fn folds(s: f64, c: f64, mc: f64) -> bool {
    c * c < 0.25 * mc * (s * s)
}

/// Δ = √(c² + m₁ s²).
#[inline(always)]
fn delta(s: f64, c: f64, mc: f64) -> f64 {
    (c * c + mc * s * s).sqrt()
}

/// ε = m₁ tan²φ up to which [`f_near_one`] and [`e_near_one`] are used
/// (with tan φ ≥ 2).
const NEAR_ONE_EPS: f64 = 1.0 / 64.0;

/// Whether r (sin r = s, cos r = c ≥ 0) lies where ε = m₁ tan²r ≤ 1/64 and
/// tan r ≥ 2, the region of [`f_near_one`] and [`e_near_one`].
#[inline(always)]
fn near_one(s: f64, c: f64, mc: f64) -> bool {
    c <= 0.5 * s && mc * (s * s) <= NEAR_ONE_EPS * (c * c)
}

/// p(m₁) by Horner, coefficient of m₁⁰ first.
#[inline(always)]
fn horner(p: &[f64], x: f64) -> f64 {
    let mut acc = 0.0;
    let mut k = p.len();
    while k > 0 {
        k -= 1;
        acc = p[k] + x * acc;
    }
    acc
}

/// F for ε = m₁ tan²φ ≤ 1/64 and tan φ ≥ 2 (so m₁ ≤ 1/256): the binomial
/// series of (1 + m₁ tan²θ)^{−1/2} integrated term by term,
///
/// ```text
/// F = A(m₁) asinh(tan φ) + (1/sin φ) Σ_{i=1..8} εⁱ Q_i(m₁),   A = 2K(m₁)/π
/// ```
/// (derivation and coefficients: `tests/data/gen_special_near_one.py`,
/// truncation ≤ 4e-19 of F). asinh(tan φ) = ln((1 + sin φ)/cos φ), one
/// logarithm of an exactly divided ratio ≥ 2 + √5, and A − 1 = O(m₁) and
/// the sum (≤ 1/64 of F) are added to it last. Near m = 1 with φ away
/// from π/2 by more than ~k′ this replaces four to six halvings (each a
/// division and two square roots).
#[inline(always)]
fn f_near_one(s: f64, c: f64, mc: f64) -> f64 {
    let eps = mc * (s * s) / (c * c);
    let (e2, e4) = (eps * eps, (eps * eps) * (eps * eps));
    let q = |a: &[f64], b: &[f64]| horner(a, mc) + eps * horner(b, mc);
    let corr = eps * ((q(&Q1, &Q2) + e2 * q(&Q3, &Q4)) + e4 * (q(&Q5, &Q6) + e2 * q(&Q7, &Q8)));
    let i0 = ((1.0 + s) / c).ln();
    i0 + (mc * horner(&A[1..], mc) * i0 + corr / s)
}

/// E for ε = m₁ tan²φ ≤ 1/64 and tan φ ≥ 2, as [`f_near_one`] with the
/// series of (1 + m₁ tan²θ)^{1/2}:
///
/// ```text
/// E = sin φ + m₁ (α(m₁) asinh(tan φ) + β(m₁) sin φ + (1/sin φ) Σ_{i=1..7} εⁱ R_i(m₁))
/// ```
/// (α, β, R_i: `tests/data/gen_special_near_one.py`, truncation ≤ 1e-18 of
/// E); everything after sin φ is O(m₁ ln(1/m₁)) and is added last.
#[inline(always)]
fn e_near_one(s: f64, c: f64, mc: f64) -> f64 {
    let eps = mc * (s * s) / (c * c);
    let (e2, e4) = (eps * eps, (eps * eps) * (eps * eps));
    let r = |a: &[f64], b: &[f64]| horner(a, mc) + eps * horner(b, mc);
    let corr = eps * ((r(&R1, &R2) + e2 * r(&R3, &R4)) + e4 * (r(&R5, &R6) + e2 * horner(&R7, mc)));
    let i0 = ((1.0 + s) / c).ln();
    s + mc * ((horner(&ALPHA[1..], mc) * i0 + horner(&BETA[1..], mc) * s) + corr / s)
}

/// F on 0 ≤ r ≤ π/2 from sin r, cos r ≥ 0: Δ = √(c² + m₁ s²) (never
/// 1 − m s², which cancels), then [`f_half_argument`], or [`f_near_one`]
/// where m₁ tan²r ≤ 1/64 and tan r ≥ 2.
#[inline(always)]
pub(crate) fn f_reduced(s: f64, c: f64, modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if near_one(s, c, mc) {
        return f_near_one(s, c, mc);
    }
    let d = delta(s, c, mc);
    if folds(s, c, mc) {
        // sin ψ = c/Δ, cos ψ = k′s/Δ, Δ(ψ) = k′/Δ: one division.
        let (kc, inv) = (mc.sqrt(), 1.0 / d);
        ellip_k(modulus) - f_half_argument(c * inv, kc * s * inv, kc * inv, m, mc)
    } else {
        f_half_argument(s, c, d, m, mc)
    }
}

/// E on 0 ≤ r ≤ π/2 from sin r, cos r ≥ 0.
#[inline(always)]
pub(crate) fn e_reduced(s: f64, c: f64, modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if near_one(s, c, mc) {
        return e_near_one(s, c, mc);
    }
    let d = delta(s, c, mc);
    if folds(s, c, mc) {
        let (kc, inv) = (mc.sqrt(), 1.0 / d);
        let sp = c * inv;
        let ep = e_half_argument(sp, kc * s * inv, kc * inv, m, mc);
        (ellip_e(modulus) - ep) + m * s * sp
    } else {
        e_half_argument(s, c, d, m, mc)
    }
}

/// Incomplete elliptic integral of the first kind F(φ, k), any real φ.
///
/// ```text
/// F(φ, k) = ∫0^φ dθ / √(1 − m sin²θ)                          DLMF 19.2.4
///         = 2jK + sgn(r) F(|r|, k),   φ = jπ + r, |r| ≤ π/2          DLMF 19.2.10
/// F(r, k) = 2ⁿ sn(uₙ) Σ_k P_k(m) yₙ^k/(2k + 1),  yₙ = sn²(u/2ⁿ) ≤ 0.07
/// ```
/// φ is reduced modulo π with π carried in double-double; 1 − m sin²φ is
/// formed as cos²φ + m₁ sin²φ so that φ → π/2, m → 1 loses nothing. The
/// argument u = F(r) itself is halved (half-argument transformation, after
/// Fukushima 2010) through sn²(u/2) = (1 − cn)/(1 + dn) (DLMF 22.6.19–21)
/// until sin² ≤ 0.07, where a 15-term series in sin² (P_k the coefficients
/// of ((1 − y)(1 − my))^{−1/2}) gives F(u/2ⁿ); near π/2 the complementary
/// amplitude folds F(r) to K − F(ψ). Near m = 1, where m₁ tan²r ≤ 1/64 and
/// tan r ≥ 2, the binomial series in m₁ tan²θ integrated term by term
/// replaces the halvings:
///
/// ```text
/// F(r, k) = A(m₁) asinh(tan r) + (1/sin r) Σ_{i=1..8} (m₁ tan²r)ⁱ Q_i(m₁),   A = 2K(k′)/π
/// ```
///
/// # Special cases
/// NaN or infinite φ gives NaN. F(0, k) = 0; F(φ, 0) = φ; F is odd in φ.
/// For k = 1 (m₁ = 0), F = atanh(sin φ) for |φ| < π/2 and ±∞ beyond.
///
/// # Accuracy
/// Max 1.08 ulp normalised by 1 + the condition number in φ (raw 3.85)
/// over 4620 points, |φ| ≤ 1e4, m₁ down to 1e-300 (1.34 on 20 000 random
/// points, where Carlson's R_F, the method before, measured 0.93).
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
/// DLMF §19.2, §22.6; T. Fukushima, *Fast computation of incomplete
/// elliptic integral of first kind by half argument transformation*,
/// Numer. Math. 116 (2010) 687–719.
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
/// E(r, k) = sin r + m₁ H(r),  H = ∫0^r sin²θ/(cos θ + Δ(θ)) dθ ≥ 0
/// ```
/// H by the half-argument transformation (after Fukushima 2011): the
/// argument u = F(r, k) is halved through sn²(u/2) = (1 − cn)/(1 + dn)
/// (DLMF 22.6.19) until sin² ≤ 0.04 (up to ½ for small m₁, where H weighs
/// little in E), H taken there from its Maclaurin
/// series in sin², and doubled back by a formula of positive terms (from
/// DLMF 22.16.27), so nothing cancels even as m → 1. Near r = π/2 the
/// complementary amplitude folds E(r) to E − E(ψ) + m sin r sin ψ. Where
/// m₁ tan²r ≤ 1/64 and tan r ≥ 2, E(r) = sin r + m₁(α(m₁) asinh(tan r) +
/// β(m₁) sin r + Σ (m₁ tan²r)ⁱ R_i(m₁)/sin r) instead, as for [`ellip_f`].
///
/// # Special cases
/// NaN or infinite φ gives NaN. E(0, k) = 0; E(φ, 0) = φ; E(φ, 1) = sin φ on
/// [−π/2, π/2]; E is odd in φ.
///
/// # Accuracy
/// Max 1.14 ulp normalised by 1 + the condition number in φ (raw 1.53)
/// over 4620 points, |φ| ≤ 1e4, m₁ down to 1e-300.
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
/// DLMF §19.2, §22.6, §22.16; T. Fukushima, *Precise and fast computation of
/// a general incomplete elliptic integral of second kind by half and double
/// argument transformations*, Math. Comp. 80 (2011) 1725–1743.
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
