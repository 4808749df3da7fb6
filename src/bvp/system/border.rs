//! The dense rows (integral conditions and the caller's border rows) and
//! the final system.
//!
//! A dense row Σ_jk D_jk dY_jk + D_q dq = d reaches every interval. Through
//! the condensation dY_jk = dY_j + h_j Σ_l a_kl dK_jl becomes
//! C_j dY_j + Cp_j dq with C_j = E_j + F_j G_j, Cp_j = F_j Q_j
//! (E_j = Σ_k D_jk, F_jl = h_j Σ_k D_jk a_kl); the interior dY_j are then
//! eliminated with the panels of the mesh elimination, leaving rows in
//! (Y_0, Y_N, q). Stacked under the last carry and the boundary rows they
//! make the final (2n + n_q) system, factored here.

use super::{LinearSolver, System, map_breakdown};
use crate::bvp::problem::Problem;
use crate::error::Result;
use crate::linalg::{Det, lu_panel, solve_upper_left};

/// Linear bordering rows: Σ_jk coef_y[r]·Y_jk + coef_q[r]·q − target[r].
#[derive(Debug, Clone, Default)]
pub(crate) struct Border {
    pub rows: usize,
    /// rows × (N m n), row-major by row.
    pub coef_y: Vec<f64>,
    /// rows × n_q, row-major.
    pub coef_q: Vec<f64>,
    pub target: Vec<f64>,
}

impl<P: Problem + ?Sized> System<'_, P> {
    /// The dense-row coefficient D_jk (nd × n, col-major) of collocation
    /// point (j, k) into `out`.
    pub(super) fn dense_coef(&self, j: usize, k: usize, out: &mut [f64]) {
        let (n, m, nint) = (self.n, self.m, self.nint);
        let nd = self.nd();
        let len = self.nn * m * n;
        let d = &self.dint[(j * m + k) * nint * n..(j * m + k + 1) * nint * n];
        for c in 0..n {
            for r in 0..nint {
                out[c * nd + r] = d[c * nint + r];
            }
            for b in 0..self.border.rows {
                out[c * nd + nint + b] = self.border.coef_y[b * len + (j * m + k) * n + c];
            }
        }
    }

    /// The dense rows through the elimination and the factorisation of the
    /// final (2n + n_q) system; with the sparse LU, the numeric factorisation
    /// of the full system. Must be re-run after the border rows change
    /// (cheap: no problem evaluations). Returns the determinant as
    /// [`factor`](System::factor) does.
    ///
    /// # Errors
    /// [`Error::SingularJacobian`] ("boundary block" or "sparse system").
    pub(crate) fn factor_border(&mut self) -> Result<Det> {
        let det = self.factor_final()?;
        if self.pinning {
            self.find_pinned_modes();
        }
        Ok(det)
    }

    /// [`factor_border`](Self::factor_border) without the search for
    /// pinned modes.
    pub(super) fn factor_final(&mut self) -> Result<Det> {
        if self.active() == LinearSolver::SparseLu {
            return self.factor_sparse();
        }
        self.factored = false;
        let (n, m, nq, nn, nint, nbc) = (self.n, self.m, self.nq, self.nn, self.nint, self.nbc);
        let mn = m * n;
        let nd = self.nd();
        let nz = 2 * n + nq;
        let wcols = mn + n + nq;
        let rows = 2 * n;
        let pcols = 2 * n + nz;
        let mut dz = std::mem::take(&mut self.dz);
        let mut dcur = std::mem::take(&mut self.dcur);
        let mut cbuf = std::mem::take(&mut self.cbuf);
        let mut fmat = std::mem::take(&mut self.fmat);
        let mut smat = std::mem::take(&mut self.smat);
        dz.fill(0.0);
        dcur.fill(0.0);
        for qi in 0..nq {
            for r in 0..nint {
                dz[(2 * n + qi) * nd + r] = self.dint_p[qi * nint + r];
            }
            for b in 0..self.border.rows {
                dz[(2 * n + qi) * nd + nint + b] = self.border.coef_q[b * nq + qi];
            }
        }
        let mut dk = vec![0.0; nd * n];
        // E_j row-major (nd × n) and one row of S_j
        let mut erow = vec![0.0; nd * n];
        let mut srow = vec![0.0; n];
        for j in 0..nn {
            if nd == 0 {
                break;
            }
            let h = self.h(j);
            // E_j = Σ_k D_jk; F_j,l = h Σ_k D_jk a_kl (row-major, nd × mn:
            // every row a contiguous vector, so that the products below and
            // the solve's F_j κ_j are dot products).
            let f = &mut fmat[j * nd * mn..(j + 1) * nd * mn];
            f.fill(0.0);
            erow.fill(0.0);
            for k in 0..m {
                self.dense_coef(j, k, &mut dk);
                for r in 0..nd {
                    let e = &mut erow[r * n..(r + 1) * n];
                    for (c, ev) in e.iter_mut().enumerate() {
                        *ev += dk[c * nd + r];
                    }
                    let frow = &mut f[r * mn..(r + 1) * mn];
                    for l in 0..m {
                        let a = h * self.tab.a[k * m + l];
                        for (c, fv) in frow[l * n..(l + 1) * n].iter_mut().enumerate() {
                            *fv += a * dk[c * nd + r];
                        }
                    }
                }
            }
            // C_j = E_j + F_j G_j, Cp_j = F_j Q_j (into cbuf, nd × (n + nq)
            // column-major).
            let wa = &self.wa[j * mn * wcols..(j + 1) * mn * wcols];
            for c in 0..n + nq {
                let g = &wa[(mn + c) * mn..(mn + c + 1) * mn];
                for r in 0..nd {
                    let mut acc = if c < n { erow[r * n + c] } else { 0.0 };
                    for (fv, gv) in f[r * mn..(r + 1) * mn].iter().zip(g) {
                        acc += fv * gv;
                    }
                    cbuf[c * nd + r] = acc;
                }
            }
            for qi in 0..nq {
                for r in 0..nd {
                    dz[(2 * n + qi) * nd + r] += cbuf[(n + qi) * nd + r];
                }
            }
            if j == 0 {
                for c in 0..n {
                    for r in 0..nd {
                        dz[c * nd + r] += cbuf[c * nd + r];
                    }
                }
                continue;
            }
            for (d, cv) in dcur.iter_mut().zip(&cbuf[..nd * n]) {
                *d += cv;
            }
            // Eliminate Y_j: S = Dcur U⁻¹; Dnext = −S X; Dz −= S Z', row by
            // row of S.
            let panel = &self.panels[(j - 1) * rows * pcols..j * rows * pcols];
            let s = &mut smat[(j - 1) * nd * n..j * nd * n];
            for r in 0..nd {
                for c in 0..n {
                    srow[c] = dcur[c * nd + r];
                }
                solve_upper_left(panel, rows, n, &mut srow);
                for c in 0..n {
                    s[c * nd + r] = srow[c];
                }
                for c in 0..n {
                    let x = &panel[(n + c) * rows..(n + c) * rows + n];
                    let mut acc = 0.0;
                    for (sv, xv) in srow.iter().zip(x) {
                        acc -= sv * xv;
                    }
                    dcur[c * nd + r] = acc;
                }
                for c in 0..nz {
                    let x = &panel[(2 * n + c) * rows..(2 * n + c) * rows + n];
                    let mut acc = dz[c * nd + r];
                    for (sv, xv) in srow.iter().zip(x) {
                        acc -= sv * xv;
                    }
                    dz[c * nd + r] = acc;
                }
            }
        }
        if nn >= 1 {
            for c in 0..n {
                for r in 0..nd {
                    dz[(n + c) * nd + r] += dcur[c * nd + r];
                }
            }
        }
        // Final system rows: carry (n), bc (nbc), dense (nd).
        let fin = &mut self.fin;
        fin.fill(0.0);
        for c in 0..nz {
            for r in 0..n {
                fin[c * nz + r] = self.carry[(n + c) * n + r];
            }
        }
        for c in 0..n {
            for r in 0..nbc {
                fin[c * nz + n + r] = self.bc0[c * nbc + r];
                fin[(n + c) * nz + n + r] = self.bc1[c * nbc + r];
            }
        }
        for qi in 0..nq {
            for r in 0..nbc {
                fin[(2 * n + qi) * nz + n + r] = self.bcp[qi * nbc + r];
            }
        }
        for c in 0..nz {
            for r in 0..nd {
                fin[c * nz + n + nbc + r] = dz[c * nd + r];
            }
        }
        self.dz = dz;
        self.dcur = dcur;
        self.cbuf = cbuf;
        self.fmat = fmat;
        self.smat = smat;
        let d = lu_panel(&mut self.fin, nz, nz, nz, &mut self.fpiv)
            .map_err(|b| map_breakdown(b, "boundary block", 0))?;
        self.factored = true;
        Ok(self.wdet.mul(self.pdet).mul(d))
    }
}
