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

use super::atan_table::ATAN_NODES;

/// atan(n/d), or π/2 − atan(n/d) when `co`, for −1/128 ≤ n/d ≤ 1 (d > 0),
/// with one division and no branch: q = 64 n/d, i = round(q), w = q − i
/// (exact, |w| ≤ ½), atan(n/d) = atan(i/64) + Σ_{k=1..8} b_k wᵏ (Taylor
/// about i/64, truncation ≤ 2⁻⁵⁷ of the value, `atan_table.rs`).
#[inline(always)]
pub(crate) fn atan_ratio(n: f64, d: f64, co: bool) -> f64 {
    const ROUND: f64 = 6_755_399_441_055_744.0;
    let q = (64.0 * n) / d;
    let t = q + ROUND;
    let i = ((t.to_bits() as usize) & 127).min(64);
    let w = q - (t - ROUND);
    let node = &ATAN_NODES[i];
    let b = &node.b;
    let w2 = w * w;
    let w4 = w2 * w2;
    // Σ b_k wᵏ = b₁w + w²(b₂ + b₃w + …): b₁w is exact at i = 0 (b₁ = 1/64),
    // where atan itself is O(w); Estrin for the rest.
    let p = ((b[1] + b[2] * w) + w2 * (b[3] + b[4] * w)) + w4 * ((b[5] + b[6] * w) + w2 * b[7]);
    let tail = w2 * p;
    let lin = b[0] * w;
    if co {
        node.co_hi + ((node.co_lo - tail) - lin)
    } else {
        node.hi + ((node.lo + tail) + lin)
    }
}

/// am on [0, K] from (sn, cn) = (s/q, c/q) at v ∈ [0, K/2] (v may be a
/// hair below 0): am(v) if not `folded`, am(K − v) if `folded` (see the
/// module docs; the ratios are s/(q + c) and k′s/c, so the doubling's
/// final division is not waited for). `kp` = k′.
#[inline(always)]
pub(crate) fn am_half_period(s: f64, c: f64, q: f64, kp: f64, folded: bool) -> f64 {
    let (n, d) = if folded { (kp * s, c) } else { (s, q + c) };
    let a = atan_ratio(n, d, folded);
    if folded { a } else { 2.0 * a }
}

#[cfg(test)]
mod tests {
    use super::atan_ratio;

    /// The kernel against libm's atan2 (≤ 1 ulp itself) on 200 000 ratios
    /// uniform in angle, near 0 and near 1, and at the interval borders
    /// (2i + 1)/128: within 1.5 ulp of libm (measured 1.0), so within 2.5 of
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
        for k in 0..64 {
            for j in -4..=4 {
                let x = f64::from(2 * k + 1) / 128.0 * (1.0 + f64::from(j) * f64::EPSILON);
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
