//! The checks of a run with a tolerance (module docs of
//! [`Continuation::tolerance`](super::Continuation::tolerance)): the mesh
//! error of the start and of each step's points, the interpolation error
//! of each step, and the guards of its length (the turn of the slope in the
//! diagram's plane, the corrector's drift from the predictor, a pair of
//! folds passed over in one step).

use super::hermite::{self, Degree, Jet, across, turns_back_twice};
use super::{Rejection, Steps};
use crate::bvp::Problem;
use crate::bvp::system::State;
use crate::error::Result;

/// Remeshes allowed for one step (a step whose error is still above the
/// tolerance after them is accepted, with its estimate).
const REMESHES_PER_STEP: u32 = 4;

/// (robust10c) The largest factor of Δs after a step rejected for skipping
/// a fold pair, so that repeated rejections reach ds_min in a bounded
/// number of tries (found by the long fuzz run: a rod on 7 intervals,
/// m = 3, whose step was rejected so with factors tending to 1,
/// Δs → 0.1333…).
const SKIPPED_SHRINK: f64 = 0.5;

/// The chord in the diagram's plane below which a step's turn is not
/// limited.
const TURN_CHORD: f64 = 1e-2;

/// The largest distance between the corrected point and the predictor,
/// relative to the step, of an accepted step with a tolerance (a larger one
/// is the mark of a trace that jumped to a nearby branch).
const MAX_DRIFT: f64 = 0.2;

/// The largest distance from the predictor, relative to the step, of a
/// point kept at Newton's rounding floor at the minimum step (where
/// [`MAX_DRIFT`] does not reject): a point of the branch on the step's
/// hyperplane lies about κΔs²/2 from the predictor, so one a whole step
/// away is noise along a nearly free mode, not a point of the branch.
/// Measured: such points drift 0.23–23 steps where loops slide freely (n = 6
/// at (89.8°, 10, −0.1) stretched); on n = 7 at (89.5°, 100, 0.05) pulled to
/// 30 (`tests/rod/slides.rs`) one 0.27 steps away is kept, and the run ends
/// two steps later at 20.
const FLOOR_DRIFT: f64 = 1.0;

/// Accepted steps between two mesh checks at most.
const CHECK_EVERY: usize = 4;

/// Relative change of the mesh density integral that triggers a check.
const DENSITY_CHANGE: f64 = 0.1;

/// Whether a neighbouring step of length `h` estimates P⁽⁶⁾ for a step of
/// length `ds` (a much shorter one carries P⁽⁵⁾ swamped by the rounding of
/// its points, ∝ 1/h⁵).
fn comparable(h: f64, ds: f64) -> bool {
    h >= 0.25 * ds && h <= 4.0 * ds
}

/// The midpoint's interpolation error times this bounds the step's (the
/// remainder's shape τ³(1 − τ)³ peaks there; the rest covers the change of
/// P⁽⁶⁾ along the step).
const MIDPOINT_SAFETY: f64 = 1.5;

/// The angle between two slopes in the diagram's plane (0 when either
/// vanishes).
fn diagram_turn(a: [f64; 2], b: [f64; 2]) -> f64 {
    let (na, nb) = (a[0].hypot(a[1]), b[0].hypot(b[1]));
    if na > 0.0 && nb > 0.0 && na.is_finite() && nb.is_finite() {
        ((a[0] * b[0] + a[1] * b[1]) / (na * nb))
            .clamp(-1.0, 1.0)
            .acos()
    } else {
        0.0
    }
}

/// The share of the tolerance left to the interpolation between points.
const INTERPOLATION_SHARE: f64 = 0.25;

/// A step whose interpolation error exceeds this share of the tolerance is
/// done again with a shorter Δs (the mesh's share being the other half, the
/// curve stays within the tolerance).
pub(super) const INTERPOLATION_REJECT: f64 = 0.5;

/// The step factor that brings the interpolation error `error` to 0.8 of
/// its share of `tol` (for the interpolant of that tolerance's degree).
pub(super) fn interpolation_factor(error: f64, tol: f64) -> f64 {
    hermite::step_factor(
        error,
        0.8 * INTERPOLATION_SHARE * tol,
        Degree::for_tolerance(tol),
    )
}

/// The interpolant of an accepted step: its P⁽⁵⁾, its error estimate and
/// the jet of its end point.
pub(super) struct StepFit {
    /// The step's arclength ([`hermite::length`]).
    pub(super) length: f64,
    pub(super) fifth: [f64; 2],
    pub(super) error: f64,
    pub(super) end: Jet,
}

/// What the mesh checks of a step decided.
pub(super) enum StepCheck {
    /// The run moved to a finer mesh at x₀: the step is done again.
    Remeshed,
    /// The step stands; coarsen to this many intervals after it.
    Accept { coarsen_to: Option<usize> },
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// The mesh check of the start point: refine (or coarsen, once) until
    /// its error is within half the tolerance.
    pub(super) fn check_start(&mut self, tol: f64) -> Result<()> {
        let goal = 0.5 * tol;
        let mut coarsened = false;
        for _ in 0..8 {
            let (x, t) = (self.x0.clone(), self.t0.clone());
            let e = self.mesh_error(&x, &t, false).unwrap_or(f64::INFINITY);
            let nn = self.mesh.intervals();
            let want = self.intervals_for(e, 0.25 * tol);
            let limit = self.cont.solver.interval_limit();
            if !self.cont.adapt_mesh {
                self.estimate.mesh = e;
                break;
            }
            if e > goal && nn < limit {
                self.remesh(want.max(nn + nn / 4 + 1).min(limit))?;
            } else if e <= goal && !coarsened && 10 * want.max(self.min_intervals) <= 7 * nn {
                coarsened = true;
                self.remesh(want.max(self.min_intervals))?;
            } else {
                self.estimate.mesh = e;
                break;
            }
        }
        self.checked_density = self.density_integral(&self.x0.clone());
        Ok(())
    }

    /// The degree of the run's step interpolant (the quintic without a
    /// tolerance, where no interpolant is checked).
    pub(super) fn degree(&self) -> Degree {
        self.cont
            .tolerance
            .map_or(Degree::Quintic, Degree::for_tolerance)
    }

    /// The arclength of the step from x₀ (tangent τ₀, jet `start`) to `x`
    /// (tangent `t`, jet `end`): [`hermite::length`] of its chord, with the
    /// angle between the tangents where the jets carry no bend.
    pub(super) fn step_length(&mut self, x: &State, t: &State, start: &Jet, end: &Jet) -> f64 {
        let mut chord = x.clone();
        chord.axpy(-1.0, &self.x0, &self.sys.free);
        let t0 = self.t0.clone();
        let turn = self.inner(t, &t0).clamp(-1.0, 1.0).acos();
        hermite::length(self.norm(&chord), start, end, turn)
    }

    /// The jet of x₀ (computed once per point).
    pub(super) fn start_jet(&mut self) -> Jet {
        if let Some(j) = self.jet0 {
            return j;
        }
        let (x, t) = (self.x0.clone(), self.t0.clone());
        let j = self.jet(&x, &t);
        self.jet0 = Some(j);
        j
    }

    /// The interpolation check of a step: its quintic's P⁽⁵⁾, error
    /// estimate and end jet, or `None` when the step was rejected (Δs
    /// reduced) for an error above half the tolerance or a guard, or, at
    /// the minimum step, the run ended for a point kept at Newton's
    /// rounding floor beyond [`FLOOR_DRIFT`] from its predictor
    /// ([`Error::CorrectorDrifted`](crate::error::Error::CorrectorDrifted)).
    pub(super) fn check_interpolation(
        &mut self,
        c: &super::corrector::Corrected,
        ds: f64,
        tol: f64,
    ) -> Option<StepFit> {
        // the corrector's distance from the predictor, relative to the step
        let free = self.sys.free.clone();
        let mut d = c.x.clone();
        d.axpy(-1.0, &self.x0.clone(), &free);
        d.axpy(-ds, &self.t0.clone(), &free);
        // (a slide along pinned modes is no drift)
        self.sys.project_pinned(&mut d);
        let drift = self.norm(&d) / ds;
        let start = self.start_jet();
        let end = self.jet(&c.x, &c.tangent);
        let h = self.step_length(&c.x, &c.tangent, &start, &end);
        let degree = self.degree();
        let fifth = hermite::fifth(&start, &end, h, degree);
        let error = if !(fifth[0].is_finite() && fifth[1].is_finite()) {
            // no curvature at an end: no interpolant to trust
            f64::INFINITY
        } else {
            match self.last_fifth {
                Some((prev, h_prev)) if comparable(h_prev, h) => {
                    hermite::error(fifth, prev, h, h_prev, degree)
                }
                // no neighbour of comparable length (the first step, after a
                // remesh or a change of scale): the error measured at the
                // midpoint, where the remainder τ³(1 − τ)³ peaks
                _ => match self.correct(0.5 * ds, false) {
                    Ok(mid) => {
                        let (pm, sm) = self.diagram_of(&mid.x, &mid.tangent);
                        let hm = hermite::at(&start, &end, h, 0.5, degree);
                        MIDPOINT_SAFETY * across(pm, sm, hm)
                    }
                    Err(_) => f64::INFINITY,
                },
            }
        };
        let (p0, s0, p1, s1) = (start.point, start.slope, end.point, end.slope);
        // (a turn over a chord below a hundredth of the plane's unit is a
        // corner the interpolation error already resolves)
        let chord = (p1[0] - p0[0]).abs().max((p1[1] - p0[1]).abs());
        let turn = if chord > TURN_CHORD {
            diagram_turn(s0, s1)
        } else {
            0.0
        };
        let skipped =
            self.cont.folds && turns_back_twice(p0[0], s0[0], p1[0], s1[0], ds, 0.1 * tol);
        let too_far = turn > self.cont.max_angle
            || drift > MAX_DRIFT
            || skipped
            || error > INTERPOLATION_REJECT * tol;
        if too_far && self.ds > self.cont.ds_min {
            let by_turn = (0.6 * self.cont.max_angle / turn).min(0.5 * MAX_DRIFT / drift);
            // (robust10c) a step rejected for a skipped fold pair shrinks by
            // `SKIPPED_SHRINK` at least: with a small interpolation error its
            // factor tended to 1, retried ever closer to the same Δs and
            // never reached ds_min (a hang inside one step); the other
            // reasons give factors below 1 (turn, drift: < 0.6; error above
            // half the tolerance: its own factor)
            let skip = if skipped { SKIPPED_SHRINK } else { 1.0 };
            let shorter = (ds
                * interpolation_factor(error, tol)
                    .min(by_turn)
                    .min(skip)
                    .max(0.25))
            .max(self.cont.ds_min);
            self.reject_to(
                shorter,
                Rejection::Interpolant {
                    error,
                    allowed: INTERPOLATION_REJECT * tol,
                    turn,
                    drift,
                    skipped_fold_pair: skipped,
                },
            );
            return None;
        }
        if drift > FLOOR_DRIFT && c.at_floor {
            // (at the minimum step, a point Newton left at its rounding
            // floor that far from the predictor is noise along a nearly
            // free mode: accepted, such points made runs of spurious
            // folds, 23 "pop-outs" at one force for n = 6 at
            // (89.8°, 10, −0.1) stretched, docs/ACCURACY.md "Stretched";
            // a converged one is an equilibrium and stands)
            self.fail(crate::error::Error::CorrectorDrifted {
                drift,
                allowed: FLOOR_DRIFT,
            });
            return None;
        }
        self.angle = self.angle.max(turn);
        Some(StepFit {
            length: h,
            fifth,
            error,
            end,
        })
    }

    /// The interpolation error of the step x₀ → `fit.end` measured at the
    /// points located inside it (at arclengths `s` ∈ (0, ds)): across the
    /// branch from each to the step's interpolant.
    pub(super) fn located_interpolation_error(
        &mut self,
        fit: &StepFit,
        ds: f64,
        located: &[(State, State, f64)],
    ) -> f64 {
        let start = self.start_jet();
        let degree = self.degree();
        located
            .iter()
            .filter(|(.., s)| *s > 0.0 && *s < ds)
            .map(|(x, t, s)| {
                let (p, slope) = self.diagram_of(x, t);
                across(
                    p,
                    slope,
                    hermite::at(&start, &fit.end, fit.length, s / ds, degree),
                )
            })
            .fold(0.0, f64::max)
    }

    /// The mesh checks of a step: every located point, and the new point
    /// when the density moved (module docs of `mesh_error`).
    pub(super) fn check_step(
        &mut self,
        c: &super::corrector::Corrected,
        located: &[(State, State, bool)],
        tol: f64,
    ) -> StepCheck {
        let goal = 0.5 * tol;
        let mut worst_located: f64 = 0.0;
        for (x, t, fold) in located {
            let e = self.mesh_error(x, t, *fold).unwrap_or(f64::INFINITY);
            worst_located = worst_located.max(e);
        }
        let density = self.density_integral(&c.x);
        let moved = (density / self.checked_density - 1.0).abs() > DENSITY_CHANGE;
        let mut regular = None;
        let due = self.accepted >= self.checked_at + CHECK_EVERY;
        if moved || due || !located.is_empty() {
            regular = Some(
                self.mesh_error(&c.x, &c.tangent, false)
                    .unwrap_or(f64::INFINITY),
            );
        }
        let worst = worst_located.max(regular.unwrap_or(0.0));
        let nn = self.mesh.intervals();
        let limit = self.cont.solver.interval_limit();
        if self.cont.adapt_mesh
            && worst > goal
            && nn < limit
            && self.remeshes_this_step < REMESHES_PER_STEP
        {
            let want = self.intervals_for(worst, 0.25 * tol);
            self.remeshes_this_step += 1;
            if let Ok(flipped) = self.remesh(want.max(nn + nn / 4 + 1).min(limit)) {
                self.last_fifth = None;
                self.jet0 = None;
                self.fold_behind |= flipped && self.cont.folds;
                return StepCheck::Remeshed;
            }
        }
        self.estimate.mesh = self.estimate.mesh.max(worst);
        self.estimate.located = self.estimate.located.max(worst_located);
        let mut coarsen_to = None;
        if let Some(e) = regular {
            self.checked_density = density;
            self.checked_at = self.accepted;
            let want = self.intervals_for(e, 0.25 * tol);
            let want = want.max(self.min_intervals);
            if self.cont.adapt_mesh && e <= goal && located.is_empty() && 10 * want <= 7 * nn {
                coarsen_to = Some(want);
            }
        }
        StepCheck::Accept { coarsen_to }
    }
}
