//! The discrete rod of the stability test: its energy's exact Hessian
//! (forward automatic differentiation), the constraint rows, and the
//! Newton polish onto the discrete equilibrium.

use nalgebra::{DMatrix, DVector, Vector3};

use super::block_tridiagonal::BlockTridiagonal;

use crate::error::{Error, Result};
use crate::rod::jet::{Jet, QuatJet, quat_const, quat_mul, rotation};

/// The discrete rod of the module docs: segment frames and stiffnesses.
pub(super) struct Discrete {
    pub(super) h: f64,
    pub(super) d: [f64; 3],
    pub(super) u0: Vector3<f64>,
    pub(super) frames: Vec<[f64; 4]>,
}

/// Hessian and gradient of L = U − F·r(1), the constraint gradients (rows
/// ∇x(1), ∇y(1), ξ, ∇z(1)) and r(1).
pub(super) struct Assembled {
    pub(super) hess: BlockTridiagonal,
    pub(super) grad: DVector<f64>,
    pub(super) rows: DMatrix<f64>,
    pub(super) end: Vector3<f64>,
}

impl Assembled {
    /// The row of the phase ⟨φ, ξ⟩ among the constraint rows.
    pub(super) const PHASE_ROW: usize = 2;

    /// ξ on segment 0: R(q₀)ᵀ k, the local phase of the sweep
    /// (`sweep.rs`).
    pub(super) fn phase0(&self) -> [f64; 3] {
        [0, 1, 2].map(|a| self.rows[(Self::PHASE_ROW, a)])
    }

    /// The Newton step of the polish, (δφ, δF_x, δF_y), from
    /// [[H, −Gᵀ], [−G, 0]] [δφ; λ] = [−∇L; x(1); y(1); 0] (G the rows of
    /// x(1), y(1) and the phase): by the sweep ([`Self::swept_step`]), or
    /// where it meets a nearly singular pivot by a sparse LU (its pattern
    /// analysed on first use, in `pattern`; O(N) fill, as the border is
    /// three rows). `None` where neither solves it.
    fn newton_step(
        &self,
        pattern: &mut Option<crate::linalg::SparsePattern>,
    ) -> Option<(Vec<f64>, [f64; 2])> {
        if let Some(step) = self.swept_step() {
            return Some(step);
        }
        self.sparse_step(pattern)
    }

    /// The Newton step in O(N). The sweep factors the system with the
    /// local phase ℓ = ξ₀ on segment 0 (`sweep.rs`), K_ℓ; the polish's
    /// system K_ξ has the global phase ξ in that row and column. Solved
    /// with K_ℓ alone, the phase multiplier twists segment 0 where it
    /// should turn the whole rod, and off the equilibrium Newton wandered
    /// (measured at 100 segments on the paper's curve: ten steps without
    /// converging where the exact step takes five). K_ξ = K_ℓ + U Vᵀ with
    /// U = [d, e_p], V = [e_p, d], d = ξ − ℓ and e_p the phase multiplier's
    /// unit vector, so by Woodbury
    ///
    /// ```text
    ///   K_ξ⁻¹ b = z_b − [z_d, z_e] (I + Vᵀ [z_d, z_e])⁻¹ Vᵀ z_b,   z_v = K_ℓ⁻¹ v,
    /// ```
    ///
    /// and K_ℓ⁻¹ is the sweep's M⁻¹ with the end rows W = (∇x(1), ∇y(1))
    /// by their 2 × 2 Schur complement: five solves with the sweep in all.
    /// `None` where the sweep or a 2 × 2 system is singular.
    fn swept_step(&self) -> Option<(Vec<f64>, [f64; 2])> {
        use nalgebra::{Matrix2, Vector2};
        let n = self.hess.size();
        let phase0 = self.phase0();
        let sweep = super::sweep::Sweep::new(&self.hess, phase0)?;
        let w = self.rows.rows(0, 2);
        let mut d: DVector<f64> = self.rows.row(Self::PHASE_ROW).transpose();
        for (a, l) in phase0.iter().enumerate() {
            d[a] -= l;
        }
        // M⁻¹ of [Wᵀ; 0], [−∇L; 0], [d; 0] and [0; 1]
        let mut r = DMatrix::<f64>::zeros(n, 5);
        r.view_mut((0, 0), (n, 2)).copy_from(&w.transpose());
        r.column_mut(2).copy_from(&(-&self.grad));
        r.column_mut(3).copy_from(&d);
        let (x, x_phase) = sweep.solve_with_phase(&r, &[0.0, 0.0, 0.0, 0.0, 1.0]);
        let xw = x.columns(0, 2);
        let s_w = (w * xw).fixed_view::<2, 2>(0, 0).into_owned();
        let s_w_inv: Matrix2<f64> = s_w.try_inverse()?;
        // K_ℓ⁻¹ (r_φ, r_p, r_w) from the column of M⁻¹ [r_φ; r_p]:
        // (φ rows, phase multiplier, end multipliers)
        let k_inv = |col: usize, r_w: Vector2<f64>| {
            let xr = x.column(col);
            let y = s_w_inv * (w * xr - r_w);
            let phi = xr - xw * y;
            let p = x_phase[col] - (x_phase[0] * y[0] + x_phase[1] * y[1]);
            (phi, p, y)
        };
        let zb = k_inv(2, -Vector2::new(self.end.x, self.end.y));
        let zd = k_inv(3, Vector2::zeros());
        let ze = k_inv(4, Vector2::zeros());
        let c = Matrix2::new(1.0 + zd.1, ze.1, d.dot(&zd.0), 1.0 + d.dot(&ze.0));
        let coef = c.try_inverse()? * Vector2::new(zb.1, d.dot(&zb.0));
        let dphi = &zb.0 - &zd.0 * coef[0] - &ze.0 * coef[1];
        let lam = zb.2 - zd.2 * coef[0] - ze.2 * coef[1];
        // the multipliers of the symmetric form are −λ
        let dforce = [-lam[0], -lam[1]];
        (dphi.iter().all(|v| v.is_finite()) && dforce.iter().all(|v| v.is_finite()))
            .then(|| (dphi.iter().copied().collect(), dforce))
    }

    /// The Newton step by a sparse LU of the whole bordered matrix.
    fn sparse_step(
        &self,
        pattern: &mut Option<crate::linalg::SparsePattern>,
    ) -> Option<(Vec<f64>, [f64; 2])> {
        let n = self.hess.size();
        if pattern.is_none() {
            *pattern = bordered_pattern(n);
        }
        let (values, rhs) = bordered_values(self);
        let step = pattern.as_ref()?.factor(&values)?.solve(&rhs)?;
        Some((step[..n].to_vec(), [step[n], step[n + 1]]))
    }
}

/// Newton iterations of [`Discrete::polish`], at most.
const POLISH_ITERATIONS: u32 = 10;
/// Largest rotation increment (radians) of a polish step: the sampled
/// frames are O(h²) from the discrete equilibrium, so a larger step means
/// there is none nearby (a fold of the force).
const POLISH_MAX_STEP: f64 = 0.5;
/// Rotation increments (radians) at which the polish has converged; the
/// rounding floor of the solve is ~1e-11 at 200 segments (measured with
/// the dense LU the sparse one replaced).
const POLISH_TOLERANCE: f64 = 1e-9;

impl Discrete {
    pub(super) fn assemble(&self, force: Vector3<f64>, segments: usize) -> Result<Assembled> {
        let nn = self.frames.len();
        let h = self.h;
        let n = 3 * nn;
        let mut hess = BlockTridiagonal::zeros(nn);
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
                    hess.add_upper(base + a, base + b, e.h[a][b]);
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
                        hess.add_upper(base + a, base + b, w * dc.h[a][b]);
                    }
                }
                let row = [0, 1, 3][c];
                for a in 0..3 {
                    rows[(row, base + a)] = h * dc.g[a];
                }
            }
            // ξ_i = R(q_i)ᵀ k: the rotation about the force axis.
            let rt_k = crate::rod::quat::rot(q).transpose() * Vector3::z();
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
    pub(super) fn polish(
        &mut self,
        force: &mut Vector3<f64>,
        first: Assembled,
        segments: usize,
    ) -> Result<()> {
        let mut sys = first;
        let mut last = f64::INFINITY;
        let mut pattern = None;
        for iteration in 0..POLISH_ITERATIONS {
            let Some((dphi, dforce)) = sys.newton_step(&mut pattern) else {
                return Err(Error::SingularJacobian {
                    block: "discrete rod's equilibrium (at a fold of the force)",
                    index: u64::from(iteration),
                });
            };
            let moved = dphi.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
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
            force.x += dforce[0];
            force.y += dforce[1];
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
pub(super) fn orthonormal_rows(mut a: DMatrix<f64>) -> DMatrix<f64> {
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

/// The entries of the polish's bordered matrix K = [[H, −Gᵀ], [−G, 0]]
/// (H block tridiagonal in 3 × 3 blocks, one per segment; G the rows of
/// x(1), y(1) and the phase, dense), in the order [`bordered_values`]
/// fills them: O(N) entries, so that a sparse LU solves it in O(N) where
/// the dense one took O(N³).
fn bordered_entries(n: usize) -> Vec<(usize, usize)> {
    let segments = n / 3;
    let mut entries = Vec::with_capacity(27 * segments + 6 * n);
    for bi in 0..segments {
        for bj in bi.saturating_sub(1)..(bi + 2).min(segments) {
            for a in 0..3 {
                for b in 0..3 {
                    entries.push((3 * bi + a, 3 * bj + b));
                }
            }
        }
    }
    for r in 0..3 {
        for j in 0..n {
            entries.push((j, n + r));
            entries.push((n + r, j));
        }
    }
    entries
}

/// The pattern (and symbolic LU) of [`bordered_entries`].
fn bordered_pattern(n: usize) -> Option<crate::linalg::SparsePattern> {
    crate::linalg::SparsePattern::new(n + 3, &bordered_entries(n))
}

/// The values of [`bordered_entries`] at `sys`, and the right-hand side
/// [−∇L; x(1); y(1); 0] of the polish's Newton step.
fn bordered_values(sys: &Assembled) -> (Vec<f64>, Vec<f64>) {
    let n = sys.hess.size();
    let values = bordered_entries(n)
        .into_iter()
        .map(|(i, j)| match (i < n, j < n) {
            (true, true) => sys.hess.get(i, j),
            (true, false) => -sys.rows[(j - n, i)],
            _ => -sys.rows[(i - n, j)],
        })
        .collect();
    let mut rhs: Vec<f64> = sys.grad.iter().map(|g| -g).collect();
    rhs.extend([sys.end.x, sys.end.y, 0.0]);
    (values, rhs)
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

    /// Frames of a bent, twisted rod that is no equilibrium (so the
    /// gradient, the phase's forcing and F_x, F_y are all nonzero).
    fn skewed_rod(segments: usize) -> Discrete {
        let h = 1.0 / segments as f64;
        let frames = (0..segments)
            .map(|i| {
                let s = (i as f64 + 0.5) * h;
                let v = Vector3::new(0.3 * (5.0 * s).sin(), 1.1 + 0.2 * s, 9.0 * s);
                let angle = v.norm();
                let (sn, cs) = (0.5 * angle).sin_cos();
                let u = v / angle;
                [cs, sn * u.x, sn * u.y, sn * u.z]
            })
            .collect();
        Discrete {
            h,
            d: [1.0, 1.3, 0.8],
            u0: Vector3::new(0.0, 0.5, 2.0),
            frames,
        }
    }

    #[test]
    fn the_swept_newton_step_is_the_sparse_lu_step() {
        // Two solvers of one linear system: the O(N) sweep with its rank-2
        // update against faer's sparse LU. Their difference is rounding
        // amplified by the system's condition: measured 4e-13 of the step
        // (2.1e-12 of 5.2) and 1.2e-12 in δF, so 1e-9 leaves a margin of
        // three orders for other platforms' rounding.
        let rod = skewed_rod(60);
        let sys = rod.assemble(Vector3::new(0.3, -0.2, 4.0), 60).unwrap();
        let (swept, f_swept) = sys.swept_step().expect("the sweep solves it");
        let (lu, f_lu) = sys.sparse_step(&mut None).expect("the LU solves it");
        let scale = lu.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        let diff = swept
            .iter()
            .zip(&lu)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(scale > 1e-3, "a step to compare: {scale}");
        assert!(diff <= 1e-9 * scale, "δφ differs by {diff:e} of {scale:e}");
        for (a, b) in f_swept.iter().zip(&f_lu) {
            assert!(
                (a - b).abs() <= 1e-9 * (1.0 + b.abs()),
                "δF {a} against {b}"
            );
        }
    }
}
