//! The full uncondensed system through faer's sparse LU: the reference
//! for the condensed path ([`LinearSolver::SparseLu`]) and its fallback when
//! an interval block or elimination panel is singular.
//!
//! Unknowns are ordered [Y_0..Y_N | K (N m n) | q], equations
//! [stage (N m n) | continuity (N n) | boundary | dense]. Every structural
//! entry is listed, zero or not, so the pattern depends only on the sizes
//! and the system's symbolic analysis is done once; each Jacobian (and each
//! change of the border rows) costs one numeric factorisation, each Newton
//! correction one solve.

use super::{LinearSolver, Residual, State, System};
use crate::bvp::problem::Problem;
use crate::error::{Error, Result};
use crate::linalg::{Det, SparseLu, SparsePattern};

/// The sparse path's pattern, its symbolic analysis and the current
/// numeric factorisation.
#[derive(Default)]
pub(super) struct SparseSystem {
    entries: Vec<(usize, usize)>,
    values: Vec<f64>,
    pattern: Option<SparsePattern>,
    lu: Option<SparseLu>,
    /// Symbolic analyses done so far (one per pattern).
    pub analyses: usize,
}

impl<P: Problem + ?Sized> System<'_, P> {
    /// Assembles the full Jacobian from the unfactored interval blocks, the
    /// boundary and the dense rows, and factors it numerically (the
    /// symbolic analysis only when the pattern is new).
    pub(super) fn factor_sparse(&mut self) -> Result<Det> {
        self.factored = false;
        let mut entries = std::mem::take(&mut self.sparse.entries);
        let mut values = std::mem::take(&mut self.sparse.values);
        entries.clear();
        values.clear();
        self.assemble(&mut |i, j, v| {
            entries.push((i, j));
            values.push(v);
        });
        let size = (self.nn + 1) * self.n + self.nn * self.m * self.n + self.nq;
        let sp = &mut self.sparse;
        if !sp.pattern.as_ref().is_some_and(|p| p.is(size, &entries)) {
            sp.pattern = SparsePattern::new(size, &entries);
            sp.analyses += 1;
        }
        sp.lu = sp.pattern.as_ref().and_then(|p| p.factor(&values));
        sp.entries = entries;
        sp.values = values;
        if sp.lu.is_none() {
            return Err(Error::SingularJacobian {
                block: "sparse system",
                index: 0,
            });
        }
        self.factored = true;
        // The sparse LU gives no determinant.
        Ok(Det {
            sign: f64::NAN,
            log_abs: f64::NAN,
        })
    }

    /// Every structural entry (row, column, value) of the full Jacobian.
    fn assemble(&self, push: &mut impl FnMut(usize, usize, f64)) {
        let (n, m, nq, nn, nbc, nint) = (self.n, self.m, self.nq, self.nn, self.nbc, self.nint);
        let mn = m * n;
        let wcols = mn + n + nq;
        let ky = (nn + 1) * n;
        let kq = ky + nn * mn;
        // Stage rows from the unfactored blocks [W_j | J_j | J^p_j].
        for j in 0..nn {
            let wa = &self.wa[j * mn * wcols..(j + 1) * mn * wcols];
            for k in 0..m {
                for r in 0..n {
                    let row = (j * m + k) * n + r;
                    let at = |col: usize| wa[col * mn + k * n + r];
                    for c in 0..n {
                        push(row, j * n + c, -at(mn + c));
                    }
                    for l in 0..m {
                        for c in 0..n {
                            push(row, ky + (j * m + l) * n + c, at(l * n + c));
                        }
                    }
                    for qi in 0..nq {
                        push(row, kq + qi, -at(mn + n + qi));
                    }
                }
            }
        }
        // Continuity rows.
        let r0 = nn * mn;
        for j in 0..nn {
            let h = self.h(j);
            for i in 0..n {
                push(r0 + j * n + i, (j + 1) * n + i, 1.0);
                push(r0 + j * n + i, j * n + i, -1.0);
                for k in 0..m {
                    push(r0 + j * n + i, ky + (j * m + k) * n + i, -h * self.tab.b[k]);
                }
            }
        }
        // Boundary rows.
        let r1 = r0 + nn * n;
        for rr in 0..nbc {
            for c in 0..n {
                push(r1 + rr, c, self.bc0[c * nbc + rr]);
                push(r1 + rr, nn * n + c, self.bc1[c * nbc + rr]);
            }
            for qi in 0..nq {
                push(r1 + rr, kq + qi, self.bcp[qi * nbc + rr]);
            }
        }
        // Dense rows through the collocation values.
        let r2 = r1 + nbc;
        let nd = self.nd();
        let mut dk = vec![0.0; nd * n];
        for j in 0..nn {
            let h = self.h(j);
            for k in 0..m {
                self.dense_coef(j, k, &mut dk);
                for rr in 0..nd {
                    for c in 0..n {
                        let d = dk[c * nd + rr];
                        push(r2 + rr, j * n + c, d);
                        for l in 0..m {
                            let a = h * self.tab.a[k * m + l];
                            push(r2 + rr, ky + (j * m + l) * n + c, d * a);
                        }
                    }
                }
            }
        }
        for qi in 0..nq {
            for rr in 0..nint {
                push(r2 + rr, kq + qi, self.dint_p[qi * nint + rr]);
            }
            for b in 0..self.border.rows {
                push(r2 + nint + b, kq + qi, self.border.coef_q[b * nq + qi]);
            }
        }
    }

    /// A Newton correction with the sparse factorisation.
    pub(super) fn solve_sparse(&mut self, r: &Residual, out: &mut State) -> Result<()> {
        debug_assert_eq!(self.active(), LinearSolver::SparseLu);
        let (n, m, nn) = (self.n, self.m, self.nn);
        let ky = (nn + 1) * n;
        let kq = ky + nn * m * n;
        let mut rhs = Vec::with_capacity(kq + self.nq);
        rhs.extend(r.stage.iter().map(|v| -v));
        rhs.extend(r.cont.iter().map(|v| -v));
        rhs.extend(r.bc.iter().map(|v| -v));
        rhs.extend(r.dense.iter().map(|v| -v));
        let x = self
            .sparse
            .lu
            .as_ref()
            .and_then(|lu| lu.solve(&rhs))
            .ok_or(Error::SingularJacobian {
                block: "sparse system",
                index: 0,
            })?;
        out.y.copy_from_slice(&x[..ky]);
        out.k.copy_from_slice(&x[ky..kq]);
        for (qi, &pc) in self.free.iter().enumerate() {
            out.p[pc] = x[kq + qi];
        }
        Ok(())
    }
}
