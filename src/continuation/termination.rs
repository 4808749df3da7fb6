//! Why a run ended.

use std::fmt;

use crate::error::Error;

/// Why a run ended: the one termination of every continuation run, kept by
/// [`Run`](super::Run) and [`Steps`](super::Steps) together with every point
/// computed before it.
///
/// A run that reaches a requested value ends with
/// [`ParameterValue`](Self::ParameterValue) or [`Event`](Self::Event), and
/// its last point is located there; one that cannot go on ends with
/// [`Failed`](Self::Failed), which carries the typed [`Error`] of the last
/// attempt at the minimum step.
///
/// ```
/// use hockle::continuation::Termination;
/// assert_eq!(Termination::MaxSteps(200).to_string(), "reached the step limit (200 steps)");
/// assert!(Termination::Stopped.error().is_none());
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Termination {
    /// The step limit was reached (the number of accepted steps).
    MaxSteps(usize),
    /// λ reached this requested stop value
    /// ([`Continuation::stop_at`](super::Continuation::stop_at)); the last
    /// point is located there.
    ParameterValue(f64),
    /// The user event with this index (in the order of
    /// [`Continuation::stop_when`](super::Continuation::stop_when)) crossed
    /// zero; the last point is located there.
    Event(usize),
    /// An observer hook returned `ControlFlow::Break`.
    Stopped,
    /// The run could not go on: a step failed even at the minimum step
    /// size, or the steps stopped moving the point, or (a rod pull) the
    /// point reached is no rod.
    Failed {
        /// The step size |Δs| of the last attempt.
        ds: f64,
        /// Why: at the minimum step, [`Error::NewtonNotConverged`] or
        /// [`Error::NewtonDiverged`] (the corrector),
        /// [`Error::SingularJacobian`], [`Error::NonFinite`] (the problem
        /// returned NaN or ∞), or [`Error::StepAngleTooLarge`] (the tangent
        /// kept turning by more than the maximum angle); at any step,
        /// [`Error::NoProgress`] (steps below the rounding of the parameter
        /// and the diagram) and, for a rod pull, [`Error::NotARod`] (a point
        /// with |Δz| > 1).
        error: Error,
    },
}

impl Termination {
    /// The error of a failed run, `None` for every other termination.
    #[must_use]
    pub fn error(&self) -> Option<&Error> {
        match self {
            Termination::Failed { error, .. } => Some(error),
            _ => None,
        }
    }
}

impl fmt::Display for Termination {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Termination::MaxSteps(n) => write!(f, "reached the step limit ({n} steps)"),
            Termination::ParameterValue(v) => write!(f, "reached the parameter value {v}"),
            Termination::Event(i) => write!(f, "user event {i} crossed zero"),
            Termination::Stopped => f.write_str("stopped by the observer"),
            Termination::Failed { ds, error } => {
                write!(f, "failed (last step Δs = {ds:e}): {error}")
            }
        }
    }
}
