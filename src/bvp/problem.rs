//! The problem trait: what a boundary-value problem is, apart from how it is
//! solved.

use nalgebra::DMatrixViewMut;

/// A two-point boundary-value problem on s ∈ [0, 1] with parameters p:
///
/// ```text
///   y′(s) = f(s, y, p)                      n ODEs
///   g(y(0), y(1), p) = 0                    n_bc boundary conditions
///   ∫₀¹ h(s, y, y_ref, p) ds = 0             n_int integral conditions
/// ```
///
/// Boundary conditions may be non-separated. `y_ref` in the integrand is a
/// reference solution supplied by the solver (the previous point of a
/// continuation, or the initial guess), so that phase conditions for
/// continuous symmetries, ∫ ⟨y, G y_ref⟩ ds = 0, can be written as integral
/// conditions.
///
/// The parameter vector holds every parameter of the problem; which of them
/// are unknowns (free) is the solver's and the continuation's business. A
/// well-posed problem has `n_bc + n_int = n + (number of free parameters)`.
///
/// Jacobians are optional: each `*_jacobian` method returns `false` by
/// default, and the solver then uses finite differences. An implementation
/// that returns `true` must have filled every entry of the matrices it was
/// given (they arrive zeroed).
///
/// Problems are `Sync`: the collocation solver may evaluate one from
/// several threads at once (the `rayon` feature condenses intervals in
/// parallel). A problem that keeps counters or caches needs atomics or a
/// `Mutex` for them.
pub trait Problem: Sync {
    /// The number of ODEs, n.
    fn dim(&self) -> usize;

    /// The number of parameters (free and fixed), the length of `p`.
    fn parameter_count(&self) -> usize;

    /// The number of boundary conditions, n_bc.
    fn boundary_count(&self) -> usize;

    /// The number of integral conditions, n_int (default 0).
    fn integral_count(&self) -> usize {
        0
    }

    /// The right-hand side: writes f(s, y, p) into `f` (length n).
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]);

    /// ∂f/∂y (n × n) into `dfdy` and ∂f/∂p (n × parameter_count) into
    /// `dfdp`; returns whether it did (default: no, use finite differences).
    fn rhs_jacobian(
        &self,
        s: f64,
        y: &[f64],
        p: &[f64],
        dfdy: DMatrixViewMut<'_, f64>,
        dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let _ = (s, y, p, dfdy, dfdp);
        false
    }

    /// The boundary conditions: writes g(y(0), y(1), p) into `g` (length n_bc).
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]);

    /// ∂g/∂y(0), ∂g/∂y(1) (n_bc × n each) and ∂g/∂p (n_bc × parameter_count);
    /// returns whether it did (default: no, use finite differences).
    fn boundary_jacobian(
        &self,
        y0: &[f64],
        y1: &[f64],
        p: &[f64],
        dg0: DMatrixViewMut<'_, f64>,
        dg1: DMatrixViewMut<'_, f64>,
        dgp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let _ = (y0, y1, p, dg0, dg1, dgp);
        false
    }

    /// The integrands of the integral conditions: writes h(s, y, y_ref, p)
    /// into `h` (length n_int). Default: no integral conditions.
    fn integrand(&self, s: f64, y: &[f64], y_ref: &[f64], p: &[f64], h: &mut [f64]) {
        let _ = (s, y, y_ref, p, h);
    }

    /// ∂h/∂y (n_int × n) and ∂h/∂p (n_int × parameter_count); returns whether
    /// it did (default: no, use finite differences).
    fn integrand_jacobian(
        &self,
        s: f64,
        y: &[f64],
        y_ref: &[f64],
        p: &[f64],
        dhdy: DMatrixViewMut<'_, f64>,
        dhdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let _ = (s, y, y_ref, p, dhdy, dhdp);
        false
    }
}
