//! The Jacobian at a state and the condensation of every interval.
//!
//! For interval j the stage rows are
//!
//! ```text
//!   dK_jk − h_j Σ_l a_kl J_jk dK_jl − J_jk dY_j − J^p_jk dq = −r_jk
//! ```
//!
//! (J_jk = ∂f/∂y at the collocation point z_jk). The mn × mn block
//! W_j = I − h_j (a ⊗ J) is factored and applied to the other columns, so
//! that dK_j = κ_j + G_j dY_j + Q_j dq; the continuity rows then read
//! −Γ_j dY_j + dY_{j+1} − Π_j dq = ρ_j with Γ_j = I + h_j Σ_k b_k G_jk and
//! Π_j = h_j Σ_k b_k Q_jk.
//!
//! Intervals are independent: with the `rayon` feature they are condensed
//! on the threads of the current pool, in contiguous groups with one
//! workspace each. Every interval's numbers are computed by the same code in
//! the same order whatever the grouping, and the sums over intervals
//! (determinant, integral rows) are taken afterwards in interval order, so
//! the result is the same bit for bit on any number of threads.

use super::jacobian::PointDerivatives;
use super::stage_split::{self, Split};
use super::{LinearSolver, State, System, map_breakdown};
use crate::bvp::problem::Problem;
use crate::bvp::tableau::Tableau;
use crate::error::{Error, Result};
use crate::linalg::{Breakdown, DenseWorkspace, Det, lu_panel, lu_solve_block, solve_upper};

/// Interval blocks up to this size (m·n) use the plain LU loops; larger
/// ones faer's SIMD kernels (whose call overhead dominates tiny blocks).
pub(super) const SMALL_BLOCK: usize = 24;

/// Below about this many flops per call the per-interval work stays on one
/// thread: waking the pool (µs to tens of µs) would cost more than it
/// saves.
#[cfg(feature = "rayon")]
const PARALLEL_WORK: usize = 1 << 17;

/// Scratch of one thread of the condensation.
pub(super) struct Workspace {
    deriv: PointDerivatives,
    pinv: Vec<usize>,
    dense: DenseWorkspace,
    /// Length 2 m n, for solves with a block.
    pub(super) tmp: Vec<f64>,
    /// Which rows and columns of the interval's Jacobians have a nonzero.
    row_nz: Vec<bool>,
    col_nz: Vec<bool>,
    /// m n (m n + n + n_q + 1), for packing a split block with its
    /// right-hand sides.
    scratch: Vec<f64>,
}

impl Workspace {
    fn new(n: usize, np: usize, nint: usize, m: usize, nq: usize) -> Self {
        Workspace {
            deriv: PointDerivatives::new(n, np, nint),
            pinv: vec![0; m * n],
            dense: DenseWorkspace::new(m * n, n + nq),
            tmp: vec![0.0; 2 * m * n],
            row_nz: vec![false; n],
            col_nz: vec![false; n],
            scratch: vec![0.0; m * n * (m * n + n + nq + 1)],
        }
    }
}

/// What every interval reads.
struct Shared<'s, P: ?Sized> {
    problem: &'s P,
    t: &'s [f64],
    tab: &'s Tableau,
    free: &'s [usize],
    ycol: &'s [f64],
    y_ref: &'s [f64],
    p: &'s [f64],
    n: usize,
    nint: usize,
    factor: bool,
}

/// What one interval writes.
struct Interval<'s> {
    j: usize,
    wa: &'s mut [f64],
    piv: &'s mut [usize],
    comps: &'s mut [usize],
    split: &'s mut [usize; 2],
    gam: &'s mut [f64],
    pim: &'s mut [f64],
    dint: &'s mut [f64],
    dint_pk: &'s mut [f64],
    det: Result<Det, Breakdown>,
}

/// `v` cut into `count` consecutive pieces of length `len` (which may be 0).
pub(super) fn pieces<T>(v: &mut [T], len: usize, count: usize) -> impl Iterator<Item = &mut [T]> {
    let mut rest = v;
    (0..count).map(move |_| {
        let (head, tail) = std::mem::take(&mut rest).split_at_mut(len);
        rest = tail;
        head
    })
}

/// How many threads share `nn` intervals of about `flops` each: one below
/// [`PARALLEL_WORK`] in all or without the `rayon` feature, else every
/// thread of the current pool.
pub(super) fn groups(nn: usize, flops: usize) -> usize {
    #[cfg(feature = "rayon")]
    {
        if flops.saturating_mul(nn) >= PARALLEL_WORK {
            return rayon::current_num_threads().clamp(1, nn.max(1));
        }
    }
    let _ = (nn, flops);
    1
}

/// Runs `f` on every item (one per interval, in order) with a workspace:
/// in `groups` contiguous groups on rayon's pool, or on this thread. `f`
/// must only write to its item and workspace, so that the result does not
/// depend on the grouping.
pub(super) fn for_each_interval<T: Send>(
    items: &mut [T],
    work: &mut [Workspace],
    groups: usize,
    f: impl Fn(&mut T, &mut Workspace) + Sync,
) {
    #[cfg(feature = "rayon")]
    if groups > 1 {
        use rayon::prelude::*;
        items
            .par_chunks_mut(items.len().div_ceil(groups))
            .zip(work.par_iter_mut())
            .for_each(|(group, ws)| group.iter_mut().for_each(|it| f(it, ws)));
        return;
    }
    let _ = groups;
    let ws = &mut work[0];
    items.iter_mut().for_each(|it| f(it, ws));
}

/// Jacobian blocks of interval `iv` and, with `sh.factor`, their
/// condensation.
fn condense_interval<P: Problem + ?Sized>(
    sh: &Shared<'_, P>,
    iv: &mut Interval<'_>,
    ws: &mut Workspace,
) {
    let (n, nint, tab) = (sh.n, sh.nint, sh.tab);
    let m = tab.m;
    let nq = sh.free.len();
    let mn = m * n;
    let wcols = mn + n + nq;
    let j = iv.j;
    let h = sh.t[j + 1] - sh.t[j];
    // (every entry of [W_j | J_j | J^p_j] is written below)
    let wa = &mut *iv.wa;
    iv.dint_pk.fill(0.0);
    ws.row_nz.fill(false);
    ws.col_nz.fill(false);
    for k in 0..m {
        let z = sh.t[j] + tab.c[k] * h;
        let idx = (j * m + k) * n;
        let yk = &sh.ycol[idx..idx + n];
        let d = &mut ws.deriv;
        d.rhs(sh.problem, sh.free, z, yk, sh.p);
        for c in 0..n {
            for r in 0..n {
                if d.jac[(r, c)] != 0.0 {
                    ws.row_nz[r] = true;
                    ws.col_nz[c] = true;
                }
            }
        }
        for l in 0..m {
            let a = h * tab.a[k * m + l];
            for c in 0..n {
                let col = &mut wa[(l * n + c) * mn + k * n..(l * n + c) * mn + k * n + n];
                for r in 0..n {
                    col[r] = -a * d.jac[(r, c)];
                }
                if l == k {
                    col[c] += 1.0;
                }
            }
        }
        for c in 0..n {
            for r in 0..n {
                wa[(mn + c) * mn + k * n + r] = d.jac[(r, c)];
            }
        }
        for (qi, &pc) in sh.free.iter().enumerate() {
            for r in 0..n {
                wa[(mn + n + qi) * mn + k * n + r] = d.jacp[(r, pc)];
            }
        }
        if nint > 0 {
            let yr = &sh.y_ref[idx..idx + n];
            d.integrand(sh.problem, sh.free, nint, z, yk, yr, sh.p);
            let w = h * tab.b[k];
            let dk = &mut iv.dint[k * nint * n..(k + 1) * nint * n];
            for c in 0..n {
                for r in 0..nint {
                    dk[c * nint + r] = w * d.hy[(r, c)];
                }
            }
            let dp = &mut iv.dint_pk[k * nq * nint..(k + 1) * nq * nint];
            for (qi, &pc) in sh.free.iter().enumerate() {
                for r in 0..nint {
                    dp[qi * nint + r] = w * d.hp[(r, pc)];
                }
            }
        }
    }
    if !sh.factor {
        iv.det = Ok(Det::ONE);
        return;
    }
    let (core, constants) = stage_split::classify(&ws.row_nz, &ws.col_nz, iv.comps);
    *iv.split = [core, constants];
    let split = Split {
        comps: iv.comps,
        core,
        constants,
        m,
    };
    let res = if split.is_reduced() {
        stage_split::pack_and_solve(
            wa,
            split,
            iv.piv,
            &mut ws.pinv,
            &mut ws.dense,
            &mut ws.scratch,
        )
    } else if mn <= SMALL_BLOCK {
        lu_panel(wa, mn, wcols, mn, iv.piv).inspect(|_| {
            let (lu, extra) = wa.split_at_mut(mn * mn);
            for col in extra.chunks_exact_mut(mn) {
                solve_upper(lu, mn, mn, col);
            }
        })
    } else {
        lu_solve_block(wa, mn, wcols, iv.piv, &mut ws.pinv, &mut ws.dense)
    };
    iv.det = res;
    if iv.det.is_err() {
        return;
    }
    // Γ_j = I + h Σ_k b_k G_k,  Π_j = h Σ_k b_k Q_k.
    let gam = &mut *iv.gam;
    gam.fill(0.0);
    for c in 0..n {
        gam[c * n + c] = 1.0;
        let g = &wa[(mn + c) * mn..(mn + c + 1) * mn];
        for k in 0..m {
            let w = h * tab.b[k];
            for r in 0..n {
                gam[c * n + r] += w * g[k * n + r];
            }
        }
    }
    let pim = &mut *iv.pim;
    pim.fill(0.0);
    for qi in 0..nq {
        let g = &wa[(mn + n + qi) * mn..(mn + n + qi + 1) * mn];
        for k in 0..m {
            let w = h * tab.b[k];
            for r in 0..n {
                pim[qi * n + r] += w * g[k * n + r];
            }
        }
    }
}

impl<P: Problem + ?Sized> System<'_, P> {
    /// Jacobian at `x` and its factorisation (condensation, elimination,
    /// final system). Returns the determinant of the full system (fixed
    /// row/column order), up to a constant sign that depends only on the
    /// sizes.
    ///
    /// A singular interval block or elimination panel does not make the
    /// whole system singular: the Jacobian is then factored by the sparse
    /// LU on the full system (the determinant is then unknown: NaN).
    pub(crate) fn factor(&mut self, x: &State) -> Result<Det> {
        let det = self.factor_unpinned(x)?;
        if self.pinning {
            self.find_pinned_modes();
        }
        Ok(det)
    }

    fn factor_unpinned(&mut self, x: &State) -> Result<Det> {
        self.fallback = false;
        match self.factor_with(x, self.linear) {
            Err(Error::SingularJacobian {
                block: "interval block" | "mesh elimination",
                ..
            }) if self.linear == LinearSolver::Condensed => {
                self.fallback = true;
                self.factor_with(x, LinearSolver::SparseLu)?;
                Ok(Det {
                    sign: f64::NAN,
                    log_abs: f64::NAN,
                })
            }
            r => r,
        }
    }

    fn factor_with(&mut self, x: &State, linear: LinearSolver) -> Result<Det> {
        self.factored = false;
        let mut ycol = std::mem::take(&mut self.ycol);
        self.collocation_values(x, &mut ycol);
        let sparse = linear == LinearSolver::SparseLu;
        let cond = self.condense_intervals(&ycol, &x.p, !sparse);
        self.ycol = ycol;
        let wdet = cond?;
        let (n, nn, nbc) = (self.n, self.nn, self.nbc);
        let bd = &mut self.bderiv;
        bd.eval(self.problem, &self.free, &x.y[..n], &x.y[nn * n..], &x.p);
        for c in 0..n {
            for r in 0..nbc {
                self.bc0[c * nbc + r] = bd.g0[(r, c)];
                self.bc1[c * nbc + r] = bd.g1[(r, c)];
            }
        }
        for (qi, &pc) in self.free.iter().enumerate() {
            for r in 0..nbc {
                self.bcp[qi * nbc + r] = bd.gp[(r, pc)];
            }
        }
        if self
            .bc0
            .iter()
            .chain(&self.bc1)
            .chain(&self.bcp)
            .chain(&self.dint_p)
            .any(|v| !v.is_finite())
        {
            return Err(Error::NonFinite {
                what: "Jacobian",
                s: f64::NAN,
            });
        }
        if sparse {
            return self.factor_sparse();
        }
        self.wdet = wdet;
        self.eliminate_mesh()?;
        self.factor_final()
    }

    /// At least `groups` workspaces.
    pub(super) fn reserve_work(&mut self, groups: usize) {
        let (n, m, nq, nint, np) = (self.n, self.m, self.nq, self.nint, self.np);
        while self.work.len() < groups.max(1) {
            self.work.push(Workspace::new(n, np, nint, m, nq));
        }
    }

    /// Every interval's Jacobian blocks (and with `factor` their
    /// condensation); the integral rows' parameter columns summed in
    /// interval order. Returns the product of the block determinants.
    fn condense_intervals(&mut self, ycol: &[f64], p: &[f64], factor: bool) -> Result<Det> {
        let (n, m, nq, nn, nint) = (self.n, self.m, self.nq, self.nn, self.nint);
        let mn = m * n;
        let wcols = mn + n + nq;
        let groups = groups(nn, mn * mn * mn);
        self.reserve_work(groups);
        let shared = Shared {
            problem: self.problem,
            t: &self.t,
            tab: &self.tab,
            free: &self.free,
            ycol,
            y_ref: &self.y_ref,
            p,
            n,
            nint,
            factor,
        };
        let mut intervals: Vec<Interval<'_>> = pieces(&mut self.wa, mn * wcols, nn)
            .zip(pieces(&mut self.wpiv, mn, nn))
            .zip(pieces(&mut self.comps, n, nn))
            .zip(self.split.iter_mut())
            .zip(pieces(&mut self.gam, n * n, nn))
            .zip(pieces(&mut self.pim, n * nq, nn))
            .zip(pieces(&mut self.dint, m * nint * n, nn))
            .zip(pieces(&mut self.dint_pk, m * nint * nq, nn))
            .enumerate()
            .map(
                |(j, (((((((wa, piv), comps), split), gam), pim), dint), dint_pk))| Interval {
                    j,
                    wa,
                    piv,
                    comps,
                    split,
                    gam,
                    pim,
                    dint,
                    dint_pk,
                    det: Ok(Det::ONE),
                },
            )
            .collect();
        for_each_interval(&mut intervals, &mut self.work, groups, |iv, ws| {
            condense_interval(&shared, iv, ws);
        });
        let mut det = Det::ONE;
        for iv in &intervals {
            match iv.det {
                Ok(d) => det = det.mul(d),
                Err(b) => return Err(map_breakdown(b, "interval block", iv.j)),
            }
        }
        self.dint_p.fill(0.0);
        for c in self.dint_pk.chunks_exact((nq * nint).max(1)) {
            for (s, v) in self.dint_p.iter_mut().zip(c) {
                *s += v;
            }
        }
        Ok(det)
    }
}
