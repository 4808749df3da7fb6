//! The rest state of a pull and the pull ready to step ([`Start`]).

use crate::bvp::{Collocation, Solution};
use crate::continuation::{Continuation, Steps};
use crate::error::Result;
use crate::load::{Control, Target};

use super::super::Rod;

/// A pull ready to step: the rest state solved and the continuation set
/// (from [`Pull::start`](super::Pull::start)). [`Start::steps`] iterates over the continuation's
/// points, the rest state first, as [`Pull::run`](super::Pull::run) does.
#[derive(Debug, Clone)]
pub struct Start {
    pub(super) rod: Rod,
    pub(super) target: Target,
    pub(super) continuation: Continuation,
    pub(super) rest: Solution,
}

impl Start {
    /// The rod the continuation solves (with the target's control; a
    /// [symmetric](Rod::symmetric) rod's points are solutions on its half).
    #[must_use]
    pub fn rod(&self) -> &Rod {
        &self.rod
    }

    /// The rest state.
    #[must_use]
    pub fn rest(&self) -> &Solution {
        &self.rest
    }

    /// The continuation settings of the pull.
    #[must_use]
    pub fn continuation(&self) -> &Continuation {
        &self.continuation
    }

    /// The continuation's step-by-step iterator from the rest state. Turn
    /// a point into the rod's outputs with [`Equilibrium::new`](crate::rod::Equilibrium::new)`(*start.rod(),
    /// point.solution().clone())` (the whole rod's, for a symmetric rod too).
    ///
    /// # Errors
    /// An error of the first tangent computation.
    pub fn steps(&self) -> Result<Steps<'_, Rod>> {
        self.continuation.steps(&self.rod, &self.rest)
    }
}

/// Steps of the homotopy from the helix's intrinsic strains to custom ones.
const RELAX_STEPS: u32 = 8;

/// The rest state (F = 0) under force control: the unstressed helix, or
/// for custom intrinsic strains u0 the equilibrium reached from it by
/// moving u0 from the helix's strains to the custom ones in
/// [`RELAX_STEPS`] equal steps, each solved by Newton from the last.
pub(super) fn relaxed_rest(solver: &Collocation, rod: &Rod, p0: &[f64; 3]) -> Result<Solution> {
    let free = rod.with_control(Control::Force);
    let helical = Rod::helical_strains(rod.coils(), rod.theta0());
    let target = rod.intrinsic_strains();
    let mut rest = solver.solve(
        &free.with_intrinsic_strains(helical)?,
        |s: f64| rod.unstressed_at(s),
        p0,
    )?;
    if !rod.is_helical() {
        for i in 1..=RELAX_STEPS {
            let t = f64::from(i) / f64::from(RELAX_STEPS);
            let step = free.with_intrinsic_strains(helical + (target - helical) * t)?;
            rest = solver.solve(&step, &rest, p0)?;
        }
    }
    Ok(rest)
}
