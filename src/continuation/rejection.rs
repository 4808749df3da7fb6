//! Why a step was rejected ([`Rejection`], [`Observer::step_rejected`](super::Observer::step_rejected)).

use crate::error::Error;

/// Why a continuation step was rejected and tried again shorter, as the
/// observer's [`step_rejected`](super::Observer::step_rejected) hears it.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Rejection {
    /// The corrector failed (Newton diverged or did not converge, a
    /// singular Jacobian, a non-finite residual).
    Corrector(Error),
    /// The tangent turned by more than the largest angle allowed
    /// ([`Continuation::max_angle`](super::Continuation::max_angle)).
    Turn {
        /// The angle between the tangents at the step's ends (radians).
        angle: f64,
        /// The largest allowed.
        max_angle: f64,
    },
    /// A fold, branch point, stop value or event inside the step could not
    /// be located (its Newton failed across the step).
    Location(Error),
    /// With a [`tolerance`](super::Continuation::tolerance): the step's
    /// interpolant in the diagram's plane was not trusted. Any of: its
    /// interpolation error above half the tolerance, its slope turned by
    /// more than the largest angle, the corrector far from the predictor,
    /// or the extension (under force control) turning back twice inside
    /// the step (a skipped fold pair).
    Interpolant {
        /// The estimated interpolation error of the step in the plane.
        error: f64,
        /// The error allowed: half the tolerance.
        allowed: f64,
        /// The angle (radians) between the plot's slopes at the step's ends.
        turn: f64,
        /// The corrector's distance from the predictor, relative to the step.
        drift: f64,
        /// Whether the step skipped over a fold pair.
        skipped_fold_pair: bool,
    },
    /// With a tolerance: the interpolation error at a point located inside
    /// the step (a fold, a stop) was above half the tolerance.
    AtLocated {
        /// The interpolation error there.
        error: f64,
        /// The error allowed: half the tolerance.
        allowed: f64,
    },
}

impl core::fmt::Display for Rejection {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Corrector(e) => write!(f, "the corrector failed: {e}"),
            Self::Turn { angle, max_angle } => write!(
                f,
                "the tangent turned by {angle:.3e} rad (at most {max_angle:.3e})"
            ),
            Self::Location(e) => write!(f, "a special point in the step was not located: {e}"),
            Self::Interpolant {
                error,
                allowed,
                turn,
                drift,
                skipped_fold_pair,
            } => {
                write!(
                    f,
                    "the step's interpolant: error {error:.3e} (at most {allowed:.3e}), slope turned by {turn:.3e} rad, drift {drift:.3e}"
                )?;
                if *skipped_fold_pair {
                    f.write_str(", a fold pair skipped")?;
                }
                Ok(())
            }
            Self::AtLocated { error, allowed } => write!(
                f,
                "the interpolation error at a located point {error:.3e} (at most {allowed:.3e})"
            ),
        }
    }
}
