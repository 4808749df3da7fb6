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

use nalgebra::{DMatrix, DVector, Vector3};

use super::Equilibrium;
use super::jet::{Jet, QuatJet, quat_const, quat_mul, rotation};
use crate::error::{Error, Result};
use crate::load::Control;
use crate::stability::Stability;

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
    /// [`Self::second_variation`] with [`STABILITY_SEGMENTS`] segments.
    ///
    /// Independent of any continuation history; it checks the index that a
    /// [`crate::spring::Response`] carries along its curve
    /// ([`crate::stability`]). Cost: a few dense LU solves and a symmetric
    /// eigenproblem of size 600, about 0.07 s (docs/PERFORMANCE.md); paid
    /// only when called.
    ///
    /// # Errors
    /// As [`Self::second_variation`].
    pub fn stability(&self, control: Control) -> Result<Stability> {
        Ok(self
            .second_variation(control, STABILITY_SEGMENTS)?
            .stability())
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
        if !(16..=MAX_SEGMENTS).contains(&segments) {
            return Err(Error::InvalidCount {
                name: "segments",
                value: segments as u64,
                allowed: "16 to 1000 segments",
            });
        }
        let nn = segments;
        let h = 1.0 / nn as f64;
        let rod = *self.rod();
        let y0 = self.eval(0.0);
        let mut rod_d = Discrete {
            h,
            d: [rod.a, rod.b, rod.c],
            u0: rod.intrinsic_strains_at(self.parameters()[2]),
            frames: (0..nn)
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
        let sys = rod_d.assemble(force, segments)?;
        let c = match control {
            Control::Force => 3,
            Control::Extension => 4,
        };
        let u = orthonormal_rows(sys.rows.rows(0, c).into_owned());
        let hess = sys.hess;
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
}

/// The discrete rod of the module docs: segment frames and stiffnesses.
struct Discrete {
    h: f64,
    d: [f64; 3],
    u0: Vector3<f64>,
    frames: Vec<[f64; 4]>,
}

/// Hessian and gradient of L = U − F·r(1), the constraint gradients (rows
/// ∇x(1), ∇y(1), ξ, ∇z(1)) and r(1).
struct Assembled {
    hess: DMatrix<f64>,
    grad: DVector<f64>,
    rows: DMatrix<f64>,
    end: Vector3<f64>,
}

/// Newton iterations of [`Discrete::polish`], at most.
const POLISH_ITERATIONS: u32 = 10;
/// Largest rotation increment (radians) of a polish step: the sampled
/// frames are O(h²) from the discrete equilibrium, so a larger step means
/// there is none nearby (a fold of the force).
const POLISH_MAX_STEP: f64 = 0.5;
/// Rotation increments (radians) at which the polish has converged; the
/// rounding floor of the dense solve is ~1e-11 at 200 segments.
const POLISH_TOLERANCE: f64 = 1e-9;

impl Discrete {
    fn assemble(&self, force: Vector3<f64>, segments: usize) -> Result<Assembled> {
        let nn = self.frames.len();
        let h = self.h;
        let n = 3 * nn;
        let mut hess = DMatrix::<f64>::zeros(n, n);
        let mut grad = DVector::<f64>::zeros(n);
        // Bending and twisting between segments k − 1 and k.
        for k in 1..nn {
            let rel = quat_mul_f(conj(self.frames[k - 1]), self.frames[k]);
            if rel[0].abs() < 0.5 {
                return Err(Error::InvalidCount {
                    name: "segments",
                    value: segments as u64,
                    allowed: "enough segments that neighbouring frames turn by less than 2π/3",
                });
            }
            let e = node_energy(rel, h, self.d, self.u0);
            let base = 3 * (k - 1);
            for a in 0..6 {
                grad[base + a] += e.g[a];
                for b in 0..6 {
                    hess[(base + a, base + b)] += e.h[a][b];
                }
            }
        }
        // The end position h Σ d3_i: the load's potential and the constraints.
        let mut rows = DMatrix::<f64>::zeros(4, n);
        let mut end = Vector3::zeros();
        for (i, q) in self.frames.iter().enumerate() {
            let d3 = tangent(*q);
            let base = 3 * i;
            for (c, dc) in d3.iter().enumerate() {
                end[c] += h * dc.v;
                let w = -h * force[c];
                for a in 0..3 {
                    grad[base + a] += w * dc.g[a];
                    for b in 0..3 {
                        hess[(base + a, base + b)] += w * dc.h[a][b];
                    }
                }
                let row = [0, 1, 3][c];
                for a in 0..3 {
                    rows[(row, base + a)] = h * dc.g[a];
                }
            }
            // ξ_i = R(q_i)ᵀ k: the rotation about the force axis.
            let rt_k = super::quat::rot(q).transpose() * Vector3::z();
            for a in 0..3 {
                rows[(2, base + a)] = rt_k[a];
            }
        }
        Ok(Assembled {
            hess,
            grad,
            rows,
            end,
        })
    }

    /// Newton's method on the discrete equilibrium at the same F_z: the
    /// frames move to a critical point of L on x(1) = y(1) = 0 (modulo the
    /// rotation about k), and F_x, F_y to their multipliers.
    fn polish(
        &mut self,
        force: &mut Vector3<f64>,
        first: Assembled,
        segments: usize,
    ) -> Result<()> {
        let mut sys = first;
        let n = sys.hess.nrows();
        let mut last = f64::INFINITY;
        for iteration in 0..POLISH_ITERATIONS {
            // [K | rhs], column-major, for the crate's dense LU
            let mut k = DMatrix::<f64>::zeros(n + 3, n + 4);
            k.view_mut((0, 0), (n, n)).copy_from(&sys.hess);
            for r in 0..3 {
                for j in 0..n {
                    k[(j, n + r)] = -sys.rows[(r, j)];
                    k[(n + r, j)] = -sys.rows[(r, j)];
                }
            }
            for j in 0..n {
                k[(j, n + 3)] = -sys.grad[j];
            }
            k[(n, n + 3)] = sys.end.x;
            k[(n + 1, n + 3)] = sys.end.y;
            let (mut perm, mut perm_inv) = (vec![0; n + 3], vec![0; n + 3]);
            let mut ws = crate::linalg::DenseWorkspace::new(n + 3, 1);
            if crate::linalg::lu_solve_block(
                k.as_mut_slice(),
                n + 3,
                n + 4,
                &mut perm,
                &mut perm_inv,
                &mut ws,
            )
            .is_err()
            {
                return Err(Error::SingularJacobian {
                    block: "discrete rod's equilibrium (at a fold of the force)",
                    index: u64::from(iteration),
                });
            }
            let step = k.column(n + 3).into_owned();
            let dphi = step.rows(0, n);
            let moved = dphi.amax();
            if !moved.is_finite() {
                return Err(Error::NonFinite {
                    what: "rotation increment of the discrete rod",
                    s: f64::NAN,
                });
            }
            for (i, q) in self.frames.iter_mut().enumerate() {
                let phi = Vector3::new(dphi[3 * i], dphi[3 * i + 1], dphi[3 * i + 2]);
                let angle = phi.norm();
                let (sn, cs) = (0.5 * angle).sin_cos();
                let axis = if angle > 0.0 { phi / angle } else { phi };
                let p = [cs, sn * axis.x, sn * axis.y, sn * axis.z];
                let mut r = quat_mul_f(*q, p);
                let norm = r.iter().map(|v| v * v).sum::<f64>().sqrt();
                r.iter_mut().for_each(|v| *v /= norm);
                *q = r;
            }
            force.x += step[n];
            force.y += step[n + 1];
            if moved > POLISH_MAX_STEP {
                return Err(Error::NewtonDiverged {
                    iteration: iteration + 1,
                    correction: moved,
                });
            }
            last = moved;
            if moved < POLISH_TOLERANCE {
                return Ok(());
            }
            sys = self.assemble(*force, segments)?;
        }
        Err(Error::NewtonNotConverged {
            iterations: POLISH_ITERATIONS,
            correction: last,
            tolerance: POLISH_TOLERANCE,
        })
    }
}

fn conj(q: [f64; 4]) -> [f64; 4] {
    [q[0], -q[1], -q[2], -q[3]]
}

fn quat_mul_f(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

/// h ½ (u − u0)ᵀ D (u − u0) between two segments whose relative rotation
/// is `rel`, as a jet in (φ_{k−1}, φ_k).
fn node_energy(rel: [f64; 4], h: f64, d: [f64; 3], u0: Vector3<f64>) -> Jet<6> {
    let pa: QuatJet<6> = rotation(0);
    let pa_conj = [pa[0], -pa[1], -pa[2], -pa[3]];
    let pb: QuatJet<6> = rotation(3);
    let q = quat_mul(&quat_mul(&pa_conj, &quat_const(rel)), &pb);
    let inv_w = q[0].recip();
    let t = [q[1] * inv_w, q[2] * inv_w, q[3] * inv_w];
    let x = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
    let (f0, f1, f2) = atan_sqrt_over_sqrt(x.v);
    let phi = x.apply(f0, f1, f2).scale(2.0 / h);
    let mut e = Jet::constant(0.0);
    for a in 0..3 {
        let du = phi * t[a] - Jet::constant(u0[a]);
        e = e + (du * du).scale(0.5 * h * d[a]);
    }
    e
}

/// d3 of q ⊗ exp(φ/2) as jets in φ.
fn tangent(q: [f64; 4]) -> [Jet<3>; 3] {
    let p: QuatJet<3> = rotation(0);
    let [w, x, y, z] = quat_mul(&quat_const(q), &p);
    [
        (x * z + w * y).scale(2.0),
        (y * z - w * x).scale(2.0),
        w * w - x * x - y * y + z * z,
    ]
}

/// φ(x) = atan(√x)/√x and its first two derivatives, x ≥ 0 (the rotation
/// angle over 2 tan(angle/2), as a function of tan²(angle/2)).
fn atan_sqrt_over_sqrt(x: f64) -> (f64, f64, f64) {
    if x < 0.1 {
        // Σ (−1)^j x^j/(2j + 1): 40 terms leave 0.1⁴⁰ of the first.
        let (mut f0, mut f1, mut f2) = (0.0, 0.0, 0.0);
        for j in (0..40).rev() {
            let c = if j % 2 == 0 { 1.0 } else { -1.0 } / (2 * j + 1) as f64;
            let jf = j as f64;
            f0 = f0 * x + c;
            if j >= 1 {
                f1 = f1 * x + c * jf;
            }
            if j >= 2 {
                f2 = f2 * x + c * jf * (jf - 1.0);
            }
        }
        (f0, f1, f2)
    } else {
        let y = x.sqrt();
        let f0 = y.atan() / y;
        let f1 = (1.0 / (1.0 + x) - f0) / (2.0 * x);
        let f2 = -1.5 * f1 / x - 1.0 / (2.0 * x * (1.0 + x) * (1.0 + x));
        (f0, f1, f2)
    }
}

/// The rows of `a`, orthonormalised (Gram–Schmidt, twice).
fn orthonormal_rows(mut a: DMatrix<f64>) -> DMatrix<f64> {
    for i in 0..a.nrows() {
        for _ in 0..2 {
            for j in 0..i {
                let p = a.row(i).dot(&a.row(j));
                let rj = a.row(j).into_owned();
                let ri = a.row(i) - rj * p;
                a.row_mut(i).copy_from(&ri);
            }
        }
        let norm = a.row(i).norm();
        a.row_mut(i).scale_mut(1.0 / norm);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_angle_function_is_smooth_across_its_two_forms() {
        // Series and closed form meet at x = 0.1; both are accurate there
        // to ~1e-13 (the closed forms lose digits to cancellation, 1/x and
        // 1/x² times rounding).
        let s = atan_sqrt_over_sqrt(0.1 - 1e-12);
        let c = atan_sqrt_over_sqrt(0.1 + 1e-12);
        assert!((s.0 - c.0).abs() < 1e-12);
        assert!((s.1 - c.1).abs() < 1e-11);
        assert!((s.2 - c.2).abs() < 1e-9);
        // φ(x) = atan(√x)/√x at x = 1: π/4.
        assert!((atan_sqrt_over_sqrt(1.0).0 - core::f64::consts::FRAC_PI_4).abs() < 1e-15);
    }
}
