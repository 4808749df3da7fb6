//! Classical test problems with independent references (closed forms and
//! published values), shared by the bvp and continuation suites.
#![allow(clippy::needless_range_loop)]

use hockle::bvp::Problem;
use hockle::nalgebra::DMatrixViewMut;

/// y'' = y, y(0) = 1, y(1) = 0: exact y = sinh(1 − s)/sinh(1).
pub struct Linear;

impl Linear {
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

/// Bratu: y'' + λ e^y = 0, y(0) = y(1) = 0; p = [λ]. `analytic` selects
/// the hand-written Jacobians (otherwise finite differences).
pub struct Bratu {
    pub analytic: bool,
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
pub fn bratu_lambda(theta: f64) -> f64 {
    theta * theta / (2.0 * (theta / 4.0).cosh().powi(2))
}

/// Troesch: y'' = μ sinh(μ y), y(0) = 0, y(1) = 1; p = [μ].
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

/// u'' + (pπ)² u − u² = 0, u(0) = u(1) = 0; p = [p]. The trivial branch
/// u = 0 has branch points exactly at p = 1, 2, 3, …
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

/// Euler buckling θ'' + P sin θ = 0, θ'(0) = θ'(1) = 0; p = [P]. Branch
/// points at P = k²π²; the first buckled branch has P = 4 K(k)², k = sin(θ(0)/2).
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

/// K(k) by the arithmetic–geometric mean: K = π / (2 AGM(1, √(1 − k²)))
/// (DLMF 19.8.5), independent of the code under test.
pub fn ellip_k_agm(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        let (an, bn) = (0.5 * (a + b), (a * b).sqrt());
        a = an;
        b = bn;
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
    }
    std::f64::consts::PI / (2.0 * a)
}

/// A 13-dimensional nonlinear test system of the size of the 3D rod:
/// y′ = M y + 0.1 sin(y) + p₀ with a fixed dense M (M_ij = 0.5 sin(i + 2j + 1)),
/// y_i(0) = 0 for i < 7, y_i(1) = 0.1 (i − 6) for i ≥ 7; analytic Jacobians.
pub struct Coupled13 {
    m: [[f64; 13]; 13],
}

impl Coupled13 {
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
        for i in 0..13 {
            let mut v = 0.1 * y[i].sin() + p[0];
            for j in 0..13 {
                v += self.m[i][j] * y[j];
            }
            f[i] = v;
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
        for i in 0..13 {
            for j in 0..13 {
                dfdy[(i, j)] = self.m[i][j];
            }
            dfdy[(i, i)] += 0.1 * y[i].cos();
            dfdp[(i, 0)] = 1.0;
        }
        true
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[..7].copy_from_slice(&y0[..7]);
        for i in 7..13 {
            g[i] = y1[i] - 0.1 * (i as f64 - 6.0);
        }
    }
}
