//! The plane of the bifurcation diagram, in which a tolerance is measured:
//! a point of the branch is (σ_λ λ, σ_g g(y, p)) for one output g of the
//! solution, and the tolerance bounds the max-norm distance in this plane
//! between the computed curve (points and their Hermite interpolant, see
//! `hermite.rs`) and the exact one. Here: the point of a solution, its
//! slope P' along a tangent x' and its curvature P'' along (x', x'').

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
    /// The collocation values of a state that [`point_and_slope`](Self::point_and_slope)
    /// and [`curvature`](Self::curvature) read: `len` of them for the
    /// integral norm, none for an end value or a parameter (whose
    /// diagrams read the mesh values and parameters alone: the values were
    /// 3–7 % of a rod's pull with a tolerance, for nothing).
    pub(super) fn values<P: crate::bvp::Problem + ?Sized>(
        &self,
        sys: &crate::bvp::system::System<'_, P>,
        x: &crate::bvp::system::State,
    ) -> Vec<f64> {
        match self.output {
            Output::Norm => {
                let mut v = vec![0.0; sys.y_ref.len()];
                sys.collocation_values(x, &mut v);
                v
            }
            Output::EndValue { .. } | Output::Parameter(_) => Vec::new(),
        }
    }

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

    /// The point of `x` and its slope along `t` on the mesh of `sys`
    /// (normed by `norm`, on the same mesh), λ being parameter `q`:
    /// [`Self::point_and_slope`] with the collocation values taken there.
    pub(super) fn point_and_slope_on<P: crate::bvp::Problem + ?Sized>(
        &self,
        sys: &crate::bvp::system::System<'_, P>,
        norm: &IntegralNorm,
        q: usize,
        x: &State,
        t: &State,
    ) -> ([f64; 2], [f64; 2]) {
        let (xcol, tcol) = (self.values(sys, x), self.values(sys, t));
        self.point_and_slope(q, sys.n, (x, &xcol), (t, &tcol), norm)
    }

    /// How far the change `d` of the state at `x` moves the diagram's point
    /// across the branch whose tangent is `t`, to first order (along the
    /// branch it only moves the point on the curve); on the mesh of `sys`.
    pub(super) fn across_on<P: crate::bvp::Problem + ?Sized>(
        &self,
        sys: &crate::bvp::system::System<'_, P>,
        norm: &IntegralNorm,
        q: usize,
        x: &State,
        (d, t): (&State, &State),
    ) -> f64 {
        let change = self.point_and_slope_on(sys, norm, q, x, d).1;
        let slope = self.point_and_slope_on(sys, norm, q, x, t).1;
        super::hermite::across([0.0; 2], slope, change)
    }

    /// The point (σ_λ λ, σ_g g) of `x` and its slope along the tangent `t`;
    /// `xcol`, `tcol` are their collocation values (used by
    /// [`Output::Norm`]).
    fn point_and_slope(
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

    /// The curvature P'' = d²/ds² (σ_λ λ, σ_g g) along the branch, from the
    /// collocation values `tcol` of the tangent x' and the second
    /// derivative `a` = x'' with its collocation values; for [`Output::Norm`], g = ⟨y, y⟩^½ gives
    /// g'' = (⟨y', y'⟩ + ⟨y, y''⟩ − g'²) / g.
    pub(super) fn curvature(
        &self,
        parameter: usize,
        n: usize,
        (x, xcol): (&State, &[f64]),
        tcol: &[f64],
        (a, acol): (&State, &[f64]),
        norm: &IntegralNorm,
    ) -> [f64; 2] {
        let g2 = match self.output {
            Output::Norm => {
                let g = norm.values(xcol, xcol).max(0.0).sqrt();
                if g > 0.0 {
                    let dg = norm.values(xcol, tcol) / g;
                    (norm.values(tcol, tcol) + norm.values(xcol, acol) - dg * dg) / g
                } else {
                    0.0
                }
            }
            Output::EndValue { component, right } => {
                let j = if right { x.y.len() / n - 1 } else { 0 };
                a.y[j * n + component]
            }
            Output::Parameter(i) => a.p[i],
        };
        [self.lambda_scale * a.p[parameter], self.output_scale * g2]
    }
}
