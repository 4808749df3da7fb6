//! Pulling the spring: pseudo-arclength continuation in the force (or the
//! extension) from the unstressed helix, with the pop-outs (folds) located.
//!
//! [`Pull`] is a rod-specific front end to [`crate::continuation`]: it
//! chooses the norm, the start and the stop, and turns the continuation's
//! points into [`PullPoint`]s (force, extension, loop count, planarity) and
//! its located folds into [`Fold`]s.
//!
//! ```text
//!   unknowns  x = (y(·), λ),   λ = F_z  (or Δz under extension control)
//!   equations rod BVP (collocation) and
//!             ⟨y − y_k, ẏ_k⟩ + θ (λ − λ_k) λ̇_k = Δs        (pseudo-arclength)
//!   ⟨a, b⟩  = Σ_i w_i ∫₀¹ a_i b_i ds,   w = 1 (r, q), 1/(2πn)⁴ (F), 1e-3 (M),
//!             θ = 1/(2πn)⁴ under force control, 1 under extension control
//! ```
//!
//! The run starts from the unstressed helix (λ = 0) and a second solution
//! a small load away (F/(2πn)² = ±1e-4, or Δz ± 1e-4), from which the
//! continuation takes its first step Δs = 2e-3: small enough not to jump
//! over the helix's initial turn-and-shear stretch at almost constant force.
//! Step control, tangents and fold location (Illinois iteration on the
//! arclength of the step, to 1e-9) are [`crate::continuation`]'s, with the
//! angle check between successive tangents (0.3 rad) that keeps the trace
//! from jumping between nearby branches; branch-point detection is off (the
//! rod's phase condition keeps the pull free of them, as the `rod` tests
//! check with it on), which lets the corrector keep its factorisation.

use std::ops::ControlFlow;
use std::time::{Duration, Instant};

use super::{Control, Equilibrium, Rod};
use crate::bvp::{Collocation, Mesh};
use crate::continuation::{Continuation, PointKind, Steps, Termination};
use crate::curve::{self, Fold, FoldKind, ForceExtension, ForcePoint};
use crate::error::{Error, Result};

/// One accepted point of a pull.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PullPoint {
    /// F_z, the physical tension.
    pub force: f64,
    /// F_z/(2πn)².
    pub force_scaled: f64,
    /// Δz = z(1).
    pub extension: f64,
    /// Arclength along the curve in the continuation norm.
    pub arclength: f64,
    /// Newton iterations of the step.
    pub newton_iterations: u32,
    /// The loop count of the shape ([`Equilibrium::loops`]; meaningful on
    /// the near-planar stretches, not during 3D excursions).
    pub loops: u32,
    /// Distance from planarity ([`Equilibrium::planarity`]).
    pub planarity: f64,
}

/// A stretch of the curve between two folds (or a fold and an end).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stretch {
    /// Index of the first point of the stretch.
    pub first: usize,
    /// Index of the last point of the stretch.
    pub last: usize,
    /// The loop count at the most nearly planar point of the stretch.
    pub loops: u32,
    /// The smallest distance from planarity on the stretch.
    pub planarity: f64,
}

/// Why a pull ended.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum PullTermination {
    /// The controlled load (force, or extension under extension control)
    /// reached the requested value.
    ReachedForce,
    /// The step limit was reached.
    MaxSteps(usize),
    /// The observer asked to stop.
    Stopped,
    /// No step ≥ Δs_min converged; `error` is the last solver error.
    StepTooSmall {
        /// The last solver error.
        error: Error,
    },
    /// The start (the unstressed helix) could not be solved.
    StartFailed(Error),
}

impl core::fmt::Display for PullTermination {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            PullTermination::ReachedForce => f.write_str("reached the requested load"),
            PullTermination::MaxSteps(n) => write!(f, "stopped after the maximum of {n} steps"),
            PullTermination::Stopped => f.write_str("stopped by the observer"),
            PullTermination::StepTooSmall { error } => {
                write!(f, "no step above the minimum size converged ({error})")
            }
            PullTermination::StartFailed(e) => write!(f, "the start failed ({e})"),
        }
    }
}

/// Hooks called during [`Pull::run`]; both default to continuing.
/// Implemented for `()` and for closures `FnMut(&Equilibrium, &PullPoint) ->
/// ControlFlow<()>` (called on every point).
pub trait PullObserver {
    /// Called on every accepted point, with its equilibrium.
    fn point(&mut self, equilibrium: &Equilibrium, point: &PullPoint) -> ControlFlow<()> {
        let _ = (equilibrium, point);
        ControlFlow::Continue(())
    }

    /// Called on every located fold, with the equilibrium at the fold.
    fn fold(&mut self, equilibrium: &Equilibrium, fold: &Fold) -> ControlFlow<()> {
        let _ = (equilibrium, fold);
        ControlFlow::Continue(())
    }
}

impl PullObserver for () {}

impl<F> PullObserver for F
where
    F: FnMut(&Equilibrium, &PullPoint) -> ControlFlow<()>,
{
    fn point(&mut self, equilibrium: &Equilibrium, point: &PullPoint) -> ControlFlow<()> {
        self(equilibrium, point)
    }
}

/// The result of a pull: every accepted point in order, the folds, and why
/// it ended. A failed run keeps its points.
#[derive(Debug, Clone)]
pub struct PullRun {
    /// The rod that was pulled.
    pub rod: Rod,
    /// Accepted points in continuation order (the first is the start).
    pub points: Vec<PullPoint>,
    /// Located folds in order: each with its [`FoldKind`], the index of the
    /// last point before it, and its force, extension and arclength.
    pub folds: Vec<Fold>,
    /// Why the run ended.
    pub termination: PullTermination,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected (retried) steps.
    pub rejected: usize,
    /// Total Newton iterations: the start, every corrector (rejected steps
    /// and fold location included).
    pub newton_iterations: u64,
    /// Mesh intervals used.
    pub intervals: usize,
    /// Wall-clock time of the run.
    pub elapsed: Duration,
}

impl PullRun {
    /// The force–extension curve (parameter: arclength).
    #[must_use]
    pub fn curve(&self) -> ForceExtension {
        let mut c = ForceExtension::new("rod pull", "arclength", self.rod.coils())
            .expect("coils ≥ 1 is checked by Rod::new");
        c.extend(self.points.iter().map(|p| ForcePoint {
            extension: p.extension,
            force: p.force,
            parameter: p.arclength,
        }));
        c
    }

    /// The stretches between folds, each with its loop count (taken where
    /// the shape is closest to planar).
    #[must_use]
    pub fn stretches(&self) -> Vec<Stretch> {
        let mut bounds = vec![0];
        bounds.extend(self.folds.iter().map(|f| f.index + 1));
        bounds.push(self.points.len());
        bounds
            .windows(2)
            .filter(|w| w[1] > w[0])
            .map(|w| {
                let best = (w[0]..w[1])
                    .min_by(|&a, &b| {
                        self.points[a]
                            .planarity
                            .total_cmp(&self.points[b].planarity)
                    })
                    .unwrap_or(w[0]);
                Stretch {
                    first: w[0],
                    last: w[1] - 1,
                    loops: self.points[best].loops,
                    planarity: self.points[best].planarity,
                }
            })
            .collect()
    }

    /// Loops lost between the first and the last stretch.
    #[must_use]
    pub fn loops_lost(&self) -> i64 {
        let s = self.stretches();
        match (s.first(), s.last()) {
            (Some(a), Some(b)) => i64::from(a.loops) - i64::from(b.loops),
            _ => 0,
        }
    }

    /// The pop-outs: each maximum fold of the controlled load paired with
    /// the minimum fold that follows it (force folds under force control,
    /// extension folds under extension control).
    #[must_use]
    pub fn pop_outs(&self) -> Vec<(Fold, Fold)> {
        self.folds
            .windows(2)
            .filter(|w| {
                matches!(
                    (w[0].kind, w[1].kind),
                    (FoldKind::MaxForce, FoldKind::MinForce)
                        | (FoldKind::MaxExtension, FoldKind::MinExtension)
                )
            })
            .map(|w| (w[0], w[1]))
            .collect()
    }
}

impl core::fmt::Display for PullRun {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        writeln!(
            f,
            "pull of {}: {} points, {} folds, {} steps ({} rejected), {} intervals, {:.2?}: {}",
            self.rod,
            self.points.len(),
            self.folds.len(),
            self.steps,
            self.rejected,
            self.intervals,
            self.elapsed,
            self.termination
        )?;
        for fold in &self.folds {
            writeln!(
                f,
                "  {} at Δz = {:.6}, F/(2πn)² = {:.6}",
                fold.kind,
                fold.point.extension,
                fold.point.force_scaled(self.rod.coils())
            )?;
        }
        for s in self.stretches() {
            writeln!(
                f,
                "  points {}..={}: {} loops (planarity {:.1e})",
                s.first, s.last, s.loops, s.planarity
            )?;
        }
        Ok(())
    }
}

/// Pulls a [`Rod`] from its unstressed helix by pseudo-arclength
/// continuation in the force (module docs: [`crate::rod`]).
///
/// ```no_run
/// use hockle::rod::{Pull, Rod};
/// let rod = Rod::nikolai(4, 89.8_f64.to_radians(), 10.0, 0.05)?;
/// let run = Pull::new(rod).to_force_scaled(3.0).run(());
/// assert_eq!(run.pop_outs().len(), 3); // the paper's cascade 4 → 3 → 2 → 1
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Pull {
    rod: Rod,
    target: f64,
    intervals: usize,
    points: usize,
    ds0: f64,
    ds_min: f64,
    ds_max: f64,
    max_steps: usize,
    max_angle: f64,
    locate_folds: bool,
}

impl Pull {
    /// A pull of `rod` under force control (dead load; folds in the force
    /// are where the spring jumps) with the defaults:
    ///
    /// | setting | default |
    /// |---|---|
    /// | [`to_force_scaled`](Self::to_force_scaled) | 3 (the paper's Fig. spring) |
    /// | [`extension_control`](Self::extension_control) | off |
    /// | [`intervals`](Self::intervals) | 48 uniform mesh intervals (folds converged to 6e-7 against 128) |
    /// | [`points`](Self::points) | 4 Gauss points per interval |
    /// | [`step`](Self::step) | Δs = 2e-3 first, within [1e-7, 0.02] |
    /// | [`max_steps`](Self::max_steps) | 20 000 |
    /// | [`max_angle`](Self::max_angle) | 0.3 rad between successive tangents |
    /// | [`locate_folds`](Self::locate_folds) | yes |
    #[must_use]
    pub fn new(rod: Rod) -> Self {
        Self {
            rod: rod.with_control(Control::Force),
            target: 3.0,
            intervals: 48,
            points: 4,
            ds0: 2e-3,
            ds_min: 1e-7,
            ds_max: 0.02,
            max_steps: 20_000,
            max_angle: 0.3,
            locate_folds: true,
        }
    }

    /// Force control, stopping once F/(2πn)² exceeds `f` (a negative
    /// target pushes instead).
    #[must_use]
    pub fn to_force_scaled(mut self, f: f64) -> Self {
        self.rod = self.rod.with_control(Control::Force);
        self.target = f;
        self
    }

    /// Extension control (hard device: Δz prescribed, F_z an unknown; folds
    /// in Δz are where the spring jumps), stopping once Δz exceeds `dz`
    /// (or falls below it, if it is below the rest extension cos θ0).
    #[must_use]
    pub fn extension_control(mut self, dz: f64) -> Self {
        self.rod = self.rod.with_control(Control::Extension);
        self.target = dz;
        self
    }

    /// Number of uniform mesh intervals.
    #[must_use]
    pub fn intervals(mut self, n: usize) -> Self {
        self.intervals = n;
        self
    }

    /// The number of mesh intervals this pull uses.
    #[must_use]
    pub fn mesh_intervals(&self) -> usize {
        self.intervals
    }

    /// Gauss points per interval (2..=7).
    #[must_use]
    pub fn points(mut self, m: usize) -> Self {
        self.points = m;
        self
    }

    /// First step Δs and its bounds [ds_min, ds_max].
    #[must_use]
    pub fn step(mut self, ds: f64, ds_min: f64, ds_max: f64) -> Self {
        self.ds0 = ds;
        self.ds_min = ds_min;
        self.ds_max = ds_max;
        self
    }

    /// Maximum number of accepted steps.
    #[must_use]
    pub fn max_steps(mut self, n: usize) -> Self {
        self.max_steps = n;
        self
    }

    /// Largest angle (radians) between successive tangents.
    #[must_use]
    pub fn max_angle(mut self, a: f64) -> Self {
        self.max_angle = a;
        self
    }

    /// Whether to locate folds precisely (otherwise only detect them).
    #[must_use]
    pub fn locate_folds(mut self, on: bool) -> Self {
        self.locate_folds = on;
        self
    }

    fn scale(&self) -> f64 {
        curve::force_scale(self.rod.coils())
    }

    fn validate(&self) -> Result<Collocation> {
        if self.intervals == 0 {
            return Err(Error::InvalidCount {
                name: "intervals",
                value: 0,
                allowed: "at least 1 mesh interval",
            });
        }
        if !(self.ds_min > 0.0 && self.ds_min <= self.ds0 && self.ds0 <= self.ds_max) {
            return Err(Error::InvalidArgument {
                name: "ds",
                value: self.ds0,
                allowed: "0 < ds_min ≤ ds ≤ ds_max",
            });
        }
        if !self.target.is_finite() {
            return Err(Error::InvalidArgument {
                name: "force_scaled",
                value: self.target,
                allowed: "a finite force",
            });
        }
        Ok(Collocation::new()
            .points(self.points)
            .mesh(Mesh::uniform(self.intervals)?)
            .max_newton(12))
    }

    /// Runs the pull, calling `observer` on every point and fold.
    ///
    /// Never fails: a run that cannot go on keeps its points and says why in
    /// [`PullRun::termination`]. At θ0 = 90° exactly the unstressed ring has
    /// both ends at the origin, so F_x, F_y are undetermined at rest and the
    /// start is singular ([`PullTermination::StartFailed`]); trace the planar
    /// case from a planar solution with [`crate::continuation`] instead (as
    /// the `rod` tests do).
    pub fn run<O: PullObserver>(&self, mut observer: O) -> PullRun {
        self.run_with(&mut observer)
    }

    /// [`Pull::run`] with a borrowed observer (to read what it collected
    /// afterwards).
    pub fn run_with<O: PullObserver>(&self, observer: &mut O) -> PullRun {
        let start = Instant::now();
        let mut run = PullRun {
            rod: self.rod,
            points: Vec::new(),
            folds: Vec::new(),
            termination: PullTermination::ReachedForce,
            steps: 0,
            rejected: 0,
            newton_iterations: 0,
            intervals: self.intervals,
            elapsed: Duration::ZERO,
        };
        run.termination = match self.trace(&mut run, observer) {
            Ok(t) => t,
            Err(e) => PullTermination::StartFailed(e),
        };
        run.elapsed = start.elapsed();
        run
    }

    fn trace<O: PullObserver>(
        &self,
        run: &mut PullRun,
        observer: &mut O,
    ) -> Result<PullTermination> {
        let solver = self.validate()?;
        let rod = self.rod;
        let scale = self.scale();
        let p0 = rod.parameters_at_rest();
        let (param, theta, stop) = match rod.control() {
            Control::Force => (Rod::FORCE, 1.0 / (scale * scale), self.target * scale),
            Control::Extension => (Rod::EXTENSION, 1.0, self.target),
        };
        let sign = if stop >= p0[param] { 1.0 } else { -1.0 };
        let s0 = solver.solve(&rod, |s: f64| rod.unstressed(s), &p0)?;
        // A second point a small load away starts the continuation, so that
        // its first step (Δs = ds0) cannot jump over the initial turn-and-
        // shear stretch at almost constant force.
        let mut p1 = p0;
        match rod.control() {
            Control::Force => p1[Rod::FORCE] = sign * 1e-4 * scale,
            Control::Extension => p1[Rod::EXTENSION] += sign * 1e-4,
        }
        let s1 = solver.solve(&rod, &s0, &p1)?;
        run.newton_iterations += u64::from(s0.newton().iterations + s1.newton().iterations);
        let cont = Continuation::new(param)
            .solver(solver)
            .weights(&weights(scale))
            .parameter_weight(theta)
            .step(sign * self.ds0)
            .step_bounds(self.ds_min, self.ds_max)
            .max_steps(self.max_steps)
            .max_angle(self.max_angle)
            .locate_tolerance(1e-9)
            .detect_folds(self.locate_folds)
            .detect_branch_points(false)
            .stop_at(stop);
        let offset = cont.distance(&s0, &s1)?;
        let eq = Equilibrium::new(rod, s0)?;
        let pt = self.point(&eq, 0.0, eq.solution().newton().iterations);
        run.points.push(pt);
        if observer.point(&eq, &pt).is_break() {
            return Ok(PullTermination::Stopped);
        }
        let mut trace = cont.steps(&rod, &s1)?;
        let outcome = self.follow(&mut trace, offset, run, observer);
        run.steps = trace.accepted();
        run.rejected = trace.rejected();
        run.newton_iterations += trace.newton_iterations();
        if let Some(t) = outcome? {
            return Ok(t);
        }
        Ok(match trace.termination() {
            Some(Termination::ParameterValue(_)) | None => PullTermination::ReachedForce,
            Some(Termination::MaxSteps(n)) => PullTermination::MaxSteps(*n),
            Some(Termination::Stopped) => PullTermination::Stopped,
            Some(Termination::Failed { error, .. }) => PullTermination::StepTooSmall {
                error: error.clone(),
            },
            Some(other) => PullTermination::StepTooSmall {
                error: Error::InvalidArgument {
                    name: "continuation",
                    value: f64::NAN,
                    allowed: match other {
                        Termination::Event(_) => "no user events in a pull",
                        _ => "a known continuation termination",
                    },
                },
            },
        })
    }

    /// Turns the continuation's points into pull points and folds, calling
    /// the observer; `Some` when the observer stopped the run.
    fn follow<O: PullObserver>(
        &self,
        trace: &mut Steps<'_, Rod>,
        offset: f64,
        run: &mut PullRun,
        observer: &mut O,
    ) -> Result<Option<PullTermination>> {
        let rod = self.rod;
        // dλ/ds at the last curve point, and (without fold location) its
        // equilibrium, which then stands for a fold detected after it.
        let mut last_dl = 0.0;
        let mut last_eq: Option<Equilibrium> = None;
        for p in trace {
            let dl = p.dparameter_ds();
            let detected = match p.kind() {
                PointKind::Fold => Some((
                    Equilibrium::new(rod, p.solution().clone())?,
                    offset + p.arclength(),
                )),
                _ if !self.locate_folds && last_dl * dl < 0.0 => {
                    last_eq.take().zip(run.points.last().map(|q| q.arclength))
                }
                _ => None,
            };
            if let Some((eq, arclength)) = detected {
                let kind = match (rod.control(), last_dl > 0.0) {
                    (Control::Force, true) => FoldKind::MaxForce,
                    (Control::Force, false) => FoldKind::MinForce,
                    (Control::Extension, true) => FoldKind::MaxExtension,
                    (Control::Extension, false) => FoldKind::MinExtension,
                };
                let fold = Fold {
                    kind,
                    index: run.points.len() - 1,
                    point: ForcePoint {
                        extension: eq.extension(),
                        force: eq.force(),
                        parameter: arclength,
                    },
                };
                run.folds.push(fold);
                if observer.fold(&eq, &fold).is_break() {
                    return Ok(Some(PullTermination::Stopped));
                }
            }
            if p.kind() == PointKind::Fold {
                continue;
            }
            let eq = Equilibrium::new(rod, p.solution().clone())?;
            let pt = self.point(&eq, offset + p.arclength(), p.newton_iterations());
            run.points.push(pt);
            if observer.point(&eq, &pt).is_break() {
                return Ok(Some(PullTermination::Stopped));
            }
            last_dl = dl;
            if !self.locate_folds {
                last_eq = Some(eq);
            }
        }
        Ok(None)
    }

    fn point(&self, eq: &Equilibrium, arclength: f64, its: u32) -> PullPoint {
        let (loops, planarity) = eq.loops_and_planarity();
        PullPoint {
            force: eq.force(),
            force_scaled: eq.force_scaled(),
            extension: eq.extension(),
            arclength,
            newton_iterations: its,
            loops,
            planarity,
        }
    }
}

/// Weights of the continuation norm (module docs).
fn weights(scale: f64) -> [f64; 13] {
    let mut w = [1.0; 13];
    for wi in &mut w[7..10] {
        *wi = 1.0 / (scale * scale);
    }
    for wi in &mut w[10..13] {
        *wi = 1e-3;
    }
    w
}
