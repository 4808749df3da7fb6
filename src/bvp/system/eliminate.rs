//! The elimination of the interior mesh values.
//!
//! After condensation interval j reads −Γ_j dY_j + dY_{j+1} − Π_j dq = ρ_j.
//! The carry row block (n rows in dY_j, dY_N-side and (Y_0, Y_N, q) columns)
//! is stacked on interval j's rows into a 2n-row panel, and dY_j is
//! eliminated by partial pivoting over those 2n rows (AUTO-07p's `solvebv`
//! structure): the bottom n rows become the next carry. The last carry,
//! with Y_N's columns folded into the (Y_0, Y_N, q) columns, is the first
//! block row of the final system.

use super::{System, map_breakdown};
use crate::bvp::problem::Problem;
use crate::error::Result;
use crate::linalg::{Det, lu_panel};

impl<P: Problem + ?Sized> System<'_, P> {
    /// Eliminates the interior mesh unknowns Y_1..Y_{N−1}.
    ///
    /// # Errors
    /// [`Error::SingularJacobian`] ("mesh elimination") on a zero pivot.
    pub(super) fn eliminate_mesh(&mut self) -> Result<()> {
        let (n, nq, nn) = (self.n, self.nq, self.nn);
        let nz = 2 * n + nq;
        let cc = n + nz;
        let pcols = 2 * n + nz;
        let rows = 2 * n;
        // Initial carry from interval 0: I dY_1 − Γ_0 dY_0 − Π_0 dq.
        self.carry.fill(0.0);
        for i in 0..n {
            self.carry[i * n + i] = 1.0;
        }
        for c in 0..n {
            for r in 0..n {
                self.carry[(n + c) * n + r] = -self.gam[c * n + r];
            }
        }
        for qi in 0..nq {
            for r in 0..n {
                self.carry[(n + 2 * n + qi) * n + r] = -self.pim[qi * n + r];
            }
        }
        let mut pdet = Det::ONE;
        for j in 1..nn {
            let pb = (j - 1) * rows * pcols;
            let panel = &mut self.panels[pb..pb + rows * pcols];
            panel.fill(0.0);
            // carry: [A | 0 | Zc]
            for c in 0..n {
                for r in 0..n {
                    panel[c * rows + r] = self.carry[c * n + r];
                }
            }
            for c in 0..nz {
                for r in 0..n {
                    panel[(2 * n + c) * rows + r] = self.carry[(n + c) * n + r];
                }
            }
            // interval j: [−Γ_j | I | 0 0 −Π_j]
            for c in 0..n {
                for r in 0..n {
                    panel[c * rows + n + r] = -self.gam[j * n * n + c * n + r];
                }
                panel[(n + c) * rows + n + c] = 1.0;
            }
            for qi in 0..nq {
                for r in 0..n {
                    panel[(4 * n + qi) * rows + n + r] = -self.pim[j * n * nq + qi * n + r];
                }
            }
            let piv = &mut self.ppiv[(j - 1) * n..j * n];
            let d = lu_panel(panel, rows, pcols, n, piv)
                .map_err(|b| map_breakdown(b, "mesh elimination", j))?;
            pdet = pdet.mul(d);
            for c in 0..cc {
                for r in 0..n {
                    self.carry[c * n + r] = panel[(n + c) * rows + n + r];
                }
            }
        }
        // The final carry's A multiplies Y_N.
        for c in 0..n {
            for r in 0..n {
                self.carry[(2 * n + c) * n + r] += self.carry[c * n + r];
            }
        }
        self.pdet = pdet;
        Ok(())
    }
}
