//! The scene: one [`Spring`], answered by every model with a [`Response`] whose
//! curve is a [`ForceExtension`](crate::ForceExtension).
//!
//! A user describes the spring once and picks the cheapest model the
//! question needs:
//!
//! | model | what it assumes | cost |
//! |---|---|---|
//! | [`HelixModel`] | the spring stays an exact helix (the paper's Appendix) | microseconds |
//! | [`ElasticaModel`] | the spring is flat, as between glass plates: the primary υ elastica | about a millisecond |
//! | [`RodModel`] | the full 3D anisotropic rod, by collocation continuation | about two seconds |
//!
//! What each costs in accuracy against the 3D rod is measured in
//! `docs/ACCURACY.md` (section "spring").
//!
//! Every model implements [`Model`]; a [`Response`] gives the curve, its folds,
//! the pop-outs, the stretches between them, their loop counts, the
//! stability of every point and the jumps under force or displacement
//! control; [`RodModel::pull_with_contact`] adds the closest approach of
//! every shape to itself.
//!
//! Or the spring chooses: [`Spring::answer`] answers a [`Question`] (a
//! curve, forces or extensions, the spring constant, the pop-outs, the
//! [`LoadedShape`] at one load and its loop count) at a tolerance with the
//! cheapest model that can be shown to meet it, and says why ([`Answer`]).
//!
//! ```
//! use hockle::spring::{HelixModel, Model, Spring};
//! let spring = Spring::paper();
//! let pull = HelixModel::default().pull(&spring, 0.5)?; // up to F/((2πn)²B) = 0.5
//! let last = pull.curve().points().last().unwrap();
//! assert!((last.force / spring.force_scale() - 0.5).abs() < 1e-9);
//! assert!(pull.pop_outs().is_empty()); // below the helix's own force maximum
//! # Ok::<(), hockle::Error>(())
//! ```

mod answer;
mod branch_match;
mod choice;
mod contact;
mod elastica_model;
mod helix_check;
mod helix_model;
mod jumps;
mod plane_distance;
mod pop_outs;
mod question;
mod response;
mod rod_model;
mod scene;
mod shape;
mod sweep;

pub use crate::load::{Control, Target};
pub use answer::{Answer, Choice, Reason, SetAside, Value};
pub use branch_match::BranchMatch;
pub use elastica_model::ElasticaModel;
pub use helix_model::HelixModel;
pub use jumps::{Direction, Jump};
pub use pop_outs::{PopOut, Stretch};
pub use question::Question;
pub use response::Response;
pub use rod_model::RodModel;
pub use scene::Spring;
pub use shape::LoadedShape;
pub use sweep::{sweep, sweep_serial};

use crate::error::{Error, Result};

/// A model of a pulled spring: answers [`Spring`]s with [`Response`]s.
pub trait Model {
    /// A short name for tables and labels.
    fn name(&self) -> &str;

    /// Pulls `spring` from rest to `target`: the force F/((2πn)²B) under
    /// force control, or the extension Δz under extension control. The last
    /// point of the curve is the target unless the run stopped early
    /// ([`Response::termination`]).
    ///
    /// # Errors
    /// [`Error::UnreachableTarget`] for a target the spring cannot reach;
    /// [`Error::OutsideModel`] if the model cannot represent the spring or
    /// the target; each model documents its own.
    fn pull_to(&self, spring: &Spring, target: Target) -> Result<Response>;

    /// [`Model::pull_to`] under force control: pulls until the force reaches
    /// `max_force_scaled`·(2πn)²B (the paper pulls to 3).
    ///
    /// # Errors
    /// As [`Model::pull_to`].
    fn pull(&self, spring: &Spring, max_force_scaled: f64) -> Result<Response> {
        self.pull_to(spring, Target::Force(max_force_scaled))
    }
}

pub(crate) fn check_samples(samples: usize) -> Result<usize> {
    crate::error::check_points("samples", samples)
}

/// The target of a model that assumes the spring keeps its intrinsic
/// helix (the helix and the elastica): validated against the rest
/// extension cos θ0, pulling only.
pub(crate) fn check_simple_target(
    model: &'static str,
    spring: &Spring,
    target: Target,
) -> Result<Target> {
    if !spring.is_helical() {
        return Err(Error::OutsideModel {
            model,
            assumption: "the spring's intrinsic strains must be those of its helix \
                         (u10 = 0, u20 = 2πn sin θ0, u30 = 2πn cos θ0); use RodModel",
        });
    }
    let target = target.validate(spring.helix_angle().cos())?;
    let pulls = match target {
        Target::Force(f) => f > 0.0,
        Target::Extension(dz) => dz > spring.helix_angle().cos(),
    };
    if !pulls {
        return Err(Error::OutsideModel {
            model,
            assumption: "the model answers pulls (a positive force, an extension above rest); \
                         use RodModel to push",
        });
    }
    Ok(target)
}
