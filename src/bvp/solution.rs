//! The solution of a collocation solve.

use std::fmt;

use nalgebra::{DMatrix, DVector};

use super::mesh::Mesh;
use super::system::State;
use super::tableau::Tableau;

/// What Newton's method did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct NewtonStats {
    /// Corrections applied (full, damped or chord).
    pub iterations: u32,
    /// Jacobian evaluations and factorisations.
    pub jacobians: u32,
    /// The scaled max-norm of the last correction, ‖δ‖∞ / (1 + ‖x‖∞).
    pub correction: f64,
}

impl fmt::Display for NewtonStats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} Newton iterations, {} Jacobians, last correction {:.2e}",
            self.iterations, self.jacobians, self.correction
        )
    }
}

/// A collocation solution: the piecewise polynomial u of degree m on each
/// mesh interval, continuous at the mesh points, satisfying the ODE at the m
/// Gauss points of every interval.
#[derive(Debug, Clone)]
pub struct Solution {
    pub(crate) mesh: Mesh,
    pub(crate) tab: Tableau,
    pub(crate) n: usize,
    pub(crate) y: Vec<f64>,
    pub(crate) k: Vec<f64>,
    pub(crate) p: Vec<f64>,
    pub(crate) residual_norm: f64,
    pub(crate) error_estimate: f64,
    pub(crate) newton: NewtonStats,
    /// The number of boundary conditions of the problem it solves (`None`
    /// for an interpolant): what tells a symmetric rod's half from the
    /// whole rod's solution, both with 13 unknowns.
    pub(crate) boundaries: Option<usize>,
}

impl Solution {
    /// The mesh.
    #[must_use]
    pub fn mesh(&self) -> &Mesh {
        &self.mesh
    }

    /// Collocation points per interval, m.
    #[must_use]
    pub fn points_per_interval(&self) -> usize {
        self.tab.m
    }

    /// The m Gauss–Legendre weights on [0, 1] of the collocation points
    /// (multiply by an interval's width for the composite rule).
    pub(crate) fn gauss_weights(&self) -> &[f64] {
        &self.tab.b
    }

    /// The dimension n of the ODE system.
    #[must_use]
    pub fn dim(&self) -> usize {
        self.n
    }

    /// Every parameter (free and fixed).
    #[must_use]
    pub fn parameters(&self) -> &[f64] {
        &self.p
    }

    /// u(t_j) at mesh point j as a slice (length n).
    ///
    /// # Panics
    /// If `j > N`.
    #[must_use]
    pub fn at_mesh(&self, j: usize) -> &[f64] {
        &self.y[j * self.n..(j + 1) * self.n]
    }

    /// All mesh values, n × (N + 1).
    #[must_use]
    pub fn mesh_values(&self) -> DMatrix<f64> {
        DMatrix::from_column_slice(self.n, self.mesh.intervals() + 1, &self.y)
    }

    /// The collocation points z_jk = t_j + c_k h_j in order.
    #[must_use]
    pub fn collocation_points(&self) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.mesh.intervals() * self.tab.m);
        for j in 0..self.mesh.intervals() {
            for c in &self.tab.c {
                out.push(self.mesh.points()[j] + c * self.mesh.width(j));
            }
        }
        out
    }

    /// The values at the collocation points, n × (N m).
    #[must_use]
    pub fn collocation_values(&self) -> DMatrix<f64> {
        let (n, m) = (self.n, self.tab.m);
        let nn = self.mesh.intervals();
        let mut out = DMatrix::zeros(n, nn * m);
        let mut lam = [0.0; 8];
        for j in 0..nn {
            let h = self.mesh.width(j);
            for k in 0..m {
                lam[..m].copy_from_slice(&self.tab.a[k * m..(k + 1) * m]);
                for i in 0..n {
                    let mut v = self.y[j * n + i];
                    for l in 0..m {
                        v += h * lam[l] * self.k[(j * m + l) * n + i];
                    }
                    out[(i, j * m + k)] = v;
                }
            }
        }
        out
    }

    /// The collocation polynomial u(s) (s is clamped to [0, 1]):
    ///
    /// ```text
    ///   u(t_j + θ h_j) = Y_j + h_j Σ_l K_jl ∫₀^θ L_l(σ) dσ
    /// ```
    ///
    /// with L_l the Lagrange basis on the Gauss nodes and K_jl = u′(z_jl).
    /// Accurate to O(h^(m+1)) between mesh points, O(h^(2m)) at them.
    #[must_use]
    pub fn eval(&self, s: f64) -> DVector<f64> {
        let mut out = DVector::zeros(self.n);
        self.eval_into(s, out.as_mut_slice());
        out
    }

    /// [`Solution::eval`] into a slice of length n (no allocation).
    ///
    /// # Panics
    /// If `out.len() != n`.
    pub fn eval_into(&self, s: f64, out: &mut [f64]) {
        let (n, m) = (self.n, self.tab.m);
        let (j, theta) = self.mesh.locate(s);
        let h = self.mesh.width(j);
        let mut lam = [0.0; 8];
        self.tab.integrated_basis(theta, &mut lam);
        out.copy_from_slice(&self.y[j * n..(j + 1) * n]);
        for l in 0..m {
            for (i, o) in out.iter_mut().enumerate() {
                *o += h * lam[l] * self.k[(j * m + l) * n + i];
            }
        }
    }

    /// The derivative u′(s) = Σ_l K_jl L_l(θ) of the collocation polynomial.
    #[must_use]
    pub fn derivative(&self, s: f64) -> DVector<f64> {
        let (n, m) = (self.n, self.tab.m);
        let (j, theta) = self.mesh.locate(s);
        let mut lb = [0.0; 8];
        self.tab.basis(theta, &mut lb);
        let mut out = DVector::zeros(n);
        for l in 0..m {
            for i in 0..n {
                out[i] += lb[l] * self.k[(j * m + l) * n + i];
            }
        }
        out
    }

    /// The max-norm of the discrete residual (stage, continuity, boundary
    /// and integral equations) at the returned solution.
    #[must_use]
    pub fn residual_norm(&self) -> f64 {
        self.residual_norm
    }

    /// Estimate of the max-norm error between mesh points,
    /// max_j C_m h_j^(m+1) ‖y^(m+1)‖ on interval j, with y^(m+1) from
    /// differences of the piecewise-constant u^(m) (AUTO's estimate).
    /// It is `NaN` for a one-interval mesh. A solution of
    /// [`Collocation::tolerance`](super::Collocation::tolerance) carries
    /// instead twice the largest difference from its solution on the halved
    /// mesh, over components (a bound whenever halving at least halves the
    /// error; the local estimate can fall far short where the mesh does not
    /// yet resolve the solution).
    #[must_use]
    pub fn error_estimate(&self) -> f64 {
        self.error_estimate
    }

    /// Newton statistics of the solve that produced this solution.
    #[must_use]
    pub fn newton(&self) -> NewtonStats {
        self.newton
    }

    /// The collocation polynomial of the unknowns `x` on `mesh`, as a
    /// solution (for evaluation and remeshing; no residual or estimate).
    pub(crate) fn interpolant(x: &State, mesh: &Mesh, tab: &Tableau, n: usize) -> Solution {
        Solution {
            mesh: mesh.clone(),
            tab: tab.clone(),
            n,
            y: x.y.clone(),
            k: x.k.clone(),
            p: x.p.clone(),
            residual_norm: f64::NAN,
            error_estimate: f64::NAN,
            newton: NewtonStats::default(),
            boundaries: None,
        }
    }

    /// ‖y^(m+1)‖∞ estimated on each interval (piecewise-constant u^(m)
    /// differenced over neighbouring intervals).
    pub(crate) fn derivative_m1(&self) -> Vec<f64> {
        let (n, m) = (self.n, self.tab.m);
        let nn = self.mesh.intervals();
        let mut fact = 1.0;
        for i in 2..m {
            fact *= i as f64;
        }
        // u^(m) on interval j (constant): (m−1)!/h^(m−1) Σ_l lead_l K_jl.
        let mut um = vec![0.0; nn * n];
        for j in 0..nn {
            let h = self.mesh.width(j);
            let sc = fact / h.powi(m as i32 - 1);
            for l in 0..m {
                for i in 0..n {
                    um[j * n + i] += sc * self.tab.lead[l] * self.k[(j * m + l) * n + i];
                }
            }
        }
        let mut d = vec![0.0; nn];
        if nn < 2 {
            d.fill(f64::NAN);
            return d;
        }
        // Differences at interior mesh points, then each interval takes the
        // larger of its two neighbours.
        let mut at = vec![0.0; nn + 1];
        for j in 1..nn {
            let dist = 0.5 * (self.mesh.width(j - 1) + self.mesh.width(j));
            let mut mx: f64 = 0.0;
            for i in 0..n {
                mx = mx.max((um[j * n + i] - um[(j - 1) * n + i]).abs());
            }
            at[j] = mx / dist;
        }
        at[0] = at[1];
        at[nn] = at[nn - 1];
        for j in 0..nn {
            d[j] = at[j].max(at[j + 1]);
        }
        d
    }

    pub(crate) fn estimate_error(&self) -> f64 {
        let d = self.derivative_m1();
        let m = self.tab.m as i32;
        let mut e: f64 = 0.0;
        for (j, dv) in d.iter().enumerate() {
            e = e.max(self.tab.error_constant * self.mesh.width(j).powi(m + 1) * dv);
        }
        e
    }
}

impl fmt::Display for Solution {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "collocation solution: n = {}, m = {}, {}; residual {:.2e}, error estimate {:.2e}; {}",
            self.n, self.tab.m, self.mesh, self.residual_norm, self.error_estimate, self.newton
        )
    }
}
