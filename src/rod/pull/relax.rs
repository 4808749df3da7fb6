//! Going on at a looser tolerance where the pull's corrector cannot
//! converge ([`Pull::relax_to`](super::Pull::relax_to)): the record of each
//! resumption ([`Relaxation`]) and the observer of a run in segments.
//!
//! Where loops left in the rod slide along it (at high tension for ν < 0,
//! or at A/B = 100 past most pop-outs), Newton's corrections stall at
//! 1e-9–1e-8 relative, above the corrector's tolerance at the default 1e-6
//! (1e-10, a ten-thousandth of the tolerance): the run ends at its shortest
//! step with [`Error::CorrectorDrifted`] or a Newton failure. A run ten or a
//! hundred times looser has its corrector's tolerance above that floor and
//! passes (docs/ACCURACY.md, "Stretched" and "Going on from the failure").
//! Resumed from the last point, the curve up to it keeps the tolerance
//! asked for.

use std::ops::ControlFlow;

use super::Pull;
use super::recorder::LastPoint;
use crate::bvp::adapt::{density, equidistribute};
use crate::bvp::{Collocation, Mesh, Solution};
use crate::continuation::{Continuation, Observer, Point, Rejection, Steps, Termination};
use crate::error::Error;
use crate::rod::Rod;

/// Where a pull went on at a looser tolerance ([`PullRun::relaxations`](super::PullRun::relaxations)).
#[derive(Debug, Clone, PartialEq)]
pub struct Relaxation {
    /// The index in [`PullRun::curve`](super::PullRun::curve) of the point
    /// it went on from: the points before it and this one were computed at
    /// the tighter tolerance.
    pub from_point: usize,
    /// The tolerance of the points after it.
    pub tolerance: f64,
    /// Why the run at the tighter tolerance stopped there.
    pub because: Error,
}

/// Each resumption loosens the tolerance by this factor (at most to the
/// loosest allowed): the corrector's Newton tolerance, a ten-thousandth of
/// the run's, rises by as much.
const LOOSER: f64 = 10.0;

/// The next tolerance after `tol`, if it is looser than `tol` and not
/// looser than `loosest`.
pub(super) fn looser(tol: f64, loosest: Option<f64>) -> Option<f64> {
    // (within rounding of `loosest` counts as there: 10·1e-6 is a hair
    // below 1e-5)
    let near = |t: f64, l: f64| t >= l * (1.0 - 1e-9);
    let loosest = loosest?;
    if near(tol, loosest) {
        return None;
    }
    // (to 13 digits: 10·1e-6 is 1e-5 to the user, not 9.999999999999999e-6)
    let next = format!("{:.12e}", LOOSER * tol)
        .parse()
        .unwrap_or(LOOSER * tol);
    Some(if near(next, loosest) { loosest } else { next })
}

/// The error of a run that a looser tolerance can pass: the corrector
/// failed at the shortest step (its Newton stalled or drifted). Every other
/// end (the target, the step limit, the observer, no rod, no progress) is
/// kept.
pub(super) fn corrector_failure(termination: &Termination) -> Option<&Error> {
    termination.error().filter(|e| {
        matches!(
            e,
            Error::CorrectorDrifted { .. }
                | Error::NewtonDiverged { .. }
                | Error::NewtonNotConverged { .. }
        )
    })
}

impl Pull {
    /// The continuation `cont` (this pull's, at its looser tolerance, with
    /// its `solver`) from `last`, the last point of the tighter run, solved
    /// again at its parameters on the first of these meshes where that
    /// solve converges and the run can start ([`resume_meshes`]); `None`
    /// where none does.
    pub(super) fn resumed<'a>(
        &self,
        cont: &'a Continuation,
        solver: Collocation,
        rod: &'a Rod,
        last: &LastPoint,
    ) -> Option<Steps<'a, Rod>> {
        let solver = solver.newton_tolerance(cont.corrector_tolerance());
        resume_meshes(self.mesh_intervals(), &last.solution)
            .into_iter()
            .find_map(|mesh| {
                let again = solver
                    .clone()
                    .mesh(mesh)
                    .solve(rod, &last.solution, last.solution.parameters())
                    .ok()?;
                cont.steps_resumed(rod, &again, last.arclength).ok()
            })
    }
}

/// The meshes a resumption tries for the last point, in turn: the looser
/// pull's first mesh (`intervals` uniform; coarser than the tighter run's
/// adapted one, where the sliding modes' rounding floor is lower: n = 6 at
/// (89.5°, 100, 0.05) passes there and fails on its own mesh), that many
/// intervals equidistributed on the point's shape, as many as the point
/// has so, and the point's own mesh (n = 5 at (89.8°, 10, −0.2): the
/// coarser ones do not converge on its localised loops).
fn resume_meshes(intervals: usize, last: &Solution) -> Vec<Mesh> {
    let own = last.mesh().clone();
    let phi = density(last);
    let mut meshes: Vec<Mesh> = [
        Mesh::uniform(intervals).ok(),
        equidistribute(&own, &phi, intervals).ok(),
        equidistribute(&own, &phi, own.intervals()).ok(),
    ]
    .into_iter()
    .flatten()
    .collect();
    meshes.push(own);
    meshes
}

/// The user's observer over the segments of a run: `start` in the first
/// segment only, the start point of a resumed segment (the last point of
/// the one before) not seen again, and no `finish` (the pull calls it once,
/// with the termination of the last segment).
pub(super) struct Segment<'o, O: Observer> {
    pub(super) observer: &'o mut O,
    pub(super) resumed: bool,
    pub(super) seen_start: bool,
}

impl<O: Observer> Observer for Segment<'_, O> {
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        if self.resumed {
            ControlFlow::Continue(())
        } else {
            self.observer.start(settings, start)
        }
    }

    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        if self.resumed && !self.seen_start {
            self.seen_start = true;
            return ControlFlow::Continue(());
        }
        self.observer.point(point)
    }

    fn fold(&mut self, fold: &Point) -> ControlFlow<()> {
        self.observer.fold(fold)
    }

    fn branch_point(&mut self, branch_point: &Point) -> ControlFlow<()> {
        self.observer.branch_point(branch_point)
    }

    fn step_rejected(&mut self, because: &Rejection, new_ds: f64) -> ControlFlow<()> {
        self.observer.step_rejected(because, new_ds)
    }

    fn finish(&mut self, _: &Termination) {}
}

#[cfg(test)]
mod tests {
    use super::looser;

    #[test]
    fn the_tolerances_loosen_by_decades_to_the_loosest() {
        assert_eq!(looser(1e-6, None), None);
        assert_eq!(looser(1e-6, Some(1e-4)), Some(1e-5));
        assert_eq!(looser(1e-5, Some(1e-4)), Some(1e-4));
        assert_eq!(looser(1e-4, Some(1e-4)), None);
        assert_eq!(looser(3e-6, Some(1e-5)), Some(1e-5));
        // within rounding of the loosest counts as there
        assert_eq!(looser(1e-4 * (1.0 - 1e-12), Some(1e-4)), None);
    }
}
