//! [`Question`]: what a user asks a [`Spring`](super::Spring), at a
//! tolerance ([`Spring::answer`](super::Spring::answer)).

use crate::error::{Compact, Error, Result};
use crate::load::{Control, Target};

/// What a user wants to know about a spring. Forces are F/((2πn)²B) (the
/// paper's scale), extensions Δz, as everywhere in [`crate::spring`].
///
/// Each question is answered by computing only what it needs: a curve
/// question pulls to its load and no further; shapes, energies, stability
/// labels and contact are never computed as a side cost.
///
/// ```
/// use hockle::spring::Question;
/// let q = Question::PopOuts { max_force: 1.5 };
/// assert!(q.check().is_ok());
/// assert!(Question::ForcesAt(vec![]).check().is_err());
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub enum Question {
    /// The force–extension curve from rest to F/((2πn)²B) = `max_force`.
    Curve {
        /// The load at which the curve ends (finite, non-zero; negative
        /// pushes).
        max_force: f64,
    },
    /// The forces F/((2πn)²B) of a test under extension control (a hard
    /// device) at these extensions: the rod is pulled from rest to the
    /// largest extension asked, and every force at which its path passes
    /// through each extension is returned (several where the path turns
    /// back in Δz before the largest). Equilibria the path does not visit
    /// (beyond the largest extension) are not searched for.
    ForcesAt(Vec<f64>),
    /// The extensions Δz of a test under force control (a dead load) at
    /// these forces F/((2πn)²B): the rod is pulled from rest to the largest
    /// force asked, and every Δz at which its path has each force is
    /// returned (several across a pop-out).
    ExtensionsAt(Vec<f64>),
    /// The linear spring constant dF/dΔz at rest (physical force per unit
    /// extension).
    SpringConstant,
    /// The pop-outs (maximum-force fold, minimum-force fold) below the load
    /// F/((2πn)²B) = `max_force`, and the jumps of a force-controlled test
    /// (loading and unloading: the hysteresis).
    PopOuts {
        /// The largest load of the test.
        max_force: f64,
    },
    /// The shape of the spring at one load, and its loop count there: the
    /// equilibrium at which the pull from rest first reaches `at` (a force
    /// F/((2πn)²B) under force control, a dead load; an extension Δz under
    /// extension control, a hard device). Under force control that is the
    /// state of a slow loading test after every pop-out below the load. A
    /// pull that stops before the load answers with the shape of its last
    /// point ([`Answer::reached_target`](super::Answer::reached_target) is
    /// then false). A load within about the tolerance of a pop-out is
    /// ill-conditioned: which side of the jump the shape lies on depends on
    /// where the pull locates the fold.
    Shape {
        /// The load (or extension) of the shape.
        at: Target,
    },
}

impl Question {
    /// The target a pull needs to answer the question: the largest load or
    /// extension asked about; `None` for the spring constant (no pull).
    ///
    /// # Errors
    /// As [`Question::check`]; [`Error::InvalidArgument`] for values on
    /// both sides of rest (naming the first across it) or all at rest
    /// (values at rest among others on one side are answered: the rest
    /// state's Δz = cos θ0 or F = 0), and for extensions when the rest
    /// extension is not known (NaN: a spring with other intrinsic strains
    /// than its helix's); [`Error::UnreachableTarget`] for any extension
    /// outside (−1, 1).
    pub fn target(&self, rest_extension: f64) -> Result<Option<Target>> {
        self.check()?;
        if let (Question::ForcesAt(_), true) = (self, rest_extension.is_nan()) {
            // (NaN: a spring with other intrinsic strains, whose rest
            // state the rod finds only when it relaxes; no side of it can
            // be told, nor which extension is farthest)
            return Err(Error::InvalidArgument {
                name: "rest extension",
                value: rest_extension,
                allowed: "a known rest extension: the forces at extensions are asked of springs \
                          with their helix's intrinsic strains; for others ask the curve \
                          (Question::Curve) and read it with ForceExtension::force_at",
            });
        }
        let (values, rest) = match self {
            Question::ExtensionsAt(forces) => (&forces[..], 0.0),
            Question::ForcesAt(extensions) => (&extensions[..], rest_extension),
            _ => (&[][..], 0.0),
        };
        if !values.is_empty() && values.iter().all(|v| *v == rest) {
            return Err(Error::InvalidArgument {
                name: "values (every one at rest)",
                value: rest,
                allowed: "at least one value off rest (at rest F = 0 and Δz = cos θ0, the rest \
                          state's, with no pull to make)",
            });
        }
        if let Some(value) = across_rest(values, rest) {
            let (name, allowed) = if matches!(self, Question::ExtensionsAt(_)) {
                (
                    "force (across rest, F = 0, from the others)",
                    "forces all on one side of rest, or at rest (all pulls or all pushes): \
                     ask pulls and pushes as two questions",
                )
            } else {
                (
                    "extension (across rest, Δz = cos θ0, from the others)",
                    "extensions all on one side of rest, or at rest (all pulls or all \
                     pushes): ask pulls and pushes as two questions",
                )
            };
            return Err(Error::InvalidArgument {
                name,
                value,
                allowed,
            });
        }
        if let Question::ForcesAt(extensions) = self
            && let Some(&dz) = extensions.iter().find(|dz| !(**dz > -1.0 && **dz < 1.0))
        {
            // (values at rest are read off the pull's first point, but
            // only inside (−1, 1): cos θ0 rounds to 1 for θ0 → 0)
            return Err(Error::UnreachableTarget {
                target: Target::Extension(dz),
                rest_extension,
            });
        }
        let target = match self {
            Question::Curve { max_force } | Question::PopOuts { max_force } => {
                Target::Force(*max_force)
            }
            Question::ExtensionsAt(forces) => Target::Force(farthest(forces, 0.0)),
            Question::ForcesAt(extensions) => {
                Target::Extension(farthest(extensions, rest_extension))
            }
            Question::Shape { at } => *at,
            Question::SpringConstant => return Ok(None),
        };
        Ok(Some(target.validate(rest_extension)?))
    }

    /// Validates the question's own values (not yet against a spring).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a load that is not finite and
    /// non-zero, a list of values that is empty, holds a non-finite value,
    /// or mixes pulls and pushes (values on both sides of rest: ask them as
    /// two questions); [`Error::UnreachableTarget`] through
    /// [`Question::target`] for an extension outside (−1, 1).
    pub fn check(&self) -> Result<()> {
        match self {
            Question::Curve { max_force } | Question::PopOuts { max_force } => {
                if !(max_force.is_finite() && *max_force != 0.0) {
                    return Err(Error::InvalidArgument {
                        name: "max_force",
                        value: *max_force,
                        allowed: "a finite, non-zero load F/((2πn)²B) (negative pushes)",
                    });
                }
            }
            Question::ForcesAt(values) | Question::ExtensionsAt(values) => {
                let name = if matches!(self, Question::ForcesAt(_)) {
                    "extensions"
                } else {
                    "forces"
                };
                if values.is_empty() {
                    return Err(Error::InvalidCount {
                        name,
                        value: 0,
                        allowed: "at least one value to answer at",
                    });
                }
                if let Some(bad) = values.iter().find(|v| !v.is_finite()) {
                    return Err(Error::InvalidArgument {
                        name,
                        value: *bad,
                        allowed: "finite values",
                    });
                }
            }
            Question::Shape { at } => {
                if !(at.value().is_finite()
                    && (at.control() == Control::Extension || at.value() != 0.0))
                {
                    return Err(Error::InvalidArgument {
                        name: "shape load",
                        value: at.value(),
                        allowed: "a finite, non-zero force F/((2πn)²B), or a finite extension \
                                  in (−1, 1) other than the rest extension",
                    });
                }
            }
            Question::SpringConstant => {}
        }
        Ok(())
    }

    /// A short name for tables.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Question::Curve { .. } => "curve",
            Question::ForcesAt(_) => "forces at extensions",
            Question::ExtensionsAt(_) => "extensions at forces",
            Question::SpringConstant => "spring constant",
            Question::PopOuts { .. } => "pop-outs",
            Question::Shape { .. } => "shape",
        }
    }
}

/// The value farthest from `rest` (the pull must reach it).
fn farthest(values: &[f64], rest: f64) -> f64 {
    values
        .iter()
        .copied()
        .max_by(|a, b| (a - rest).abs().total_cmp(&(b - rest).abs()))
        .unwrap_or(rest)
}

/// The first value on the other side of `rest` from the first value off
/// it, if any: one pull from rest reaches every value at rest or on one
/// side.
fn across_rest(values: &[f64], rest: f64) -> Option<f64> {
    let first = values.iter().find(|v| **v != rest)?;
    let side = (first - rest).signum();
    values.iter().copied().find(|v| (v - rest) * side < 0.0)
}

impl core::fmt::Display for Question {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Question::Curve { max_force } => {
                write!(f, "the curve up to F/((2πn)²B) = {}", Compact(*max_force))
            }
            Question::ForcesAt(x) => write!(f, "the forces at {} extensions", x.len()),
            Question::ExtensionsAt(x) => write!(f, "the extensions at {} forces", x.len()),
            Question::SpringConstant => f.write_str("the spring constant at rest"),
            Question::PopOuts { max_force } => {
                write!(
                    f,
                    "the pop-outs up to F/((2πn)²B) = {}",
                    Compact(*max_force)
                )
            }
            Question::Shape { at } => write!(f, "the shape at {at}"),
        }
    }
}
