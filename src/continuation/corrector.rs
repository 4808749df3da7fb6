//! The corrector: chord Newton on the bordered system, the new tangent and
//! the determinant sign.

use super::Steps;
use super::difference::{Difference, derivative_on};
use super::norm::IntegralNorm;
use crate::bvp::system::{State, System};
use crate::bvp::{NewtonStats, Problem, newton, newton_pinned, scaled_norm};
use crate::error::{Error, Result};
use crate::linalg::Det;

/// (robust10c) A corrector of a run with a tolerance whose Newton stalls
/// (damping cannot reduce the correction, or the iterations run out) at a
/// correction within this multiple of its tolerance has reached the
/// rounding floor of its system: the point is kept. The tolerance is
/// 1e-4 tol, so such a point is still within ~1e-2 tol by the same mapping;
/// its noise can only raise the run's estimates (the mesh check and the
/// interpolation compare independent solves), not hide an error.
/// Measured: the rod at ν = −0.5 from F/((2πn)²B) ≈ 8 and n = 16 near its
/// folds stall at 1e-12..1.5e-9 on meshes of 100–500 intervals (the floor
/// grows with the mesh, with either linear solver), where the tolerance is
/// 1e-10 (tol 1e-6): their steps shrank to the minimum and the run failed,
/// and their mesh checks reported ∞ and doubled the mesh to the interval
/// limit (16 min and more for one pull). 10 was not enough for n = 16
/// (1.5e-9 after the quintic dense output).
pub(super) const STUCK_FLOOR: f64 = 100.0;

/// The iterations a point kept at its rounding floor (within
/// [`STUCK_FLOOR`]) counts as in the step control: the iterations Newton
/// spent there went on rounding noise, not on the step's nonlinearity, so
/// they are no reason to shorten the next step (six lets it grow by 1.1,
/// `Steps::adapt_step`; the angle and interpolation guards still bound it).
/// Counted as the most iterations, as before, each such point halved the
/// step, and where the floor persists the run crawled at the shortest
/// step: n = 4 at (89.5°, A/B = 10, ν = −0.2) stretched to Δz = 0.99, where
/// past the third maximum force the loops left in the rod are nearly free
/// to slide and Newton's fresh corrections stall at 1e-9 relative (the
/// tolerance 1e-10, contractions 0.5–0.9), crawled at Δs = 1e-7 for 2000
/// steps without getting through; now it passes in 418 steps, and at 89.7°
/// and 89.8° in 528 and 650 (docs/ACCURACY.md, "Stretched").
const FLOOR_ITERATIONS: u32 = 6;

/// Beyond [`STUCK_FLOOR`]: a corrector whose Newton stalls at the shortest
/// step, where the run would otherwise fail, at a relative correction of at
/// most this (a rounding floor of a system whose condition number reaches
/// ~1e10) keeps its point when that correction would move
/// the point across the branch in the diagram's plane by at most
/// [`STALLED_ACROSS`] of the run's tolerance; that distance is added to the
/// run's estimate ([`ErrorEstimate::stalled`]). A floor, not a multiple of
/// the Newton tolerance: at tol 1e-4 (Newton's 1e-8) ten thousand times it
/// let a pull to F/((2πn)²B) = 1e10 keep a point with Δz > 1 near 1e9.
/// Measured (29 Nov, tol 1e-6, so a Newton tolerance of 1e-10): the rod with
/// A/B = 100 at ν = 0.05 past its last pop-outs, the loops left in the rod
/// under tension nearly free to slide (n = 6 at θ0 = 89.5° from
/// F/((2πn)²B) ≈ 7.15, n = 8 there, n = 7 at 89.5° and 89.8°), stalls at
/// corrections of 1.7e-8 … 5e-7, which would move the point 1.2e-7 … 5e-7
/// along the curve and at most 3.8e-10 across it; the pulls to F/((2πn)²B) = 30 failed there. With
/// this rule n = 8 at 89.5° reaches 30 with its seven pop-outs (its
/// estimate, 2.1e-4, says the tolerance is not met); n = 6 at 89.5° fails a
/// little further on, where Newton diverges at the shortest step. Kept at
/// every step length (tried), such points let n = 6 and 8 meet 1e-6 but
/// the paper's spring at ν = −0.5 slide its loops into the halved-mesh
/// checks (estimate 1e-4 by step 136, not ≤ 4e-6) and n = 16 crawl past
/// its folds for over 15 minutes: only where the run would otherwise fail.
///
/// [`ErrorEstimate::stalled`]: super::ErrorEstimate::stalled
pub(super) const STALLED_FLOOR: f64 = 1e-6;

/// The largest distance across the branch in the diagram's plane, as a
/// fraction of the run's tolerance, that the correction left where Newton
/// stalled between [`STUCK_FLOOR`] times its tolerance and
/// [`STALLED_FLOOR`] may move the point, for the point to be kept: what the
/// tolerance can spare beside the mesh and interpolation errors, as for
/// [`PINNED_ACROSS`].
pub(super) const STALLED_ACROSS: f64 = 0.25;

/// With a tolerance, the most a corrected point pinned along near-null
/// modes ([`crate::bvp::newton_pinned`]) may lie across the branch from
/// the equilibrium its modes would slide to, to first order, as a fraction
/// of the tolerance; a farther point is rejected
/// ([`Error::SlideNotNegligible`]) and the step shortened. The distances
/// accepted are added to the run's estimate ([`ErrorEstimate::pinned`]),
/// so the budget is what the tolerance can spare beside the mesh and
/// interpolation errors, which the estimates overstate about twofold
/// (docs/ACCURACY.md). Measured on the rod with loops sliding (ν = −0.5,
/// n = 4, F/((2πn)²B) = 8–11, tol 1e-6): 8e-9 to 1.4e-7 across, while the
/// pinned part itself moved the point up to 1.6e-4 along the branch.
///
/// [`ErrorEstimate::pinned`]: super::ErrorEstimate::pinned
pub(super) const PINNED_ACROSS: f64 = 0.25;

/// Whether a Newton failure is a stall (damping could not reduce the
/// correction, or the iterations ran out), not a failed evaluation.
pub(super) fn stalled(e: &Error) -> bool {
    matches!(
        e,
        Error::NewtonDiverged { .. } | Error::NewtonNotConverged { .. }
    )
}

/// Sets the border row of `sys` to the hyperplane ⟨· − x, t⟩ = ds of the
/// integral norm `norm` (on the system's mesh); `xcol`, `tcol` are work
/// buffers for the collocation values.
pub(super) fn set_hyperplane<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    norm: &IntegralNorm,
    (x, t): (&State, &State),
    ds: f64,
    (xcol, tcol): (&mut [f64], &mut [f64]),
) {
    sys.collocation_values(t, tcol);
    sys.collocation_values(x, xcol);
    let border = &mut sys.border;
    norm.row(
        (tcol, &t.p),
        &sys.free,
        &mut border.coef_y,
        &mut border.coef_q,
    );
    let mut target = ds;
    for (c, v) in border.coef_y.iter().zip(xcol.iter()) {
        target += c * v;
    }
    for (c, &q) in border.coef_q.iter().zip(&sys.free) {
        target += c * x.p[q];
    }
    border.target[0] = target;
}

/// Solves J τ = e_border with the current factorisation of `sys` (the
/// tangent of a bordered system, unnormalised).
pub(super) fn border_rhs_solution<P: Problem + ?Sized>(sys: &mut System<'_, P>) -> Result<State> {
    let mut r = sys.zero_residual();
    let nd = r.dense.len();
    r.dense[nd - 1] = -1.0;
    let mut t = sys.zero_state();
    sys.solve(&r, &mut t)?;
    Ok(t)
}

/// The solution of [F_x(x); b] τ = e (b the border row of `sys`) from
/// `guess` by iterative refinement preconditioned by the current
/// factorisation of `sys` (at or near x), with F_x(x)τ by central
/// differences ([`derivative_on`]): [`Steps::refined_tangent`]'s iteration,
/// on any system of the run. It stops at a correction of a tenth of
/// `enough` (not below 1e-10), or where it stalls (the difference
/// quotient's rounding, about 1e-8 on the rod) if it got within `enough`;
/// `None` otherwise.
pub(super) fn refine_border_solution<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &State,
    guess: State,
    enough: f64,
) -> Option<State> {
    let free = sys.free.clone();
    let mut t = guess;
    let mut work = Difference::on(sys, x);
    let mut d = sys.zero_state();
    let mut prev = f64::INFINITY;
    for _ in 0..8 {
        derivative_on(sys, x, &t, &mut work).ok()?;
        let last = work.out.dense.len() - 1;
        work.out.dense[last] -= 1.0;
        sys.solve(&work.out, &mut d).ok()?;
        let nd = scaled_norm(&d, &t, &free);
        if nd > 0.25 * prev {
            // stalled: t is as good as the difference quotient allows
            return (prev <= enough).then_some(t);
        }
        t.axpy(1.0, &d, &free);
        if nd <= (0.1 * enough).max(1e-10) {
            return Some(t);
        }
        prev = nd;
    }
    (prev <= enough).then_some(t)
}

/// A corrected point with its tangent and determinant (internal).
pub(super) struct Corrected {
    pub(super) x: State,
    pub(super) tangent: State,
    pub(super) det: Det,
    pub(super) iterations: u32,
    /// Whether Newton stopped at its rounding floor above its tolerance
    /// and the point was kept there (`stuck`).
    pub(super) at_floor: bool,
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// Border row e_λᵀ (target irrelevant: only used for the first tangent).
    pub(super) fn set_parameter_border(&mut self) {
        let b = &mut self.sys.border;
        b.coef_y.fill(0.0);
        b.coef_q.fill(0.0);
        let nq = b.coef_q.len();
        b.coef_q[nq - 1] = 1.0;
        b.target[0] = 0.0;
    }

    /// Border row ⟨· − x₀, τ₀⟩ = ds.
    pub(super) fn set_tangent_border(&mut self, ds: f64) {
        set_hyperplane(
            &mut self.sys,
            &self.norm,
            (&self.x0, &self.t0),
            ds,
            (&mut self.ycol_b, &mut self.ycol_a),
        );
    }

    /// The predictor at arclength `ds` from x₀: with a tolerance, the cubic
    /// through the last two points and their tangents, extrapolated
    /// (Hermite basis on the last step, at τ = 1 + ds/h), when the last
    /// step is known and `ds` lies within twice its length h (about a tenth
    /// fewer corrector iterations on the rod); the tangent x₀ + ds τ₀
    /// otherwise.
    pub(super) fn predict(&self, ds: f64) -> State {
        let free = &self.sys.free;
        let mut x = self.x0.clone();
        match &self.previous {
            Some((xp, tp, h)) if self.cont.tolerance.is_some() && ds > 0.0 && ds <= 2.0 * h => {
                let tau = 1.0 + ds / h;
                let h00 = 2.0 * tau.powi(3) - 3.0 * tau * tau + 1.0;
                let h10 = tau.powi(3) - 2.0 * tau * tau + tau;
                let h01 = -2.0 * tau.powi(3) + 3.0 * tau * tau;
                let h11 = tau.powi(3) - tau * tau;
                x.scale(h01);
                x.axpy(h00, xp, free);
                x.axpy(h10 * h, tp, free);
                x.axpy(h11 * h, &self.t0, free);
                // the parameters that are not free stay as they are
                for (i, v) in x.p.iter_mut().enumerate() {
                    if !free.contains(&i) {
                        *v = self.x0.p[i];
                    }
                }
            }
            _ => x.axpy(ds, &self.t0, free),
        }
        x
    }

    /// Solves J τ = e_border with the current factorisation.
    pub(super) fn solve_border_rhs(&mut self) -> Result<State> {
        border_rhs_solution(&mut self.sys)
    }

    /// Corrects from x₀ at arclength `ds` along τ₀; factorises at the
    /// result and computes its tangent and determinant.
    pub(super) fn correct(&mut self, ds: f64, reuse: bool) -> Result<Corrected> {
        self.set_tangent_border(ds);
        let x = self.predict(ds);
        let mut x = x;
        if reuse {
            self.sys.factor_border()?;
        }
        let stats = self.corrector_newton(&mut x, reuse)?;
        self.newton_iterations += u64::from(stats.iterations);
        let at_floor = stats.correction > self.opts.tol;
        if let Some(tol) = self.cont.tolerance
            && self.sys.pinned_modes() > 0
        {
            let across = self.pinned_across(&x)?;
            if across.is_nan() || across > PINNED_ACROSS * tol {
                return Err(Error::SlideNotNegligible {
                    across,
                    allowed: PINNED_ACROSS * tol,
                });
            }
            self.estimate.pinned = self.estimate.pinned.max(across);
        }
        // Without branch-point detection the determinant is not needed: when
        // the chord corrector converged fast on the old factorisation (with
        // a tolerance: on any factorisation it made), keep it and refine the
        // tangent on it instead of factorising again.
        let near = match self.cont.tolerance {
            Some(_) => reuse || stats.jacobians > 0,
            None => reuse && stats.jacobians == 0 && stats.iterations <= 4,
        };
        if !self.cont.branch_points
            && near
            && let Some(mut t) = self.refined_tangent(&x)
        {
            let nrm = self.norm(&t);
            t.scale(1.0 / nrm);
            return Ok(Corrected {
                x,
                tangent: t,
                det: Det {
                    sign: f64::NAN,
                    log_abs: f64::NAN,
                },
                iterations: stats.iterations,
                at_floor,
            });
        }
        let det = self.sys.factor(&x)?;
        let mut t = self.solve_border_rhs()?;
        let nrm = self.norm(&t);
        t.scale(1.0 / nrm);
        Ok(Corrected {
            x,
            tangent: t,
            det,
            iterations: stats.iterations,
            at_floor,
        })
    }

    /// Newton for the corrector from the predicted `x`, and where it
    /// stalls with a tolerance: a point stuck at the rounding floor is kept
    /// ([`Self::stuck`]); otherwise, with
    /// [`pin_slides`](super::Continuation::pin_slides), a pinned system
    /// tries again unpinned from the prediction (its modes may have
    /// stopped being null), and a system with near-null modes at the last
    /// iterate tries again pinned ([`newton_pinned`]), after which the run
    /// pins wherever Newton stalls.
    fn corrector_newton(&mut self, x: &mut State, reuse: bool) -> Result<NewtonStats> {
        // the prediction, kept only where a pinned Newton may retry unpinned
        let predicted = (self.cont.pin_slides && self.sys.is_pinning()).then(|| x.clone());
        let failure = match newton(&mut self.sys, x, self.opts, reuse) {
            Ok(stats) => return Ok(stats),
            Err(e) => e,
        };
        if self.cont.tolerance.is_none() {
            return Err(failure);
        }
        if let Some(stats) = self.stuck(&failure, x) {
            return Ok(stats);
        }
        if !self.cont.pin_slides || !stalled(&failure) {
            return Err(failure);
        }
        let mut failure = failure;
        if let Some(predicted) = predicted {
            self.sys.disable_pinning();
            x.clone_from(&predicted);
            match newton(&mut self.sys, x, self.opts, false) {
                Ok(stats) => return Ok(stats),
                Err(e) => {
                    if let Some(stats) = self.stuck(&e, x) {
                        return Ok(stats);
                    }
                    failure = e;
                }
            }
        }
        let mut pinned = x.clone();
        match newton_pinned(&mut self.sys, &mut pinned, self.opts) {
            Some(stats) => {
                *x = pinned;
                Ok(stats)
            }
            None => Err(failure),
        }
    }

    /// (robust10c) The statistics of a Newton that failed stuck at its
    /// rounding floor at `x`, within [`STUCK_FLOOR`] times its tolerance,
    /// or, at the shortest step, within [`STALLED_FLOOR`] where the
    /// correction left moves the diagram's point across the branch by at
    /// most [`STALLED_ACROSS`] of the run's tolerance (that distance joins
    /// the estimate): its point is kept, counted as [`FLOOR_ITERATIONS`]
    /// within [`STUCK_FLOOR`] (the next step about as long) and as the most
    /// iterations beyond it (the next step shorter).
    fn stuck(&mut self, e: &Error, x: &State) -> Option<NewtonStats> {
        let (Error::NewtonDiverged { correction, .. }
        | Error::NewtonNotConverged { correction, .. }) = *e
        else {
            return None;
        };
        let stats = NewtonStats {
            iterations: self.opts.max_iter,
            jacobians: 1,
            correction,
        };
        if correction <= STUCK_FLOOR * self.opts.tol {
            return Some(NewtonStats {
                iterations: FLOOR_ITERATIONS,
                ..stats
            });
        }
        // (the last resort only: see STALLED_FLOOR)
        let tol = self.cont.tolerance?;
        if correction > STALLED_FLOOR || self.ds > self.cont.ds_min {
            return None;
        }
        let moved = self.correction_across(x).ok()?;
        // (a NaN distance is no evidence: not kept)
        if moved.is_nan() || moved > STALLED_ACROSS * tol {
            return None;
        }
        self.estimate.stalled = self.estimate.stalled.max(moved);
        Some(stats)
    }

    /// How far across the branch Newton's next correction at `x`, on the
    /// current factorisation, would move the point in the diagram's plane,
    /// to first order (measured across the slope at x₀, like
    /// [`pinned_across`](Self::pinned_across): along the branch it only
    /// moves the point on the curve).
    fn correction_across(&mut self, x: &State) -> Result<f64> {
        let q = self.cont.parameter;
        correction_across_on(
            &mut self.sys,
            &self.norm,
            &self.cont.diagram,
            q,
            x,
            &self.t0,
        )
    }

    /// How far across the branch the pinned point `x` lies from the
    /// equilibrium its pinned modes would slide to, to first order: the
    /// diagram's change along the part of the unpinned Newton correction
    /// in the modes' span, measured across the slope at x₀ (along the
    /// branch it only moves the point on the curve).
    fn pinned_across(&mut self, x: &State) -> Result<f64> {
        let mut res = self.sys.zero_residual();
        self.sys.residual(x, &mut res)?;
        let part = self.sys.pinned_part(&res)?;
        Ok(self.across_at(x, &part))
    }

    /// How far the change `d` of the state at `x` moves the diagram's point
    /// across the branch, to first order: measured across the slope at x₀.
    fn across_at(&self, x: &State, d: &State) -> f64 {
        let q = self.cont.parameter;
        self.cont
            .diagram
            .across_on(&self.sys, &self.norm, q, x, (d, &self.t0))
    }

    /// The tangent at `x` without a new factorisation: iterative
    /// refinement of [F_x(x); τ₀ᵀ] τ = e preconditioned by the current
    /// (chord) factorisation, with F_x(x)τ by
    /// [`residual_derivative`](Self::residual_derivative). The refinement
    /// stops at a correction of a tenth of
    /// [`tangent_tolerance`](Self::tangent_tolerance) (the error left is
    /// about the next correction, at most a third of this one at the
    /// contraction ¼ it requires) but not below 1e-10, or where the difference quotient's
    /// rounding stalls it (about 1e-8 on the rod) if that is below
    /// [`tangent_tolerance`](Self::tangent_tolerance); `None` when it does
    /// not get there.
    pub(super) fn refined_tangent(&mut self, x: &State) -> Option<State> {
        let enough = self.tangent_tolerance();
        let t0 = self.t0.clone();
        refine_border_solution(&mut self.sys, x, t0, enough)
    }

    /// The correction below which a tangent is good enough: 1e-10, or with
    /// a tolerance a tenth of it (a slope error δ moves a step's Hermite
    /// interpolant by at most h δ / 4 in the diagram's plane, with steps
    /// h < 1).
    fn tangent_tolerance(&self) -> f64 {
        self.cont
            .tolerance
            .map_or(1e-10, |tol| (0.1 * tol).max(1e-10))
    }
}

/// How far across the branch (tangent `t`) Newton's next correction at `x`,
/// on the current factorisation of `sys`, would move the point in the
/// diagram's plane, to first order: the corrector's stalled point and the
/// halved-mesh check's.
pub(super) fn correction_across_on<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    norm: &IntegralNorm,
    diagram: &super::diagram::Diagram,
    q: usize,
    x: &State,
    t: &State,
) -> Result<f64> {
    let mut res = sys.zero_residual();
    sys.residual(x, &mut res)?;
    let mut d = sys.zero_state();
    sys.solve(&res, &mut d)?;
    Ok(diagram.across_on(sys, norm, q, x, (&d, t)))
}
