//! One equilibrium of the rod with its outputs, computed on demand.

use core::f64::consts::PI;

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

use super::Rod;
use super::measure;
use crate::bvp::Solution;
use crate::error::{Error, Result};

/// One equilibrium of a [`Rod`]: a collocation [`Solution`] of the rod's
/// boundary-value problem, with every output computed only when asked.
///
/// | output | meaning |
/// |---|---|
/// | [`force`](Self::force) | F_z, the physical tension (units B/L²) |
/// | [`force_scaled`](Self::force_scaled) | F_z/((2πn)²B), the paper's plotting scale |
/// | [`extension`](Self::extension) | Δz = z(1) |
/// | [`centreline`](Self::centreline), [`frame`](Self::frame) | r(s) and (d1, d2, d3)(s) at any s |
/// | [`strains`](Self::strains), [`curvature`](Self::curvature), [`twist`](Self::twist) | u(s), √(u1² + u2²), u3 |
/// | [`energy`](Self::energy) | ½∫ A(u1 − u10)² + B(u2 − u20)² + C(u3 − u30)² ds |
/// | [`planarity`](Self::planarity) | largest distance from the best plane through the force axis |
/// | [`turning_number`](Self::turning_number), [`loops`](Self::loops) | the writhe-like loop count |
/// | [`axial_turns`](Self::axial_turns) | turns of the tangent about the force axis (unwinding / overwinding) |
/// | [`quaternion_drift`](Self::quaternion_drift) | max | \|q\| − 1 |, an accuracy check |
#[derive(Debug, Clone)]
pub struct Equilibrium {
    rod: Rod,
    solution: Solution,
}

impl Equilibrium {
    /// Wraps a solution of `rod`'s problem; of a [symmetric](Rod::symmetric)
    /// rod's, the whole rod's equilibrium: the half and its image (the
    /// equilibrium's [`rod`](Self::rod) is then the whole rod).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if the solution is not of a 13-dimensional
    /// problem with the rod's 3 parameters, or solves a problem with other
    /// boundary conditions (a symmetric rod's half given the whole rod, or
    /// the other way round).
    pub fn new(rod: Rod, solution: Solution) -> Result<Self> {
        if solution.dim() != Rod::DIM {
            return Err(Error::InvalidCount {
                name: "solution.dim()",
                value: solution.dim() as u64,
                allowed: "13, the rod's unknowns (r, q, F, M)",
            });
        }
        if solution.parameters().len() != Rod::PARAMETERS {
            return Err(Error::InvalidCount {
                name: "solution.parameters().len()",
                value: solution.parameters().len() as u64,
                allowed: "3, the rod's parameters (λ, Δz, θ0)",
            });
        }
        // a symmetric rod's half and the whole rod both have 13 unknowns;
        // their boundary conditions tell them apart (an interpolant does not
        // say)
        if let Some(b) = solution.boundaries
            && b != crate::bvp::Problem::boundary_count(&rod)
        {
            return Err(Error::InvalidCount {
                name: "the solution's boundary conditions",
                value: b as u64,
                allowed: "the rod's: 12 for the whole rod, 13 for a symmetric rod's half \
                          (a half's solution needs the symmetric rod, `Rod::symmetric`)",
            });
        }
        if rod.is_symmetric() {
            return Ok(Self {
                rod: rod.whole(),
                solution: super::symmetry::whole_solution(&solution)?,
            });
        }
        Ok(Self { rod, solution })
    }

    /// The rod (its control is the one the solution was computed with).
    #[must_use]
    pub fn rod(&self) -> &Rod {
        &self.rod
    }

    /// The collocation solution.
    #[must_use]
    pub fn solution(&self) -> &Solution {
        &self.solution
    }

    /// The parameters (λ, Δz, θ0) of the solution.
    #[must_use]
    pub fn parameters(&self) -> [f64; 3] {
        let p = self.solution.parameters();
        [p[0], p[1], p[2]]
    }

    /// The physical tension F_z (units B/L², positive when pulling).
    #[must_use]
    pub fn force(&self) -> f64 {
        self.solution.at_mesh(0)[9]
    }

    /// F_z / ((2πn)²B), the scale of the paper's figures
    /// ([`Rod::scale`]).
    #[must_use]
    pub fn force_scaled(&self) -> f64 {
        self.force() / self.rod.scale().value()
    }

    /// The extension Δz = z(1) (end-to-end distance along the force per
    /// unit length).
    #[must_use]
    pub fn extension(&self) -> f64 {
        self.solution.at_mesh(self.solution.mesh().intervals())[2]
    }

    /// The state y(s) = (r, q, F, M) from the collocation polynomial.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn state(&self, s: f64) -> Result<[f64; 13]> {
        if !(0.0..=1.0).contains(&s) {
            return Err(Error::InvalidArgument {
                name: "s",
                value: s,
                allowed: "an arclength in [0, 1]",
            });
        }
        Ok(self.eval(s))
    }

    pub(super) fn eval(&self, s: f64) -> [f64; 13] {
        let mut y = [0.0; 13];
        self.solution.eval_into(s, &mut y);
        y
    }

    fn breaks(&self) -> &[f64] {
        self.solution.mesh().points()
    }

    /// (quadrature weight, state) at the mesh points (weight 0) and the
    /// Gauss points (their composite Gauss weights), in order of s: exact
    /// moments of degree ≤ 2m − 1 per interval, and the tangent sampled m + 1
    /// times per interval.
    fn samples(&self) -> Vec<(f64, [f64; 13])> {
        let sol = &self.solution;
        let m = sol.points_per_interval();
        let nn = sol.mesh().intervals();
        let cv = sol.collocation_values();
        let gw = sol.gauss_weights();
        let mut out = Vec::with_capacity(nn * (m + 1) + 1);
        let state = |col: &[f64]| {
            let mut y = [0.0; 13];
            y.copy_from_slice(col);
            y
        };
        for j in 0..nn {
            out.push((0.0, state(sol.at_mesh(j))));
            let h = sol.mesh().width(j);
            for (k, w) in gw.iter().enumerate() {
                out.push((w * h, state(cv.column(j * m + k).as_slice())));
            }
        }
        out.push((0.0, state(sol.at_mesh(nn))));
        out
    }

    /// The centreline r(s).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn centreline(&self, s: f64) -> Result<Vector3<f64>> {
        let y = self.state(s)?;
        Ok(Vector3::new(y[0], y[1], y[2]))
    }

    /// The centreline at `samples + 1` equally spaced s ∈ [0, 1].
    ///
    /// # Errors
    /// [`Error::InvalidCount`] unless 1 ≤ `samples` <
    /// [`MAX_POINTS`](crate::error::MAX_POINTS).
    pub fn centreline_samples(&self, samples: usize) -> Result<Vec<Vector3<f64>>> {
        crate::error::check_points("samples", samples.saturating_add(1))?;
        Ok((0..=samples)
            .map(|j| {
                let y = self.eval(j as f64 / samples as f64);
                Vector3::new(y[0], y[1], y[2])
            })
            .collect())
    }

    /// The material frame at s as a unit quaternion: d_i = q e_i (the
    /// solution's q, normalised; see [`Self::quaternion_drift`]).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn frame(&self, s: f64) -> Result<UnitQuaternion<f64>> {
        let y = self.state(s)?;
        Ok(UnitQuaternion::from_quaternion(Quaternion::new(
            y[3], y[4], y[5], y[6],
        )))
    }

    /// The material strains u(s) = D⁻¹ Rᵀ M + u0 (curvatures u1, u2 about
    /// d1, d2 and twist u3).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn strains(&self, s: f64) -> Result<Vector3<f64>> {
        let y = self.state(s)?;
        Ok(measure::strains(&self.rod, self.parameters()[2], &y))
    }

    /// The curvature of the centreline, √(u1² + u2²), at s.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn curvature(&self, s: f64) -> Result<f64> {
        let u = self.strains(s)?;
        Ok(u.x.hypot(u.y))
    }

    /// The twist rate u3 at s.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn twist(&self, s: f64) -> Result<f64> {
        Ok(self.strains(s)?.z)
    }

    /// The elastic energy ½∫ [A(u1 − u10)² + B(u2 − u20)² + C(u3 − u30)²] ds
    /// = ½∫ Mᵀ R D⁻¹ Rᵀ M ds, by 5-point Gauss on each mesh interval. Along a
    /// force-controlled branch dU/dΔz = F_z (tested).
    #[must_use]
    pub fn energy(&self) -> f64 {
        measure::energy(&self.rod, |s| self.eval(s), self.breaks())
    }

    /// Distance from planarity: the largest distance of the centreline from
    /// the plane through the force axis that fits it best in L². Zero for
    /// planar elastica solutions; R0 = sin θ0/(2πn) for the unstressed helix.
    #[must_use]
    pub fn planarity(&self) -> f64 {
        measure::planarity(&self.samples())
    }

    /// The turning number: the net turn of the tangent, projected onto the
    /// plane it leaves least (normal to the eigenvector of the smallest
    /// eigenvalue of ∫ d3 d3ᵀ ds), over 2π. n for the unstressed helix,
    /// j + δ/π for a planar j-loop υ-shape whose end tangents are turned by δ
    /// from its curvature maxima; continuous along a branch.
    #[must_use]
    pub fn turning_number(&self) -> f64 {
        measure::turning(&self.samples()).turns
    }

    /// The number of loops: the net number of times the tangent, projected
    /// onto the plane of [`Self::turning_number`], passes the force direction
    /// (or, when the force is normal to that plane as for the unstressed
    /// helix, the direction perpendicular to the mean end tangent), passes
    /// counted with their sign. n for the unstressed helix, j for a planar
    /// j-loop υ-shape whatever the direction of its end tangents; it drops by
    /// one across each pop-out.
    ///
    /// `None` where the count is not defined: the tangent leaves that plane
    /// somewhere (its projection is shorter than ½, i.e. it stands within
    /// 60° of the plane's normal), as in the 3D excursion of a pop-out, or
    /// the passes and [`Self::turning_number`] differ by a whole turn or
    /// more (they agree within a turn on every planar υ-shape and on the
    /// helix), so that the projection misrepresents the shape.
    #[must_use]
    pub fn loops(&self) -> Option<u32> {
        measure::turning(&self.samples()).loops
    }

    /// The number of turns of the tangent about the force axis: the net
    /// azimuth of d3 around k over 2π (signed, positive in the sense of the
    /// unstressed helix's winding for θ0 < 90°). n for the unstressed helix;
    /// it falls when a spring unwinds and grows when it overwinds (the
    /// paper's slinky, A/B = 0.1). Sampled at the mesh and Gauss points.
    #[must_use]
    pub fn axial_turns(&self) -> f64 {
        let mut total = 0.0;
        let mut prev: Option<f64> = None;
        for (_, y) in self.samples() {
            let d3 = super::quat::rot(&y[3..7]).column(2).into_owned();
            let a = d3.y.atan2(d3.x);
            if let Some(p) = prev {
                let d = a - p;
                total += d - 2.0 * PI * (d / (2.0 * PI)).round();
            }
            prev = Some(a);
        }
        total / (2.0 * PI)
    }

    /// max | |q(t_j)| − 1 | over the mesh points t_j. Gauss collocation is
    /// a symplectic Runge–Kutta method and conserves the quadratic invariant
    /// |q|² of q′ = ½ q ⊗ (0, u) exactly at the mesh points, so this measures
    /// the Newton tolerance and rounding, not the discretisation (between
    /// mesh points the collocation polynomial drifts by O(h^(m+1))).
    #[must_use]
    pub fn quaternion_drift(&self) -> f64 {
        (0..=self.solution.mesh().intervals())
            .map(|j| {
                let y = self.solution.at_mesh(j);
                let n2: f64 = y[3..7].iter().map(|v| v * v).sum();
                (n2.sqrt() - 1.0).abs()
            })
            .fold(0.0, f64::max)
    }
}

impl core::fmt::Display for Equilibrium {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "rod equilibrium: F = {:.6} (F/((2πn)²B) = {:.6}), Δz = {:.6}, {} intervals",
            self.force(),
            self.force_scaled(),
            self.extension(),
            self.solution.mesh().intervals()
        )
    }
}
