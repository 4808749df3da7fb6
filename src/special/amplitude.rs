//! The amplitude am on [0, K] from the quarter-period values (crate-private).
//!
//! am(v) = atan2(sn v, cn v) is taken in the form whose ratio lies in
//! [0, 1], so one branch-free kernel serves both halves of [0, K]:
//!
//! ```text
//! am(v)     = 2 atan(sn v / (1 + cn v))          v ≤ K/2   (half angle, sn² + cn² = 1)
//! am(K − s) = π/2 − atan(k′ sn s / cn s)         s ≤ K/2   (tan am(K − s) = cn s/(k′ sn s), DLMF 22.4.3)
//! ```
//! (k′ sc s ≤ k′ sc(K/2) = √k′ ≤ 1.) The second form needs no value at K − s
//! itself, so am does not wait for the quarter-period shift's division and
//! square root.

/// atan(i/8) for i = 0..8 as hi + lo (mpmath, 40 digits:
/// `atan(mpf(i)/8)` split into two doubles).
const ATAN_HI: [f64; 9] = [
    0.0,
    0.12435499454676144,
    0.24497866312686414,
    0.35877067027057225,
    0.4636476090008061,
    0.5585993153435624,
    0.6435011087932844,
    0.7188299996216245,
    core::f64::consts::FRAC_PI_4,
];
const ATAN_LO: [f64; 9] = [
    0.0,
    -3.1253241424539383e-18,
    1.0698755618734451e-17,
    -2.4623815582638635e-17,
    2.2698777452961687e-17,
    -5.4556305485916264e-18,
    1.5834785051444286e-17,
    -2.1478388444456983e-17,
    3.061616997868383e-17,
];
/// π/2 − atan(i/8) for i = 0..8 as hi + lo (mpmath, 40 digits).
const COATAN_HI: [f64; 9] = [
    core::f64::consts::FRAC_PI_2,
    1.446441332248135,
    1.3258176636680326,
    1.2120256565243244,
    1.1071487177940904,
    1.0121970114513341,
    0.9272952180016122,
    0.8519663271732721,
    core::f64::consts::FRAC_PI_4,
];
const COATAN_LO: [f64; 9] = [
    6.123233995736766e-17,
    9.211323971545052e-17,
    -8.824429373951136e-17,
    3.034500430874847e-17,
    9.40447137356638e-17,
    6.668797050595929e-17,
    4.5397554905923374e-17,
    -2.831157406069101e-17,
    3.061616997868383e-17,
];

/// atan(n/d), or π/2 − atan(n/d) when `co`, for 0 ≤ n ≤ d (n may be a hair
/// below 0, d > 0), with one division and no branch.
///
/// n/d is placed by eight comparisons next to the nearest c = i/8, and
/// atan(n/d) = atan c + atan x with x = (8n − i d)/(8d + i n), |x| ≤ 1/16,
/// where the Taylor series x − x³/3 + … + x¹³/13 is exact to rounding (the
/// next term is ≤ 2⁻⁵⁶/15 of x). The tables hold atan c and π/2 − atan c in
/// double-double; the result rounds once, after x's own rounding (i·d and
/// i·n carry at most 3 more bits than d and n).
#[inline(always)]
pub(crate) fn atan_ratio(n: f64, d: f64, co: bool) -> f64 {
    let t = 16.0 * n;
    let i = usize::from(t >= d)
        + usize::from(t >= 3.0 * d)
        + usize::from(t >= 5.0 * d)
        + usize::from(t >= 7.0 * d)
        + usize::from(t >= 9.0 * d)
        + usize::from(t >= 11.0 * d)
        + usize::from(t >= 13.0 * d)
        + usize::from(t >= 15.0 * d);
    let c = i as f64;
    let x = (8.0 * n - c * d) / (8.0 * d + c * n);
    let z = x * x;
    let z2 = z * z;
    let z4 = z2 * z2;
    // atan x = x + x z q(z), q = −1/3 + z/5 − z²/7 + z³/9 − z⁴/11 + z⁵/13 (Estrin).
    let q = (-1.0 / 3.0 + z * (1.0 / 5.0))
        + z2 * (-1.0 / 7.0 + z * (1.0 / 9.0))
        + z4 * (-1.0 / 11.0 + z * (1.0 / 13.0));
    let (hi, lo, xs) = if co {
        (COATAN_HI[i], COATAN_LO[i], -x)
    } else {
        (ATAN_HI[i], ATAN_LO[i], x)
    };
    hi + ((lo + xs * z * q) + xs)
}

/// am on [0, K] from (sn, cn) at v ∈ [0, K/2] (v may be a hair below 0):
/// am(v) if not `folded`, am(K − v) if `folded` (see the module docs).
/// `kp` = k′.
#[inline(always)]
pub(crate) fn am_half_period(s: f64, c: f64, kp: f64, folded: bool) -> f64 {
    let (n, d) = if folded { (kp * s, c) } else { (s, 1.0 + c) };
    let a = atan_ratio(n, d, folded);
    if folded { a } else { 2.0 * a }
}

#[cfg(test)]
mod tests {
    use super::atan_ratio;

    /// The kernel against libm's atan2 (≤ 1 ulp itself) on 200 000 ratios
    /// uniform in angle, near 0 and near 1, and at the interval borders
    /// (2i − 1)/16: within 1.5 ulp of libm (measured 1.0), so within 2.5 of
    /// the truth; the am table (mpmath) bounds the whole amplitude more
    /// tightly.
    #[test]
    fn atan_ratio_matches_libm() {
        let mut seed = 12_345_u64;
        let mut next = || {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst: f64 = 0.0;
        let mut check = |n: f64, d: f64| {
            for co in [false, true] {
                let a = atan_ratio(n, d, co);
                let b = if co {
                    // π/2 − atan2(n, d) = atan2(d, n), no cancellation.
                    d.atan2(n)
                } else {
                    n.atan2(d)
                };
                let e = if b == 0.0 {
                    a.abs()
                } else {
                    ((a - b) / b).abs() / f64::EPSILON
                };
                worst = worst.max(e);
            }
        };
        for i in 0..200_000 {
            let theta = match i % 4 {
                0 | 1 => core::f64::consts::FRAC_PI_4 * next(),
                2 => core::f64::consts::FRAC_PI_4 * 10f64.powf(-12.0 * next()),
                _ => core::f64::consts::FRAC_PI_4 * (1.0 - 10f64.powf(-12.0 * next())),
            };
            let (s, c) = theta.sin_cos();
            check(s, c);
            check(s * 3.7, c * 3.7);
        }
        for k in [1.0, 3.0, 5.0, 7.0, 9.0, 11.0, 13.0, 15.0] {
            for j in -4..=4 {
                let x = k / 16.0 * (1.0 + f64::from(j) * f64::EPSILON);
                check(x, 1.0);
                check(1.0, 1.0 / x);
            }
        }
        check(0.0, 1.0);
        check(1e-300, 1.0);
        check(1.0, 1.0);
        assert!(worst <= 1.5, "worst {worst} ulp against libm");
    }
}
