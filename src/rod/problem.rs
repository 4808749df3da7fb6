//! The rod as a [`Problem`]: right-hand side, zero-moment boundary
//! conditions, the rotational phase condition, and their analytic Jacobians.

use nalgebra::{DMatrixViewMut, Matrix3, Vector3};

use super::quat::{drot, half_q_times_u, l_matrix, rot};
use super::{Control, Rod, symmetry};
use crate::bvp::Problem;

/// Index of the first component of r, q, F, M in the state vector.
pub(super) const R: usize = 0;
pub(super) const Q: usize = 3;
pub(super) const F: usize = 7;
pub(super) const M: usize = 10;

impl Rod {
    /// The material strains u = D⁻¹ Rᵀ M + u0(θ0) and the pieces needed to
    /// differentiate them.
    fn strains(&self, y: &[f64], theta0: f64) -> (Matrix3<f64>, Vector3<f64>) {
        let rq = rot(&y[Q..Q + 4]);
        let m = Vector3::new(y[M], y[M + 1], y[M + 2]);
        let mm = rq.transpose() * m;
        let u = Vector3::new(mm.x / self.a, mm.y / self.b, mm.z / self.c)
            + self.intrinsic_strains_at(theta0);
        (rq, u)
    }
}

impl Problem for Rod {
    fn dim(&self) -> usize {
        Rod::DIM
    }

    fn parameter_count(&self) -> usize {
        Rod::PARAMETERS
    }

    fn boundary_count(&self) -> usize {
        if self.half {
            symmetry::HALF_BOUNDARIES
        } else {
            symmetry::WHOLE_BOUNDARIES
        }
    }

    fn integral_count(&self) -> usize {
        if self.half { 0 } else { 1 }
    }

    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        let (rq, u) = self.strains(y, p[Rod::THETA0]);
        let d3 = rq.column(2).into_owned();
        f[R..R + 3].copy_from_slice(d3.as_slice());
        f[Q..Q + 4].copy_from_slice(&half_q_times_u(&y[Q..Q + 4], &u));
        f[F..F + 3].fill(0.0);
        let fv = Vector3::new(y[F], y[F + 1], y[F + 2]);
        let mp = fv.cross(&d3);
        f[M..M + 3].copy_from_slice(mp.as_slice());
        if self.half {
            // (σ = 2s on the half: d/dσ = ½ d/ds)
            f[..Rod::DIM].iter_mut().for_each(|v| *v *= 0.5);
        }
    }

    fn rhs_jacobian(
        &self,
        _s: f64,
        y: &[f64],
        p: &[f64],
        mut dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let q = &y[Q..Q + 4];
        let (rq, u) = self.strains(y, p[Rod::THETA0]);
        let dr = drot(q);
        let l = l_matrix(q);
        let m = Vector3::new(y[M], y[M + 1], y[M + 2]);
        let fv = Vector3::new(y[F], y[F + 1], y[F + 2]);
        let d3 = rq.column(2).into_owned();
        let dinv = Vector3::new(1.0 / self.a, 1.0 / self.b, 1.0 / self.c);

        // r′ = d3 = R e3.
        for k in 0..4 {
            for i in 0..3 {
                dfdy[(R + i, Q + k)] = dr[k][(i, 2)];
            }
        }
        // q′ = ½ q ⊗ (0, u): direct dependence on q at fixed u …
        // ∂/∂w = ½ (0, u); ∂/∂v = ½ (−uᵀ; −[u]×).
        dfdy[(Q, Q)] = 0.0;
        for i in 0..3 {
            dfdy[(Q + 1 + i, Q)] = 0.5 * u[i];
            dfdy[(Q, Q + 1 + i)] = -0.5 * u[i];
        }
        let ux = [[0.0, -u.z, u.y], [u.z, 0.0, -u.x], [-u.y, u.x, 0.0]];
        for i in 0..3 {
            for j in 0..3 {
                dfdy[(Q + 1 + i, Q + 1 + j)] = -0.5 * ux[i][j];
            }
        }
        // … plus ½ L(q) ∂u/∂q, with ∂u/∂q_k = D⁻¹ (∂R/∂q_k)ᵀ M.
        for (k, drk) in dr.iter().enumerate() {
            let du = (drk.transpose() * m).component_mul(&dinv);
            for (i, li) in l.iter().enumerate() {
                dfdy[(Q + i, Q + k)] += 0.5 * (li[0] * du.x + li[1] * du.y + li[2] * du.z);
            }
        }
        // ∂q′/∂M = ½ L(q) D⁻¹ Rᵀ.
        let dudm = Matrix3::from_diagonal(&dinv) * rq.transpose();
        for (i, li) in l.iter().enumerate() {
            for j in 0..3 {
                dfdy[(Q + i, M + j)] =
                    0.5 * (li[0] * dudm[(0, j)] + li[1] * dudm[(1, j)] + li[2] * dudm[(2, j)]);
            }
        }
        // ∂q′/∂θ0 = ½ L(q) ∂u0/∂θ0, ∂u0/∂θ0 = 2πn (0, cos θ0, −sin θ0).
        let du0 = Self::intrinsic_strains_derivative(self.coils, p[Rod::THETA0]);
        for (i, li) in l.iter().enumerate() {
            dfdp[(Q + i, Rod::THETA0)] = 0.5 * (li[1] * du0.y + li[2] * du0.z);
        }
        // M′ = F × d3: ∂/∂F = −[d3]×, ∂/∂q_k = F × ∂d3/∂q_k.
        let d3x = [[0.0, -d3.z, d3.y], [d3.z, 0.0, -d3.x], [-d3.y, d3.x, 0.0]];
        for i in 0..3 {
            for j in 0..3 {
                dfdy[(M + i, F + j)] = -d3x[i][j];
            }
        }
        for (k, drk) in dr.iter().enumerate() {
            let c = fv.cross(&drk.column(2).into_owned());
            for i in 0..3 {
                dfdy[(M + i, Q + k)] = c[i];
            }
        }
        if self.half {
            dfdy *= 0.5;
            dfdp *= 0.5;
        }
        true
    }

    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        if self.half {
            return symmetry::boundary(self, y0, y1, p, g);
        }
        g[0] = y0[R];
        g[1] = y0[R + 1];
        g[2] = y0[R + 2];
        g[3] = y1[R];
        g[4] = y1[R + 1];
        g[5] = match self.control {
            Control::Force => y0[F + 2] - p[Rod::FORCE],
            Control::Extension => y1[R + 2] - p[Rod::EXTENSION],
        };
        g[6] = y0[M];
        g[7] = y0[M + 1];
        g[8] = y0[M + 2];
        g[9] = y1[M];
        g[10] = y1[M + 1];
        let q0 = &y0[Q..Q + 4];
        g[11] = 0.5 * (q0.iter().map(|v| v * v).sum::<f64>() - 1.0);
    }

    fn boundary_jacobian(
        &self,
        y0: &[f64],
        y1: &[f64],
        _p: &[f64],
        mut dg0: DMatrixViewMut<'_, f64>,
        mut dg1: DMatrixViewMut<'_, f64>,
        mut dgp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        if self.half {
            symmetry::boundary_jacobian(self, y0, y1, dg0, dg1, dgp);
            return true;
        }
        dg0[(0, R)] = 1.0;
        dg0[(1, R + 1)] = 1.0;
        dg0[(2, R + 2)] = 1.0;
        dg1[(3, R)] = 1.0;
        dg1[(4, R + 1)] = 1.0;
        match self.control {
            Control::Force => {
                dg0[(5, F + 2)] = 1.0;
                dgp[(5, Rod::FORCE)] = -1.0;
            }
            Control::Extension => {
                dg1[(5, R + 2)] = 1.0;
                dgp[(5, Rod::EXTENSION)] = -1.0;
            }
        }
        dg0[(6, M)] = 1.0;
        dg0[(7, M + 1)] = 1.0;
        dg0[(8, M + 2)] = 1.0;
        dg1[(9, M)] = 1.0;
        dg1[(10, M + 1)] = 1.0;
        for k in 0..4 {
            dg0[(11, Q + k)] = y0[Q + k];
        }
        true
    }

    fn integrand(&self, _s: f64, y: &[f64], y_ref: &[f64], _p: &[f64], h: &mut [f64]) {
        let g = rotation_generator(&y_ref[Q..Q + 4]);
        h[0] = (0..4).map(|k| y[Q + k] * g[k]).sum();
    }

    fn integrand_jacobian(
        &self,
        _s: f64,
        _y: &[f64],
        y_ref: &[f64],
        _p: &[f64],
        mut dhdy: DMatrixViewMut<'_, f64>,
        _dhdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let g = rotation_generator(&y_ref[Q..Q + 4]);
        for k in 0..4 {
            dhdy[(0, Q + k)] = g[k];
        }
        true
    }
}

/// G q = ½ k ⊗ q = ½ (−q3, −q2, q1, q0): the velocity of q under a rigid
/// rotation of the whole rod about the force axis k (left multiplication by
/// exp(ε k/2)). |G q| = |q|/2, so the phase condition ∫⟨q, G q_ref⟩ ds = 0
/// is transversal to the symmetry orbit at every q_ref.
fn rotation_generator(q: &[f64]) -> [f64; 4] {
    [-0.5 * q[3], -0.5 * q[2], 0.5 * q[1], 0.5 * q[0]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generator_is_the_derivative_of_a_rotation_about_k() {
        let q = [0.3, -0.5, 0.7, 0.2];
        let eps: f64 = 1e-6;
        let rot_k = |e: f64| [(e / 2.0).cos(), 0.0, 0.0, (e / 2.0).sin()];
        let qp = super::super::quat::mul(rot_k(eps), q);
        let qm = super::super::quat::mul(rot_k(-eps), q);
        let g = rotation_generator(&q);
        for k in 0..4 {
            // Central difference of a smooth function: O(ε²) ≈ 1e-12 plus
            // rounding ε_mach/ε ≈ 1e-10.
            assert!(((qp[k] - qm[k]) / (2.0 * eps) - g[k]).abs() < 1e-9);
        }
        // And the rotation of R(q) about k is what we meant: R(k-rotated q)
        // = Rz(ε) R(q).
        let r = rot(&super::super::quat::mul(rot_k(0.4), q));
        let rz = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4);
        assert!((r - rz.matrix() * rot(&q)).abs().max() < 1e-14);
    }
}
