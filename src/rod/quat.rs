//! Quaternion kinematics used by the rod: the rotation matrix of a (not
//! necessarily unit) quaternion, its partial derivatives, and the product
//! q ⊗ (0, u).
//!
//! Convention: q = (w, x, y, z), scalar first. R(q) is the homogeneous
//! quadratic form, equal to the rotation matrix when |q| = 1 and |q|² times
//! it otherwise; its columns are the directors d1, d2, d3 in lab components.

use nalgebra::{Matrix3, Vector3};

/// R(q), homogeneous quadratic form (columns d1, d2, d3).
pub(crate) fn rot(q: &[f64]) -> Matrix3<f64> {
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    Matrix3::new(
        w * w + x * x - y * y - z * z,
        2.0 * (x * y - w * z),
        2.0 * (x * z + w * y),
        2.0 * (x * y + w * z),
        w * w - x * x + y * y - z * z,
        2.0 * (y * z - w * x),
        2.0 * (x * z - w * y),
        2.0 * (y * z + w * x),
        w * w - x * x - y * y + z * z,
    )
}

/// ∂R/∂q_k for k = 0..4 (R is quadratic, so these are linear in q).
pub(crate) fn drot(q: &[f64]) -> [Matrix3<f64>; 4] {
    let (w, x, y, z) = (2.0 * q[0], 2.0 * q[1], 2.0 * q[2], 2.0 * q[3]);
    [
        Matrix3::new(w, -z, y, z, w, -x, -y, x, w),
        Matrix3::new(x, y, z, y, -x, -w, z, w, -x),
        Matrix3::new(-y, x, w, x, y, z, -w, z, -y),
        Matrix3::new(-z, -w, x, w, -z, y, x, y, z),
    ]
}

/// ½ q ⊗ (0, u) = ½ (−v·u, w u + v × u) with q = (w, v).
pub(crate) fn half_q_times_u(q: &[f64], u: &Vector3<f64>) -> [f64; 4] {
    let w = q[0];
    let v = Vector3::new(q[1], q[2], q[3]);
    let c = v.cross(u);
    [
        -0.5 * v.dot(u),
        0.5 * (w * u.x + c.x),
        0.5 * (w * u.y + c.y),
        0.5 * (w * u.z + c.z),
    ]
}

/// The 4 × 3 matrix L(q) with ½ q ⊗ (0, u) = ½ L(q) u: rows −vᵀ and
/// w I + [v]×.
pub(crate) fn l_matrix(q: &[f64]) -> [[f64; 3]; 4] {
    let (w, x, y, z) = (q[0], q[1], q[2], q[3]);
    [[-x, -y, -z], [w, -z, y], [z, w, -x], [-y, x, w]]
}

/// The quaternion product a ⊗ b.
#[cfg(test)]
pub(crate) fn mul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drot_matches_central_differences() {
        let q = [0.3, -0.5, 0.7, 0.2];
        let d = drot(&q);
        for (k, dk) in d.iter().enumerate() {
            let h = 1e-6;
            let mut qp = q;
            let mut qm = q;
            qp[k] += h;
            qm[k] -= h;
            let fd = (rot(&qp) - rot(&qm)) / (2.0 * h);
            // R is quadratic: the central difference is exact up to rounding
            // (ε/h ≈ 1e-10).
            assert!((fd - dk).abs().max() < 1e-9, "k = {k}");
        }
    }

    #[test]
    fn unit_quaternion_gives_the_rotation_of_nalgebra() {
        let q = nalgebra::UnitQuaternion::from_euler_angles(0.3, -1.1, 2.0);
        let c = q.coords; // (i, j, k, w)
        let r = rot(&[c.w, c.x, c.y, c.z]);
        assert!((r - q.to_rotation_matrix().into_inner()).abs().max() < 1e-15);
    }

    #[test]
    fn l_matrix_is_the_product_with_a_pure_quaternion() {
        let q = [0.3, -0.5, 0.7, 0.2];
        let u = Vector3::new(0.4, 1.3, -2.0);
        let p = mul(q, [0.0, u.x, u.y, u.z]);
        let h = half_q_times_u(&q, &u);
        let l = l_matrix(&q);
        for i in 0..4 {
            let lu = l[i][0] * u.x + l[i][1] * u.y + l[i][2] * u.z;
            assert!((0.5 * p[i] - h[i]).abs() < 1e-15);
            assert!((0.5 * lu - h[i]).abs() < 1e-15);
        }
    }
}
