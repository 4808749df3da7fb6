//! The integral inner product of the continuation (module docs):
//!
//! ```text
//!   ⟨a, b⟩ = Σ_i w_i ∫₀¹ a_i(s) b_i(s) ds + θ Σ_q a_q b_q
//! ```
//!
//! over the solution components i and the free parameters q (the solver's
//! and λ), the integrals by the Gauss rule of the collocation: on a mesh of
//! widths h_j with Gauss weights b_k it is Σ_r W_r a_r b_r over the values
//! a_r = a_i(s_jk) at the collocation points, W_r = h_j b_k w_i. The one
//! place this product is written: the corrector's border row, the tangent
//! normalisation, the angle check and [`Continuation::distance`] all use
//! [`IntegralNorm`].

use super::{Continuation, Steps};
use crate::bvp::system::State;
use crate::bvp::{Problem, Solution};
use crate::error::{Error, Result};

/// The quadrature weights W_r of the integral inner product on one mesh, and
/// the parameter weight θ.
#[derive(Debug, Clone)]
pub(super) struct IntegralNorm {
    quadrature: Vec<f64>,
    theta: f64,
}

impl IntegralNorm {
    /// W_r = h_j b_k w_i for r = (j m + k) n + i, the layout of the
    /// collocation values.
    pub(super) fn new(
        widths: impl Iterator<Item = f64>,
        gauss: &[f64],
        weights: &[f64],
        theta: f64,
    ) -> Self {
        let mut quadrature = Vec::new();
        for h in widths {
            for bk in gauss {
                let w = h * bk;
                quadrature.extend(weights.iter().map(|wi| w * wi));
            }
        }
        IntegralNorm { quadrature, theta }
    }

    /// The solution part Σ_r W_r a_r b_r of ⟨a, b⟩ (collocation values).
    pub(super) fn values(&self, a: &[f64], b: &[f64]) -> f64 {
        let mut s = 0.0;
        for ((w, x), y) in self.quadrature.iter().zip(a).zip(b) {
            s += w * x * y;
        }
        s
    }

    /// ⟨a, b⟩ from the collocation values and the parameters, summed over
    /// the parameters `free`.
    pub(super) fn inner(
        &self,
        (a, ap): (&[f64], &[f64]),
        (b, bp): (&[f64], &[f64]),
        free: &[usize],
    ) -> f64 {
        let mut s = self.values(a, b);
        for &q in free {
            s += self.theta * ap[q] * bp[q];
        }
        s
    }

    /// The border row ⟨·, t⟩: coefficients W_r t_r of the collocation
    /// values into `coef_y`, θ t_q of the parameters `free` into `coef_q`.
    pub(super) fn row(
        &self,
        (t, tp): (&[f64], &[f64]),
        free: &[usize],
        coef_y: &mut [f64],
        coef_q: &mut [f64],
    ) {
        for ((c, w), v) in coef_y.iter_mut().zip(&self.quadrature).zip(t) {
            *c = w * v;
        }
        for (c, &q) in coef_q.iter_mut().zip(free) {
            *c = self.theta * tp[q];
        }
    }

    /// ‖a − b‖ from the collocation values and the parameters `free`.
    pub(super) fn distance(
        &self,
        (a, ap): (&[f64], &[f64]),
        (b, bp): (&[f64], &[f64]),
        free: &[usize],
    ) -> f64 {
        let mut s = 0.0;
        for ((w, x), y) in self.quadrature.iter().zip(a).zip(b) {
            let d = x - y;
            s += w * (d * d);
        }
        for &q in free {
            let d = ap[q] - bp[q];
            s += self.theta * (d * d);
        }
        s.sqrt()
    }
}

impl Continuation {
    /// The distance ‖a − b‖ of two solutions in this continuation's norm
    /// (module docs: weights w_i, θ on the solver's free parameters and λ),
    /// integrals by the Gauss rule of the solver, so that it measures
    /// arclength the way [`Point::arclength`](super::Point::arclength) does (e.g. to join a point
    /// computed before the run to the branch).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] or [`Error::InvalidCount`] unless both
    /// solutions have the dimension of the weights, the solver's points per
    /// interval, and the same mesh; bad settings as [`Continuation::steps`].
    pub fn distance(&self, a: &Solution, b: &Solution) -> Result<f64> {
        let n = a.dim();
        self.validate(n, a.parameters().len())?;
        let tab = self.solver.validate()?;
        if b.dim() != n || b.parameters().len() != a.parameters().len() {
            return Err(Error::LengthMismatch {
                name: "solution dimension",
                found: b.dim() as u64,
                expected: n as u64,
            });
        }
        for s in [a, b] {
            if s.points_per_interval() != tab.m || s.mesh() != a.mesh() {
                return Err(Error::InvalidCount {
                    name: "points per interval",
                    value: s.points_per_interval() as u64,
                    allowed: "the solver's m, on the same mesh for both solutions",
                });
            }
        }
        let mesh = a.mesh();
        let weights = self.weights.clone().unwrap_or_else(|| vec![1.0; n]);
        let norm = IntegralNorm::new(
            (0..mesh.intervals()).map(|j| mesh.width(j)),
            &tab.b,
            &weights,
            self.parameter_weight,
        );
        let mut free = self.solver.free().to_vec();
        free.push(self.parameter);
        let (ya, yb) = (a.collocation_values(), b.collocation_values());
        Ok(norm.distance(
            (ya.as_slice(), a.parameters()),
            (yb.as_slice(), b.parameters()),
            &free,
        ))
    }
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// ⟨a, b⟩ of two states on the run's mesh.
    pub(super) fn inner(&mut self, a: &State, b: &State) -> f64 {
        self.sys.collocation_values(a, &mut self.ycol_a);
        self.sys.collocation_values(b, &mut self.ycol_b);
        self.norm
            .inner((&self.ycol_a, &a.p), (&self.ycol_b, &b.p), &self.sys.free)
    }

    /// ‖a‖.
    pub(super) fn norm(&mut self, a: &State) -> f64 {
        self.inner(a, a).sqrt()
    }
}
