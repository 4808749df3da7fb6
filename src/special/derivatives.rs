//! Derivatives in the parameter m = k² of K, E, F(φ), E(φ) and of sn, cn,
//! dn, am at fixed u.
//!
//! ```text
//! dK/dm      = (E − m₁K)/(2 m m₁) = R_D(0, 1, m₁)/6                      DLMF 19.4.1, 19.25.1
//! dE/dm      = (E − K)/(2m)       = −R_D(0, m₁, 1)/6
//! ∂F(φ)/∂m   = (E(φ) − m₁F(φ))/(2 m m₁) − sin φ cos φ/(2 m₁ Δ)
//!            = (sin³φ/6) R_D(cos²φ, 1, Δ²),   Δ² = cos²φ + m₁ sin²φ        DLMF 19.4.2, 19.25.10
//! ∂E(φ)/∂m   = (E(φ) − F(φ))/(2m) = −(sin³φ/6) R_D(cos²φ, Δ², 1)          DLMF 19.4.2, 19.25.9
//! ∂am/∂m     = −dn · ∂F/∂m at φ = am u      (u = F(am u | m) held fixed)
//! ∂sn/∂m     = cn ∂am/∂m,   ∂cn/∂m = −sn ∂am/∂m,
//! ∂dn/∂m     = −sn (sn + 2m cn ∂am/∂m)/(2 dn)  (from dn² = 1 − m sn²)
//! ```
//! (d/dk = 2k d/dm.) Beyond |φ| ≤ π/2 the quasi-periods add their own
//! derivative: ∂F(φ + jπ)/∂m = 2j dK/dm + ∂F(φ)/∂m, likewise E, and
//! am(u) = jπ + am(r) with u = 2jK + r. Every R_D form is a sum of
//! non-negative terms; where R_D would need many duplication steps (m₁ → 0
//! in dK/dm, m → 0 in dE/dm) the closed forms in K and E are used instead,
//! which cancel little there.

use super::Modulus;
use super::carlson::rd;
use super::complete::{ellip_e, ellip_k};
use super::incomplete::reduce_pi_sin_cos;
use super::jacobi::{Jacobi, assemble, sncndn_am_half_period, sncndn_quarter_numerators};
use super::period::Period;

/// Below this m₁, dK/dm = (E − m₁K)/(2 m m₁) (E ≥ 1 ≫ m₁K ≤ 0.16: little
/// cancellation) rather than R_D(0, 1, m₁)/6 (steps grow as ln(1/m₁)).
const KDM_CLOSED_MC: f64 = 0.05;
/// Below this m₁, dE/dm = (E − K)/(2m) (K ≥ 4.8 > 3.5 E: little
/// cancellation) rather than −R_D(0, m₁, 1)/6.
const EDM_CLOSED_MC: f64 = 1e-3;

/// dK/dm, the derivative of the complete integral K in the parameter m.
///
/// ```text
/// dK/dm = (E − m₁ K)/(2 m m₁) = R_D(0, 1, m₁)/6          DLMF 19.4.1, 19.25.1
/// ```
/// π/8 at m = 0, +∞ at m = 1; dK/dk = 2k dK/dm.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_k_dm};
/// let d = ellip_k_dm(Modulus::from_m(0.5)?);
/// assert!((d - 0.847_213_084_793_979).abs() < 1e-15); // mpmath diff(ellipk, 0.5)
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn ellip_k_dm(modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if mc == 0.0 {
        f64::INFINITY
    } else if mc < KDM_CLOSED_MC {
        (ellip_e(modulus) - mc * ellip_k(modulus)) / (2.0 * m * mc)
    } else {
        rd(0.0, 1.0, mc) / 6.0
    }
}

/// dE/dm, the derivative of the complete integral E in the parameter m.
///
/// ```text
/// dE/dm = (E − K)/(2m) = −R_D(0, m₁, 1)/6                DLMF 19.4.1, 19.25.1
/// ```
/// −π/8 at m = 0, −∞ at m = 1.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_e_dm};
/// let d = ellip_e_dm(Modulus::from_m(0.5)?);
/// assert!((d + 0.503_430_796_253_696_4).abs() < 1e-15); // mpmath diff(ellipe, 0.5)
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn ellip_e_dm(modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if mc == 0.0 {
        f64::NEG_INFINITY
    } else if mc < EDM_CLOSED_MC {
        (ellip_e(modulus) - ellip_k(modulus)) / (2.0 * m)
    } else {
        -rd(0.0, mc, 1.0) / 6.0
    }
}

/// ∂F/∂m on 0 ≤ r ≤ π/2 from s = sin r, c = cos r: (s³/6) R_D(c², 1, Δ²).
#[inline]
fn f_dm_reduced(s: f64, c: f64, mc: f64) -> f64 {
    let d2 = c * c + mc * (s * s);
    if d2 == 0.0 {
        return f64::INFINITY;
    }
    s * s * s / 6.0 * rd(c * c, 1.0, d2)
}

/// ∂F(φ | m)/∂m, the derivative of the incomplete integral of the first
/// kind in m at fixed φ, any real φ.
///
/// ```text
/// ∂F/∂m = (sin³φ/6) R_D(cos²φ, 1, Δ²),  Δ² = cos²φ + m₁ sin²φ,  |φ| ≤ π/2      DLMF 19.4.2, 19.25.10
/// ∂F(φ + jπ)/∂m = 2j dK/dm + ∂F(φ)/∂m
/// ```
///
/// # Special cases
/// NaN or infinite φ gives NaN; ∂F/∂m = 0 at φ = 0; +∞ at m = 1 beyond
/// |φ| = π/2.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_f_dm};
/// let d = ellip_f_dm(1.1, Modulus::from_m(0.7)?);
/// assert!((d - 0.373_449_450_080_919_06).abs() < 1e-15); // mpmath diff(lambda m: ellipf(1.1, m), 0.7)
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn ellip_f_dm(phi: f64, modulus: Modulus) -> f64 {
    if !phi.is_finite() {
        return f64::NAN;
    }
    let (j, r, s, c) = reduce_pi_sin_cos(phi);
    let f = f_dm_reduced(s, c, modulus.complement()).copysign(r);
    if j == 0.0 {
        f
    } else {
        2.0 * j * ellip_k_dm(modulus) + f
    }
}

/// ∂E(φ | m)/∂m, the derivative of the incomplete integral of the second
/// kind in m at fixed φ, any real φ.
///
/// ```text
/// ∂E/∂m = −(sin³φ/6) R_D(cos²φ, Δ², 1),  |φ| ≤ π/2                          DLMF 19.4.2, 19.25.9
/// ∂E(φ + jπ)/∂m = 2j dE/dm + ∂E(φ)/∂m
/// ```
///
/// # Special cases
/// NaN or infinite φ gives NaN; 0 at φ = 0.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_e_inc_dm};
/// let d = ellip_e_inc_dm(1.1, Modulus::from_m(0.7)?);
/// assert!((d + 0.221_911_223_593_984_25).abs() < 1e-15); // mpmath diff(lambda m: ellipe(1.1, m), 0.7)
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn ellip_e_inc_dm(phi: f64, modulus: Modulus) -> f64 {
    if !phi.is_finite() {
        return f64::NAN;
    }
    let mc = modulus.complement();
    let (j, r, s, c) = reduce_pi_sin_cos(phi);
    let d2 = c * c + mc * (s * s);
    let e = -(s * s * s / 6.0 * rd(c * c, d2, 1.0)).copysign(r);
    if j == 0.0 {
        e
    } else {
        2.0 * j * ellip_e_dm(modulus) + e
    }
}

/// The derivatives of sn, cn, dn and am in the parameter m at fixed u
/// (from [`jacobi_dm`] or [`FixedModulus::jacobi_dm`](crate::special::FixedModulus::jacobi_dm)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct JacobiDm {
    /// ∂sn/∂m.
    pub sn: f64,
    /// ∂cn/∂m.
    pub cn: f64,
    /// ∂dn/∂m.
    pub dn: f64,
    /// ∂am/∂m.
    pub am: f64,
}

/// The m-derivatives from the values at u = 2jK + r, |sn r|, cn r ≥ 0 and
/// dK/dm (only read when j ≠ 0).
#[inline]
pub(crate) fn jacobi_dm_from(
    value: &Jacobi,
    j: f64,
    r: f64,
    m: f64,
    k_dm: impl FnOnce() -> f64,
) -> JacobiDm {
    let (sn, cn, dn) = (value.sn, value.cn, value.dn);
    let (s, c) = (sn.abs(), cn.abs());
    // ∂F/∂m at φ = am u = jπ + am r (DLMF 19.4.2 with 19.25.10).
    // At m = 1 (dn = cn) this stays finite for |φ| < π/2; only when cn
    // and dn underflow together (φ → π/2) is it infinite.
    let mut f_m = if c == 0.0 && dn == 0.0 {
        f64::INFINITY
    } else {
        (s * s * s / 6.0 * rd(c * c, 1.0, dn * dn)).copysign(r)
    };
    if j != 0.0 {
        f_m += 2.0 * j * k_dm();
    }
    let am = -dn * f_m;
    JacobiDm {
        sn: cn * am,
        cn: -sn * am,
        dn: -sn * (sn + 2.0 * m * cn * am) / (2.0 * dn),
        am,
    }
}

/// sn, cn, dn, am at u and their derivatives in the parameter m at fixed u.
///
/// ```text
/// ∂am/∂m = −dn ∂F(φ|m)/∂m at φ = am u,  ∂F/∂m = 2j dK/dm + (sin³φ_r/6) R_D(cos²φ_r, 1, dn²)
/// ∂sn/∂m = cn ∂am/∂m,  ∂cn/∂m = −sn ∂am/∂m,  ∂dn/∂m = −sn (sn + 2m cn ∂am/∂m)/(2 dn)
/// ```
/// with u = 2jK + r and φ_r = am r (DLMF 19.4.2, 22.16.1; u = F(am u | m)
/// held fixed). For many u at one modulus use
/// [`FixedModulus::jacobi_dm`](crate::special::FixedModulus::jacobi_dm).
///
/// # Special cases
/// NaN or infinite u gives NaN; all derivatives vanish at u = 0; m = 0
/// (sin, cos) has ∂am/∂m = (sin 2u − 2u)/8 by the same formula; at m = 1
/// (no period) they are finite, from R_D(sech²u, 1, sech²u).
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, jacobi_dm};
/// let (j, d) = jacobi_dm(0.7, Modulus::from_m(0.5)?);
/// assert!((j.sn - 0.624_340_090_966_217_3).abs() < 1e-15);
/// // mpmath: diff(lambda m: ellipfun('sn', 0.7, m=m), 0.5)
/// assert!((d.sn + 0.039_863_440_905_545_85).abs() < 1e-15);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn jacobi_dm(u: f64, modulus: Modulus) -> (Jacobi, JacobiDm) {
    let (m, mc) = (modulus.m(), modulus.complement());
    if !u.is_finite() || mc == 0.0 || m == 0.0 {
        // The special cases of `jacobi` (the general formulas below still
        // apply to their values).
        return super::fixed::FixedModulus::new(modulus).jacobi_dm(u);
    }
    let period = Period::new(modulus);
    let red = period.reduce(u);
    let f = sncndn_am_half_period(red.r.abs(), &period, mc, mc.sqrt(), |v| {
        sncndn_quarter_numerators(v, m, mc)
    });
    let value = assemble(&red, f);
    let d = jacobi_dm_from(&value, red.j, red.r, m, || ellip_k_dm(modulus));
    (value, d)
}
