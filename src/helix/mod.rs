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

mod scaled;

use core::f64::consts::PI;

use crate::curve::{ForceExtension, ForcePoint, ForceScale};
use crate::error::{Error, Result, check_points};
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

/// P and Q over max(B, C), and min(B, C) (see [`Helix::scaled_p_q`]).
struct ScaledPQ {
    p: f64,
    q: f64,
    big: f64,
    small: f64,
}

/// Largest extension of [`Helix::curve`]: the force diverges as Δz → 1.
pub const DEFAULT_MAX_EXTENSION: f64 = 0.99;

impl Helix {
    /// The unstressed helix of `coils` turns at helix angle `helix_angle`
    /// (θ0, radians, between the tangent and the axis; θ0 = π/2 is the flat
    /// n-covered ring): the arguments of [`Spring::new`](crate::spring::Spring::new)
    /// and [`Rod::new`](crate::rod::Rod::new).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `coils` = 0; [`Error::InvalidArgument`] if
    /// the helix angle is not in (0, π/2].
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(4, 88f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
    /// assert_eq!(h.force(88f64.to_radians())?, 0.0);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn new(coils: u32, helix_angle: f64, stiffness: Stiffness) -> Result<Self> {
        if coils == 0 {
            return Err(Error::InvalidCount {
                name: "coils",
                value: 0,
                allowed: "at least one coil",
            });
        }
        if !(helix_angle > 0.0 && helix_angle <= core::f64::consts::FRAC_PI_2) {
            return Err(Error::InvalidArgument {
                name: "helix_angle",
                value: helix_angle,
                allowed: "a helix angle in (0, π/2] radians",
            });
        }
        Ok(Self {
            coils,
            theta0: helix_angle,
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

    /// (P, Q) of the module docs divided by max(B, C), with min(B, C): every
    /// closed form is written with these so that no stiffness in
    /// (0, `f64::MAX`] overflows or underflows on the way (the helix depends
    /// on B and C only through C/B and one overall scale).
    fn scaled_p_q(&self, theta: f64) -> ScaledPQ {
        let (b, c) = (self.stiffness.b(), self.stiffness.c());
        let (big, small) = if b >= c { (b, c) } else { (c, b) };
        let (bt, ct) = (b / big, c / big);
        let (s, co) = theta.sin_cos();
        let (s0, c0) = self.theta0.sin_cos();
        ScaledPQ {
            p: bt * s * s0 + ct * co * c0,
            q: bt * s * s + ct * co * co,
            big,
            small,
        }
    }

    /// F = −(2πn)² min(B, C) p̃ sin(θ − θ0) / (sin θ q̃²), p̃ = P/max(B, C),
    /// q̃ = Q/max(B, C) (the module docs' F), factors kept apart.
    fn scaled_force(&self, theta: f64) -> f64 {
        let pq = self.scaled_p_q(theta);
        let r0 = self.rho0();
        -scaled::ratio(
            &[pq.small, pq.p, (theta - self.theta0).sin(), r0, r0],
            &[theta.sin(), pq.q, pq.q],
        )
    }

    fn finite(value: f64, quantity: &'static str, theta: f64) -> Result<f64> {
        if value.is_finite() {
            Ok(value)
        } else {
            Err(Error::Overflow {
                quantity,
                name: "theta",
                value: theta,
            })
        }
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
    /// (`tests/helix`). Evaluated with B and C scaled by max(B, C) and the
    /// exponents of the factors carried apart, so every stiffness in
    /// (0, `f64::MAX`] gives the same relative accuracy (`tests/helix`:
    /// scaling B, C by 2^±1000 scales F exactly).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π); [`Error::Overflow`]
    /// if |F| is beyond the largest double (θ → 0 with a huge stiffness).
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
        Self::finite(self.scaled_force(theta), "force", theta)
    }

    /// [`Self::force`] divided by (2πn)²B, the scale of the paper's plots
    /// ([`crate::ForceScale`]).
    ///
    /// # Errors
    /// As [`Self::force`].
    pub fn force_scaled(&self, theta: f64) -> Result<f64> {
        Self::check(theta)?;
        let pq = self.scaled_p_q(theta);
        // F/((2πn)²B) = −(min(B, C)/B) p̃ sin(θ − θ0) / (sin θ q̃²)
        let f = -scaled::ratio(
            &[pq.small, pq.p, (theta - self.theta0).sin()],
            &[theta.sin(), pq.q, pq.q, self.stiffness.b()],
        );
        Self::finite(f, "force", theta)
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
        let pq = self.scaled_p_q(theta);
        let r = scaled::ratio(&[theta.sin(), pq.q], &[self.rho0(), pq.p]);
        Self::finite(r, "radius", theta)
    }

    /// Turning rate ρ = ρ0 P / Q of the frame about the axis (2π times the
    /// number of turns of the deformed helix); ρ0 = 2πn.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if θ is not in (0, π); [`Error::Overflow`]
    /// if ρ is beyond the largest double.
    pub fn twist_rate(&self, theta: f64) -> Result<f64> {
        Self::check(theta)?;
        let pq = self.scaled_p_q(theta);
        Self::finite(self.rho0() * pq.p / pq.q, "twist rate", theta)
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
    /// [`Error::InvalidArgument`] if θ is not in (0, π); [`Error::Overflow`]
    /// if U is beyond the largest double.
    pub fn energy(&self, theta: f64) -> Result<f64> {
        let rho = self.twist_rate(theta)?;
        let r0 = self.rho0();
        let (s, c) = theta.sin_cos();
        let (s0, c0) = self.theta0.sin_cos();
        let dk = rho * s - r0 * s0;
        let dt = rho * c - r0 * c0;
        let pq = self.scaled_p_q(theta);
        let (bt, ct) = (self.stiffness.b() / pq.big, self.stiffness.c() / pq.big);
        let u = scaled::ratio(&[0.5 * (bt * dk * dk + ct * dt * dt), pq.big], &[]);
        Self::finite(u, "energy", theta)
    }

    /// Spring constant dF/dΔz at the unstressed state:
    /// (2πn)² B C / (sin²θ0 (B sin²θ0 + C cos²θ0)), evaluated as
    /// (2πn)² min(B, C) / (sin²θ0 q̃0) with the exponents carried apart (see
    /// [`Self::force`]).
    ///
    /// ```
    /// use hockle::Stiffness;
    /// use hockle::helix::Helix;
    /// let h = Helix::new(4, 1.2, Stiffness::nikolai(10.0, 0.05)?)?;
    /// let t = 1.2 - 1e-7;
    /// let slope = h.force(t)? / (h.extension(t)? - h.extension(1.2)?);
    /// assert!((slope / h.spring_constant()? - 1.0).abs() < 1e-5);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::Overflow`] if the constant is beyond the largest double
    /// (θ0 → 0 with a large stiffness).
    pub fn spring_constant(&self) -> Result<f64> {
        let pq = self.scaled_p_q(self.theta0);
        let (s0, r0) = (self.theta0.sin(), self.rho0());
        let k = scaled::ratio(&[r0, r0, pq.small], &[s0, s0, pq.q]);
        Self::finite(k, "spring constant", self.theta0)
    }

    /// The force–extension curve from the unstressed state Δz = cos θ0 to
    /// Δz = [`DEFAULT_MAX_EXTENSION`], `samples` points equally spaced in Δz,
    /// parameter θ (radians), force scaled by (2πn)².
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `samples` < 2 or > [`MAX_POINTS`](crate::error::MAX_POINTS).
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
    /// [`Error::InvalidCount`] if `samples` < 2 or > [`MAX_POINTS`](crate::error::MAX_POINTS); [`Error::InvalidArgument`] if
    /// `max_extension` is not in (cos θ0, 1); [`Error::Overflow`] if the
    /// curve's force scale (2πn)²B or a force is beyond the largest double.
    pub fn curve_to(&self, samples: usize, max_extension: f64) -> Result<ForceExtension> {
        check_points("samples", samples)?;
        let z0 = self.theta0.cos();
        if !(max_extension > z0 && max_extension < 1.0) {
            return Err(Error::InvalidArgument {
                name: "max_extension",
                value: max_extension,
                allowed: "an extension between cos θ0 and 1 (exclusive)",
            });
        }
        // a curve carries its force scale (2πn)²B, which can overflow where
        // the helix's own (scaled) closed forms do not
        let scale =
            ForceScale::new(self.coils, self.stiffness.b()).map_err(|_| Error::Overflow {
                quantity: "force scale (2πn)²B of the curve",
                name: "B",
                value: self.stiffness.b(),
            })?;
        let mut curve = ForceExtension::new(
            format!("helix n={} θ0={:.4}°", self.coils, self.theta0.to_degrees()),
            "theta",
            scale,
        );
        for i in 0..samples {
            let theta = if i == 0 {
                self.theta0
            } else {
                let t = i as f64 / (samples - 1) as f64;
                // z0 + (zmax − z0) can round above zmax (to 1 for
                // zmax = 1 − 2⁻⁵³, where θ = 0 is not a helix)
                (z0 + t * (max_extension - z0)).min(max_extension).acos()
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

// Every model, setting and result type of this layer can cross threads.
const _: fn() = || {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<Helix>();
    send_sync::<Stiffness>();
    send_sync::<ForceExtension>();
};
