//! The residual of every equation of the collocation system.

use super::{Residual, State, System};
use crate::bvp::problem::Problem;
use crate::error::{Error, Result};

impl<P: Problem + ?Sized> System<'_, P> {
    /// Evaluates every residual block at `x`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] when f, h or g is not finite.
    pub(crate) fn residual(&mut self, x: &State, r: &mut Residual) -> Result<()> {
        let mut ycol = std::mem::take(&mut self.ycol);
        self.collocation_values(x, &mut ycol);
        let out = self.residual_at(x, &ycol, r);
        self.ycol = ycol;
        out
    }

    fn residual_at(&mut self, x: &State, ycol: &[f64], r: &mut Residual) -> Result<()> {
        let (n, m) = (self.n, self.m);
        let p = &x.p;
        let nint = self.nint;
        r.dense.fill(0.0);
        for j in 0..self.nn {
            let h = self.h(j);
            for k in 0..m {
                let z = self.z(j, k);
                let idx = (j * m + k) * n;
                let yk = &ycol[idx..idx + n];
                let f = &mut self.fbuf[..n];
                self.problem.rhs(z, yk, p, f);
                if f.iter().any(|v| !v.is_finite()) {
                    return Err(Error::NonFinite {
                        what: "right-hand side",
                        s: z,
                    });
                }
                for i in 0..n {
                    r.stage[idx + i] = x.k[idx + i] - f[i];
                }
                if nint > 0 {
                    let hv = &mut self.hbuf[..nint];
                    hv.fill(0.0);
                    self.problem
                        .integrand(z, yk, &self.y_ref[idx..idx + n], p, hv);
                    if hv.iter().any(|v| !v.is_finite()) {
                        return Err(Error::NonFinite {
                            what: "integrand",
                            s: z,
                        });
                    }
                    let w = h * self.tab.b[k];
                    for i in 0..nint {
                        r.dense[i] += w * hv[i];
                    }
                }
            }
            for i in 0..n {
                let mut s = x.y[(j + 1) * n + i] - x.y[j * n + i];
                for k in 0..m {
                    s -= h * self.tab.b[k] * x.k[(j * m + k) * n + i];
                }
                r.cont[j * n + i] = s;
            }
        }
        let nbc = self.nbc;
        let g = &mut self.fbuf[..nbc];
        self.problem.boundary(&x.y[..n], &x.y[self.nn * n..], p, g);
        if g.iter().any(|v| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: "boundary conditions",
                s: f64::NAN,
            });
        }
        r.bc.copy_from_slice(g);
        let len = self.nn * m * n;
        for b in 0..self.border.rows {
            let cy = &self.border.coef_y[b * len..(b + 1) * len];
            let mut s: f64 = cy.iter().zip(ycol).map(|(a, v)| a * v).sum();
            for (qi, &pi) in self.free.iter().enumerate() {
                s += self.border.coef_q[b * self.nq + qi] * p[pi];
            }
            r.dense[nint + b] = s - self.border.target[b];
        }
        Ok(())
    }
}
