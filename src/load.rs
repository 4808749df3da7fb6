//! The end load: which quantity a test machine prescribes ([`Control`]) and
//! how far it goes ([`Target`]).
//!
//! Two quasi-static experiments pull a spring (the paper's Section 5):
//!
//! - **force control** (dead load): the force F is prescribed, the
//!   extension Δz follows. The spring jumps at folds of F.
//! - **extension control** (hard device): Δz is prescribed, F follows. The
//!   spring jumps at folds of Δz.
//!
//! Both are answered by the same equilibria; only which of them can be
//! held, and where the spring jumps, differ. A [`Target`] is the value at
//! which a pull ends, in the paper's units: forces as F/((2πn)²B)
//! ([`crate::ForceScale`]), extensions as Δz ∈ (−1, 1).

use crate::error::{Compact, Error, Result};

/// Which end load is prescribed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Control {
    /// The force F is prescribed (dead load); Δz follows.
    #[default]
    Force,
    /// The extension Δz is prescribed (hard device); F follows.
    Extension,
}

impl core::fmt::Display for Control {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Control::Force => f.write_str("force control"),
            Control::Extension => f.write_str("extension control"),
        }
    }
}

/// Where a pull ends: the controlled quantity and its final value.
///
/// | variant | value | allowed |
/// |---|---|---|
/// | `Force(f)` | f = F/((2πn)²B), the paper's force scale | finite, ≠ 0 (negative pushes) |
/// | `Extension(dz)` | Δz, end-to-end distance per unit length | −1 < Δz < 1, ≠ the rest extension |
///
/// A model meets a target exactly: the last point of its curve is located
/// at the target (to the model's accuracy), not the first point past it.
///
/// ```
/// use hockle::{Control, Target};
/// let t = Target::Force(3.0);
/// assert_eq!(t.control(), Control::Force);
/// assert!(Target::Extension(1.0).validate(0.0).is_err()); // Δz = 1 is the straight rod
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Target {
    /// Pull until F/((2πn)²B) reaches this value (force control).
    Force(f64),
    /// Pull until Δz reaches this value (extension control).
    Extension(f64),
}

impl Target {
    /// The controlled quantity.
    #[must_use]
    pub fn control(&self) -> Control {
        match self {
            Target::Force(_) => Control::Force,
            Target::Extension(_) => Control::Extension,
        }
    }

    /// The target value: F/((2πn)²B) or Δz.
    #[must_use]
    pub fn value(&self) -> f64 {
        match *self {
            Target::Force(f) | Target::Extension(f) => f,
        }
    }

    /// The target if a spring whose rest extension is `rest_extension` can
    /// reach it.
    ///
    /// # Errors
    /// [`Error::UnreachableTarget`] if the value is not finite, a force is 0
    /// (the rest state), or an extension is not in (−1, 1) or equals
    /// `rest_extension`.
    pub fn validate(self, rest_extension: f64) -> Result<Self> {
        let ok = match self {
            Target::Force(f) => f.is_finite() && f != 0.0,
            Target::Extension(dz) => dz > -1.0 && dz < 1.0 && dz != rest_extension,
        };
        if ok {
            Ok(self)
        } else {
            Err(Error::UnreachableTarget {
                target: self,
                rest_extension,
            })
        }
    }
}

impl core::fmt::Display for Target {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Target::Force(v) => write!(f, "F/((2πn)²B) = {}", Compact(*v)),
            Target::Extension(v) => write!(f, "Δz = {}", Compact(*v)),
        }
    }
}
