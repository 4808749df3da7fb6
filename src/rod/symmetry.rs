//! The rod's end-to-end symmetry: the half of a spring on one side of its
//! midpoint, the other half its image ([`Rod::symmetric`]).
//!
//! A helix of n coils is mapped onto itself, ends exchanged, by the rotation
//! R by π about its principal normal at the midpoint (the line through the
//! midpoint perpendicular to the helix axis). Pulled with zero end moments
//! along the line through its ends, the spring keeps that symmetry: with the
//! ends on the z axis and the midpoint's normal along e_y, an equilibrium y
//! has the image
//!
//! y*(s) = (R(r − c) + c, R Q diag(1, −1, −1), −R F, −R M)(1 − s),
//!
//! R = diag(−1, 1, −1), c = (0, 0, Δz/2): r*′ = d3* since d3* = −R d3
//! (s reversed); the strains of the image are u* = (−u1, u2, u3), which
//! keeps u0 = (0, u20, u30), the helix's, and makes M* = −R M; the ends'
//! conditions map onto each other. The paper's branches are symmetric
//! (its primary and secondary υ elasticas, Section 3), and so is the pull
//! from rest until a symmetry-breaking bifurcation.
//!
//! Solving the half s ∈ [0, ½] with the fixed-point conditions of the map
//! at the midpoint removes the rod's antisymmetric modes from the problem:
//! on a long spring's unlooping plateau (one front coming in from each
//! end) and where loops left in the rod slide along it, such a mode is
//! nearly free, and the full rod's Newton drifts along it at its rounding
//! floor (docs/ACCURACY.md, "Long springs"). At the midpoint:
//! r_x = 0, d1 ∥ e_y (d1_x = d1_z = 0), F_y = 0, M_y = 0. The half rod's
//! unknown arclength is σ = 2s ∈ [0, 1], so its right-hand side is ½ the
//! rod's; Δz = 2 z(½); the rotation about the force axis is fixed by
//! r_x(½) = 0, so the half has no phase condition.

use nalgebra::DMatrixViewMut;

use super::Rod;
use super::problem::{F, M, Q, R};
use super::quat::{drot, rot};
use crate::bvp::guess::state_from_guess;
use crate::bvp::{Mesh, Solution};
use crate::error::{Error, Result};
use crate::load::Control;

/// Boundary conditions of the whole rod (the half has one more: the
/// midpoint's five fixed-point conditions for the far end's four and the
/// phase condition's integral).
pub(super) const WHOLE_BOUNDARIES: usize = 12;
/// Boundary conditions of the half.
pub(super) const HALF_BOUNDARIES: usize = 13;

impl Rod {
    /// The same rod solved on its half s ∈ [0, ½], the other half its image
    /// under the rotation by π about the midpoint's normal (module docs):
    /// the equilibria symmetric end to end, at half the unknowns and without
    /// the antisymmetric modes that make long springs and sliding loops
    /// nearly singular. Its [`Problem`](crate::bvp::Problem) solutions live
    /// on the half (σ = 2s ∈ [0, 1]); [`Equilibrium::new`](super::Equilibrium::new)
    /// turns one into the whole rod's. A symmetric rod is symmetric already.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if the intrinsic strain u10 is not zero:
    /// the map keeps only u0 = (0, u20, u30) (every helix's).
    pub fn symmetric(mut self) -> Result<Self> {
        let u10 = self.intrinsic_strains().x;
        if u10 != 0.0 {
            return Err(Error::InvalidArgument {
                name: "u10",
                value: u10,
                allowed: "0 for a symmetric rod (the midpoint's rotation keeps only u0 = (0, u20, u30))",
            });
        }
        self.half = true;
        Ok(self)
    }

    /// Whether the rod is solved on its half ([`Rod::symmetric`]).
    #[must_use]
    pub fn is_symmetric(&self) -> bool {
        self.half
    }

    /// The whole rod of a symmetric one (itself otherwise).
    pub(crate) fn whole(mut self) -> Self {
        self.half = false;
        self
    }

    /// Δz of a solution of this rod's problem: z at its right end, twice it
    /// on a half.
    pub(crate) fn extension_of(&self, solution: &Solution) -> f64 {
        let z = solution.at_mesh(solution.mesh().intervals())[R + 2];
        if self.half { 2.0 * z } else { z }
    }

    /// The unstressed helix at the problem's own arclength: s on the whole
    /// rod, σ = 2s on a half.
    pub(crate) fn unstressed_at(&self, sigma: f64) -> [f64; 13] {
        self.unstressed(if self.half { 0.5 * sigma } else { sigma })
    }
}

/// The half's boundary conditions (module docs): the whole rod's at s = 0,
/// the control, and the map's fixed point at the midpoint.
pub(super) fn boundary(rod: &Rod, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
    g[0] = y0[R];
    g[1] = y0[R + 1];
    g[2] = y0[R + 2];
    g[3] = match rod.control {
        Control::Force => y0[F + 2] - p[Rod::FORCE],
        Control::Extension => y1[R + 2] - 0.5 * p[Rod::EXTENSION],
    };
    g[4] = y0[M];
    g[5] = y0[M + 1];
    g[6] = y0[M + 2];
    g[7] = 0.5 * (y0[Q..Q + 4].iter().map(|v| v * v).sum::<f64>() - 1.0);
    let d1 = rot(&y1[Q..Q + 4]).column(0).into_owned();
    g[8] = y1[R];
    g[9] = d1.x;
    g[10] = d1.z;
    g[11] = y1[F + 1];
    g[12] = y1[M + 1];
}

/// ∂g/∂y(0), ∂g/∂y(1), ∂g/∂p of [`boundary`].
pub(super) fn boundary_jacobian(
    rod: &Rod,
    y0: &[f64],
    y1: &[f64],
    mut dg0: DMatrixViewMut<'_, f64>,
    mut dg1: DMatrixViewMut<'_, f64>,
    mut dgp: DMatrixViewMut<'_, f64>,
) {
    dg0[(0, R)] = 1.0;
    dg0[(1, R + 1)] = 1.0;
    dg0[(2, R + 2)] = 1.0;
    match rod.control {
        Control::Force => {
            dg0[(3, F + 2)] = 1.0;
            dgp[(3, Rod::FORCE)] = -1.0;
        }
        Control::Extension => {
            dg1[(3, R + 2)] = 1.0;
            dgp[(3, Rod::EXTENSION)] = -0.5;
        }
    }
    dg0[(4, M)] = 1.0;
    dg0[(5, M + 1)] = 1.0;
    dg0[(6, M + 2)] = 1.0;
    for k in 0..4 {
        dg0[(7, Q + k)] = y0[Q + k];
    }
    dg1[(8, R)] = 1.0;
    for (k, drk) in drot(&y1[Q..Q + 4]).iter().enumerate() {
        dg1[(9, Q + k)] = drk[(0, 0)];
        dg1[(10, Q + k)] = drk[(2, 0)];
    }
    dg1[(11, F + 1)] = 1.0;
    dg1[(12, M + 1)] = 1.0;
}

/// The whole rod's solution from a half's: the half on s ∈ [0, ½] (σ = 2s)
/// and its image on [½, 1] (module docs), on the half's mesh and its mirror
/// image. The collocation polynomial of each interval maps onto one of the
/// same degree (the Gauss points are symmetric), so the image is exact.
///
/// q and −q are one rotation; the image's quaternion takes the sign that
/// meets the half's at the midpoint.
pub(super) fn whole_solution(half: &Solution) -> Result<Solution> {
    let points = half.mesh().points();
    let mut whole: Vec<f64> = points.iter().map(|t| 0.5 * t).collect();
    whole.extend(points.iter().rev().skip(1).map(|t| 1.0 - 0.5 * t));
    let mesh = Mesh::from_points(whole)?;
    let mid = half.at_mesh(half.mesh().intervals());
    let z_mid = mid[R + 2];
    let (w, x, y, z) = (mid[Q], mid[Q + 1], mid[Q + 2], mid[Q + 3]);
    let sign = if z * w + y * x + x * y + w * z >= 0.0 {
        1.0
    } else {
        -1.0
    };
    let image = |sigma: f64| -> [f64; 13] {
        let mut v = [0.0; 13];
        half.eval_into(sigma, &mut v);
        let (w, x, y, z) = (v[Q], v[Q + 1], v[Q + 2], v[Q + 3]);
        [
            -v[R],
            v[R + 1],
            2.0 * z_mid - v[R + 2],
            sign * z,
            sign * y,
            sign * x,
            sign * w,
            v[F],
            -v[F + 1],
            v[F + 2],
            v[M],
            -v[M + 1],
            v[M + 2],
        ]
    };
    let guess = |s: f64| -> [f64; 13] {
        if s <= 0.5 {
            let mut v = [0.0; 13];
            half.eval_into(2.0 * s, &mut v);
            v
        } else {
            image(2.0 * (1.0 - s))
        }
    };
    let state = state_from_guess(&guess, &mesh, &half.tab, Rod::DIM, half.parameters());
    let mut whole = Solution::interpolant(&state, &mesh, &half.tab, Rod::DIM);
    whole.boundaries = Some(WHOLE_BOUNDARIES);
    Ok(whole)
}
