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

/// Central differences of `eval` in the variables `cols` of `x`: entry r of
/// (e(x + δ_c e_c) − e(x − δ_c e_c))/(2δ_c) goes to `store(r, c, ·)`
/// (`plus`, `minus`: scratch of e's length; `x` is restored).
fn central_differences(
    x: &mut [f64],
    cols: impl IntoIterator<Item = usize>,
    plus: &mut [f64],
    minus: &mut [f64],
    mut eval: impl FnMut(&[f64], &mut [f64]),
    mut store: impl FnMut(usize, usize, f64),
) {
    for c in cols {
        let x0 = x[c];
        let d = fd_step(x0);
        x[c] = x0 + d;
        eval(x, plus);
        x[c] = x0 - d;
        eval(x, minus);
        x[c] = x0;
        for (r, (a, b)) in plus.iter().zip(minus.iter()).enumerate() {
            store(r, c, (a - b) / (2.0 * d));
        }
    }
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
        let (yb, pb) = (&mut self.ybuf[..n], &mut self.pbuf);
        let (fp, fm) = (&mut self.fbuf[..n], &mut self.fbuf2[..n]);
        yb.copy_from_slice(y);
        pb.copy_from_slice(p);
        let jac = &mut self.jac;
        central_differences(
            yb,
            0..n,
            fp,
            fm,
            |y, f| problem.rhs(z, y, p, f),
            |r, c, v| {
                jac[(r, c)] = v;
            },
        );
        let jacp = &mut self.jacp;
        let each = free.iter().copied();
        central_differences(
            pb,
            each,
            fp,
            fm,
            |p, f| problem.rhs(z, y, p, f),
            |r, c, v| {
                jacp[(r, c)] = v;
            },
        );
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
        let (yb, pb) = (&mut self.ybuf[..n], &mut self.pbuf);
        let (hp, hm) = (&mut self.fbuf[..ni], &mut self.fbuf2[..ni]);
        yb.copy_from_slice(y);
        pb.copy_from_slice(p);
        let eval_y = |y: &[f64], h: &mut [f64]| {
            h.fill(0.0);
            problem.integrand(z, y, yr, p, h);
        };
        let dhdy = &mut self.hy;
        central_differences(yb, 0..n, hp, hm, eval_y, |r, c, v| dhdy[(r, c)] = v);
        let eval_p = |p: &[f64], h: &mut [f64]| {
            h.fill(0.0);
            problem.integrand(z, y, yr, p, h);
        };
        let dhdp = &mut self.hp;
        let each = free.iter().copied();
        central_differences(pb, each, hp, hm, eval_p, |r, c, v| dhdp[(r, c)] = v);
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
        let mut yb = [y0, y1].concat();
        let mut pb = p.to_vec();
        let (mut gplus, mut gminus) = (vec![0.0; nb], vec![0.0; nb]);
        let (g0, g1) = (&mut self.g0, &mut self.g1);
        let eval_y = |y: &[f64], g: &mut [f64]| problem.boundary(&y[..n], &y[n..], p, g);
        central_differences(
            &mut yb,
            0..2 * n,
            &mut gplus,
            &mut gminus,
            eval_y,
            |r, c, v| {
                if c < n {
                    g0[(r, c)] = v;
                } else {
                    g1[(r, c - n)] = v;
                }
            },
        );
        let gp = &mut self.gp;
        let eval_p = |p: &[f64], g: &mut [f64]| problem.boundary(y0, y1, p, g);
        let each = free.iter().copied();
        central_differences(&mut pb, each, &mut gplus, &mut gminus, eval_p, |r, c, v| {
            gp[(r, c)] = v;
        });
    }
}
