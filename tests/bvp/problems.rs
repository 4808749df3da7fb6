//! Classical test problems with independent references (closed forms and
//! published values), shared by the bvp and continuation suites.

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
