//! Outputs of one rod equilibrium, computed on demand from a state
//! evaluator s ↦ y(s) and the breakpoints of its piecewise representation
//! (quadratures are composite Gauss–Legendre on those panels, exact for the
//! piecewise polynomials of a collocation solution up to its own degree).

use core::f64::consts::PI;
use std::sync::OnceLock;

use nalgebra::{Matrix2, Matrix3, SymmetricEigen, Vector3};

use super::Rod;
use super::quat::rot;
use crate::quadrature::GaussLegendre;

/// ∫₀¹ g(s) ds by 5-point Gauss on each panel [b_i, b_{i+1}], `sub` equal
/// sub-panels each.
pub(crate) fn integrate<G: FnMut(f64) -> f64>(breaks: &[f64], sub: usize, mut g: G) -> f64 {
    static GL5: OnceLock<GaussLegendre> = OnceLock::new();
    let rule = GL5.get_or_init(|| GaussLegendre::new(5));
    let mut total = 0.0;
    for w in breaks.windows(2) {
        let h = (w[1] - w[0]) / sub as f64;
        for j in 0..sub {
            let a = w[0] + j as f64 * h;
            for (x, wt) in rule.nodes.iter().zip(&rule.weights) {
                total += h * wt * g(a + h * x);
            }
        }
    }
    total
}

/// The material strains u(s) of the state y (u = D⁻¹ Rᵀ M + u0).
pub(crate) fn strains(rod: &Rod, theta0: f64, y: &[f64; 13]) -> Vector3<f64> {
    let r = rot(&y[3..7]);
    let m = r.transpose() * Vector3::new(y[10], y[11], y[12]);
    Vector3::new(m.x / rod.a, m.y / rod.b, m.z / rod.c) + rod.intrinsic_strains_at(theta0)
}

/// Elastic energy ½ ∫ A(u1 − u10)² + B(u2 − u20)² + C(u3 − u30)² ds.
pub(crate) fn energy<E: Fn(f64) -> [f64; 13]>(rod: &Rod, eval: E, breaks: &[f64]) -> f64 {
    integrate(breaks, 1, |s| {
        let y = eval(s);
        let m = rot(&y[3..7]).transpose() * Vector3::new(y[10], y[11], y[12]);
        0.5 * (m.x * m.x / rod.a + m.y * m.y / rod.b + m.z * m.z / rod.c)
    })
}

/// Distance from planarity: the largest distance of the centreline from
/// the plane through the force axis k that fits it best in L² (planar
/// elastica solutions lie in such a plane). `samples` are (quadrature
/// weight, state) in order of s.
pub(crate) fn planarity(samples: &[(f64, [f64; 13])]) -> f64 {
    let mut s2 = Matrix2::zeros();
    for (w, y) in samples {
        let v = nalgebra::Vector2::new(y[0], y[1]);
        s2 += *w * v * v.transpose();
    }
    let eig = SymmetricEigen::new(s2);
    let i = if eig.eigenvalues[0] <= eig.eigenvalues[1] {
        0
    } else {
        1
    };
    let n = eig.eigenvectors.column(i).into_owned();
    samples
        .iter()
        .map(|(_, y)| (y[0] * n.x + y[1] * n.y).abs())
        .fold(0.0, f64::max)
}

/// Smallest length of the tangent projected on the plane of
/// [`turning`] at which the loop count is still defined: below it the
/// tangent stands within 60° of the plane's normal somewhere, the shape is
/// out of plane there (during a pop-out), and counting turns of the
/// projection would count that excursion's wobble.
pub(crate) const LOOP_PROJECTION_MIN: f64 = 0.5;

/// The tangent's turning in the plane it leaves least: the turning number
/// (net turn / 2π, continuous) and the loop count (net signed passes of the
/// projected tangent through a reference direction, an integer; `None`
/// where the tangent leaves the plane, |P d3| < [`LOOP_PROJECTION_MIN`], or
/// where the passes and the turning number differ by a turn or more).
///
/// ν is the eigenvector of the smallest eigenvalue of ∫ d3 d3ᵀ ds (k for the
/// unstressed helix, the normal of the plane for a planar elastica). The
/// reference direction is the projection of the force axis k when it lies
/// in the plane (a planar j-loop υ-shape turns its tangent through the force
/// direction exactly j times, wherever its ends point), otherwise the
/// in-plane direction perpendicular to the mean end tangent (the helix: n).
/// Passes are counted with their sign, so a wobble back and forth across
/// the reference (an inflection near it) counts zero.
pub(crate) struct Turning {
    pub(crate) turns: f64,
    pub(crate) loops: Option<u32>,
}

pub(crate) fn turning(samples: &[(f64, [f64; 13])]) -> Turning {
    let mut t = Matrix3::zeros();
    let tangents: Vec<Vector3<f64>> = samples
        .iter()
        .map(|(_, y)| rot(&y[3..7]).column(2).into_owned())
        .collect();
    for ((w, _), d3) in samples.iter().zip(&tangents) {
        t += *w * d3 * d3.transpose();
    }
    let eig = SymmetricEigen::new(t);
    let imin = eig.eigenvalues.imin();
    let nu = eig.eigenvectors.column(imin).into_owned();
    let seed = if nu.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let e1 = (seed - nu * nu.dot(&seed)).normalize();
    let e2 = nu.cross(&e1);
    let projected: Vec<(f64, f64)> = tangents
        .iter()
        .map(|d3| (d3.dot(&e1), d3.dot(&e2)))
        .collect();
    let in_plane = projected
        .iter()
        .all(|(x, y)| x.hypot(*y) >= LOOP_PROJECTION_MIN);
    let angles: Vec<f64> = projected.iter().map(|(x, y)| y.atan2(*x)).collect();
    let kp = Vector3::z() - nu * nu.z;
    let reference = if kp.norm() > 0.5 {
        kp.dot(&e2).atan2(kp.dot(&e1))
    } else {
        let (a0, a1) = (angles[0], angles[angles.len() - 1]);
        let mean = (a0.sin() + a1.sin()).atan2(a0.cos() + a1.cos());
        mean + 0.5 * PI
    };
    let wrap = |d: f64| d - 2.0 * PI * (d / (2.0 * PI)).round();
    let mut total = 0.0;
    let mut passes = 0.0;
    let mut unwrapped = wrap(angles[0] - reference);
    for w in angles.windows(2) {
        let d = wrap(w[1] - w[0]);
        total += d;
        let next = unwrapped + d;
        passes += (next / (2.0 * PI)).floor() - (unwrapped / (2.0 * PI)).floor();
        unwrapped = next;
    }
    let turns = (total / (2.0 * PI)).abs();
    let passes = passes.abs();
    // The two counts agree to within a turn on every planar υ-shape
    // (turns = j + δ/π, |δ| < π) and on the helix (both n); where they do
    // not, the projection misrepresents the shape and no count is given.
    let consistent = (turns - passes).abs() < 1.0;
    Turning {
        turns,
        // passes ≤ samples, so the conversion cannot saturate in practice.
        loops: (in_plane && consistent).then(|| passes.min(f64::from(u32::MAX)) as u32),
    }
}
