//! Why a run ended.

use std::fmt;

use crate::error::Error;

/// Why a run ended.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Termination {
    /// The step limit was reached.
    MaxSteps(usize),
    /// λ reached a requested stop value (the last point is located there).
    ParameterValue(f64),
    /// A user event (by index) crossed zero (the last point is located there).
    Event(usize),
    /// The corrector failed at the minimum step.
    NewtonFailed {
        /// The step size at failure.
        ds: f64,
        /// The last error.
        reason: Error,
    },
    /// The linearised system was exactly singular at the minimum step.
    Singular(Error),
    /// The problem returned NaN or ∞ at the minimum step.
    NonFinite(Error),
    /// The tangent kept turning by more than the maximum angle at the
    /// minimum step.
    AngleTooLarge {
        /// The step size at failure.
        ds: f64,
        /// The angle between successive tangents, radians.
        angle: f64,
    },
    /// The observer asked to stop.
    Stopped,
}

impl fmt::Display for Termination {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Termination::MaxSteps(n) => write!(f, "reached the step limit ({n} steps)"),
            Termination::ParameterValue(v) => write!(f, "reached the parameter value {v}"),
            Termination::Event(i) => write!(f, "user event {i} crossed zero"),
            Termination::NewtonFailed { ds, reason } => {
                write!(
                    f,
                    "the corrector failed at the minimum step {ds:e}: {reason}"
                )
            }
            Termination::Singular(e) => write!(f, "singular system at the minimum step: {e}"),
            Termination::NonFinite(e) => write!(f, "non-finite values at the minimum step: {e}"),
            Termination::AngleTooLarge { ds, angle } => write!(
                f,
                "the tangent turned by {angle:.3} rad even at the minimum step {ds:e}"
            ),
            Termination::Stopped => f.write_str("stopped by the observer"),
        }
    }
}
