//! The second derivative x'' of the branch at a point, and the point's jet
//! (P, P', P'') in the diagram's plane: the data of the quintic
//! interpolant of a step (`hermite.rs`).
//!
//! Differentiating F(x(s)) = 0 twice along the arclength s gives
//!
//! ```text
//!   F_x x'' = −F_xx[x', x'],      ⟨x', x''⟩ = 0
//! ```
//!
//! (the second from ⟨x', x'⟩ = 1). The first, bordered by the system's
//! current border row b, [F_x; b] z = [−F_xx[x', x']; 0], is solved by
//! iterative refinement preconditioned by the current factorisation (the
//! corrector's, at or next to x), with F_x z and F_xx[x', x'] by central
//! differences; z differs from x'' by a multiple of x' (F_x x' = 0), so
//! x'' = z − ⟨z, x'⟩ x'. When the refinement does not contract, [F_x; b]
//! is factored at x and the solve is direct.

use super::Steps;
use super::hermite::{Degree, Jet};
use crate::bvp::Problem;
use crate::bvp::scaled_norm;
use crate::bvp::system::State;

/// Relative correction at which the refinement of z stops: the
/// difference quotients carry about 1e-8 (`difference.rs`). With a
/// tolerance it stops at 1e-2 tol when that is larger: a relative error δ
/// in P'' (the diagram's coordinates are O(1) functionals of the state)
/// moves a step's quintic by at most max τ²(1 − τ)³/2 · h²δ(1 + |P''|)
/// ≈ 0.02 h²δ(1 + |P''|), and steps (h ≤ 1) turn by less than their
/// maximum angle (h|P''| < 1), so the interpolant moves by about 1e-3 tol
/// or less.
const REFINED: f64 = 1e-8;

/// Relative correction above which the refinement is abandoned for a
/// direct solve on a new factorisation.
const UNREFINED: f64 = 1e-5;

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// x'' at `x` with unit tangent `t` (module docs); `None` when neither
    /// the refinement nor a new factorisation gives it.
    pub(super) fn second_derivative(&mut self, x: &State, t: &State) -> Option<State> {
        let free = self.sys.free.clone();
        let mut work = self.difference(x);
        self.residual_second_derivative(x, t, &mut work).ok()?;
        let w = work.out.clone();
        let mut z = self.sys.zero_state();
        let mut d = self.sys.zero_state();
        // (the solver returns −J⁻¹ r)
        self.sys.solve(&w, &mut z).ok()?;
        let refined = self
            .cont
            .tolerance
            .map_or(REFINED, |tol| (1e-2 * tol).max(REFINED));
        let mut last = f64::INFINITY;
        for _ in 0..6 {
            self.residual_derivative(x, &z, &mut work).ok()?;
            for (r, v) in work.out.rows_mut().zip(w.rows()) {
                *r += v;
            }
            self.sys.solve(&work.out, &mut d).ok()?;
            let nd = scaled_norm(&d, &z, &free);
            if nd > 0.25 * last {
                break;
            }
            z.axpy(1.0, &d, &free);
            last = nd;
            if nd <= refined {
                break;
            }
        }
        if last > UNREFINED.max(refined) {
            self.sys.factor(x).ok()?;
            self.sys.solve(&w, &mut z).ok()?;
        }
        let along = self.inner(&z, t);
        z.axpy(-along, t, &free);
        Some(z)
    }

    /// The jet (P, P', P'') of `x` with unit tangent `t` in the diagram's
    /// plane; P'' is NaN when x'' cannot be had, and not computed (NaN)
    /// for a run whose interpolant is the cubic (`hermite::CUBIC_FROM`).
    pub(super) fn jet(&mut self, x: &State, t: &State) -> Jet {
        let (point, slope) = self.diagram_of(x, t);
        let mut bend = f64::NAN;
        let second = match self.degree() {
            Degree::Quintic => self.second_derivative(x, t),
            Degree::Cubic => None,
        };
        let curvature = match second {
            Some(a) => {
                bend = self.inner(&a, &a);
                let diagram = &self.cont.diagram;
                let (xcol, tcol, acol) = (
                    diagram.values(&self.sys, x),
                    diagram.values(&self.sys, t),
                    diagram.values(&self.sys, &a),
                );
                diagram.curvature(
                    self.cont.parameter,
                    self.sys.n,
                    (x, &xcol),
                    &tcol,
                    (&a, &acol),
                    &self.norm,
                )
            }
            None => [f64::NAN; 2],
        };
        Jet {
            point,
            slope,
            curvature,
            bend,
        }
    }
}
