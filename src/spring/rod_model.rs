//! [`RodModel`]: the full 3D pull by collocation continuation.

use crate::continuation::Observer;
use crate::error::Result;
use crate::load::Target;
use crate::rod::{Pull, PullRun, Rod};

use super::{Model, Response, Spring};

/// The spring as the 3D anisotropic Kirchhoff rod of [`crate::rod`],
/// pulled from rest by pseudo-arclength continuation to a force or an
/// extension. The folds of the controlled load are located by the
/// continuation; every point carries its loop count.
///
/// Settings are those of [`Pull`]; [`RodModel::default`] uses its defaults
/// (a tolerance of 1e-6 in (Δz, F/((2πn)²B)), from which the pull chooses
/// its mesh, degree and steps). The rod takes the spring's intrinsic
/// strains as they are. The [`Response`] carries the run's estimated error
/// ([`Response::estimated_error`]).
///
/// [`RodModel::symmetric`]`(true)` solves the rod on its half
/// ([`Rod::symmetric`]) where its intrinsic strains allow (u10 = 0, every
/// helix): the equilibria symmetric end to end, which the pull from rest
/// follows on the whole rod too (the paper's branches are symmetric), at
/// half the unknowns and without the antisymmetric modes that stall long
/// springs and sliding loops.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RodModel {
    tolerance: Option<f64>,
    intervals: Option<usize>,
    points: Option<usize>,
    relax_to: Option<f64>,
    /// Solve the half where the rod allows ([`RodModel::symmetric`]).
    symmetric: bool,
}

impl RodModel {
    /// The same model at the accuracy `tol` ([`Pull::tolerance`]).
    #[must_use]
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tolerance = Some(tol);
        self
    }

    /// Expert override: a fixed mesh of `intervals` uniform intervals
    /// ([`Pull::intervals`]).
    #[must_use]
    pub fn intervals(mut self, intervals: usize) -> Self {
        self.intervals = Some(intervals);
        self
    }

    /// Expert override: `points` Gauss points per interval (2..=7).
    #[must_use]
    pub fn points(mut self, points: usize) -> Self {
        self.points = Some(points);
        self
    }

    /// Where the pull's corrector fails (loops sliding along the rod), go on
    /// from the last point at looser tolerances up to `loosest`
    /// ([`Pull::relax_to`]); the [`Response`]'s estimated error covers the
    /// looser part, and [`Response::relaxations`] says where it began.
    #[must_use]
    pub fn relax_to(mut self, loosest: f64) -> Self {
        self.relax_to = Some(loosest);
        self
    }

    /// Whether to solve the rod on its half where its intrinsic strains
    /// allow ([`Rod::symmetric`]), or the whole rod (the default). The
    /// [`Response`] is the whole rod's either way; an observer given to
    /// [`RodModel::pull_observed`] sees the continuation's points, whose
    /// solutions are then on the half: turn one into the whole rod's
    /// equilibrium with the driver's rod,
    /// [`Equilibrium::new`](crate::rod::Equilibrium::new)`(*model.driver(spring, target)?.rod(), solution)`.
    #[must_use]
    pub fn symmetric(mut self, on: bool) -> Self {
        self.symmetric = on;
        self
    }

    /// The whole rod of a spring: its coils, helix angle, stiffnesses and
    /// intrinsic strains ([`RodModel::driver`] solves it on its half where
    /// it can).
    ///
    /// # Errors
    /// As [`Rod::new`] and [`Rod::with_intrinsic_strains`] (a valid
    /// [`Spring`] passes both).
    pub fn rod(spring: &Spring) -> Result<Rod> {
        let rod = Rod::new(spring.coils(), spring.helix_angle(), spring.stiffness())?;
        if spring.is_helical() {
            Ok(rod)
        } else {
            rod.with_intrinsic_strains(spring.intrinsic_strains())
        }
    }

    /// The continuation driver this model runs, validated ([`Pull::check`]).
    ///
    /// # Errors
    /// As [`RodModel::rod`] and [`Pull::check`].
    pub fn driver(&self, spring: &Spring, target: Target) -> Result<Pull> {
        let rod = Self::rod(spring)?;
        let rod = if self.symmetric {
            rod.symmetric().unwrap_or(rod)
        } else {
            rod
        };
        let mut pull = Pull::new(rod, target);
        if let Some(tol) = self.tolerance {
            pull = pull.tolerance(tol);
        }
        if let Some(n) = self.intervals {
            pull = pull.intervals(n);
        }
        if let Some(m) = self.points {
            pull = pull.points(m);
        }
        if let Some(loosest) = self.relax_to {
            pull = pull.relax_to(loosest);
        }
        pull.check()?;
        Ok(pull)
    }

    /// Pulls with an observer of the continuation points (progress,
    /// cancellation) and returns the spring's [`Response`].
    ///
    /// # Errors
    /// As [`RodModel::driver`] and [`Pull::run`].
    pub fn pull_observed<O: Observer>(
        &self,
        spring: &Spring,
        target: Target,
        observer: O,
    ) -> Result<Response> {
        Self::response(self.driver(spring, target)?.run(observer)?)
    }

    /// The spring's [`Response`] from a finished run.
    ///
    /// # Errors
    /// None in practice: the run's folds and loop counts fit its curve.
    pub fn response(run: PullRun) -> Result<Response> {
        Response::new(
            "rod",
            run.target(),
            run.curve().clone(),
            run.termination().clone(),
        )
        .with_folds(run.folds().to_vec())?
        .with_loops(run.loops().to_vec())?
        .with_relaxations(run.relaxations().to_vec())
        .map(|r| r.with_estimated_error(run.estimate().curve()))
    }
}

impl Model for RodModel {
    fn name(&self) -> &str {
        "rod"
    }

    /// A run that stops before the target (Newton failure at the smallest
    /// step, step limit) still answers, with every point it computed and
    /// [`Response::termination`] saying why. A spring with a strip width
    /// ([`Spring::with_strip_width`]) gets the closest approach of every
    /// shape and its first contact ([`RodModel::pull_with_contact`]).
    ///
    /// # Errors
    /// As [`RodModel::pull_observed`].
    fn pull_to(&self, spring: &Spring, target: Target) -> Result<Response> {
        // a spring with a strip width asks where the strip first touches
        if spring.strip_width().is_some() {
            self.pull_with_contact(spring, target, ())
        } else {
            self.pull_observed(spring, target, ())
        }
    }
}
