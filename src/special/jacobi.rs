//! Jacobi elliptic functions sn, cn, dn and the amplitude am.

use core::fmt;

use super::Modulus;
use super::duplication::sncndn_small;
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
/// and doubling ([`sncndn_small`]) take at most five steps.
#[inline]
pub(crate) fn sncndn_quarter(v: f64, m: f64, mc: f64) -> (f64, f64, f64) {
    if v >= LANDEN_MIN_V && mc <= LANDEN_MC {
        LandenChain::new(m, mc, v).eval(v)
    } else {
        sncndn_small(v, m, mc)
    }
}

/// (sn, cn, dn) for 0 ≤ a ≤ K (a reduced argument), folding a > K/2 with
/// the quarter-period shift (DLMF 22.4.3): with s = K − a,
/// sn a = cd s = √(1 − m₁ sd² s), cn a = k′ sd s, dn a = k′ nd s.
/// K = `k` + `k_tail` (double-double), so s carries no rounding of K;
/// `quarter` gives (sn, cn, dn) on [0, K/2].
#[inline(always)]
pub(crate) fn sncndn_half_period(
    a: f64,
    period: &Period,
    mc: f64,
    kp: f64,
    quarter: impl Fn(f64) -> (f64, f64, f64),
) -> (f64, f64, f64) {
    if a > 0.5 * period.k {
        let (s, _, d) = quarter((period.k - a) + period.k_tail);
        // sn a = cd s = √(1 − m₁ sd² s): the ratio cn/dn of two values
        // near √k′ would carry both their errors, while m₁ sd² ≤ ½ here.
        let sd = s / d;
        ((1.0 - mc * sd * sd).sqrt(), kp * sd, kp / d)
    } else {
        quarter(a)
    }
}

/// atan2(s, c) for s ≥ 0, c > 0 (an angle in [0, π/2)), inline: fdlibm's
/// `atan` (reduction to |x| < 7/16 about atan ½, atan 1, atan 3/2 or π/2,
/// then an odd polynomial of degree 23) applied to x = s/c without forming
/// s/c: each reduced argument (a x − b)/(c₀ + d x) is taken as
/// (a s − b c)/(c₀ c + d s), one division in all. Branch-free but for c ≤ 0
/// (a hair beyond K after rounding), which takes libm's `atan2`.
/// am keeps its accuracy (≤ 1.1 ulp normalised over the Jacobi table, 1.25
/// with libm's atan2), and am no longer costs ~17 ns of a 42 ns
/// `FixedModulus::jacobi` (7 of ~90 in a single `jacobi` call).
#[inline(always)]
pub(crate) fn atan2_first_quadrant(s: f64, c: f64) -> f64 {
    // fdlibm s_atan.c: atanhi/atanlo and aT[0..10].
    const HI: [f64; 5] = [
        0.0,
        0.4636476090008061,
        core::f64::consts::FRAC_PI_4,
        0.982793723247329,
        core::f64::consts::FRAC_PI_2,
    ];
    const LO: [f64; 5] = [
        0.0,
        2.2698777452961687e-17,
        3.061616997868383e-17,
        1.3903311031230998e-17,
        6.123233995736766e-17,
    ];
    // x' = (A s − B c)/(C c + D s) per interval of x = s/c:
    // [0, 7/16): x; [7/16, 11/16): (2x − 1)/(2 + x); [11/16, 19/16): (x − 1)/(x + 1);
    // [19/16, 39/16): (x − 1.5)/(1 + 1.5x); beyond: −1/x.
    const A: [f64; 5] = [1.0, 2.0, 1.0, 1.0, 0.0];
    const B: [f64; 5] = [0.0, 1.0, 1.0, 1.5, 1.0];
    const C: [f64; 5] = [1.0, 2.0, 1.0, 1.0, 0.0];
    const D: [f64; 5] = [0.0, 1.0, 1.0, 1.5, 1.0];
    const AT: [f64; 11] = [
        0.3333333333333293,
        -0.19999999999876483,
        0.14285714272503466,
        -0.11111110405462356,
        0.09090887133436507,
        -0.0769187620504483,
        0.06661073137387531,
        -0.058335701337905735,
        0.049768779946159324,
        -0.036531572744216916,
        0.016285820115365782,
    ];
    if c <= 0.0 || s.is_nan() || s < 0.0 {
        return s.atan2(c);
    }
    let t = 16.0 * s;
    let id = usize::from(t >= 7.0 * c)
        + usize::from(t >= 11.0 * c)
        + usize::from(t >= 19.0 * c)
        + usize::from(t >= 39.0 * c);
    let x = (A[id] * s - B[id] * c) / (C[id] * c + D[id] * s);
    let z = x * x;
    let w = z * z;
    let s1 = z * (AT[0] + w * (AT[2] + w * (AT[4] + w * (AT[6] + w * (AT[8] + w * AT[10])))));
    let s2 = w * (AT[1] + w * (AT[3] + w * (AT[5] + w * (AT[7] + w * AT[9]))));
    if id == 0 {
        x - x * (s1 + s2)
    } else {
        HI[id] - ((x * (s1 + s2) - LO[id]) - x)
    }
}

/// sn, cn, dn and am at u = 2jK + r from (sn, cn, dn) at |r|.
#[inline(always)]
pub(crate) fn assemble(red: &Reduced, (sn, cn, dn): (f64, f64, f64)) -> Jacobi {
    let Reduced { j, odd, r } = *red;
    let am_r = atan2_first_quadrant(sn, cn).copysign(r);
    let sn = sn.copysign(r);
    let (sn, cn) = if odd { (-sn, -cn) } else { (sn, cn) };
    let am = if j == 0.0 {
        am_r
    } else {
        j * PI_HI + (j * PI_LO + am_r)
    };
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
/// cancellation, carrying 1 − cn and 1 − dn while small) applied back. am
/// is atan2(sn, cn) on [−K, K] plus jπ, so it is continuous and increasing.
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
/// K/2 ≤ |u| ≤ 4K): sn 1.06, cn 1.16, dn 0.89, am 1.08 ulp;
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
    let f = sncndn_half_period(red.r.abs(), &period, mc, mc.sqrt(), |v| {
        sncndn_quarter(v, m, mc)
    });
    assemble(&red, f)
}

#[cfg(test)]
mod tests {
    use super::atan2_first_quadrant;

    /// The inline atan2 against libm's (≤ 1 ulp itself) on 200 000 points
    /// of the first quadrant, uniform in angle and near 0 and π/2, and at
    /// the interval borders x = 7/16, 11/16, 19/16, 39/16: within 2 ulp of
    /// libm (measured 1.0), so within 3 ulp of the truth; the am table
    /// (mpmath) bounds the combination more tightly (≤ 1.25 ulp normalised).
    #[test]
    fn atan2_first_quadrant_matches_libm() {
        let mut seed = 12_345_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst: f64 = 0.0;
        let mut check = |s: f64, c: f64| {
            let (a, b) = (atan2_first_quadrant(s, c), s.atan2(c));
            let e = if b == 0.0 {
                a.abs()
            } else {
                ((a - b) / b).abs() / f64::EPSILON
            };
            worst = worst.max(e);
        };
        for i in 0..200_000 {
            let theta = match i % 4 {
                0 | 1 => core::f64::consts::FRAC_PI_2 * next(),
                2 => 10f64.powf(-12.0 * next()),
                _ => core::f64::consts::FRAC_PI_2 - 10f64.powf(-12.0 * next()),
            };
            let (s, c) = theta.sin_cos();
            check(s, c);
        }
        for x in [7.0 / 16.0, 11.0 / 16.0, 19.0 / 16.0, 39.0 / 16.0] {
            for k in -4..=4 {
                let xs = x * (1.0 + f64::from(k) * f64::EPSILON);
                check(xs, 1.0);
                check(1.0, 1.0 / xs);
            }
        }
        check(0.0, 1.0);
        check(1e-300, 1.0);
        assert!(worst <= 2.0, "worst {worst} ulp against libm");
    }
}
