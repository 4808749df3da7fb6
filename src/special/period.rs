//! u reduced modulo 2K, with 2K in double-double (crate-private).

use super::Modulus;
use super::complete::ellip_k_dd;
use super::incomplete::round_ties_even;

/// u reduced modulo 2K: u = 2jK + r with |r| ≤ K (up to rounding).
pub(crate) struct Reduced {
    /// The period count j (for |u| ≥ 2⁵³·2K only approximate, like u).
    pub j: f64,
    /// Whether j is odd (sn and cn change sign with every 2K).
    pub odd: bool,
    /// The remainder r.
    pub r: f64,
}

/// Whether the integer-valued double j is odd (doubles of magnitude ≥ 2⁵³
/// are even).
fn is_odd(j: f64) -> bool {
    j.abs() < 9_007_199_254_740_992.0 && (j as i64) & 1 == 1
}

/// The quarter period K of a modulus and what reducing u modulo 2K needs.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Period {
    /// K, rounded.
    pub k: f64,
    /// K − `k` (K in double-double), so that K − a is formed to ~1e-32.
    pub k_tail: f64,
    /// 2K = `hi` + `mid` + `lo`: `hi` + `mid` = 2k_hi split 27 + 26 bits
    /// (Dekker), so that j·hi and j·mid are exact for |j| < 2²⁶.
    hi: f64,
    mid: f64,
    lo: f64,
    /// 1/(2K), to find j by a product.
    inv_two_k: f64,
}

impl Period {
    /// From K as a double-double (hi, lo).
    #[inline(always)]
    pub(crate) fn from_dd((k_hi, k_lo): (f64, f64)) -> Self {
        let k = k_hi + k_lo;
        let two_k = 2.0 * k_hi;
        let c = 134_217_729.0 * two_k;
        let hi = c - (c - two_k);
        Self {
            k,
            k_tail: (k_hi - k) + k_lo,
            hi,
            mid: two_k - hi,
            lo: 2.0 * k_lo,
            inv_two_k: 0.5 / k,
        }
    }

    /// The period of a modulus.
    #[inline(always)]
    pub(crate) fn new(modulus: Modulus) -> Self {
        Self::from_dd(ellip_k_dd(modulus))
    }

    /// u = 2jK + r. j = round(u/2K) may be off by one at half-way points
    /// (|r| a hair above K), which the half-period fold absorbs.
    #[inline(always)]
    pub(crate) fn reduce(&self, u: f64) -> Reduced {
        let j = round_ties_even(u * self.inv_two_k);
        if j == 0.0 {
            return Reduced {
                j,
                odd: false,
                r: u,
            };
        }
        if j.abs() < 67_108_864.0 {
            // u − j·hi is exact (Sterbenz), j·mid exact.
            let r = ((u - j * self.hi) - j * self.mid) - j * self.lo;
            return Reduced {
                j,
                odd: is_odd(j),
                r,
            };
        }
        self.reduce_far(u, j)
    }

    /// |u| ≥ 2²⁶·2K: u/2K itself is rounded, so the first remainder can
    /// still span many periods; reduce again until |r| ≤ K. (Beyond 2⁵³·2K
    /// the spacing of doubles exceeds the period and the result, though
    /// finite and in range, carries no information about u.)
    #[cold]
    fn reduce_far(&self, u: f64, mut j: f64) -> Reduced {
        let (k, two_k) = (self.k, self.hi + self.mid);
        let mut r = (-j).mul_add(two_k, u) - j * self.lo;
        let mut odd = is_odd(j);
        for _ in 0..64 {
            if r.abs() <= k {
                break;
            }
            let j2 = round_ties_even(r * self.inv_two_k);
            r = (-j2).mul_add(two_k, r) - j2 * self.lo;
            odd ^= is_odd(j2);
            j += j2;
        }
        if r.abs() > k {
            r = 0.0;
        }
        Reduced { j, odd, r }
    }
}
