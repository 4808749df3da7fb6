//! [`Spring`]: what a user has in hand.

use core::f64::consts::PI;

use nalgebra::Vector3;

use crate::curve::ForceScale;
use crate::error::{Error, Result};
use crate::stiffness::Stiffness;

/// A helical spring of unit length: `n` coils at helix angle θ0 (between the
/// tangent and the axis), bending stiffnesses A (about d1) and B (about d2)
/// and torsional stiffness C, and intrinsic strains (u10, u20, u30).
///
/// Validated once at construction; every model then answers it without
/// re-checking. By default the intrinsic strains are those of the unstressed
/// helix bent about d2 (the paper's Section 4):
///
/// ```text
/// u10 = 0,   u20 = κ0 = 2πn sin θ0,   u30 = τ0 = 2πn cos θ0.
/// ```
///
/// ```
/// use hockle::spring::Spring;
/// let s = Spring::paper();
/// assert_eq!(s.coils(), 4);
/// assert!((s.stiffness().c() - 1.7316).abs() < 1e-4); // the paper's C/B
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "SpringParts", into = "SpringParts")
)]
pub struct Spring {
    coils: u32,
    helix_angle: f64,
    stiffness: Stiffness,
    intrinsic: Vector3<f64>,
    strip_width: Option<f64>,
}

/// The serialized form of [`Spring`], validated by its constructors on
/// the way in.
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct SpringParts {
    coils: u32,
    helix_angle: f64,
    stiffness: Stiffness,
    intrinsic_strains: [f64; 3],
    #[serde(default)]
    strip_width: Option<f64>,
}

#[cfg(feature = "serde")]
impl From<Spring> for SpringParts {
    fn from(s: Spring) -> Self {
        Self {
            coils: s.coils,
            helix_angle: s.helix_angle,
            stiffness: s.stiffness,
            intrinsic_strains: s.intrinsic.into(),
            strip_width: s.strip_width,
        }
    }
}

#[cfg(feature = "serde")]
impl TryFrom<SpringParts> for Spring {
    type Error = Error;
    fn try_from(p: SpringParts) -> Result<Self> {
        let spring = Spring::new(p.coils, p.helix_angle, p.stiffness)?
            .with_intrinsic_strains(Vector3::from(p.intrinsic_strains))?;
        match p.strip_width {
            Some(w) => spring.with_strip_width(w),
            None => Ok(spring),
        }
    }
}

impl Spring {
    /// A spring of `coils` turns at `helix_angle` (radians) with `stiffness`,
    /// whose intrinsic strains are those of its unstressed helix.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `coils` is 0; [`Error::InvalidArgument`] if
    /// `helix_angle` is not in (0, π/2] or (2πn)²B overflows.
    pub fn new(coils: u32, helix_angle: f64, stiffness: Stiffness) -> Result<Self> {
        ForceScale::new(coils, stiffness.b())?;
        if !(helix_angle > 0.0 && helix_angle <= PI / 2.0) {
            return Err(Error::InvalidArgument {
                name: "helix_angle",
                value: helix_angle,
                allowed: "an angle in (0, π/2] radians between tangent and axis",
            });
        }
        let rho = 2.0 * PI * f64::from(coils);
        let intrinsic = Vector3::new(0.0, rho * helix_angle.sin(), rho * helix_angle.cos());
        Ok(Self {
            coils,
            helix_angle,
            stiffness,
            intrinsic,
            strip_width: None,
        })
    }

    /// The same spring with the helix angle given in degrees.
    ///
    /// # Errors
    /// As [`Spring::new`].
    pub fn from_degrees(
        coils: u32,
        helix_angle_degrees: f64,
        stiffness: Stiffness,
    ) -> Result<Self> {
        Self::new(coils, helix_angle_degrees.to_radians(), stiffness)
    }

    /// The paper's spring (Fig. spring): n = 4, θ0 = 89.8°, A/B = 10, ν = 0.05
    /// (C/B = 1.7316 by the Nikolai equality).
    #[must_use]
    pub fn paper() -> Self {
        let stiffness = Stiffness::nikolai(10.0, 0.05).expect("A/B = 10, ν = 0.05 are valid");
        Self::from_degrees(4, 89.8, stiffness).expect("n = 4, θ0 = 89.8° are valid")
    }

    /// The same spring with other intrinsic strains (u10, u20, u30), e.g. a
    /// rod whose natural curvature is not about d2.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if a component is not finite.
    pub fn with_intrinsic_strains(mut self, strains: Vector3<f64>) -> Result<Self> {
        for (name, v) in ["u10", "u20", "u30"].into_iter().zip(strains.iter()) {
            if !v.is_finite() {
                return Err(Error::InvalidArgument {
                    name,
                    value: *v,
                    allowed: "a finite intrinsic strain",
                });
            }
        }
        self.intrinsic = strains;
        Ok(self)
    }

    /// The same spring as a strip of `width` (in units of the rod's length,
    /// like every length here), so that a pull that computes shapes flags
    /// the first point where the strip would touch itself
    /// ([`Response::first_contact`](super::Response::first_contact)). The
    /// rod model itself knows no width: the paper's "narrow strip".
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless the width is finite and positive.
    pub fn with_strip_width(mut self, width: f64) -> Result<Self> {
        check_strip_width(width)?;
        self.strip_width = Some(width);
        Ok(self)
    }

    /// The strip width, if given ([`Spring::with_strip_width`]).
    #[must_use]
    pub fn strip_width(&self) -> Option<f64> {
        self.strip_width
    }

    /// The number of coils n of the unstressed helix.
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.coils
    }

    /// The helix angle θ0 in radians.
    #[must_use]
    pub fn helix_angle(&self) -> f64 {
        self.helix_angle
    }

    /// The stiffnesses A, B, C.
    #[must_use]
    pub fn stiffness(&self) -> Stiffness {
        self.stiffness
    }

    /// The intrinsic strains (u10, u20, u30).
    #[must_use]
    pub fn intrinsic_strains(&self) -> Vector3<f64> {
        self.intrinsic
    }

    /// Whether the intrinsic strains are those of the unstressed helix
    /// (u10 = 0, u20 = 2πn sin θ0, u30 = 2πn cos θ0), as the helix and
    /// elastica models assume.
    #[must_use]
    pub fn is_helical(&self) -> bool {
        let rho = 2.0 * PI * f64::from(self.coils);
        let natural = Vector3::new(
            0.0,
            rho * self.helix_angle.sin(),
            rho * self.helix_angle.cos(),
        );
        self.intrinsic == natural
    }

    /// The paper's force scale (2πn)²·B of F/((2πn)²B).
    #[must_use]
    pub fn scale(&self) -> ForceScale {
        ForceScale::new(self.coils, self.stiffness.b()).expect("validated by Spring::new")
    }

    /// (2πn)²·B, the value of [`Spring::scale`].
    #[must_use]
    pub fn force_scale(&self) -> f64 {
        self.scale().value()
    }
}

/// A strip width: finite and positive.
pub(crate) fn check_strip_width(width: f64) -> Result<f64> {
    if width.is_finite() && width > 0.0 {
        Ok(width)
    } else {
        Err(Error::InvalidArgument {
            name: "strip width",
            value: width,
            allowed: "a finite, positive width (in units of the rod's length)",
        })
    }
}

impl core::fmt::Display for Spring {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "spring: {} coils, θ0 = {}°, {}",
            self.coils,
            self.helix_angle.to_degrees(),
            self.stiffness
        )
    }
}
