//! The planar elastica with intrinsic curvature 2πn (the paper's Section 3).
//!
//! TODO module docs.

mod bifurcation;
mod family;
mod integrals;
mod nonsymmetric;
mod secondary;
pub mod series;
mod solution;
mod symmetric;
mod trace;

pub use bifurcation::{Bifurcation, bifurcation};
pub use secondary::{Fold, secondary_fold};
pub use solution::{Arm, Branch, Elastica, Shape};
pub use symmetric::Symmetric;
pub use trace::Trace;
