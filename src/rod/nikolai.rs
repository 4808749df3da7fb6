//! The rod with its stiffnesses as continuation parameters: ln(A/B) and ν,
//! with C by the Nikolai equality ([`NikolaiRod`]).

use nalgebra::{DMatrixViewMut, Vector3};

use super::Rod;
use super::quat::{l_matrix, rot};
use crate::bvp::{Problem, Solution};
use crate::error::{Error, Result};
use crate::stiffness::Stiffness;

/// The [`Rod`] of a spring whose stiffnesses follow from the anisotropy A/B
/// and the Poisson ratio ν by the Nikolai equality
/// ([`Stiffness::nikolai`]), with both as parameters of the
/// boundary-value problem, so that a fold can be continued in them
/// ([`crate::continuation::FoldContinuation`]). The anisotropy enters as
/// ln(A/B), so that a step of the continuation covers a ratio, not a
/// difference (A/B from 2 to 100 in a few dozen steps).
///
/// ```text
///   p = [f, Δz, θ0, ln(A/B), ν]    f = F_z/((2πn)²B) (the rod's λ scaled), Δz, θ0 as the rod's
///   A = (A/B)·B,   C = 2AB / ((1 + ν)(A + B)),   B fixed
///   ∂u/∂A = (−(RᵀM)₁/A², 0, 0),   ∂u/∂C = (0, 0, −(RᵀM)₃/C²)
///   ∂C/∂A = 2B² / ((1 + ν)(A + B)²),   ∂C/∂ν = −C/(1 + ν),   ∂A/∂ln(A/B) = A
/// ```
///
/// Everything else (equations, boundary and phase conditions, control) is
/// the rod's, evaluated at the stiffnesses of p and the force f·(2πn)²B;
/// the analytic Jacobians are the rod's plus the two columns above
/// (through q′ = ½ q ⊗ (0, u)). The force is scaled so that every
/// parameter is of order one: a fold curve's arclength then weighs a
/// change of force like one of θ0, A/B or ν.
///
/// ```
/// use hockle::bvp::Problem;
/// use hockle::rod::{NikolaiRod, Rod};
/// use hockle::Stiffness;
/// let rod = Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
/// let family = NikolaiRod::new(rod, 0.05)?;
/// assert_eq!(family.parameter_count(), 5);
/// let p = family.parameters(&rod.parameters_at_rest());
/// assert_eq!(family.rod_at(&p), rod);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NikolaiRod {
    rod: Rod,
    nu: f64,
    /// ln(A/B) of `rod`.
    ln_ratio: f64,
}

impl NikolaiRod {
    /// Number of parameters.
    pub const PARAMETERS: usize = 5;
    /// Index of the scaled force f = F_z/((2πn)²B) in the parameter vector.
    pub const FORCE_SCALED: usize = 0;
    /// Index of ln(A/B) in the parameter vector.
    pub const LN_A_OVER_B: usize = 3;
    /// Index of the Poisson ratio ν in the parameter vector.
    pub const NU: usize = 4;

    /// The family through `rod`, whose C must be the Nikolai value of its
    /// A/B and `nu`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] if `nu` is not in (−1, ½] or the rod's C
    /// is not 2AB/((1 + ν)(A + B)) to 1e-12 relative.
    pub fn new(rod: Rod, nu: f64) -> Result<Self> {
        let s = rod.stiffness();
        let expected = Stiffness::nikolai(s.a() / s.b(), nu)?.c() * s.b();
        if (s.c() / expected - 1.0).abs() > 1e-12 {
            return Err(Error::InvalidArgument {
                name: "torsional stiffness C",
                value: s.c(),
                allowed: "the Nikolai value 2AB/((1 + ν)(A + B)) of the rod's A, B and this ν",
            });
        }
        Ok(Self {
            rod,
            nu,
            ln_ratio: (s.a() / s.b()).ln(),
        })
    }

    /// The rod this family was built from.
    #[must_use]
    pub fn rod(&self) -> &Rod {
        &self.rod
    }

    /// The Poisson ratio of [`NikolaiRod::rod`].
    #[must_use]
    pub fn nu(&self) -> f64 {
        self.nu
    }

    /// The family's parameter vector from the rod's `[λ, Δz, θ0]`, with
    /// this family's A/B and ν.
    #[must_use]
    pub fn parameters(&self, rod_parameters: &[f64; 3]) -> [f64; 5] {
        let s = self.rod.stiffness();
        let [l, dz, t] = *rod_parameters;
        let _ = s;
        [l / self.scale(), dz, t, self.ln_ratio, self.nu]
    }

    /// (2πn)²B.
    fn scale(&self) -> f64 {
        self.rod.scale().value()
    }

    /// The rod's parameters `[λ, Δz, θ0]` at the family's `p`.
    fn rod_parameters(&self, p: &[f64]) -> [f64; 3] {
        [p[0] * self.scale(), p[1], p[2]]
    }

    /// The rod at parameters `p` (its θ0 field is the family's; θ0 as a
    /// parameter is `p[Rod::THETA0]`). Stiffnesses that are not finite and
    /// positive at `p` give the family's own.
    #[must_use]
    pub fn rod_at(&self, p: &[f64]) -> Rod {
        if p[Self::LN_A_OVER_B] == self.ln_ratio && p[Self::NU] == self.nu {
            // the family's own stiffnesses, without exp(ln(A/B))'s rounding
            return self.rod;
        }
        let b = self.rod.b;
        let (a, c) = stiffness_at(b, p[Self::LN_A_OVER_B].exp(), p[Self::NU]);
        if a.is_finite() && c.is_finite() && a > 0.0 && c > 0.0 {
            Rod { a, c, ..self.rod }
        } else {
            self.rod
        }
    }

    /// A solution of [`NikolaiRod::rod`] (3 parameters) as a solution of
    /// the family (5 parameters), and back with [`NikolaiRod::restrict`].
    #[must_use]
    pub fn extend(&self, rod_solution: &Solution) -> Solution {
        let mut s = rod_solution.clone();
        let p: [f64; 3] = [s.p[0], s.p[1], s.p[2]];
        s.p = self.parameters(&p).to_vec();
        s
    }

    /// A solution of the family as one of the rod at its parameters
    /// ([`NikolaiRod::rod_at`]), e.g. for [`super::Equilibrium::new`].
    #[must_use]
    pub fn restrict(&self, solution: &Solution) -> (Rod, Solution) {
        let rod = self.rod_at(solution.parameters());
        let mut s = solution.clone();
        s.p = self.rod_parameters(&s.p).to_vec();
        (rod, s)
    }
}

/// A and C at B, A/B, ν (Nikolai).
fn stiffness_at(b: f64, a_over_b: f64, nu: f64) -> (f64, f64) {
    let a = a_over_b * b;
    (a, 2.0 * a * b / ((1.0 + nu) * (a + b)))
}

impl Problem for NikolaiRod {
    fn dim(&self) -> usize {
        Rod::DIM
    }

    fn parameter_count(&self) -> usize {
        Self::PARAMETERS
    }

    fn boundary_count(&self) -> usize {
        self.rod.boundary_count()
    }

    fn integral_count(&self) -> usize {
        self.rod.integral_count()
    }

    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        self.rod_at(p).rhs(s, y, &self.rod_parameters(p), f);
    }

    fn rhs_jacobian(
        &self,
        s: f64,
        y: &[f64],
        p: &[f64],
        dfdy: DMatrixViewMut<'_, f64>,
        mut dfdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        let rod = self.rod_at(p);
        if !rod.rhs_jacobian(
            s,
            y,
            &self.rod_parameters(p),
            dfdy,
            dfdp.columns_mut(0, Rod::PARAMETERS),
        ) {
            return false;
        }
        let (a, b, c, nu) = (rod.a, rod.b, rod.c, p[Self::NU]);
        let q = &y[3..7];
        let mm = rot(q).transpose() * Vector3::new(y[10], y[11], y[12]);
        let (du_da, du_dc) = (-mm.x / (a * a), -mm.z / (c * c));
        let dc_da = 2.0 * b * b / ((1.0 + nu) * (a + b) * (a + b));
        let dc_dnu = -c / (1.0 + nu);
        // ∂u/∂ln(A/B) = A (∂u/∂A + ∂C/∂A ∂u/∂C), ∂u/∂ν = ∂C/∂ν ∂u/∂C
        let du_ratio = Vector3::new(a * du_da, 0.0, a * dc_da * du_dc);
        let du_nu = Vector3::new(0.0, 0.0, dc_dnu * du_dc);
        let l = l_matrix(q);
        for (i, li) in l.iter().enumerate() {
            dfdp[(3 + i, Self::LN_A_OVER_B)] = 0.5 * (li[0] * du_ratio.x + li[2] * du_ratio.z);
            dfdp[(3 + i, Self::NU)] = 0.5 * li[2] * du_nu.z;
        }
        for i in (0..3).chain(7..Rod::DIM) {
            dfdp[(i, Self::LN_A_OVER_B)] = 0.0;
            dfdp[(i, Self::NU)] = 0.0;
        }
        true
    }

    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        self.rod.boundary(y0, y1, &self.rod_parameters(p), g);
    }

    fn boundary_jacobian(
        &self,
        y0: &[f64],
        y1: &[f64],
        p: &[f64],
        dg0: DMatrixViewMut<'_, f64>,
        dg1: DMatrixViewMut<'_, f64>,
        mut dgp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        dgp.columns_mut(Rod::PARAMETERS, 2).fill(0.0);
        let analytic = self.rod.boundary_jacobian(
            y0,
            y1,
            &self.rod_parameters(p),
            dg0,
            dg1,
            dgp.columns_mut(0, Rod::PARAMETERS),
        );
        let scale = self.scale();
        dgp.column_mut(Self::FORCE_SCALED).scale_mut(scale);
        analytic
    }

    fn integrand(&self, s: f64, y: &[f64], y_ref: &[f64], p: &[f64], h: &mut [f64]) {
        self.rod.integrand(s, y, y_ref, &self.rod_parameters(p), h);
    }

    fn integrand_jacobian(
        &self,
        s: f64,
        y: &[f64],
        y_ref: &[f64],
        p: &[f64],
        dhdy: DMatrixViewMut<'_, f64>,
        mut dhdp: DMatrixViewMut<'_, f64>,
    ) -> bool {
        dhdp.columns_mut(Rod::PARAMETERS, 2).fill(0.0);
        self.rod.integrand_jacobian(
            s,
            y,
            y_ref,
            &self.rod_parameters(p),
            dhdy,
            dhdp.columns_mut(0, Rod::PARAMETERS),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∂f/∂(A/B) and ∂f/∂ν against central differences of f.
    #[test]
    fn stiffness_columns_are_the_derivatives_of_the_rhs() {
        let rod = Rod::new(4, 1.3, Stiffness::nikolai(7.0, 0.2).unwrap()).unwrap();
        let fam = NikolaiRod::new(rod, 0.2).unwrap();
        let y = [
            0.1, 0.2, 0.3, 0.5, -0.3, 0.6, 0.2, 1.0, -2.0, 3.0, 0.7, -0.4, 0.9,
        ];
        let p = [0.01, 0.5, 1.3, 7_f64.ln(), 0.2];
        let mut dfdy = nalgebra::DMatrix::zeros(13, 13);
        let mut dfdp = nalgebra::DMatrix::from_element(13, 5, f64::NAN);
        assert!(fam.rhs_jacobian(0.3, &y, &p, dfdy.as_view_mut(), dfdp.as_view_mut()));
        for k in [NikolaiRod::LN_A_OVER_B, NikolaiRod::NU] {
            let h = 1e-6;
            let (mut pp, mut pm) = (p, p);
            pp[k] += h;
            pm[k] -= h;
            let (mut fp, mut fm) = ([0.0; 13], [0.0; 13]);
            fam.rhs(0.3, &y, &pp, &mut fp);
            fam.rhs(0.3, &y, &pm, &mut fm);
            for i in 0..13 {
                let d = (fp[i] - fm[i]) / (2.0 * h);
                // central difference: O(h²) ≈ 1e-12 times the third
                // derivative (O(1) here) plus rounding ε/h ≈ 1e-10
                assert!(
                    (dfdp[(i, k)] - d).abs() < 1e-8,
                    "row {i} column {k}: {} vs {d}",
                    dfdp[(i, k)]
                );
            }
        }
    }
}
