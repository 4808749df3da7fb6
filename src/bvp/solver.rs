//! The collocation solver (how): builder, Newton, mesh adaptation.

use std::fmt;

use super::mesh::Mesh;
use super::problem::Problem;
use super::solution::{NewtonStats, Solution};
use super::system::{LinearSolver, Residual, State, System};
use super::tableau::Tableau;
use crate::error::{Error, Result};

/// A starting guess for [`Collocation::solve`]: a closure s ↦ y(s) (any
/// `Fn(f64) -> V` with `V: AsRef<[f64]>`, e.g. arrays, `Vec` or `DVector`),
/// or a previous [`Solution`] (copied exactly when the mesh and m agree,
/// otherwise evaluated through its collocation polynomial).
pub trait InitialGuess {
    /// Writes the guess y(s) into `y` (length n).
    fn value(&self, s: f64, y: &mut [f64]);

    /// The solution this guess is, when it is one.
    fn solution(&self) -> Option<&Solution> {
        None
    }
}

impl<F, V> InitialGuess for F
where
    F: Fn(f64) -> V,
    V: AsRef<[f64]>,
{
    fn value(&self, s: f64, y: &mut [f64]) {
        let v = self(s);
        let v = v.as_ref();
        let k = v.len().min(y.len());
        y[..k].copy_from_slice(&v[..k]);
    }
}

impl InitialGuess for Solution {
    fn value(&self, s: f64, y: &mut [f64]) {
        self.eval_into(s, y);
    }

    fn solution(&self) -> Option<&Solution> {
        Some(self)
    }
}

impl InitialGuess for &Solution {
    fn value(&self, s: f64, y: &mut [f64]) {
        self.eval_into(s, y);
    }

    fn solution(&self) -> Option<&Solution> {
        Some(self)
    }
}

/// Newton settings shared with continuation.
#[derive(Debug, Clone, Copy)]
pub(crate) struct NewtonOptions {
    pub tol: f64,
    pub max_iter: u32,
}

/// ‖δ‖∞ / (1 + ‖x‖∞) over the mesh values and the free parameters.
pub(crate) fn scaled_norm(d: &State, x: &State, free: &[usize]) -> f64 {
    let mut dn: f64 = 0.0;
    let mut xn: f64 = 0.0;
    for (a, b) in d.y.iter().zip(&x.y) {
        dn = dn.max(a.abs());
        xn = xn.max(b.abs());
    }
    for &i in free {
        dn = dn.max(d.p[i].abs());
        xn = xn.max(x.p[i].abs());
    }
    if dn.is_nan() {
        return f64::INFINITY;
    }
    dn / (1.0 + xn)
}

/// Damped Newton with chord steps (natural monotonicity test, Deuflhard):
/// a step λδ is accepted when the simplified correction δ̄ computed with the
/// same factorisation satisfies ‖δ̄‖ < (1 − λ/4)‖δ‖; the factorisation is
/// kept (chord) while the contraction ‖δ̄‖/‖δ‖ stays below ⅛. With `reuse`,
/// the system's existing factorisation is tried first.
pub(crate) fn newton<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &mut State,
    opts: NewtonOptions,
    reuse: bool,
) -> Result<NewtonStats> {
    let free = sys.free.clone();
    let mut stats = NewtonStats::default();
    let mut res = sys.zero_residual();
    let mut dx = sys.zero_state();
    let mut dbar = sys.zero_state();
    let mut trial = x.clone();
    sys.residual(x, &mut res)?;
    let mut fresh = !reuse;
    if fresh {
        sys.factor(x)?;
        stats.jacobians += 1;
    }
    sys.solve(&res, &mut dx)?;
    let mut ndx = scaled_norm(&dx, x, &free);
    for it in 0..opts.max_iter {
        if ndx <= opts.tol {
            x.axpy(1.0, &dx, &free);
            stats.iterations += 1;
            stats.correction = ndx;
            return Ok(stats);
        }
        let mut lam = 1.0;
        let theta;
        loop {
            trial.clone_from(x);
            trial.axpy(lam, &dx, &free);
            let ok = match sys.residual(&trial, &mut res) {
                Ok(()) => sys.solve(&res, &mut dbar).is_ok(),
                Err(Error::NonFinite { .. }) => false,
                Err(e) => return Err(e),
            };
            if ok {
                let nb = scaled_norm(&dbar, &trial, &free);
                if nb < (1.0 - 0.25 * lam) * ndx {
                    theta = nb / ndx;
                    break;
                }
            }
            if !fresh {
                sys.residual(x, &mut res)?;
                sys.factor(x)?;
                stats.jacobians += 1;
                fresh = true;
                sys.solve(&res, &mut dx)?;
                ndx = scaled_norm(&dx, x, &free);
                lam = 1.0;
                if ndx <= opts.tol {
                    x.axpy(1.0, &dx, &free);
                    stats.iterations += 1;
                    stats.correction = ndx;
                    return Ok(stats);
                }
                continue;
            }
            lam *= 0.5;
            if lam < 1.0 / 1024.0 {
                return Err(Error::NewtonDiverged {
                    iteration: it,
                    correction: ndx,
                });
            }
        }
        std::mem::swap(x, &mut trial);
        stats.iterations += 1;
        if theta > 0.125 || lam < 1.0 {
            sys.factor(x)?;
            stats.jacobians += 1;
            fresh = true;
            sys.solve(&res, &mut dx)?;
        } else {
            std::mem::swap(&mut dx, &mut dbar);
            fresh = false;
        }
        ndx = scaled_norm(&dx, x, &free);
        stats.correction = ndx;
    }
    if ndx <= opts.tol {
        x.axpy(1.0, &dx, &free);
        stats.iterations += 1;
        return Ok(stats);
    }
    Err(Error::NewtonNotConverged {
        iterations: opts.max_iter,
        correction: ndx,
        tolerance: opts.tol,
    })
}

/// Builds the unknowns on `mesh` from a guess: Y_j = y(t_j) and K_j such
/// that the collocation polynomial interpolates y at the Gauss points.
pub(crate) fn state_from_guess<G: InitialGuess + ?Sized>(
    guess: &G,
    mesh: &Mesh,
    tab: &Tableau,
    n: usize,
    p: &[f64],
) -> State {
    let m = tab.m;
    let nn = mesh.intervals();
    if let Some(sol) = guess.solution()
        && sol.n == n
        && sol.tab.m == m
        && sol.mesh == *mesh
    {
        return State {
            y: sol.y.clone(),
            k: sol.k.clone(),
            p: p.to_vec(),
        };
    }
    let mut y = vec![0.0; (nn + 1) * n];
    for j in 0..=nn {
        guess.value(mesh.points()[j], &mut y[j * n..(j + 1) * n]);
    }
    let mut k = vec![0.0; nn * m * n];
    let mut v = vec![0.0; m * n];
    for j in 0..nn {
        let h = mesh.width(j);
        for l in 0..m {
            let z = mesh.points()[j] + tab.c[l] * h;
            guess.value(z, &mut v[l * n..(l + 1) * n]);
            for i in 0..n {
                v[l * n + i] -= y[j * n + i];
            }
        }
        for kk in 0..m {
            for l in 0..m {
                let a = tab.a_inv[kk * m + l] / h;
                for i in 0..n {
                    k[(j * m + kk) * n + i] += a * v[l * n + i];
                }
            }
        }
    }
    State {
        y,
        k,
        p: p.to_vec(),
    }
}

/// The collocation solver: Gauss–Legendre collocation with m points per
/// interval, damped chord Newton, O(N) condensed linear algebra and an
/// optional adaptive mesh.
///
/// ```
/// use hockle::bvp::{Collocation, Problem};
/// // y'' = y, y(0) = 1, y(1) = 0 as a first-order system.
/// struct Lin;
/// impl Problem for Lin {
///     fn dim(&self) -> usize { 2 }
///     fn parameter_count(&self) -> usize { 0 }
///     fn boundary_count(&self) -> usize { 2 }
///     fn rhs(&self, _s: f64, y: &[f64], _p: &[f64], f: &mut [f64]) {
///         f[0] = y[1];
///         f[1] = y[0];
///     }
///     fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
///         g[0] = y0[0] - 1.0;
///         g[1] = y1[0];
///     }
/// }
/// let sol = Collocation::new().intervals(8).solve(&Lin, |_s: f64| [0.0, 0.0], &[])?;
/// // Exact: y'(0) = −cosh(1)/sinh(1); error O(h^8) at mesh points.
/// let exact = -1.0_f64.cosh() / 1.0_f64.sinh();
/// assert!((sol.at_mesh(0)[1] - exact).abs() < 1e-10);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Collocation {
    points: usize,
    intervals: Option<usize>,
    mesh: Option<Mesh>,
    tolerance: Option<f64>,
    max_intervals: usize,
    newton_tolerance: f64,
    max_newton: u32,
    free: Vec<usize>,
    linear: LinearSolver,
}

impl Default for Collocation {
    fn default() -> Self {
        Self::new()
    }
}

impl Collocation {
    /// A solver with the defaults:
    ///
    /// | setting | default |
    /// |---|---|
    /// | [`points`](Self::points) m | 4 (error O(h⁸) at mesh points) |
    /// | mesh | the guess's mesh if it is a [`Solution`], else 20 equal intervals |
    /// | [`tolerance`](Self::tolerance) | none: solve on the given mesh only |
    /// | [`max_intervals`](Self::max_intervals) | 4000 |
    /// | [`newton_tolerance`](Self::newton_tolerance) | 1e-10 (scaled max-norm of the correction) |
    /// | [`max_newton`](Self::max_newton) | 30 |
    /// | [`free_parameters`](Self::free_parameters) | none |
    /// | [`linear_solver`](Self::linear_solver) | [`LinearSolver::Condensed`] |
    #[must_use]
    pub fn new() -> Self {
        Collocation {
            points: 4,
            intervals: None,
            mesh: None,
            tolerance: None,
            max_intervals: 4000,
            newton_tolerance: 1e-10,
            max_newton: 30,
            free: Vec::new(),
            linear: LinearSolver::Condensed,
        }
    }

    /// Collocation points per interval, m ∈ 2..=7 (checked by `solve`).
    #[must_use]
    pub fn points(mut self, m: usize) -> Self {
        self.points = m;
        self
    }

    /// A uniform mesh of N intervals (overrides a guess's mesh).
    #[must_use]
    pub fn intervals(mut self, n: usize) -> Self {
        self.intervals = Some(n);
        self
    }

    /// An explicit mesh (overrides `intervals` and the guess's mesh).
    #[must_use]
    pub fn mesh(mut self, mesh: Mesh) -> Self {
        self.mesh = Some(mesh);
        self
    }

    /// Adapt the mesh until the error estimate (see
    /// [`Solution::error_estimate`]) is below `tol · (1 + max|y|)`, using
    /// the coarsest equidistributed mesh the estimate allows.
    #[must_use]
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tolerance = Some(tol);
        self
    }

    /// The interval limit of the adaptive mesh.
    #[must_use]
    pub fn max_intervals(mut self, n: usize) -> Self {
        self.max_intervals = n;
        self
    }

    /// Newton stops when ‖δ‖∞ ≤ tol·(1 + ‖x‖∞) (tol ∈ [1e-14, 1e-2]).
    #[must_use]
    pub fn newton_tolerance(mut self, tol: f64) -> Self {
        self.newton_tolerance = tol;
        self
    }

    /// The Newton iteration limit.
    #[must_use]
    pub fn max_newton(mut self, n: u32) -> Self {
        self.max_newton = n;
        self
    }

    /// Indices into p of the parameters that are unknowns.
    #[must_use]
    pub fn free_parameters(mut self, idx: &[usize]) -> Self {
        self.free = idx.to_vec();
        self
    }

    /// The linear solver (the sparse LU is the slower reference).
    #[must_use]
    pub fn linear_solver(mut self, linear: LinearSolver) -> Self {
        self.linear = linear;
        self
    }

    pub(crate) fn free(&self) -> &[usize] {
        &self.free
    }

    pub(crate) fn newton_options(&self) -> NewtonOptions {
        NewtonOptions {
            tol: self.newton_tolerance,
            max_iter: self.max_newton,
        }
    }

    pub(crate) fn linear(&self) -> LinearSolver {
        self.linear
    }

    pub(crate) fn validate(&self) -> Result<Tableau> {
        if !(2..=7).contains(&self.points) {
            return Err(Error::InvalidCount {
                name: "points",
                value: self.points as u64,
                allowed: "2..=7 collocation points per interval",
            });
        }
        if !(1e-14..=1e-2).contains(&self.newton_tolerance) {
            return Err(Error::InvalidArgument {
                name: "newton_tolerance",
                value: self.newton_tolerance,
                allowed: "1e-14 ≤ tol ≤ 1e-2",
            });
        }
        if let Some(t) = self.tolerance
            && !(t > 0.0 && t.is_finite())
        {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: t,
                allowed: "a finite positive number",
            });
        }
        if self.max_newton == 0 {
            return Err(Error::InvalidCount {
                name: "max_newton",
                value: 0,
                allowed: "at least 1",
            });
        }
        Ok(Tableau::new(self.points))
    }

    fn initial_mesh<G: InitialGuess + ?Sized>(&self, guess: &G) -> Result<Mesh> {
        if let Some(m) = &self.mesh {
            return Ok(m.clone());
        }
        if let Some(n) = self.intervals {
            return Mesh::uniform(n);
        }
        if let Some(s) = guess.solution() {
            return Ok(s.mesh.clone());
        }
        Mesh::uniform(20)
    }

    /// Solves the problem from a guess, with `parameters` the full parameter
    /// vector (the free entries are the starting values of the unknowns).
    ///
    /// # Errors
    /// [`Error::InvalidCount`]/[`Error::InvalidArgument`] for bad settings,
    /// [`Error::LengthMismatch`] if `parameters` has the wrong length,
    /// [`Error::IllPosed`] if n_bc + n_int ≠ n + free parameters,
    /// [`Error::NonFinite`] if the problem returns NaN/∞ at the guess,
    /// [`Error::SingularJacobian`], [`Error::NewtonDiverged`],
    /// [`Error::NewtonNotConverged`], and with a tolerance
    /// [`Error::ToleranceNotMet`].
    pub fn solve<P, G>(&self, problem: &P, guess: G, parameters: &[f64]) -> Result<Solution>
    where
        P: Problem + ?Sized,
        G: InitialGuess,
    {
        let tab = self.validate()?;
        if parameters.len() != problem.parameter_count() {
            return Err(Error::LengthMismatch {
                name: "parameters",
                found: parameters.len() as u64,
                expected: problem.parameter_count() as u64,
            });
        }
        let mesh = self.initial_mesh(&guess)?;
        let sol = self.solve_on(problem, &guess, parameters, mesh, &tab)?;
        let Some(tol) = self.tolerance else {
            return Ok(sol);
        };
        self.adapt(problem, sol, tol, &tab)
    }

    fn adapt<P: Problem + ?Sized>(
        &self,
        problem: &P,
        mut sol: Solution,
        tol: f64,
        tab: &Tableau,
    ) -> Result<Solution> {
        let mut best: Option<Solution> = None;
        for _round in 0..12 {
            let ymax = sol.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            let atol = tol * (1.0 + ymax);
            let est = sol.error_estimate;
            let ok = est <= atol;
            let nn = sol.mesh.intervals();
            // Equidistribute φ = ‖y^(m+1)‖^(1/(m+1)); the estimate on an
            // equidistributed mesh is C_m (I/N)^(m+1).
            let d = sol.derivative_m1();
            let m1 = (tab.m + 1) as f64;
            let dmax = d.iter().fold(0.0_f64, |a, v| a.max(*v));
            let mut phi: Vec<f64> = d
                .iter()
                .map(|v| v.max(1e-6 * dmax).max(1e-300).powf(1.0 / m1))
                .collect();
            if phi.len() > 2 {
                let raw = phi.clone();
                for j in 0..raw.len() {
                    let a = raw[j.saturating_sub(1)];
                    let c = raw[(j + 1).min(raw.len() - 1)];
                    phi[j] = 0.25 * (a + 2.0 * raw[j] + c);
                }
            }
            let integral: f64 = phi
                .iter()
                .enumerate()
                .map(|(j, f)| f * sol.mesh.width(j))
                .sum();
            let mut target =
                (integral * (1.2 * tab.error_constant / atol).powf(1.0 / m1)).ceil() as usize;
            target = target.max(2);
            if ok {
                if best
                    .as_ref()
                    .is_none_or(|b| b.mesh.intervals() > sol.mesh.intervals())
                {
                    best = Some(sol.clone());
                }
                // Coarsen only when clearly possible.
                if target * 10 >= nn * 8
                    || best.as_ref().is_some_and(|b| b.mesh.intervals() <= target)
                {
                    return Ok(best.unwrap_or(sol));
                }
            } else {
                target = target.max(nn + nn / 5 + 1);
            }
            if target > self.max_intervals {
                if let Some(b) = best {
                    return Ok(b);
                }
                return Err(Error::ToleranceNotMet {
                    tolerance: tol,
                    estimate: est,
                    intervals: nn as u64,
                });
            }
            let mesh = equidistribute(&sol.mesh, &phi, target)?;
            let p = sol.p.clone();
            match self.solve_on(problem, &sol, &p, mesh, tab) {
                Ok(s) => sol = s,
                Err(e) => {
                    if let Some(b) = best {
                        return Ok(b);
                    }
                    return Err(e);
                }
            }
        }
        if let Some(b) = best {
            return Ok(b);
        }
        Err(Error::ToleranceNotMet {
            tolerance: tol,
            estimate: sol.error_estimate,
            intervals: sol.mesh.intervals() as u64,
        })
    }

    pub(crate) fn solve_on<P, G>(
        &self,
        problem: &P,
        guess: &G,
        parameters: &[f64],
        mesh: Mesh,
        tab: &Tableau,
    ) -> Result<Solution>
    where
        P: Problem + ?Sized,
        G: InitialGuess + ?Sized,
    {
        let n = problem.dim();
        let mut x = state_from_guess(guess, &mesh, tab, n, parameters);
        let mut sys = System::new(
            problem,
            mesh.points().to_vec(),
            tab.clone(),
            self.free.clone(),
            0,
        )?;
        sys.linear = self.linear;
        let mut yref = std::mem::take(&mut sys.y_ref);
        sys.collocation_values(&x, &mut yref);
        sys.y_ref = yref;
        let stats = newton(&mut sys, &mut x, self.newton_options(), false)?;
        finish(&mut sys, x, mesh, stats)
    }
}

/// Builds the public solution from a converged state.
pub(crate) fn finish<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: State,
    mesh: Mesh,
    newton: NewtonStats,
) -> Result<Solution> {
    let mut r: Residual = sys.zero_residual();
    sys.residual(&x, &mut r)?;
    let mut sol = Solution {
        mesh,
        tab: sys.tab.clone(),
        n: sys.n,
        y: x.y,
        k: x.k,
        p: x.p,
        residual_norm: r.max_norm(),
        error_estimate: f64::NAN,
        newton,
    };
    sol.error_estimate = sol.estimate_error();
    Ok(sol)
}

/// A mesh of `n` intervals equidistributing the piecewise-constant density
/// `phi` given on `old`.
pub(crate) fn equidistribute(old: &Mesh, phi: &[f64], n: usize) -> Result<Mesh> {
    let nn = old.intervals();
    let mut cum = vec![0.0; nn + 1];
    for j in 0..nn {
        cum[j + 1] = cum[j] + phi[j] * old.width(j);
    }
    let total = cum[nn];
    let mut pts = Vec::with_capacity(n + 1);
    pts.push(0.0);
    let mut j = 0;
    for i in 1..n {
        let target = total * i as f64 / n as f64;
        while j < nn - 1 && cum[j + 1] < target {
            j += 1;
        }
        let frac = if phi[j] > 0.0 {
            (target - cum[j]) / (phi[j] * old.width(j))
        } else {
            0.5
        };
        let t = old.points()[j] + frac.clamp(0.0, 1.0) * old.width(j);
        if t > *pts.last().unwrap_or(&0.0) && t < 1.0 {
            pts.push(t);
        }
    }
    pts.push(1.0);
    Mesh::from_points(pts)
}

impl fmt::Display for Collocation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Gauss–Legendre collocation, m = {}", self.points)?;
        if let Some(t) = self.tolerance {
            write!(f, ", adaptive mesh (tolerance {t:.1e})")?;
        }
        write!(f, ", Newton tolerance {:.1e}", self.newton_tolerance)
    }
}
