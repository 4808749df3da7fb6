//! Running a pull ([`Pull::run`]): the continuation driven from rest to the
//! target, in segments where it goes on at looser tolerances
//! ([`Pull::relax_to`]).

use std::time::Instant;

use super::recorder::Recorder;
use super::relax::{Segment, corrector_failure, looser};
use super::{Pull, PullRun, Relaxation};
use crate::continuation::{Observer, drive_into};
use crate::error::Result;
#[cfg(doc)]
use crate::{continuation::Continuation, error::Error};

impl Pull {
    /// Runs the pull to its target, calling `observer`'s hooks as
    /// [`Continuation::run`] does (the same driver): `start` at the rest
    /// state, `point` at every point (located folds are points of kind
    /// [`PointKind::Fold`](crate::continuation::PointKind::Fold)), `fold` at each located fold, `step_rejected`,
    /// `finish` with the termination. The pull keeps the curve, not the
    /// solutions.
    ///
    /// A run that cannot go on (Newton failure at the smallest step, the
    /// step limit, the observer) keeps its points and says why in
    /// [`PullRun::termination`]; a point with |Δz| > 1 + tolerance (no
    /// rod: a fixed mesh too coarse for the shape) ends it with
    /// `Failed` and [`Error::NotARod`], the point not kept. Where
    /// [`Pull::relax_to`] allows it, a run whose corrector fails goes on
    /// from its last point at looser tolerances; the observer sees one run
    /// all the same (one `start`, one `finish`, the arclength going on).
    ///
    /// # Errors
    /// As [`Pull::start`]: bad settings, an unreachable target, or a rest
    /// state that cannot be solved; nothing is computed past the error.
    pub fn run<O: Observer>(&self, mut observer: O) -> Result<PullRun> {
        let clock = Instant::now();
        let start = self.start()?;
        let mut recorder = Recorder::new(
            &start,
            self.locate_folds,
            self.tolerance,
            self.relax_to.is_some(),
        );
        let mut trace = start.steps()?;
        let mut segment = Segment {
            observer: &mut observer,
            resumed: false,
            seen_start: false,
        };
        let mut termination = drive_into(&mut trace, &mut segment, |p| recorder.record(&p));
        let mut estimate = trace.estimate();
        let (mut steps, mut rejected) = (trace.accepted(), trace.rejected());
        let mut newton_iterations =
            trace.newton_iterations() + u64::from(start.rest.newton().iterations);
        drop(trace);
        let mut relaxations = Vec::new();
        let mut tol = self.tolerance;
        while let (Some(next), Some(because), Some(last)) = (
            looser(tol, self.relax_to),
            corrector_failure(&termination).cloned(),
            recorder.last.take(),
        ) {
            tol = next;
            let remaining = self.max_steps.saturating_sub(steps);
            let looser_pull = self.clone().tolerance(next).max_steps(remaining.max(1));
            let ds = last.step.clamp(self.ds_min, self.largest_step());
            // (the looser pull's settings are this one's, checked, with a
            // tolerance relax_to has checked: no error is expected here,
            // and none is allowed to lose the points so far)
            let Ok(solver) = looser_pull.check() else {
                break;
            };
            let cont = start
                .continuation
                .clone()
                .solver(solver.clone())
                .tolerance(next)
                .max_steps(remaining.max(1))
                .step(if last.dparameter < 0.0 { -ds } else { ds });
            let resumed = (remaining > 0)
                .then(|| looser_pull.resumed(&cont, solver, &start.rod, &last))
                .flatten();
            let Some(mut trace) = resumed else {
                // (not from here at this tolerance: a looser one may)
                recorder.last = Some(last);
                continue;
            };
            relaxations.push(Relaxation {
                from_point: recorder.curve.len() - 1,
                tolerance: next,
                because,
            });
            let mut segment = Segment {
                observer: &mut observer,
                resumed: true,
                seen_start: false,
            };
            termination = drive_into(&mut trace, &mut segment, |p| recorder.record(&p));
            estimate = estimate.followed_by(&trace.estimate());
            steps += trace.accepted();
            rejected += trace.rejected();
            newton_iterations += trace.newton_iterations();
            if recorder.last.is_none() {
                recorder.last = Some(last);
            }
        }
        observer.finish(&termination);
        Ok(PullRun {
            rod: start.rod,
            target: start.target,
            curve: recorder.curve,
            folds: recorder.folds,
            loops: recorder.loops,
            termination,
            steps,
            rejected,
            newton_iterations,
            elapsed: clock.elapsed(),
            tolerance: self.tolerance,
            relaxations,
            estimate,
            points_per_interval: self.points_per_interval(),
        })
    }
}
