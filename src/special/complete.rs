//! Complete elliptic integrals K(k) and E(k).

use super::Modulus;
use super::coeffs::{E_PIECES, K_PIECES, PIECE_OF, PK, QK, RE, SE};
use super::poly::Poly;

/// floor(1280 m) for m ∈ [0, 0.95), the index into `PIECE_OF`, by the
/// 1.5·2⁵² rounding trick: 1280 m − ½ ∈ [−½, 1215.5) rounded to an integer
/// lands in the low bits (−½ rounds to the even 0). A float-to-int `as` cast
/// saturates and maps NaN to 0, ~10 instructions more per call. Where 1280 m
/// is an integer the tie may round down: the piece to the left, at its own
/// border. The mask (the table is padded to 2048 entries) spares a bounds
/// check.
#[inline(always)]
fn slot(m: f64) -> usize {
    const ROUND: f64 = 6_755_399_441_055_744.0;
    (((m * 1280.0 - 0.5) + ROUND).to_bits() as usize) & (PIECE_OF.len() - 1)
}

/// The piece of [0, 0.95) holding m, and the offset t from its centre,
/// formed from m₁ as (1 − centre) − m₁ (1 − centre is exact), so that a
/// modulus given by its complement loses nothing. For m < ½ a modulus
/// given by m has m₁ = fl(1 − m), ≤ 2⁻⁵⁴ off, which moves K and E by
/// ≤ (K′/K) 2⁻⁵⁴ ≤ 0.11 ulp (measured maxima unchanged); with `EXACT`
/// (the K and E that reduce u modulo 2K and 2E, where such an offset is
/// multiplied by the period count) t = m − centre there instead, by a
/// branch-free select (m < ½ is a coin toss on uniform input) that costs
/// the single calls ~8 instructions (K 5.9 → 5.0 ns replayed without it).
#[inline(always)]
fn piece<const N: usize, const EXACT: bool>(
    table: &'static [Poly<N>; 192],
    m: f64,
    mc: f64,
) -> (&'static Poly<N>, f64) {
    let slot = slot(m);
    let p = &table[usize::from(PIECE_OF[slot])];
    if EXACT {
        let mask = 0u64.wrapping_sub(u64::from(m < 0.5));
        let t_m = (m - p.centre).to_bits();
        let t_c = (p.omc - mc).to_bits();
        (p, f64::from_bits((t_m & mask) | (t_c & !mask)))
    } else {
        (p, p.omc - mc)
    }
}

/// a·b as (p, e) with p = fl(ab) and p + e = ab exactly (Dekker's product
/// with Veltkamp's split; no FMA on the baseline target).
#[inline(always)]
pub(crate) fn two_prod(a: f64, b: f64) -> (f64, f64) {
    #[inline(always)]
    fn split(x: f64) -> (f64, f64) {
        let c = 134_217_729.0 * x;
        let hi = c - (c - x);
        (hi, x - hi)
    }
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// ln 2 to 32 significant bits (fdlibm's `ln2_hi`), so that e·LN2_HI is
/// exact for |e| < 2²¹, and the rest.
const LN2_HI: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000);
const LN2_LO: f64 = f64::from_bits(0x3dea_39ef_3579_3c76);

/// L = −ln m₁ as a double-double for 0 < m₁ ≤ 0.05: m₁ = f·2^e with
/// f ∈ [1, 2), L = −e ln 2 − ln f, where e ln 2 is exact and ln f ≤ 0.7
/// carries libm's half ulp of a number much smaller than L ≥ 3 (≤ 0.12 ulp
/// of L).
#[inline(always)]
pub(crate) fn neg_ln_dd(mc: f64) -> (f64, f64) {
    // Subnormals: scale by 2⁵⁴ first.
    let (x, e0) = if mc < f64::MIN_POSITIVE {
        (mc * 18_014_398_509_481_984.0, -54)
    } else {
        (mc, 0)
    };
    let bits = x.to_bits();
    let e = f64::from(((bits >> 52) & 0x7ff) as i32 - 1023 + e0);
    let f = f64::from_bits((bits & 0x000f_ffff_ffff_ffff) | 0x3ff0_0000_0000_0000);
    let a = -e * LN2_HI;
    let b = -(e * LN2_LO + f.ln());
    let hi = a + b;
    (hi, (a - hi) + b)
}

/// K as a double-double (hi, lo), |lo| ≤ ½ ulp(hi); used to reduce
/// arguments modulo 2K and rounded once by [`ellip_k`]. For m ≥ 0.95 the
/// product L·QK and the sum PK + L·QK are carried exactly (Dekker), so the
/// only errors left are the polynomials' and ln f's, each ≪ 1 ulp of K.
#[inline]
pub(crate) fn ellip_k_dd(modulus: Modulus) -> (f64, f64) {
    let (m, mc) = (modulus.m(), modulus.complement());
    if m < 0.95 {
        let (p, t) = piece::<_, true>(&K_PIECES, m, mc);
        p.eval_t(t)
    } else if mc == 0.0 {
        (f64::INFINITY, 0.0)
    } else {
        k_near_one::<true>(mc)
    }
}

/// K = PK(m₁) + L·QK(m₁) for 0 < m₁ ≤ 0.05 as a double-double: L in
/// double-double, the sum PK + L·QK by Knuth's two-sum, and with `EXACT`
/// the product L·QK by Dekker's (≤ 0.5 ulp, for reducing u modulo 2K);
/// without, L·QK rounds once (≤ 0.75 ulp measured, ~3 ns less).
#[inline(always)]
fn k_near_one<const EXACT: bool>(mc: f64) -> (f64, f64) {
    let t = mc - PK.centre;
    let (p, pl) = PK.eval_t(t);
    let (q, ql) = QK.eval_t(t);
    let (l, ll) = neg_ln_dd(mc);
    let (lq, lq_err) = if EXACT { two_prod(l, q) } else { (l * q, 0.0) };
    let hi = p + lq;
    let bb = hi - p;
    let s_err = (p - (hi - bb)) + (lq - bb);
    let lo = s_err + (pl + (lq_err + (l * ql + ll * q)));
    let k = hi + lo;
    (k, lo - (k - hi))
}

/// Complete elliptic integral of the first kind K(k).
///
/// ```text
/// K(k) = ∫0^{π/2} dθ / √(1 − m sin²θ) = (π/2) ₂F₁(½, ½; 1; m)      DLMF 19.2.8, 19.5.1
/// K(k) = PK(m₁) − ln(m₁) QK(m₁),  m ≥ 0.95                           DLMF 19.12.1
/// ```
/// with m = k², m₁ = 1 − m read exactly from the [`Modulus`].
///
/// Method: on 192 pieces of [0, 0.95) an exact Taylor polynomial (degree
/// ≤ 8) about the piece's centre, with the constant term in double-double
/// and the offset from the centre formed from m₁;
/// for m ≥ 0.95 the logarithmic expansion in m₁ (DLMF 19.12.1), whose two
/// power series are re-expanded about m₁ = 0.025. Coefficients:
/// `tests/data/gen_special_coeffs.py` (mpmath). Every term of the m₁
/// expansion is positive.
///
/// # Special cases
/// K(0) = π/2; K(1) = +∞ (m₁ = 0); K ~ ½ ln(16/m₁) as m₁ → 0, finite for
/// every m₁ > 0 including subnormals.
///
/// # Accuracy
/// Max 0.74 ulp, median 0.18, over 3512 moduli with m₁ down to 1e-300
/// (1500 of them with m₁ ∈ [1e-14, 1e-2]).
/// See the [module docs](crate::special#accuracy) for the table.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_k};
/// let k = ellip_k(Modulus::from_m(0.5)?);
/// assert!((k - 1.854_074_677_301_372).abs() < 1e-15); // mpmath ellipk(0.5)
/// assert_eq!(ellip_k(Modulus::from_k(1.0)?), f64::INFINITY);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §19.2, §19.5, §19.12; T. Fukushima, Celest. Mech. Dyn. Astr. 105
/// (2009) 305–328 (piecewise series for K and E).
#[must_use]
#[inline]
pub fn ellip_k(modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if m < 0.95 {
        let (p, t) = piece::<_, false>(&K_PIECES, m, mc);
        p.eval(t)
    } else if mc == 0.0 {
        f64::INFINITY
    } else {
        k_near_one::<false>(mc).0
    }
}

/// Complete elliptic integral of the second kind E(k).
///
/// ```text
/// E(k) = ∫0^{π/2} √(1 − m sin²θ) dθ = (π/2) ₂F₁(−½, ½; 1; m)     DLMF 19.2.8, 19.5.2
/// E(k) = 1 + m₁ (SE(m₁) − ln(m₁) RE(m₁)),  m ≥ 0.95                  DLMF 19.12.2
/// ```
/// Method as for [`ellip_k`]: piecewise exact Taylor polynomials for
/// m < 0.95, the logarithmic expansion in m₁ above (all terms positive).
///
/// # Special cases
/// E(0) = π/2; E(1) = 1.
///
/// # Accuracy
/// Max 0.50 ulp, median 0.14, over 3512 moduli with m₁ down to 1e-300.
/// See the [module docs](crate::special#accuracy) for the table.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_e};
/// let e = ellip_e(Modulus::from_m(0.5)?);
/// assert!((e - 1.350_643_881_047_675_5).abs() < 1e-15); // mpmath ellipe(0.5)
/// assert_eq!(ellip_e(Modulus::from_k(1.0)?), 1.0);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §19.2, §19.5, §19.12.
#[must_use]
#[inline]
pub fn ellip_e(modulus: Modulus) -> f64 {
    let (hi, lo) = e_dd::<false>(modulus);
    hi + lo
}

/// E as a double-double (hi, lo): the piece's (hi, lo) for m < 0.95, and
/// (1, E − 1) above, E − 1 = m₁ (SE + L RE) to a relative ulp or two. For
/// the quasi-period 2jE, so the offset in its piece is exact (`piece`).
#[inline(always)]
pub(crate) fn ellip_e_dd(modulus: Modulus) -> (f64, f64) {
    e_dd::<true>(modulus)
}

#[inline(always)]
fn e_dd<const EXACT: bool>(modulus: Modulus) -> (f64, f64) {
    let (m, mc) = (modulus.m(), modulus.complement());
    if m < 0.95 {
        let (p, t) = piece::<_, EXACT>(&E_PIECES, m, mc);
        p.eval_t(t)
    } else if mc == 0.0 {
        (1.0, 0.0)
    } else {
        let t = mc - SE.centre;
        let (p, pl) = SE.eval_t(t);
        let (q, ql) = RE.eval_t(t);
        (1.0, mc * (p + (pl + -mc.ln() * (q + ql))))
    }
}

#[cfg(test)]
mod tests {
    use super::slot;

    /// The slot is floor(1280 m), or one less where 1280 m is an integer (a
    /// piece's border), on a dense grid, at every border and its neighbours.
    #[test]
    fn slot_is_floor() {
        let check = |m: f64| {
            let x = m * 1280.0;
            let s = slot(m) as f64;
            assert!(
                s == x.floor() || (x == x.floor() && s == x - 1.0),
                "m = {m}: slot {s}"
            );
        };
        for i in 0..950_000 {
            check(f64::from(i) * 1e-6);
        }
        for k in 0..1216 {
            let m = f64::from(k) / 1280.0;
            for m in [m, m.next_up(), m.next_down().max(0.0)] {
                check(m);
            }
        }
        check(0.95_f64.next_down());
        check(1e-300);
    }
}
