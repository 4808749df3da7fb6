//! Jacobi elliptic functions sn, cn, dn and the amplitude am.

use core::fmt;

use super::Modulus;
use super::amplitude::am_half_period;
use super::duplication::{Quarter, sncndn_small};
use super::incomplete::{PI_HI, PI_LO};
use super::landen::{LANDEN_MC, LANDEN_MIN_V, LandenChain};
use super::period::{Period, Reduced};

/// The Jacobi elliptic functions at one point, with the amplitude.
///
/// ```text
/// u = F(am u, k),  sn u = sin am u,  cn u = cos am u,  dn u = √(1 − m sn² u)   DLMF 22.16.1, 22.2
/// ```
/// The nine other Glaisher functions are the quotients returned by the
/// helpers (`nd = 1/dn`, `cd = cn/dn`, `sd = sn/dn`, …; DLMF 22.2.10).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Jacobi {
    /// sn(u, k).
    pub sn: f64,
    /// cn(u, k).
    pub cn: f64,
    /// dn(u, k).
    pub dn: f64,
    /// The amplitude am(u, k), continuous (and increasing) in u.
    pub am: f64,
}

impl Jacobi {
    /// ns = 1/sn.
    #[must_use]
    pub fn ns(&self) -> f64 {
        1.0 / self.sn
    }
    /// nc = 1/cn.
    #[must_use]
    pub fn nc(&self) -> f64 {
        1.0 / self.cn
    }
    /// nd = 1/dn.
    #[must_use]
    pub fn nd(&self) -> f64 {
        1.0 / self.dn
    }
    /// sc = sn/cn.
    #[must_use]
    pub fn sc(&self) -> f64 {
        self.sn / self.cn
    }
    /// sd = sn/dn.
    #[must_use]
    pub fn sd(&self) -> f64 {
        self.sn / self.dn
    }
    /// cd = cn/dn.
    #[must_use]
    pub fn cd(&self) -> f64 {
        self.cn / self.dn
    }
    /// cs = cn/sn.
    #[must_use]
    pub fn cs(&self) -> f64 {
        self.cn / self.sn
    }
    /// ds = dn/sn.
    #[must_use]
    pub fn ds(&self) -> f64 {
        self.dn / self.sn
    }
    /// dc = dn/cn.
    #[must_use]
    pub fn dc(&self) -> f64 {
        self.dn / self.cn
    }
}

impl fmt::Display for Jacobi {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "sn = {}, cn = {}, dn = {}, am = {}",
            self.sn, self.cn, self.dn, self.am
        )
    }
}

/// (sn, cn, dn) for 0 ≤ v ≤ K/2 (v may be a hair below 0 after
/// rounding). For m₁ ≤ 0.1 and v ≥ 1 the ascending Landen transformation
/// carries v to a modulus so close to 1 that the expansion about m = 1 is
/// exact to rounding ([`LandenChain`]): no doubling, whose rounding errors
/// (~1.5 ulp per step, each doubled by the steps after it) reached 8 ulp
/// in cn and dn near m₁ ~ 1e-8 and v ~ K/2. Elsewhere the Maclaurin series
/// and doubling ([`sncndn_small`]) take at most four steps.
#[inline]
pub(crate) fn sncndn_quarter(v: f64, m: f64, mc: f64) -> (f64, f64, f64) {
    let (s, c, d, ..) = sncndn_quarter_numerators(v, m, mc);
    (s, c, d)
}

/// [`sncndn_quarter`] with am's numerators ([`Quarter`]).
#[inline]
pub(crate) fn sncndn_quarter_numerators(v: f64, m: f64, mc: f64) -> Quarter {
    if v >= LANDEN_MIN_V && mc <= LANDEN_MC {
        let (s, c, d) = LandenChain::new(m, mc, v).eval(v);
        (s, c, d, s, c, 1.0)
    } else {
        sncndn_small(v, m, mc)
    }
}

/// (sn, cn, dn, am) for 0 ≤ a ≤ K (a reduced argument), folding a > K/2
/// with the quarter-period shift (DLMF 22.4.3): with s = K − a,
/// sn a = cd s = √(1 − m₁ sd² s), cn a = k′ sd s, dn a = k′ nd s.
/// K = `k` + `k_tail` (double-double), so s carries no rounding of K;
/// `quarter` gives (sn, cn, dn) on [0, K/2]. am comes from the quarter
/// values directly ([`am_half_period`]), so it does not wait for the
/// shift's division and square root; both halves are computed without a
/// branch on the fold (a coin toss for random u).
#[inline(always)]
pub(crate) fn sncndn_am_half_period(
    a: f64,
    period: &Period,
    mc: f64,
    kp: f64,
    quarter: impl Fn(f64) -> Quarter,
) -> (f64, f64, f64, f64) {
    let folded = a > 0.5 * period.k;
    let v = if folded {
        (period.k - a) + period.k_tail
    } else {
        a
    };
    let (s, c, d, s_num, c_num, q) = quarter(v);
    let am = am_half_period(s_num, c_num, q, kp, folded);
    // sn a = cd s = √(1 − m₁ sd² s): the ratio cn/dn of two values near √k′
    // would carry both their errors, while m₁ sd² ≤ ½ here.
    let sd = s / d;
    let (sn, cn, dn) = if folded {
        ((1.0 - mc * sd * sd).sqrt(), kp * sd, kp / d)
    } else {
        (s, c, d)
    };
    (sn, cn, dn, am)
}

/// sn, cn, dn and am at u = 2jK + r from (sn, cn, dn, am) at |r|.
#[inline(always)]
pub(crate) fn assemble(red: &Reduced, (sn, cn, dn, am_r): (f64, f64, f64, f64)) -> Jacobi {
    let Reduced { j, odd, r } = *red;
    let am_r = am_r.copysign(r);
    let sn = sn.copysign(r);
    let (sn, cn) = if odd { (-sn, -cn) } else { (sn, cn) };
    let am = j * PI_HI + (j * PI_LO + am_r);
    Jacobi { sn, cn, dn, am }
}

/// The values at m = 0 (sin, cos), at m = 1 (tanh, sech) and at a NaN or
/// infinite u, where the general path does not apply.
#[inline(always)]
pub(crate) fn jacobi_special(u: f64, m: f64, mc: f64) -> Option<Jacobi> {
    if !u.is_finite() {
        return Some(Jacobi {
            sn: f64::NAN,
            cn: f64::NAN,
            dn: f64::NAN,
            am: f64::NAN,
        });
    }
    if m == 0.0 {
        let (sn, cn) = u.sin_cos();
        return Some(Jacobi {
            sn,
            cn,
            dn: 1.0,
            am: u,
        });
    }
    if mc == 0.0 {
        let sech = 1.0 / u.cosh();
        return Some(Jacobi {
            sn: u.tanh(),
            cn: sech,
            dn: sech,
            am: u.sinh().atan(),
        });
    }
    None
}

/// Jacobi elliptic functions sn, cn, dn and the amplitude am at real u.
///
/// ```text
/// u = ∫0^{am u} dθ / √(1 − m sin²θ),  sn = sin am, cn = cos am, dn = √(1 − m sn²)   DLMF 22.16.1
/// ```
/// Method: u = 2jK + r with |r| ≤ K (2K in double-double); for |r| > K/2
/// the quarter-period shift (DLMF 22.4.3) maps to K − |r| ∈ [0, K/2];
/// there, for m₁ ≤ 0.1 and v ≥ 1, ascending Landen steps (DLMF 22.7.4–7)
/// down to the expansion about m = 1 (DLMF 22.10.4–6); otherwise the
/// argument is halved to ≤ 1/8, the Maclaurin series (DLMF 22.10.1–3)
/// evaluated and the duplication formulas (DLMF 22.8.20, written without
/// cancellation, carrying 1 − cn and 1 − dn, with one division at the end)
/// applied back. am is atan2(sn, cn) on [−K, K] (taken from the values on
/// [0, K/2] by a branch-free atan kernel) plus jπ, so it is continuous and
/// increasing.
/// For many u at one modulus, [`FixedModulus`](crate::special::FixedModulus)
/// holds what depends on the modulus. See the
/// [module docs](crate::special#methods-and-why).
///
/// # Special cases
/// NaN or infinite u gives NaN in every field. m = 0: sin u, cos u, 1, u.
/// m = 1 (m₁ = 0): tanh u, sech u, sech u, gd u.
///
/// # Accuracy
/// Normalised by 1 + the condition number in u (max over 5254 points,
/// |u| ≤ 1e4, m₁ down to 1e-300, 3051 of them with m₁ ∈ [1e-12, 1e-3] and
/// K/2 ≤ |u| ≤ 4K): sn 1.02, cn 1.16, dn 0.89, am 1.00 ulp;
/// no NaN for finite u. Near the zeros of sn and cn at large |u| the raw
/// error is large, as the rounding of u itself dictates.
/// See the [module docs](crate::special#accuracy) for the table.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, jacobi};
/// let j = jacobi(0.7, Modulus::from_m(0.5)?);
/// assert!((j.sn - 0.624_340_090_966_217_3).abs() < 1e-15); // mpmath ellipfun('sn', 0.7, m=0.5)
/// assert!((j.sn * j.sn + j.cn * j.cn - 1.0).abs() < 1e-15);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §22.2, §22.4, §22.8, §22.10, §22.16; T. Fukushima, Numer. Math. 123
/// (2013) 585–605 (conditional duplication).
#[must_use]
pub fn jacobi(u: f64, modulus: Modulus) -> Jacobi {
    let (m, mc) = (modulus.m(), modulus.complement());
    if let Some(j) = jacobi_special(u, m, mc) {
        return j;
    }
    let period = Period::new(modulus);
    let red = period.reduce(u);
    let f = sncndn_am_half_period(red.r.abs(), &period, mc, mc.sqrt(), |v| {
        sncndn_quarter_numerators(v, m, mc)
    });
    assemble(&red, f)
}
