//! [`Stiffness`]: the rod's bending stiffnesses A (about d1), B (about d2)
//! and torsional stiffness C, shared by every model that needs them
//! (the helix, the 3D rod and the spring scene). Re-exported as
//! `hockle::Stiffness`.

use crate::error::{Error, Result};

/// Bending stiffnesses A (about d1) and B (about d2) and torsional stiffness C.
///
/// Validated once at construction (every value finite and positive); the
/// helix formulas use only B and C (u1 = 0 means no bending about d1).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "StiffnessParts", into = "StiffnessParts")
)]
pub struct Stiffness {
    a: f64,
    b: f64,
    c: f64,
}

/// The serialized form of [`Stiffness`], validated by [`Stiffness::new`]
/// on the way in.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct StiffnessParts {
    a: f64,
    b: f64,
    c: f64,
}

#[cfg(feature = "serde")]
impl From<Stiffness> for StiffnessParts {
    fn from(s: Stiffness) -> Self {
        Self {
            a: s.a,
            b: s.b,
            c: s.c,
        }
    }
}

#[cfg(feature = "serde")]
impl TryFrom<StiffnessParts> for Stiffness {
    type Error = Error;
    fn try_from(p: StiffnessParts) -> Result<Self> {
        Stiffness::new(p.a, p.b, p.c)
    }
}

impl Stiffness {
    /// The stiffnesses (A, B, C).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if any value is not finite and positive.
    ///
    /// ```
    /// let s = hockle::Stiffness::new(10.0, 1.0, 1.7)?;
    /// assert_eq!(s.c(), 1.7);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn new(a: f64, b: f64, c: f64) -> Result<Self> {
        for (name, v) in [("a", a), ("b", b), ("c", c)] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::InvalidArgument {
                    name,
                    value: v,
                    allowed: "a finite positive stiffness",
                });
            }
        }
        Ok(Self { a, b, c })
    }

    /// The paper's choice: B = 1, A = `a_over_b`, and C on the Nikolai bound
    ///
    /// ```text
    /// C = 2AB / ((1 + ν)(A + B))
    /// ```
    ///
    /// (equality holds for elliptical cross-sections). C/B = 1.7316 at
    /// A/B = 10, ν = 0.05, as the paper states.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if `a_over_b` is not finite and positive or
    /// ν is not in (−1, 0.5]. Every A/B up to `f64::MAX` is accepted (C is
    /// computed as 2/((1 + ν)(1 + B/A)) for A > B, without overflow).
    ///
    /// ```
    /// let s = hockle::Stiffness::nikolai(10.0, 0.05)?;
    /// assert!((s.c() - 1.7316).abs() < 5e-5);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn nikolai(a_over_b: f64, nu: f64) -> Result<Self> {
        if !(a_over_b.is_finite() && a_over_b > 0.0) {
            return Err(Error::InvalidArgument {
                name: "a_over_b",
                value: a_over_b,
                allowed: "a finite positive ratio A/B",
            });
        }
        if !(nu > -1.0 && nu <= 0.5) {
            return Err(Error::InvalidArgument {
                name: "nu",
                value: nu,
                allowed: "a Poisson ratio in (-1, 0.5]",
            });
        }
        // 2A/(A + 1) written so that neither A + 1 nor 2A overflows
        let ratio = if a_over_b <= 1.0 {
            2.0 * a_over_b / (1.0 + a_over_b)
        } else {
            2.0 / (1.0 + 1.0 / a_over_b)
        };
        let c = ratio / (1.0 + nu);
        if !(c.is_finite() && c > 0.0) {
            // not reached for A/B in (0, f64::MAX] and ν in (−1, ½]; kept so
            // that a failure names the user's arguments, not C
            return Err(Error::InvalidArgument {
                name: "a_over_b",
                value: a_over_b,
                allowed: "a ratio A/B whose Nikolai C is a finite positive double",
            });
        }
        Self::new(a_over_b, 1.0, c)
    }

    /// Bending stiffness A about d1.
    #[must_use]
    pub fn a(&self) -> f64 {
        self.a
    }

    /// Bending stiffness B about d2 (the axis of intrinsic curvature).
    #[must_use]
    pub fn b(&self) -> f64 {
        self.b
    }

    /// Torsional stiffness C.
    #[must_use]
    pub fn c(&self) -> f64 {
        self.c
    }
}

impl core::fmt::Display for Stiffness {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "A = {}, B = {}, C = {}", self.a, self.b, self.c)
    }
}
