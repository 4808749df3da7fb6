//! The continuation driver.

use std::collections::VecDeque;
use std::fmt;
use std::ops::ControlFlow;
use std::sync::Arc;

use crate::bvp::system::{State, System};
use crate::bvp::{Collocation, NewtonOptions, Problem, Solution, finish, newton, scaled_norm};
use crate::error::{Error, Result};
use crate::linalg::Det;

/// The kind of a point on a branch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum PointKind {
    /// The first point of a run.
    Start,
    /// An ordinary step.
    Regular,
    /// A located fold (limit point): dλ/ds = 0.
    Fold,
    /// A located branch point: det [F_x; τᵀ] = 0.
    BranchPoint,
    /// A located point where λ reached a requested value.
    ParameterValue,
    /// A located zero of the user event with this index.
    Event(usize),
}

impl PointKind {
    fn name(self) -> &'static str {
        match self {
            PointKind::Start => "start point",
            PointKind::Regular => "regular point",
            PointKind::Fold => "fold",
            PointKind::BranchPoint => "branch point",
            PointKind::ParameterValue => "parameter value",
            PointKind::Event(_) => "event",
        }
    }
}

impl fmt::Display for PointKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PointKind::Event(i) => write!(f, "event {i}"),
            k => f.write_str(k.name()),
        }
    }
}

/// One point of a branch.
#[derive(Debug, Clone)]
pub struct Point {
    solution: Solution,
    parameter: f64,
    arclength: f64,
    newton_iterations: u32,
    dparameter: f64,
    determinant_sign: f64,
    kind: PointKind,
    pub(crate) tangent: Option<State>,
}

impl Point {
    /// The collocation solution at this point.
    #[must_use]
    pub fn solution(&self) -> &Solution {
        &self.solution
    }

    /// The continuation parameter λ.
    #[must_use]
    pub fn parameter(&self) -> f64 {
        self.parameter
    }

    /// Every parameter of the problem at this point.
    #[must_use]
    pub fn parameters(&self) -> &[f64] {
        self.solution.parameters()
    }

    /// Arclength from the start of the run (in the weighted integral norm).
    #[must_use]
    pub fn arclength(&self) -> f64 {
        self.arclength
    }

    /// Newton iterations of the corrector that produced the point.
    #[must_use]
    pub fn newton_iterations(&self) -> u32 {
        self.newton_iterations
    }

    /// dλ/ds, the parameter component of the unit tangent (its sign changes
    /// at folds).
    #[must_use]
    pub fn dparameter_ds(&self) -> f64 {
        self.dparameter
    }

    /// The sign (±1) of det [F_x; τᵀ] of the discretised system; it changes
    /// at branch points. Along a branch of stable equilibria of a variational
    /// problem it changes exactly when a mode crosses zero, so the count of
    /// changes since a known-stable point tracks the index.
    #[must_use]
    pub fn determinant_sign(&self) -> f64 {
        self.determinant_sign
    }

    /// What the point is.
    #[must_use]
    pub fn kind(&self) -> PointKind {
        self.kind
    }

    /// Whether the point is a located special point (not start or regular).
    #[must_use]
    pub fn is_special(&self) -> bool {
        !matches!(self.kind, PointKind::Start | PointKind::Regular)
    }
}

impl fmt::Display for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} lambda={:.15e} s={:.6e} dlambda/ds={:+.3e} det_sign={:+} newton={}",
            self.kind,
            self.parameter,
            self.arclength,
            self.dparameter,
            self.determinant_sign,
            self.newton_iterations
        )
    }
}

/// Why a run ended.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Termination {
    /// The step limit was reached.
    MaxSteps(usize),
    /// λ reached a requested stop value (the last point is located there).
    ParameterValue(f64),
    /// A user event (by index) crossed zero (the last point is located there).
    Event(usize),
    /// The corrector failed at the minimum step.
    NewtonFailed {
        /// The step size at failure.
        ds: f64,
        /// The last error.
        reason: Error,
    },
    /// The linearised system was exactly singular at the minimum step.
    Singular(Error),
    /// The problem returned NaN or ∞ at the minimum step.
    NonFinite(Error),
    /// The tangent kept turning by more than the maximum angle at the
    /// minimum step.
    AngleTooLarge {
        /// The step size at failure.
        ds: f64,
        /// The angle between successive tangents, radians.
        angle: f64,
    },
    /// The observer asked to stop.
    Stopped,
}

impl fmt::Display for Termination {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Termination::MaxSteps(n) => write!(f, "reached the step limit ({n} steps)"),
            Termination::ParameterValue(v) => write!(f, "reached the parameter value {v}"),
            Termination::Event(i) => write!(f, "user event {i} crossed zero"),
            Termination::NewtonFailed { ds, reason } => {
                write!(
                    f,
                    "the corrector failed at the minimum step {ds:e}: {reason}"
                )
            }
            Termination::Singular(e) => write!(f, "singular system at the minimum step: {e}"),
            Termination::NonFinite(e) => write!(f, "non-finite values at the minimum step: {e}"),
            Termination::AngleTooLarge { ds, angle } => write!(
                f,
                "the tangent turned by {angle:.3} rad even at the minimum step {ds:e}"
            ),
            Termination::Stopped => f.write_str("stopped by the observer"),
        }
    }
}

/// Direction of a bifurcating branch relative to the second null vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// Along +φ.
    Positive,
    /// Along −φ.
    Negative,
}

/// Hooks called by [`Continuation::run`]; every hook is defaulted and
/// returns [`ControlFlow`] (`Break` stops the run with
/// [`Termination::Stopped`], keeping the points so far). Implemented for
/// `()` and for closures `FnMut(&Point) -> ControlFlow<()>`.
pub trait Observer {
    /// Called for every point, in order (special points included).
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        let _ = point;
        ControlFlow::Continue(())
    }

    /// Called when a step is rejected and retried with `new_ds`.
    fn step_rejected(&mut self, new_ds: f64) -> ControlFlow<()> {
        let _ = new_ds;
        ControlFlow::Continue(())
    }
}

impl Observer for () {}

impl<F: FnMut(&Point) -> ControlFlow<()>> Observer for F {
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        self(point)
    }
}

/// A user event: stop where `f(solution) = 0`.
type EventFn = Arc<dyn Fn(&Solution) -> f64 + Send + Sync>;

/// The result of a run: every point in order and why it ended.
#[derive(Debug, Clone)]
pub struct Branch {
    points: Vec<Point>,
    termination: Termination,
}

impl Branch {
    /// Every point, in order.
    #[must_use]
    pub fn points(&self) -> &[Point] {
        &self.points
    }

    /// Why the run ended.
    #[must_use]
    pub fn termination(&self) -> &Termination {
        &self.termination
    }

    /// The located special points, in order.
    pub fn special_points(&self) -> impl Iterator<Item = &Point> {
        self.points.iter().filter(|p| p.is_special())
    }

    /// The located folds.
    pub fn folds(&self) -> impl Iterator<Item = &Point> {
        self.points.iter().filter(|p| p.kind == PointKind::Fold)
    }

    /// The located branch points.
    pub fn branch_points(&self) -> impl Iterator<Item = &Point> {
        self.points
            .iter()
            .filter(|p| p.kind == PointKind::BranchPoint)
    }

    /// The last point.
    #[must_use]
    pub fn last(&self) -> Option<&Point> {
        self.points.last()
    }
}

impl fmt::Display for Branch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "branch of {} points; {}",
            self.points.len(),
            self.termination
        )?;
        for p in self.special_points() {
            writeln!(f, "  {p}")?;
        }
        Ok(())
    }
}

/// Pseudo-arclength continuation settings (the builder).
///
/// ```
/// use hockle::bvp::{Collocation, Problem};
/// use hockle::continuation::{Continuation, PointKind};
/// // Bratu: y'' + λ e^y = 0, y(0) = y(1) = 0, fold at λ* = 3.513830719125…
/// struct Bratu;
/// impl Problem for Bratu {
///     fn dim(&self) -> usize { 2 }
///     fn parameter_count(&self) -> usize { 1 }
///     fn boundary_count(&self) -> usize { 2 }
///     fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
///         f[0] = y[1];
///         f[1] = -p[0] * y[0].exp();
///     }
///     fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
///         g[0] = y0[0];
///         g[1] = y1[0];
///     }
/// }
/// let start = Collocation::new().intervals(10).solve(&Bratu, |_s: f64| [0.0, 0.0], &[0.0])?;
/// // Around the fold, stopping on the upper branch where y'(0) = 10.
/// let branch = Continuation::new(0)
///     .step(0.1)
///     .stop_when(|sol| sol.at_mesh(0)[1] - 10.0)
///     .run(&Bratu, &start, ())?;
/// let fold = branch.folds().next().expect("a fold");
/// assert!((fold.parameter() - 3.513830719125162).abs() < 1e-8);
/// assert_eq!(branch.last().unwrap().kind(), PointKind::Event(0));
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Clone)]
pub struct Continuation {
    parameter: usize,
    solver: Collocation,
    ds: f64,
    ds_min: f64,
    ds_max: f64,
    max_steps: usize,
    max_newton: u32,
    weights: Option<Vec<f64>>,
    parameter_weight: f64,
    max_angle: f64,
    folds: bool,
    branch_points: bool,
    locate_tolerance: f64,
    stops: Vec<f64>,
    events: Vec<EventFn>,
}

impl fmt::Debug for Continuation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Continuation")
            .field("parameter", &self.parameter)
            .field("solver", &self.solver)
            .field("ds", &self.ds)
            .field("ds_min", &self.ds_min)
            .field("ds_max", &self.ds_max)
            .field("max_steps", &self.max_steps)
            .field("stops", &self.stops)
            .field("events", &self.events.len())
            .finish_non_exhaustive()
    }
}

impl fmt::Display for Continuation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "pseudo-arclength continuation in p[{}]: ds = {}, |ds| ∈ [{:e}, {}], {} steps max; {}",
            self.parameter, self.ds, self.ds_min, self.ds_max, self.max_steps, self.solver
        )
    }
}

impl Continuation {
    /// Continuation in the parameter with index `parameter` (into p), with
    /// the defaults:
    ///
    /// | setting | default |
    /// |---|---|
    /// | [`solver`](Self::solver) | [`Collocation::new()`] (its free parameters stay free; its mesh is the start solution's) |
    /// | [`step`](Self::step) Δs | 0.01 (its sign picks the initial direction of λ) |
    /// | [`step_bounds`](Self::step_bounds) | Δs_min = 1e-8, Δs_max = 0.5 |
    /// | [`max_steps`](Self::max_steps) | 200 |
    /// | [`max_newton`](Self::max_newton) | 10 corrector iterations |
    /// | [`weights`](Self::weights) | 1 for every variable |
    /// | [`parameter_weight`](Self::parameter_weight) θ | 1 |
    /// | [`max_angle`](Self::max_angle) | 0.35 rad between successive tangents |
    /// | [`detect_folds`](Self::detect_folds), [`detect_branch_points`](Self::detect_branch_points) | on |
    /// | [`locate_tolerance`](Self::locate_tolerance) | 1e-10 in arclength |
    /// | stops and events | none |
    #[must_use]
    pub fn new(parameter: usize) -> Self {
        Continuation {
            parameter,
            solver: Collocation::new(),
            ds: 0.01,
            ds_min: 1e-8,
            ds_max: 0.5,
            max_steps: 200,
            max_newton: 10,
            weights: None,
            parameter_weight: 1.0,
            max_angle: 0.35,
            folds: true,
            branch_points: true,
            locate_tolerance: 1e-10,
            stops: Vec::new(),
            events: Vec::new(),
        }
    }

    /// The collocation settings (m, Newton tolerance, free parameters).
    #[must_use]
    pub fn solver(mut self, solver: Collocation) -> Self {
        self.solver = solver;
        self
    }

    /// The initial step Δs; negative to start with decreasing λ.
    #[must_use]
    pub fn step(mut self, ds: f64) -> Self {
        self.ds = ds;
        self
    }

    /// Bounds of |Δs|.
    #[must_use]
    pub fn step_bounds(mut self, ds_min: f64, ds_max: f64) -> Self {
        self.ds_min = ds_min;
        self.ds_max = ds_max;
        self
    }

    /// The maximum number of accepted steps.
    #[must_use]
    pub fn max_steps(mut self, n: usize) -> Self {
        self.max_steps = n;
        self
    }

    /// The corrector's Newton iteration limit (also the scale of the step
    /// control).
    #[must_use]
    pub fn max_newton(mut self, n: u32) -> Self {
        self.max_newton = n;
        self
    }

    /// Per-variable weights w_i of the integral norm (length n).
    #[must_use]
    pub fn weights(mut self, w: &[f64]) -> Self {
        self.weights = Some(w.to_vec());
        self
    }

    /// The weight θ of the parameters in the norm.
    #[must_use]
    pub fn parameter_weight(mut self, theta: f64) -> Self {
        self.parameter_weight = theta;
        self
    }

    /// The largest accepted angle (radians) between successive tangents.
    #[must_use]
    pub fn max_angle(mut self, angle: f64) -> Self {
        self.max_angle = angle;
        self
    }

    /// Detect and locate folds.
    #[must_use]
    pub fn detect_folds(mut self, on: bool) -> Self {
        self.folds = on;
        self
    }

    /// Detect and locate branch points.
    #[must_use]
    pub fn detect_branch_points(mut self, on: bool) -> Self {
        self.branch_points = on;
        self
    }

    /// The arclength tolerance of special-point location.
    #[must_use]
    pub fn locate_tolerance(mut self, tol: f64) -> Self {
        self.locate_tolerance = tol;
        self
    }

    /// Stop where λ reaches `value` (located exactly; may be repeated).
    #[must_use]
    pub fn stop_at(mut self, value: f64) -> Self {
        self.stops.push(value);
        self
    }

    /// Stop where `event(solution)` crosses zero (an output functional
    /// minus its target value), located exactly. Events are numbered in the
    /// order they are added.
    #[must_use]
    pub fn stop_when(mut self, event: impl Fn(&Solution) -> f64 + Send + Sync + 'static) -> Self {
        self.events.push(Arc::new(event));
        self
    }

    fn validate(&self, n: usize, np: usize) -> Result<()> {
        if self.parameter >= np {
            return Err(Error::InvalidCount {
                name: "continuation parameter",
                value: self.parameter as u64,
                allowed: "an index below the problem's parameter_count()",
            });
        }
        if !(self.ds.is_finite() && self.ds != 0.0) {
            return Err(Error::InvalidArgument {
                name: "ds",
                value: self.ds,
                allowed: "finite and non-zero",
            });
        }
        if !(self.ds_min > 0.0 && self.ds_min <= self.ds_max && self.ds_max.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "ds_min",
                value: self.ds_min,
                allowed: "0 < ds_min ≤ ds_max < ∞",
            });
        }
        if let Some(w) = &self.weights {
            if w.len() != n {
                return Err(Error::LengthMismatch {
                    name: "weights",
                    found: w.len() as u64,
                    expected: n as u64,
                });
            }
            if let Some(bad) = w.iter().find(|v| !(**v >= 0.0 && v.is_finite())) {
                return Err(Error::InvalidArgument {
                    name: "weight",
                    value: *bad,
                    allowed: "finite and ≥ 0",
                });
            }
        }
        if !(self.parameter_weight > 0.0 && self.parameter_weight.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "parameter_weight",
                value: self.parameter_weight,
                allowed: "finite and > 0",
            });
        }
        if !(self.max_angle > 0.0 && self.max_angle <= std::f64::consts::PI) {
            return Err(Error::InvalidArgument {
                name: "max_angle",
                value: self.max_angle,
                allowed: "0 < angle ≤ π",
            });
        }
        if self.max_newton == 0 {
            return Err(Error::InvalidCount {
                name: "max_newton",
                value: 0,
                allowed: "at least 1",
            });
        }
        Ok(())
    }

    /// The distance ‖a − b‖ of two solutions in this continuation's norm
    /// (module docs: weights w_i, θ on the solver's free parameters and λ),
    /// integrals by the Gauss rule of the solver, so that it measures
    /// arclength the way [`Point::arclength`] does (e.g. to join a point
    /// computed before the run to the branch).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] or [`Error::InvalidCount`] unless both
    /// solutions have the dimension of the weights, the solver's points per
    /// interval, and the same mesh; bad settings as [`Continuation::trace`].
    pub fn distance(&self, a: &Solution, b: &Solution) -> Result<f64> {
        let n = a.dim();
        self.validate(n, a.parameters().len())?;
        let tab = self.solver.validate()?;
        if b.dim() != n || b.parameters().len() != a.parameters().len() {
            return Err(Error::LengthMismatch {
                name: "solution dimension",
                found: b.dim() as u64,
                expected: n as u64,
            });
        }
        for s in [a, b] {
            if s.points_per_interval() != tab.m || s.mesh() != a.mesh() {
                return Err(Error::InvalidCount {
                    name: "points per interval",
                    value: s.points_per_interval() as u64,
                    allowed: "the solver's m, on the same mesh for both solutions",
                });
            }
        }
        let (ya, yb) = (a.collocation_values(), b.collocation_values());
        let mesh = a.mesh();
        let mut sum = 0.0;
        for j in 0..mesh.intervals() {
            let h = mesh.width(j);
            for (k, bk) in tab.b.iter().enumerate() {
                for i in 0..n {
                    let w = self.weights.as_ref().map_or(1.0, |w| w[i]);
                    sum += h * bk * w * (ya[(i, j * tab.m + k)] - yb[(i, j * tab.m + k)]).powi(2);
                }
            }
        }
        for &q in self.solver.free().iter().chain([&self.parameter]) {
            sum += self.parameter_weight * (a.parameters()[q] - b.parameters()[q]).powi(2);
        }
        Ok(sum.sqrt())
    }

    /// A step-by-step iterator over the branch through `start` (a solution
    /// of the problem at its parameter values). The first item is the start
    /// point.
    ///
    /// # Errors
    /// Bad settings ([`Error::InvalidArgument`], [`Error::InvalidCount`],
    /// [`Error::LengthMismatch`]), [`Error::IllPosed`] if the counts do not
    /// match with λ free, or an error of the first tangent computation.
    pub fn trace<'a, P: Problem + ?Sized>(
        &'a self,
        problem: &'a P,
        start: &Solution,
    ) -> Result<Trace<'a, P>> {
        Trace::new(self, problem, start, None)
    }

    /// Runs to termination, calling `observer` at every point, and returns
    /// every point with the reason the run ended.
    ///
    /// # Errors
    /// As [`Continuation::trace`]; failures after the start end the run with
    /// a [`Termination`] instead.
    pub fn run<P: Problem + ?Sized, O: Observer>(
        &self,
        problem: &P,
        start: &Solution,
        observer: O,
    ) -> Result<Branch> {
        let trace = self.trace(problem, start)?;
        Ok(drive(trace, observer))
    }

    /// Starts the bifurcating branch at a located branch point `bp` along
    /// ±φ, φ the second null vector, and runs it like [`Continuation::run`].
    ///
    /// # Errors
    /// [`Error::NotABranchPoint`] unless `bp` is a located branch point of a
    /// run with the same problem; otherwise as [`Continuation::trace`].
    pub fn run_from_branch_point<P: Problem + ?Sized, O: Observer>(
        &self,
        problem: &P,
        bp: &Point,
        direction: Direction,
        observer: O,
    ) -> Result<Branch> {
        let trace = self.switch_branch(problem, bp, direction)?;
        Ok(drive(trace, observer))
    }

    /// The iterator form of [`Continuation::run_from_branch_point`].
    ///
    /// # Errors
    /// As [`Continuation::run_from_branch_point`].
    pub fn switch_branch<'a, P: Problem + ?Sized>(
        &'a self,
        problem: &'a P,
        bp: &Point,
        direction: Direction,
    ) -> Result<Trace<'a, P>> {
        let Some(tangent) = bp
            .tangent
            .as_ref()
            .filter(|_| bp.kind == PointKind::BranchPoint)
        else {
            return Err(Error::NotABranchPoint {
                arclength: bp.arclength,
                kind: bp.kind.name(),
            });
        };
        Trace::new(
            self,
            problem,
            &bp.solution,
            Some((tangent.clone(), direction, bp.arclength)),
        )
    }
}

fn drive<P: Problem + ?Sized, O: Observer>(mut trace: Trace<'_, P>, mut observer: O) -> Branch {
    let mut points = Vec::new();
    let mut stopped = false;
    while let Some(p) = trace.next() {
        for ds in trace.rejections.drain(..) {
            if observer.step_rejected(ds).is_break() {
                stopped = true;
            }
        }
        let flow = observer.point(&p);
        points.push(p);
        if stopped || flow.is_break() {
            stopped = true;
            break;
        }
    }
    if !stopped {
        for ds in trace.rejections.drain(..) {
            if observer.step_rejected(ds).is_break() {
                break;
            }
        }
    }
    let termination = if stopped {
        Termination::Stopped
    } else {
        trace
            .termination
            .take()
            .unwrap_or(Termination::MaxSteps(trace.steps))
    };
    Branch {
        points,
        termination,
    }
}

/// What the location iteration is tracking.
#[derive(Clone, Copy, PartialEq)]
enum Watch {
    Fold,
    BranchPoint,
    Stop(usize),
    Event(usize),
}

/// A corrected point with its tangent and determinant (internal).
struct Corrected {
    x: State,
    tangent: State,
    det: Det,
    iterations: u32,
}

/// The step-by-step continuation iterator (see [`Continuation::trace`]).
/// After it returns `None`, [`Trace::termination`] says why.
pub struct Trace<'a, P: Problem + ?Sized> {
    cont: &'a Continuation,
    sys: System<'a, P>,
    mesh: crate::bvp::Mesh,
    opts: NewtonOptions,
    weights: Vec<f64>,
    x0: State,
    t0: State,
    det0: Det,
    ds: f64,
    arclength: f64,
    steps: usize,
    factored_at_x0: bool,
    skip_detection: bool,
    pending: VecDeque<Point>,
    termination: Option<Termination>,
    rejections: Vec<f64>,
    rejected: usize,
    newton_iterations: u64,
    ycol_a: Vec<f64>,
    ycol_b: Vec<f64>,
}

impl<P: Problem + ?Sized> fmt::Debug for Trace<'_, P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Trace")
            .field("steps", &self.steps)
            .field("ds", &self.ds)
            .field("arclength", &self.arclength)
            .field("termination", &self.termination)
            .finish_non_exhaustive()
    }
}

impl<'a, P: Problem + ?Sized> Trace<'a, P> {
    fn new(
        cont: &'a Continuation,
        problem: &'a P,
        start: &Solution,
        switch: Option<(State, Direction, f64)>,
    ) -> Result<Self> {
        let n = problem.dim();
        let np = problem.parameter_count();
        cont.validate(n, np)?;
        let tab = cont.solver.validate()?;
        if start.dim() != n || start.parameters().len() != np {
            return Err(Error::LengthMismatch {
                name: "start solution dimension",
                found: start.dim() as u64,
                expected: n as u64,
            });
        }
        if start.points_per_interval() != tab.m {
            return Err(Error::InvalidCount {
                name: "start solution points per interval",
                value: start.points_per_interval() as u64,
                allowed: "the solver's m (solve the start with the same Collocation)",
            });
        }
        let mut free: Vec<usize> = cont.solver.free().to_vec();
        if free.contains(&cont.parameter) {
            return Err(Error::InvalidCount {
                name: "continuation parameter",
                value: cont.parameter as u64,
                allowed: "a parameter that is not already one of the solver's free parameters",
            });
        }
        free.push(cont.parameter);
        let mesh = start.mesh().clone();
        let mut sys = System::new(problem, mesh.points().to_vec(), tab, free, 1)?;
        sys.linear = cont.solver.linear();
        let weights = cont.weights.clone().unwrap_or_else(|| vec![1.0; n]);
        let x0 = State {
            y: start.y.clone(),
            k: start.k.clone(),
            p: start.p.clone(),
        };
        let len = sys.y_ref.len();
        let mut trace = Trace {
            cont,
            sys,
            mesh,
            opts: NewtonOptions {
                tol: cont.solver.newton_options().tol,
                max_iter: cont.max_newton,
            },
            weights,
            x0,
            t0: State {
                y: Vec::new(),
                k: Vec::new(),
                p: Vec::new(),
            },
            det0: Det::ONE,
            ds: cont.ds.abs().clamp(cont.ds_min, cont.ds_max),
            arclength: 0.0,
            steps: 0,
            factored_at_x0: false,
            skip_detection: false,
            pending: VecDeque::new(),
            termination: None,
            rejections: Vec::new(),
            rejected: 0,
            newton_iterations: 0,
            ycol_a: vec![0.0; len],
            ycol_b: vec![0.0; len],
        };
        let mut y_ref = std::mem::take(&mut trace.sys.y_ref);
        trace.sys.collocation_values(&trace.x0, &mut y_ref);
        trace.sys.y_ref = y_ref;
        match switch {
            None => {
                // Tangent from [F_x; e_λᵀ] τ = e, oriented by the sign of ds.
                trace.set_parameter_border();
                let x0 = trace.x0.clone();
                trace.sys.factor(&x0)?;
                let mut t = trace.solve_border_rhs()?;
                let nrm = trace.norm(&t);
                let sgn = if cont.ds < 0.0 { -1.0 } else { 1.0 };
                t.scale(sgn / nrm);
                trace.t0 = t;
                trace.set_tangent_border(0.0);
                trace.det0 = trace.sys.factor_border()?;
                trace.factored_at_x0 = true;
            }
            Some((tangent, direction, arclength)) => {
                trace.arclength = arclength;
                let x0 = trace.x0.clone();
                trace.t0 = tangent;
                trace.set_tangent_border(0.0);
                if let Err(e) = trace.sys.factor(&x0) {
                    // Exactly singular at the located point: the null
                    // vector of a neighbour 1e-7 along the branch is as good.
                    if !matches!(e, Error::SingularJacobian { .. }) {
                        return Err(e);
                    }
                    let mut shifted = x0.clone();
                    let t0 = trace.t0.clone();
                    shifted.axpy(1e-7, &t0, &trace.sys.free.clone());
                    trace.sys.factor(&shifted)?;
                }
                // One solve with the nearly singular matrix gives its null
                // vector; remove the τ component.
                let mut r = trace.sys.zero_residual();
                let mut seed = 0x2545_f491_4f6c_dd1d_u64;
                let mut next = || {
                    seed ^= seed << 13;
                    seed ^= seed >> 7;
                    seed ^= seed << 17;
                    (seed >> 11) as f64 / (1u64 << 53) as f64 + 0.5
                };
                for v in r
                    .stage
                    .iter_mut()
                    .chain(r.cont.iter_mut())
                    .chain(r.bc.iter_mut())
                    .chain(r.dense.iter_mut())
                {
                    *v = next();
                }
                let mut phi = trace.sys.zero_state();
                trace.sys.solve(&r, &mut phi)?;
                let a = trace.inner(&phi, &trace.t0.clone())
                    / trace.inner(&trace.t0.clone(), &trace.t0.clone());
                let t0 = trace.t0.clone();
                phi.axpy(-a, &t0, &trace.sys.free.clone());
                let nrm = trace.norm(&phi);
                let sgn = if direction == Direction::Positive {
                    1.0
                } else {
                    -1.0
                };
                phi.scale(sgn / nrm);
                trace.t0 = phi;
                trace.set_tangent_border(0.0);
                // [F_x; φᵀ] is singular at the branch point itself (τ is its
                // null vector): the first corrector factorises afresh, and
                // detection restarts after the first step.
                trace.factored_at_x0 = false;
                trace.skip_detection = true;
            }
        }
        let sol = trace.solution(&trace.x0.clone(), Default::default())?;
        let first = trace.point(
            sol,
            &trace.x0.clone(),
            &trace.t0.clone(),
            trace.det0,
            PointKind::Start,
            0,
        );
        trace.pending.push_back(first);
        Ok(trace)
    }

    /// Why the run ended, once the iterator is exhausted.
    #[must_use]
    pub fn termination(&self) -> Option<&Termination> {
        self.termination.as_ref()
    }

    /// The current step size |Δs|.
    #[must_use]
    pub fn step_size(&self) -> f64 {
        self.ds
    }

    /// Accepted steps so far.
    #[must_use]
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Rejected (halved and retried) steps so far.
    #[must_use]
    pub fn rejected(&self) -> usize {
        self.rejected
    }

    /// Corrector iterations so far: accepted, rejected and special-point
    /// location correctors alike (failed correctors are not counted).
    #[must_use]
    pub fn newton_iterations(&self) -> u64 {
        self.newton_iterations
    }

    fn inner(&mut self, a: &State, b: &State) -> f64 {
        let (n, m) = (self.sys.n, self.sys.m);
        self.sys.collocation_values(a, &mut self.ycol_a);
        self.sys.collocation_values(b, &mut self.ycol_b);
        let mut s = 0.0;
        for j in 0..self.sys.nn {
            let h = self.sys.h(j);
            for k in 0..m {
                let w = h * self.sys.tab.b[k];
                let o = (j * m + k) * n;
                for i in 0..n {
                    s += w * self.weights[i] * self.ycol_a[o + i] * self.ycol_b[o + i];
                }
            }
        }
        for &q in &self.sys.free {
            s += self.cont.parameter_weight * a.p[q] * b.p[q];
        }
        s
    }

    fn norm(&mut self, a: &State) -> f64 {
        self.inner(a, a).sqrt()
    }

    /// Border row e_λᵀ (target irrelevant: only used for the first tangent).
    fn set_parameter_border(&mut self) {
        let b = &mut self.sys.border;
        b.coef_y.fill(0.0);
        b.coef_q.fill(0.0);
        let nq = b.coef_q.len();
        b.coef_q[nq - 1] = 1.0;
        b.target[0] = 0.0;
    }

    /// Border row ⟨· − x₀, τ₀⟩ = ds.
    fn set_tangent_border(&mut self, ds: f64) {
        let (n, m) = (self.sys.n, self.sys.m);
        self.sys.collocation_values(&self.t0, &mut self.ycol_a);
        self.sys.collocation_values(&self.x0, &mut self.ycol_b);
        let mut target = ds;
        for j in 0..self.sys.nn {
            let h = self.sys.h(j);
            for k in 0..m {
                let w = h * self.sys.tab.b[k];
                let o = (j * m + k) * n;
                for i in 0..n {
                    let c = w * self.weights[i] * self.ycol_a[o + i];
                    self.sys.border.coef_y[o + i] = c;
                    target += c * self.ycol_b[o + i];
                }
            }
        }
        for (qi, &q) in self.sys.free.iter().enumerate() {
            let c = self.cont.parameter_weight * self.t0.p[q];
            self.sys.border.coef_q[qi] = c;
            target += c * self.x0.p[q];
        }
        self.sys.border.target[0] = target;
    }

    /// Solves J τ = e_border with the current factorisation.
    fn solve_border_rhs(&mut self) -> Result<State> {
        let mut r = self.sys.zero_residual();
        let nd = r.dense.len();
        r.dense[nd - 1] = -1.0;
        let mut t = self.sys.zero_state();
        self.sys.solve(&r, &mut t)?;
        Ok(t)
    }

    fn solution(&mut self, x: &State, stats: crate::bvp::NewtonStats) -> Result<Solution> {
        finish(&mut self.sys, x.clone(), self.mesh.clone(), stats)
    }

    fn point(
        &self,
        solution: Solution,
        x: &State,
        t: &State,
        det: Det,
        kind: PointKind,
        iterations: u32,
    ) -> Point {
        let q = self.cont.parameter;
        Point {
            solution,
            parameter: x.p[q],
            arclength: self.arclength,
            newton_iterations: iterations,
            dparameter: t.p[q],
            determinant_sign: det.sign,
            kind,
            tangent: (kind == PointKind::BranchPoint).then(|| t.clone()),
        }
    }

    /// Corrects from x₀ at arclength `ds` along τ₀; factorises at the
    /// result and computes its tangent and determinant.
    fn correct(&mut self, ds: f64, reuse: bool) -> Result<Corrected> {
        self.set_tangent_border(ds);
        let mut x = self.x0.clone();
        let t0 = self.t0.clone();
        x.axpy(ds, &t0, &self.sys.free.clone());
        if reuse {
            self.sys.factor_border()?;
        }
        let stats = newton(&mut self.sys, &mut x, self.opts, reuse)?;
        self.newton_iterations += u64::from(stats.iterations);
        // Without branch-point detection the determinant is not needed: when
        // the chord corrector converged fast on the old factorisation, keep
        // it and refine the tangent on it instead of factorising again.
        if !self.cont.branch_points
            && reuse
            && stats.jacobians == 0
            && stats.iterations <= 4
            && let Some(mut t) = self.refined_tangent(&x)
        {
            let nrm = self.norm(&t);
            t.scale(1.0 / nrm);
            return Ok(Corrected {
                x,
                tangent: t,
                det: Det {
                    sign: f64::NAN,
                    log_abs: f64::NAN,
                },
                iterations: stats.iterations,
            });
        }
        let det = self.sys.factor(&x)?;
        let mut t = self.solve_border_rhs()?;
        let nrm = self.norm(&t);
        t.scale(1.0 / nrm);
        Ok(Corrected {
            x,
            tangent: t,
            det,
            iterations: stats.iterations,
        })
    }

    /// The tangent at `x` without a new factorisation: iterative
    /// refinement of [F_x(x); τ₀ᵀ] τ = e preconditioned by the current
    /// (chord) factorisation, with F_x(x)τ by central differences of the
    /// residual (step 1e-6 relative: error ~1e-12). `None` when it does not
    /// contract.
    fn refined_tangent(&mut self, x: &State) -> Option<State> {
        let free = self.sys.free.clone();
        let mut t = self.t0.clone();
        let mut rp = self.sys.zero_residual();
        let mut rm = self.sys.zero_residual();
        let mut d = self.sys.zero_state();
        let mut xp = x.clone();
        let mut xm = x.clone();
        let xn = x.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let mut prev = f64::INFINITY;
        for _ in 0..8 {
            let tn = t.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            let tn = free.iter().fold(tn, |a, &q| a.max(t.p[q].abs()));
            let eps = 1e-6 * (1.0 + xn) / tn.max(1e-300);
            xp.clone_from(x);
            xp.axpy(eps, &t, &free);
            xm.clone_from(x);
            xm.axpy(-eps, &t, &free);
            self.sys.residual(&xp, &mut rp).ok()?;
            self.sys.residual(&xm, &mut rm).ok()?;
            let inv = 0.5 / eps;
            for (a, b) in rp
                .stage
                .iter_mut()
                .chain(rp.cont.iter_mut())
                .chain(rp.bc.iter_mut())
                .chain(rp.dense.iter_mut())
                .zip(
                    rm.stage
                        .iter()
                        .chain(&rm.cont)
                        .chain(&rm.bc)
                        .chain(&rm.dense),
                )
            {
                *a = (*a - b) * inv;
            }
            let last = rp.dense.len() - 1;
            rp.dense[last] -= 1.0;
            self.sys.solve(&rp, &mut d).ok()?;
            t.axpy(1.0, &d, &free);
            let nd = scaled_norm(&d, &t, &free);
            if nd <= 1e-10 {
                return Some(t);
            }
            if nd > 0.25 * prev {
                return None;
            }
            prev = nd;
        }
        None
    }

    fn watch_value(&self, w: Watch, c: &Corrected, log_ref: f64) -> f64 {
        let q = self.cont.parameter;
        match w {
            Watch::Fold => c.tangent.p[q],
            Watch::BranchPoint => c.det.sign * (c.det.log_abs - log_ref).exp(),
            Watch::Stop(i) => c.x.p[q] - self.cont.stops[i],
            Watch::Event(_) => f64::NAN,
        }
    }

    fn event_value(&mut self, i: usize, x: &State) -> Result<f64> {
        let sol = self.solution(x, Default::default())?;
        Ok((self.cont.events[i])(&sol))
    }

    /// Illinois iteration for the zero of a watched function on [0, ds].
    fn locate(
        &mut self,
        w: Watch,
        f0: f64,
        f1: f64,
        ds: f64,
        log_ref: f64,
    ) -> Result<(Corrected, f64)> {
        let (mut a, mut fa, mut b, mut fb) = (0.0, f0, ds, f1);
        let mut best: Option<(Corrected, f64)> = None;
        let mut prev = f64::NAN;
        for _ in 0..60 {
            let mut s = (a * fb - b * fa) / (fb - fa);
            if !s.is_finite() || s <= a.min(b) || s >= a.max(b) {
                s = 0.5 * (a + b);
            }
            let c = match self.correct(s, false) {
                Err(Error::SingularJacobian { .. }) => {
                    // Landed exactly on the singular point: step off it by
                    // a fraction of the tolerance.
                    let nudge = 0.5 * self.cont.locate_tolerance * (b - a).signum();
                    self.correct(s + nudge, false)?
                }
                r => r?,
            };
            let fs = match w {
                Watch::Event(i) => self.event_value(i, &c.x)?,
                _ => self.watch_value(w, &c, log_ref),
            };
            let done = (s - prev).abs() <= self.cont.locate_tolerance || fs == 0.0;
            prev = s;
            best = Some((c, s));
            if done || (b - a).abs() <= self.cont.locate_tolerance {
                break;
            }
            if fs * fb < 0.0 {
                a = b;
                fa = fb;
            } else {
                fa *= 0.5;
            }
            b = s;
            fb = fs;
        }
        best.ok_or(Error::NewtonNotConverged {
            iterations: 0,
            correction: f64::NAN,
            tolerance: self.cont.locate_tolerance,
        })
    }

    fn fail(&mut self, e: Error) {
        self.termination = Some(match e {
            Error::NonFinite { .. } => Termination::NonFinite(e),
            Error::SingularJacobian { .. } => Termination::Singular(e),
            _ => Termination::NewtonFailed {
                ds: self.ds,
                reason: e,
            },
        });
    }

    /// One accepted step (plus any located special points) into `pending`.
    fn advance(&mut self) {
        if self.steps >= self.cont.max_steps {
            self.termination = Some(Termination::MaxSteps(self.steps));
            return;
        }
        let c = loop {
            let reuse = self.factored_at_x0;
            let res = self.correct(self.ds, reuse);
            match res {
                Ok(c) => {
                    let cosang = self.inner(&c.tangent, &self.t0.clone());
                    let angle = cosang.clamp(-1.0, 1.0).acos();
                    if angle <= self.cont.max_angle {
                        break c;
                    }
                    if self.ds <= self.cont.ds_min {
                        self.termination = Some(Termination::AngleTooLarge { ds: self.ds, angle });
                        return;
                    }
                }
                Err(e) => {
                    if self.ds <= self.cont.ds_min {
                        self.fail(e);
                        return;
                    }
                }
            }
            self.factored_at_x0 = false;
            self.ds = (0.5 * self.ds).max(self.cont.ds_min);
            self.rejected += 1;
            self.rejections.push(self.ds);
        };
        self.steps += 1;
        let q = self.cont.parameter;
        let ds = self.ds;
        // Special points inside the step, by arclength.
        let mut found: Vec<(Corrected, f64, PointKind, bool)> = Vec::new();
        let mut err: Option<Error> = None;
        let log_ref = self.det0.log_abs;
        let mut watches: Vec<(Watch, f64, f64)> = Vec::new();
        if !self.skip_detection {
            if self.cont.folds && self.t0.p[q] * c.tangent.p[q] < 0.0 {
                watches.push((Watch::Fold, self.t0.p[q], c.tangent.p[q]));
            }
            // (A NaN sign means the sparse fallback factorised: no test.)
            if self.cont.branch_points && self.det0.sign * c.det.sign < 0.0 {
                let f1 = c.det.sign * (c.det.log_abs - log_ref).exp();
                watches.push((Watch::BranchPoint, self.det0.sign, f1));
            }
        }
        for (i, v) in self.cont.stops.iter().enumerate() {
            let (f0, f1) = (self.x0.p[q] - v, c.x.p[q] - v);
            if f0 != 0.0 && f0 * f1 <= 0.0 {
                watches.push((Watch::Stop(i), f0, f1));
            }
        }
        for i in 0..self.cont.events.len() {
            let x0 = self.x0.clone();
            let f0 = self.event_value(i, &x0);
            let f1 = self.event_value(i, &c.x);
            match (f0, f1) {
                (Ok(f0), Ok(f1)) if f0 != 0.0 && f0 * f1 <= 0.0 => {
                    watches.push((Watch::Event(i), f0, f1))
                }
                (Err(e), _) | (_, Err(e)) => err = Some(e),
                _ => {}
            }
        }
        for (w, f0, f1) in watches {
            let kind = match w {
                Watch::Fold => PointKind::Fold,
                Watch::BranchPoint => PointKind::BranchPoint,
                Watch::Stop(_) => PointKind::ParameterValue,
                Watch::Event(i) => PointKind::Event(i),
            };
            let stop = matches!(w, Watch::Stop(_) | Watch::Event(_));
            match self.locate(w, f0, f1, ds, log_ref) {
                Ok((cs, s)) => found.push((cs, s, kind, stop)),
                Err(e) => {
                    err = Some(e);
                }
            }
        }
        // Whatever factorisation is current (at the new point, a located
        // point or an earlier chord point) preconditions the next corrector;
        // Newton refreshes it when the contraction degrades.
        self.factored_at_x0 = true;
        found.sort_by(|a, b| a.1.total_cmp(&b.1));
        let base = self.arclength;
        for (cs, s, kind, stop) in found {
            self.arclength = base + s;
            let sol = match self.solution(&cs.x, Default::default()) {
                Ok(s) => s,
                Err(e) => {
                    self.fail(e);
                    return;
                }
            };
            let p = self.point(sol, &cs.x, &cs.tangent, cs.det, kind, cs.iterations);
            self.pending.push_back(p);
            if stop {
                self.termination = Some(match kind {
                    PointKind::Event(i) => Termination::Event(i),
                    _ => Termination::ParameterValue(cs.x.p[q]),
                });
                return;
            }
        }
        if let Some(e) = err {
            self.fail(e);
            return;
        }
        self.arclength = base + ds;
        let sol = match self.solution(&c.x, Default::default()) {
            Ok(s) => s,
            Err(e) => {
                self.fail(e);
                return;
            }
        };
        let p = self.point(
            sol,
            &c.x,
            &c.tangent,
            c.det,
            PointKind::Regular,
            c.iterations,
        );
        self.pending.push_back(p);
        // Accept: the new point becomes x₀; its factorisation is current
        // unless location overwrote it.
        let its = c.iterations;
        self.x0 = c.x;
        self.t0 = c.tangent;
        self.det0 = c.det;
        self.skip_detection = false;
        let mut y_ref = std::mem::take(&mut self.sys.y_ref);
        self.sys.collocation_values(&self.x0, &mut y_ref);
        self.sys.y_ref = y_ref;
        let factor = match its {
            0..=4 => 2.0,
            5 => 1.5,
            6 => 1.1,
            _ => 0.5,
        };
        self.ds = (self.ds * factor).clamp(self.cont.ds_min, self.cont.ds_max);
    }
}

impl<P: Problem + ?Sized> Iterator for Trace<'_, P> {
    type Item = Point;

    fn next(&mut self) -> Option<Point> {
        loop {
            if let Some(p) = self.pending.pop_front() {
                return Some(p);
            }
            if self.termination.is_some() {
                return None;
            }
            self.advance();
        }
    }
}
