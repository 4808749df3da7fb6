//! Jacobi elliptic functions sn, cn, dn and the amplitude am.

use core::fmt;

use super::Modulus;
use super::complete::ellip_k_dd;
use super::incomplete::{PI_HI, PI_LO, round_ties_even};
use super::landen::{LANDEN_MC, LANDEN_MIN_V, LandenChain, hyperbolic_reach, sncndn_hyperbolic};

/// The Jacobi elliptic functions at one point, with the amplitude.
///
/// ```text
/// u = F(am u, k),  sn u = sin am u,  cn u = cos am u,  dn u = √(1 − m sn² u)   DLMF 22.16.1, 22.2
/// ```
/// The nine other Glaisher functions are the quotients returned by the
/// helpers (`nd = 1/dn`, `cd = cn/dn`, `sd = sn/dn`, …; DLMF 22.2.10).
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// u reduced modulo 2K: u = 2jK + r with |r| ≤ K (up to rounding).
pub(crate) struct Reduced {
    /// The period count j (for |u| ≥ 2⁵³·2K only approximate, like u).
    pub j: f64,
    /// Whether j is odd (sn and cn change sign with every 2K).
    pub odd: bool,
    /// The remainder r.
    pub r: f64,
    /// K itself, rounded.
    pub k: f64,
    /// K − `k` (from K in double-double), so that K − a is formed to ~1e-32.
    pub k_tail: f64,
}

/// Whether the integer-valued double j is odd (doubles of magnitude ≥ 2⁵³
/// are even).
fn is_odd(j: f64) -> bool {
    j.abs() < 9_007_199_254_740_992.0 && (j as i64) & 1 == 1
}

pub(crate) fn reduce_2k(u: f64, modulus: Modulus) -> Reduced {
    let (k_hi, k_lo) = ellip_k_dd(modulus);
    let k = k_hi + k_lo;
    let k_tail = (k_hi - k) + k_lo;
    let mut j = round_ties_even(u / (2.0 * k));
    if j == 0.0 {
        return Reduced {
            j,
            odd: false,
            r: u,
            k,
            k_tail,
        };
    }
    let two_k = 2.0 * k_hi;
    if j.abs() < 67_108_864.0 {
        // r = u − j·2K with 2K = 2k_hi + 2k_lo a double-double: split
        // 2k_hi into 27 + 26 bits (Dekker) so that j·hi and j·lo are exact
        // for |j| < 2²⁶; u − j·hi is then exact (Sterbenz).
        let c = 134_217_729.0 * two_k;
        let hi = c - (c - two_k);
        let lo = two_k - hi;
        let r = ((u - j * hi) - j * lo) - j * (2.0 * k_lo);
        return Reduced {
            j,
            odd: is_odd(j),
            r,
            k,
            k_tail,
        };
    }
    // |u| ≥ 2²⁶·2K: u/2K itself is rounded, so the first remainder can
    // still span many periods; reduce again until |r| ≤ K. (Beyond 2⁵³·2K
    // the spacing of doubles exceeds the period and the result, though
    // finite and in range, carries no information about u.)
    let mut r = (-j).mul_add(two_k, u) - j * (2.0 * k_lo);
    let mut odd = is_odd(j);
    for _ in 0..64 {
        if r.abs() <= k {
            break;
        }
        let j2 = round_ties_even(r / (2.0 * k));
        r = (-j2).mul_add(two_k, r) - j2 * (2.0 * k_lo);
        odd ^= is_odd(j2);
        j += j2;
    }
    if r.abs() > k {
        r = 0.0;
    }
    Reduced {
        j,
        odd,
        r,
        k,
        k_tail,
    }
}

/// Below this |u| the Maclaurin series (to u¹¹ for sn, u¹⁰ for cn, dn) is
/// exact to rounding: the first neglected coefficient is ≤ 0.0057 for every
/// m ∈ [0, 1] (m = 1, sech), and 0.0057 · (1/16)¹² ≈ 2e-17.
const SERIES_MAX: f64 = 1.0 / 16.0;

/// (sn, cn, dn) for 0 ≤ v ≤ K/2: halve to |v| ≤ 1/16, Maclaurin series,
/// then double back (conditional duplication, after Fukushima 2013).
///
/// While cn and dn are near 1 the doubling carries their complements
/// y = 1 − cn, z = 1 − dn (carrying cn itself would double its relative
/// error at every step); once y (or z) exceeds ½ it switches to cn (or dn)
/// itself. With D = cn² + sn² dn² (= 1 − m sn⁴, a sum of positives):
///
/// ```text
/// sn(2v)     = 2 sn cn dn / D                 DLMF 22.8.20
/// 1 − cn(2v) = 2 sn² dn² / D                  (positive terms)
/// 1 − dn(2v) = 2 m sn² cn² / D                (positive terms)
/// cn(2v)     = (cn⁴ − m₁ sn⁴) / D             (= cn² − sn² dn²; benign for 2v ≤ K/2)
/// dn(2v)     = √(cn²(2v) + m₁ sn²(2v))       (once dn < ½, which needs cn < ½)
/// ```
pub(crate) fn sncndn_small(v: f64, m: f64, mc: f64) -> (f64, f64, f64) {
    if mc < HYPERBOLIC_MC {
        return sncndn_near_one(v, mc);
    }
    let mut n = 0;
    let mut x = v;
    while x > SERIES_MAX {
        x *= 0.5;
        n += 1;
    }
    let x2 = x * x;
    let m2 = m * m;
    let m3 = m2 * m;
    let s5 = (1.0 + 14.0 * m + m2) / 120.0;
    let s7 = (1.0 + 135.0 * m + 135.0 * m2 + m3) / 5040.0;
    let m4 = m2 * m2;
    let s9 = (1.0 + 1228.0 * m + 5478.0 * m2 + 1228.0 * m3 + m4) / 362_880.0;
    let s11 = (1.0 + 11069.0 * m + 165_826.0 * (m2 + m3) + 11069.0 * m4 + m4 * m) / 39_916_800.0;
    let mut sn =
        x * (1.0 + x2 * (-(1.0 + m) / 6.0 + x2 * (s5 + x2 * (-s7 + x2 * (s9 - x2 * s11)))));
    let c4 = (1.0 + 4.0 * m) / 24.0;
    let c6 = (1.0 + 44.0 * m + 16.0 * m2) / 720.0;
    let c8 = (1.0 + 408.0 * m + 912.0 * m2 + 64.0 * m3) / 40320.0;
    // y = 1 − cn, z = 1 − dn.
    let c10 = (1.0 + 3688.0 * m + 30768.0 * m2 + 15808.0 * m3 + 256.0 * m4) / 3_628_800.0;
    let mut y = x2 * (0.5 - x2 * (c4 - x2 * (c6 - x2 * (c8 - x2 * c10))));
    let d4 = m * (4.0 + m) / 24.0;
    let d6 = m * (16.0 + 44.0 * m + m2) / 720.0;
    let d8 = m * (64.0 + 912.0 * m + 408.0 * m2 + m3) / 40320.0;
    let d10 = m * (256.0 + 15808.0 * m + 30768.0 * m2 + 3688.0 * m3 + m4) / 3_628_800.0;
    let mut z = x2 * (0.5 * m - x2 * (d4 - x2 * (d6 - x2 * (d8 - x2 * d10))));
    // cn, dn carried directly once their complements pass ½ (NaN until then).
    let mut cn = f64::NAN;
    let mut dn = f64::NAN;
    let mut cn_direct = false;
    let mut dn_direct = false;
    for _ in 0..n {
        let c = if cn_direct { cn } else { 1.0 - y };
        let d = if dn_direct { dn } else { 1.0 - z };
        let s2 = sn * sn;
        let c2 = c * c;
        let d2 = d * d;
        let den = c2 + s2 * d2;
        sn = 2.0 * sn * c * d / den;
        if cn_direct {
            cn = (c2 * c2 - mc * (s2 * s2)) / den;
        } else {
            y = 2.0 * s2 * d2 / den;
            if y > 0.5 {
                cn_direct = true;
                cn = 1.0 - y;
            }
        }
        if dn_direct {
            // dn² = cn² + m₁ sn² (positive terms). Doubling cn and dn
            // separately would let the error in this identity grow 4× per
            // step (only the part consistent with a shift of v grows 2×).
            let c = if cn_direct { cn } else { 1.0 - y };
            dn = (c * c + mc * (sn * sn)).sqrt();
        } else {
            z = 2.0 * m * s2 * c2 / den;
            if z > 0.5 {
                dn_direct = true;
                dn = 1.0 - z;
            }
        }
    }
    let c = if cn_direct { cn } else { 1.0 - y };
    let d = if dn_direct { dn } else { 1.0 - z };
    (sn, c, d)
}

/// Below this m₁ (≈ 9.3e-10) sn, cn, dn start from the expansion about
/// m = 1 instead of the Maclaurin series.
const HYPERBOLIC_MC: f64 = 1.0 / (1u64 << 30) as f64;

/// (sn, cn, dn) for 0 ≤ v ≤ K/2 and m₁ < 2⁻³⁰. The first-order expansion
/// about m = 1 (below) has relative corrections ~ m₁ e^{2v}/16 and a
/// neglected second-order term ~ (m₁ e^{2v}/16)²: exact to rounding while
/// m₁ e^{2v} ≤ 2⁻²⁴, i.e. v ≤ v₀ = ½ ln(2⁻²⁴/m₁) ≥ 2. Larger v are halved
/// to ≤ v₀ and doubled back with cn carried directly (cn ≤ sech 2 there)
/// and dn = √(cn² + m₁ sn²). Starting the doubling at v₀ ≥ 2 rather than
/// at 1/16 matters: each step adds ~2 ulp to cn and doubles what came
/// before, which the condition number (~v) absorbs only from a large start.
/// For m₁ < 2⁻⁶⁰, v₀ ≥ 12.5 > K/2 and no doubling happens.
fn sncndn_near_one(v: f64, mc: f64) -> (f64, f64, f64) {
    let v0 = hyperbolic_reach(mc);
    let mut n = 0;
    let mut x = v;
    while x > v0 {
        x *= 0.5;
        n += 1;
    }
    let (mut sn, mut cn, mut dn) = sncndn_hyperbolic(x, mc);
    for _ in 0..n {
        let (s2, c2, d2) = (sn * sn, cn * cn, dn * dn);
        let den = c2 + s2 * d2;
        sn = 2.0 * sn * cn * dn / den;
        cn = (c2 * c2 - mc * (s2 * s2)) / den;
        dn = (cn * cn + mc * (sn * sn)).sqrt();
    }
    (sn, cn, dn)
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
/// K = `k` + `k_tail` (double-double), so s carries no rounding of K.
pub(crate) fn sncndn_half_period(a: f64, k: f64, k_tail: f64, m: f64, mc: f64) -> (f64, f64, f64) {
    if a > 0.5 * k {
        let (s, _, d) = sncndn_quarter((k - a) + k_tail, m, mc);
        // sn a = cd s = √(1 − m₁ sd² s): the ratio cn/dn of two values
        // near √k′ would carry both their errors, while m₁ sd² ≤ ½ here.
        let kp = mc.sqrt();
        let sd = s / d;
        ((1.0 - mc * sd * sd).sqrt(), kp * sd, kp / d)
    } else {
        sncndn_quarter(a, m, mc)
    }
}

/// Jacobi elliptic functions sn, cn, dn and the amplitude am at real u.
///
/// ```text
/// u = ∫0^{am u} dθ / √(1 − m sin²θ),  sn = sin am, cn = cos am, dn = √(1 − m sn²)   DLMF 22.16.1
/// ```
/// Method: u = 2jK + r with |r| ≤ K (2K in double-double); for |r| > K/2
/// the quarter-period shift (DLMF 22.4.3) maps to K − |r| ∈ [0, K/2];
/// there the argument is halved to ≤ 1/16, the Maclaurin series (DLMF
/// 22.10.1–3) evaluated and the duplication formulas (DLMF 22.8.20, written
/// without cancellation, carrying 1 − cn and 1 − dn while small) applied
/// back; for m₁ < 2⁻³⁰ the doubling starts from the expansion about m = 1
/// (DLMF 22.10.4–6) instead. am is atan2(sn, cn) on [−K, K] plus jπ, so it
/// is continuous and increasing. See the [module docs](crate::special#methods-and-why).
///
/// # Special cases
/// NaN or infinite u gives NaN in every field. m = 0: sin u, cos u, 1, u.
/// m = 1 (m₁ = 0): tanh u, sech u, sech u, gd u.
///
/// # Accuracy
/// Normalised by 1 + the condition number in u (max over 2203 points,
/// |u| ≤ 1e4, m₁ down to 1e-300): sn 1.18, cn 2.38, dn 1.73, am 1.25 ulp;
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
    if !u.is_finite() {
        return Jacobi {
            sn: f64::NAN,
            cn: f64::NAN,
            dn: f64::NAN,
            am: f64::NAN,
        };
    }
    let (m, mc) = (modulus.m(), modulus.complement());
    if m == 0.0 {
        let (sn, cn) = u.sin_cos();
        return Jacobi {
            sn,
            cn,
            dn: 1.0,
            am: u,
        };
    }
    if mc == 0.0 {
        let sech = 1.0 / u.cosh();
        return Jacobi {
            sn: u.tanh(),
            cn: sech,
            dn: sech,
            am: u.sinh().atan(),
        };
    }
    let Reduced {
        j,
        odd,
        r,
        k,
        k_tail,
    } = reduce_2k(u, modulus);
    let (sn, cn, dn) = sncndn_half_period(r.abs(), k, k_tail, m, mc);
    let am_r = sn.atan2(cn).copysign(r);
    let sn = sn.copysign(r);
    let (sn, cn) = if odd { (-sn, -cn) } else { (sn, cn) };
    let am = if j == 0.0 {
        am_r
    } else {
        j * PI_HI + (j * PI_LO + am_r)
    };
    Jacobi { sn, cn, dn, am }
}
