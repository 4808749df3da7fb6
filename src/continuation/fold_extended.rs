//! The extended boundary-value problem of a fold (AUTO's ISW = 2): the
//! problem, its linearisation along a null vector v, and ∫ v·v = 1.
//!
//! For a problem y′ = f(s, y, p), g(y(0), y(1), p) = 0, ∫ h = 0 with the
//! solver's free parameters q and the fold parameter λ fixed, a fold is a
//! solution where the linearisation in (y, q) has a non-trivial solution
//! (v, δq):
//!
//! ```text
//!   v′ = f_y v + f_q δq,   g_0 v(0) + g_1 v(1) + g_q δq = 0,
//!   ∫ (h_y v + h_q δq) ds = 0,   ∫₀¹ v·v ds + δq·δq = 1.
//! ```
//!
//! The extended problem has 2n components (y, v), the parameters
//! (p, δq), 2 n_bc boundary conditions and 2 n_int + 1 integral conditions;
//! with q, λ and δq free it is well posed when the original one is with q
//! free, and continuation in a second parameter μ traces the fold curve.

use nalgebra::{DMatrix, DMatrixViewMut, DVector};

use crate::bvp::Problem;

/// Central-difference step ε^(1/3) (as the solver's Jacobians): directional
/// derivatives to about ε^(2/3) ≈ 4e-11 relative.
const STEP: f64 = 6.055_454_452_393_343e-6;

/// The extended problem of a fold of `problem` (module docs): a
/// [`Problem`] of its own, whose solutions are (y, v) with parameters
/// (p, δq); [`FoldPoint::extended`](super::FoldPoint::extended) is one.
///
/// Exported as [`FoldProblem`](super::FoldProblem) so that a fold curve's
/// own folds can be continued: a cusp of a fold in λ is a fold of this
/// problem in μ (the curve's turn in μ where λ stops too), so
/// [`FoldContinuation`](super::FoldContinuation) run on it, with μ as the
/// fold parameter and λ among the solver's free parameters, traces the
/// curve of cusps in a third parameter.
pub struct Extended<'a, P: Problem + ?Sized> {
    pub(super) problem: &'a P,
    /// The solver's free parameters q of the original problem (δq follows p).
    pub(super) free: Vec<usize>,
}

/// `out = (e(x + δd) − e(x − δd)) / 2δ`, the derivative of `eval` at `x`
/// along `d`, with δ = STEP (1 + ‖x‖∞)/‖d‖∞ (zero for d = 0).
fn directional(x: &[f64], d: &[f64], mut eval: impl FnMut(&[f64], &mut [f64]), out: &mut [f64]) {
    let dn = d.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    if dn == 0.0 {
        out.fill(0.0);
        return;
    }
    let xn = x.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let delta = STEP * (1.0 + xn) / dn;
    let plus: Vec<f64> = x.iter().zip(d).map(|(a, b)| a + delta * b).collect();
    let minus: Vec<f64> = x.iter().zip(d).map(|(a, b)| a - delta * b).collect();
    let mut back = vec![0.0; out.len()];
    eval(&plus, out);
    eval(&minus, &mut back);
    for (o, b) in out.iter_mut().zip(&back) {
        *o = (*o - b) / (2.0 * delta);
    }
}

impl<'a, P: Problem + ?Sized> Extended<'a, P> {
    /// The extended problem of `problem`'s folds when the solver frees the
    /// parameters `free` (their variations δq follow p in the extended
    /// parameter vector; the fold parameter is not among them).
    #[must_use]
    pub fn new(problem: &'a P, free: &[usize]) -> Self {
        Extended {
            problem,
            free: free.to_vec(),
        }
    }
}

impl<P: Problem + ?Sized> Extended<'_, P> {
    fn n(&self) -> usize {
        self.problem.dim()
    }

    fn np(&self) -> usize {
        self.problem.parameter_count()
    }

    /// The parameter direction (0 except δq at the free indices) of `p`.
    fn parameter_direction(&self, p: &[f64]) -> Vec<f64> {
        let np = self.np();
        let mut dp = vec![0.0; np];
        for (k, &i) in self.free.iter().enumerate() {
            dp[i] = p[np + k];
        }
        dp
    }
}

impl<P: Problem + ?Sized> Problem for Extended<'_, P> {
    fn dim(&self) -> usize {
        2 * self.n()
    }
    fn parameter_count(&self) -> usize {
        self.np() + self.free.len()
    }
    fn boundary_count(&self) -> usize {
        2 * self.problem.boundary_count()
    }
    fn integral_count(&self) -> usize {
        2 * self.problem.integral_count() + 1
    }
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        let (n, np) = (self.n(), self.np());
        let (y0, v) = y.split_at(n);
        let pp = &p[..np];
        let (f0, fv) = f.split_at_mut(n);
        self.problem.rhs(s, y0, pp, f0);
        let dp = self.parameter_direction(p);
        let mut fy = DMatrix::zeros(n, n);
        let mut fp = DMatrix::zeros(n, np);
        if self
            .problem
            .rhs_jacobian(s, y0, pp, fy.as_view_mut(), fp.as_view_mut())
        {
            let lin = &fy * DVector::from_column_slice(v) + &fp * DVector::from_column_slice(&dp);
            fv.copy_from_slice(lin.as_slice());
            return;
        }
        let x: Vec<f64> = y0.iter().chain(pp).copied().collect();
        let d: Vec<f64> = v.iter().chain(&dp).copied().collect();
        directional(
            &x,
            &d,
            |x, out| self.problem.rhs(s, &x[..n], &x[n..], out),
            fv,
        );
    }
    /// With the problem's analytic ∂f/∂y, ∂f/∂p: those for the y rows and
    /// the v block, and central differences of f_y v + f_p δp (one problem
    /// Jacobian per side, steps as the solver's) for the second
    /// derivatives; without them, `false` (the solver differences
    /// [`rhs`](Problem::rhs)).
    fn rhs_jacobian(
        &self,
        s: f64,
        y: &[f64],
        p: &[f64],
        mut dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let (n, np) = (self.n(), self.np());
        let (y0, v) = y.split_at(n);
        let pp = &p[..np];
        let mut fy = DMatrix::zeros(n, n);
        let mut fp = DMatrix::zeros(n, np);
        if !self
            .problem
            .rhs_jacobian(s, y0, pp, fy.as_view_mut(), fp.as_view_mut())
        {
            return false;
        }
        let dp = DVector::from_vec(self.parameter_direction(p));
        let v = DVector::from_column_slice(v);
        let linearised = |yy: &[f64], ppp: &[f64]| {
            let mut gy = DMatrix::zeros(n, n);
            let mut gp = DMatrix::zeros(n, np);
            self.problem
                .rhs_jacobian(s, yy, ppp, gy.as_view_mut(), gp.as_view_mut());
            gy * &v + gp * &dp
        };
        dfdy.view_mut((0, 0), (n, n)).copy_from(&fy);
        dfdy.view_mut((n, n), (n, n)).copy_from(&fy);
        dfdp.view_mut((0, 0), (n, np)).copy_from(&fp);
        for (k, &q) in self.free.iter().enumerate() {
            dfdp.view_mut((n, np + k), (n, 1)).copy_from(&fp.column(q));
        }
        let mut x: Vec<f64> = y0.iter().chain(pp).copied().collect();
        for c in 0..n + np {
            let x0 = x[c];
            let h = STEP * x0.abs().max(1.0);
            x[c] = x0 + h;
            let plus = linearised(&x[..n], &x[n..]);
            x[c] = x0 - h;
            let minus = linearised(&x[..n], &x[n..]);
            x[c] = x0;
            let col = (plus - minus) / (2.0 * h);
            if c < n {
                dfdy.view_mut((n, c), (n, 1)).copy_from(&col);
            } else {
                dfdp.view_mut((n, c - n), (n, 1)).copy_from(&col);
            }
        }
        true
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        let (n, np) = (self.n(), self.np());
        let nbc = self.problem.boundary_count();
        let pp = &p[..np];
        let (g0, gv) = g.split_at_mut(nbc);
        self.problem.boundary(&y0[..n], &y1[..n], pp, g0);
        let dp = self.parameter_direction(p);
        let (v0, v1) = (&y0[n..], &y1[n..]);
        let mut g0y = DMatrix::zeros(nbc, n);
        let mut g1y = DMatrix::zeros(nbc, n);
        let mut gp = DMatrix::zeros(nbc, np);
        if self.problem.boundary_jacobian(
            &y0[..n],
            &y1[..n],
            pp,
            g0y.as_view_mut(),
            g1y.as_view_mut(),
            gp.as_view_mut(),
        ) {
            let lin = &g0y * DVector::from_column_slice(v0)
                + &g1y * DVector::from_column_slice(v1)
                + &gp * DVector::from_column_slice(&dp);
            gv.copy_from_slice(lin.as_slice());
            return;
        }
        let x: Vec<f64> = y0[..n].iter().chain(&y1[..n]).chain(pp).copied().collect();
        let d: Vec<f64> = v0.iter().chain(v1).chain(&dp).copied().collect();
        directional(
            &x,
            &d,
            |x, out| {
                self.problem
                    .boundary(&x[..n], &x[n..2 * n], &x[2 * n..], out);
            },
            gv,
        );
    }
    fn integrand(&self, s: f64, y: &[f64], y_ref: &[f64], p: &[f64], h: &mut [f64]) {
        let (n, np) = (self.n(), self.np());
        let nint = self.problem.integral_count();
        let (y0, v) = y.split_at(n);
        let pp = &p[..np];
        let (h0, rest) = h.split_at_mut(nint);
        let (hv, hnorm) = rest.split_at_mut(nint);
        if nint > 0 {
            let r = &y_ref[..n];
            self.problem.integrand(s, y0, r, pp, h0);
            let dp = self.parameter_direction(p);
            let mut hy = DMatrix::zeros(nint, n);
            let mut hp = DMatrix::zeros(nint, np);
            if self
                .problem
                .integrand_jacobian(s, y0, r, pp, hy.as_view_mut(), hp.as_view_mut())
            {
                let lin =
                    &hy * DVector::from_column_slice(v) + &hp * DVector::from_column_slice(&dp);
                hv.copy_from_slice(lin.as_slice());
            } else {
                let x: Vec<f64> = y0.iter().chain(pp).copied().collect();
                let d: Vec<f64> = v.iter().chain(&dp).copied().collect();
                directional(
                    &x,
                    &d,
                    |x, out| self.problem.integrand(s, &x[..n], r, &x[n..], out),
                    hv,
                );
            }
        }
        hnorm[0] = v.iter().chain(&p[np..]).map(|a| a * a).sum::<f64>() - 1.0;
    }
}
