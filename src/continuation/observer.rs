//! The hooks a run calls.

use std::ops::ControlFlow;

use super::Point;

/// Hooks called by [`Continuation::run`]; every hook is defaulted and
/// returns [`ControlFlow`] (`Break` stops the run with
/// [`Termination::Stopped`], keeping the points so far). Implemented for
/// `()` and for closures `FnMut(&Point) -> ControlFlow<()>`.
pub trait Observer {
    /// Called for every point, in order (special points included).
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        let _ = point;
        ControlFlow::Continue(())
    }

    /// Called when a step is rejected and retried with `new_ds`.
    fn step_rejected(&mut self, new_ds: f64) -> ControlFlow<()> {
        let _ = new_ds;
        ControlFlow::Continue(())
    }
}

impl Observer for () {}

impl<F: FnMut(&Point) -> ControlFlow<()>> Observer for F {
    fn point(&mut self, point: &Point) -> ControlFlow<()> {
        self(point)
    }
}
