//! Derivatives of the problem's functions at one point: the problem's own
//! Jacobians when it provides them, else central differences.

use nalgebra::DMatrix;

use crate::bvp::problem::Problem;

/// Central-difference step for a value of size |x|: ε^(1/3) max(1, |x|),
/// which balances truncation O(δ²) against rounding O(ε/δ): Jacobian entries
/// to about ε^(2/3) ≈ 4e-11 relative.
fn fd_step(x: f64) -> f64 {
    6.055454452393343e-6 * x.abs().max(1.0)
}

/// ∂f/∂y, ∂f/∂p, ∂h/∂y, ∂h/∂p at one collocation point, with the scratch
/// their differences need (one per thread of the condensation).
pub(super) struct PointDerivatives {
    /// ∂f/∂y, n × n.
    pub jac: DMatrix<f64>,
    /// ∂f/∂p, n × n_p (only the free columns are filled by differences).
    pub jacp: DMatrix<f64>,
    /// ∂h/∂y, n_int × n.
    pub hy: DMatrix<f64>,
    /// ∂h/∂p, n_int × n_p.
    pub hp: DMatrix<f64>,
    fbuf: Vec<f64>,
    fbuf2: Vec<f64>,
    ybuf: Vec<f64>,
    pbuf: Vec<f64>,
}

impl PointDerivatives {
    pub(super) fn new(n: usize, np: usize, nint: usize) -> Self {
        PointDerivatives {
            jac: DMatrix::zeros(n, n),
            jacp: DMatrix::zeros(n, np),
            hy: DMatrix::zeros(nint, n),
            hp: DMatrix::zeros(nint, np),
            fbuf: vec![0.0; n.max(nint)],
            fbuf2: vec![0.0; n.max(nint)],
            ybuf: vec![0.0; n],
            pbuf: vec![0.0; np],
        }
    }

    /// ∂f/∂y into `jac` and ∂f/∂p (free columns) into `jacp` at (z, y).
    pub(super) fn rhs<P: Problem + ?Sized>(
        &mut self,
        problem: &P,
        free: &[usize],
        z: f64,
        y: &[f64],
        p: &[f64],
    ) {
        self.jac.fill(0.0);
        self.jacp.fill(0.0);
        if problem.rhs_jacobian(z, y, p, self.jac.as_view_mut(), self.jacp.as_view_mut()) {
            return;
        }
        let n = y.len();
        let (yb, pb) = (&mut self.ybuf, &mut self.pbuf);
        yb[..n].copy_from_slice(y);
        pb.copy_from_slice(p);
        for c in 0..n {
            let d = fd_step(y[c]);
            yb[c] = y[c] + d;
            problem.rhs(z, &yb[..n], p, &mut self.fbuf[..n]);
            yb[c] = y[c] - d;
            problem.rhs(z, &yb[..n], p, &mut self.fbuf2[..n]);
            yb[c] = y[c];
            for r in 0..n {
                self.jac[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
        for &c in free {
            let d = fd_step(p[c]);
            pb[c] = p[c] + d;
            problem.rhs(z, y, pb, &mut self.fbuf[..n]);
            pb[c] = p[c] - d;
            problem.rhs(z, y, pb, &mut self.fbuf2[..n]);
            pb[c] = p[c];
            for r in 0..n {
                self.jacp[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
    }

    /// ∂h/∂y into `hy` and ∂h/∂p (free columns) into `hp` at (z, y, y_ref).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn integrand<P: Problem + ?Sized>(
        &mut self,
        problem: &P,
        free: &[usize],
        nint: usize,
        z: f64,
        y: &[f64],
        yr: &[f64],
        p: &[f64],
    ) {
        self.hy.fill(0.0);
        self.hp.fill(0.0);
        if problem.integrand_jacobian(z, y, yr, p, self.hy.as_view_mut(), self.hp.as_view_mut()) {
            return;
        }
        let (n, ni) = (y.len(), nint);
        let (yb, pb) = (&mut self.ybuf, &mut self.pbuf);
        yb[..n].copy_from_slice(y);
        pb.copy_from_slice(p);
        for c in 0..n {
            let d = fd_step(y[c]);
            yb[c] = y[c] + d;
            self.fbuf[..ni].fill(0.0);
            problem.integrand(z, &yb[..n], yr, p, &mut self.fbuf[..ni]);
            yb[c] = y[c] - d;
            self.fbuf2[..ni].fill(0.0);
            problem.integrand(z, &yb[..n], yr, p, &mut self.fbuf2[..ni]);
            yb[c] = y[c];
            for r in 0..ni {
                self.hy[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
        for &c in free {
            let d = fd_step(p[c]);
            pb[c] = p[c] + d;
            self.fbuf[..ni].fill(0.0);
            problem.integrand(z, y, yr, pb, &mut self.fbuf[..ni]);
            pb[c] = p[c] - d;
            self.fbuf2[..ni].fill(0.0);
            problem.integrand(z, y, yr, pb, &mut self.fbuf2[..ni]);
            pb[c] = p[c];
            for r in 0..ni {
                self.hp[(r, c)] = (self.fbuf[r] - self.fbuf2[r]) / (2.0 * d);
            }
        }
    }
}

/// ∂g/∂y(0), ∂g/∂y(1), ∂g/∂p of the boundary conditions.
pub(super) struct BoundaryDerivatives {
    pub g0: DMatrix<f64>,
    pub g1: DMatrix<f64>,
    pub gp: DMatrix<f64>,
}

impl BoundaryDerivatives {
    pub(super) fn new(n: usize, np: usize, nbc: usize) -> Self {
        BoundaryDerivatives {
            g0: DMatrix::zeros(nbc, n),
            g1: DMatrix::zeros(nbc, n),
            gp: DMatrix::zeros(nbc, np),
        }
    }

    /// The derivatives at (y0, y1, p) (free parameter columns only when by
    /// differences).
    pub(super) fn eval<P: Problem + ?Sized>(
        &mut self,
        problem: &P,
        free: &[usize],
        y0: &[f64],
        y1: &[f64],
        p: &[f64],
    ) {
        self.g0.fill(0.0);
        self.g1.fill(0.0);
        self.gp.fill(0.0);
        if problem.boundary_jacobian(
            y0,
            y1,
            p,
            self.g0.as_view_mut(),
            self.g1.as_view_mut(),
            self.gp.as_view_mut(),
        ) {
            return;
        }
        let (n, nb) = (y0.len(), self.g0.nrows());
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
            problem.boundary(&yb[..n], &yb[n..], p, &mut gplus);
            yb[c] = x - d;
            problem.boundary(&yb[..n], &yb[n..], p, &mut gminus);
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
        for &c in free {
            let x = pb[c];
            let d = fd_step(x);
            pb[c] = x + d;
            problem.boundary(y0, y1, &pb, &mut gplus);
            pb[c] = x - d;
            problem.boundary(y0, y1, &pb, &mut gminus);
            pb[c] = x;
            for r in 0..nb {
                self.gp[(r, c)] = (gplus[r] - gminus[r]) / (2.0 * d);
            }
        }
    }
}
