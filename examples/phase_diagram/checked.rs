//! A carried fold's force checked against its mesh, as `--forces`,
//! `--force-map` and `--cross-check` report it.

use hockle::bvp::Solution;
use hockle::rod::{CuspSearch, NikolaiRod};

/// How far a carried fold's force F/((2πn)²B) may move when its mesh is
/// halved: the six digits the example prints.
pub const FORCE_TOLERANCE: f64 = 1e-6;

/// A fold's force F/((2πn)²B) on the finest mesh its check reached, and
/// how far it moved in the last halving (`inf` where the fold was not
/// found on the halved mesh: the force is then the carried mesh's).
#[derive(Debug, Clone, Copy)]
pub struct CheckedForce {
    /// F/((2πn)²B) of the fold.
    pub force: f64,
    /// |ΔF|/((2πn)²B) in the last halving.
    pub change: f64,
}

impl CheckedForce {
    /// Whether the last halving moved the force by at most
    /// [`FORCE_TOLERANCE`].
    pub fn resolved(&self) -> bool {
        self.change <= FORCE_TOLERANCE
    }
}

/// `fold` (a fold of `family` on `search`'s mesh) located again on halved
/// meshes until its force moves by at most [`FORCE_TOLERANCE`]
/// ([`CuspSearch::mesh_checked`], at most three halvings).
pub fn checked_force(search: &CuspSearch, family: &NikolaiRod, fold: &Solution) -> CheckedForce {
    match search.mesh_checked(family, fold, FORCE_TOLERANCE) {
        Ok(checked) => CheckedForce {
            force: checked.fold.parameters()[NikolaiRod::FORCE_SCALED],
            change: checked.change,
        },
        // the fold on the finer mesh is not found from this one: its force
        // is not resolved here
        Err(e) => {
            eprintln!("  a fold's mesh check failed: {e}");
            CheckedForce {
                force: fold.parameters()[NikolaiRod::FORCE_SCALED],
                change: f64::INFINITY,
            }
        }
    }
}
