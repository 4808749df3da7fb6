//! The 3D anisotropic Kirchhoff rod with zero-moment ends (the paper's
//! Section 2), as a boundary-value [`Problem`](crate::bvp::Problem), and
//! the pull of a helical spring from rest through its pop-outs.
//!
//! ## Main types
//!
//! | type | role |
//! |---|---|
//! | [`Rod`] | the problem: n coils, helix angle θ0, stiffnesses, [`Control`]; implements [`crate::bvp::Problem`] with analytic Jacobians; [`Rod::symmetric`] solves its half, the other half the image under the midpoint's two-fold rotation |
//! | [`Equilibrium`] | one solution with its outputs on demand (force, extension, frame, strains, energy, planarity, loop count, \|q\| drift) |
//! | [`Pull`] | the driver: pseudo-arclength from rest to a [`crate::Target`] (force or extension), folds located; [`Start`] to drive it step by step |
//! | [`PullRun`] | the curve in order, the located [`crate::Fold`]s, a loop count per point, the continuation's [`crate::continuation::Termination`] |
//! | [`Relaxation`] | where a pull allowed to ([`Pull::relax_to`]) went on at a looser tolerance past loops sliding along the rod, and why |
//!
//! ```no_run
//! use hockle::rod::{Pull, Rod};
//! use hockle::{Stiffness, Target};
//! // The paper's Fig. spring: three pop-outs, 4 → 3 → 2 → 1 loops, ~2 s.
//! let rod = Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
//! let run = Pull::new(rod, Target::Force(3.0)).run(())?;
//! assert!(run.reached_target());
//! for fold in run.folds() {
//!     println!(
//!         "{} at Δz = {:.4}, F/((2πn)²B) = {:.4}",
//!         fold.kind,
//!         fold.point.extension,
//!         fold.point.force_scaled(rod.scale())
//!     );
//! }
//! # Ok::<(), hockle::Error>(())
//! ```
//!
//! ## Equations
//!
//! A thin, inextensible, unshearable rod of length 1 with principal bending
//! stiffnesses A (about d1), B (about d2), torsional stiffness C and intrinsic
//! strains u0 = (u10, u20, u30). Thirteen unknowns on s ∈ [0, 1]:
//!
//! ```text
//!   y = (r, q, F, M)        r ∈ ℝ³ centreline, q ∈ ℝ⁴ quaternion (w, x, y, z),
//!                           F ∈ ℝ³ internal force, M ∈ ℝ³ internal moment (lab frame)
//!   d_i = R(q) e_i          R(q) the homogeneous rotation matrix of q
//!   u   = D⁻¹ Rᵀ M + u0     D = diag(A, B, C)                      (eq:constit)
//!   r′  = d3
//!   q′  = ½ q ⊗ (0, u)      ⇔ d_i′ = u × d_i
//!   F′  = 0,  M′ = F × d3                                          (eq:bal)
//! ```
//!
//! For a helical spring of n coils and helix angle θ0 (angle between the
//! tangent and the axis): u0 = 2πn (0, sin θ0, cos θ0), i.e. curvature
//! κ0 = 2πn sin θ0 about d2 (the soft axis when A > B) and torsion
//! τ0 = 2πn cos θ0.
//!
//! ## Boundary conditions (the paper's eq. bcs, with a different gauge)
//!
//! ```text
//!   r(0) = 0,  x(1) = y(1) = 0,  M(0) = 0,  M_x(1) = M_y(1) = 0,
//!   F_z = λ   (force control)   or   z(1) = Δz   (extension control),
//!   ½(|q(0)|² − 1) = 0,
//!   ∫₀¹ ⟨q, G q_ref⟩ ds = 0,   G q = ½ k ⊗ q.
//! ```
//!
//! Twelve boundary conditions and one integral condition for 13 unknowns.
//! |q(0)| = 1 is enough: q′ = ½ q ⊗ (0, u) conserves |q|², and Gauss
//! collocation conserves quadratic invariants exactly, so |q| − 1 stays at
//! the level of the Newton tolerance along the whole rod (a free accuracy
//! check, [`Equilibrium::quaternion_drift`]).
//!
//! **The rotational gauge.** A rigid rotation of a solution about the force
//! axis k is again a solution. The paper removes it with d1(1)·i = 0, which
//! degenerates where d1(1) ∥ k (planar solutions at θ0 = 90°); the integral
//! condition ∫x ds = 0 degenerates where the centroid crosses the axis. Both
//! create spurious branch points whose "branch" is the rigid rotation. hockle
//! uses the phase condition of a continuous symmetry instead: the new
//! solution is orthogonal, in L², to the generator of the rotation applied to
//! the reference solution q_ref (the previous continuation point). Its
//! derivative along the symmetry orbit is ∫ |G q_ref|² ds = ¼ ∫ |q_ref|² ds =
//! ¼, never zero, so the condition cannot degenerate anywhere on any path.
//! Only the quaternion enters (r, F, M rotate too, but adding them would only
//! change the weighting, not the transversality).
//!
//! ## Parameters
//!
//! `p = [λ, Δz, θ0]` ([`Rod::FORCE`], [`Rod::EXTENSION`], [`Rod::THETA0`]):
//! the force F_z (used by force control), the prescribed extension z(1)
//! (used by extension control) and the helix angle that sets u0 (so that one
//! can also continue in θ0, e.g. to θ0 = 90° exactly).
//!
//! ## Start
//!
//! At λ = 0 the unstressed helix is an exact solution ([`Rod::unstressed`]):
//! with φ = 2πn s, c = cos θ0, S = sin θ0, R0 = S/(2πn),
//!
//! ```text
//!   r  = (R0 sin φ, R0 (1 − cos φ), c s)
//!   d1 = (−sin φ, cos φ, 0),  d2 = (−c cos φ, −c sin φ, S),  d3 = (S cos φ, S sin φ, c)
//!   q  = q_z(φ + π/2) ⊗ q_x(θ0) = (cos β cos a, cos β sin a, sin β sin a, sin β cos a),
//!        β = (φ + π/2)/2,  a = θ0/2
//!   F = M = 0.
//! ```
//!
//! (The frame at φ = 0 is R_z(π/2) R_x(θ0), and the whole frame turns
//! about k with φ.)
//!
//! ## Pulling
//!
//! [`Pull`] continues the solution from rest by pseudo-arclength in the
//! controlled load (F_z, or Δz under [`Control::Extension`]); see the
//! [`Pull`] docs for the norm, the step control and the fold location. The
//! first steps must be small: within F/((2πn)²B) ≈ 0.004–0.01 the low-pitch
//! helix tilts its coils into a plane through the force axis at almost
//! constant force (the paper's "turns and shears"); a parameter stepping in
//! F jumps over that stretch onto a stiffer branch of tilted coils.
//!
//! Accuracy and cost (docs/ACCURACY.md, docs/PERFORMANCE.md): the paper's
//! curve with its six folds in 2.0 s of CPU and 7 MB, folds converged to
//! 6e-7; at θ0 = 90° the planar solutions agree with the elastica to 1e-10.

pub mod cascade;
mod contact;
mod equilibrium;
mod jet;
mod measure;
mod nikolai;
mod phase_diagram;
mod problem;
mod pull;
mod quat;
mod stability;
mod symmetry;

use core::f64::consts::{FRAC_PI_2, PI};

use nalgebra::Vector3;

use crate::curve::ForceScale;
use crate::error::{Error, Result};
use crate::load::Control;
use crate::stiffness::Stiffness;

pub use cascade::{CuspSearch, Followed, MeshChecked};
pub use contact::Contact;
pub use equilibrium::Equilibrium;
pub use nikolai::NikolaiRod;
pub use phase_diagram::{CuspAt, CuspLine, Fixed, LineEnd, PhaseDiagram, Unfinished};
pub use pull::{Pull, PullRun, Relaxation, Start};
pub use stability::{STABILITY_SEGMENTS, SecondVariation};

/// A helical spring of n coils as a 3D anisotropic Kirchhoff rod with
/// zero-moment ends: the boundary-value problem of the module docs.
///
/// Validated on construction; every method afterwards is infallible.
///
/// ```
/// use hockle::bvp::Problem;
/// use hockle::rod::Rod;
/// use hockle::Stiffness;
/// let rod = Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
/// assert_eq!(rod.dim(), 13);
/// assert!((rod.stiffness().c() - 1.7316).abs() < 5e-5); // the paper's C/B
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Rod {
    coils: u32,
    theta0: f64,
    a: f64,
    b: f64,
    c: f64,
    /// u0 − 2πn (0, sin θ0, cos θ0): zero for a helical spring.
    strain_offset: Vector3<f64>,
    control: Control,
    /// Solved on its half s ∈ [0, ½] ([`Rod::symmetric`]).
    #[cfg_attr(feature = "serde", serde(default))]
    half: bool,
}

impl Rod {
    /// Number of unknowns (r, q, F, M).
    pub const DIM: usize = 13;
    /// Number of parameters.
    pub const PARAMETERS: usize = 3;
    /// Index of the force λ = F_z in the parameter vector.
    pub const FORCE: usize = 0;
    /// Index of the prescribed extension z(1) in the parameter vector.
    pub const EXTENSION: usize = 1;
    /// Index of the helix angle θ0 in the parameter vector.
    pub const THETA0: usize = 2;

    /// A spring of `coils` turns at helix angle `helix_angle` (radians,
    /// between the tangent and the axis) with `stiffness` (A about d1, B
    /// about d2, C torsion) and the intrinsic strains of its unstressed
    /// helix, under force control.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if `coils` is 0; [`Error::InvalidArgument`] if
    /// the helix angle is not in (0, π/2] or (2πn)²B overflows.
    pub fn new(coils: u32, helix_angle: f64, stiffness: Stiffness) -> Result<Self> {
        ForceScale::new(coils, stiffness.b())?;
        if !(helix_angle > 0.0 && helix_angle <= FRAC_PI_2) {
            return Err(Error::InvalidArgument {
                name: "helix_angle",
                value: helix_angle,
                allowed: "a helix angle in (0, π/2] radians",
            });
        }
        Ok(Self {
            coils,
            theta0: helix_angle,
            a: stiffness.a(),
            b: stiffness.b(),
            c: stiffness.c(),
            strain_offset: Vector3::zeros(),
            control: Control::Force,
            half: false,
        })
    }

    /// The same rod with intrinsic strains u0 = (u10, u20, u30) instead of
    /// those of its helix (for instance a strip whose natural curvature is
    /// not about d2, or a natural twist). The pull still starts from the
    /// helix of n coils at θ0, relaxed at zero load to these strains by
    /// Newton's method.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if a component is not finite, or on a
    /// [symmetric](Rod::symmetric) rod if u10 is not zero.
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
        self.strain_offset = strains - Self::helical_strains(self.coils, self.theta0);
        if self.half {
            // (a symmetric rod stays one only with u10 = 0)
            return self.whole().symmetric();
        }
        Ok(self)
    }

    /// The stiffnesses (A, B, C).
    #[must_use]
    pub fn stiffness(&self) -> Stiffness {
        Stiffness::new(self.a, self.b, self.c).expect("validated by Rod::new")
    }

    /// The force scale (2πn)²B of F/((2πn)²B).
    #[must_use]
    pub fn scale(&self) -> ForceScale {
        ForceScale::new(self.coils, self.b).expect("validated by Rod::new")
    }

    /// The weights w_i of the continuation's integral norm
    /// ⟨a, b⟩ = Σ_i w_i ∫₀¹ a_i b_i ds over this rod's state (r, q, F, M):
    /// 1 on the position and the quaternion, 1/((2πn)²B)² on the force (of
    /// the order of the force scale) and 1e-3 on the moment (module docs
    /// of `rod::pull`); for a [`Continuation`](crate::continuation::Continuation)
    /// of the rod outside a [`Pull`].
    #[must_use]
    pub fn norm_weights(&self) -> [f64; Rod::DIM] {
        let scale = self.scale().value();
        let mut w = [1.0; Rod::DIM];
        w[7..10].fill(1.0 / (scale * scale));
        w[10..13].fill(1e-3);
        w
    }

    /// The same rod under another [`Control`].
    #[must_use]
    pub fn with_control(mut self, control: Control) -> Self {
        self.control = control;
        self
    }

    /// The end-load control.
    #[must_use]
    pub fn control(&self) -> Control {
        self.control
    }

    /// Number of coils n.
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.coils
    }

    /// The helix angle θ0 of the unstressed rod (radians).
    #[must_use]
    pub fn theta0(&self) -> f64 {
        self.theta0
    }

    /// Intrinsic strains u0 of this rod: 2πn (0, sin θ0, cos θ0) unless
    /// given by [`Rod::with_intrinsic_strains`].
    #[must_use]
    pub fn intrinsic_strains(&self) -> Vector3<f64> {
        self.intrinsic_strains_at(self.theta0)
    }

    /// Whether u0 is that of the helix of n coils at θ0 (then the helix is
    /// an exact unstressed solution, [`Rod::unstressed`]).
    #[must_use]
    pub fn is_helical(&self) -> bool {
        self.strain_offset == Vector3::zeros()
    }

    pub(crate) fn helical_strains(coils: u32, theta0: f64) -> Vector3<f64> {
        let k = 2.0 * PI * f64::from(coils);
        Vector3::new(0.0, k * theta0.sin(), k * theta0.cos())
    }

    /// u0 when the helix angle parameter is `theta0` (continuation in θ0
    /// moves the helical part; a custom offset stays).
    fn intrinsic_strains_at(&self, theta0: f64) -> Vector3<f64> {
        Self::helical_strains(self.coils, theta0) + self.strain_offset
    }

    fn intrinsic_strains_derivative(coils: u32, theta0: f64) -> Vector3<f64> {
        let k = 2.0 * PI * f64::from(coils);
        Vector3::new(0.0, k * theta0.cos(), -k * theta0.sin())
    }

    /// The parameter vector of the unstressed helix: λ = 0, Δz = cos θ0, θ0.
    #[must_use]
    pub fn parameters_at_rest(&self) -> [f64; 3] {
        [0.0, self.theta0.cos(), self.theta0]
    }

    /// The exact unstressed helix at arclength s (the module docs give the
    /// formulas): an exact solution of the ODE and of every boundary and
    /// phase condition at [`Rod::parameters_at_rest`]. For a
    /// [symmetric](Rod::symmetric) rod it is still the whole rod's helix at
    /// s; its half's problem has it at σ = 2s.
    ///
    /// ```
    /// use hockle::rod::Rod;
    /// let rod = Rod::new(4, 89.8_f64.to_radians(), hockle::Stiffness::nikolai(10.0, 0.05)?)?;
    /// let y1 = rod.unstressed(1.0);
    /// assert!(y1[0].abs() < 1e-15 && y1[1].abs() < 1e-15); // back on the axis
    /// assert!((y1[2] - rod.theta0().cos()).abs() < 1e-15); // Δz = cos θ0
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn unstressed(&self, s: f64) -> [f64; 13] {
        let n = f64::from(self.coils);
        let phi = 2.0 * PI * n * s;
        let (sn, cs) = self.theta0.sin_cos();
        let r0 = sn / (2.0 * PI * n);
        // sin φ and 1 − cos φ = 2 sin²(φ/2) without cancellation; φ reduced
        // by whole turns so that s = 1 lands exactly on the axis.
        let turns = (n * s).floor();
        let phi_red = 2.0 * PI * (n * s - turns);
        let (sp, _) = phi_red.sin_cos();
        let sh = (phi_red / 2.0).sin();
        let beta = (phi + FRAC_PI_2) / 2.0;
        let (sb, cb) = beta.sin_cos();
        let (sa, ca) = (self.theta0 / 2.0).sin_cos();
        [
            r0 * sp,
            r0 * 2.0 * sh * sh,
            cs * s,
            cb * ca,
            cb * sa,
            sb * sa,
            sb * ca,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
        ]
    }
}

impl core::fmt::Display for Rod {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "rod: n = {} coils, θ0 = {}°, A = {}, B = {}, C = {}, {}",
            self.coils,
            self.theta0.to_degrees(),
            self.a,
            self.b,
            self.c,
            self.control
        )?;
        if self.half {
            write!(f, ", symmetric (solved on its half)")?;
        }
        Ok(())
    }
}
