//! The settings of a run: the [`Continuation`] builder and its validation.

use std::fmt;
use std::sync::Arc;

use super::diagram::{Diagram, Output};
use crate::bvp::{Collocation, Solution};
use crate::error::{Error, Result};

/// A user event: stop where `f(solution) = 0`.
pub(super) type EventFn = Arc<dyn Fn(&Solution) -> f64 + Send + Sync>;

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
    pub(super) parameter: usize,
    pub(super) solver: Collocation,
    pub(super) ds: f64,
    pub(super) ds_min: f64,
    pub(super) ds_max: f64,
    pub(super) max_steps: usize,
    pub(super) max_newton: u32,
    pub(super) weights: Option<Vec<f64>>,
    pub(super) parameter_weight: f64,
    pub(super) max_angle: f64,
    pub(super) folds: bool,
    pub(super) branch_points: bool,
    pub(super) locate_tolerance: f64,
    pub(super) stops: Vec<f64>,
    pub(super) events: Vec<EventFn>,
    pub(super) tolerance: Option<f64>,
    pub(super) adapt_mesh: bool,
    pub(super) pin_slides: bool,
    pub(super) diagram: Diagram,
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
            .field("tolerance", &self.tolerance)
            .field("pin_slides", &self.pin_slides)
            .field("diagram", &self.diagram)
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
    /// the defaults below and the domain each setting must lie in.
    ///
    /// | setting | default | allowed (else the error names it) |
    /// |---|---|---|
    /// | `parameter` | (given) | below the problem's `parameter_count()`, not one of the solver's free parameters ([`Error::InvalidCount`]) |
    /// | [`solver`](Self::solver) | [`Collocation::new()`] (its free parameters stay free; its mesh is the start solution's) | as [`Collocation`]; `m` equal to the start solution's |
    /// | [`step`](Self::step) Δs | 0.01 (its sign picks the initial direction of λ) | finite, ≠ 0; \|Δs\| is clamped into [Δs_min, Δs_max] |
    /// | [`step_bounds`](Self::step_bounds) | Δs_min = 1e-8, Δs_max = 0.5 | 0 < Δs_min ≤ Δs_max < ∞ |
    /// | [`max_steps`](Self::max_steps) | 200 | any (0: the start point only) |
    /// | [`max_newton`](Self::max_newton) | 10 corrector iterations | ≥ 1 |
    /// | [`weights`](Self::weights) | 1 for every variable | one per variable, finite, ≥ 0 ([`Error::LengthMismatch`] for the length) |
    /// | [`parameter_weight`](Self::parameter_weight) θ | 1 | finite, > 0 |
    /// | [`max_angle`](Self::max_angle) | 0.35 rad between successive tangents | 0 < angle ≤ π |
    /// | [`detect_folds`](Self::detect_folds), [`detect_branch_points`](Self::detect_branch_points) | on | |
    /// | [`locate_tolerance`](Self::locate_tolerance) | 1e-10 in arclength | finite, > 0 |
    /// | [`stop_at`](Self::stop_at) values | none | finite |
    /// | [`stop_when`](Self::stop_when) events | none | |
    /// | [`tolerance`](Self::tolerance) | none (fixed mesh, Newton and location tolerances as set) | 1e-12 ≤ tol ≤ 1 |
    /// | [`diagram`](Self::diagram) | ([`Output::Norm`], σ_λ = 1, σ_g = 1) | component or parameter in range; scales finite, > 0 |
    ///
    /// The setters never fail. [`run`](Self::run), [`steps`](Self::steps),
    /// [`run_from_branch_point`](Self::run_from_branch_point),
    /// [`switch_branch`](Self::switch_branch) and
    /// [`distance`](Self::distance) check every setting first and return
    /// [`Error::InvalidArgument`] (or the error named above) with the value
    /// given, before the problem is called once.
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
            tolerance: None,
            adapt_mesh: true,
            pin_slides: false,
            diagram: Diagram::default(),
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

    /// The arclength tolerance of special-point location (folds, branch
    /// points, stop values, events): the Illinois iteration stops when its
    /// arclength changes by less (finite, > 0).
    #[must_use]
    pub fn locate_tolerance(mut self, tol: f64) -> Self {
        self.locate_tolerance = tol;
        self
    }

    /// Stop where λ first reaches `value` (finite; may be repeated for
    /// several values, the first reached ends the run).
    ///
    /// The crossing is located like a fold, by arclength, and the located
    /// point is then corrected with λ fixed at `value`: the last point of
    /// the run has [`PointKind::ParameterValue`](super::PointKind) and
    /// λ = `value` exactly, and the run ends with
    /// [`Termination::ParameterValue`](super::Termination)`(value)`. A value
    /// reached twice inside one step (the step passes over a fold) is found
    /// on the first crossing. A value equal to λ at the start point is met
    /// only when the branch comes back to it.
    #[must_use]
    pub fn stop_at(mut self, value: f64) -> Self {
        self.stops.push(value);
        self
    }

    /// Stop where `event(solution)` crosses zero: an output functional of
    /// the solution minus its target value (e.g. an end displacement minus
    /// the extension wanted). Events are numbered from 0 in the order they
    /// are added; the first to cross ends the run with
    /// [`Termination::Event`](super::Termination)`(index)`, on a last point of
    /// kind [`PointKind::Event`](super::PointKind)`(index)` located by
    /// arclength to [`locate_tolerance`](Self::locate_tolerance) (the
    /// event's value there is that tolerance times its rate of change along
    /// the branch, or less). A crossing at the start point does not count.
    /// An event that returns NaN or ∞ at the start is an
    /// [`Error::NonFinite`]; later, it ends the run with
    /// [`Termination::Failed`](super::Termination).
    #[must_use]
    pub fn stop_when(mut self, event: impl Fn(&Solution) -> f64 + Send + Sync + 'static) -> Self {
        self.events.push(Arc::new(event));
        self
    }

    /// The accuracy wanted on the curve in the plane of the
    /// [`diagram`](Self::diagram): the max-norm distance between the computed
    /// branch (its points, its located folds and stops, and the quintic
    /// Hermite interpolant between points, [`Point::diagram`](super::Point::diagram),
    /// [`Point::diagram_slope`](super::Point::diagram_slope) and
    /// [`Point::diagram_curvature`](super::Point::diagram_curvature)) and the exact one.
    ///
    /// With a tolerance the run chooses, from it:
    /// - the mesh during the run: the error of the points is measured by
    ///   re-solving them on the mesh with every interval halved (at the
    ///   start, at every located point, and wherever the mesh density
    ///   ∫‖y^(m+1)‖^(1/(m+1)) changed by 10 % since the last check); a point
    ///   off by more than half the tolerance is computed again on an
    ///   equidistributed mesh with N·(e/(tol/4))^(1/2m) intervals, and a
    ///   mesh far finer than needed is coarsened the same way;
    /// - the step: besides the corrector and the angle between tangents, the
    ///   interpolation error of the quintic Hermite interpolant of the step
    ///   (h⁶ ‖P⁽⁶⁾‖/46080, the curvature P'' from x'' of the branch, one
    ///   extra solve per step) is aimed at a fifth of the tolerance and a
    ///   step above half of it is done again (a cubic through points and
    ///   slopes alone, h⁴ ‖P''''‖/384, took 2.3–2.7 times the steps at
    ///   1e-6 … 1e-8 on the rod); at tolerances of 1e-3 and looser, where
    ///   the angle between tangents sets the steps, the cubic it is, without
    ///   the curvatures ([`Point::diagram_curvature`](super::Point::diagram_curvature)
    ///   is `None` there and the dense output cubic);
    /// - the corrector's Newton tolerance 1e-4·tol (within [1e-12, 3e-7]) and
    ///   the location tolerance 0.05·tol (in arclength).
    ///
    /// What was achieved is in [`Run::estimate`](super::Run::estimate). The
    /// collocation degree stays the solver's (the rod's pull chooses it
    /// from the tolerance).
    #[must_use]
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tolerance = Some(tol);
        self
    }

    /// The corrector's Newton tolerance (relative to 1 + ‖x‖∞): with a
    /// [`tolerance`](Self::tolerance) 1e-4 of it, within [1e-12, 3e-7]
    /// (at 1e-6, tol 1e-2, the paper's spring with 24 coils took ten
    /// iterations near the folds of its plateau and then failed at the
    /// shortest step: tests/rod/long_springs.rs); without, the solver's.
    pub(crate) fn corrector_tolerance(&self) -> f64 {
        self.tolerance
            .map_or(self.solver.newton_options().tol, |tol| {
                (1e-4 * tol).clamp(1e-12, 3e-7)
            })
    }

    /// With a [`tolerance`](Self::tolerance): whether the mesh follows it
    /// (default) or stays the start solution's, the error still being
    /// measured and reported in [`Run::estimate`](super::Run::estimate).
    #[must_use]
    pub fn adapt_mesh(mut self, on: bool) -> Self {
        self.adapt_mesh = on;
        self
    }

    /// With a [`tolerance`](Self::tolerance), experimental (default off):
    /// where the corrector's Newton stalls on a system with near-null modes
    /// (a few singular values 10⁴ and more below the rest: a loop sliding
    /// along a rod under tension, held only by end effects), pin those
    /// modes from then on (`src/bvp/system/pin.rs`): every solve drops its
    /// components along them, so Newton converges in the other directions
    /// instead of stalling on rounding amplified by 10¹⁰ and more. A pinned
    /// point is kept when its first-order distance across the branch from
    /// the equilibrium the modes would slide to is at most a quarter of the
    /// tolerance; that distance is part of the estimate
    /// ([`ErrorEstimate::pinned`](super::ErrorEstimate::pinned)).
    ///
    /// Where the modes stop being null (a sliding loop reaching an end or
    /// another loop, as at a pop-out), the pinned run can fail where the
    /// unpinned one goes on: measured on the rod in docs/ACCURACY.md
    /// ("Sliding loops, pinned"), faster and within its tolerance on springs whose
    /// loops slide without popping out, failing on others. Off, nothing of
    /// it runs.
    #[must_use]
    pub fn pin_slides(mut self, on: bool) -> Self {
        self.pin_slides = on;
        self
    }

    /// The plane of the bifurcation diagram in which the
    /// [`tolerance`](Self::tolerance) is measured: (σ_λ λ, σ_g g) for the
    /// `output` g.
    #[must_use]
    pub fn diagram(mut self, output: Output, lambda_scale: f64, output_scale: f64) -> Self {
        self.diagram = Diagram {
            output,
            lambda_scale,
            output_scale,
        };
        self
    }

    pub(super) fn validate(&self, n: usize, np: usize) -> Result<()> {
        if let Some(tol) = self.tolerance
            && !((1e-12..=1.0).contains(&tol))
        {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: tol,
                allowed: "1e-12 ≤ tol ≤ 1 (an absolute distance in the diagram's plane)",
            });
        }
        self.diagram.validate(n, np)?;
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
        if !(self.ds_min > 0.0 && self.ds_min.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "ds_min",
                value: self.ds_min,
                allowed: "finite and > 0",
            });
        }
        if !(self.ds_max >= self.ds_min && self.ds_max.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "ds_max",
                value: self.ds_max,
                allowed: "finite and ≥ ds_min",
            });
        }
        if !(self.locate_tolerance > 0.0 && self.locate_tolerance.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "locate_tolerance",
                value: self.locate_tolerance,
                allowed: "finite and > 0 (an arclength)",
            });
        }
        if let Some(&bad) = self.stops.iter().find(|v| !v.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "stop_at",
                value: bad,
                allowed: "a finite parameter value",
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
}
