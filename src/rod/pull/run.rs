//! What a pull returns: [`PullRun`].

use std::time::Duration;

use crate::continuation::{ErrorEstimate, Termination};
use crate::curve::{Fold, ForceExtension};
use crate::load::Target;

use super::super::Rod;
use super::Relaxation;

/// The result of a pull: the curve in continuation order, its located folds,
/// the loop count at every point, and why it ended. A run that stops early
/// keeps every point.
#[derive(Debug, Clone)]
pub struct PullRun {
    pub(super) rod: Rod,
    pub(super) target: Target,
    pub(super) curve: ForceExtension,
    pub(super) folds: Vec<Fold>,
    pub(super) loops: Vec<Option<u32>>,
    pub(super) termination: Termination,
    pub(super) steps: usize,
    pub(super) rejected: usize,
    pub(super) newton_iterations: u64,
    pub(super) elapsed: Duration,
    pub(super) tolerance: f64,
    pub(super) relaxations: Vec<Relaxation>,
    pub(super) estimate: ErrorEstimate,
    pub(super) points_per_interval: usize,
}

impl PullRun {
    /// The tolerance the pull was asked for.
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Where the run went on at a looser tolerance, in order (empty unless
    /// [`Pull::relax_to`](super::Pull::relax_to) allowed it and the
    /// corrector failed at the tolerance asked).
    #[must_use]
    pub fn relaxations(&self) -> &[Relaxation] {
        &self.relaxations
    }

    /// The errors the run measured, in the plane (Δz, F/((2πn)²B)) of the
    /// paper's plots ([`ErrorEstimate`]): of the points against the halved
    /// mesh, of the located folds, and of the quintic Hermite interpolant
    /// between points (the cubic at tolerances of 1e-3 and looser;
    /// [`ForceExtension::force_at`]).
    #[must_use]
    pub fn estimate(&self) -> ErrorEstimate {
        self.estimate
    }

    /// The collocation points per interval m the run used.
    #[must_use]
    pub fn points_per_interval(&self) -> usize {
        self.points_per_interval
    }

    /// The rod that was pulled (with the control of its target).
    #[must_use]
    pub fn rod(&self) -> &Rod {
        &self.rod
    }

    /// The target of the pull.
    #[must_use]
    pub fn target(&self) -> Target {
        self.target
    }

    /// The force–extension curve (parameter: arclength), from the rest state
    /// to the last point; located folds are in [`Self::folds`], not points.
    #[must_use]
    pub fn curve(&self) -> &ForceExtension {
        &self.curve
    }

    /// The located folds of the controlled load, in order; each fold's
    /// `index` is the last curve point before it.
    #[must_use]
    pub fn folds(&self) -> &[Fold] {
        &self.folds
    }

    /// The loop count of every curve point ([`Equilibrium::loops`](crate::rod::Equilibrium::loops)).
    #[must_use]
    pub fn loops(&self) -> &[Option<u32>] {
        &self.loops
    }

    /// Why the run ended: [`Termination::ParameterValue`] when it reached
    /// its target.
    #[must_use]
    pub fn termination(&self) -> &Termination {
        &self.termination
    }

    /// Whether the last point is the target.
    #[must_use]
    pub fn reached_target(&self) -> bool {
        matches!(self.termination, Termination::ParameterValue(_))
    }

    /// Whether the run's estimated errors (of its folds and of its curve,
    /// [`Self::estimate`]) are within the tolerance it was asked for. A run
    /// can reach its target without meeting it: a fixed mesh too coarse
    /// for the tolerance, or a mesh that reached its interval limit (the
    /// estimate is then large, or ∞ where the check against the halved mesh
    /// failed).
    #[must_use]
    pub fn meets_tolerance(&self) -> bool {
        self.estimate.overall() <= self.tolerance
    }

    /// Accepted continuation steps.
    #[must_use]
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Rejected (retried) steps.
    #[must_use]
    pub fn rejected(&self) -> usize {
        self.rejected
    }

    /// Newton iterations: the start and every corrector (rejected steps and
    /// fold location included).
    #[must_use]
    pub fn newton_iterations(&self) -> u64 {
        self.newton_iterations
    }

    /// Wall-clock time of the run.
    #[must_use]
    pub fn elapsed(&self) -> Duration {
        self.elapsed
    }
}

impl core::fmt::Display for PullRun {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        writeln!(
            f,
            "pull of {} to {} (tolerance {:.0e}): {} points, {} folds, {} steps ({} rejected), {:.2?}: {}\n  {}, m = {}",
            self.rod,
            self.target,
            self.tolerance,
            self.curve.len(),
            self.folds.len(),
            self.steps,
            self.rejected,
            self.elapsed,
            self.termination,
            self.estimate,
            self.points_per_interval
        )?;
        for r in &self.relaxations {
            writeln!(
                f,
                "  went on at tolerance {:.0e} from point {}: {}",
                r.tolerance, r.from_point, r.because
            )?;
        }
        if !self.meets_tolerance() {
            writeln!(
                f,
                "  the tolerance {:.0e} is NOT met: estimated error {:.1e}",
                self.tolerance,
                self.estimate.overall()
            )?;
        }
        for fold in &self.folds {
            writeln!(
                f,
                "  {} at Δz = {:.6}, F/((2πn)²B) = {:.6}",
                fold.kind,
                fold.point.extension,
                fold.point.force_scaled(self.curve.scale())
            )?;
        }
        Ok(())
    }
}
