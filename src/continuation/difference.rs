//! Directional derivatives of the collocation residual by central
//! differences: the one finite-difference helper of the continuation.

use super::Steps;
use crate::bvp::Problem;
use crate::bvp::system::{Residual, State};
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

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// Scratch for [`Steps::residual_derivative`] on this run's system.
    pub(super) fn difference(&self, x: &State) -> Difference {
        Difference {
            plus: x.clone(),
            minus: x.clone(),
            out: self.sys.zero_residual(),
            back: self.sys.zero_residual(),
            centre: self.sys.zero_residual(),
        }
    }

    /// F_x(x)·t ≈ (F(x + εt) − F(x − εt)) / 2ε into `work.out` (every
    /// residual row, the border included), with
    /// ε = 1e-6 (1 + ‖y‖∞) / ‖t‖∞ over the solution values y of x and the
    /// components of t: truncation O(ε²) and rounding O(u/ε) both about
    /// 1e-12 relative.
    pub(super) fn residual_derivative(
        &mut self,
        x: &State,
        t: &State,
        work: &mut Difference,
    ) -> Result<()> {
        let free = &self.sys.free;
        let xn = x.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let tn = t.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let tn = free.iter().fold(tn, |a, &q| a.max(t.p[q].abs()));
        let eps = 1e-6 * (1.0 + xn) / tn.max(1e-300);
        work.plus.clone_from(x);
        work.plus.axpy(eps, t, free);
        work.minus.clone_from(x);
        work.minus.axpy(-eps, t, free);
        self.sys.residual(&work.plus, &mut work.out)?;
        self.sys.residual(&work.minus, &mut work.back)?;
        let inv = 0.5 / eps;
        let out = &mut work.out;
        let back = &work.back;
        for (a, b) in out
            .stage
            .iter_mut()
            .chain(out.cont.iter_mut())
            .chain(out.bc.iter_mut())
            .chain(out.dense.iter_mut())
            .zip(
                back.stage
                    .iter()
                    .chain(&back.cont)
                    .chain(&back.bc)
                    .chain(&back.dense),
            )
        {
            *a = (*a - b) * inv;
        }
        Ok(())
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
        let free = &self.sys.free;
        let xn = x.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let tn = t.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let tn = free.iter().fold(tn, |a, &q| a.max(t.p[q].abs()));
        let eps = 1e-4 * (1.0 + xn) / tn.max(1e-300);
        work.plus.clone_from(x);
        work.plus.axpy(eps, t, free);
        work.minus.clone_from(x);
        work.minus.axpy(-eps, t, free);
        self.sys.residual(&work.plus, &mut work.out)?;
        self.sys.residual(&work.minus, &mut work.back)?;
        self.sys.residual(x, &mut work.centre)?;
        let inv = 1.0 / (eps * eps);
        let out = &mut work.out;
        let (back, centre) = (&work.back, &work.centre);
        for ((a, b), c) in out
            .stage
            .iter_mut()
            .chain(out.cont.iter_mut())
            .chain(out.bc.iter_mut())
            .chain(out.dense.iter_mut())
            .zip(
                back.stage
                    .iter()
                    .chain(&back.cont)
                    .chain(&back.bc)
                    .chain(&back.dense),
            )
            .zip(
                centre
                    .stage
                    .iter()
                    .chain(&centre.cont)
                    .chain(&centre.bc)
                    .chain(&centre.dense),
            )
        {
            *a = (*a + b - 2.0 * c) * inv;
        }
        let nd = out.dense.len();
        let rows = self.sys.border.rows;
        out.dense[nd - rows..].fill(0.0);
        Ok(())
    }
}
