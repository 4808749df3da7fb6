//! Directional derivatives of the collocation residual by central
//! differences: the one finite-difference helper of the continuation.

use super::Steps;
use crate::bvp::Problem;
use crate::bvp::system::{Residual, State, System};
use crate::error::Result;

/// Scratch of [`Steps::residual_derivative`]; the derivative is left in
/// `out`.
pub(super) struct Difference {
    plus: State,
    minus: State,
    pub(super) out: Residual,
    back: Residual,
    centre: Residual,
}

impl Difference {
    /// Scratch for [`derivative_on`] on `sys`.
    pub(super) fn on<P: Problem + ?Sized>(sys: &System<'_, P>, x: &State) -> Self {
        Difference {
            plus: x.clone(),
            minus: x.clone(),
            out: sys.zero_residual(),
            back: sys.zero_residual(),
            centre: sys.zero_residual(),
        }
    }
}

/// F(x + εt) into `work.out` and F(x − εt) into `work.back` of `sys`, with
/// ε = `relative` (1 + ‖y‖∞) / ‖t‖∞ over the solution values y of x and
/// the components of t; returns ε.
fn residuals_at_both_sides<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &State,
    t: &State,
    relative: f64,
    work: &mut Difference,
) -> Result<f64> {
    let free = &sys.free;
    let xn = x.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let tn = t.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let tn = free.iter().fold(tn, |a, &q| a.max(t.p[q].abs()));
    let eps = relative * (1.0 + xn) / tn.max(1e-300);
    work.plus.clone_from(x);
    work.plus.axpy(eps, t, free);
    work.minus.clone_from(x);
    work.minus.axpy(-eps, t, free);
    sys.residual(&work.plus, &mut work.out)?;
    sys.residual(&work.minus, &mut work.back)?;
    Ok(eps)
}

/// [`Steps::residual_derivative`] on any system of the run (the halved
/// mesh's too).
pub(super) fn derivative_on<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &State,
    t: &State,
    work: &mut Difference,
) -> Result<()> {
    let eps = residuals_at_both_sides(sys, x, t, 1e-6, work)?;
    let inv = 0.5 / eps;
    for (a, b) in work.out.rows_mut().zip(work.back.rows()) {
        *a = (*a - b) * inv;
    }
    Ok(())
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// Scratch for [`Steps::residual_derivative`] on this run's system.
    pub(super) fn difference(&self, x: &State) -> Difference {
        Difference::on(&self.sys, x)
    }

    /// F_x(x)·t ≈ (F(x + εt) − F(x − εt)) / 2ε into `work.out` (every
    /// residual row, the border included), with
    /// ε = 1e-6 (1 + ‖y‖∞) / ‖t‖∞ over the solution values y of x and the
    /// components of t: truncation O(ε²) and rounding O(u/ε), about 1e-12
    /// of the residual's terms (the rod's terms are large: a tangent refined
    /// with it stalls near 1e-8, measured).
    pub(super) fn residual_derivative(
        &mut self,
        x: &State,
        t: &State,
        work: &mut Difference,
    ) -> Result<()> {
        derivative_on(&mut self.sys, x, t, work)
    }

    /// F_xx(x)[t, t] ≈ (F(x + εt) − 2F(x) + F(x − εt)) / ε² into
    /// `work.out`, the border row (linear) set to 0, with
    /// ε = 1e-4 (1 + ‖y‖∞) / ‖t‖∞: truncation O(ε²) and rounding O(u/ε²)
    /// both about 1e-8 relative, ample for a curvature that enters the
    /// interpolant multiplied by h².
    pub(super) fn residual_second_derivative(
        &mut self,
        x: &State,
        t: &State,
        work: &mut Difference,
    ) -> Result<()> {
        let eps = residuals_at_both_sides(&mut self.sys, x, t, 1e-4, work)?;
        self.sys.residual(x, &mut work.centre)?;
        let inv = 1.0 / (eps * eps);
        let (back, centre) = (&work.back, &work.centre);
        for ((a, b), c) in work.out.rows_mut().zip(back.rows()).zip(centre.rows()) {
            *a = (*a + b - 2.0 * c) * inv;
        }
        let out = &mut work.out;
        let nd = out.dense.len();
        let rows = self.sys.border.rows;
        out.dense[nd - rows..].fill(0.0);
        Ok(())
    }
}
