//! [`Continuation::run`]: a whole branch with its termination.

use std::fmt;
use std::ops::ControlFlow;

use super::mesh_error::ErrorEstimate;
use super::{Continuation, Observer, Point, PointKind, Steps, Termination};
use crate::bvp::{Problem, Solution};
use crate::error::Result;

/// The result of a run: every point in order, why it ended, and the work
/// it took (the counts of [`Steps`] at its end).
#[derive(Debug, Clone)]
pub struct Run {
    points: Vec<Point>,
    termination: Termination,
    accepted: usize,
    rejected: usize,
    newton_iterations: u64,
    estimate: ErrorEstimate,
}

impl Run {
    /// With a [`tolerance`](Continuation::tolerance): the errors the run
    /// measured in the diagram's plane ([`ErrorEstimate`]); without one, all
    /// zero.
    #[must_use]
    pub fn estimate(&self) -> ErrorEstimate {
        self.estimate
    }

    /// Every point, in order.
    #[must_use]
    pub fn points(&self) -> &[Point] {
        &self.points
    }

    /// Why the run ended.
    #[must_use]
    pub fn termination(&self) -> &Termination {
        &self.termination
    }

    /// The located special points, in order.
    pub fn special_points(&self) -> impl Iterator<Item = &Point> {
        self.points.iter().filter(|p| p.is_special())
    }

    /// The located folds.
    pub fn folds(&self) -> impl Iterator<Item = &Point> {
        self.points.iter().filter(|p| p.kind == PointKind::Fold)
    }

    /// The located branch points.
    pub fn branch_points(&self) -> impl Iterator<Item = &Point> {
        self.points
            .iter()
            .filter(|p| p.kind == PointKind::BranchPoint)
    }

    /// The last point.
    #[must_use]
    pub fn last(&self) -> Option<&Point> {
        self.points.last()
    }

    /// Accepted steps (as [`Steps::accepted`]).
    #[must_use]
    pub fn accepted(&self) -> usize {
        self.accepted
    }

    /// Rejected (halved and retried) steps (as [`Steps::rejected`]).
    #[must_use]
    pub fn rejected(&self) -> usize {
        self.rejected
    }

    /// Corrector iterations of every step and location (as
    /// [`Steps::newton_iterations`]).
    #[must_use]
    pub fn newton_iterations(&self) -> u64 {
        self.newton_iterations
    }
}

impl fmt::Display for Run {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "branch of {} points; {}",
            self.points.len(),
            self.termination
        )?;
        for p in self.special_points() {
            writeln!(f, "  {p}")?;
        }
        Ok(())
    }
}

impl Continuation {
    /// Runs to termination, calling `observer` at every point, and returns
    /// every point with the reason the run ended.
    ///
    /// # Errors
    /// As [`Continuation::steps`]; failures after the start end the run with
    /// a [`Termination`] instead.
    pub fn run<P: Problem + ?Sized, O: Observer>(
        &self,
        problem: &P,
        start: &Solution,
        observer: O,
    ) -> Result<Run> {
        let steps = self.steps(problem, start)?;
        Ok(drive(steps, observer))
    }
}

/// Drives `steps` to its end and keeps every point.
pub(super) fn drive<P: Problem + ?Sized, O: Observer>(
    mut steps: Steps<'_, P>,
    mut observer: O,
) -> Run {
    let mut points = Vec::new();
    let termination = drive_into(&mut steps, &mut observer, |p| {
        points.push(p);
        Ok(())
    });
    Run {
        points,
        termination,
        accepted: steps.accepted,
        rejected: steps.rejected,
        newton_iterations: steps.newton_iterations,
        estimate: steps.estimate,
    }
}

/// Drives `steps` to its end, calling the observer's hooks in the order
/// documented on [`Observer`] and handing every point to `keep` (after its
/// hooks); returns why the run ended. A driver that keeps less than every
/// point (the rod's pull keeps its curve, not its solutions) uses this
/// directly. An error from `keep` ends the run as a failure.
pub(crate) fn drive_into<P: Problem + ?Sized, O: Observer>(
    steps: &mut Steps<'_, P>,
    observer: &mut O,
    mut keep: impl FnMut(Point) -> crate::error::Result<()>,
) -> Termination {
    let mut first = true;
    let mut stopped = false;
    while let Some(p) = steps.next() {
        for (because, ds) in steps.rejections.drain(..) {
            if observer.step_rejected(&because, ds).is_break() {
                stopped = true;
            }
        }
        let mut flow = if stopped {
            ControlFlow::Break(())
        } else if first {
            observer.start(steps.cont, &p)
        } else {
            ControlFlow::Continue(())
        };
        first = false;
        if flow.is_continue() {
            flow = observer.point(&p);
        }
        if flow.is_continue() {
            flow = match p.kind() {
                PointKind::Fold => observer.fold(&p),
                PointKind::BranchPoint => observer.branch_point(&p),
                _ => ControlFlow::Continue(()),
            };
        }
        let ds = steps.ds;
        if let Err(error) = keep(p) {
            let termination = Termination::Failed { ds, error };
            observer.finish(&termination);
            return termination;
        }
        if flow.is_break() {
            stopped = true;
            break;
        }
    }
    if !stopped {
        for (because, ds) in steps.rejections.drain(..) {
            if observer.step_rejected(&because, ds).is_break() {
                break;
            }
        }
    }
    let termination = if stopped {
        Termination::Stopped
    } else {
        steps
            .termination
            .take()
            .unwrap_or(Termination::MaxSteps(steps.accepted))
    };
    observer.finish(&termination);
    termination
}
