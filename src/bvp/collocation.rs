//! The collocation solver (how): builder, validation, solve on a mesh.

use std::fmt;

use super::guess::{InitialGuess, state_from_guess};
use super::mesh::Mesh;
use super::newton::{NewtonOptions, ROUNDOFF_STALL, finish, newton};
use super::problem::Problem;
use super::solution::Solution;
use super::system::{LinearSolver, System};
use super::tableau::Tableau;
use crate::error::{Error, Result};

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
    pub(super) max_intervals: usize,
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
    /// The largest Newton iteration limit, 1000 (a limit is there to stop a
    /// run that does not converge; more iterations than this never help).
    pub const MAX_NEWTON: u32 = 1000;

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
    ///
    /// The setters never fail. Every setting is checked by
    /// [`solve`](Self::solve) (and by [`Continuation::run`]) before any work,
    /// and a bad one is a typed error: `points` outside 2..=7, `intervals`
    /// or `max_intervals` outside 1..=[`Mesh::MAX_INTERVALS`], `max_newton`
    /// outside 1..=[`Collocation::MAX_NEWTON`], a `newton_tolerance` outside
    /// [1e-14, 1e-2] or a `tolerance` that is not finite and positive give
    /// [`Error::InvalidCount`] or [`Error::InvalidArgument`]. A system that
    /// would need more than 2 GiB of workspace is refused with
    /// [`Error::SystemTooLarge`] before it is allocated.
    ///
    /// [`Continuation::run`]: crate::continuation::Continuation::run
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

    /// A uniform mesh of N intervals, 1 ≤ N ≤ [`Mesh::MAX_INTERVALS`]
    /// (overrides a guess's mesh; checked by `solve`).
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

    /// Adapt the mesh until the error is below `tol · (1 + max|y|)` (max
    /// over components and mesh values): the coarsest equidistributed mesh
    /// the local estimate allows, verified on its halved mesh (the returned
    /// [`Solution::error_estimate`] is twice the largest difference of the
    /// two, and meets the tolerance) and refined until it does.
    #[must_use]
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tolerance = Some(tol);
        self
    }

    /// The interval limit of the adaptive mesh, at most
    /// [`Mesh::MAX_INTERVALS`] (checked by `solve`). The halved mesh that
    /// verifies a tolerance counts: a mesh of more than half the limit
    /// cannot be verified, and `solve` says `ToleranceNotMet`.
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

    /// The Newton iteration limit, 1..=[`Collocation::MAX_NEWTON`] (checked
    /// by `solve`).
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

    pub(crate) fn interval_limit(&self) -> usize {
        self.max_intervals
    }

    pub(crate) fn free(&self) -> &[usize] {
        &self.free
    }

    pub(crate) fn newton_options(&self) -> NewtonOptions {
        NewtonOptions {
            tol: self.newton_tolerance,
            max_iter: self.max_newton,
            stall: 1.0,
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
        if !(1..=Self::MAX_NEWTON).contains(&self.max_newton) {
            return Err(Error::InvalidCount {
                name: "max_newton",
                value: u64::from(self.max_newton),
                allowed: "1..=1000 (Collocation::MAX_NEWTON)",
            });
        }
        let counts = [
            ("intervals", self.intervals),
            ("max_intervals", Some(self.max_intervals)),
        ];
        for (name, count) in counts {
            if let Some(c) = count
                && !(1..=Mesh::MAX_INTERVALS).contains(&c)
            {
                return Err(Error::InvalidCount {
                    name,
                    value: c as u64,
                    allowed: "1..=1_000_000 (Mesh::MAX_INTERVALS)",
                });
            }
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
        let mut sys = System::new(
            problem,
            mesh.points().to_vec(),
            tab.clone(),
            self.free.clone(),
            0,
        )?;
        let mut x = state_from_guess(guess, &mesh, tab, sys.n, parameters);
        sys.linear = self.linear;
        let mut yref = std::mem::take(&mut sys.y_ref);
        sys.collocation_values(&x, &mut yref);
        sys.y_ref = yref;
        let opts = NewtonOptions {
            stall: ROUNDOFF_STALL,
            ..self.newton_options()
        };
        let stats = newton(&mut sys, &mut x, opts, false)?;
        finish(&mut sys, x, mesh, stats)
    }
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
