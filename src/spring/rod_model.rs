//! [`RodModel`]: the full 3D pull by collocation continuation.

use crate::curve::ForceExtension;
use crate::error::{Error, Result};
use crate::rod::{self, PullObserver, PullRun, PullTermination, Rod};

use super::{Model, Response, Spring, check_target};

/// The spring as the 3D anisotropic Kirchhoff rod of [`crate::rod`],
/// pulled from its unstressed helix by pseudo-arclength continuation in the
/// force. Folds are located by the continuation; every point carries its
/// loop count.
///
/// Settings are those of [`rod::Pull`]; [`RodModel::default`] uses its
/// defaults (48 intervals, 4 Gauss points).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RodModel {
    intervals: Option<usize>,
    points: Option<usize>,
}

impl RodModel {
    /// The same model on a mesh of `intervals` uniform intervals.
    #[must_use]
    pub fn intervals(mut self, intervals: usize) -> Self {
        self.intervals = Some(intervals);
        self
    }

    /// The same model with `points` Gauss points per interval (2..=7).
    #[must_use]
    pub fn points(mut self, points: usize) -> Self {
        self.points = Some(points);
        self
    }

    /// The rod of a spring.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if the spring's intrinsic strains are not
    /// those of its helix (the rod takes them from n and θ0).
    pub fn rod(spring: &Spring) -> Result<Rod> {
        if !spring.is_helical() {
            return Err(Error::InvalidArgument {
                name: "u10",
                value: spring.intrinsic_strains().x,
                allowed: "the rod model takes the intrinsic strains of the unstressed helix",
            });
        }
        let k = spring.stiffness();
        Rod::new(spring.coils(), spring.helix_angle(), k.a(), k.b(), k.c())
    }

    /// The continuation driver this model runs.
    ///
    /// # Errors
    /// As [`RodModel::rod`].
    pub fn driver(&self, spring: &Spring, max_force_scaled: f64) -> Result<rod::Pull> {
        let mut pull = rod::Pull::new(Self::rod(spring)?).to_force_scaled(max_force_scaled);
        if let Some(n) = self.intervals {
            pull = pull.intervals(n);
        }
        if let Some(m) = self.points {
            pull = pull.points(m);
        }
        Ok(pull)
    }

    /// Pulls with an observer (progress, cancellation) and returns the
    /// rod's full record of the run.
    ///
    /// # Errors
    /// As [`RodModel::rod`], or a bad target.
    pub fn run<O: PullObserver>(
        &self,
        spring: &Spring,
        max_force_scaled: f64,
        observer: O,
    ) -> Result<PullRun> {
        let target = check_target(max_force_scaled)?;
        Ok(self.driver(spring, target)?.run(observer))
    }

    /// The spring's [`Response`] from a finished run.
    #[must_use]
    pub fn response(run: &PullRun) -> Response {
        let curve: ForceExtension = run.curve();
        let folds = run.folds.clone();
        let loops = run.points.iter().map(|p| p.loops).collect();
        let response = Response::with_folds("rod", curve, folds).with_loops(loops);
        match run.termination {
            PullTermination::ReachedForce => response,
            ref other => response.with_early_stop(other.to_string()),
        }
    }
}

impl Model for RodModel {
    fn name(&self) -> &str {
        "rod"
    }

    /// A run that stops before the target (Newton failure at the smallest
    /// step, step limit) still answers, with every point it computed and
    /// [`Response::stopped_early`] saying why.
    ///
    /// # Errors
    /// As [`RodModel::rod`], or a bad target.
    fn pull(&self, spring: &Spring, max_force_scaled: f64) -> Result<Response> {
        Ok(Self::response(&self.run(spring, max_force_scaled, ())?))
    }
}
