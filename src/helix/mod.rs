//! Closed-form helical response of the anisotropic rod (the paper's Appendix).
//!
//! A rod of unit length whose unstressed shape is a helix of `n` turns at helix
//! angle θ0 (between tangent and axis) is assumed to stay an exact helix while
//! it is pulled along its axis, bending only about d2 (u1 = 0). The helix is
//! described by its angle θ and by the rate ρ at which the frame turns about the
//! axis, so that the curvature and torsion are
//!
//! ```text
//! κ = ρ sin θ,   τ = ρ cos θ,   ρ0 = 2πn,   κ0 = 2πn sin θ0,   τ0 = 2πn cos θ0,
//! ```
//!
//! the extension is Δz = cos θ and the radius R = sin θ / ρ. The strain energy
//!
//! ```text
//! U(ρ, θ) = ½ [ B (κ − κ0)² + C (τ − τ0)² ]
//! ```
//!
//! is minimised over ρ: ∂U/∂ρ = B(κ − κ0) sin θ + C(τ − τ0) cos θ is exactly the
//! axial moment M·k, so this is the helix with **zero axial moment** (ends free
//! to turn about the axis, as the zero-moment boundary conditions of the 3D
//! problem allow; the number of turns ρ/2π is then not fixed). It gives
//!
//! ```text
//! ρ(θ) = ρ0 P / Q,   P = B sin θ sin θ0 + C cos θ cos θ0,   Q = B sin²θ + C cos²θ,
//! R(θ) = R0 sin θ Q / (sin θ0 P),                     R0 = sin θ0 / (2πn) = sin²θ0 / κ0,
//! F(θ) = dU/dΔz = −B C (2πn)² P sin(θ − θ0) / (sin θ Q²)
//!      = −B C sin²θ0 P sin(θ − θ0) / (R0² sin θ Q²).
//! ```
//!
//! F is also what the Kirchhoff balance gives directly for a uniform helix,
//! F = [C(τ − τ0) sin θ − B(κ − κ0) cos θ]/R, and the spring constant of the
//! unstressed helix is
//!
//! ```text
//! dF/dΔz |θ0 = (2πn)² B C / (sin²θ0 (B sin²θ0 + C cos²θ0)).
//! ```
//!
//! # The paper's print
//!
//! The Appendix prints the force with the factor `(B sin θ0 sin θ + C cos θ0 sin θ)`
//! where the derivation gives P = `B sin θ0 sin θ + C cos θ0 cos θ` (the same
//! factor that appears, correctly, in its radius formula). The printed
//! version is not the energy derivative: at θ0 = 60°, A/B = 10, ν = 0.05 it is
//! 27 % too small already at the unstressed state (so its spring constant is
//! wrong too) and 27 % too small at θ = θ0/2; at θ0 = 89.8° the two differ by
//! C cos θ0 (cos θ − sin θ) in P, which is why the paper's low-pitch figures
//! are not visibly affected. hockle implements the derived formula and tests
//! it against dU/dΔz computed by mpmath (`tests/data/gen_elastica.py`, which
//! minimises U numerically, never using the closed form) and against finite
//! differences of [`Helix::energy`]. The radius R and R0 = sin²θ0/κ0 are printed
//! correctly.
//!
//! Forces are physical tensions in units of B/L² (there is no factor 2 here:
//! the Appendix's F is the physical one, unlike Section 3's elastica F).

use core::f64::consts::PI;

use crate::curve::{ForceExtension, ForcePoint, ForceScale};
use crate::error::{Error, Result};
use crate::stiffness::Stiffness;

/// A unit-length helical spring of `n` turns at helix angle θ0 that stays an
/// exact helix with zero axial moment while pulled (see the [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Helix {
    coils: u32,
    theta0: f64,
    stiffness: Stiffness,
}

/// Largest extension of [`Helix::curve`]: the force diverges as Δz → 1.
pub const DEFAULT_MAX_EXTENSION: f64 = 0.99;

impl Helix {
    /// The unstressed helix of `n` turns at angle `theta0` (radians, between the
    /// tangent and the axis; θ0 = π/2 is the flat n-covered ring).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if n = 0; [`Error::InvalidArgument`] if θ0 is not
    /// in (0, π/2].
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(4, 88f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
    /// assert_eq!(h.force(88f64.to_radians())?, 0.0);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn new(n: u32, theta0: f64, stiffness: Stiffness) -> Result<Self> {
        if n == 0 {
            return Err(Error::InvalidCount {
                name: "n",
                value: 0,
                allowed: "at least one turn",
            });
        }
        if !(theta0 > 0.0 && theta0 <= core::f64::consts::FRAC_PI_2) {
            return Err(Error::InvalidArgument {
                name: "theta0",
                value: theta0,
                allowed: "a helix angle in (0, π/2] radians",
            });
        }
        Ok(Self {
            coils: n,
            theta0,
            stiffness,
        })
    }

    /// Number of turns n of the unstressed helix.
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.coils
    }

    /// Unstressed helix angle θ0 (radians).
    #[must_use]
    pub fn theta0(&self) -> f64 {
        self.theta0
    }

    /// The stiffnesses.
    #[must_use]
    pub fn stiffness(&self) -> Stiffness {
        self.stiffness
    }

    fn rho0(&self) -> f64 {
        2.0 * PI * f64::from(self.coils)
    }

    fn check(theta: f64) -> Result<()> {
        if theta > 0.0 && theta < PI {
            Ok(())
        } else {
            Err(Error::InvalidArgument {
                name: "theta",
                value: theta,
                allowed: "a helix angle in (0, π) radians",
            })
        }
    }

    /// (P, Q) of the module docs.
    fn p_q(&self, theta: f64) -> (f64, f64) {
        let (b, c) = (self.stiffness.b(), self.stiffness.c());
        let (s, co) = theta.sin_cos();
        let (s0, c0) = self.theta0.sin_cos();
        (b * s * s0 + c * co * c0, b * s * s + c * co * co)
    }

    /// Physical tension along the axis at helix angle θ (corrected Appendix
    /// formula, see the [module docs](self)):
    ///
    /// ```text
    /// F(θ) = −B C (2πn)² P sin(θ − θ0) / (sin θ Q²)
    /// ```
    ///
    /// Positive (tension) for θ < θ0, zero at θ0, → ∞ as θ → 0.
    /// Accuracy: 8e-16 relative (worst of 135 points) against the mpmath energy derivative
    /// (`tests/helix`).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π).
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(4, 1.0, Stiffness::new(10.0, 1.0, 1.5)?)?;
    /// assert!(h.force(0.9)? > 0.0 && h.force(1.1)? < 0.0);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn force(&self, theta: f64) -> Result<f64> {
        Self::check(theta)?;
        let (p, q) = self.p_q(theta);
        let r0 = self.rho0();
        let bc = self.stiffness.b() * self.stiffness.c();
        Ok(-bc * r0 * r0 * p * (theta - self.theta0).sin() / (theta.sin() * q * q))
    }

    /// [`Self::force`] divided by (2πn)²B, the scale of the paper's plots
    /// ([`crate::ForceScale`]).
    ///
    /// # Errors
    /// As [`Self::force`].
    pub fn force_scaled(&self, theta: f64) -> Result<f64> {
        let r0 = self.rho0();
        Ok(self.force(theta)? / (r0 * r0) / self.stiffness.b())
    }

    /// Extension Δz = cos θ (unit length).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π).
    pub fn extension(&self, theta: f64) -> Result<f64> {
        Self::check(theta)?;
        Ok(theta.cos())
    }

    /// Radius of the deformed helix, R = R0 sin θ Q / (sin θ0 P) (Appendix,
    /// printed correctly), with R0 = sin θ0 / (2πn).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π).
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(2, 1.2, Stiffness::new(1.0, 1.0, 1.0)?)?;
    /// let r0 = 1.2f64.sin() / (4.0 * std::f64::consts::PI);
    /// assert!((h.radius(1.2)? - r0).abs() < 1e-16);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn radius(&self, theta: f64) -> Result<f64> {
        Self::check(theta)?;
        Ok(theta.sin() / self.twist_rate(theta)?)
    }

    /// Turning rate ρ = ρ0 P / Q of the frame about the axis (2π times the
    /// number of turns of the deformed helix); ρ0 = 2πn.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π).
    pub fn twist_rate(&self, theta: f64) -> Result<f64> {
        Self::check(theta)?;
        let (p, q) = self.p_q(theta);
        Ok(self.rho0() * p / q)
    }

    /// Strain energy U = ½[B(κ − κ0)² + C(τ − τ0)²] of the helix at angle θ
    /// (minimised over ρ). [`Self::force`] is dU/dΔz.
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(3, 1.0, Stiffness::new(2.0, 1.0, 1.5)?)?;
    /// let (t, d) = (0.7, 1e-6);
    /// let fd = (h.energy(t + d)? - h.energy(t - d)?) / ((t + d).cos() - (t - d).cos());
    /// assert!((fd / h.force(t)? - 1.0).abs() < 1e-7);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π).
    pub fn energy(&self, theta: f64) -> Result<f64> {
        let rho = self.twist_rate(theta)?;
        let r0 = self.rho0();
        let (s, c) = theta.sin_cos();
        let (s0, c0) = self.theta0.sin_cos();
        let dk = rho * s - r0 * s0;
        let dt = rho * c - r0 * c0;
        Ok(0.5 * (self.stiffness.b() * dk * dk + self.stiffness.c() * dt * dt))
    }

    /// Spring constant dF/dΔz at the unstressed state:
    /// (2πn)² B C / (sin²θ0 (B sin²θ0 + C cos²θ0)).
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(4, 1.2, Stiffness::nikolai(10.0, 0.05)?)?;
    /// let t = 1.2 - 1e-7;
    /// let slope = h.force(t)? / (h.extension(t)? - h.extension(1.2)?);
    /// assert!((slope / h.spring_constant() - 1.0).abs() < 1e-5);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn spring_constant(&self) -> f64 {
        let (s0, c0) = self.theta0.sin_cos();
        let (b, c) = (self.stiffness.b(), self.stiffness.c());
        let r0 = self.rho0();
        r0 * r0 * b * c / (s0 * s0 * (b * s0 * s0 + c * c0 * c0))
    }

    /// The force–extension curve from the unstressed state Δz = cos θ0 to
    /// Δz = [`DEFAULT_MAX_EXTENSION`], `samples` points equally spaced in Δz,
    /// parameter θ (radians), force scaled by (2πn)².
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `samples` < 2.
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(4, 1.0, Stiffness::nikolai(10.0, 0.05)?)?;
    /// let c = h.curve(50)?;
    /// assert_eq!(c.len(), 50);
    /// assert_eq!(c.points()[0].force, 0.0);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn curve(&self, samples: usize) -> Result<ForceExtension> {
        self.curve_to(samples, DEFAULT_MAX_EXTENSION)
    }

    /// As [`Self::curve`], up to the extension `max_extension`.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `samples` < 2; [`Error::InvalidArgument`] if
    /// `max_extension` is not in (cos θ0, 1).
    pub fn curve_to(&self, samples: usize, max_extension: f64) -> Result<ForceExtension> {
        if samples < 2 {
            return Err(Error::InvalidCount {
                name: "samples",
                value: samples as u64,
                allowed: "at least 2 points",
            });
        }
        let z0 = self.theta0.cos();
        if !(max_extension > z0 && max_extension < 1.0) {
            return Err(Error::InvalidArgument {
                name: "max_extension",
                value: max_extension,
                allowed: "an extension between cos θ0 and 1 (exclusive)",
            });
        }
        let mut curve = ForceExtension::new(
            format!("helix n={} θ0={:.4}°", self.coils, self.theta0.to_degrees()),
            "theta",
            ForceScale::new(self.coils, self.stiffness.b())?,
        );
        for i in 0..samples {
            let theta = if i == 0 {
                self.theta0
            } else {
                let t = i as f64 / (samples - 1) as f64;
                (z0 + t * (max_extension - z0)).acos()
            };
            curve.push(ForcePoint {
                extension: theta.cos(),
                force: self.force(theta)?,
                parameter: theta,
            });
        }
        Ok(curve)
    }
}

impl core::fmt::Display for Helix {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "helix of {} turns at θ0 = {}° ({})",
            self.coils,
            self.theta0.to_degrees(),
            self.stiffness
        )
    }
}
