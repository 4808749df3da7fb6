//! Pulling the spring: pseudo-arclength continuation in the force (or the
//! extension) from the unstressed helix to a [`Target`], with the folds
//! located.
//!
//! [`Pull`] is a thin rod-specific front end to [`crate::continuation`]: it
//! chooses the norm, the start and the stop, and turns the continuation's
//! points into a [`ForceExtension`] curve with a loop count per point and
//! located [`Fold`]s. The run's vocabulary (points, observers, the
//! termination) is the continuation's.
//!
//! ```text
//!   unknowns  x = (y(·), λ),   λ = F_z  (or Δz under extension control)
//!   equations rod BVP (collocation) and
//!             ⟨y − y_k, ẏ_k⟩ + θ (λ − λ_k) λ̇_k = Δs        (pseudo-arclength)
//!   ⟨a, b⟩  = Σ_i w_i ∫₀¹ a_i b_i ds,   w = 1 (r, q), 1/((2πn)²B)² (F), 1e-3 (M),
//!             θ = 1/((2πn)²B)² under force control, 1 under extension control
//! ```
//!
//! The run starts from the rest state (λ = 0, or Δz at rest) with a first
//! step Δs equal to the distance, in this norm, to the equilibrium a load
//! δ = min(1e-4, |target|/2) away (F/((2πn)²B) = ±δ, or Δz ± δ): small
//! enough not to jump over the helix's initial turn-and-shear stretch at
//! almost constant force, and never past the target.
//!
//! The accuracy is a [`Pull::tolerance`] (default 1e-6) in the plane
//! (Δz, F/((2πn)²B)) of the paper's plots, handed to the continuation
//! ([`Continuation::tolerance`], with that plane as its diagram): it sets
//! the collocation degree m (4 down to 1e-4, 5 down to 1e-7, 6 down to
//! 1e-9, 7 below), the first mesh (n·1.45·tol^(−1/2m) intervals, at least
//! 3 per coil, calibrated on the paper's spring), and through the
//! continuation the mesh during the run (points checked against the
//! halved mesh, remeshed by equidistribution), the steps (the quintic
//! Hermite interpolation error, the cubic's at 1e-3 and looser, the tangent's angle, at most 0.4 rad, and its turn
//! in the plane, the corrector's drift), the Newton and the location
//! tolerances. What the run achieved is [`PullRun::estimate`]; where loops
//! sliding along the rod stall the corrector, [`Pull::relax_to`] lets the
//! run go on from its last point at looser tolerances. Branch-point
//! detection is off (the rod's phase condition keeps the pull free of
//! them, as the `rod` tests check with it on), which lets the corrector
//! keep its factorisation. The target is a stop of the continuation: the
//! last point is located on it.

mod drive;
mod recorder;
mod relax;
mod run;
mod start;

pub use relax::Relaxation;
pub use run::PullRun;
pub use start::Start;

use start::relaxed_rest;

use super::Rod;
use crate::bvp::{Collocation, Mesh, Solution};
use crate::continuation::{Continuation, Output};
use crate::error::{Error, Result};
use crate::load::{Control, Target};

/// Pulls a [`Rod`] from its rest state to a [`Target`] by pseudo-arclength
/// continuation (module docs: [`crate::rod`]).
///
/// A [symmetric](Rod::symmetric) rod is pulled on its half: the equilibria
/// symmetric end to end, which the pull from rest follows on the whole rod
/// too (the paper's spring: the same folds to 1e-7, in less than half the
/// time), without the nearly free antisymmetric modes that stall the whole
/// rod on long springs' unlooping plateaus and where loops slide
/// (docs/ACCURACY.md, "Long springs"). Its mesh starts with half the
/// intervals; the curve, folds and loop counts are the whole rod's.
///
/// ```no_run
/// use hockle::rod::{Pull, Rod};
/// use hockle::{Stiffness, Target};
/// let rod = Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
/// let run = Pull::new(rod, Target::Force(3.0)).run(())?;
/// assert_eq!(run.folds().len(), 6); // the paper's cascade 4 → 3 → 2 → 1
/// assert!(run.reached_target());
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Pull {
    rod: Rod,
    target: Target,
    tolerance: f64,
    intervals: Option<usize>,
    points: Option<usize>,
    first_step: Option<f64>,
    ds_min: f64,
    /// `None`: [`Pull::largest_step`]'s default.
    ds_max: Option<f64>,
    max_steps: usize,
    max_angle: f64,
    locate_folds: bool,
    pin_slides: bool,
    /// The loosest tolerance the pull may go on at ([`Pull::relax_to`]).
    relax_to: Option<f64>,
}

/// Largest load, in the controlled quantity, of the second equilibrium that
/// sets the first step (module docs).
const START_LOAD: f64 = 1e-4;

/// The first step of a pull whose small-load equilibrium (`START_LOAD`)
/// cannot be solved: a step in the continuation norm that the step control
/// doubles in a few accepted steps where it is too small.
const FALLBACK_STEP: f64 = 1e-3;

/// Under force control the largest step is at least the target over this
/// ([`Pull::largest_step`]).
const LARGEST_STEPS_TO_TARGET: f64 = 100.0;

/// `rod` solved at `parameters` from `guess`, or `None` where Newton
/// fails or the system is singular there (the start's re-solves, which
/// then keep what they had); any other error is returned.
fn solve_unless_singular(
    solver: &Collocation,
    rod: &Rod,
    guess: &Solution,
    parameters: &[f64],
) -> Result<Option<Solution>> {
    match solver.solve(rod, guess, parameters) {
        Ok(s) => Ok(Some(s)),
        Err(
            Error::NewtonDiverged { .. }
            | Error::NewtonNotConverged { .. }
            | Error::SingularJacobian { .. },
        ) => Ok(None),
        Err(e) => Err(e),
    }
}

/// Mesh intervals per coil of the first mesh (the start's check refines or
/// coarsens it).
const START_INTERVALS_PER_COIL: usize = 3;

impl Pull {
    /// The tolerance of a pull that is not given one, in (Δz,
    /// F/((2πn)²B)): the paper's folds to 1e-6.
    pub const DEFAULT_TOLERANCE: f64 = 1e-6;

    /// The loosest tolerance a pull runs at, its own or going on
    /// ([`Pull::tolerance`], [`Pull::relax_to`]): 1e-1 in (Δz,
    /// F/((2πn)²B)), a tenth of the plot's unit.
    pub const LOOSEST_TOLERANCE: f64 = 1e-1;

    /// A pull of `rod` to `target` (force control for [`Target::Force`],
    /// extension control for [`Target::Extension`]) with the defaults:
    ///
    /// | setting | default |
    /// |---|---|
    /// | [`tolerance`](Self::tolerance) | 1e-6 in (Δz, F/((2πn)²B)), 1e-12 ≤ tol ≤ 1e-1 |
    /// | [`points`](Self::points) | from the tolerance: m = 4 (tol ≥ 1e-4), 5 (≥ 1e-7), 6 (≥ 1e-9), 7 |
    /// | [`intervals`](Self::intervals) | adaptive, from 3n equidistributed intervals (n coils) |
    /// | [`step`](Self::step) | first Δs: the distance to a load 1e-4 away (module docs); within [1e-7, [`largest_step`](Self::largest_step)] (1, or under force control a hundredth of the target where larger) |
    /// | [`max_steps`](Self::max_steps) | 20 000 |
    /// | [`max_angle`](Self::max_angle) | 0.4 rad between successive tangents |
    /// | [`locate_folds`](Self::locate_folds) | yes |
    /// | [`pin_slides`](Self::pin_slides) | no (experimental) |
    /// | [`relax_to`](Self::relax_to) | none: the run ends where its corrector fails |
    ///
    /// Setters do not fail; [`Pull::check`] (called by [`Pull::run`] and
    /// [`Pull::start`] before any work) validates every setting and the
    /// target.
    #[must_use]
    pub fn new(rod: Rod, target: Target) -> Self {
        Self {
            rod: rod.with_control(target.control()),
            target,
            tolerance: Self::DEFAULT_TOLERANCE,
            intervals: None,
            points: None,
            first_step: None,
            ds_min: 1e-7,
            ds_max: None,
            max_steps: 20_000,
            max_angle: 0.4,
            locate_folds: true,
            pin_slides: false,
            relax_to: None,
        }
    }

    /// The same pull to another target.
    #[must_use]
    pub fn to(mut self, target: Target) -> Self {
        self.rod = self.rod.with_control(target.control());
        self.target = target;
        self
    }

    /// The accuracy wanted on the curve and its folds, in the plane
    /// (Δz, F/((2πn)²B)) of the paper's plots (max-norm distance; see
    /// [`Continuation::tolerance`]): from it the pull chooses the
    /// collocation degree, the mesh (during the run), the steps, and the
    /// Newton and location tolerances, and reports what it achieved in
    /// [`PullRun::estimate`].
    #[must_use]
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tolerance = tol;
        self
    }

    /// Expert override: a fixed uniform mesh of `n` intervals (no
    /// adaptation; the error is still measured and reported). On a
    /// [symmetric](Rod::symmetric) rod they cover its half: the whole rod's
    /// equilibrium has 2n.
    #[must_use]
    pub fn intervals(mut self, n: usize) -> Self {
        self.intervals = Some(n);
        self
    }

    /// Expert override: Gauss points per interval (2..=7).
    #[must_use]
    pub fn points(mut self, m: usize) -> Self {
        self.points = Some(m);
        self
    }

    /// First step Δs and the bounds [ds_min, ds_max] of every step.
    #[must_use]
    pub fn step(mut self, ds: f64, ds_min: f64, ds_max: f64) -> Self {
        self.first_step = Some(ds);
        self.ds_min = ds_min;
        self.ds_max = Some(ds_max);
        self
    }

    /// The largest step Δs: the one set by [`step`](Self::step), else 1
    /// (in F/((2πn)²B), the continuation norm's force unit), or under force
    /// control a hundredth of the target force where that is larger, so
    /// that a pull to a large force is not a walk of unit steps (the
    /// tolerance sets the steps below the cap: the paper's spring reaches
    /// F/((2πn)²B) = 3·10⁵ in about 300 steps at tolerance 1e-4).
    #[must_use]
    pub fn largest_step(&self) -> f64 {
        self.ds_max.unwrap_or(match self.target {
            Target::Force(f) => (f.abs() / LARGEST_STEPS_TO_TARGET).max(1.0),
            Target::Extension(_) => 1.0,
        })
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

    /// Whether to locate folds precisely (otherwise only detect them, at the
    /// last point before each).
    #[must_use]
    pub fn locate_folds(mut self, on: bool) -> Self {
        self.locate_folds = on;
        self
    }

    /// Experimental: pin loops that slide along the rod where the
    /// corrector's Newton stalls on them
    /// ([`Continuation::pin_slides`]). At negative ν the loops left in the
    /// rod at high tension slide at an exponentially small cost and the
    /// unpinned pull crawls or fails there; pinned, the paper's spring with
    /// ν = −0.5 reaches F/((2πn)²B) = 14 within 1e-6 in about a second. It
    /// can fail where the loops stop sliding freely (near a pop-out, or at
    /// higher forces): docs/ACCURACY.md, "Sliding loops, pinned".
    #[must_use]
    pub fn pin_slides(mut self, on: bool) -> Self {
        self.pin_slides = on;
        self
    }

    /// Where the corrector fails at the shortest step (Newton stalled or
    /// drifted: [`Error::NewtonNotConverged`], [`Error::NewtonDiverged`],
    /// [`Error::CorrectorDrifted`]), go on from the last point at ten times
    /// the tolerance, and again, up to `loosest`. The last point is solved
    /// again at its parameters on the looser pull's first mesh (where that
    /// does not converge, on meshes equidistributed on its shape, or on its
    /// own) and the run goes on from there with the looser pull's degree,
    /// steps and Newton tolerance; each resumption is a [`Relaxation`] of
    /// the run ([`PullRun::relaxations`]). Every point up to the first is
    /// the run's at the tolerance asked for, bit for bit, and a run that
    /// does not fail is the same run; the estimate is the largest of the
    /// segments', so [`PullRun::meets_tolerance`] says whether the looser
    /// part met the tolerance asked. The step limit counts every segment's
    /// steps.
    ///
    /// What it is for: loops left in the rod that slide along it (at high
    /// tension for ν < 0, at A/B = 100 past most pop-outs), where Newton's
    /// corrections stall at 1e-9–1e-8 relative, above the corrector's
    /// tolerance at the default 1e-6 (1e-10), and below it at 1e-5 and 1e-4
    /// (docs/ACCURACY.md, "Going on from the failure"). It is no cure for
    /// sliding loops: where they slide freely over a long stretch the
    /// looser segments fail too, and a looser corrector can follow the
    /// slide itself, along a branch whose plot retraces the curve (n = 7 at
    /// (89°, 100, 0.05) stretched went on to eleven force maxima and ended
    /// at F/((2πn)²B) = 83 with two loops held, where a stretch from rest
    /// at 1e-5 passes the six pop-outs and ends at 1.15). The
    /// [`Relaxation`]s say where the curve is the looser runs'; a run from
    /// rest at the looser tolerance is the other way to try. Where no
    /// looser tolerance could even resume (its re-solve of the last point
    /// fails on every mesh: the paper's spring with 40 coils at 1e-2,
    /// docs/ACCURACY.md "Long springs"), the run has no relaxation and ends
    /// with the tight run's corrector failure.
    ///
    /// `loosest` must lie in [tolerance, 1e-1] ([`Pull::check`]).
    ///
    /// ```no_run
    /// use hockle::rod::{Pull, Rod};
    /// use hockle::{Stiffness, Target};
    /// // n = 6 at A/B = 100 stretched: the default ends after four pop-outs
    /// // (its loops slide); going on at 1e-5 it passes the fifth.
    /// let rod = Rod::new(6, 89.5_f64.to_radians(), Stiffness::nikolai(100.0, 0.05)?)?;
    /// let run = Pull::new(rod, Target::Extension(0.99)).relax_to(1e-4).run(())?;
    /// assert!(run.reached_target());
    /// for r in run.relaxations() {
    ///     println!("from point {} at {:.0e}: {}", r.from_point, r.tolerance, r.because);
    /// }
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn relax_to(mut self, loosest: f64) -> Self {
        self.relax_to = Some(loosest);
        self
    }

    /// The rod, with the control of the target.
    #[must_use]
    pub fn rod(&self) -> &Rod {
        &self.rod
    }

    /// The target.
    #[must_use]
    pub fn target(&self) -> Target {
        self.target
    }

    /// The number of mesh intervals the pull starts with: the override, or
    /// from the tolerance and m, n·c_m·tol^(−1/2m) (the superconvergent
    /// error ∝ (n/N)^2m of the folds, c_m calibrated on the paper's
    /// spring, where the third pop-out needs the finest mesh), and never
    /// fewer than 3 per coil. The run refines it where its checks ask.
    #[must_use]
    pub fn mesh_intervals(&self) -> usize {
        self.intervals.unwrap_or_else(|| {
            let m = self.points_per_interval();
            let per_coil = 1.45 * self.tolerance.powf(-0.5 / m as f64);
            // (a symmetric rod's problem is its half: n/2 coils)
            let n = f64::from(self.rod.coils()) * if self.rod.is_symmetric() { 0.5 } else { 1.0 };
            ((n * per_coil).ceil() as usize)
                .max((START_INTERVALS_PER_COIL as f64 * n).ceil() as usize)
        })
    }

    /// The collocation points per interval m: the override, or the
    /// tolerance's choice.
    #[must_use]
    pub fn points_per_interval(&self) -> usize {
        self.points.unwrap_or(match self.tolerance {
            t if t >= 1e-4 => 4,
            t if t >= 1e-7 => 5,
            t if t >= 1e-9 => 6,
            _ => 7,
        })
    }

    /// Validates every setting and the target, and returns the collocation
    /// solver the pull will use. No equation is solved.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for a mesh or Gauss-point count out of range;
    /// [`Error::InvalidArgument`] for step sizes that are not
    /// 0 < ds_min ≤ |ds| ≤ ds_max < ∞, a force scale (2πn)²B whose square
    /// leaves the double range (B outside about [1e-154, 1e154]/(2πn)²), a maximum angle outside (0, π], or no
    /// steps; [`Error::UnreachableTarget`] for a target the spring cannot
    /// reach (for extensions, judged against cos θ0 when the rod is
    /// helical; for forces, also one whose physical value f·(2πn)²B is
    /// beyond the largest double); [`Error::OutsideModel`] at θ0 = 90°, where the unstressed
    /// ring closes on itself and its end forces are undetermined.
    pub fn check(&self) -> Result<Collocation> {
        if self.rod.theta0() == core::f64::consts::FRAC_PI_2 {
            return Err(Error::OutsideModel {
                model: "rod",
                assumption: "the pull starts from the unstressed helix, whose ends meet at θ0 = 90° \
                             (a closed ring: end forces undetermined); use θ0 < 90°, or continue \
                             a planar solution in θ0 with `continuation`",
            });
        }
        let rest = if self.rod.is_helical() {
            self.rod.theta0().cos()
        } else {
            f64::NAN
        };
        self.target.validate(rest)?;
        if let Target::Force(f) = self.target
            && !(f * self.rod.scale().value()).is_finite()
        {
            // the physical force F = f·(2πn)²B is beyond the largest double
            return Err(Error::UnreachableTarget {
                target: self.target,
                rest_extension: rest,
            });
        }
        let scale = self.rod.scale().value();
        let theta = 1.0 / (scale * scale);
        if !(theta.is_finite() && theta > 0.0) {
            // the continuation norm weighs forces by 1/((2πn)²B)²
            return Err(Error::InvalidArgument {
                name: "bending stiffness B",
                value: self.rod.stiffness().b(),
                allowed: "(2πn)²B between about 1e-154 and 1e154: the pull's norm squares it",
            });
        }
        // (audit15) the strains are M/K: a stiffness whose reciprocal
        // overflows (A/B = 1e-320) reached the start and failed there with
        // a non-finite Jacobian blamed on the problem
        let k = self.rod.stiffness();
        for (name, v) in [
            ("stiffness A", k.a()),
            ("stiffness B", k.b()),
            ("stiffness C", k.c()),
        ] {
            if !(1.0 / v).is_finite() {
                return Err(Error::InvalidArgument {
                    name,
                    value: v,
                    allowed: "a stiffness whose reciprocal is finite (at least 1/f64::MAX): the rod's strains are M/K",
                });
            }
        }
        let ds = self.first_step.unwrap_or(self.ds_min);
        if !(self.ds_min > 0.0
            && self.ds_min <= ds.abs()
            && ds.abs() <= self.largest_step()
            && self.largest_step().is_finite())
        {
            return Err(Error::InvalidArgument {
                name: "step",
                value: ds,
                allowed: "0 < ds_min ≤ |ds| ≤ ds_max < ∞",
            });
        }
        if !(self.max_angle > 0.0 && self.max_angle <= core::f64::consts::PI) {
            return Err(Error::InvalidArgument {
                name: "max_angle",
                value: self.max_angle,
                allowed: "an angle in (0, π] radians",
            });
        }
        if self.max_steps == 0 {
            return Err(Error::InvalidCount {
                name: "max_steps",
                value: 0,
                allowed: "at least 1 step",
            });
        }
        if !(1e-12..=Self::LOOSEST_TOLERANCE).contains(&self.tolerance) {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: self.tolerance,
                allowed: "1e-12 ≤ tol ≤ 1e-1 (in Δz and F/((2πn)²B))",
            });
        }
        if let Some(loosest) = self.relax_to
            && !(self.tolerance..=Self::LOOSEST_TOLERANCE).contains(&loosest)
        {
            return Err(Error::InvalidArgument {
                name: "relax_to",
                value: loosest,
                allowed: "a tolerance between the pull's own and 1e-1",
            });
        }
        let solver = Collocation::new()
            .points(self.points_per_interval())
            .mesh(Mesh::uniform(self.mesh_intervals())?)
            .max_newton(12);
        solver.validate()?;
        Ok(solver)
    }

    /// Solves the rest state and prepares the continuation: the first half
    /// of [`Pull::run`], for users who drive the steps themselves
    /// ([`Start::steps`]).
    ///
    /// # Errors
    /// As [`Pull::check`]; a typed solver error if the rest state cannot be
    /// solved (with custom intrinsic strains far from the helix's); for a
    /// non-helical rod, [`Error::UnreachableTarget`] if an extension target
    /// equals the solved rest extension.
    pub fn start(&self) -> Result<Start> {
        let solver = self.check()?;
        let rod = self.rod;
        let scale = rod.scale().value();
        let mut p0 = rod.parameters_at_rest();
        let rest = relaxed_rest(&solver, &rod, &p0)?;
        let rest_extension = rod.extension_of(&rest);
        p0[Rod::EXTENSION] = rest_extension;
        let (param, theta, stop, from) = match self.target {
            Target::Force(f) => (Rod::FORCE, 1.0 / (scale * scale), f * scale, 0.0),
            Target::Extension(dz) => {
                self.target.validate(rest_extension)?;
                (Rod::EXTENSION, 1.0, dz, rest_extension)
            }
        };
        // the plane of the paper's plots: (F/((2πn)²B), Δz) under force
        // control, (Δz, F/((2πn)²B)) under extension control
        let (output, lambda_scale, output_scale) = match self.target {
            // (Δz = 2 z(½) on a symmetric rod's half)
            Target::Force(_) => (
                Output::EndValue {
                    component: 2,
                    right: true,
                },
                1.0 / scale,
                if rod.is_symmetric() { 2.0 } else { 1.0 },
            ),
            // the end force F_z = y₉(0) (the force is a state of the rod)
            Target::Extension(_) => (
                Output::EndValue {
                    component: 9,
                    right: false,
                },
                1.0,
                1.0 / scale,
            ),
        };
        let sign = if stop >= from { 1.0 } else { -1.0 };
        // The force-controlled rest with its own Δz as the extension is an
        // equilibrium of the extension-controlled rod already; the solve
        // re-converges it on that problem. Where that solve is singular (a
        // straight rod: ∂Δz/∂F = 0 at Δz = 1) and its Newton fails, the
        // rest is kept as it is.
        let rest = if rod.control() == Control::Extension {
            solve_unless_singular(&solver, &rod, &rest, &p0)?.unwrap_or(rest)
        } else {
            rest
        };
        let cont = Continuation::new(param)
            .solver(solver.clone())
            .weights(&rod.norm_weights())
            .parameter_weight(theta)
            .step_bounds(self.ds_min, self.largest_step())
            .max_steps(self.max_steps)
            .max_angle(self.max_angle)
            .tolerance(self.tolerance)
            .adapt_mesh(self.intervals.is_none())
            .pin_slides(self.pin_slides)
            .diagram(output, lambda_scale, output_scale)
            .detect_folds(self.locate_folds)
            .detect_branch_points(false)
            .stop_at(stop);
        let ds = match self.first_step {
            Some(ds) => ds.abs(),
            None => {
                // A second equilibrium a small load δ away measures the
                // first step in the continuation norm.
                let delta = START_LOAD.min(0.5 * (self.target.value() - from).abs());
                let mut p1 = p0;
                match self.target {
                    Target::Force(_) => p1[Rod::FORCE] = sign * delta * scale,
                    Target::Extension(_) => p1[Rod::EXTENSION] += sign * delta,
                }
                // (where that equilibrium cannot be solved, e.g. a straight
                // rod compressed at its buckling load, a singular point of
                // this solve, the first step is FALLBACK_STEP and the step
                // control grows it)
                match solve_unless_singular(&solver, &rod, &rest, &p1)? {
                    Some(near) => cont.distance(&rest, &near)?,
                    None => FALLBACK_STEP,
                }
                .clamp(self.ds_min, self.largest_step())
            }
        };
        Ok(Start {
            rod,
            target: self.target,
            continuation: cont.step(sign * ds),
            rest,
        })
    }
}
