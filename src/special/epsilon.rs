//! Jacobi's epsilon function ε(u, k) = E(am u, k) and the zeta function Z(u, k).

use super::Modulus;
use super::carlson::rd_roots;
use super::complete::{ellip_e, ellip_e_dd, two_prod};
use super::jacobi::sncndn_quarter;
use super::period::Period;

/// cd = cn/dn on [0, K/2] as √(1 − m₁ sd²) (m₁ sd² ≤ ½ there): the quotient
/// of two values computed apart would carry both their errors when m → 1.
fn cd_small(sn: f64, dn: f64, mc: f64) -> f64 {
    let sd = sn / dn;
    (1.0 - mc * sd * sd).sqrt()
}

/// ε(v) for 0 ≤ v ≤ K/2 from sn, cn, dn at v.
///
/// ```text
/// ε(v) = E(am v) = m₁ v + (m m₁/3) sn³ R_D(cn², 1, dn²) + m sn cn / dn
/// ```
/// (DLMF 19.25.9 with φ = am v, F(am v) = v): three non-negative terms.
fn epsilon_small(v: f64, sn: f64, cn: f64, dn: f64, m: f64, mc: f64) -> f64 {
    let mut e = mc * v + m * sn * cd_small(sn, dn, mc);
    if mc != 0.0 {
        e += m * mc / 3.0 * sn * sn * sn * rd_roots(cn * cn, 1.0, dn * dn, cn, 1.0, dn);
    }
    e
}

/// ε(a) for 0 ≤ a ≤ K (up to rounding). Beyond K/2 the addition formula
/// ε(u + v) = ε(u) + ε(v) − m sn u sn v sn(u + v) (DLMF 22.16.27) at u = K,
/// v = −s gives
///
/// ```text
/// ε(K − s) = E − ε(s) + m sn s cd s,   s = K − a ∈ [0, K/2]
/// ```
/// which avoids R_D at cn(a)², dn(a)² (these underflow when m₁ < 1e-300
/// and a → K) and works when rounding leaves a a hair above K (s < 0).
pub(crate) fn epsilon_half_period(
    a: f64,
    period: &Period,
    e_complete: f64,
    m: f64,
    mc: f64,
    quarter: impl Fn(f64) -> (f64, f64, f64),
) -> f64 {
    if a <= 0.5 * period.k {
        let (sn, cn, dn) = quarter(a);
        epsilon_small(a, sn, cn, dn, m, mc)
    } else {
        let s = (period.k - a) + period.k_tail;
        let v = s.abs();
        let (sn, cn, dn) = quarter(v);
        let es = epsilon_small(v, sn, cn, dn, m, mc);
        (e_complete - es.copysign(s)) + m * sn.copysign(s) * cd_small(sn, dn, mc)
    }
}

/// ε(u) = 2jE + sgn(r) ε(|r|) from ε(|r|) and E = e_hi + e_lo.
#[inline(always)]
pub(crate) fn epsilon_assemble(j: f64, r: f64, e_r: f64, (e_hi, e_lo): (f64, f64)) -> f64 {
    let e = e_r.copysign(r);
    if j == 0.0 {
        e
    } else if j.abs() > 4_503_599_627_370_496.0 {
        // Beyond 2⁵² periods u carries no fraction of a period; Dekker's
        // split would overflow near f64::MAX.
        2.0 * j * (e_hi + e_lo) + e
    } else {
        // 2jE exactly as p + pe + 2j E_lo: where ε(u) ≈ E (u ≈ 2K − r,
        // m → 1) the rounding of 2jE alone would be a whole ulp of ε.
        let (p, pe) = two_prod(2.0 * j, e_hi);
        p + (pe + 2.0 * j * e_lo + e)
    }
}

/// Jacobi's epsilon function, the paper's E(u, k) in eq5.
///
/// ```text
/// ε(u, k) = ∫0^u dn²(w, k) dw = E(am u, k)                   DLMF 22.16.14, 22.16.18
///         = 2jE + sgn(r) ε(|r|),  u = 2jK + r, |r| ≤ K         (quasi-periodicity, DLMF 22.16.20)
/// ε(a)    = m₁ a + (m m₁/3) sn³ R_D(cn², 1, dn²) + m sn cn/dn   (0 ≤ a ≤ K; DLMF 19.25.9)
/// ```
/// Conventions: modulus k, parameter m = k², m₁ = 1 − m from the [`Modulus`].
///
/// # Special cases
/// NaN or infinite u gives NaN. m = 0: ε = u. m = 1: ε = tanh u.
/// ε is odd and ε(u + 2K) = ε(u) + 2E.
///
/// # Accuracy
/// Max 1.58 ulp normalised by 1 + the condition number in u (raw 1.58)
/// over 5254 points, |u| ≤ 1e4, m₁ down to 1e-300.
/// See the [module docs](crate::special#accuracy) for the table.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, jacobi_epsilon};
/// let e = jacobi_epsilon(0.7, Modulus::from_m(0.5)?);
/// assert!((e - 0.650_207_505_543_338_4).abs() < 1e-15); // mpmath: quad(ellipfun('dn', w, m=0.5)**2, [0, 0.7])
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §22.16(ii); P. F. Byrd and M. D. Friedman, *Handbook of Elliptic
/// Integrals* (1971) 310.02.
#[must_use]
pub fn jacobi_epsilon(u: f64, modulus: Modulus) -> f64 {
    if !u.is_finite() {
        return f64::NAN;
    }
    let (m, mc) = (modulus.m(), modulus.complement());
    if m == 0.0 {
        return u;
    }
    if mc == 0.0 {
        return u.tanh();
    }
    let period = Period::new(modulus);
    let red = period.reduce(u);
    let e_dd = ellip_e_dd(modulus);
    let e_r = epsilon_half_period(red.r.abs(), &period, e_dd.0 + e_dd.1, m, mc, |v| {
        sncndn_quarter(v, m, mc)
    });
    epsilon_assemble(red.j, red.r, e_r, e_dd)
}

/// Jacobi's zeta function Z(u, k) = ε(u, k) − u E/K.
///
/// ```text
/// Z(u, k) = E(am u, k) − (E/K) u                               DLMF 22.16.32
/// ```
/// Periodic with period 2K, odd, Z(K) = 0. Computed as the difference
/// above, so its absolute error is that of ε (a few ulps of ε), not
/// relative to Z where Z is small.
///
/// # Special cases
/// NaN or infinite u gives NaN. m = 0: Z = 0. m = 1: Z = tanh u.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, jacobi_zeta, ellip_k};
/// let k = Modulus::from_m(0.5)?;
/// assert!(jacobi_zeta(ellip_k(k), k).abs() < 1e-15);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §22.16(iii).
#[must_use]
pub fn jacobi_zeta(u: f64, modulus: Modulus) -> f64 {
    if !u.is_finite() {
        return f64::NAN;
    }
    let (m, mc) = (modulus.m(), modulus.complement());
    if m == 0.0 {
        return 0.0;
    }
    if mc == 0.0 {
        return u.tanh();
    }
    let period = Period::new(modulus);
    let r = period.reduce(u).r;
    let a = r.abs();
    let e_complete = ellip_e(modulus);
    let e = epsilon_half_period(a, &period, e_complete, m, mc, |v| sncndn_quarter(v, m, mc));
    (e - a * (e_complete / period.k)).copysign(r)
}
