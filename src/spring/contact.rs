//! The rod's pull with the closest approach of every shape to itself: self-
//! contact, computed only when asked.

use std::ops::ControlFlow;

use crate::continuation::{Continuation, Observer, Point, PointKind, Rejection, Termination};
use crate::error::Result;
use crate::load::Target;
use crate::rod::{Equilibrium, Rod};

use super::{Response, RodModel, Spring};

impl RodModel {
    /// [`RodModel::pull_observed`] that also measures, at every curve point,
    /// the closest approach of the shape to itself between parts that are
    /// not neighbours ([`Equilibrium::closest_approach`]), and flags the
    /// first point where a strip of the spring's width would touch itself
    /// ([`Spring::with_strip_width`], [`Response::first_contact`]).
    ///
    /// Costs about a millisecond per point on top of the pull
    /// (docs/PERFORMANCE.md); [`Model::pull`](super::Model::pull) on the rod does not pay it.
    ///
    /// ```no_run
    /// use hockle::spring::{RodModel, Spring, Target};
    /// // The paper's strip, 0.1 mm wide on a 1 m rod: it never touches itself.
    /// let spring = Spring::paper().with_strip_width(1e-4)?;
    /// let pull = RodModel::default().pull_with_contact(&spring, Target::Force(3.0), ())?;
    /// assert_eq!(pull.first_contact(), None);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    ///
    /// # Errors
    /// As [`RodModel::pull_observed`].
    pub fn pull_with_contact<O: Observer>(
        &self,
        spring: &Spring,
        target: Target,
        observer: O,
    ) -> Result<Response> {
        let rod = *self.driver(spring, target)?.rod();
        let mut contact = ContactObserver {
            rod,
            inner: observer,
            closest: Vec::new(),
            error: None,
        };
        let response = self.pull_observed(spring, target, &mut contact)?;
        if let Some(e) = contact.error {
            return Err(e);
        }
        response.with_closest_approach(contact.closest, spring.strip_width())
    }
}

/// Measures the closest approach of every curve point (every point but the
/// located folds, as the pull's curve), then passes the point on.
struct ContactObserver<O> {
    rod: Rod,
    inner: O,
    closest: Vec<Option<f64>>,
    error: Option<crate::Error>,
}

impl<O: Observer> Observer for &mut ContactObserver<O> {
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        self.inner.start(settings, start)
    }

    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        if point.kind() != PointKind::Fold {
            match Equilibrium::new(self.rod, point.solution().clone()) {
                Ok(eq) => self.closest.push(eq.closest_approach().map(|c| c.distance)),
                Err(e) => {
                    self.error = Some(e);
                    return ControlFlow::Break(());
                }
            }
        }
        self.inner.point(point)
    }

    fn fold(&mut self, fold: &Point) -> ControlFlow<()> {
        self.inner.fold(fold)
    }

    fn branch_point(&mut self, branch_point: &Point) -> ControlFlow<()> {
        self.inner.branch_point(branch_point)
    }

    fn step_rejected(&mut self, because: &Rejection, new_ds: f64) -> ControlFlow<()> {
        self.inner.step_rejected(because, new_ds)
    }

    fn finish(&mut self, termination: &Termination) {
        self.inner.finish(termination);
    }
}
