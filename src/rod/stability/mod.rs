//! The direct stability test of one rod equilibrium: the inertia of the
//! second variation of its potential energy, discretised, on the manifold
//! of the constraints of each [`Control`].
//!
//! ## Formulation
//!
//! The rod of length 1 is cut into N segments of length h = 1/N. Segment i
//! carries the frame of the equilibrium at its midpoint, the unit
//! quaternion q_i = q((i + ½)h), and is perturbed by a small rotation φ_i
//! in its own frame: q_i → q_i ⊗ exp(φ_i/2). With r(0) = 0,
//!
//! ```text
//!   r(1)  = h Σ_i d3(q_i)                                        (midpoint rule)
//!   u_k   = (2/h) atan(|v|/w) v/|v|,  (w, v) = q̄_{k−1} ⊗ q_k      (k = 1..N−1)
//!   U     = Σ_k h ½ (u_k − u0)ᵀ D (u_k − u0),   D = diag(A, B, C)
//!   L     = U − F·r(1)
//! ```
//!
//! u_k is the exact rotation vector between neighbouring frames over h, so
//! a helix (constant u) is represented without error; the discrete
//! equilibria converge to the rod's at O(h²). F is the rod's constant
//! internal force, the multiplier of the end conditions: (0, 0, F_z) at
//! every equilibrium with Δz ≠ 0 (M(1) − M(0) = F × r(1) and the
//! zero-moment ends force F_x = F_y = 0).
//!
//! The boundary conditions of [`Rod`](super::Rod) become constraints on the
//! perturbations φ = (φ_0, …, φ_{N−1}) ∈ ℝ³ᴺ: r(0) = 0 holds by
//! construction, the ends are free to turn (zero end moments are natural
//! conditions), and
//!
//! - **force control** (dead load): x(1) = y(1) = 0, so the admissible φ
//!   satisfy δx(1) = δy(1) = 0; the load's potential −F_z z(1) is in L;
//! - **extension control** (hard device): also δz(1) = 0;
//! - both: the rotation about the force axis, an exact symmetry (a zero
//!   mode of the second variation), is factored out by the phase condition
//!   ⟨φ, ξ⟩ = 0 with ξ_i = R(q_i)ᵀ k, the generator of that rotation.
//!
//! The Hessian H of L at φ = 0 is exact (second-order forward automatic
//! differentiation of every term); with P the orthogonal projector onto
//! the admissible φ (the complement of the c constraint gradients), the
//! second variation on the constraint manifold is P H P on range(P). The
//! matrix P H P + σ (I − P), σ > 0, has the eigenvalues of that restriction
//! and σ (c times), so its number of negative eigenvalues is the
//! **index**: the count of independent admissible perturbations that lower
//! the energy. (Including F·∇²r(1) makes this the Hessian of the
//! Lagrangian, the correct second-order condition on a curved constraint
//! manifold.) The eigenvalues reported are divided by h: in the L² norm
//! ∫|δφ|² ds of the perturbation they approximate the second variation's
//! own spectrum.
//!
//! Those eigenvalues cost O(N³) ([`Equilibrium::second_variation`]). The
//! index alone ([`Equilibrium::stability`]) costs O(N): H is block
//! tridiagonal (each node's energy couples two neighbouring segments), and
//! by Sylvester's law and Haynsworth's inertia additivity the index is
//! n₋ of the bordered matrix [[H, Gᵀ], [G, 0]] less c, counted by a block
//! LDLᵀ along the rod with the phase taken on the first segment alone
//! (`sweep.rs`; the dense eigenvalues where a pivot is nearly singular).
//! The polish's Newton steps below take the same sweep with a rank-2
//! update to the global phase (before, a dense LU of size 3N + 3).
//!
//! The sampled frames are an equilibrium of the rod to the collocation's
//! accuracy, but of the discrete energy only to O(h²); an eigenvalue
//! smaller than that error can have the wrong sign. That happens only next
//! to a fold or a branch point, where an eigenvalue passes through zero
//! (the tests say how near).
//!
//! ## Sources
//!
//! - J. H. Maddocks, *Stability of nonlinearly elastic rods*, Arch.
//!   Rational Mech. Anal. 85 (1984) 311–354: the second variation of the
//!   Kirchhoff rod with isoperimetric (end-position) constraints; its
//!   conjugate-point test counts the same index in the continuum.
//! - A. Lazarus, J. T. Miller, P. M. Reis, *Continuation of equilibria and
//!   stability of slender elastic rods using an asymptotic numerical
//!   method*, J. Mech. Phys. Solids 61 (2013) 1712–1736: stability from the
//!   eigenvalues of the discretised tangent stiffness, constraints by
//!   Lagrange multipliers.
//! - Bordered Hessians: the index of a quadratic form on the kernel of a
//!   constraint (Debreu 1952; Maddocks 1987).

use nalgebra::Vector3;

use super::Equilibrium;
use crate::error::{Error, Result};
use crate::load::Control;
use crate::stability::Stability;

mod block_tridiagonal;
mod discrete;
mod sweep;

use discrete::{Discrete, orthonormal_rows};

/// Segments of [`Equilibrium::stability`]'s discretisation.
pub const STABILITY_SEGMENTS: usize = 200;

/// Largest segment count of [`Equilibrium::second_variation`] (a dense
/// eigenproblem of size 3N: several seconds at the limit).
const MAX_SEGMENTS: usize = 1000;

/// The result of the direct stability test of one equilibrium under one
/// control ([`Equilibrium::second_variation`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SecondVariation {
    control: Control,
    segments: usize,
    index: u32,
    lowest: Vec<f64>,
    residual: f64,
}

impl SecondVariation {
    /// The control the test was made for.
    #[must_use]
    pub fn control(&self) -> Control {
        self.control
    }

    /// The number of segments N of the discretisation.
    #[must_use]
    pub fn segments(&self) -> usize {
        self.segments
    }

    /// The index and the verdict.
    #[must_use]
    pub fn stability(&self) -> Stability {
        Stability::new(self.index)
    }

    /// The lowest eigenvalues of the second variation on the constraint
    /// manifold, ascending (at most six), in the L² norm of the rotation
    /// perturbation (units B). Their distance from zero says how sure the
    /// verdict is: next to a fold one of them passes through zero.
    #[must_use]
    pub fn lowest_eigenvalues(&self) -> &[f64] {
        &self.lowest
    }

    /// How far the sampled frames are from an equilibrium of the discrete
    /// energy: the largest admissible component of the energy's gradient,
    /// divided by h (a moment, units B). O(h²) for a converged equilibrium.
    #[must_use]
    pub fn residual(&self) -> f64 {
        self.residual
    }
}

impl core::fmt::Display for SecondVariation {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} under {} ({} segments; lowest eigenvalue {:.3e})",
            self.stability(),
            self.control,
            self.segments,
            self.lowest.first().copied().unwrap_or(f64::NAN)
        )
    }
}

impl Equilibrium {
    /// Whether a real spring can sit at this equilibrium under `control`:
    /// the index of [`Self::second_variation`] with [`STABILITY_SEGMENTS`]
    /// segments, counted in O(N) by the inertia of the bordered Hessian
    /// (a block LDLᵀ along the rod, Sylvester's law; `sweep.rs`), and by
    /// the dense eigenvalues where a pivot of that sweep is nearly
    /// singular.
    ///
    /// Independent of any continuation history; it checks the index that a
    /// [`crate::spring::Response`] carries along its curve
    /// ([`crate::stability`]). Cost: about 3 ms (docs/PERFORMANCE.md), paid
    /// only when called.
    ///
    /// # Errors
    /// As [`Self::second_variation`].
    pub fn stability(&self, control: Control) -> Result<Stability> {
        let segments = STABILITY_SEGMENTS;
        let (sys, residual) = self.polished(segments)?;
        let end = sys.rows.select_rows(end_rows(control));
        match sweep::constrained_index(&sys.hess, &end, sys.phase0()) {
            Some(index) => Ok(Stability::new(u32::try_from(index).unwrap_or(u32::MAX))),
            None => Ok(dense_test(&sys, control, segments, residual)?.stability()),
        }
    }

    /// The direct stability test (module docs of [`crate::rod`]'s
    /// second variation, summarised here): the inertia of the exact Hessian
    /// of the discrete energy U − F·r(1) of `segments` rigid segments
    /// around this equilibrium, on the perturbations that keep x(1) = y(1) =
    /// 0 (and z(1) under [`Control::Extension`]), modulo the rotation about
    /// the force axis.
    ///
    /// ```text
    ///   r(1) = h Σ d3(q_i),   u_k = (2/h) atan(|v|/w) v/|v| with (w, v) = q̄_{k−1} ⊗ q_k,
    ///   U = Σ h ½ (u_k − u0)ᵀ diag(A, B, C) (u_k − u0),   q_i → q_i ⊗ exp(φ_i/2)
    /// ```
    ///
    /// Sources: Maddocks (1984) for the constrained second variation of
    /// rods, Lazarus, Miller & Reis (JMPS 2013) for the discretised
    /// stiffness' eigenvalues along a continuation.
    ///
    /// Before the Hessian is taken the sampled frames are moved, by Newton's
    /// method at the same F_z, onto the discrete rod's own equilibrium (an
    /// O(h²) correction; without it the gradient's O(h²) residual would
    /// pollute the small eigenvalues, [`SecondVariation::residual`]).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] unless 16 ≤ `segments` ≤ 1000, or if
    /// neighbouring segments turn by more than 2π/3 (too few segments for
    /// the shape's curvature); [`Error::NewtonDiverged`],
    /// [`Error::NewtonNotConverged`] or [`Error::SingularJacobian`] if the
    /// discrete rod has no equilibrium near this one at this force: at a
    /// point within the discretisation error of a fold of the force (at 200
    /// segments, the points of the paper's curve next to its folds, within
    /// 7e-4 of them in the (Δz, F/((2πn)²B)) plane), where the verdict
    /// would be unsure anyway.
    pub fn second_variation(&self, control: Control, segments: usize) -> Result<SecondVariation> {
        let (sys, residual) = self.polished(segments)?;
        dense_test(&sys, control, segments, residual)
    }

    /// The discrete rod of `segments` segments moved onto its equilibrium
    /// at this one's F_z ([`Discrete::polish`]), assembled there, and the
    /// sampled frames' gradient residual ([`SecondVariation::residual`]).
    fn polished(&self, segments: usize) -> Result<(discrete::Assembled, f64)> {
        if !(16..=MAX_SEGMENTS).contains(&segments) {
            return Err(Error::InvalidCount {
                name: "segments",
                value: segments as u64,
                allowed: "16 to 1000 segments",
            });
        }
        let h = 1.0 / segments as f64;
        let rod = *self.rod();
        let y0 = self.eval(0.0);
        let mut rod_d = Discrete {
            h,
            d: [rod.a, rod.b, rod.c],
            u0: rod.intrinsic_strains_at(self.parameters()[2]),
            frames: (0..segments)
                .map(|i| {
                    let y = self.eval((i as f64 + 0.5) * h);
                    let norm = (y[3] * y[3] + y[4] * y[4] + y[5] * y[5] + y[6] * y[6]).sqrt();
                    [y[3] / norm, y[4] / norm, y[5] / norm, y[6] / norm]
                })
                .collect(),
        };
        let mut force = Vector3::new(y0[7], y0[8], y0[9]);
        let first = rod_d.assemble(force, segments)?;
        let residual = {
            let u = orthonormal_rows(first.rows.rows(0, 3).into_owned());
            (&first.grad - u.transpose() * (&u * &first.grad)).amax() / h
        };
        rod_d.polish(&mut force, first, segments)?;
        Ok((rod_d.assemble(force, segments)?, residual))
    }
}

/// The rows of the end conditions a control holds (of the assembled
/// constraint rows: x(1), y(1), then z(1) under extension control).
fn end_rows(control: Control) -> &'static [usize] {
    match control {
        Control::Force => &[0, 1],
        Control::Extension => &[0, 1, 3],
    }
}

/// The dense eigenvalues of the second variation of the polished system
/// `sys` (module docs): P H P + σ UᵀU, P = I − UᵀU, its negative
/// eigenvalues the index.
fn dense_test(
    sys: &discrete::Assembled,
    control: Control,
    segments: usize,
    residual: f64,
) -> Result<SecondVariation> {
    let h = 1.0 / segments as f64;
    let c = end_rows(control).len() + 1;
    let u = orthonormal_rows(sys.rows.rows(0, c).into_owned());
    let hess = sys.hess.to_dense();
    let n = hess.nrows();
    // P H P + σ UᵀU, P = I − UᵀU.
    let uh = &u * &hess;
    let uhu = &uh * u.transpose();
    let mut m = &hess - u.transpose() * &uh - uh.transpose() * &u + u.transpose() * &uhu * &u;
    let sigma = (0..n).map(|i| hess[(i, i)].abs()).fold(1.0, f64::max);
    m += u.transpose() * &u * sigma;
    // symmetrise the rounding of the products
    let m = (&m + m.transpose()) * 0.5;
    if m.iter().any(|v| !v.is_finite()) {
        return Err(Error::NonFinite {
            what: "second variation of the discrete rod",
            s: f64::NAN,
        });
    }
    let Some(eig) = crate::linalg::symmetric_eigenvalues(m.as_slice(), n) else {
        return Err(Error::NonFinite {
            what: "second variation of the discrete rod (eigenvalues did not converge)",
            s: f64::NAN,
        });
    };
    let index = eig.iter().filter(|&&l| l < 0.0).count();
    Ok(SecondVariation {
        control,
        segments,
        index: u32::try_from(index).unwrap_or(u32::MAX),
        lowest: eig.iter().take(6).map(|l| l / h).collect(),
        residual,
    })
}
