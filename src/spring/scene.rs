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

    /// The linear spring constant dF/dΔz of the unloaded spring (physical
    /// force per unit extension, in units of B): the slope at rest of the
    /// 3D rod's force–extension curve, whose ends lie on the force line.
    ///
    /// Castigliano's theorem on the unstressed helix: with M(0) = 0 and the
    /// end load F k applied on the line through both ends, the moment is
    /// statically determinate, M(s) = (r(s) − r(0)) × F k, so in the frame
    /// of the rest helix (φ = 2πn s, R0 = sin θ0/(2πn))
    ///
    /// ```text
    /// M·d1 = −F R0 sin φ,  M·d2 = F R0 cos θ0 (1 − cos φ),  M·d3 = −F R0 sin θ0 (1 − cos φ)
    /// 1/k  = ∫₀¹ Σ (M·dᵢ)²/Kᵢ ds / F²
    ///      = R0² [ 1/(2A) + (3/2)(cos²θ0/B + sin²θ0/C) ]        (n whole turns)
    /// ```
    ///
    /// The exact-helix model ([`crate::helix::Helix::spring_constant`]) is
    /// loaded on the helix's axis instead (end plates): its lever is R0
    /// everywhere and 1/k_helix = R0² (cos²θ0/B + sin²θ0/C), stiffer by a
    /// factor of about 1.6 for the paper's spring. The two answer different
    /// loadings; this one is the rod's (`tests/spring/choice.rs` checks it
    /// against the rod's slope at rest and against a quadrature of the
    /// integral).
    ///
    /// Only for a spring whose intrinsic strains are its helix's (the rest
    /// state must be that helix).
    ///
    /// # Errors
    /// [`Error::OutsideModel`] if the intrinsic strains are not the
    /// helix's; [`Error::Overflow`] if the constant is not a positive
    /// finite double (stiffnesses many hundred orders of magnitude apart).
    ///
    /// ```
    /// use hockle::spring::Spring;
    /// let s = Spring::paper();
    /// let k = s.spring_constant()? / s.force_scale();
    /// assert!((k - 1.0914).abs() < 1e-4); // dF/dΔz in units of (2πn)²B
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn spring_constant(&self) -> Result<f64> {
        if !self.is_helical() {
            return Err(Error::OutsideModel {
                model: "linear response",
                assumption: "the closed form needs the unstressed helix as the rest state \
                             (the spring's intrinsic strains are not its helix's): pull the \
                             rod (RodModel) and read the slope of its first point",
            });
        }
        let (a, b, c) = (self.stiffness.a(), self.stiffness.b(), self.stiffness.c());
        // the compliance times the smallest stiffness s: every term at most
        // 1.5, so no stiffness in (0, f64::MAX] overflows on the way (over
        // the largest, 0.5/(A/s) overflowed for A/B = 1e-320, whose k,
        // about 2A(2πn/sin θ0)², is a double); the lever squared is
        // formed with √s, so a tiny s does not follow an overflow
        let s = a.min(b).min(c);
        let (sin, cos) = self.helix_angle.sin_cos();
        let compliance = 0.5 * (s / a) + 1.5 * (cos * cos * (s / b) + sin * sin * (s / c));
        let rho = 2.0 * PI * f64::from(self.coils);
        let lever = rho / sin * s.sqrt();
        let k = lever * lever / compliance;
        if k.is_finite() && k > 0.0 {
            Ok(k)
        } else {
            Err(Error::Overflow {
                quantity: "spring constant",
                name: "A/B",
                value: a / b,
            })
        }
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
