//! E(φ|m) and F(φ|m) on [0, π/2] by the half-argument transformation and
//! Maclaurin series in y = sin²φ (after T. Fukushima, Math. Comp. 80
//! (2011) 1725–1743 and Numer. Math. 116 (2010) 687–719), E in a form with
//! no cancellation (crate-private; F at [`f_half_argument`]).
//!
//! With u = F(φ|m), s = sn u = sin φ, c = cn u = cos φ, d = dn u = Δ(φ),
//! y = s², write E as sin φ plus a positive remainder:
//!
//! ```text
//! E(φ|m) = s + m₁ H,   H = ∫0^φ sin²θ / (cos θ + Δ(θ)) dθ ≥ 0
//! ```
//! (the integrand of E − sin φ is Δ − cos θ = m₁ sin²θ/(cos θ + Δ)). H is
//! evaluated by halving u until y ≤ 0.04 (more for small m₁, [`reach`]),
//! the series there, and
//! doubling back:
//!
//! ```text
//! sn²(u/2) = (1 − c)/(1 + d) = y/((1 + c)(1 + d)),  cn²(u/2) = (c + d)/(1 + d),
//! dn²(u/2) = (m₁ + d + m c)/(1 + d)                                    DLMF 22.6.19–21
//! H(u) = s y Σ h_k(m) y^{k−1},  k = 1…12                              (`h_series.rs`)
//! H(2u) = 2 H(u) + 2 s y (m₁ y + c d² (c + d)) / ((c + d)² (c² (1 + y) + m₁ y²))
//! ```
//! The doubling step follows from the addition formula
//! E(2u) = 2E(u) − m sn²u sn 2u (DLMF 22.16.27) with sn 2u = 2scd/(1 − m y²)
//! (22.8.20), after the differences are cleared by hand
//! (d − c = m₁ y/(c + d), 1 − m y² = c²(1 + y) + m₁ y²): every term is
//! positive, so rounding errors do not grow as they are doubled. (The
//! textbook pair B = ∫cos²/Δ, D = ∫sin²/Δ with B(2u) = 2B(u) − sn²u sn 2u
//! cancels near φ = π/2, m = 1: measured 28 ulp.) Against Carlson's
//! R_F + R_D (the method before): no R_D series, no R_F at all, and the
//! steps need one division and two square roots, not three square roots.

use super::h_series::{H, REACH};

/// At most this many halvings: u ≤ K < 374 for every m₁ > 0 reaches
/// y ≤ 0.04 in ≤ 12.
const MAX_HALVINGS: usize = 64;

/// The y = sin² below which the series is used: 0.0445 for m₁ ≥ ⅛ (its 12
/// terms leave ≤ 2⁻⁵⁷ of H), rising to ½ for m₁ < 2⁻⁴⁸, since H weighs
/// only m₁H/E ≤ 1.25 m₁ ln(16/m₁) in E and a coarser H suffices (table by
/// the binary exponent of m₁, checked against the series' true tail by
/// `tests/data/gen_special_halfarg.py`). Fewer halvings near m = 1: E(φ)
/// 57 → 50 ns on the bench's extreme set, same accuracy.
#[inline(always)]
fn reach(mc: f64) -> f64 {
    let e = ((mc.to_bits() >> 52) & 0x7ff) as i32 - 1023; // m₁ ∈ [2^e, 2^(e+1))
    REACH[((-e).clamp(1, 64) - 1) as usize]
}

/// h_1(m) … h_12(m), each a polynomial of degree k − 1 with positive
/// coefficients (Horner, independent of each other).
#[inline(always)]
fn coefficients(m: f64) -> [f64; 12] {
    let mut h = [0.0; 12];
    for (hk, p) in h.iter_mut().zip(H) {
        *hk = p.iter().rev().fold(0.0, |acc, &c| c + m * acc);
    }
    h
}

/// Σ h_k y^{k−1} (12 terms) by Estrin's scheme.
#[inline(always)]
fn series(h: &[f64; 12], y: f64) -> f64 {
    let y2 = y * y;
    let y4 = y2 * y2;
    let q = |i: usize| h[i] + h[i + 1] * y;
    ((q(0) + q(2) * y2) + (q(4) + q(6) * y2) * y4) + (q(8) + q(10) * y2) * (y4 * y4)
}

/// One halving: (y, c, d) at u/2 from (y, c, d) at u. While c < ½,
/// sn²(u/2) = (1 − c)/(1 + d) keeps every digit (y/((1 + c)(1 + d)) would
/// stay at y = 1 when 1 + c rounds to 1); above, 1 − c would cancel.
#[inline(always)]
fn halve(y: f64, c: f64, d: f64, m: f64, mc: f64) -> (f64, f64, f64) {
    let inv = 1.0 / (1.0 + d);
    let y2 = if c < 0.5 {
        (1.0 - c) * inv
    } else {
        y * inv / (1.0 + c)
    };
    (y2, ((c + d) * inv).sqrt(), ((mc + d + m * c) * inv).sqrt())
}

/// E(r|m) for 0 ≤ r ≤ π/2 from s = sin r, c = cos r ≥ 0, d = Δ(r) (so
/// y = s²; m₁ = `mc`).
#[inline(always)]
pub(crate) fn e_half_argument(s: f64, c: f64, d: f64, m: f64, mc: f64) -> f64 {
    if mc == 0.0 {
        return s; // E(r|1) = sin r
    }
    let h = coefficients(m);
    let delta = reach(mc);
    let (mut y, mut c, mut d) = (s * s, c, d);
    let mut sn = s;
    // H = Σ 2^{j−1} T_j + 2ⁿ H_n, T_j the doubling term at level j.
    let (mut sum, mut scale) = (0.0, 1.0);
    let mut n = 0;
    while y > delta && n < MAX_HALVINGS {
        (y, c, d) = halve(y, c, d, m, mc);
        n += 1;
        sn = y.sqrt();
        let cd = c + d;
        let t =
            2.0 * sn * y * (mc * y + c * d * d * cd) / (cd * cd * (c * c * (1.0 + y) + mc * y * y));
        sum += scale * t;
        scale *= 2.0;
    }
    s + mc * (sum + scale * (sn * y * series(&h, y)))
}

/// Halving stops for F once y = sin² ≤ this: the 15-term series below then
/// leaves ≤ 0.07¹⁵/31 < 2⁻⁶² of F (its coefficients are ≤ 1 for m ≤ 1).
const F_REACH: f64 = 0.07;

/// F(r|m) for 0 ≤ r ≤ π/2 from s = sin r, c = cos r ≥ 0, d = Δ(r), by the
/// half-argument transformation: F(u) = u, so halving u (as for E) until
/// y ≤ 0.07 and multiplying by 2ⁿ is exact, and at the small amplitude
///
/// ```text
/// F = s Σ P_k(m) y^k / (2k + 1),   y = s²,  k = 0…14
/// P_k = [y^k] ((1 − y)(1 − m y))^{−1/2}
///     = ((2k − 1)/(2k)) (1 + m) P_{k−1} − ((k − 1)/k) m P_{k−2},   P₀ = 1, P₁ = (1 + m)/2
/// ```
/// (the binomial series of 1/Δ integrated term by term; the recurrence is
/// that of the Legendre functions, as ((1 − y)(1 − my))^{−1/2} is their
/// generating function in disguise, and only depends on m, so it runs
/// beside the halvings). A halving here takes one division,
/// 1/((1 + c)(1 + d)), for y and for 1/(1 + d) alike, so the loop's exit
/// test gets y early.
#[inline(always)]
pub(crate) fn f_half_argument(s: f64, c: f64, d: f64, m: f64, mc: f64) -> f64 {
    let e1 = 1.0 + m;
    let mut p = [0.0; 15];
    p[0] = 1.0;
    p[1] = 0.5 * e1;
    for k in 2..15 {
        let kf = k as f64;
        p[k] = ((2.0 * kf - 1.0) / (2.0 * kf)) * e1 * p[k - 1] - ((kf - 1.0) / kf) * m * p[k - 2];
    }
    let (mut y, mut c, mut d) = (s * s, c, d);
    let (mut sn, mut scale) = (s, 1.0);
    let mut n = 0;
    while y > F_REACH && n < MAX_HALVINGS {
        let (pc, pd) = (1.0 + c, 1.0 + d);
        let inv = 1.0 / pd;
        // While c < ½, sn²(u/2) = (1 − c)/(1 + d) keeps every digit (see
        // `halve`); above, y/((1 + c)(1 + d)).
        let (num, den) = if c < 0.5 { (1.0 - c, pd) } else { (y, pc * pd) };
        (y, c, d) = (
            num / den,
            ((c + d) * inv).sqrt(),
            ((mc + d + m * c) * inv).sqrt(),
        );
        sn = y.sqrt();
        scale *= 2.0;
        n += 1;
    }
    let a = |k: usize| p[k] * (1.0 / (2 * k + 1) as f64);
    let y2 = y * y;
    let y4 = y2 * y2;
    let q = |k: usize| a(k) + a(k + 1) * y;
    let series = ((q(0) + q(2) * y2) + (q(4) + q(6) * y2) * y4)
        + ((q(8) + q(10) * y2) + (q(12) + a(14) * y2) * y4) * (y4 * y4);
    scale * sn * series
}
