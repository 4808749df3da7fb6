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

    /// ‖a − b‖ from the collocation values and the parameters `free`,
    /// computed scaled so that no intermediate overflows or underflows: with
    /// T a power of two ≥ max |a_r − b_r|, ‖a − b‖ = T (Σ W_r ((a_r −
    /// b_r)/T)²)^½ (the division is exact). If a difference itself
    /// overflows (|a_r|, |b_r| near the largest double), the values are
    /// halved first. `None` if the distance is beyond the largest double
    /// or a value is not finite.
    pub(super) fn distance(
        &self,
        (a, ap): (&[f64], &[f64]),
        (b, bp): (&[f64], &[f64]),
        free: &[usize],
    ) -> Option<f64> {
        let pairs = || {
            let values = self.quadrature.iter().zip(a).zip(b);
            let values = values.map(|((w, x), y)| (*w, *x, *y));
            let params = free.iter().map(|&q| (self.theta, ap[q], bp[q]));
            values.chain(params)
        };
        if pairs().any(|(_, x, y)| !x.is_finite() || !y.is_finite()) {
            return None;
        }
        let largest = |h: f64| pairs().fold(0.0_f64, |m, (_, x, y)| m.max((h * x - h * y).abs()));
        let (h, dmax) = match largest(1.0) {
            d if d.is_finite() => (1.0, d),
            _ => (0.5, largest(0.5)),
        };
        if dmax == 0.0 {
            return Some(0.0);
        }
        let t = power_of_two_at_least(dmax);
        let sum: f64 = pairs()
            .map(|(w, x, y)| {
                let d = (h * x - h * y) / t;
                w * (d * d)
            })
            .sum();
        let dist = sum.sqrt() * t / h;
        dist.is_finite().then_some(dist)
    }
}

/// A power of two ≥ x (x finite and positive; 2¹⁰²³ for x above it): the
/// smallest one, up to the rounding of log₂.
fn power_of_two_at_least(x: f64) -> f64 {
    let e = (x.log2().ceil() as i32).clamp(-1074, 1023);
    let p = if e >= -1022 {
        f64::from_bits(((e + 1023) as u64) << 52)
    } else {
        f64::from_bits(1_u64 << (e + 1074))
    };
    if p < x && e < 1023 { 2.0 * p } else { p }
}

impl Continuation {
    /// The distance ‖a − b‖ of two solutions in this continuation's norm
    /// (module docs: weights w_i, θ on the solver's free parameters and λ),
    /// integrals by the Gauss rule of the solver, so that it measures
    /// arclength the way [`Point::arclength`](super::Point::arclength) does (e.g. to join a point
    /// computed before the run to the branch).
    ///
    /// The sum is scaled (the differences divided by a power of two above
    /// the largest), so it is finite for every pair of finite solutions
    /// whose distance is a double, and as accurate for solutions of size
    /// 1e300 as of size 1.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] or [`Error::InvalidCount`] unless both
    /// solutions have the dimension of the weights, the solver's points per
    /// interval, and the same mesh; [`Error::Overflow`] if the distance is
    /// beyond the largest double (or a value is not finite); bad settings as
    /// [`Continuation::steps`].
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
        norm.distance(
            (ya.as_slice(), a.parameters()),
            (yb.as_slice(), b.parameters()),
            &free,
        )
        .ok_or_else(|| Error::Overflow {
            quantity: "distance ‖a − b‖",
            name: "largest |component| of a and b",
            value: ya
                .iter()
                .chain(yb.iter())
                .chain(a.parameters())
                .chain(b.parameters())
                .fold(0.0, |m: f64, v| m.max(v.abs())),
        })
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
