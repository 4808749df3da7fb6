//! The discretised collocation system: residual, Jacobian, the condensed
//! O(N) factorisation and its solves (crate-private; used by the solver and
//! by continuation).
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
//! Condensation: each interval's stage equations are solved for
//! dK_j = κ_j + G_j dY_j + Q_j dq with a dense LU of the mn × mn block,
//! leaving −Γ_j dY_j + dY_{j+1} − Π_j dq = ρ_j. The interior mesh unknowns are
//! then eliminated one by one with partial pivoting over the 2n rows that
//! hold them (AUTO's structure), leaving a dense (2n + n_q) system in
//! (Y_0, Y_N, q) with the boundary and dense rows.

use nalgebra::DMatrix;

use super::problem::Problem;
use super::tableau::Tableau;
use crate::error::{Error, Result};
use crate::linalg::{
    Breakdown, DenseWorkspace, Det, apply_lower, lu_panel, lu_solve_block, lu_solve_vec,
    solve_upper, solve_upper_left,
};

/// Interval blocks up to this size (m·n) use the plain LU loops; larger
/// ones faer's SIMD kernels (whose call overhead dominates tiny blocks).
const SMALL_BLOCK: usize = 24;

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
        self.stage
            .iter()
            .chain(&self.cont)
            .chain(&self.bc)
            .chain(&self.dense)
            .fold(0.0_f64, |m, v| m.max(v.abs()))
    }
}

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

/// Which linear solver the Newton iteration uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LinearSolver {
    /// Condensation plus structured elimination, O(N) (default).
    #[default]
    Condensed,
    /// faer's sparse LU on the full uncondensed system (the reference).
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
    // Phase A.
    wa: Vec<f64>,
    wpiv: Vec<usize>,
    wpinv: Vec<usize>,
    ws: DenseWorkspace,
    tmp: Vec<f64>,
    gam: Vec<f64>,
    pim: Vec<f64>,
    dint: Vec<f64>,
    dint_p: Vec<f64>,
    bc0: Vec<f64>,
    bc1: Vec<f64>,
    bcp: Vec<f64>,
    wdet: Det,
    // Phase B.
    panels: Vec<f64>,
    ppiv: Vec<usize>,
    carry: Vec<f64>,
    pdet: Det,
    // Phase C.
    fmat: Vec<f64>,
    smat: Vec<f64>,
    fin: Vec<f64>,
    fpiv: Vec<usize>,
    fdet: Det,
    // Sparse reference path: the full Jacobian as triplets.
    triplets: Vec<(usize, usize, f64)>,
    // Scratch.
    jac: DMatrix<f64>,
    jacp: DMatrix<f64>,
    g0: DMatrix<f64>,
    g1: DMatrix<f64>,
    gp: DMatrix<f64>,
    hy: DMatrix<f64>,
    hp: DMatrix<f64>,
    fbuf: Vec<f64>,
    fbuf2: Vec<f64>,
    ybuf: Vec<f64>,
    pbuf: Vec<f64>,
    pbuf_x: Vec<f64>,
    kap: Vec<f64>,
    rho: Vec<f64>,
    rtop: Vec<f64>,
    drhs: Vec<f64>,
    cbuf: Vec<f64>,
    dcur: Vec<f64>,
    dz: Vec<f64>,
    vbuf: Vec<f64>,
    zbuf: Vec<f64>,
    factored: bool,
    fallback: bool,
}

/// Central-difference step for a value of size |x|: ε^(1/3) max(1, |x|),
/// which balances truncation O(δ²) against rounding O(ε/δ): Jacobian entries
/// to about ε^(2/3) ≈ 4e-11 relative.
fn fd_step(x: f64) -> f64 {
    6.055454452393343e-6 * x.abs().max(1.0)
}

fn map_breakdown(b: Breakdown, block: &'static str, index: usize) -> Error {
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

impl<'a, P: Problem + ?Sized> System<'a, P> {
    /// Sets up the system. `extra` is the number of border rows to come.
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
        if nbc + nint + extra != n + nq {
            return Err(Error::IllPosed {
                conditions: (nbc + nint) as u64,
                extra: extra as u64,
                unknowns: (n + nq) as u64,
            });
        }
        let m = tab.m;
        let nn = t.len() - 1;
        let mn = m * n;
        let nz = 2 * n + nq;
        let nd = nint + extra;
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
            wa: vec![0.0; nn * mn * wcols],
            wpiv: vec![0; nn * mn],
            wpinv: vec![0; mn],
            ws: DenseWorkspace::new(mn, n + nq),
            tmp: vec![0.0; mn],
            gam: vec![0.0; nn * n * n],
            pim: vec![0.0; nn * n * nq],
            dint: vec![0.0; nn * m * nint * n],
            dint_p: vec![0.0; nint * nq],
            bc0: vec![0.0; nbc * n],
            bc1: vec![0.0; nbc * n],
            bcp: vec![0.0; nbc * nq],
            wdet: Det::ONE,
            panels: vec![0.0; nn.saturating_sub(1) * 2 * n * pcols],
            ppiv: vec![0; nn.saturating_sub(1) * n],
            carry: vec![0.0; n * (n + nz)],
            pdet: Det::ONE,
            fmat: vec![0.0; nn * nd * mn],
            smat: vec![0.0; nn.saturating_sub(1) * nd * n],
            fin: vec![0.0; nz * nz],
            fpiv: vec![0; nz],
            fdet: Det::ONE,
            triplets: Vec::new(),
            jac: DMatrix::zeros(n, n),
            jacp: DMatrix::zeros(n, np),
            g0: DMatrix::zeros(nbc, n),
            g1: DMatrix::zeros(nbc, n),
            gp: DMatrix::zeros(nbc, np),
            hy: DMatrix::zeros(nint, n),
            hp: DMatrix::zeros(nint, np),
            fbuf: vec![0.0; n.max(nbc).max(nint)],
            fbuf2: vec![0.0; n.max(nbc).max(nint)],
            ybuf: vec![0.0; 2 * n],
            pbuf: vec![0.0; np],
            pbuf_x: vec![0.0; np],
            kap: vec![0.0; nn * mn],
            rho: vec![0.0; nn * n],
            rtop: vec![0.0; nn * n],
            drhs: vec![0.0; nd],
            cbuf: vec![0.0; nd * (n + nq)],
            dcur: vec![0.0; nd * n],
            dz: vec![0.0; nd * nz],
            vbuf: vec![0.0; 2 * n + nz],
            zbuf: vec![0.0; nz],
            factored: false,
            fallback: false,
        })
    }

    pub(crate) fn nd(&self) -> usize {
        self.nint + self.border.rows
    }

    pub(crate) fn h(&self, j: usize) -> f64 {
        self.t[j + 1] - self.t[j]
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

    fn z(&self, j: usize, k: usize) -> f64 {
        self.t[j] + self.tab.c[k] * self.h(j)
    }

    /// Evaluates every residual block at `x`.
    pub(crate) fn residual(&mut self, x: &State, r: &mut Residual) -> Result<()> {
        let (n, m) = (self.n, self.m);
        let mut ycol = std::mem::take(&mut self.ycol);
        self.collocation_values(x, &mut ycol);
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
                    self.ycol = ycol;
                    return Err(Error::NonFinite {
                        what: "right-hand side",
                        s: z,
                    });
                }
                for i in 0..n {
                    r.stage[idx + i] = x.k[idx + i] - f[i];
                }
                if nint > 0 {
                    let hv = &mut self.fbuf2[..nint];
                    hv.fill(0.0);
                    self.problem
                        .integrand(z, yk, &self.y_ref[idx..idx + n], p, hv);
                    if hv.iter().any(|v| !v.is_finite()) {
                        self.ycol = ycol;
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
            self.ycol = ycol;
            return Err(Error::NonFinite {
                what: "boundary conditions",
                s: f64::NAN,
            });
        }
        r.bc.copy_from_slice(g);
        let len = self.nn * m * n;
        for b in 0..self.border.rows {
            let cy = &self.border.coef_y[b * len..(b + 1) * len];
            let mut s: f64 = cy.iter().zip(&ycol).map(|(a, v)| a * v).sum();
            for (qi, &pi) in self.free.iter().enumerate() {
                s += self.border.coef_q[b * self.nq + qi] * p[pi];
            }
            r.dense[nint + b] = s - self.border.target[b];
        }
        self.ycol = ycol;
        Ok(())
    }

    /// ∂f/∂y (n×n, col-major in `self.jac`) and ∂f/∂p (all params) at (z, y).
    fn rhs_jacobian(&mut self, z: f64, y: &[f64], p: &[f64]) {
        self.jac.fill(0.0);
        self.jacp.fill(0.0);
        if self
            .problem
            .rhs_jacobian(z, y, p, self.jac.as_view_mut(), self.jacp.as_view_mut())
        {
            return;
        }
        let n = self.n;
        let (yb, pb) = (&mut self.ybuf, &mut self.pbuf);
        yb[..n].copy_from_slice(y);
        pb.copy_from_slice(p);
        for c in 0..n {
            let d = fd_step(y[c]);
            yb[c] = y[c] + d;
            self.problem.rhs(z, &yb[..n], p, &mut self.fbuf[..n]);
            yb[c] = y[c] - d;
            self.problem.rhs(z, &yb[..n], p, &mut self.fbuf2[..n]);
            yb[c] = y[c];
            for r in 0..n {
                self.jac[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
        for &c in &self.free {
            let d = fd_step(p[c]);
            pb[c] = p[c] + d;
            self.problem.rhs(z, y, pb, &mut self.fbuf[..n]);
            pb[c] = p[c] - d;
            self.problem.rhs(z, y, pb, &mut self.fbuf2[..n]);
            pb[c] = p[c];
            for r in 0..n {
                self.jacp[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
    }

    fn integrand_jacobian(&mut self, z: f64, y: &[f64], yr: &[f64], p: &[f64]) {
        self.hy.fill(0.0);
        self.hp.fill(0.0);
        if self.problem.integrand_jacobian(
            z,
            y,
            yr,
            p,
            self.hy.as_view_mut(),
            self.hp.as_view_mut(),
        ) {
            return;
        }
        let (n, ni) = (self.n, self.nint);
        let (yb, pb) = (&mut self.ybuf, &mut self.pbuf);
        yb[..n].copy_from_slice(y);
        pb.copy_from_slice(p);
        for c in 0..n {
            let d = fd_step(y[c]);
            yb[c] = y[c] + d;
            self.fbuf[..ni].fill(0.0);
            self.problem
                .integrand(z, &yb[..n], yr, p, &mut self.fbuf[..ni]);
            yb[c] = y[c] - d;
            self.fbuf2[..ni].fill(0.0);
            self.problem
                .integrand(z, &yb[..n], yr, p, &mut self.fbuf2[..ni]);
            yb[c] = y[c];
            for r in 0..ni {
                self.hy[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
        for &c in &self.free {
            let d = fd_step(p[c]);
            pb[c] = p[c] + d;
            self.fbuf[..ni].fill(0.0);
            self.problem.integrand(z, y, yr, pb, &mut self.fbuf[..ni]);
            pb[c] = p[c] - d;
            self.fbuf2[..ni].fill(0.0);
            self.problem.integrand(z, y, yr, pb, &mut self.fbuf2[..ni]);
            pb[c] = p[c];
            for r in 0..ni {
                self.hp[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
    }

    fn boundary_jacobian(&mut self, y0: &[f64], y1: &[f64], p: &[f64]) {
        self.g0.fill(0.0);
        self.g1.fill(0.0);
        self.gp.fill(0.0);
        if self.problem.boundary_jacobian(
            y0,
            y1,
            p,
            self.g0.as_view_mut(),
            self.g1.as_view_mut(),
            self.gp.as_view_mut(),
        ) {
            return;
        }
        let (n, nb) = (self.n, self.nbc);
        let mut yb = vec![0.0; 2 * n];
        yb[..n].copy_from_slice(y0);
        yb[n..].copy_from_slice(y1);
        let mut pb = p.to_vec();
        let mut gplus = vec![0.0; nb];
        let mut gminus = vec![0.0; nb];
        for c in 0..2 * n {
            let x = yb[c];
            let d = fd_step(x);
            yb[c] = x + d;
            self.problem.boundary(&yb[..n], &yb[n..], p, &mut gplus);
            yb[c] = x - d;
            self.problem.boundary(&yb[..n], &yb[n..], p, &mut gminus);
            yb[c] = x;
            for r in 0..nb {
                let v = (gplus[r] - gminus[r]) / (2.0 * d);
                if c < n {
                    self.g0[(r, c)] = v;
                } else {
                    self.g1[(r, c - n)] = v;
                }
            }
        }
        for &c in &self.free {
            let x = pb[c];
            let d = fd_step(x);
            pb[c] = x + d;
            self.problem.boundary(y0, y1, &pb, &mut gplus);
            pb[c] = x - d;
            self.problem.boundary(y0, y1, &pb, &mut gminus);
            pb[c] = x;
            for r in 0..nb {
                self.gp[(r, c)] = (gplus[r] - gminus[r]) / (2.0 * d);
            }
        }
    }

    /// Jacobian at `x` and its factorisation (all phases). Returns the
    /// determinant of the full system (fixed row/column order), up to a
    /// constant sign that depends only on the sizes.
    pub(crate) fn factor(&mut self, x: &State) -> Result<Det> {
        // A singular interval block or elimination panel does not make the
        // whole system singular: fall back to the sparse LU on the full
        // system for this Jacobian (the determinant is then unknown: NaN).
        self.fallback = false;
        match self.factor_with(x, self.linear) {
            Err(Error::SingularJacobian {
                block: "interval block" | "mesh elimination",
                ..
            }) if self.linear == LinearSolver::Condensed => {
                self.factor_with(x, LinearSolver::SparseLu)?;
                self.fallback = true;
                Ok(Det {
                    sign: f64::NAN,
                    log_abs: f64::NAN,
                })
            }
            r => r,
        }
    }

    fn active(&self) -> LinearSolver {
        if self.fallback {
            LinearSolver::SparseLu
        } else {
            self.linear
        }
    }

    fn factor_with(&mut self, x: &State, linear: LinearSolver) -> Result<Det> {
        self.factored = false;
        let (n, m, nq, nn) = (self.n, self.m, self.nq, self.nn);
        let mn = m * n;
        let wcols = mn + n + nq;
        let mut ycol = std::mem::take(&mut self.ycol);
        self.collocation_values(x, &mut ycol);
        let p = std::mem::take(&mut self.pbuf_x);
        let mut p = p;
        p.clear();
        p.extend_from_slice(&x.p);
        let y_ref = std::mem::take(&mut self.y_ref);
        let nint = self.nint;
        self.dint_p.fill(0.0);
        let sparse = linear == LinearSolver::SparseLu;
        if sparse {
            self.triplets.clear();
        }
        let mut wdet = Det::ONE;
        for j in 0..nn {
            let h = self.h(j);
            let wbase = j * mn * wcols;
            self.wa[wbase..wbase + mn * wcols].fill(0.0);
            for k in 0..m {
                let z = self.z(j, k);
                let idx = (j * m + k) * n;
                self.rhs_jacobian(z, &ycol[idx..idx + n], &p);
                let wa = &mut self.wa[wbase..wbase + mn * wcols];
                for l in 0..m {
                    let a = h * self.tab.a[k * m + l];
                    for c in 0..n {
                        let col = &mut wa[(l * n + c) * mn + k * n..(l * n + c) * mn + k * n + n];
                        for r in 0..n {
                            col[r] = -a * self.jac[(r, c)];
                        }
                        if l == k {
                            col[c] += 1.0;
                        }
                    }
                }
                for c in 0..n {
                    for r in 0..n {
                        wa[(mn + c) * mn + k * n + r] = self.jac[(r, c)];
                    }
                }
                for (qi, &pc) in self.free.iter().enumerate() {
                    for r in 0..n {
                        wa[(mn + n + qi) * mn + k * n + r] = self.jacp[(r, pc)];
                    }
                }
                if sparse {
                    self.push_stage_triplets(j, k, h);
                }
                if nint > 0 {
                    self.integrand_jacobian(z, &ycol[idx..idx + n], &y_ref[idx..idx + n], &p);
                    let w = h * self.tab.b[k];
                    let d = &mut self.dint[(j * m + k) * nint * n..(j * m + k + 1) * nint * n];
                    for c in 0..n {
                        for r in 0..nint {
                            d[c * nint + r] = w * self.hy[(r, c)];
                        }
                    }
                    for (qi, &pc) in self.free.iter().enumerate() {
                        for r in 0..nint {
                            self.dint_p[qi * nint + r] += w * self.hp[(r, pc)];
                        }
                    }
                }
            }
            if sparse {
                continue;
            }
            let wa = &mut self.wa[wbase..wbase + mn * wcols];
            let piv = &mut self.wpiv[j * mn..(j + 1) * mn];
            let pinv = &mut self.wpinv[..];
            let res = if mn <= SMALL_BLOCK {
                lu_panel(wa, mn, wcols, mn, piv).inspect(|_| {
                    let (lu, extra) = wa.split_at_mut(mn * mn);
                    for col in extra.chunks_exact_mut(mn) {
                        solve_upper(lu, mn, mn, col);
                    }
                })
            } else {
                lu_solve_block(wa, mn, wcols, piv, pinv, &mut self.ws)
            };
            let d = match res {
                Ok(d) => d,
                Err(b) => {
                    self.ycol = ycol;
                    self.y_ref = y_ref;
                    self.pbuf_x = p;
                    return Err(map_breakdown(b, "interval block", j));
                }
            };
            wdet = wdet.mul(d);
            // Γ_j = I + h Σ_k b_k G_k,  Π_j = h Σ_k b_k Q_k.
            let gam = &mut self.gam[j * n * n..(j + 1) * n * n];
            gam.fill(0.0);
            for c in 0..n {
                gam[c * n + c] = 1.0;
                let g = &wa[(mn + c) * mn..(mn + c + 1) * mn];
                for k in 0..m {
                    let w = h * self.tab.b[k];
                    for r in 0..n {
                        gam[c * n + r] += w * g[k * n + r];
                    }
                }
            }
            let pim = &mut self.pim[j * n * nq..(j + 1) * n * nq];
            pim.fill(0.0);
            for qi in 0..nq {
                let g = &wa[(mn + n + qi) * mn..(mn + n + qi + 1) * mn];
                for k in 0..m {
                    let w = h * self.tab.b[k];
                    for r in 0..n {
                        pim[qi * n + r] += w * g[k * n + r];
                    }
                }
            }
        }
        self.y_ref = y_ref;
        self.boundary_jacobian(&x.y[..n], &x.y[nn * n..], &p);
        self.pbuf_x = p;
        let nbc = self.nbc;
        for c in 0..n {
            for r in 0..nbc {
                self.bc0[c * nbc + r] = self.g0[(r, c)];
                self.bc1[c * nbc + r] = self.g1[(r, c)];
            }
        }
        for (qi, &pc) in self.free.iter().enumerate() {
            for r in 0..nbc {
                self.bcp[qi * nbc + r] = self.gp[(r, pc)];
            }
        }
        self.ycol = ycol;
        if self.problem_jacobian_nonfinite() {
            return Err(Error::NonFinite {
                what: "Jacobian",
                s: f64::NAN,
            });
        }
        if sparse {
            self.factored = true;
            return Ok(Det {
                sign: f64::NAN,
                log_abs: f64::NAN,
            });
        }
        self.wdet = wdet;
        self.phase_b()?;
        self.phase_c()
    }

    fn problem_jacobian_nonfinite(&self) -> bool {
        self.bc0
            .iter()
            .chain(&self.bc1)
            .chain(&self.bcp)
            .chain(&self.dint_p)
            .any(|v| !v.is_finite())
    }

    fn push_stage_triplets(&mut self, j: usize, k: usize, h: f64) {
        // Full system ordering: unknowns [Y_0..Y_N | K (N m n) | q], equations
        // [stage (N m n) | continuity (N n) | bc | dense].
        let (n, m, nn) = (self.n, self.m, self.nn);
        let ky = (nn + 1) * n;
        let row0 = (j * m + k) * n;
        for r in 0..n {
            self.triplets.push((row0 + r, ky + row0 + r, 1.0));
            for c in 0..n {
                let jv = self.jac[(r, c)];
                if jv != 0.0 {
                    self.triplets.push((row0 + r, j * n + c, -jv));
                    for l in 0..m {
                        let a = h * self.tab.a[k * m + l];
                        self.triplets
                            .push((row0 + r, ky + (j * m + l) * n + c, -a * jv));
                    }
                }
            }
            for (qi, &pc) in self.free.iter().enumerate() {
                let v = self.jacp[(r, pc)];
                if v != 0.0 {
                    self.triplets.push((row0 + r, ky + nn * m * n + qi, -v));
                }
            }
        }
    }

    /// Phase B: eliminates the interior mesh unknowns.
    fn phase_b(&mut self) -> Result<()> {
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

    /// The dense-row coefficient D_jk (nd × n, col-major) of collocation
    /// point (j, k) into `out`.
    fn dense_coef(&self, j: usize, k: usize, out: &mut [f64]) {
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

    /// Phase C: dense rows and the final (2n + n_q) system. Must be re-run
    /// after the border rows change (cheap: no problem evaluations).
    pub(crate) fn phase_c(&mut self) -> Result<Det> {
        if self.active() == LinearSolver::SparseLu {
            // The sparse LU gives no determinant.
            self.factored = true;
            return Ok(Det {
                sign: f64::NAN,
                log_abs: f64::NAN,
            });
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
        let mut srow = vec![0.0; n];
        for j in 0..nn {
            if nd == 0 {
                break;
            }
            let h = self.h(j);
            // E_j = Σ_k D_jk into cbuf[..nd n]; F_j,l = h Σ_k D_jk a_kl.
            let f = &mut fmat[j * nd * mn..(j + 1) * nd * mn];
            f.fill(0.0);
            cbuf.fill(0.0);
            for k in 0..m {
                self.dense_coef(j, k, &mut dk);
                for (e, d) in cbuf[..nd * n].iter_mut().zip(&dk) {
                    *e += d;
                }
                for l in 0..m {
                    let a = h * self.tab.a[k * m + l];
                    for (fv, d) in f[l * n * nd..(l + 1) * n * nd].iter_mut().zip(&dk) {
                        *fv += a * d;
                    }
                }
            }
            // C_j = E_j + F_j G_j, Cp_j = F_j Q_j.
            let wa = &self.wa[j * mn * wcols..(j + 1) * mn * wcols];
            for c in 0..n + nq {
                let g = &wa[(mn + c) * mn..(mn + c + 1) * mn];
                let out = &mut cbuf[c * nd..(c + 1) * nd];
                for (i, gv) in g.iter().enumerate() {
                    if *gv != 0.0 {
                        for (o, fv) in out.iter_mut().zip(&f[i * nd..(i + 1) * nd]) {
                            *o += fv * gv;
                        }
                    }
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
            // Eliminate Y_j: S = Dcur U⁻¹; Dnext = −S X; Dz −= S Z'.
            let panel = &self.panels[(j - 1) * rows * pcols..j * rows * pcols];
            let s = &mut smat[(j - 1) * nd * n..j * nd * n];
            let srow = &mut srow[..];
            for r in 0..nd {
                for c in 0..n {
                    srow[c] = dcur[c * nd + r];
                }
                solve_upper_left(panel, rows, n, srow);
                for c in 0..n {
                    s[c * nd + r] = srow[c];
                }
            }
            dcur.fill(0.0);
            for c in 0..n {
                for i in 0..n {
                    let x = panel[(n + c) * rows + i];
                    if x != 0.0 {
                        for r in 0..nd {
                            dcur[c * nd + r] -= s[i * nd + r] * x;
                        }
                    }
                }
            }
            for c in 0..nz {
                for i in 0..n {
                    let x = panel[(2 * n + c) * rows + i];
                    if x != 0.0 {
                        for r in 0..nd {
                            dz[c * nd + r] -= s[i * nd + r] * x;
                        }
                    }
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
        self.fdet = d;
        self.factored = true;
        Ok(self.wdet.mul(self.pdet).mul(d))
    }

    /// Solves J δ = −r with the current factorisation (condensed path) or
    /// the sparse reference.
    pub(crate) fn solve(&mut self, r: &Residual, out: &mut State) -> Result<()> {
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
        // 1. κ_j, ρ_j and the dense rhs.
        for (d, v) in self.drhs.iter_mut().zip(&r.dense) {
            *d = -v;
        }
        for j in 0..nn {
            let h = self.h(j);
            let kap = &mut self.kap[j * mn..(j + 1) * mn];
            for (kv, v) in kap.iter_mut().zip(&r.stage[j * mn..(j + 1) * mn]) {
                *kv = -v;
            }
            let wa = &self.wa[j * mn * wcols..(j + 1) * mn * wcols];
            let piv = &self.wpiv[j * mn..(j + 1) * mn];
            if mn <= SMALL_BLOCK {
                apply_lower(wa, mn, mn, piv, kap);
                solve_upper(wa, mn, mn, kap);
            } else {
                lu_solve_vec(wa, mn, piv, kap, &mut self.tmp);
            }
            for i in 0..n {
                let mut s = -r.cont[j * n + i];
                for k in 0..m {
                    s += h * self.tab.b[k] * kap[k * n + i];
                }
                self.rho[j * n + i] = s;
            }
            let f = &self.fmat[j * nd * mn..(j + 1) * nd * mn];
            for (i, kv) in kap.iter().enumerate() {
                for (d, fv) in self.drhs.iter_mut().zip(&f[i * nd..(i + 1) * nd]) {
                    *d -= fv * kv;
                }
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
        // 5. Stage derivatives.
        for j in 0..nn {
            let wa = &self.wa[j * mn * wcols..(j + 1) * mn * wcols];
            let dk = &mut out.k[j * mn..(j + 1) * mn];
            dk.copy_from_slice(&self.kap[j * mn..(j + 1) * mn]);
            for c in 0..n {
                let yv = out.y[j * n + c];
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
        }
        if out.y.iter().chain(&out.k).any(|v| !v.is_finite()) {
            return Err(Error::NonFinite {
                what: "Jacobian",
                s: f64::NAN,
            });
        }
        Ok(())
    }

    /// The full uncondensed system through faer's sparse LU.
    fn solve_sparse(&mut self, r: &Residual, out: &mut State) -> Result<()> {
        let (n, m, nq, nn, nbc, nint) = (self.n, self.m, self.nq, self.nn, self.nbc, self.nint);
        let mn = m * n;
        let ky = (nn + 1) * n;
        let kq = ky + nn * mn;
        let size = kq + nq;
        let mut e = self.triplets.clone();
        // Continuity rows.
        let r0 = nn * mn;
        for j in 0..nn {
            let h = self.h(j);
            for i in 0..n {
                e.push((r0 + j * n + i, (j + 1) * n + i, 1.0));
                e.push((r0 + j * n + i, j * n + i, -1.0));
                for k in 0..m {
                    e.push((r0 + j * n + i, ky + (j * m + k) * n + i, -h * self.tab.b[k]));
                }
            }
        }
        // Boundary rows.
        let r1 = r0 + nn * n;
        for rr in 0..nbc {
            for c in 0..n {
                e.push((r1 + rr, c, self.bc0[c * nbc + rr]));
                e.push((r1 + rr, nn * n + c, self.bc1[c * nbc + rr]));
            }
            for qi in 0..nq {
                e.push((r1 + rr, kq + qi, self.bcp[qi * nbc + rr]));
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
                        if d != 0.0 {
                            e.push((r2 + rr, j * n + c, d));
                            for l in 0..m {
                                let a = h * self.tab.a[k * m + l];
                                e.push((r2 + rr, ky + (j * m + l) * n + c, d * a));
                            }
                        }
                    }
                }
            }
        }
        for qi in 0..nq {
            for rr in 0..nint {
                e.push((r2 + rr, kq + qi, self.dint_p[qi * nint + rr]));
            }
            for b in 0..self.border.rows {
                e.push((r2 + nint + b, kq + qi, self.border.coef_q[b * nq + qi]));
            }
        }
        let mut rhs = Vec::with_capacity(size);
        rhs.extend(r.stage.iter().map(|v| -v));
        rhs.extend(r.cont.iter().map(|v| -v));
        rhs.extend(r.bc.iter().map(|v| -v));
        rhs.extend(r.dense.iter().map(|v| -v));
        let x = crate::linalg::sparse_solve(size, &e, &rhs).ok_or(Error::SingularJacobian {
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

#[cfg(test)]
mod tests {
    use super::*;

    struct Bratu(bool);
    impl Problem for Bratu {
        fn dim(&self) -> usize {
            2
        }
        fn parameter_count(&self) -> usize {
            2
        }
        fn boundary_count(&self) -> usize {
            2
        }
        fn integral_count(&self) -> usize {
            usize::from(self.0)
        }
        fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
            f[0] = y[1] + 0.3 * s * y[0];
            f[1] = -p[0] * y[0].exp() + p[1] * s;
        }
        fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
            g[0] = y0[0] + 0.1 * y1[1];
            g[1] = y1[0] - 0.2 * p[0];
        }
        fn integrand(&self, s: f64, y: &[f64], _r: &[f64], p: &[f64], h: &mut [f64]) {
            h[0] = y[0] * y[0] + s * y[1] - p[0];
        }
    }

    /// The condensed solve and faer's sparse LU on the full system give the
    /// same Newton correction at an arbitrary (non-solution) state, with a
    /// free parameter, an integral row and a border row.
    #[test]
    fn condensed_matches_sparse() {
        for (nn, full) in [(1usize, false), (1, true), (2, true), (5, true)] {
            let tab = Tableau::new(3);
            let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
            let prob = Bratu(full);
            let mut sys = System::new(
                &prob,
                t.clone(),
                tab.clone(),
                if full { vec![0, 1] } else { vec![] },
                usize::from(full),
            )
            .unwrap();
            let mut x = sys.zero_state();
            for (i, v) in x.y.iter_mut().enumerate() {
                *v = 0.1 * (i as f64).sin();
            }
            for (i, v) in x.k.iter_mut().enumerate() {
                *v = 0.2 * (i as f64 * 0.7).cos();
            }
            x.p[0] = 1.3;
            x.p[1] = -0.4;
            for (i, v) in sys.border.coef_y.iter_mut().enumerate() {
                *v = 0.01 * (i as f64 + 1.0);
            }
            if full {
                sys.border.coef_q[0] = 0.5;
                sys.border.coef_q[1] = -0.25;
                sys.border.target[0] = 0.3;
            }
            let mut r = sys.zero_residual();
            sys.residual(&x, &mut r).unwrap();
            sys.factor(&x).unwrap();
            let mut a = sys.zero_state();
            sys.solve(&r, &mut a).unwrap();
            sys.linear = LinearSolver::SparseLu;
            sys.factor(&x).unwrap();
            let mut b = sys.zero_state();
            sys.solve(&r, &mut b).unwrap();
            // Third reference: dense FD Jacobian of the residual.
            let flat = |r: &Residual| -> Vec<f64> {
                r.stage
                    .iter()
                    .chain(&r.cont)
                    .chain(&r.bc)
                    .chain(&r.dense)
                    .copied()
                    .collect()
            };
            let ny = x.y.len();
            let nk = x.k.len();
            let size = ny + nk + if full { 2 } else { 0 };
            let mut jm = vec![0.0; size * size];
            for c in 0..size {
                let mut xp = x.clone();
                let mut xm = x.clone();
                let d = 1e-6;
                if c < ny {
                    xp.y[c] += d;
                    xm.y[c] -= d;
                } else if c < ny + nk {
                    xp.k[c - ny] += d;
                    xm.k[c - ny] -= d;
                } else {
                    xp.p[c - ny - nk] += d;
                    xm.p[c - ny - nk] -= d;
                }
                let mut rp = sys.zero_residual();
                let mut rm = sys.zero_residual();
                sys.residual(&xp, &mut rp).unwrap();
                sys.residual(&xm, &mut rm).unwrap();
                let (fp, fm) = (flat(&rp), flat(&rm));
                for i in 0..size {
                    jm[c * size + i] = (fp[i] - fm[i]) / (2.0 * d);
                }
            }
            let mut rhs: Vec<f64> = flat(&r).iter().map(|v| -v).collect();
            let mut piv = vec![0; size];
            crate::linalg::lu_panel(&mut jm, size, size, size, &mut piv).unwrap();
            crate::linalg::apply_lower(&jm, size, size, &piv, &mut rhs);
            crate::linalg::solve_upper(&jm, size, size, &mut rhs);
            let c: Vec<f64> = rhs;
            let av: Vec<f64> = a.y.iter().chain(&a.k).chain(&a.p).copied().collect();
            let bv: Vec<f64> = b.y.iter().chain(&b.k).chain(&b.p).copied().collect();
            for i in 0..size {
                assert!(
                    (c[i] - av[i]).abs() < 1e-6 * (1.0 + c[i].abs()),
                    "condensed N={nn} i={i}: {} vs {}",
                    av[i],
                    c[i]
                );
                assert!(
                    (c[i] - bv[i]).abs() < 1e-6 * (1.0 + c[i].abs()),
                    "sparse N={nn} i={i}: {} vs {}",
                    bv[i],
                    c[i]
                );
            }
            for (u, v) in
                a.y.iter()
                    .chain(&a.k)
                    .chain(&a.p)
                    .zip(b.y.iter().chain(&b.k).chain(&b.p))
            {
                assert!((u - v).abs() < 1e-9 * (1.0 + v.abs()), "N={nn}: {u} vs {v}");
            }
        }
    }
}

#[cfg(test)]
mod timing {
    use super::*;
    use crate::bvp::classic::{Coupled13, Troesch};

    /// Mean wall time of `f` over `reps` calls, in seconds.
    fn mean_seconds(reps: u32, mut f: impl FnMut()) -> f64 {
        let t0 = std::time::Instant::now();
        for _ in 0..reps {
            f();
        }
        t0.elapsed().as_secs_f64() / f64::from(reps)
    }

    #[test]
    #[ignore = "timing probe: cargo test --release --lib system::timing -- --ignored --nocapture"]
    fn big_parts() {
        let nn = 50;
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let big = Coupled13::new();
        let mut sys = System::new(&big, t, Tableau::new(4), vec![0], 1).unwrap();
        let mut x = sys.zero_state();
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.01 * i as f64;
        }
        sys.border.coef_q[0] = 1.0;
        let mut r = sys.zero_residual();
        let mut d = sys.zero_state();
        let reps = 200;
        let tr = mean_seconds(reps, || {
            sys.residual(&x, &mut r).unwrap();
        });
        let tf = mean_seconds(reps, || {
            sys.factor(&x).unwrap();
        });
        let tc = mean_seconds(reps, || {
            sys.phase_c().unwrap();
        });
        let ts = mean_seconds(reps, || {
            sys.solve(&r, &mut d).unwrap();
        });
        eprintln!(
            "13-dim N=50: residual {:.1} µs, factor {:.1} µs, phase C {:.1} µs, solve {:.1} µs",
            tr * 1e6,
            tf * 1e6,
            tc * 1e6,
            ts * 1e6
        );
    }

    #[test]
    #[ignore = "timing probe: cargo test --release --lib system::timing -- --ignored --nocapture"]
    fn troesch_parts() {
        let nn = 48;
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let mut sys = System::new(&Troesch, t, Tableau::new(4), vec![], 0).unwrap();
        let mut x = sys.zero_state();
        x.p[0] = 5.0;
        for j in 0..=nn {
            x.y[2 * j] = j as f64 / nn as f64;
            x.y[2 * j + 1] = 1.0;
        }
        let mut r = sys.zero_residual();
        let mut d = sys.zero_state();
        let reps = 2000;
        let tr = mean_seconds(reps, || {
            sys.residual(&x, &mut r).unwrap();
        });
        let tf = mean_seconds(reps, || {
            sys.factor(&x).unwrap();
        });
        let ts = mean_seconds(reps, || {
            sys.solve(&r, &mut d).unwrap();
        });
        eprintln!(
            "residual {:.1} µs, factor {:.1} µs, solve {:.1} µs",
            tr * 1e6,
            tf * 1e6,
            ts * 1e6
        );
    }
}
