//! The discretised collocation system (crate-private; used by the solver and
//! by continuation): its unknowns and equations here, and one file for each
//! thing computed with them.
//!
//! Unknowns: mesh values Y_j (j = 0..N), stage derivatives K_jk (the
//! derivative of the collocation polynomial at the Gauss points), and the
//! free parameters q. Collocation values Y_jk = Y_j + h_j Σ_l a_kl K_jl.
//!
//! ```text
//!   stage        K_jk − f(z_jk, Y_jk, p) = 0                  (N m n)
//!   continuity   Y_{j+1} − Y_j − h_j Σ_k b_k K_jk = 0         (N n)
//!   boundary     g(Y_0, Y_N, p) = 0                           (n_bc)
//!   dense rows   Σ_j h_j Σ_k b_k h(z_jk, Y_jk, y_ref, p) = 0  (n_int)
//!                Σ_jk c_jk·Y_jk + c_q·q − target = 0          (border rows)
//! ```
//!
//! | file | computes |
//! |---|---|
//! | `residual` | the residual of every equation |
//! | `jacobian` | derivatives of f, g, h at one point (the problem's or central differences) |
//! | `condense` | the Jacobian and, per interval, dK_j = κ_j + G_j dY_j + Q_j dq and Γ_j, Π_j (in parallel with `rayon`) |
//! | `stage_split` | the interval block's constants and quadratures, and the solve that factors only its core |
//! | `eliminate` | the elimination of the interior mesh values Y_1..Y_{N−1} |
//! | `border` | the dense (integral and border) rows and the final (2n + n_q) system in (Y_0, Y_N, q) |
//! | `solve` | a Newton correction with the condensed factorisation |
//! | `sparse` | the full uncondensed system through faer's sparse LU (reference and fallback) |
//!
//! Condensation: each interval's stage equations are solved for
//! dK_j = κ_j + G_j dY_j + Q_j dq with a dense LU of the mn × mn block
//! (of its core only, where components are constant or quadratures),
//! leaving −Γ_j dY_j + dY_{j+1} − Π_j dq = ρ_j. The interior mesh unknowns are
//! then eliminated one by one with partial pivoting over the 2n rows that
//! hold them (AUTO's structure), leaving a dense (2n + n_q) system in
//! (Y_0, Y_N, q) with the boundary and dense rows.

mod border;
mod condense;
mod eliminate;
mod jacobian;
mod pin;
mod residual;
mod solve;
mod sparse;
mod stage_split;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod timing;

pub(crate) use border::Border;

use super::problem::Problem;
use super::tableau::Tableau;
use crate::error::{Error, Result};
use crate::linalg::{Breakdown, Det};
use condense::Workspace;
use jacobian::BoundaryDerivatives;
use sparse::SparseSystem;

/// The most memory one system may ask for: 2³¹ bytes (2 GiB) of f64
/// workspace. Larger meshes or problems are refused with
/// [`Error::SystemTooLarge`] before anything is allocated.
pub(crate) const MAX_WORKSPACE_BYTES: u64 = 1 << 31;

/// Unknowns (or a direction in their space). `p` always has the problem's
/// full parameter length; only the free entries are unknowns.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct State {
    pub y: Vec<f64>,
    pub k: Vec<f64>,
    pub p: Vec<f64>,
}

impl State {
    pub(crate) fn axpy(&mut self, a: f64, d: &State, free: &[usize]) {
        for (x, v) in self.y.iter_mut().zip(&d.y) {
            *x += a * v;
        }
        for (x, v) in self.k.iter_mut().zip(&d.k) {
            *x += a * v;
        }
        for &i in free {
            self.p[i] += a * d.p[i];
        }
    }

    pub(crate) fn scale(&mut self, a: f64) {
        self.y.iter_mut().for_each(|v| *v *= a);
        self.k.iter_mut().for_each(|v| *v *= a);
        self.p.iter_mut().for_each(|v| *v *= a);
    }
}

/// Residual blocks, in equation order.
#[derive(Debug, Clone)]
pub(crate) struct Residual {
    pub stage: Vec<f64>,
    pub cont: Vec<f64>,
    pub bc: Vec<f64>,
    pub dense: Vec<f64>,
}

impl Residual {
    pub(crate) fn max_norm(&self) -> f64 {
        self.rows().fold(0.0_f64, |m, v| m.max(v.abs()))
    }

    /// Every row: stage, continuity, boundary, dense.
    pub(crate) fn rows(&self) -> impl Iterator<Item = &f64> {
        self.stage
            .iter()
            .chain(&self.cont)
            .chain(&self.bc)
            .chain(&self.dense)
    }

    /// Every row, mutable, in the order of [`rows`](Self::rows).
    pub(crate) fn rows_mut(&mut self) -> impl Iterator<Item = &mut f64> {
        self.stage
            .iter_mut()
            .chain(self.cont.iter_mut())
            .chain(self.bc.iter_mut())
            .chain(self.dense.iter_mut())
    }
}

/// Which linear solver the Newton iteration uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LinearSolver {
    /// Condensation plus structured elimination, O(N) (default).
    #[default]
    Condensed,
    /// faer's sparse LU on the full uncondensed system (the reference). Its
    /// symbolic analysis is done once per system; each Jacobian costs one
    /// numeric factorisation.
    SparseLu,
}

pub(crate) struct System<'a, P: Problem + ?Sized> {
    problem: &'a P,
    pub t: Vec<f64>,
    pub tab: Tableau,
    pub free: Vec<usize>,
    pub n: usize,
    pub m: usize,
    pub nn: usize,
    pub nq: usize,
    pub nbc: usize,
    pub nint: usize,
    pub np: usize,
    pub y_ref: Vec<f64>,
    pub border: Border,
    pub linear: LinearSolver,
    // Collocation values of the state last passed to `residual`/`factor`.
    ycol: Vec<f64>,
    // residual: values of f or g, and of h, at one point.
    fbuf: Vec<f64>,
    hbuf: Vec<f64>,
    // condense: per interval the factored stage block with G_j, Q_j beside
    // it, its pivots, Γ_j, Π_j, the integral rows' D_jk and the (j, k)
    // contributions to the integral rows' parameter columns.
    wa: Vec<f64>,
    wpiv: Vec<usize>,
    // per interval its components ordered core, constants, quadratures and
    // the first two counts (`stage_split`; the block in `wa` is packed
    // when the core is not every component)
    comps: Vec<usize>,
    split: Vec<[usize; 2]>,
    gam: Vec<f64>,
    pim: Vec<f64>,
    dint: Vec<f64>,
    dint_pk: Vec<f64>,
    dint_p: Vec<f64>,
    wdet: Det,
    work: Vec<Workspace>,
    // Boundary-condition derivatives ∂g/∂Y_0, ∂g/∂Y_N, ∂g/∂q (nbc rows).
    bc0: Vec<f64>,
    bc1: Vec<f64>,
    bcp: Vec<f64>,
    bderiv: BoundaryDerivatives,
    // eliminate: one 2n-row panel per interior mesh point.
    panels: Vec<f64>,
    ppiv: Vec<usize>,
    carry: Vec<f64>,
    pdet: Det,
    // border: the dense rows through the elimination and the final system
    // (F_j row-major, nd × mn per interval; S_j column-major, nd × n).
    fmat: Vec<f64>,
    smat: Vec<f64>,
    fin: Vec<f64>,
    fpiv: Vec<usize>,
    dz: Vec<f64>,
    dcur: Vec<f64>,
    cbuf: Vec<f64>,
    // solve: right-hand sides through the condensation.
    kdense: Vec<f64>,
    kap: Vec<f64>,
    rho: Vec<f64>,
    rtop: Vec<f64>,
    drhs: Vec<f64>,
    vbuf: Vec<f64>,
    zbuf: Vec<f64>,
    sparse: SparseSystem,
    factored: bool,
    fallback: bool,
    /// Whether each factorisation searches for near-null modes to pin
    /// ([`pin`]).
    pinning: bool,
    /// The near-null modes found at the last factorisation, orthonormal;
    /// solves remove their components.
    pinned: Vec<State>,
}

pub(super) fn map_breakdown(b: Breakdown, block: &'static str, index: usize) -> Error {
    match b {
        Breakdown::Singular(_) => Error::SingularJacobian {
            block,
            index: index as u64,
        },
        Breakdown::NonFinite(_) => Error::NonFinite {
            what: "Jacobian",
            s: f64::NAN,
        },
    }
}

/// Checks that n_bc + n_int + extra = n + n_q without overflow.
fn check_posed(n: usize, nq: usize, nbc: usize, nint: usize, extra: usize) -> Result<()> {
    let conditions = nbc.checked_add(nint);
    let rows = conditions.and_then(|c| c.checked_add(extra));
    let unknowns = n.checked_add(nq);
    if rows.is_none() || rows != unknowns {
        return Err(Error::IllPosed {
            conditions: (nbc as u64).saturating_add(nint as u64),
            extra: extra as u64,
            unknowns: (n as u64).saturating_add(nq as u64),
        });
    }
    Ok(())
}

/// An estimate of the f64 workspace of a system, in bytes (in floating
/// point, so that no count can overflow it).
fn workspace_bytes(nn: usize, n: usize, m: usize, nq: usize, np: usize, nd: usize) -> f64 {
    let [nn, n, m, nq, np, nd] = [nn, n, m, nq, np, nd].map(|v| v as f64);
    let mn = m * n;
    let wcols = mn + n + nq;
    let nz = 2.0 * n + nq;
    let floats = nn * mn * wcols // stage blocks
        + nn * (n * n + n * nq) // Γ, Π
        + nn * mn * (nd + nq + 6.0) // collocation values, states, residual, D_jk
        + nn * 2.0 * n * (2.0 * n + nz) // elimination panels
        + nn * nd * (mn + n) // dense rows through the elimination
        + nz * nz
        + np * (n + 2.0);
    floats * 8.0
}

impl<'a, P: Problem + ?Sized> System<'a, P> {
    /// Sets up the system. `extra` is the number of border rows to come.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for a free parameter index out of range or
    /// n = 0, [`Error::IllPosed`] unless n_bc + n_int + extra = n + n_q,
    /// [`Error::SystemTooLarge`] past [`MAX_WORKSPACE_BYTES`].
    pub(crate) fn new(
        problem: &'a P,
        t: Vec<f64>,
        tab: Tableau,
        free: Vec<usize>,
        extra: usize,
    ) -> Result<Self> {
        let n = problem.dim();
        let np = problem.parameter_count();
        let nbc = problem.boundary_count();
        let nint = problem.integral_count();
        let nq = free.len();
        for &i in &free {
            if i >= np {
                return Err(Error::InvalidCount {
                    name: "free parameter index",
                    value: i as u64,
                    allowed: "an index below the problem's parameter_count()",
                });
            }
        }
        if n == 0 {
            return Err(Error::InvalidCount {
                name: "dim",
                value: 0,
                allowed: "at least 1",
            });
        }
        check_posed(n, nq, nbc, nint, extra)?;
        let m = tab.m;
        let nn = t.len() - 1;
        let nd = nint + extra;
        let bytes = workspace_bytes(nn, n, m, nq, np, nd);
        if bytes > MAX_WORKSPACE_BYTES as f64 {
            return Err(Error::SystemTooLarge {
                intervals: nn as u64,
                dim: n as u64,
                // Saturating conversion.
                bytes: bytes as u64,
                limit: MAX_WORKSPACE_BYTES,
            });
        }
        let mn = m * n;
        let nz = 2 * n + nq;
        let wcols = mn + n + nq;
        let pcols = 2 * n + nz;
        Ok(System {
            problem,
            t,
            tab,
            free,
            n,
            m,
            nn,
            nq,
            nbc,
            nint,
            np,
            y_ref: vec![0.0; nn * mn],
            border: Border {
                rows: extra,
                coef_y: vec![0.0; extra * nn * mn],
                coef_q: vec![0.0; extra * nq],
                target: vec![0.0; extra],
            },
            linear: LinearSolver::Condensed,
            ycol: vec![0.0; nn * mn],
            fbuf: vec![0.0; n.max(nbc)],
            hbuf: vec![0.0; nint],
            wa: vec![0.0; nn * mn * wcols],
            wpiv: vec![0; nn * mn],
            comps: (0..nn).flat_map(|_| 0..n).collect(),
            split: vec![[n, 0]; nn],
            gam: vec![0.0; nn * n * n],
            pim: vec![0.0; nn * n * nq],
            dint: vec![0.0; nn * m * nint * n],
            dint_pk: vec![0.0; nn * m * nint * nq],
            dint_p: vec![0.0; nint * nq],
            wdet: Det::ONE,
            work: Vec::new(),
            bc0: vec![0.0; nbc * n],
            bc1: vec![0.0; nbc * n],
            bcp: vec![0.0; nbc * nq],
            bderiv: BoundaryDerivatives::new(n, np, nbc),
            panels: vec![0.0; nn.saturating_sub(1) * 2 * n * pcols],
            ppiv: vec![0; nn.saturating_sub(1) * n],
            carry: vec![0.0; n * (n + nz)],
            pdet: Det::ONE,
            fmat: vec![0.0; nn * nd * mn],
            smat: vec![0.0; nn.saturating_sub(1) * nd * n],
            fin: vec![0.0; nz * nz],
            fpiv: vec![0; nz],
            dz: vec![0.0; nd * nz],
            dcur: vec![0.0; nd * n],
            cbuf: vec![0.0; nd * (n + nq)],
            kdense: vec![0.0; nn * nd],
            kap: vec![0.0; nn * mn],
            rho: vec![0.0; nn * n],
            rtop: vec![0.0; nn * n],
            drhs: vec![0.0; nd],
            vbuf: vec![0.0; 2 * n + nz],
            zbuf: vec![0.0; nz],
            sparse: SparseSystem::default(),
            factored: false,
            fallback: false,
            pinning: false,
            pinned: Vec::new(),
        })
    }

    /// The problem the system discretises.
    pub(crate) fn problem(&self) -> &'a P {
        self.problem
    }

    pub(crate) fn nd(&self) -> usize {
        self.nint + self.border.rows
    }

    pub(crate) fn h(&self, j: usize) -> f64 {
        self.t[j + 1] - self.t[j]
    }

    fn z(&self, j: usize, k: usize) -> f64 {
        self.t[j] + self.tab.c[k] * self.h(j)
    }

    /// Whether a factorisation is current (a chord corrector can start
    /// from it after [`factor_border`](Self::factor_border)).
    pub(crate) fn is_factored(&self) -> bool {
        self.factored
    }

    pub(crate) fn zero_state(&self) -> State {
        State {
            y: vec![0.0; (self.nn + 1) * self.n],
            k: vec![0.0; self.nn * self.m * self.n],
            p: vec![0.0; self.np],
        }
    }

    pub(crate) fn zero_residual(&self) -> Residual {
        Residual {
            stage: vec![0.0; self.nn * self.m * self.n],
            cont: vec![0.0; self.nn * self.n],
            bc: vec![0.0; self.nbc],
            dense: vec![0.0; self.nd()],
        }
    }

    /// Collocation values Y_jk of a state (or direction) into `out`.
    pub(crate) fn collocation_values(&self, x: &State, out: &mut [f64]) {
        let (n, m) = (self.n, self.m);
        for j in 0..self.nn {
            let h = self.h(j);
            let yj = &x.y[j * n..(j + 1) * n];
            let kj = &x.k[j * m * n..(j + 1) * m * n];
            for k in 0..m {
                let o = &mut out[(j * m + k) * n..(j * m + k + 1) * n];
                o.copy_from_slice(yj);
                for l in 0..m {
                    let a = h * self.tab.a[k * m + l];
                    for (v, kk) in o.iter_mut().zip(&kj[l * n..(l + 1) * n]) {
                        *v += a * kk;
                    }
                }
            }
        }
    }

    /// The solver in use for the current factorisation (the sparse LU after
    /// a fallback).
    fn active(&self) -> LinearSolver {
        if self.fallback {
            LinearSolver::SparseLu
        } else {
            self.linear
        }
    }
}
