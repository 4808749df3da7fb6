//! Classical boundary-value problems with known answers (closed forms and
//! published values): the problems the solver and the continuation are
//! tested and benchmarked on, and small examples of writing a [`Problem`].
//!
//! | problem | known answer |
//! |---|---|
//! | [`Linear`] | y = sinh(1 − s)/sinh(1) |
//! | [`Bratu`] | fold at λ* = 3.513830719125162 with y′(0) = 4; exact family [`bratu_lambda`] |
//! | [`BratuLength`] | on [0, L]: fold at λ*(L) = λ*(1)/L² with dy/dx(0) = 4/L |
//! | [`Troesch`] | y′(0) = 4.575046140632e-2 at μ = 5 (boundary layer at μ = 10) |
//! | [`Quadratic`] | branch points of the trivial branch at p = 1, 2, 3, … |
//! | [`Euler`] | branch points at P = k²π²; first buckled branch P = 4K(k)² |
//! | [`Eigen`] | λ = π², y = √(2a) sin(πs) for every amplitude a |
//! | [`Coupled13`] | none: a 13-dimensional system of the 3D rod's size, for benches |

use nalgebra::DMatrixViewMut;

use super::Problem;

/// y'' = y, y(0) = 1, y(1) = 0: exact y = sinh(1 − s)/sinh(1).
#[derive(Debug, Clone, Copy, Default)]
pub struct Linear;

impl Linear {
    /// The exact solution (y, y′) at s.
    #[must_use]
    pub fn exact(s: f64) -> [f64; 2] {
        let d = 1.0_f64.sinh();
        [(1.0 - s).sinh() / d, -(1.0 - s).cosh() / d]
    }
}

impl Problem for Linear {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        0
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], _p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = y[0];
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0] - 1.0;
        g[1] = y1[0];
    }
}

/// Bratu: y'' + λ e^y = 0, y(0) = y(1) = 0; `p = [λ]`. `analytic` selects
/// the hand-written Jacobians (otherwise finite differences).
#[derive(Debug, Clone, Copy)]
pub struct Bratu {
    /// Whether [`Problem::rhs_jacobian`] gives the analytic Jacobian
    /// (otherwise the solver differences the right-hand side).
    pub analytic: bool,
}

impl Default for Bratu {
    /// With the analytic Jacobian.
    fn default() -> Self {
        Self { analytic: true }
    }
}

impl Problem for Bratu {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = -p[0] * y[0].exp();
    }
    fn rhs_jacobian(
        &self,
        _s: f64,
        y: &[f64],
        p: &[f64],
        mut dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        if !self.analytic {
            return false;
        }
        dfdy[(0, 1)] = 1.0;
        dfdy[(1, 0)] = -p[0] * y[0].exp();
        dfdp[(1, 0)] = -y[0].exp();
        true
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0];
    }
}

/// Bratu exact solution: y = −2 ln(cosh((s − ½)θ/2)/cosh(θ/4)) with
/// θ = √(2λ) cosh(θ/4); y'(0) = θ tanh(θ/4). Given θ, λ = θ²/(2 cosh²(θ/4)).
#[must_use]
pub fn bratu_lambda(theta: f64) -> f64 {
    theta * theta / (2.0 * (theta / 4.0).cosh().powi(2))
}

/// Bratu on a domain of length L: y_xx + λ e^y = 0 on x ∈ [0, L],
/// y(0) = y(L) = 0; `p = [λ, L]`. In s = x/L ∈ [0, 1] the components are
/// (y, dy/ds) and y_ss = −λ L² e^y, Bratu with λ L²: the fold is at
/// λ*(L) = λ*(1)/L² (λ*(1) = 3.513830719125162), where dy/ds(0) = 4, i.e.
/// dy/dx(0) = 4/L. Analytic Jacobians.
#[derive(Debug, Clone, Copy, Default)]
pub struct BratuLength;

impl Problem for BratuLength {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        2
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = -p[0] * p[1] * p[1] * y[0].exp();
    }
    fn rhs_jacobian(
        &self,
        _s: f64,
        y: &[f64],
        p: &[f64],
        mut dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let e = y[0].exp();
        dfdy[(0, 1)] = 1.0;
        dfdy[(1, 0)] = -p[0] * p[1] * p[1] * e;
        dfdp[(1, 0)] = -p[1] * p[1] * e;
        dfdp[(1, 1)] = -2.0 * p[0] * p[1] * e;
        true
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0];
    }
}

/// Troesch: y'' = μ sinh(μ y), y(0) = 0, y(1) = 1; `p = [μ]`.
#[derive(Debug, Clone, Copy, Default)]
pub struct Troesch;

impl Problem for Troesch {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = p[0] * (p[0] * y[0]).sinh();
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0] - 1.0;
    }
}

/// u'' + (pπ)² u − u² = 0, u(0) = u(1) = 0; `p = [p]`. The trivial branch
/// u = 0 has branch points exactly at p = 1, 2, 3, …
#[derive(Debug, Clone, Copy, Default)]
pub struct Quadratic;

impl Problem for Quadratic {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        let w = p[0] * std::f64::consts::PI;
        f[0] = y[1];
        f[1] = -w * w * y[0] + y[0] * y[0];
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0];
    }
}

/// Euler buckling θ'' + P sin θ = 0, θ'(0) = θ'(1) = 0; `p = [P]`. Branch
/// points at P = k²π²; the first buckled branch has P = 4 K(k)², k = sin(θ(0)/2).
#[derive(Debug, Clone, Copy, Default)]
pub struct Euler;

impl Problem for Euler {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = -p[0] * y[0].sin();
    }
    fn rhs_jacobian(
        &self,
        _s: f64,
        y: &[f64],
        p: &[f64],
        mut dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        dfdy[(0, 1)] = 1.0;
        dfdy[(1, 0)] = -p[0] * y[0].cos();
        dfdp[(1, 0)] = -y[0].sin();
        true
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[1];
        g[1] = y1[1];
    }
}

/// The first eigenpair as a boundary-value problem with an integral
/// condition: y″ + λ y = 0, y(0) = y(1) = 0, ∫₀¹ y² ds = a; `p = [λ, a]`.
/// With λ free, every amplitude a gives λ = π² and y = √(2a) sin(πs).
#[derive(Debug, Clone, Copy, Default)]
pub struct Eigen;

impl Problem for Eigen {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        2
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn integral_count(&self) -> usize {
        1
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = -p[0] * y[0];
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0];
    }
    fn integrand(&self, _s: f64, y: &[f64], _r: &[f64], p: &[f64], h: &mut [f64]) {
        h[0] = y[0] * y[0] - p[1];
    }
}

/// A 13-dimensional nonlinear test system of the size of the 3D rod:
/// y′ = M y + 0.1 sin(y) + p₀ with a fixed dense M (M_ij = 0.5 sin(i + 2j + 1)),
/// y_i(0) = 0 for i < 7, y_i(1) = 0.1 (i − 6) for i ≥ 7; analytic Jacobians.
#[derive(Debug, Clone)]
pub struct Coupled13 {
    m: [[f64; 13]; 13],
}

impl Default for Coupled13 {
    fn default() -> Self {
        Self::new()
    }
}

impl Coupled13 {
    /// The system with its fixed matrix M.
    #[must_use]
    pub fn new() -> Self {
        let mut m = [[0.0; 13]; 13];
        for (i, row) in m.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = 0.5 * ((i + 2 * j + 1) as f64).sin();
            }
        }
        Coupled13 { m }
    }
}

impl Problem for Coupled13 {
    fn dim(&self) -> usize {
        13
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        13
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        for ((fi, row), yi) in f.iter_mut().zip(&self.m).zip(y) {
            *fi = 0.1 * yi.sin() + p[0] + row.iter().zip(y).map(|(a, b)| a * b).sum::<f64>();
        }
    }
    fn rhs_jacobian(
        &self,
        _s: f64,
        y: &[f64],
        _p: &[f64],
        mut dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        for (i, row) in self.m.iter().enumerate() {
            for (j, v) in row.iter().enumerate() {
                dfdy[(i, j)] = *v;
            }
            dfdy[(i, i)] += 0.1 * y[i].cos();
            dfdp[(i, 0)] = 1.0;
        }
        true
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[..7].copy_from_slice(&y0[..7]);
        for (i, gi) in g.iter_mut().enumerate().skip(7) {
            *gi = y1[i] - 0.1 * (i as f64 - 6.0);
        }
    }
}
