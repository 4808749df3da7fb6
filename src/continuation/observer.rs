//! The hooks a run calls, and the every-n-th-point adapter.

use std::ops::ControlFlow;

use super::{Continuation, Point, PointKind, Rejection, Termination};

/// Hooks called by [`Continuation::run`] (and
/// [`Continuation::run_from_branch_point`]), in argmin's manner: every hook
/// is defaulted, and every hook where stopping makes sense returns
/// [`ControlFlow`]: `Break` ends the run with [`Termination::Stopped`],
/// keeping every point computed so far (the point just observed included).
///
/// The order within a run:
/// 1. [`start`](Self::start) once, with the settings and the start point;
/// 2. for every point in order (the start point first):
///    [`step_rejected`](Self::step_rejected) for each rejected attempt
///    before it, then [`point`](Self::point), then [`fold`](Self::fold) or
///    [`branch_point`](Self::branch_point) if it is one;
/// 3. [`finish`](Self::finish) once, with the termination (also after a
///    `Break`).
///
/// After a `Break` no further hook but `finish` is called.
///
/// Implemented for `()` (observes nothing), for closures
/// `FnMut(&Point) -> ControlFlow<()>` (which see every point, special ones
/// included, through [`point`](Self::point)), and for [`Every`]
/// ([`Observer::every`]).
///
/// ```
/// use std::ops::ControlFlow;
/// use hockle::continuation::{Continuation, Observer, Point, Termination};
///
/// /// Counts the folds and prints why the run ended.
/// #[derive(Default)]
/// struct Folds(usize);
///
/// impl Observer for Folds {
///     fn fold(&mut self, fold: &Point) -> ControlFlow<()> {
///         self.0 += 1;
///         println!("fold at λ = {}", fold.parameter());
///         ControlFlow::Continue(())
///     }
///     fn finish(&mut self, termination: &Termination) {
///         println!("{} folds; {termination}", self.0);
///     }
/// }
/// ```
pub trait Observer {
    /// Called once before any point, with the run's settings and its start
    /// point.
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        let _ = (settings, start);
        ControlFlow::Continue(())
    }

    /// Called for every point, in order (the start and the special points
    /// included).
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        let _ = point;
        ControlFlow::Continue(())
    }

    /// Called for every located fold ([`PointKind::Fold`]), after
    /// [`point`](Self::point).
    fn fold(&mut self, fold: &Point) -> ControlFlow<()> {
        let _ = fold;
        ControlFlow::Continue(())
    }

    /// Called for every located branch point ([`PointKind::BranchPoint`]),
    /// after [`point`](Self::point).
    fn branch_point(&mut self, branch_point: &Point) -> ControlFlow<()> {
        let _ = branch_point;
        ControlFlow::Continue(())
    }

    /// Called when a step is rejected `because` of what [`Rejection`]
    /// says, and retried from the same point with the shorter step
    /// `new_ds`.
    fn step_rejected(&mut self, because: &Rejection, new_ds: f64) -> ControlFlow<()> {
        let _ = (because, new_ds);
        ControlFlow::Continue(())
    }

    /// Called once when the run has ended, with its termination.
    fn finish(&mut self, termination: &Termination) {
        let _ = termination;
    }

    /// This observer called with every `n`-th point only (see [`Every`]).
    #[must_use]
    fn every(self, n: usize) -> Every<Self>
    where
        Self: Sized,
    {
        Every::new(n, self)
    }
}

impl Observer for () {}

impl<F: FnMut(&Point) -> ControlFlow<()>> Observer for F {
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        self(point)
    }
}

/// An observer that passes on the start point, every `n`-th point after it
/// and every special point (fold, branch point, located stop) to the
/// [`point`](Observer::point) hook of the observer it wraps; every other
/// hook is passed on always. `n = 0` is taken as 1 (every point).
///
/// ```
/// use std::ops::ControlFlow;
/// use hockle::continuation::{Observer, Point};
/// // Print every tenth point of a run.
/// let every_tenth = (|p: &Point| {
///     println!("{p}");
///     ControlFlow::Continue(())
/// })
/// .every(10);
/// # let _ = every_tenth;
/// ```
#[derive(Debug, Clone)]
pub struct Every<O> {
    n: usize,
    seen: usize,
    inner: O,
}

impl<O: Observer> Every<O> {
    /// Wraps `observer` to see every `n`-th point (`n = 0` is taken as 1).
    #[must_use]
    pub fn new(n: usize, observer: O) -> Self {
        Every {
            n: n.max(1),
            seen: 0,
            inner: observer,
        }
    }

    /// The wrapped observer (to read what it collected).
    #[must_use]
    pub fn into_inner(self) -> O {
        self.inner
    }
}

impl<O: Observer> Observer for Every<O> {
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        self.inner.start(settings, start)
    }

    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        let due = self.seen.is_multiple_of(self.n);
        self.seen += 1;
        if due || !matches!(point.kind(), PointKind::Regular) {
            self.inner.point(point)
        } else {
            ControlFlow::Continue(())
        }
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
