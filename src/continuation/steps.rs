//! The step-by-step iterator [`Steps`] and one continuation step.

use std::collections::VecDeque;
use std::fmt;

use super::diagram::{hermite_error, hermite_third, turns_back_twice};
use super::mesh_error::{ErrorEstimate, HalvedMesh};
use super::norm::IntegralNorm;
use super::{BranchSide, Continuation, Point, PointKind, Termination};
use crate::bvp::system::{State, System};
use crate::bvp::{NewtonOptions, Problem, Solution, finish};
use crate::error::{Error, Result};
use crate::linalg::Det;

/// The step-by-step continuation iterator (see [`Continuation::steps`]).
/// After it returns `None`, [`Steps::termination`] says why.
pub struct Steps<'a, P: Problem + ?Sized> {
    pub(super) cont: &'a Continuation,
    pub(super) sys: System<'a, P>,
    pub(super) mesh: crate::bvp::Mesh,
    pub(super) opts: NewtonOptions,
    pub(super) norm: IntegralNorm,
    pub(super) x0: State,
    pub(super) t0: State,
    pub(super) det0: Det,
    pub(super) ds: f64,
    pub(super) arclength: f64,
    pub(super) accepted: usize,
    pub(super) factored_at_x0: bool,
    pub(super) skip_detection: bool,
    pub(super) pending: VecDeque<Point>,
    pub(super) termination: Option<Termination>,
    pub(super) rejections: Vec<f64>,
    pub(super) rejected: usize,
    pub(super) newton_iterations: u64,
    pub(super) ycol_a: Vec<f64>,
    pub(super) ycol_b: Vec<f64>,
    /// The user events at x₀.
    pub(super) events0: Vec<f64>,
    /// The arclength tolerance of location (the setting, or derived from
    /// the tolerance).
    pub(super) locate_tolerance: f64,
    /// The angle between the last two accepted tangents.
    pub(super) angle: f64,
    /// With a tolerance: what the run achieved so far.
    pub(super) estimate: ErrorEstimate,
    /// With a tolerance: the halved mesh of the checks.
    pub(super) halved: Option<HalvedMesh<'a, P>>,
    /// With a tolerance: the mesh density integral at the last check.
    pub(super) checked_density: f64,
    /// With a tolerance: P''' of the last step's Hermite interpolant and
    /// the step's length.
    pub(super) last_third: Option<([f64; 2], f64)>,
    /// Remeshes spent on the current step.
    pub(super) remeshes_this_step: u32,
    /// The coarsest mesh the run may move to: the start solution's.
    pub(super) min_intervals: usize,
    /// A remesh moved x₀ past a fold: locate it before the next step.
    pub(super) fold_behind: bool,
    /// The accepted-step count at the last mesh check.
    pub(super) checked_at: usize,
}

/// Remeshes allowed for one step (a step whose error is still above the
/// tolerance after them is accepted, with its estimate).
const REMESHES_PER_STEP: u32 = 4;

/// The chord in the diagram's plane below which a step's turn is not
/// limited.
const TURN_CHORD: f64 = 1e-2;

/// The largest distance between the corrected point and the predictor,
/// relative to the step, of an accepted step with a tolerance (a larger one
/// is the mark of a trace that jumped to a nearby branch).
const MAX_DRIFT: f64 = 0.2;

/// Accepted steps between two mesh checks at most.
const CHECK_EVERY: usize = 4;

/// Relative change of the mesh density integral that triggers a check.
const DENSITY_CHANGE: f64 = 0.1;

impl Continuation {
    /// A step-by-step iterator over the branch through `start` (a solution
    /// of the problem at its parameter values). The first item is the start
    /// point.
    ///
    /// # Errors
    /// Bad settings ([`Error::InvalidArgument`], [`Error::InvalidCount`],
    /// [`Error::LengthMismatch`]), [`Error::IllPosed`] if the counts do not
    /// match with λ free, or an error of the first tangent computation.
    pub fn steps<'a, P: Problem + ?Sized>(
        &'a self,
        problem: &'a P,
        start: &Solution,
    ) -> Result<Steps<'a, P>> {
        Steps::new(self, problem, start, None)
    }
}

impl<P: Problem + ?Sized> fmt::Debug for Steps<'_, P> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Steps")
            .field("steps", &self.accepted)
            .field("ds", &self.ds)
            .field("arclength", &self.arclength)
            .field("termination", &self.termination)
            .finish_non_exhaustive()
    }
}

impl<'a, P: Problem + ?Sized> Steps<'a, P> {
    pub(super) fn new(
        cont: &'a Continuation,
        problem: &'a P,
        start: &Solution,
        switch: Option<(State, BranchSide, f64)>,
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
        let mesh_intervals = mesh.intervals();
        let mut sys = System::new(problem, mesh.points().to_vec(), tab, free, 1)?;
        sys.linear = cont.solver.linear();
        let weights = cont.weights.clone().unwrap_or_else(|| vec![1.0; n]);
        let norm = IntegralNorm::new(
            (0..mesh.intervals()).map(|j| mesh.width(j)),
            &sys.tab.b,
            &weights,
            cont.parameter_weight,
        );
        let x0 = State {
            y: start.y.clone(),
            k: start.k.clone(),
            p: start.p.clone(),
        };
        let len = sys.y_ref.len();
        let mut steps = Steps {
            cont,
            sys,
            mesh,
            opts: NewtonOptions {
                tol: cont
                    .tolerance
                    .map_or(cont.solver.newton_options().tol, |tol| {
                        (1e-4 * tol).clamp(1e-12, 1e-6)
                    }),
                max_iter: cont.max_newton,
            },
            norm,
            x0,
            t0: State {
                y: Vec::new(),
                k: Vec::new(),
                p: Vec::new(),
            },
            det0: Det::ONE,
            ds: cont.ds.abs().clamp(cont.ds_min, cont.ds_max),
            arclength: 0.0,
            accepted: 0,
            factored_at_x0: false,
            skip_detection: false,
            pending: VecDeque::new(),
            termination: None,
            rejections: Vec::new(),
            rejected: 0,
            newton_iterations: 0,
            ycol_a: vec![0.0; len],
            ycol_b: vec![0.0; len],
            events0: Vec::new(),
            locate_tolerance: cont
                .tolerance
                .map_or(cont.locate_tolerance, |tol| 0.05 * tol),
            angle: 0.0,
            estimate: ErrorEstimate {
                intervals: mesh_intervals,
                max_intervals: mesh_intervals,
                ..ErrorEstimate::default()
            },
            halved: None,
            checked_density: f64::NAN,
            last_third: None,
            remeshes_this_step: 0,
            min_intervals: mesh_intervals,
            fold_behind: false,
            checked_at: 0,
        };
        let mut y_ref = std::mem::take(&mut steps.sys.y_ref);
        steps.sys.collocation_values(&steps.x0, &mut y_ref);
        steps.sys.y_ref = y_ref;
        match switch {
            None => {
                // Tangent from [F_x; e_λᵀ] τ = e, oriented by the sign of ds.
                steps.set_parameter_border();
                let x0 = steps.x0.clone();
                steps.sys.factor(&x0)?;
                let mut t = steps.solve_border_rhs()?;
                let nrm = steps.norm(&t);
                let sgn = if cont.ds < 0.0 { -1.0 } else { 1.0 };
                t.scale(sgn / nrm);
                steps.t0 = t;
                steps.set_tangent_border(0.0);
                steps.det0 = steps.sys.factor_border()?;
                steps.factored_at_x0 = true;
            }
            Some((tangent, direction, arclength)) => {
                steps.start_on_bifurcating_branch(tangent, direction, arclength)?;
            }
        }
        if let Some(tol) = cont.tolerance {
            steps.check_start(tol)?;
        }
        let sol = steps.solution(&steps.x0.clone(), Default::default())?;
        for i in 0..cont.events.len() {
            let v = steps.event_at(i, &sol)?;
            steps.events0.push(v);
        }
        let first = steps.point(
            sol,
            &steps.x0.clone(),
            &steps.t0.clone(),
            steps.det0,
            PointKind::Start,
            0,
        );
        steps.pending.push_back(first);
        Ok(steps)
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
    pub fn accepted(&self) -> usize {
        self.accepted
    }

    /// Rejected (halved and retried) steps so far.
    #[must_use]
    pub fn rejected(&self) -> usize {
        self.rejected
    }

    /// With a [`tolerance`](Continuation::tolerance): the errors measured
    /// so far (all zero without one).
    #[must_use]
    pub fn estimate(&self) -> ErrorEstimate {
        self.estimate
    }

    /// The current mesh.
    #[must_use]
    pub fn mesh(&self) -> &crate::bvp::Mesh {
        &self.mesh
    }

    /// Corrector iterations so far: accepted, rejected and special-point
    /// location correctors alike (failed correctors are not counted).
    #[must_use]
    pub fn newton_iterations(&self) -> u64 {
        self.newton_iterations
    }

    pub(super) fn solution(
        &mut self,
        x: &State,
        stats: crate::bvp::NewtonStats,
    ) -> Result<Solution> {
        finish(&mut self.sys, x.clone(), self.mesh.clone(), stats)
    }

    pub(super) fn point(
        &self,
        solution: Solution,
        x: &State,
        t: &State,
        det: Det,
        kind: PointKind,
        iterations: u32,
    ) -> Point {
        let q = self.cont.parameter;
        let (diagram, diagram_slope) = self.diagram_of(x, t);
        Point {
            diagram,
            diagram_slope,
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

    /// Ends the run: the step failed at |Δs| with `error`.
    pub(super) fn fail(&mut self, error: Error) {
        self.termination = Some(Termination::Failed { ds: self.ds, error });
    }

    /// One accepted step (plus any located special points) into `pending`.
    fn advance(&mut self) {
        if self.accepted >= self.cont.max_steps {
            self.termination = Some(Termination::MaxSteps(self.accepted));
            return;
        }
        if std::mem::take(&mut self.fold_behind)
            && let Some((cs, s)) = self.fold_behind()
        {
            let base = self.arclength;
            self.arclength = base + s;
            match self.solution(&cs.x, Default::default()) {
                Ok(sol) => {
                    let p = self.point(
                        sol,
                        &cs.x,
                        &cs.tangent,
                        cs.det,
                        PointKind::Fold,
                        cs.iterations,
                    );
                    self.pending.push_back(p);
                }
                Err(e) => {
                    self.fail(e);
                    return;
                }
            }
            self.arclength = base;
            self.factored_at_x0 = false;
        }
        let Some(c) = self.accepted_step() else {
            return;
        };
        let ds = self.ds;
        let mut hermite = None;
        if let Some(tol) = self.cont.tolerance {
            let Some(h) = self.check_interpolation(&c, ds, tol) else {
                return;
            };
            hermite = Some(h);
        }
        let in_step = self.special_points_in_step(&c, ds);
        let mut coarsen = None;
        if let Some(tol) = self.cont.tolerance {
            let located: Vec<(State, State, bool)> = in_step
                .found
                .iter()
                .map(|(cs, _, kind, _)| {
                    (cs.x.clone(), cs.tangent.clone(), *kind == PointKind::Fold)
                })
                .collect();
            match self.check_step(&c, &located, tol) {
                StepCheck::Remeshed => return,
                StepCheck::Accept { coarsen_to } => coarsen = coarsen_to,
            }
        }
        self.accepted += 1;
        self.remeshes_this_step = 0;
        let q = self.cont.parameter;
        // Whatever factorisation is current (at the new point, a located
        // point or an earlier chord point) preconditions the next corrector;
        // Newton refreshes it when the contraction degrades.
        self.factored_at_x0 = true;
        let base = self.arclength;
        for (cs, s, kind, stop) in in_step.found {
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
        if let Some(e) = in_step.error {
            self.fail(e);
            return;
        }
        self.arclength = base + ds;
        let sol = match in_step
            .solution
            .map_or_else(|| self.solution(&c.x, Default::default()), Ok)
        {
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
        self.events0 = in_step.events;
        let mut y_ref = std::mem::take(&mut self.sys.y_ref);
        self.sys.collocation_values(&self.x0, &mut y_ref);
        self.sys.y_ref = y_ref;
        let mut factor = f64::INFINITY;
        if let Some((third, error)) = hermite {
            self.last_third = Some((third, ds));
            self.estimate.interpolation = self.estimate.interpolation.max(error);
            if let Some(tol) = self.cont.tolerance {
                factor = hermite_factor(error, tol);
            }
        }
        self.adapt_step(its, factor);
        if let Some(n) = coarsen
            && let Ok(flipped) = self.remesh(n)
        {
            self.fold_behind |= flipped && self.cont.folds;
            // (a failed coarsening keeps the finer mesh)
            self.last_third = None;
        }
    }
}

/// The angle between two slopes in the diagram's plane (0 when either
/// vanishes).
fn diagram_turn(a: [f64; 2], b: [f64; 2]) -> f64 {
    let (na, nb) = (a[0].hypot(a[1]), b[0].hypot(b[1]));
    if na > 0.0 && nb > 0.0 && na.is_finite() && nb.is_finite() {
        ((a[0] * b[0] + a[1] * b[1]) / (na * nb))
            .clamp(-1.0, 1.0)
            .acos()
    } else {
        0.0
    }
}

/// The share of the tolerance left to the interpolation between points.
const INTERPOLATION_SHARE: f64 = 0.25;

/// The step factor that brings the Hermite interpolation error `error` to
/// 0.8 of its share of `tol` (error ∝ h⁴).
fn hermite_factor(error: f64, tol: f64) -> f64 {
    if error > 0.0 {
        (0.8 * INTERPOLATION_SHARE * tol / error).powf(0.25)
    } else {
        f64::INFINITY
    }
}

/// What the mesh checks of a step decided.
enum StepCheck {
    /// The run moved to a finer mesh at x₀: the step is done again.
    Remeshed,
    /// The step stands; coarsen to this many intervals after it.
    Accept { coarsen_to: Option<usize> },
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// The mesh check of the start point: refine (or coarsen, once) until
    /// its error is within half the tolerance.
    fn check_start(&mut self, tol: f64) -> Result<()> {
        let goal = 0.5 * tol;
        let mut coarsened = false;
        for _ in 0..8 {
            let (x, t) = (self.x0.clone(), self.t0.clone());
            let e = self.mesh_error(&x, &t, false).unwrap_or(f64::INFINITY);
            let nn = self.mesh.intervals();
            let want = self.intervals_for(e, 0.25 * tol);
            let limit = self.cont.solver.interval_limit();
            if !self.cont.adapt_mesh {
                self.estimate.mesh = e;
                break;
            }
            if e > goal && nn < limit {
                self.remesh(want.max(nn + nn / 4 + 1).min(limit))?;
            } else if e <= goal && !coarsened && 10 * want.max(self.min_intervals) <= 7 * nn {
                coarsened = true;
                self.remesh(want.max(self.min_intervals))?;
            } else {
                self.estimate.mesh = e;
                break;
            }
        }
        self.checked_density = self.density_integral(&self.x0.clone());
        Ok(())
    }

    /// The interpolation check of a step: its P''' and error estimate, or
    /// `None` when the step was rejected (Δs reduced) for an error above
    /// four times its share of the tolerance.
    fn check_interpolation(
        &mut self,
        c: &super::corrector::Corrected,
        ds: f64,
        tol: f64,
    ) -> Option<([f64; 2], f64)> {
        // the corrector's distance from the predictor, relative to the step
        let free = self.sys.free.clone();
        let mut d = c.x.clone();
        d.axpy(-1.0, &self.x0.clone(), &free);
        d.axpy(-ds, &self.t0.clone(), &free);
        let drift = self.norm(&d) / ds;
        let (p0, s0) = self.diagram_of(&self.x0, &self.t0);
        let (p1, s1) = self.diagram_of(&c.x, &c.tangent);
        let third = hermite_third(p0, s0, p1, s1, ds);
        let error = self
            .last_third
            .map_or(0.0, |(prev, h)| hermite_error(third, prev, ds, h));
        // (a turn over a chord below a hundredth of the plane's unit is a
        // corner the interpolation error already resolves)
        let chord = (p1[0] - p0[0]).abs().max((p1[1] - p0[1]).abs());
        let turn = if chord > TURN_CHORD {
            diagram_turn(s0, s1)
        } else {
            0.0
        };
        let skipped =
            self.cont.folds && turns_back_twice(p0[0], s0[0], p1[0], s1[0], ds, 0.1 * tol);
        let too_far = turn > self.cont.max_angle
            || drift > MAX_DRIFT
            || skipped
            || error > 4.0 * INTERPOLATION_SHARE * tol;
        if too_far && self.ds > self.cont.ds_min {
            let by_turn = (0.6 * self.cont.max_angle / turn).min(0.5 * MAX_DRIFT / drift);
            self.ds =
                (ds * hermite_factor(error, tol).min(by_turn).max(0.25)).max(self.cont.ds_min);
            self.factored_at_x0 = false;
            self.rejected += 1;
            self.rejections.push(self.ds);
            return None;
        }
        self.angle = self.angle.max(turn);
        Some((third, error))
    }

    /// The mesh checks of a step: every located point, and the new point
    /// when the density moved (module docs of `mesh_error`).
    fn check_step(
        &mut self,
        c: &super::corrector::Corrected,
        located: &[(State, State, bool)],
        tol: f64,
    ) -> StepCheck {
        let goal = 0.5 * tol;
        let mut worst_located: f64 = 0.0;
        for (x, t, fold) in located {
            let e = self.mesh_error(x, t, *fold).unwrap_or(f64::INFINITY);
            worst_located = worst_located.max(e);
        }
        let density = self.density_integral(&c.x);
        let moved = (density / self.checked_density - 1.0).abs() > DENSITY_CHANGE;
        let mut regular = None;
        let due = self.accepted >= self.checked_at + CHECK_EVERY;
        if moved || due || !located.is_empty() {
            regular = Some(
                self.mesh_error(&c.x, &c.tangent, false)
                    .unwrap_or(f64::INFINITY),
            );
        }
        let worst = worst_located.max(regular.unwrap_or(0.0));
        let nn = self.mesh.intervals();
        let limit = self.cont.solver.interval_limit();
        if self.cont.adapt_mesh
            && worst > goal
            && nn < limit
            && self.remeshes_this_step < REMESHES_PER_STEP
        {
            let want = self.intervals_for(worst, 0.25 * tol);
            self.remeshes_this_step += 1;
            if let Ok(flipped) = self.remesh(want.max(nn + nn / 4 + 1).min(limit)) {
                self.last_third = None;
                self.fold_behind |= flipped && self.cont.folds;
                return StepCheck::Remeshed;
            }
        }
        self.estimate.mesh = self.estimate.mesh.max(worst);
        self.estimate.located = self.estimate.located.max(worst_located);
        let mut coarsen_to = None;
        if let Some(e) = regular {
            self.checked_density = density;
            self.checked_at = self.accepted;
            let want = self.intervals_for(e, 0.25 * tol);
            let want = want.max(self.min_intervals);
            if self.cont.adapt_mesh && e <= goal && located.is_empty() && 10 * want <= 7 * nn {
                coarsen_to = Some(want);
            }
        }
        StepCheck::Accept { coarsen_to }
    }
}

impl<P: Problem + ?Sized> Iterator for Steps<'_, P> {
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
