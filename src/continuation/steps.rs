//! The step-by-step iterator [`Steps`] and one continuation step.

use std::collections::VecDeque;
use std::fmt;

use super::hermite::Jet;
use super::mesh_error::{ErrorEstimate, HalvedMesh};
use super::norm::IntegralNorm;
use super::tolerance::{INTERPOLATION_REJECT, StepCheck, interpolation_factor};
use super::{BranchSide, Continuation, Point, PointKind, Rejection, Termination};
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
    pub(super) rejections: Vec<(Rejection, f64)>,
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
    /// With a tolerance: P⁽⁵⁾ of the last step's interpolant and the
    /// step's length.
    pub(super) last_fifth: Option<([f64; 2], f64)>,
    /// With a tolerance: the jet of x₀ in the diagram's plane, once
    /// computed.
    pub(super) jet0: Option<Jet>,
    /// Remeshes spent on the current step.
    pub(super) remeshes_this_step: u32,
    /// The point and tangent before x₀ and the step between them (the
    /// cubic predictor's data; none at the start and after a remesh).
    pub(super) previous: Option<(State, State, f64)>,
    /// The coarsest mesh the run may move to: the start solution's.
    pub(super) min_intervals: usize,
    /// A remesh moved x₀ past a fold: locate it before the next step.
    pub(super) fold_behind: bool,
    /// The accepted-step count at the last mesh check.
    pub(super) checked_at: usize,
    /// Successive accepted steps that left the parameter and the diagram's
    /// point unchanged ([`Error::NoProgress`] at [`STALLED_STEPS`]).
    pub(super) stalled: u32,
}

/// Successive steps that move nothing before a run ends with
/// [`Error::NoProgress`]: one could be a coincidence of rounding at a
/// turning point of both coordinates; three in a row are the rounding floor.
const STALLED_STEPS: u32 = 3;

/// Whether a and b differ by no more than their last few digits (4 ulp):
/// a step that moved them less moved nothing a double can show.
fn rounding_apart(a: f64, b: f64) -> bool {
    (a - b).abs() <= 4.0 * f64::EPSILON * a.abs().max(b.abs())
}

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

    /// [`Continuation::steps`] from `start`, a point of an earlier run at
    /// `arclength` along it: the same iterator with every arclength counted
    /// from there, so that the two runs read as one branch (a pull going on
    /// at a looser tolerance, [`crate::rod::Pull::relax_to`]). The
    /// direction is the sign of the step, as for a fresh start.
    pub(crate) fn steps_resumed<'a, P: Problem + ?Sized>(
        &'a self,
        problem: &'a P,
        start: &Solution,
        arclength: f64,
    ) -> Result<Steps<'a, P>> {
        let mut steps = Steps::new(self, problem, start, None)?;
        steps.arclength = arclength;
        for p in &mut steps.pending {
            p.arclength += arclength;
        }
        Ok(steps)
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

/// [`Error::LengthMismatch`] unless `start` is a solution of a problem of
/// dimension `n` with `np` parameters, [`Error::InvalidCount`] unless it
/// has the solver's `m` collocation points per interval: the checks of a
/// run's start.
pub(super) fn start_fits(start: &Solution, n: usize, np: usize, m: usize) -> Result<()> {
    if start.dim() != n || start.parameters().len() != np {
        return Err(Error::LengthMismatch {
            name: "start solution dimension",
            found: start.dim() as u64,
            expected: n as u64,
        });
    }
    if start.points_per_interval() != m {
        return Err(Error::InvalidCount {
            name: "start solution points per interval",
            value: start.points_per_interval() as u64,
            allowed: "the solver's m (solve the start with the same Collocation)",
        });
    }
    Ok(())
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
        start_fits(start, n, np, tab.m)?;
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
                tol: cont.corrector_tolerance(),
                max_iter: cont.max_newton,
                stall: 1.0,
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
            last_fifth: None,
            jet0: None,
            remeshes_this_step: 0,
            previous: None,
            min_intervals: mesh_intervals,
            fold_behind: false,
            checked_at: 0,
            stalled: 0,
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
        let mut first = steps.point(
            sol,
            &steps.x0.clone(),
            &steps.t0.clone(),
            steps.det0,
            PointKind::Start,
            0,
        );
        if cont.tolerance.is_some() {
            first.diagram_curvature = steps.start_jet().curvature;
        }
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
            diagram_curvature: [f64::NAN; 2],
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

    /// Rejects the step just corrected `because`: halves Δs (not below
    /// Δs_min) for the next attempt from the same x₀.
    pub(super) fn reject_step(&mut self, because: Rejection) {
        self.reject_to((0.5 * self.ds).max(self.cont.ds_min), because);
    }

    /// Rejects the step just corrected `because`, the next attempt from the
    /// same x₀ with Δs = `ds`.
    pub(super) fn reject_to(&mut self, ds: f64, because: Rejection) {
        self.ds = ds;
        self.factored_at_x0 = false;
        self.rejected += 1;
        self.rejections.push((because, ds));
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
        let mut fit = None;
        if let Some(tol) = self.cont.tolerance {
            let Some(f) = self.check_interpolation(&c, ds, tol) else {
                return;
            };
            fit = Some(f);
        }
        let in_step = self.special_points_in_step(&c, ds);
        if let Some(e) = in_step
            .error
            .as_ref()
            .filter(|_| self.ds > self.cont.ds_min)
        {
            // A special point that cannot be located in this step (its
            // Newton failing across a long step) is looked for again in a
            // shorter one; only at the shortest step does it end the run.
            self.reject_step(Rejection::Location(e.clone()));
            return;
        }
        let mut coarsen = None;
        if let (Some(tol), Some(f)) = (self.cont.tolerance, fit.as_mut()) {
            let inside: Vec<(State, State, f64)> = in_step
                .found
                .iter()
                .map(|(cs, s, ..)| (cs.x.clone(), cs.tangent.clone(), *s))
                .collect();
            let at_located = self.located_interpolation_error(f, ds, &inside);
            let allowed = INTERPOLATION_REJECT * tol;
            if at_located > allowed && self.ds > self.cont.ds_min {
                self.reject_step(Rejection::AtLocated {
                    error: at_located,
                    allowed,
                });
                return;
            }
            f.error = f.error.max(at_located);
        }
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
        // (with a tolerance, the step's arclength rather than its Δs)
        let length = fit.as_ref().map_or(ds, |f| f.length);
        for (cs, s, kind, stop) in in_step.found {
            // with a tolerance, the located point's jet (a stop ends the
            // curve: the last segment is interpolated to it) and its
            // arclength from x₀ like the step's
            let mut jet = None;
            self.arclength = if fit.is_some() {
                let start = self.start_jet();
                let j = self.jet(&cs.x, &cs.tangent);
                jet = Some(j);
                base + self.step_length(&cs.x, &cs.tangent, &start, &j)
            } else {
                base + s
            };
            let sol = match self.solution(&cs.x, Default::default()) {
                Ok(s) => s,
                Err(e) => {
                    self.fail(e);
                    return;
                }
            };
            let mut p = self.point(sol, &cs.x, &cs.tangent, cs.det, kind, cs.iterations);
            if let Some(j) = jet {
                p.diagram_curvature = j.curvature;
            }
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
        self.arclength = base + length;
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
        let mut p = self.point(
            sol,
            &c.x,
            &c.tangent,
            c.det,
            PointKind::Regular,
            c.iterations,
        );
        if let Some(f) = &fit {
            p.diagram_curvature = f.end.curvature;
        }
        if rounding_apart(c.x.p[q], self.x0.p[q]) && {
            let before = self.diagram_of(&self.x0, &self.t0).0;
            rounding_apart(p.diagram[0], before[0]) && rounding_apart(p.diagram[1], before[1])
        } {
            self.stalled += 1;
            if self.stalled >= STALLED_STEPS {
                self.fail(Error::NoProgress {
                    parameter: c.x.p[q],
                    ds,
                    steps: self.stalled,
                });
                return;
            }
        } else {
            self.stalled = 0;
        }
        self.pending.push_back(p);
        // Accept: the new point becomes x₀; its factorisation is current
        // unless location overwrote it.
        let its = c.iterations;
        let (x_old, t_old) = (
            std::mem::replace(&mut self.x0, c.x),
            std::mem::replace(&mut self.t0, c.tangent),
        );
        self.previous = Some((x_old, t_old, ds));
        self.det0 = c.det;
        self.skip_detection = false;
        self.events0 = in_step.events;
        let mut y_ref = std::mem::take(&mut self.sys.y_ref);
        self.sys.collocation_values(&self.x0, &mut y_ref);
        self.sys.y_ref = y_ref;
        let mut factor = f64::INFINITY;
        self.jet0 = None;
        if let Some(f) = fit {
            self.last_fifth = Some((f.fifth, f.length));
            self.jet0 = Some(f.end);
            self.estimate.interpolation = self.estimate.interpolation.max(f.error);
            if let Some(tol) = self.cont.tolerance {
                factor = interpolation_factor(f.error, tol);
            }
        }
        self.adapt_step(its, factor);
        if let Some(n) = coarsen
            && let Ok(flipped) = self.remesh(n)
        {
            self.fold_behind |= flipped && self.cont.folds;
            // (a failed coarsening keeps the finer mesh)
            self.last_fifth = None;
        }
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
