//! The curve of cusps through a cusp ([`CuspSearch::cusp_curve`]): the
//! boundary of a pop-out's region in a plane of two spring parameters.

use super::{CUSP_NEWTON_TOLERANCE, CuspSearch};
use crate::bvp::Solution;
use crate::continuation::{Continuation, FoldContinuation, FoldObserver};
#[cfg(doc)]
use crate::continuation::{FoldPoint, FoldPointKind};
use crate::error::Result;
use crate::rod::{NikolaiRod, Rod};

impl CuspSearch {
    /// How close to 90° a cusp curve counts as having reached θ0 = 90°
    /// (radians, [`CuspSearch::cusp_curve`]).
    ///
    /// A cusp curve may meet θ0 = 90° tangentially (measured on n = 8: θ0
    /// within 1e-9 rad of 90° over 4e-4 in ln A/B, dθ0/ds → 0): a zero of
    /// θ0 − π/2 is then not crossed, and the continuation stalls where the
    /// curve ends. A gap of 1e-6 rad (5.7e-5°) is crossed transversally;
    /// the pop-out's region between the gap and 90° is not resolved.
    pub const TIP_GAP: f64 = 1e-6;

    /// The curve of cusps through `cusp` (a located cusp of a fold curve in
    /// `mu`: its [`FoldPoint::extended`], or a point of another cusp curve:
    /// its [`FoldPoint::solution`]), continued in `nu` from the step `ds`
    /// towards `to`, or until θ0 reaches 90° − [`CuspSearch::TIP_GAP`]
    /// ([`FoldPointKind::Event`] 0): the fold problem's own folds in `mu`
    /// ([`crate::continuation::FoldProblem`]). Every point is a cusp of the
    /// force folds, its [`FoldPoint::solution`] the fold problem's solution
    /// there; `(mu, nu)` of the points draw the boundary of the pop-out's
    /// region in that plane. The curve's turns in `mu` or `nu`
    /// ([`FoldPointKind::Turn`]) and its own cusps ([`FoldPointKind::Cusp`]:
    /// swallowtails, where three force folds meet) are located.
    ///
    /// # Errors
    /// As [`FoldContinuation::run`] at the start.
    pub fn cusp_curve<O: FoldObserver>(
        &self,
        family: &NikolaiRod,
        cusp: &Solution,
        (mu, nu): (usize, usize),
        to: f64,
        ds: f64,
        observer: O,
    ) -> Result<crate::continuation::FoldCurve> {
        // the rod's weights on the state and on the null vector alike
        let rod_weights = family.rod().norm_weights();
        let mut w = [1.0; 2 * Rod::DIM];
        for half in [0, Rod::DIM] {
            w[half..half + Rod::DIM].copy_from_slice(&rod_weights);
        }
        let problem = crate::continuation::FoldProblem::new(family, &[]);
        let settings = Continuation::new(nu)
            .solver(
                // The fold problem's own linearisation differences the
                // fold problem's Jacobian, whose second derivatives are
                // central differences already: the residual's noise is
                // ~1e-10 of ‖x‖ (forces ~ (2πn)²B in y), so Newton's
                // corrections stall there (measured: up to 2e-8); 1e-7 is reached in 2–4 steps.
                self.solver(family)?
                    .free_parameters(&[NikolaiRod::FORCE_SCALED])
                    .newton_tolerance(CUSP_NEWTON_TOLERANCE),
            )
            .weights(&w)
            .step(ds)
            .step_bounds(1e-8, self.curve_ds_max)
            .locate_tolerance(1e-9)
            .max_angle(self.curve_max_angle)
            .stop_at(to)
            .stop_when(|s: &Solution| {
                s.parameters()[Rod::THETA0] - (core::f64::consts::FRAC_PI_2 - Self::TIP_GAP)
            })
            .max_steps(self.max_steps);
        // Turns of the cusp curve in either parameter and its own cusps
        // (swallowtails) are located: where it turns back in `nu` the
        // boundary covers some `nu` twice ([`super::PhaseDiagram`]).
        FoldContinuation::new(mu, settings).run(&problem, cusp, observer)
    }
}
