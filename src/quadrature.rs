//! Gauss–Legendre quadrature: the crate's one rule, used by the collocation
//! tableau (`bvp`) and by the elastica's integrals.
//!
//! The m-point rule on [0, 1] has the nodes c_k = (1 + x_k)/2 with x_k the
//! zeros of the Legendre polynomial P_m, and the weights
//! b_k = 1/((1 − x_k²) P_m′(x_k)²) (DLMF 3.5.19 halved for [0, 1]); it
//! integrates polynomials of degree ≤ 2m − 1 exactly. The zeros are found
//! by Newton's method on the three-term recurrence (DLMF 18.9.1) from
//! Tricomi's estimate x_k ≈ −cos(π(k + ¾)/(m + ½)) (DLMF 18.16.6).

use std::sync::OnceLock;

/// P_m(x) and P_m′(x) by the three-term recurrence (DLMF 18.9.1, 18.9.19).
fn legendre(m: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for j in 2..=m {
        let jf = j as f64;
        let p2 = ((2.0 * jf - 1.0) * x * p1 - (jf - 1.0) * p0) / jf;
        p0 = p1;
        p1 = p2;
    }
    let mf = m as f64;
    let dp = mf * (x * p1 - p0) / (x * x - 1.0);
    (p1, dp)
}

/// The m-point Gauss–Legendre rule on [0, 1].
#[derive(Debug, Clone)]
pub(crate) struct GaussLegendre {
    /// Nodes c_k, increasing.
    pub nodes: Vec<f64>,
    /// Weights b_k, summing to 1.
    pub weights: Vec<f64>,
}

impl GaussLegendre {
    /// The m-point rule (m ≥ 1).
    pub(crate) fn new(m: usize) -> GaussLegendre {
        let mut nodes = vec![0.0; m];
        let mut weights = vec![0.0; m];
        for i in 0..m {
            let mut x = -(std::f64::consts::PI * (i as f64 + 0.75) / (m as f64 + 0.5)).cos();
            for _ in 0..100 {
                let (p, dp) = legendre(m, x);
                let dx = p / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            let (_, dp) = legendre(m, x);
            nodes[i] = 0.5 * (1.0 + x);
            weights[i] = 1.0 / ((1.0 - x * x) * dp * dp);
        }
        GaussLegendre { nodes, weights }
    }
}

/// Composite 8-point Gauss–Legendre quadrature of f over [a, b] on equal
/// pieces no longer than `h` (at most 2²⁰ pieces): exact for polynomials of
/// degree ≤ 15 on each piece.
pub(crate) fn gauss_legendre(f: impl Fn(f64) -> f64, a: f64, b: f64, h: f64) -> f64 {
    static RULE: OnceLock<GaussLegendre> = OnceLock::new();
    let rule = RULE.get_or_init(|| GaussLegendre::new(8));
    let pieces = (((b - a).abs() / h).ceil() as usize).clamp(1, 1 << 20);
    let step = (b - a) / pieces as f64;
    let mut total = 0.0;
    for p in 0..pieces {
        let lo = a + p as f64 * step;
        let mut acc = 0.0;
        for (c, w) in rule.nodes.iter().zip(&rule.weights) {
            acc += w * f(lo + c * step);
        }
        total += acc * step;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eight_point_rule_is_the_tabulated_one() {
        // A&S Table 25.4 (n = 8) on [−1, 1]: x = ±0.183434642495650,
        // ±0.525532409916329, ±0.796666477413627, ±0.960289856497536 with
        // weights 0.362683783378362, 0.313706645877887, 0.222381034453374,
        // 0.101228536290376 (15 digits: compared to 1e-15).
        let x = [
            0.183_434_642_495_650,
            0.525_532_409_916_329,
            0.796_666_477_413_627,
            0.960_289_856_497_536,
        ];
        let w = [
            0.362_683_783_378_362,
            0.313_706_645_877_887,
            0.222_381_034_453_374,
            0.101_228_536_290_376,
        ];
        let r = GaussLegendre::new(8);
        for i in 0..4 {
            // Nodes 4 + i and 3 − i are the pair ±x_i mapped to [0, 1].
            let (hi, lo) = (4 + i, 3 - i);
            assert!((2.0 * r.nodes[hi] - 1.0 - x[i]).abs() < 1e-15, "node {hi}");
            assert!((1.0 - 2.0 * r.nodes[lo] - x[i]).abs() < 1e-15, "node {lo}");
            assert!((2.0 * r.weights[hi] - w[i]).abs() < 1e-15, "weight {hi}");
            assert!((2.0 * r.weights[lo] - w[i]).abs() < 1e-15, "weight {lo}");
        }
    }

    #[test]
    fn composite_rule_matches_closed_forms() {
        // ∫₀¹⁰ sin = 1 − cos 10; pieces of 0.5: the error of 8 points on a
        // piece of length h is ~ h¹⁷/(17·16!·…) ≈ 1e-20, so only rounding
        // remains (a few ε of the sum of |terms| ≈ 6).
        let s = gauss_legendre(f64::sin, 0.0, 10.0, 0.5);
        assert!((s - (1.0 - 10.0_f64.cos())).abs() < 1e-14, "{s}");
        // Reversed limits change the sign; a degree-15 polynomial is exact.
        let s = gauss_legendre(|x| x.powi(15), 2.0, 0.0, 10.0);
        assert!((s + 2.0_f64.powi(16) / 16.0).abs() < 1e-11, "{s}");
    }
}
