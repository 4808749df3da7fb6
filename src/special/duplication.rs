//! sn, cn, dn on [0, K/2] by the Maclaurin series and conditional
//! duplication (crate-private).

use super::landen::{hyperbolic_reach, sncndn_hyperbolic};
use super::maclaurin_coeffs::{SN, Y, Z};

/// Below this |u| the Maclaurin series (to u¹⁵ for sn, u¹⁶ for 1 − cn,
/// 1 − dn) is exact to rounding: the first neglected terms are ≤ 2.6e-18
/// relative for every m ∈ [0, 1] (largest at m = 1: tanh, sech).
const SERIES_MAX: f64 = 1.0 / 8.0;

/// (sn, cn, dn) for 0 ≤ v ≤ K/2: halve to |v| ≤ 1/8, Maclaurin series,
/// then double back (conditional duplication, after Fukushima 2013).
///
/// The doubling carries the complements y = 1 − cn, z = 1 − dn (carrying
/// cn itself would double its relative error at every step), and with
/// D = cn² + sn² dn² (= 1 − m sn⁴, a sum of positives):
///
/// ```text
/// sn(2v)     = 2 sn cn dn / D                 DLMF 22.8.20
/// 1 − cn(2v) = 2 sn² dn² / D                  (positive terms)
/// 1 − dn(2v) = 2 m sn² cn² / D                (positive terms)
/// ```
/// On [0, K/2] that is enough: every argument but the last is ≤ K/4 (or
/// < ½ where m₁ < 0.1, as this path sees only v < 1 there), where
/// cn, dn ≥ 0.8, and at the last y ≤ 0.51, z ≤ 0.44 (cn(K/2) =
/// √(k′/(1 + k′)) ≥ 0.49 and dn(K/2) = √k′ ≥ 0.56 for m₁ ≥ 0.1; sech 1 =
/// 0.65 bounds both below for m₁ < 0.1, v < 1), so 1 − y and 1 − z lose at
/// most a bit. (A switch to carrying cn, dn themselves once y or z passed ½
/// fired only at the last step, where it gave the same 1 − y, and cost a
/// mispredicted branch.)
#[inline(always)]
pub(crate) fn sncndn_small(v: f64, m: f64, mc: f64) -> Quarter {
    MaclaurinLow::new(m, mc).eval(v)
}

/// (sn, cn, dn) at v and, for am, sn and cn as S/Q and C/Q before the
/// doubling's final division: (sn, cn, dn, S, C, Q). am's ratios
/// sn/(1 + cn) = S/(Q + C) and k′ sn/cn = k′S/C then wait for one division,
/// not two in a row (jacobi −6% on the bench's uniform set, sixth pass).
/// Paths without a doubling give (sn, cn, dn, sn, cn, 1).
pub(crate) type Quarter = (f64, f64, f64, f64, f64, f64);

/// The Maclaurin coefficients of sn, 1 − cn and 1 − dn at one modulus
/// (DLMF 22.10.1–3), in x² after the leading term, signs included: `NS`
/// terms for sn (from u³), `NY` for 1 − cn and 1 − dn (from u²), exact to
/// rounding for |u| ≤ `max`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Maclaurin<const NS: usize, const NY: usize> {
    s: [f64; NS],
    y: [f64; NY],
    z: [f64; NY],
    max: f64,
    m: f64,
    mc: f64,
}

/// To u¹⁵ (sn) and u¹⁶ (1 − cn, 1 − dn) from |u| ≤ 1/8: coefficients
/// cheap enough to form at every call.
pub(crate) type MaclaurinLow = Maclaurin<7, 8>;
/// To u²² from |u| ≤ 1/4 (one doubling fewer), for `FixedModulus`,
/// which forms its 32 polynomials once.
pub(crate) type MaclaurinHigh = Maclaurin<10, 11>;

/// Below this |u| the order-22 series is exact to rounding: its first
/// neglected terms are ≤ 2.3e-18 relative for every m ∈ [0, 1]
/// (`tests/data/gen_special_coeffs.py`).
const SERIES_MAX_HIGH: f64 = 0.25;

impl MaclaurinHigh {
    /// The coefficients from their exact polynomials in m (generated).
    pub(crate) fn new(m: f64, mc: f64) -> Self {
        let at = |p: &[f64]| p.iter().rev().fold(0.0, |acc, &c| c + m * acc);
        Self {
            s: SN.map(at),
            y: Y.map(at),
            z: Z.map(at),
            max: SERIES_MAX_HIGH,
            m,
            mc,
        }
    }
}

impl MaclaurinLow {
    #[inline(always)]
    pub(crate) fn new(m: f64, mc: f64) -> Self {
        let m2 = m * m;
        let m3 = m2 * m;
        let m4 = m2 * m2;
        let s5 = (1.0 + 14.0 * m + m2) * (1.0 / 120.0);
        let s7 = (1.0 + 135.0 * m + 135.0 * m2 + m3) * (1.0 / 5040.0);
        let s9 = (1.0 + 1228.0 * m + 5478.0 * m2 + 1228.0 * m3 + m4) * (1.0 / 362_880.0);
        let s11 = (1.0 + 11069.0 * m + 165_826.0 * (m2 + m3) + 11069.0 * m4 + m4 * m)
            * (1.0 / 39_916_800.0);
        let c4 = (1.0 + 4.0 * m) * (1.0 / 24.0);
        let c6 = (1.0 + 44.0 * m + 16.0 * m2) * (1.0 / 720.0);
        let c8 = (1.0 + 408.0 * m + 912.0 * m2 + 64.0 * m3) * (1.0 / 40320.0);
        let c10 =
            (1.0 + 3688.0 * m + 30768.0 * m2 + 15808.0 * m3 + 256.0 * m4) * (1.0 / 3_628_800.0);
        let d4 = m * (4.0 + m) * (1.0 / 24.0);
        let d6 = m * (16.0 + 44.0 * m + m2) * (1.0 / 720.0);
        let d8 = m * (64.0 + 912.0 * m + 408.0 * m2 + m3) * (1.0 / 40320.0);
        let d10 = m * (256.0 + 15808.0 * m + 30768.0 * m2 + 3688.0 * m3 + m4) * (1.0 / 3_628_800.0);
        // Orders 13–16 (integer coefficients from gen_special_coeffs.py's
        // Maclaurin polynomials times k!).
        let (m5, m6, m7) = (m4 * m, m3 * m3, m4 * m3);
        let s13 = (1.0 + 99642.0 * (m + m5) + 4_494_351.0 * (m2 + m4) + 13_180_268.0 * m3 + m6)
            * (1.0 / 6_227_020_800.0);
        let s15 = (1.0
            + 896_803.0 * (m + m6)
            + 116_294_673.0 * (m2 + m5)
            + 834_687_179.0 * (m3 + m4)
            + m7)
            * (1.0 / 1_307_674_368_000.0);
        let c12 =
            (1.0 + 33212.0 * m + 870_640.0 * m2 + 1_538_560.0 * m3 + 259_328.0 * m4 + 1024.0 * m5)
                * (1.0 / 479_001_600.0);
        let c14 = (1.0
            + 298_932.0 * m
            + 22_945_056.0 * m2
            + 106_923_008.0 * m3
            + 65_008_896.0 * m4
            + 4_180_992.0 * m5
            + 4096.0 * m6)
            * (1.0 / 87_178_291_200.0);
        let c16 = (1.0
            + 2_690_416.0 * m
            + 586_629_984.0 * m2
            + 6_337_665_152.0 * m3
            + 9_860_488_448.0 * m4
            + 2_536_974_336.0 * m5
            + 67_047_424.0 * m6
            + 16384.0 * m7)
            * (1.0 / 20_922_789_888_000.0);
        let d12 = m
            * (1024.0 + 259_328.0 * m + 1_538_560.0 * m2 + 870_640.0 * m3 + 33212.0 * m4 + m5)
            * (1.0 / 479_001_600.0);
        let d14 = m
            * (4096.0
                + 4_180_992.0 * m
                + 65_008_896.0 * m2
                + 106_923_008.0 * m3
                + 22_945_056.0 * m4
                + 298_932.0 * m5
                + m6)
            * (1.0 / 87_178_291_200.0);
        let d16 = m
            * (16384.0
                + 67_047_424.0 * m
                + 2_536_974_336.0 * m2
                + 9_860_488_448.0 * m3
                + 6_337_665_152.0 * m4
                + 586_629_984.0 * m5
                + 2_690_416.0 * m6
                + m7)
            * (1.0 / 20_922_789_888_000.0);
        Self {
            s: [-(1.0 + m) * (1.0 / 6.0), s5, -s7, s9, -s11, s13, -s15],
            y: [0.5, -c4, c6, -c8, c10, -c12, c14, -c16],
            z: [0.5 * m, -d4, d6, -d8, d10, -d12, d14, -d16],
            max: SERIES_MAX,
            m,
            mc,
        }
    }
}

impl<const NS: usize, const NY: usize> Maclaurin<NS, NY> {
    /// (sn, cn, dn) at 0 ≤ v ≤ K/2, as described at [`sncndn_small`], with
    /// am's numerators ([`Quarter`]).
    #[inline(always)]
    pub(crate) fn eval(&self, v: f64) -> Quarter {
        let m = self.m;
        if self.mc < HYPERBOLIC_MC {
            let (s, c, d) = sncndn_near_one(v, self.mc);
            return (s, c, d, s, c, 1.0);
        }
        let (x, n) = halve_below(v, self.max);
        let x2 = x * x;
        let x4 = x2 * x2;
        let x8 = x4 * x4;
        // Horner in x⁴ over the pairs (a₂ₖ + a₂ₖ₊₁ x²): kept for the order-22
        // series of `FixedModulus`, where Estrin (below) made the extreme
        // set's FixedModulus::jacobi 1.24× slower (docs/PERFORMANCE.md, sixth
        // pass; not understood).
        let horner = |a: &[f64]| {
            let mut acc = 0.0;
            let mut k = a.len();
            if k % 2 == 1 {
                k -= 1;
                acc = a[k];
            }
            while k > 0 {
                k -= 2;
                acc = (a[k] + a[k + 1] * x2) + x4 * acc;
            }
            acc
        };
        // Estrin to the end for the order-16 series of single calls: pairs,
        // then quads in x⁴ and octets in x⁸ (up to 8 coefficients): two
        // dependent multiply-adds after the pairs where Horner took four
        // (the series feeds every doubling step, so its latency is the
        // call's: jacobi −6% on the bench's uniform set, sixth pass).
        let estrin = |a: &[f64]| {
            if a.len() > 8 {
                return horner(a);
            }
            let p = |k: usize| match a.len().saturating_sub(k) {
                0 => 0.0,
                1 => a[k],
                _ => a[k] + a[k + 1] * x2,
            };
            let q = |k: usize| p(k) + x4 * p(k + 2);
            q(0) + x8 * q(4)
        };
        let mut sn = x + (x * x2) * estrin(&self.s);
        // y = 1 − cn, z = 1 − dn.
        let mut y = x2 * estrin(&self.y);
        let mut z = x2 * estrin(&self.z);
        // Homogeneous doubling: (S, Y, Z, Q) stand for sn = S/Q, y = Y/Q,
        // z = Z/Q, and the formulas above, multiplied through by Q⁴, need no
        // division until the end (each step's dependency chain loses a
        // division's latency; jacobi 66 → 63 ns on the bench's uniform set).
        // Each step raises Q to the 4th power and multiplies it by
        // D ∈ [½, 1], so after the at most four steps here Q ≥ 2⁻⁸⁵: no
        // underflow (Z underflows only for m below ~1e-280, where dn rounds
        // to 1 anyway).
        let mut q = 1.0;
        for _ in 0..n {
            let c = q - y;
            let d = q - z;
            let s2 = sn * sn;
            let (c2, d2, q2) = (c * c, d * d, q * q);
            let s2d2 = s2 * d2;
            let sq = 2.0 * sn * q;
            sn = sq * (c * d);
            y = 2.0 * s2d2;
            z = 2.0 * m * (s2 * c2);
            q = c2 * q2 + s2d2;
        }
        (sn / q, 1.0 - y / q, 1.0 - z / q, sn, q - y, q)
    }
}

/// (x, n) with x = v/2ⁿ ≤ `max` (a power of two) and n ≥ 0, from the
/// exponent bits instead of a loop (whose exit was mispredicted about once
/// a call): for v ∈ [2^e, 2^(e+1)) above `max` = 2^e₀, n = e − e₀ + 1 and
/// x ∈ [max/2, max). x is exact. v ≤ `max` (also a v a hair below 0 after
/// the quarter-period fold) takes n = 0.
#[inline(always)]
fn halve_below(v: f64, max: f64) -> (f64, i32) {
    let e = ((v.to_bits() >> 52) & 0x7ff) as i32;
    let e_max = ((max.to_bits() >> 52) & 0x7ff) as i32;
    let n = if v > max { e - e_max + 1 } else { 0 };
    let scale = f64::from_bits(((1023 - n) as u64) << 52);
    (v * scale, n)
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
/// at 1/8 matters: each step adds ~2 ulp to cn and doubles what came
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
