//! Pulling the spring: pseudo-arclength continuation in the force (or the
//! extension) from the unstressed helix, with the pop-outs (folds) located.
//!
//! This driver is written on [`Collocation::solve`] alone (the rod's
//! phase condition needs the previous point as `y_ref`, and the arclength
//! condition is one more integral condition), so it owns its secant
//! predictor, step control and fold location; `crate::continuation` is the
//! general tool (used by the tests for branch points at θ0 = 90°).
//!
//! ```text
//!   unknowns  x = (y(·), λ),   λ = F_z
//!   equations rod BVP (collocation) and
//!             ⟨y − y_k, ẏ_k⟩ + θ (λ − λ_k) λ̇_k = Δs        (pseudo-arclength)
//!   ⟨a, b⟩  = Σ_i w_i ∫₀¹ a_i b_i ds,   w = 1 (r, q), 1/(2πn)⁴ (F), 1e-3 (M),
//!             θ = 1/(2πn)⁴  (forces measured in the paper's scale)
//! ```
//!
//! The tangent (ẏ_k, λ̇_k) is the normalised secant through the last two
//! points. The arclength condition is an integral condition of the
//! collocation system (its constant terms integrate to themselves), so the
//! whole step is one [`Collocation::solve`] with λ free. Step control: Δs ×1.5
//! after ≤ 3 Newton iterations, ×0.7 after ≥ 7, ×½ and retry on failure or
//! when the secant turns by more than the maximum angle (which keeps the
//! trace from jumping between nearby branches). A fold is a sign change of
//! λ̇; it is located by parabolic interpolation of λ(σ) along the arclength
//! through the point before it, to |Δσ| ≤ 1e-9.

use core::f64::consts::PI;
use std::ops::ControlFlow;
use std::time::{Duration, Instant};

use nalgebra::DMatrixViewMut;

use super::{Control, Equilibrium, Rod};
use crate::bvp::{Collocation, Mesh, Problem, Solution};
use crate::curve::{FoldKind, ForceExtension, ForcePoint};
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

/// A located fold (limit point in the force).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Fold {
    /// Maximum or minimum of the force.
    pub kind: FoldKind,
    /// F_z at the fold.
    pub force: f64,
    /// F_z/(2πn)² at the fold.
    pub force_scaled: f64,
    /// Δz at the fold.
    pub extension: f64,
    /// Index of the last accepted point before the fold.
    pub after_point: usize,
}

impl core::fmt::Display for Fold {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} at Δz = {:.6}, F/(2πn)² = {:.6}",
            self.kind, self.extension, self.force_scaled
        )
    }
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
    /// Located folds in order.
    pub folds: Vec<Fold>,
    /// Why the run ended.
    pub termination: PullTermination,
    /// Accepted steps.
    pub steps: usize,
    /// Rejected (retried) steps.
    pub rejected: usize,
    /// Total Newton iterations, fold location included.
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
        bounds.extend(self.folds.iter().map(|f| f.after_point + 1));
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
            writeln!(f, "  {fold}")?;
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
    /// | [`max_angle`](Self::max_angle) | 0.3 rad between successive secants |
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

    /// Largest angle (radians) between successive secants.
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
        let k = 2.0 * PI * f64::from(self.rod.coils());
        k * k
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
        let (param, theta, sign) = match rod.control() {
            Control::Force => (
                Rod::FORCE,
                1.0 / (scale * scale),
                if self.target >= 0.0 { 1.0 } else { -1.0 },
            ),
            Control::Extension => (
                Rod::EXTENSION,
                1.0,
                if self.target >= p0[Rod::EXTENSION] {
                    1.0
                } else {
                    -1.0
                },
            ),
        };
        let s0 = solver.solve(&rod, |s: f64| rod.unstressed(s), &p0)?;
        // A second point a small load away gives the first secant.
        let mut p1 = p0;
        match rod.control() {
            Control::Force => p1[Rod::FORCE] = sign * 1e-4 * scale,
            Control::Extension => p1[Rod::EXTENSION] += sign * 1e-4,
        }
        let s1 = solver.solve(&rod, &s0, &p1)?;
        run.newton_iterations += u64::from(s0.newton().iterations + s1.newton().iterations);

        let arc_solver = solver.clone().free_parameters(&[param]);
        let weights = weights(scale);
        let prev = Cached::new(s0, &weights, theta, param);
        let mut cur = Cached::new(s1, &weights, theta, param);
        let mut arclength = prev.distance(&cur);
        for (c, a) in [(&prev, 0.0), (&cur, arclength)] {
            let eq = Equilibrium::new(rod, c.solution.clone())?;
            let pt = self.point(&eq, a, c.solution.newton().iterations);
            run.points.push(pt);
            if observer.point(&eq, &pt).is_break() {
                return Ok(PullTermination::Stopped);
            }
        }
        let mut tangent = Tangent::secant(&prev, &cur, arclength);
        let mut ds = self.ds0;
        loop {
            if run.steps >= self.max_steps {
                return Ok(PullTermination::MaxSteps(self.max_steps));
            }
            let attempt = self.corrector(&rod, &arc_solver, &cur, &tangent, ds);
            let next = match attempt {
                Ok(sol) => {
                    run.newton_iterations += u64::from(sol.newton().iterations);
                    let next = Cached::new(sol, &weights, theta, param);
                    let step = cur.distance(&next);
                    let t_new = Tangent::secant(&cur, &next, step);
                    if tangent.cos_angle(&t_new, &weights, theta) < self.max_angle.cos() {
                        Err((
                            Error::InvalidArgument {
                                name: "step angle",
                                value: ds,
                                allowed: "secants turning by less than the maximum angle",
                            },
                            None,
                        ))
                    } else {
                        Ok((next, t_new, step))
                    }
                }
                Err(e) => Err((e, None::<()>)),
            };
            let (next, t_new, step) = match next {
                Ok(v) => v,
                Err((e, _)) => {
                    run.rejected += 1;
                    ds *= 0.5;
                    if ds < self.ds_min {
                        return Ok(PullTermination::StepTooSmall { error: e });
                    }
                    continue;
                }
            };
            run.steps += 1;
            let its = next.solution.newton().iterations;
            arclength += step;
            // A fold: the force turned between the previous secant and this one.
            if tangent.dlambda * t_new.dlambda < 0.0 {
                let kind = match (rod.control(), tangent.dlambda > 0.0) {
                    (Control::Force, true) => FoldKind::MaxForce,
                    (Control::Force, false) => FoldKind::MinForce,
                    (Control::Extension, true) => FoldKind::MaxExtension,
                    (Control::Extension, false) => FoldKind::MinExtension,
                };
                let located = if self.locate_folds {
                    self.locate(&rod, &arc_solver, &cur, &t_new, step, run)
                } else {
                    Ok(cur.solution.clone())
                };
                if let Ok(sol) = located {
                    let eq = Equilibrium::new(rod, sol)?;
                    let fold = Fold {
                        kind,
                        force: eq.force(),
                        force_scaled: eq.force() / scale,
                        extension: eq.extension(),
                        after_point: run.points.len() - 1,
                    };
                    run.folds.push(fold);
                    if observer.fold(&eq, &fold).is_break() {
                        return Ok(PullTermination::Stopped);
                    }
                }
            }
            let eq = Equilibrium::new(rod, next.solution.clone())?;
            let pt = self.point(&eq, arclength, its);
            run.points.push(pt);
            if observer.point(&eq, &pt).is_break() {
                return Ok(PullTermination::Stopped);
            }
            let reached = match rod.control() {
                Control::Force => pt.force_scaled,
                Control::Extension => pt.extension,
            };
            if sign * reached >= sign * self.target {
                return Ok(PullTermination::ReachedForce);
            }
            cur = next;
            tangent = t_new;
            ds = if its <= 3 {
                (ds * 1.5).min(self.ds_max)
            } else if its >= 7 {
                (ds * 0.7).max(self.ds_min)
            } else {
                ds
            };
        }
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

    /// One corrector solve on the hyperplane ⟨x − x_k, τ⟩ = σ from the
    /// predictor x_k + σ τ.
    fn corrector(
        &self,
        rod: &Rod,
        solver: &Collocation,
        cur: &Cached,
        tangent: &Tangent,
        sigma: f64,
    ) -> Result<Solution> {
        let problem = Arclength {
            rod,
            anchor: cur,
            tangent,
            sigma,
            weights: cur.weights,
            theta: cur.theta,
        };
        let mut p = *cur.parameters();
        p[cur.param] += sigma * tangent.dlambda;
        let guess = |s: f64| {
            let mut y = [0.0; 13];
            cur.solution.eval_into(s, &mut y);
            let t = tangent.at(s);
            for i in 0..13 {
                y[i] += sigma * t[i];
            }
            y
        };
        solver.solve(&problem, guess, &p)
    }

    /// Parabolic interpolation of λ(σ) along the hyperplanes through the
    /// point before the fold, to |Δσ| ≤ 1e-9.
    fn locate(
        &self,
        rod: &Rod,
        solver: &Collocation,
        before: &Cached,
        tangent: &Tangent,
        step: f64,
        run: &mut PullRun,
    ) -> Result<Solution> {
        let mut samples: Vec<(f64, f64, Option<Solution>)> = vec![(0.0, before.lambda(), None)];
        for sigma in [0.5 * step, step] {
            let sol = self.corrector(rod, solver, before, tangent, sigma)?;
            run.newton_iterations += u64::from(sol.newton().iterations);
            samples.push((sigma, sol.parameters()[before.param], Some(sol)));
        }
        for _ in 0..12 {
            let (a, b, c) = (&samples[0], &samples[1], &samples[2]);
            let (x0, x1, x2) = (a.0, b.0, c.0);
            let (f0, f1, f2) = (a.1, b.1, c.1);
            let num = (x1 - x0).powi(2) * (f1 - f2) - (x1 - x2).powi(2) * (f1 - f0);
            let den = (x1 - x0) * (f1 - f2) - (x1 - x2) * (f1 - f0);
            if den == 0.0 {
                break;
            }
            let x = x1 - 0.5 * num / den;
            if !x.is_finite() || (x - x1).abs() <= 1e-9 {
                break;
            }
            let sol = self.corrector(rod, solver, before, tangent, x)?;
            run.newton_iterations += u64::from(sol.newton().iterations);
            let f = sol.parameters()[before.param];
            samples.push((x, f, Some(sol)));
            // Keep the three samples closest to the new abscissa.
            samples.sort_by(|p, q| (p.0 - x).abs().total_cmp(&(q.0 - x).abs()));
            samples.truncate(3);
            samples.sort_by(|p, q| p.0.total_cmp(&q.0));
        }
        // The sample with the extreme force.
        let best = samples
            .into_iter()
            .filter_map(|s| s.2.map(|sol| (s.1, sol)))
            .max_by(|p, q| {
                let sgn = if p.0 > before.lambda() { 1.0 } else { -1.0 };
                (sgn * p.0).total_cmp(&(sgn * q.0))
            });
        best.map(|b| b.1).ok_or(Error::InvalidArgument {
            name: "fold",
            value: before.lambda(),
            allowed: "a fold bracketed by converged points",
        })
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

/// A solution with its values at the collocation points (the quadrature
/// nodes of every integral condition) cached.
struct Cached {
    solution: Solution,
    nodes: Vec<f64>,
    values: Vec<[f64; 13]>,
    quad: Vec<f64>,
    weights: [f64; 13],
    theta: f64,
    param: usize,
}

impl Cached {
    fn new(solution: Solution, weights: &[f64; 13], theta: f64, param: usize) -> Self {
        let nodes = solution.collocation_points();
        let cv = solution.collocation_values();
        let values = (0..nodes.len())
            .map(|k| {
                let mut y = [0.0; 13];
                for (i, yi) in y.iter_mut().enumerate() {
                    *yi = cv[(i, k)];
                }
                y
            })
            .collect();
        // Gauss weights of the composite rule, recovered per interval from
        // the node positions (the rule integrates polynomials of degree
        // 2m − 1, so solving the moment equations is exact).
        let quad = quadrature_weights(&solution, &nodes);
        Self {
            solution,
            nodes,
            values,
            quad,
            weights: *weights,
            theta,
            param,
        }
    }

    fn parameters(&self) -> &[f64; 3] {
        self.solution
            .parameters()
            .try_into()
            .expect("rod solutions have 3 parameters")
    }

    /// The continuation parameter λ.
    fn lambda(&self) -> f64 {
        self.parameters()[self.param]
    }

    fn index(&self, s: f64) -> Option<usize> {
        self.nodes.binary_search_by(|x| x.total_cmp(&s)).ok()
    }

    /// ‖x − y‖ in the continuation norm.
    fn distance(&self, other: &Cached) -> f64 {
        let (w, theta) = (&self.weights, self.theta);
        let mut t = 0.0;
        for k in 0..self.nodes.len() {
            let (a, b) = (&self.values[k], &other.values[k]);
            let mut v = 0.0;
            for i in 0..13 {
                v += w[i] * (a[i] - b[i]).powi(2);
            }
            t += self.quad[k] * v;
        }
        let dl = self.lambda() - other.lambda();
        (t + theta * dl * dl).sqrt()
    }
}

fn quadrature_weights(solution: &Solution, nodes: &[f64]) -> Vec<f64> {
    let m = solution.points_per_interval();
    let mesh = solution.mesh();
    let mut out = Vec::with_capacity(nodes.len());
    for j in 0..mesh.intervals() {
        let h = mesh.width(j);
        let t0 = mesh.points()[j];
        let c: Vec<f64> = (0..m).map(|k| (nodes[j * m + k] - t0) / h).collect();
        // Solve Σ_k w_k c_k^i = 1/(i+1), i = 0..m−1 (Vandermonde).
        let mut a = nalgebra::DMatrix::zeros(m, m);
        let mut b = nalgebra::DVector::zeros(m);
        for i in 0..m {
            for k in 0..m {
                a[(i, k)] = c[k].powi(i as i32);
            }
            b[i] = 1.0 / (i as f64 + 1.0);
        }
        let w = a
            .lu()
            .solve(&b)
            .unwrap_or_else(|| nalgebra::DVector::from_element(m, 1.0 / m as f64));
        out.extend(w.iter().map(|wk| wk * h));
    }
    out
}

/// The unit secant (ẏ, λ̇) at the collocation points.
struct Tangent {
    nodes: Vec<f64>,
    values: Vec<[f64; 13]>,
    quad: Vec<f64>,
    dlambda: f64,
    from: Solution,
    to: Solution,
    step: f64,
}

impl Tangent {
    fn secant(a: &Cached, b: &Cached, step: f64) -> Self {
        let values = a
            .values
            .iter()
            .zip(&b.values)
            .map(|(x, y)| {
                let mut t = [0.0; 13];
                for i in 0..13 {
                    t[i] = (y[i] - x[i]) / step;
                }
                t
            })
            .collect();
        Self {
            nodes: a.nodes.clone(),
            values,
            quad: a.quad.clone(),
            dlambda: (b.lambda() - a.lambda()) / step,
            from: a.solution.clone(),
            to: b.solution.clone(),
            step,
        }
    }

    /// The tangent at any s (from the two solutions' polynomials).
    fn at(&self, s: f64) -> [f64; 13] {
        if let Ok(k) = self.nodes.binary_search_by(|x| x.total_cmp(&s)) {
            return self.values[k];
        }
        let (mut a, mut b) = ([0.0; 13], [0.0; 13]);
        self.from.eval_into(s, &mut a);
        self.to.eval_into(s, &mut b);
        let mut t = [0.0; 13];
        for i in 0..13 {
            t[i] = (b[i] - a[i]) / self.step;
        }
        t
    }

    fn cos_angle(&self, other: &Tangent, w: &[f64; 13], theta: f64) -> f64 {
        let mut d = theta * self.dlambda * other.dlambda;
        let mut n1 = theta * self.dlambda * self.dlambda;
        let mut n2 = theta * other.dlambda * other.dlambda;
        for k in 0..self.nodes.len() {
            let (a, b) = (&self.values[k], &other.values[k]);
            for i in 0..13 {
                d += self.quad[k] * w[i] * a[i] * b[i];
                n1 += self.quad[k] * w[i] * a[i] * a[i];
                n2 += self.quad[k] * w[i] * b[i] * b[i];
            }
        }
        d / (n1 * n2).sqrt()
    }
}

/// The rod plus the pseudo-arclength condition as a second integral
/// condition, with λ = p[FORCE] free.
struct Arclength<'a> {
    rod: &'a Rod,
    anchor: &'a Cached,
    tangent: &'a Tangent,
    sigma: f64,
    weights: [f64; 13],
    theta: f64,
}

impl Problem for Arclength<'_> {
    fn dim(&self) -> usize {
        Rod::DIM
    }
    fn parameter_count(&self) -> usize {
        Rod::PARAMETERS
    }
    fn boundary_count(&self) -> usize {
        self.rod.boundary_count()
    }
    fn integral_count(&self) -> usize {
        2
    }
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        self.rod.rhs(s, y, p, f);
    }
    fn rhs_jacobian(
        &self,
        s: f64,
        y: &[f64],
        p: &[f64],
        dfdy: DMatrixViewMut<'_, f64>,
        dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        self.rod.rhs_jacobian(s, y, p, dfdy, dfdp)
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        self.rod.boundary(y0, y1, p, g);
    }
    fn boundary_jacobian(
        &self,
        y0: &[f64],
        y1: &[f64],
        p: &[f64],
        dg0: DMatrixViewMut<'_, f64>,
        dg1: DMatrixViewMut<'_, f64>,
        dgp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        self.rod.boundary_jacobian(y0, y1, p, dg0, dg1, dgp)
    }
    fn integrand(&self, s: f64, y: &[f64], y_ref: &[f64], p: &[f64], h: &mut [f64]) {
        self.rod.integrand(s, y, y_ref, p, &mut h[..1]);
        let (a, t) = match self.anchor.index(s) {
            Some(k) => (self.anchor.values[k], self.tangent.values[k]),
            None => {
                let mut a = [0.0; 13];
                self.anchor.solution.eval_into(s, &mut a);
                (a, self.tangent.at(s))
            }
        };
        let mut v = 0.0;
        for i in 0..13 {
            v += self.weights[i] * (y[i] - a[i]) * t[i];
        }
        let dl = p[self.anchor.param] - self.anchor.lambda();
        h[1] = v + self.theta * dl * self.tangent.dlambda - self.sigma;
    }
    fn integrand_jacobian(
        &self,
        s: f64,
        y: &[f64],
        y_ref: &[f64],
        p: &[f64],
        mut dhdy: DMatrixViewMut<'_, f64>,
        mut dhdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        self.rod
            .integrand_jacobian(s, y, y_ref, p, dhdy.rows_mut(0, 1), dhdp.rows_mut(0, 1));
        let t = self.tangent.at(s);
        for i in 0..13 {
            dhdy[(1, i)] = self.weights[i] * t[i];
        }
        dhdp[(1, self.anchor.param)] = self.theta * self.tangent.dlambda;
        true
    }
}
