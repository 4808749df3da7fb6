//! The mesh error of a run with a tolerance, measured, and the remeshing
//! it asks for.
//!
//! The check: a point x with tangent τ is carried onto the mesh with every
//! interval halved (through its collocation polynomial) and corrected there
//! on the hyperplane ⟨· − x, τ⟩ = 0; the distance in the diagram's plane
//! between the two is the error of x, up to the error of the halved mesh,
//! 2^(−2m) times smaller where the collocation superconverges at the mesh
//! points and in the parameters (de Boor & Swartz 1973); the estimate is
//! twice that distance (`MESH_SAFETY`). Near a fold of λ
//! the hyperplane crosses the halved mesh's branch near its fold, so the
//! same check measures the error of the fold. Where the halved mesh's
//! Newton stalls on a near-null mode (loops sliding along a rod) at a
//! relative correction ≤ `STALLED_FLOOR`, its point stands if the
//! correction left would move it across the branch by at most
//! `STALLED_ACROSS` of the tolerance, and that distance is added to the
//! check's difference (before: an error, an estimate of ∞).
//!
//! The remesh: the current point and tangent are carried onto a new mesh
//! that equidistributes the density ‖y^(m+1)‖^(1/(m+1)) (as
//! [`Collocation::tolerance`](crate::bvp::Collocation::tolerance) does),
//! with N·(e/(tol/4))^(1/2m) intervals for a measured error e, and the
//! point is corrected on the hyperplane through it (the continuation goes
//! on from there).

use super::Steps;
use super::corrector::{
    STALLED_ACROSS, STALLED_FLOOR, STUCK_FLOOR, border_rhs_solution, correction_across_on,
    refine_border_solution, set_hyperplane, stalled,
};
use super::norm::IntegralNorm;
use crate::bvp::system::{State, System};
use crate::bvp::{
    Mesh, NewtonOptions, Problem, density, equidistribute, newton, newton_pinned, state_on_mesh,
};
use crate::error::{Error, Result};

/// The error of a point is estimated as this multiple of its distance to
/// the halved mesh's: the distance is e_N − e_2N with e_2N ≈ 2^(−2m) e_N,
/// so e_N ≈ 2^2m/(2^2m − 1) times it (at most 4/3, for m = 1), and the rest
/// covers meshes not yet in the asymptotic regime (measured on the paper's
/// spring and two others in `tests/rod/tolerance.rs`: the distance is
/// 0.999 of the true error there).
const MESH_SAFETY: f64 = 2.0;

/// How often [`Steps::fold_behind`] doubles its search back from half the
/// step: to 2⁹ half-steps at most. A remesh moves x₀ by its mesh error,
/// which is below what the accepted step allowed, so the fold it crossed
/// lies within about a step; bounded only by the largest step, the search
/// made ~10³ corrector attempts where that step is 10²⁹⁸ (a pull to
/// F/((2πn)²B) = 10³⁰⁰).
const FOLD_BEHIND_DOUBLINGS: u32 = 9;

/// What a run with a tolerance achieved (see
/// [`Continuation::tolerance`](super::Continuation::tolerance)), in the
/// plane of the diagram.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct ErrorEstimate {
    /// The largest error of a point measured against the halved mesh
    /// (over the checks; the error of the located points is included).
    pub mesh: f64,
    /// The largest error of a located point (fold, branch point, stop,
    /// event) measured against the halved mesh.
    pub located: f64,
    /// The largest interpolation error estimate of a step's quintic
    /// Hermite interpolant.
    pub interpolation: f64,
    /// The largest distance across the branch, to first order, between a
    /// point pinned along near-null modes and the equilibrium the modes
    /// would slide to (0 where nothing was pinned; see
    /// [`Continuation::pin_slides`](super::Continuation::pin_slides)).
    #[cfg_attr(feature = "serde", serde(default))]
    pub pinned: f64,
    /// The largest distance across the branch, to first order, by which
    /// the Newton correction left at a point kept where Newton stalled
    /// above its tolerance would move it (the rounding floor of a nearly
    /// singular system; 0 where no point was kept so).
    #[cfg_attr(feature = "serde", serde(default))]
    pub stalled: f64,
    /// Points checked against the halved mesh.
    pub checks: u32,
    /// Remeshes (finer or coarser) during the run.
    pub remeshes: u32,
    /// The mesh intervals at the end of the run.
    pub intervals: usize,
    /// The largest mesh of the run.
    pub max_intervals: usize,
}

impl ErrorEstimate {
    /// The estimated error of the curve between its points: the mesh error
    /// plus the solves' ([`solves`](Self::solves)) plus the interpolation
    /// error.
    #[must_use]
    pub fn curve(&self) -> f64 {
        self.mesh + self.solves() + self.interpolation
    }

    /// The error of the points' solves beside the mesh's: the pinning's
    /// plus the stalled Newtons'.
    #[must_use]
    pub fn solves(&self) -> f64 {
        self.pinned + self.stalled
    }

    /// The run's estimated error as a whole: the larger of the located
    /// points' (their mesh error plus the solves') and the curve's.
    #[must_use]
    pub fn overall(&self) -> f64 {
        (self.located + self.solves()).max(self.curve())
    }

    /// The estimate of a run continued by another from its last point
    /// (`later`): the larger of each error, the checks and remeshes of
    /// both, the mesh at the end of `later` and the largest of either.
    #[must_use]
    pub(crate) fn followed_by(&self, later: &Self) -> Self {
        Self {
            mesh: self.mesh.max(later.mesh),
            located: self.located.max(later.located),
            interpolation: self.interpolation.max(later.interpolation),
            pinned: self.pinned.max(later.pinned),
            stalled: self.stalled.max(later.stalled),
            checks: self.checks + later.checks,
            remeshes: self.remeshes + later.remeshes,
            intervals: later.intervals,
            max_intervals: self.max_intervals.max(later.max_intervals),
        }
    }
}

impl core::fmt::Display for ErrorEstimate {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "estimated error: points {:.1e} (located {:.1e}",
            self.mesh, self.located
        )?;
        if self.pinned > 0.0 {
            write!(f, ", pinned {:.1e}", self.pinned)?;
        }
        if self.stalled > 0.0 {
            write!(f, ", stalled {:.1e}", self.stalled)?;
        }
        write!(
            f,
            "), interpolation {:.1e}; {} checks, {} remeshes, {} intervals (max {})",
            self.interpolation, self.checks, self.remeshes, self.intervals, self.max_intervals
        )
    }
}

/// The halved mesh of the current one, its system and norm (kept while the
/// mesh does not change).
pub(super) struct HalvedMesh<'a, P: Problem + ?Sized> {
    mesh: Mesh,
    sys: System<'a, P>,
    norm: IntegralNorm,
    /// The accepted-step count of the run at the last check.
    checked_at: usize,
}

impl<'a, P: Problem + ?Sized> Steps<'a, P> {
    /// The integral norm of the run on `mesh`.
    pub(super) fn norm_on(&self, mesh: &Mesh) -> IntegralNorm {
        let n = self.sys.n;
        let ones;
        let weights = match &self.cont.weights {
            Some(w) => w.as_slice(),
            None => {
                ones = vec![1.0; n];
                &ones
            }
        };
        IntegralNorm::new(
            (0..mesh.intervals()).map(|j| mesh.width(j)),
            &self.sys.tab.b,
            weights,
            self.cont.parameter_weight,
        )
    }

    /// The point of `x` and its slope along `t` in the diagram's plane.
    pub(super) fn diagram_of(&self, x: &State, t: &State) -> ([f64; 2], [f64; 2]) {
        self.cont
            .diagram
            .point_and_slope_on(&self.sys, &self.norm, self.cont.parameter, x, t)
    }

    /// ∫ φ ds of the density that equidistribution balances, at `x`.
    pub(super) fn density_integral(&self, x: &State) -> f64 {
        let sol = crate::bvp::Solution::interpolant(x, &self.mesh, &self.sys.tab, self.sys.n);
        density(&sol)
            .iter()
            .enumerate()
            .map(|(j, f)| f * self.mesh.width(j))
            .sum()
    }

    /// The distance in the diagram's plane between `x` and the branch on
    /// the halved mesh (module docs); for a `fold`, between `x` and the
    /// fold of the halved mesh's branch, found by the secant method on
    /// dλ/ds over the hyperplanes ⟨· − x, τ⟩ = σ (the hyperplane through x
    /// alone sees the fold's shift in λ but not along the branch).
    ///
    /// # Errors
    /// A failure of the halved mesh's corrector.
    pub(super) fn mesh_error(&mut self, x: &State, t: &State, fold: bool) -> Result<f64> {
        if self.halved.is_none() {
            let mesh = self.mesh.halved()?;
            let mut sys = System::new(
                self.sys.problem(),
                mesh.points().to_vec(),
                self.sys.tab.clone(),
                self.sys.free.clone(),
                1,
            )?;
            sys.linear = self.sys.linear;
            let norm = self.norm_on(&mesh);
            self.halved = Some(HalvedMesh {
                mesh,
                sys,
                norm,
                checked_at: usize::MAX,
            });
        }
        let (tab, n) = (self.sys.tab.clone(), self.sys.n);
        let q = self.cont.parameter;
        let coarse = self.diagram_of(x, t).0;
        // (a floor of 1e-13 sat in the rounding of the rod's corrections:
        // Newton "diverged" at |δ| ~ 1e-13 and the check reported ∞ on
        // fixed meshes at tol ≤ 1e-8; branch trade11)
        let opts = NewtonOptions {
            tol: (1e-2 * self.opts.tol).max(1e-12),
            max_iter: 12,
            stall: 1.0,
        };
        let floor = STUCK_FLOOR * self.opts.tol;
        // (the fold's tangent refined to this relative correction on
        // Newton's factorisation: its error δ moves dλ/ds by about δ and the
        // secant's zero by δ/|d²λ/ds²| in arclength, a fiftieth of the
        // location tolerance where |d²λ/ds²| ≥ 1; not below the difference
        // quotient's floor, ~1e-8 on the rod: where the refinement stalls
        // above it, a factorisation at the point takes over)
        let enough = (0.02 * self.locate_tolerance).max(1e-8);
        let across_allowed = self.cont.tolerance.map_or(0.0, |tol| STALLED_ACROSS * tol);
        let mut stalled_across: f64 = 0.0;
        let accepted = self.accepted;
        let Some(h) = self.halved.as_mut() else {
            unreachable!("set above")
        };
        // modes pinned on one mesh are pinned on the other
        if self.sys.is_pinning() {
            h.sys.enable_pinning();
        }
        // the last check's factorisation starts the corrector when it was
        // made in this step (the located points' checks and the new
        // point's, a fold's secant): from a few steps back its chord
        // contracted too slowly in 41 of 43 checks of the paper's spring
        // at tol 1e-2, and the failed try cost two residuals and solves
        let mut recent = std::mem::replace(&mut h.checked_at, accepted) == accepted;
        let free = h.sys.free.clone();
        let xs = state_on_mesh(x, &self.mesh, &tab, n, &h.mesh);
        let ts = state_on_mesh(t, &self.mesh, &tab, n, &h.mesh);
        let len = h.sys.y_ref.len();
        let (mut xcol, mut tcol) = (vec![0.0; len], vec![0.0; len]);
        h.sys.collocation_values(&xs, &mut xcol);
        h.sys.y_ref.clone_from(&xcol);
        // the point of the halved mesh's branch on ⟨· − x, τ⟩ = σ, with
        // dλ/ds there
        let mut on_plane = |sigma: f64, guess: &State| -> Result<(State, f64)> {
            set_hyperplane(
                &mut h.sys,
                &h.norm,
                (&xs, &ts),
                sigma,
                (&mut xcol, &mut tcol),
            );
            let mut fine = guess.clone();
            // a recent factorisation (same mesh) starts a chord corrector;
            // Newton refreshes it when it contracts too slowly
            // (and always after the first corrector of a fold's secant)
            let reuse = recent && h.sys.is_factored() && h.sys.factor_border().is_ok();
            recent = true;
            match newton(&mut h.sys, &mut fine, opts, reuse) {
                Ok(_) => {}
                // (robust10c) Newton stuck at its rounding floor above the
                // check's tolerance, within the corrector's (`STUCK_FLOOR`):
                // the point stands, instead of a check of ∞ that doubles
                // the mesh
                Err(
                    Error::NewtonDiverged { correction, .. }
                    | Error::NewtonNotConverged { correction, .. },
                ) if correction <= floor => {}
                // stalled on near-null modes in a run that pins: pinned, as
                // the corrector's
                Err(e) if stalled(&e) && h.sys.is_pinning() => {
                    if newton_pinned(&mut h.sys, &mut fine, opts).is_none() {
                        return Err(e);
                    }
                }
                // stalled on a near-null mode (loops sliding) at a relative
                // correction ≤ STALLED_FLOOR: the point stands where the
                // correction left would move it across the branch by at
                // most STALLED_ACROSS of the tolerance, that distance
                // added to the check's difference (as the corrector's
                // `stuck` at the shortest step)
                Err(
                    e @ (Error::NewtonDiverged { correction, .. }
                    | Error::NewtonNotConverged { correction, .. }),
                ) if correction <= STALLED_FLOOR => {
                    let moved = correction_across_on(
                        &mut h.sys,
                        &h.norm,
                        &self.cont.diagram,
                        q,
                        &fine,
                        &ts,
                    )?;
                    if moved.is_nan() || moved > across_allowed {
                        return Err(e);
                    }
                    stalled_across = stalled_across.max(moved);
                }
                Err(e) => return Err(e),
            }
            if !fold {
                return Ok((fine, f64::NAN));
            }
            // the tangent refined on Newton's last factorisation (at a point
            // of this corrector or the last one's), factored at `fine` only
            // where the refinement does not get there
            let tangent = match refine_border_solution(&mut h.sys, &fine, ts.clone(), enough) {
                Some(t) => t,
                None => {
                    h.sys.factor(&fine)?;
                    border_rhs_solution(&mut h.sys)?
                }
            };
            Ok((fine, tangent.p[q]))
        };
        let (mut fine, f0) = on_plane(0.0, &xs)?;
        if fold {
            // secant on σ ↦ dλ/ds, from σ = 0 and a probe a thousandth of
            // the step away
            let probe = 1e-3 * self.ds.max(self.cont.ds_min);
            let mut guess = fine.clone();
            guess.axpy(probe, &ts, &free);
            let (_, f1) = on_plane(probe, &guess)?;
            let (mut a, mut fa, mut b, mut fb) = (0.0, f0, probe, f1);
            for _ in 0..6 {
                let sigma = b - fb * (b - a) / (fb - fa);
                if !sigma.is_finite() {
                    break;
                }
                let mut guess = fine.clone();
                guess.axpy(sigma - a, &ts, &free);
                let (at, f) = on_plane(sigma, &guess)?;
                fine = at;
                (a, fa, b, fb) = (b, fb, sigma, f);
                if (b - a).abs() <= self.locate_tolerance {
                    break;
                }
            }
        }
        let (p, _) = self
            .cont
            .diagram
            .point_and_slope_on(&h.sys, &h.norm, q, &fine, &ts);
        self.estimate.checks += 1;
        let difference = (p[0] - coarse[0]).abs().max((p[1] - coarse[1]).abs()) + stalled_across;
        if self.halved.as_ref().is_some_and(|h| h.sys.is_pinning()) {
            self.sys.enable_pinning();
        }
        Ok(MESH_SAFETY * difference)
    }

    /// Moves the run onto an equidistributed mesh of `intervals` intervals
    /// at the current point x₀ (module docs). Returns whether dλ/ds changed
    /// sign: the fold the point was near lies behind it on the new mesh.
    ///
    /// # Errors
    /// A mesh or system that cannot be built, or a corrector that fails on
    /// the new mesh (the run keeps its old mesh then).
    pub(super) fn remesh(&mut self, intervals: usize) -> Result<bool> {
        let (tab, n) = (self.sys.tab.clone(), self.sys.n);
        let sol = crate::bvp::Solution::interpolant(&self.x0, &self.mesh, &tab, n);
        let mesh = equidistribute(&self.mesh, &density(&sol), intervals)?;
        let mut sys = System::new(
            self.sys.problem(),
            mesh.points().to_vec(),
            tab.clone(),
            self.sys.free.clone(),
            1,
        )?;
        sys.linear = self.sys.linear;
        if self.sys.is_pinning() {
            sys.enable_pinning();
        }
        let norm = self.norm_on(&mesh);
        let x = state_on_mesh(&self.x0, &self.mesh, &tab, n, &mesh);
        let t = state_on_mesh(&self.t0, &self.mesh, &tab, n, &mesh);
        let len = sys.y_ref.len();
        let (mut xcol, mut tcol) = (vec![0.0; len], vec![0.0; len]);
        sys.collocation_values(&x, &mut xcol);
        sys.y_ref.clone_from(&xcol);
        set_hyperplane(&mut sys, &norm, (&x, &t), 0.0, (&mut xcol, &mut tcol));
        let mut corrected = x;
        let stats = match newton(&mut sys, &mut corrected, self.opts, false) {
            Ok(stats) => stats,
            // stalled on near-null modes in a run that pins: pinned, as
            // the corrector's
            Err(e) if stalled(&e) && sys.is_pinning() => {
                newton_pinned(&mut sys, &mut corrected, self.opts).ok_or(e)?
            }
            Err(e) => return Err(e),
        };
        self.newton_iterations += u64::from(stats.iterations);
        // The tangent on the new mesh: [F_x; τ₀ᵀ] τ = e at the corrected
        // point, oriented along the old one.
        let det = sys.factor(&corrected)?;
        let old = std::mem::replace(&mut self.sys, sys);
        let old_mesh = std::mem::replace(&mut self.mesh, mesh);
        let old_norm = std::mem::replace(&mut self.norm, norm);
        let old_t = std::mem::replace(&mut self.t0, t);
        self.ycol_a = vec![0.0; len];
        self.ycol_b = vec![0.0; len];
        let tangent = match self.solve_border_rhs() {
            Ok(tangent) => tangent,
            Err(e) => {
                self.sys = old;
                self.mesh = old_mesh;
                self.norm = old_norm;
                self.t0 = old_t;
                self.ycol_a = vec![0.0; self.sys.y_ref.len()];
                self.ycol_b = vec![0.0; self.sys.y_ref.len()];
                return Err(e);
            }
        };
        let mut tangent = tangent;
        let nrm = self.norm(&tangent);
        let sgn = if self.inner(&tangent, &self.t0.clone()) < 0.0 {
            -1.0
        } else {
            1.0
        };
        tangent.scale(sgn / nrm);
        let q = self.cont.parameter;
        let flipped = tangent.p[q] * old_t.p[q] < 0.0;
        self.t0 = tangent;
        self.x0 = corrected;
        self.previous = None;
        self.det0 = det;
        self.factored_at_x0 = true;
        self.halved = None;
        self.jet0 = None;
        self.estimate.remeshes += 1;
        self.estimate.intervals = intervals;
        self.estimate.max_intervals = self.estimate.max_intervals.max(intervals);
        let mut y_ref = std::mem::take(&mut self.sys.y_ref);
        self.sys.collocation_values(&self.x0, &mut y_ref);
        self.sys.y_ref = y_ref;
        self.set_tangent_border(0.0);
        Ok(flipped)
    }

    /// After a remesh that moved x₀ past a fold: the fold located behind
    /// x₀ (in s ∈ [−d, 0] along τ₀, d doubling from half the step, at most
    /// [`FOLD_BEHIND_DOUBLINGS`] times and to the largest step, until dλ/ds
    /// has its old sign there) and its mesh error measured; `None` when it
    /// cannot be bracketed.
    pub(super) fn fold_behind(&mut self) -> Option<(super::corrector::Corrected, f64)> {
        let q = self.cont.parameter;
        let f0 = self.t0.p[q];
        let mut back = -0.5 * self.ds;
        for _ in 0..=FOLD_BEHIND_DOUBLINGS {
            if -back > self.cont.ds_max {
                break;
            }
            if let Ok(c) = self.correct(back, false)
                && c.tangent.p[q] * f0 < 0.0
            {
                let fb = c.tangent.p[q];
                let log_ref = self.det0.log_abs;
                let found = self
                    .locate(super::locate::Watch::Fold, (back, fb), (0.0, f0), log_ref)
                    .ok()?;
                let e = self
                    .mesh_error(&found.0.x, &found.0.tangent, true)
                    .unwrap_or(f64::INFINITY);
                self.estimate.mesh = self.estimate.mesh.max(e);
                self.estimate.located = self.estimate.located.max(e);
                return Some(found);
            }
            back *= 2.0;
        }
        None
    }

    /// The intervals for a measured error `e` against the target `goal`:
    /// N (e/goal)^(1/2m), at least 2; twice N when the check failed (e not
    /// finite), so that one failed check does not ask for the interval
    /// limit.
    pub(super) fn intervals_for(&self, e: f64, goal: f64) -> usize {
        let nn = self.mesh.intervals() as f64;
        let m2 = 2.0 * self.sys.tab.m as f64;
        let want = nn * (e / goal).max(1e-300).powf(1.0 / m2);
        if want.is_finite() {
            (want.ceil() as usize).max(2)
        } else {
            2 * self.mesh.intervals()
        }
    }
}
