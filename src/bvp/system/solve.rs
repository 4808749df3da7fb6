//! A Newton correction with the condensed factorisation: the right-hand
//! side is condensed interval by interval (κ_j, ρ_j), swept forward through
//! the elimination panels, the final system is solved for (Y_0, Y_N, q),
//! and the interior mesh values and stage derivatives follow by back
//! substitution.

use super::condense::{SMALL_BLOCK, for_each_interval, groups, pieces};
use super::stage_split::{self, Split};
use super::{LinearSolver, Residual, State, System};
use crate::bvp::problem::Problem;
use crate::bvp::tableau::Tableau;
use crate::error::{Error, Result};
use crate::linalg::{apply_lower, lu_solve_vec, solve_upper};

/// What every interval reads when the right-hand side is condensed.
struct Stage<'s> {
    t: &'s [f64],
    tab: &'s Tableau,
    wa: &'s [f64],
    wpiv: &'s [usize],
    comps: &'s [usize],
    split: &'s [[usize; 2]],
    fmat: &'s [f64],
    stage: &'s [f64],
    cont: &'s [f64],
    n: usize,
    nd: usize,
    wcols: usize,
}

/// Interval j's κ_j = W_j⁻¹(−r_stage), ρ_j = −r_cont + h_j Σ_k b_k κ_jk and
/// its share F_j κ_j of the dense rows (`tmp`: scratch of length m n).
fn condense_rhs(
    sh: &Stage<'_>,
    j: usize,
    kap: &mut [f64],
    rho: &mut [f64],
    kdense: &mut [f64],
    tmp: &mut [f64],
) {
    let (n, nd, m) = (sh.n, sh.nd, sh.tab.m);
    let mn = m * n;
    let h = sh.t[j + 1] - sh.t[j];
    for (kv, v) in kap.iter_mut().zip(&sh.stage[j * mn..(j + 1) * mn]) {
        *kv = -v;
    }
    let wa = &sh.wa[j * mn * sh.wcols..(j + 1) * mn * sh.wcols];
    let piv = &sh.wpiv[j * mn..(j + 1) * mn];
    let [core, constants] = sh.split[j];
    let split = Split {
        comps: &sh.comps[j * n..(j + 1) * n],
        core,
        constants,
        m,
    };
    if split.is_reduced() {
        stage_split::solve(wa, piv, split, kap, tmp);
    } else if mn <= SMALL_BLOCK {
        apply_lower(wa, mn, mn, piv, kap);
        solve_upper(wa, mn, mn, kap);
    } else {
        lu_solve_vec(wa, mn, piv, kap, tmp);
    }
    for i in 0..n {
        let mut s = -sh.cont[j * n + i];
        for k in 0..m {
            s += h * sh.tab.b[k] * kap[k * n + i];
        }
        rho[i] = s;
    }
    let f = &sh.fmat[j * nd * mn..(j + 1) * nd * mn];
    for (r, d) in kdense.iter_mut().enumerate() {
        let mut acc = 0.0;
        for (fv, kv) in f[r * mn..(r + 1) * mn].iter().zip(kap.iter()) {
            acc += fv * kv;
        }
        *d = acc;
    }
}

impl<P: Problem + ?Sized> System<'_, P> {
    /// Solves J δ = −r with the current factorisation (condensed path) or
    /// the sparse reference.
    pub(crate) fn solve(&mut self, r: &Residual, out: &mut State) -> Result<()> {
        self.solve_unpinned(r, out)?;
        self.project_pinned(out);
        Ok(())
    }

    /// [`solve`](Self::solve) keeping the components along the pinned
    /// modes.
    pub(crate) fn solve_unpinned(&mut self, r: &Residual, out: &mut State) -> Result<()> {
        debug_assert!(self.factored);
        if self.active() == LinearSolver::SparseLu {
            return self.solve_sparse(r, out);
        }
        let (n, m, nq, nn, nbc) = (self.n, self.m, self.nq, self.nn, self.nbc);
        let mn = m * n;
        let nd = self.nd();
        let nz = 2 * n + nq;
        let wcols = mn + n + nq;
        let rows = 2 * n;
        let pcols = 2 * n + nz;
        // 1. κ_j, ρ_j and each interval's share of the dense rhs.
        let groups = groups(nn, 2 * mn * mn);
        self.reserve_work(groups);
        let shared = Stage {
            t: &self.t,
            tab: &self.tab,
            wa: &self.wa,
            wpiv: &self.wpiv,
            comps: &self.comps,
            split: &self.split,
            fmat: &self.fmat,
            stage: &r.stage,
            cont: &r.cont,
            n,
            nd,
            wcols,
        };
        let mut intervals: Vec<_> = pieces(&mut self.kap, mn, nn)
            .zip(pieces(&mut self.rho, n, nn))
            .zip(pieces(&mut self.kdense, nd, nn))
            .enumerate()
            .collect();
        for_each_interval(&mut intervals, &mut self.work, groups, |it, ws| {
            let (j, ((kap, rho), kd)) = it;
            condense_rhs(&shared, *j, kap, rho, kd, &mut ws.tmp);
        });
        for (d, v) in self.drhs.iter_mut().zip(&r.dense) {
            *d = -v;
        }
        for kd in self.kdense.chunks_exact(nd.max(1)) {
            for (d, v) in self.drhs.iter_mut().zip(kd) {
                *d -= v;
            }
        }
        // 2. Forward sweep through the panels.
        let v = &mut self.vbuf;
        v[..n].copy_from_slice(&self.rho[..n]);
        for j in 1..nn {
            v[n..2 * n].copy_from_slice(&self.rho[j * n..(j + 1) * n]);
            let panel = &self.panels[(j - 1) * rows * pcols..j * rows * pcols];
            apply_lower(
                panel,
                rows,
                n,
                &self.ppiv[(j - 1) * n..j * n],
                &mut v[..rows],
            );
            self.rtop[j * n..(j + 1) * n].copy_from_slice(&v[..n]);
            let s = &self.smat[(j - 1) * nd * n..j * nd * n];
            for i in 0..n {
                for (d, sv) in self.drhs.iter_mut().zip(&s[i * nd..(i + 1) * nd]) {
                    *d -= sv * v[i];
                }
            }
            v.copy_within(n..2 * n, 0);
        }
        // 3. Final dense system.
        let z = &mut self.zbuf;
        z[..n].copy_from_slice(&v[..n]);
        for (zv, g) in z[n..n + nbc].iter_mut().zip(&r.bc) {
            *zv = -g;
        }
        z[n + nbc..].copy_from_slice(&self.drhs);
        apply_lower(&self.fin, nz, nz, &self.fpiv, z);
        solve_upper(&self.fin, nz, nz, z);
        // 4. Back substitution for the interior mesh values.
        out.y[..n].copy_from_slice(&z[..n]);
        out.y[nn * n..].copy_from_slice(&z[n..2 * n]);
        for (qi, &pc) in self.free.iter().enumerate() {
            out.p[pc] = z[2 * n + qi];
        }
        for j in (1..nn).rev() {
            let panel = &self.panels[(j - 1) * rows * pcols..j * rows * pcols];
            let w = &mut v[..n];
            w.copy_from_slice(&self.rtop[j * n..(j + 1) * n]);
            for c in 0..n {
                let yv = out.y[(j + 1) * n + c];
                for (wv, x) in w.iter_mut().zip(&panel[(n + c) * rows..(n + c) * rows + n]) {
                    *wv -= x * yv;
                }
            }
            for c in 0..nz {
                let zv = z[c];
                if zv != 0.0 {
                    for (wv, x) in w
                        .iter_mut()
                        .zip(&panel[(2 * n + c) * rows..(2 * n + c) * rows + n])
                    {
                        *wv -= x * zv;
                    }
                }
            }
            solve_upper(panel, rows, n, w);
            out.y[j * n..(j + 1) * n].copy_from_slice(w);
        }
        // 5. Stage derivatives dK_j = κ_j + G_j dY_j + Q_j dq.
        let (wa, kap, y) = (&self.wa, &self.kap, &out.y);
        let (comps, split) = (&self.comps, &self.split);
        let mut intervals: Vec<_> = pieces(&mut out.k, mn, nn).enumerate().collect();
        for_each_interval(&mut intervals, &mut self.work, groups, |it, _| {
            let (j, dk) = it;
            let j = *j;
            let wa = &wa[j * mn * wcols..(j + 1) * mn * wcols];
            dk.copy_from_slice(&kap[j * mn..(j + 1) * mn]);
            // (a quadrature's column of G_j is zero: `stage_split`)
            let [core, constants] = split[j];
            let active = &comps[j * n..j * n + core + constants];
            for &c in active {
                let yv = y[j * n + c];
                for (d, g) in dk.iter_mut().zip(&wa[(mn + c) * mn..(mn + c + 1) * mn]) {
                    *d += g * yv;
                }
            }
            for qi in 0..nq {
                let qv = z[2 * n + qi];
                for (d, g) in dk
                    .iter_mut()
                    .zip(&wa[(mn + n + qi) * mn..(mn + n + qi + 1) * mn])
                {
                    *d += g * qv;
                }
            }
        });
        if out.y.iter().chain(&out.k).any(|v| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: "Jacobian",
                s: f64::NAN,
            });
        }
        Ok(())
    }
}
