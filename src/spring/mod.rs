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
//! | [`RodModel`] | the full 3D anisotropic rod, by collocation continuation | about a second |
//!
//! What each costs in accuracy against the 3D rod is measured in
//! `docs/ACCURACY.md` (section "spring").
//!
//! Every model implements [`Model`]; a [`Response`] gives the curve, its folds,
//! the pop-outs, the stretches between them, their loop counts and the
//! jumps under force or displacement control.
//!
//! ```
//! use hockle::spring::{HelixModel, Model, Spring};
//! let spring = Spring::paper();
//! let pull = HelixModel::default().pull(&spring, 0.5)?; // up to F/(2πn)² = 0.5
//! let last = pull.curve().points().last().unwrap();
//! assert!((last.force / spring.force_scale() - 0.5).abs() < 1e-9);
//! assert!(pull.pop_outs().is_empty()); // below the helix's own force maximum
//! # Ok::<(), hockle::Error>(())
//! ```

mod elastica_model;
mod helix_model;
mod response;
mod rod_model;
mod scene;

pub use crate::rod::Control;
pub use elastica_model::ElasticaModel;
pub use helix_model::HelixModel;
pub use response::{BranchMatch, Direction, Jump, PopOut, Response, Stretch};
pub use rod_model::RodModel;
pub use scene::Spring;

use crate::error::Result;

/// A model of a pulled spring: answers [`Spring`]s with [`Response`]s.
pub trait Model {
    /// A short name for tables and labels.
    fn name(&self) -> &str;

    /// Pulls `spring` from rest until the force reaches
    /// `max_force_scaled`·(2πn)²B (the paper pulls to 3).
    ///
    /// # Errors
    /// If the model cannot represent the spring, or `max_force_scaled` is not
    /// positive and finite; each model documents its own.
    fn pull(&self, spring: &Spring, max_force_scaled: f64) -> Result<Response>;
}

pub(crate) fn check_samples(samples: usize) -> Result<usize> {
    if samples >= 2 {
        Ok(samples)
    } else {
        Err(crate::Error::InvalidCount {
            name: "samples",
            value: samples as u64,
            allowed: "at least 2 points",
        })
    }
}

pub(crate) fn check_target(max_force_scaled: f64) -> Result<f64> {
    if max_force_scaled.is_finite() && max_force_scaled > 0.0 {
        Ok(max_force_scaled)
    } else {
        Err(crate::Error::InvalidArgument {
            name: "max_force_scaled",
            value: max_force_scaled,
            allowed: "a positive, finite force in units of (2πn)²B",
        })
    }
}
