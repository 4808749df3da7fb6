//! The plane of the bifurcation diagram, in which a tolerance is measured:
//! a point of the branch is (σ_λ λ, σ_g g(y, p)) for one output g of the
//! solution, and the tolerance bounds the max-norm distance in this plane
//! between the computed curve (points and their cubic Hermite interpolant)
//! and the exact one.
//!
//! The cubic Hermite interpolant between two points P₀, P₁ with slopes
//! T₀, T₁ (d/ds, s the arclength) over a step h has the third derivative
//!
//! ```text
//!   P''' = 6 (2 (P₀ − P₁) + h (T₀ + T₁)) / h³
//! ```
//!
//! and its interpolation error is at most h⁴ ‖P''''‖ / 384. The fourth
//! derivative is estimated by the change of P''' between successive steps,
//! divided by the mean of their lengths: an estimate of the same order as
//! the error it bounds.

use super::norm::IntegralNorm;
use crate::bvp::system::State;
use crate::error::{Error, Result};

/// The output g of a solution plotted against λ (the vertical axis of a
/// bifurcation diagram).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Output {
    /// The continuation's integral norm of y, ⟨y, y⟩^½ without the
    /// parameters (AUTO's L2-norm diagram). The default.
    Norm,
    /// One component of y at an end: s = 0 (`right = false`) or s = 1.
    EndValue {
        /// Index into y.
        component: usize,
        /// The end s = 1 (otherwise s = 0).
        right: bool,
    },
    /// A parameter (one of the solver's free parameters, or a fixed one).
    Parameter(usize),
}

/// The plane of the diagram: the output and the scales σ_λ, σ_g of its two
/// axes (see [`Continuation::diagram`](super::Continuation::diagram)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Diagram {
    pub(super) output: Output,
    pub(super) lambda_scale: f64,
    pub(super) output_scale: f64,
}

impl Default for Diagram {
    fn default() -> Self {
        Diagram {
            output: Output::Norm,
            lambda_scale: 1.0,
            output_scale: 1.0,
        }
    }
}

impl Diagram {
    pub(super) fn validate(&self, n: usize, np: usize) -> Result<()> {
        match self.output {
            Output::EndValue { component, .. } if component >= n => {
                return Err(Error::InvalidCount {
                    name: "diagram output component",
                    value: component as u64,
                    allowed: "an index below the problem's dim()",
                });
            }
            Output::Parameter(i) if i >= np => {
                return Err(Error::InvalidCount {
                    name: "diagram output parameter",
                    value: i as u64,
                    allowed: "an index below the problem's parameter_count()",
                });
            }
            _ => {}
        }
        for (name, v) in [
            ("diagram lambda scale", self.lambda_scale),
            ("diagram output scale", self.output_scale),
        ] {
            if !(v > 0.0 && v.is_finite()) {
                return Err(Error::InvalidArgument {
                    name,
                    value: v,
                    allowed: "finite and > 0",
                });
            }
        }
        Ok(())
    }

    /// The point (σ_λ λ, σ_g g) of `x` and its slope along the tangent `t`;
    /// `xcol`, `tcol` are their collocation values (used by
    /// [`Output::Norm`]).
    pub(super) fn point_and_slope(
        &self,
        parameter: usize,
        n: usize,
        (x, xcol): (&State, &[f64]),
        (t, tcol): (&State, &[f64]),
        norm: &IntegralNorm,
    ) -> ([f64; 2], [f64; 2]) {
        let (g, dg) = match self.output {
            Output::Norm => {
                let g = norm.values(xcol, xcol).max(0.0).sqrt();
                let dg = if g > 0.0 {
                    norm.values(xcol, tcol) / g
                } else {
                    0.0
                };
                (g, dg)
            }
            Output::EndValue { component, right } => {
                let j = if right { x.y.len() / n - 1 } else { 0 };
                (x.y[j * n + component], t.y[j * n + component])
            }
            Output::Parameter(i) => (x.p[i], t.p[i]),
        };
        (
            [self.lambda_scale * x.p[parameter], self.output_scale * g],
            [self.lambda_scale * t.p[parameter], self.output_scale * dg],
        )
    }
}

/// The third derivative P''' of the cubic Hermite interpolant of one step
/// (module docs), per axis.
pub(super) fn hermite_third(
    p0: [f64; 2],
    t0: [f64; 2],
    p1: [f64; 2],
    t1: [f64; 2],
    h: f64,
) -> [f64; 2] {
    let d = |i: usize| 6.0 * (2.0 * (p0[i] - p1[i]) + h * (t0[i] + t1[i])) / (h * h * h);
    [d(0), d(1)]
}

/// The interpolation error estimate 3 h⁴ |ΔP'''·n| / (384 h̄) of a step of
/// length `h` whose P''' is `third`, after (or before) a step of length
/// `h_prev` whose P''' was `third_prev` (h̄ the mean length), with ΔP'''
/// in the direction of a unit `normal` if given (an error along the curve
/// moves the interpolant's parametrisation, not its trace), its max-norm
/// otherwise: three times the bound with the difference quotient for
/// P'''', which lags the step by half a step (measured in
/// `tests/rod/tolerance.rs`: the bound alone fell 1.3 times short of the
/// true error on a spring at θ0 = 60°, twice it 1.04 times on the paper's
/// spring at 1e-6).
pub(super) fn hermite_error(
    third: [f64; 2],
    third_prev: [f64; 2],
    h: f64,
    h_prev: f64,
    normal: Option<[f64; 2]>,
) -> f64 {
    let d = [third[0] - third_prev[0], third[1] - third_prev[1]];
    let jump = match normal {
        Some(n) => (d[0] * n[0] + d[1] * n[1]).abs(),
        None => d[0].abs().max(d[1].abs()),
    };
    3.0 * h.powi(4) * jump / (384.0 * 0.5 * (h + h_prev))
}

/// The cubic Hermite interpolant of a step at τ ∈ [0, 1].
pub(super) fn hermite_at(
    (p0, t0): ([f64; 2], [f64; 2]),
    (p1, t1): ([f64; 2], [f64; 2]),
    h: f64,
    tau: f64,
) -> [f64; 2] {
    let h00 = 2.0 * tau.powi(3) - 3.0 * tau * tau + 1.0;
    let h10 = tau.powi(3) - 2.0 * tau * tau + tau;
    let h01 = -2.0 * tau.powi(3) + 3.0 * tau * tau;
    let h11 = tau.powi(3) - tau * tau;
    let at = |i: usize| h00 * p0[i] + h10 * h * t0[i] + h01 * p1[i] + h11 * h * t1[i];
    [at(0), at(1)]
}

/// The distance from the point `p` of the branch, whose slope is `t`, to
/// the interpolant's point `q`, across the branch (along `t` it is a
/// shift of the parametrisation): |(q − p) × t̂|, or the max-norm when
/// `t` vanishes.
pub(super) fn across(p: [f64; 2], t: [f64; 2], q: [f64; 2]) -> f64 {
    let d = [q[0] - p[0], q[1] - p[1]];
    let len = t[0].hypot(t[1]);
    if len > 0.0 && len.is_finite() {
        (d[0] * t[1] - d[1] * t[0]).abs() / len
    } else {
        d[0].abs().max(d[1].abs())
    }
}

/// Whether the cubic Hermite interpolant of one axis over a step, from
/// (p0, slope d0) to (p1, d1) over the length h, turns back twice inside
/// the step by more than `amplitude`: the trace of a pair of folds that
/// one step passed over (with end slopes of one sign, a cubic whose secant
/// is much flatter than its ends must wiggle).
pub(super) fn turns_back_twice(p0: f64, d0: f64, p1: f64, d1: f64, h: f64, amplitude: f64) -> bool {
    let (a, b) = (h * d0, h * d1);
    if a * b <= 0.0 {
        return false;
    }
    let c2 = 3.0 * (p1 - p0) - 2.0 * a - b;
    let c3 = 2.0 * (p0 - p1) + a + b;
    // q(τ) = a + 2 c2 τ + 3 c3 τ²: two roots in (0, 1)?
    let (qa, qb, qc) = (3.0 * c3, 2.0 * c2, a);
    if qa == 0.0 {
        return false;
    }
    let disc = qb * qb - 4.0 * qa * qc;
    if disc <= 0.0 {
        return false;
    }
    let r = disc.sqrt();
    let q = -0.5 * (qb + qb.signum() * r);
    if q == 0.0 {
        return false;
    }
    let (t1, t2) = (q / qa, qc / q);
    let inside = |t: f64| t > 0.0 && t < 1.0;
    if !(inside(t1) && inside(t2)) {
        return false;
    }
    let at = |t: f64| p0 + t * (a + t * (c2 + t * c3));
    (at(t1) - at(t2)).abs() > amplitude
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic is reproduced exactly: P''' is its own third derivative
    /// and the error estimate between two steps on it vanishes.
    #[test]
    fn hermite_of_a_cubic() {
        let p = |s: f64| [s * s * s - 2.0 * s, 0.5 * s * s];
        let dp = |s: f64| [3.0 * s * s - 2.0, s];
        let third = hermite_third(p(0.2), dp(0.2), p(0.7), dp(0.7), 0.5);
        assert!((third[0] - 6.0).abs() < 1e-11 && third[1].abs() < 1e-11);
        let prev = hermite_third(p(-0.1), dp(-0.1), p(0.2), dp(0.2), 0.3);
        assert!(hermite_error(third, prev, 0.5, 0.3, None) < 1e-12);
    }

    /// A step over a hairpin (λ = s − 3 sin(s)… sampled at its ends only)
    /// is recognised; a monotone step is not.
    #[test]
    fn fold_pair_trace() {
        // λ(s) = s³ − s on [−1.2, 1.2]: slopes 3.32 at both ends, folds at ±0.577
        let (p0, p1, d) = (
            -1.2_f64.powi(3) + 1.2,
            1.2_f64.powi(3) - 1.2,
            3.0 * 1.44 - 1.0,
        );
        assert!(turns_back_twice(p0, d, p1, d, 2.4, 1e-3));
        // λ(s) = s³ + s: monotone
        assert!(!turns_back_twice(
            -1.2_f64.powi(3) - 1.2,
            5.32,
            1.2_f64.powi(3) + 1.2,
            5.32,
            2.4,
            1e-3
        ));
    }

    /// On sin, the estimate is above the true maximum interpolation error
    /// h⁴/384 · max|sin''''|, and within a factor 6 of it.
    #[test]
    fn hermite_error_of_sine() {
        let h = 0.2;
        let at = |s: f64| ([s.sin(), 0.0], [s.cos(), 0.0]);
        let (a, da) = at(1.0);
        let (b, db) = at(1.0 + h);
        let (c, dc) = at(1.0 + 2.0 * h);
        let e = hermite_error(
            hermite_third(b, db, c, dc, h),
            hermite_third(a, da, b, db, h),
            h,
            h,
            None,
        );
        let truth = h.powi(4) / 384.0 * (1.2_f64).sin();
        assert!(e > truth && e < 6.0 * truth, "{e} vs {truth}");
    }
}
