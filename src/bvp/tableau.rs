//! Gauss–Legendre collocation coefficients on [0, 1].

use crate::quadrature::GaussLegendre;

/// The m-point Gauss–Legendre tableau: nodes c, weights b, the collocation
/// matrix a_kl = ∫₀^{c_k} L_l(σ) dσ (L_l the Lagrange basis on c) and data
/// for evaluating the collocation polynomial.
#[derive(Debug, Clone)]
pub(crate) struct Tableau {
    pub m: usize,
    pub c: Vec<f64>,
    pub b: Vec<f64>,
    /// Row-major m × m.
    pub a: Vec<f64>,
    /// Row-major m × m inverse of `a`.
    pub a_inv: Vec<f64>,
    /// Leading coefficients 1/Π_{i≠l}(c_l − c_i) of the Lagrange basis.
    pub lead: Vec<f64>,
    /// max over θ ∈ [0, 1] of |∫₀^θ Π_k (σ − c_k) dσ| / m!: the constant of
    /// the leading error term between mesh points.
    pub error_constant: f64,
}

impl Tableau {
    pub(crate) fn new(m: usize) -> Tableau {
        let GaussLegendre {
            nodes: c,
            weights: b,
        } = GaussLegendre::new(m);
        let mut lead = vec![0.0; m];
        for l in 0..m {
            let mut d = 1.0;
            for i in 0..m {
                if i != l {
                    d *= c[l] - c[i];
                }
            }
            lead[l] = 1.0 / d;
        }
        let mut t = Tableau {
            m,
            c,
            b,
            a: vec![0.0; m * m],
            a_inv: vec![0.0; m * m],
            lead,
            error_constant: 0.0,
        };
        let mut row = vec![0.0; m];
        for k in 0..m {
            t.integrated_basis(t.c[k], &mut row);
            t.a[k * m..(k + 1) * m].copy_from_slice(&row);
        }
        t.a_inv = invert(&t.a, m);
        // Error constant: ω(σ) = Π (σ − c_k) expanded in monomials (exact
        // enough for m ≤ 7 on [0, 1]), integrated, sampled on a fine grid.
        let mut fact = 1.0;
        for i in 2..=m {
            fact *= i as f64;
        }
        let mut poly = vec![1.0];
        for ck in &t.c {
            let mut next = vec![0.0; poly.len() + 1];
            for (d, p) in poly.iter().enumerate() {
                next[d + 1] += p;
                next[d] -= ck * p;
            }
            poly = next;
        }
        let mut best: f64 = 0.0;
        let samples = 1000;
        for s in 0..=samples {
            let theta = s as f64 / samples as f64;
            let acc: f64 = poly
                .iter()
                .enumerate()
                .map(|(d, p)| p * theta.powi(d as i32 + 1) / (d as f64 + 1.0))
                .sum();
            best = best.max(acc.abs());
        }
        t.error_constant = best / fact;
        t
    }

    /// L_l(θ) for every l.
    pub(crate) fn basis(&self, theta: f64, out: &mut [f64]) {
        let m = self.m;
        for l in 0..m {
            let mut v = self.lead[l];
            for i in 0..m {
                if i != l {
                    v *= theta - self.c[i];
                }
            }
            out[l] = v;
        }
    }

    /// ∫₀^θ L_l(σ) dσ for every l (exact: m-point Gauss on [0, θ]).
    pub(crate) fn integrated_basis(&self, theta: f64, out: &mut [f64]) {
        let m = self.m;
        out[..m].fill(0.0);
        let mut tmp = [0.0; 8];
        for i in 0..m {
            self.basis(theta * self.c[i], &mut tmp);
            for l in 0..m {
                out[l] += theta * self.b[i] * tmp[l];
            }
        }
    }
}

fn invert(a: &[f64], m: usize) -> Vec<f64> {
    // Gauss–Jordan with partial pivoting on a tiny well-conditioned matrix.
    let mut w = a.to_vec();
    let mut inv = vec![0.0; m * m];
    for i in 0..m {
        inv[i * m + i] = 1.0;
    }
    for col in 0..m {
        let mut p = col;
        for r in col + 1..m {
            if w[r * m + col].abs() > w[p * m + col].abs() {
                p = r;
            }
        }
        for j in 0..m {
            w.swap(col * m + j, p * m + j);
            inv.swap(col * m + j, p * m + j);
        }
        let d = w[col * m + col];
        for j in 0..m {
            w[col * m + j] /= d;
            inv[col * m + j] /= d;
        }
        for r in 0..m {
            if r != col {
                let f = w[r * m + col];
                for j in 0..m {
                    w[r * m + j] -= f * w[col * m + j];
                    inv[r * m + j] -= f * inv[col * m + j];
                }
            }
        }
    }
    inv
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_weights_are_the_legendre_weights() {
        // A&S Table 25.4, halved for [0, 1].
        let w = Tableau::new(4).b;
        let r = [0.173_927_422_568_726_9, 0.326_072_577_431_273_1];
        for (a, b) in w.iter().zip([r[0], r[1], r[1], r[0]]) {
            assert!((a - b).abs() < 1e-15, "{a} vs {b}");
        }
    }

    #[test]
    fn gauss_rule_is_exact_to_degree_2m_minus_1() {
        for m in 2..=7 {
            let t = Tableau::new(m);
            for d in 0..2 * m {
                let q: f64 =
                    t.c.iter()
                        .zip(&t.b)
                        .map(|(c, b)| b * c.powi(d as i32))
                        .sum();
                // Quadrature of a polynomial: rounding only (a few ulps of 1).
                assert!((q - 1.0 / (d as f64 + 1.0)).abs() < 1e-14, "m={m} d={d}");
            }
            // Row sums of A are c_k (∫₀^{c_k} 1), and Σ_l a_kl c_l = c_k²/2.
            for k in 0..m {
                let s: f64 = t.a[k * m..(k + 1) * m].iter().sum();
                assert!((s - t.c[k]).abs() < 1e-14);
                let s2: f64 = (0..m).map(|l| t.a[k * m + l] * t.c[l]).sum();
                assert!((s2 - 0.5 * t.c[k] * t.c[k]).abs() < 1e-14);
            }
        }
    }
}
