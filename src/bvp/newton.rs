//! Damped chord Newton on the collocation system, shared with
//! continuation, and the solution built from its result.

use super::mesh::Mesh;
use super::problem::Problem;
use super::solution::{NewtonStats, Solution};
use super::system::{Residual, State, System};
use crate::error::{Error, Result};

/// How far above its tolerance a fresh Newton correction may stall and
/// still count as converged.
///
/// Damping that cannot reduce a correction computed with a fresh Jacobian
/// means the residual is at its rounding floor: no iterate is closer than
/// the correction says. Within this factor of the tolerance the iterate is
/// kept (its [`NewtonStats::correction`] says how far it is); beyond it the
/// iteration diverged. Measured: the rod's fold curves on 96 intervals stall
/// at 1.1e-10 and 1.2e-10 against the default 1e-10 when their start is
/// corrected. Used by solves ([`super::Collocation::solve`], the start of a
/// fold curve), not by the continuation's steps ([`NewtonOptions::stall`]).
pub(crate) const ROUNDOFF_STALL: f64 = 10.0;

/// Newton settings shared with continuation.
#[derive(Debug, Clone, Copy)]
pub(crate) struct NewtonOptions {
    pub tol: f64,
    pub max_iter: u32,
    /// A correction that damping cannot reduce, computed with a fresh
    /// Jacobian, within `stall` × `tol` counts as converged
    /// ([`ROUNDOFF_STALL`] for a solve, 1 for never: the continuation's
    /// corrector keeps such points only as its last resort, where it
    /// measures how far they are across the branch; accepted at every
    /// step, points displaced along sliding loops made spurious folds).
    pub stall: f64,
}

/// ‖δ‖∞ / (1 + ‖x‖∞) over the mesh values and the free parameters.
pub(crate) fn scaled_norm(d: &State, x: &State, free: &[usize]) -> f64 {
    let mut dn: f64 = 0.0;
    let mut xn: f64 = 0.0;
    for (a, b) in d.y.iter().zip(&x.y) {
        dn = dn.max(a.abs());
        xn = xn.max(b.abs());
    }
    for &i in free {
        dn = dn.max(d.p[i].abs());
        xn = xn.max(x.p[i].abs());
    }
    if dn.is_nan() {
        return f64::INFINITY;
    }
    dn / (1.0 + xn)
}

/// Damped Newton with chord steps (natural monotonicity test, Deuflhard):
/// a step λδ is accepted when the simplified correction δ̄ computed with the
/// same factorisation satisfies ‖δ̄‖ < (1 − λ/4)‖δ‖; the factorisation is
/// kept (chord) while the contraction ‖δ̄‖/‖δ‖ stays below ⅛. With `reuse`,
/// the system's existing factorisation is tried first.
pub(crate) fn newton<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &mut State,
    opts: NewtonOptions,
    reuse: bool,
) -> Result<NewtonStats> {
    let free = sys.free.clone();
    let mut stats = NewtonStats::default();
    let mut res = sys.zero_residual();
    let mut dx = sys.zero_state();
    let mut dbar = sys.zero_state();
    let mut trial = x.clone();
    sys.residual(x, &mut res)?;
    let mut fresh = !reuse;
    if fresh {
        sys.factor(x)?;
        stats.jacobians += 1;
    }
    sys.solve(&res, &mut dx)?;
    let mut ndx = scaled_norm(&dx, x, &free);
    for it in 0..opts.max_iter {
        if ndx <= opts.tol {
            x.axpy(1.0, &dx, &free);
            stats.iterations += 1;
            stats.correction = ndx;
            return Ok(stats);
        }
        let mut lam = 1.0;
        let theta;
        loop {
            trial.clone_from(x);
            trial.axpy(lam, &dx, &free);
            let ok = match sys.residual(&trial, &mut res) {
                Ok(()) => sys.solve(&res, &mut dbar).is_ok(),
                Err(Error::NonFinite { .. }) => false,
                Err(e) => return Err(e),
            };
            if ok {
                let nb = scaled_norm(&dbar, &trial, &free);
                if nb < (1.0 - 0.25 * lam) * ndx {
                    theta = nb / ndx;
                    break;
                }
            }
            if !fresh {
                sys.residual(x, &mut res)?;
                sys.factor(x)?;
                stats.jacobians += 1;
                fresh = true;
                sys.solve(&res, &mut dx)?;
                ndx = scaled_norm(&dx, x, &free);
                lam = 1.0;
                if ndx <= opts.tol {
                    x.axpy(1.0, &dx, &free);
                    stats.iterations += 1;
                    stats.correction = ndx;
                    return Ok(stats);
                }
                continue;
            }
            lam *= 0.5;
            if lam < 1.0 / 1024.0 {
                if ndx <= opts.stall * opts.tol {
                    // converged as far as rounding lets it: keep x
                    stats.correction = ndx;
                    return Ok(stats);
                }
                return Err(Error::NewtonDiverged {
                    iteration: it,
                    correction: ndx,
                });
            }
        }
        std::mem::swap(x, &mut trial);
        stats.iterations += 1;
        if theta > 0.125 || lam < 1.0 {
            sys.factor(x)?;
            stats.jacobians += 1;
            fresh = true;
            sys.solve(&res, &mut dx)?;
        } else {
            std::mem::swap(&mut dx, &mut dbar);
            fresh = false;
        }
        ndx = scaled_norm(&dx, x, &free);
        stats.correction = ndx;
    }
    if ndx <= opts.tol {
        x.axpy(1.0, &dx, &free);
        stats.iterations += 1;
        return Ok(stats);
    }
    Err(Error::NewtonNotConverged {
        iterations: opts.max_iter,
        correction: ndx,
        tolerance: opts.tol,
    })
}

/// Newton again from `x`, where [`newton`] failed (damping could not
/// reduce the correction, or the iterations ran out), with the near-null
/// modes of the system there pinned ([`System::find_pinned_modes`]).
/// Pinning stays enabled on success: later factorisations pin the modes
/// they find. On failure it is disabled. Returns `None` where the system has no
/// near-null modes at `x` or the pinned iteration fails too (x unchanged).
pub(crate) fn newton_pinned<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &mut State,
    opts: NewtonOptions,
) -> Option<NewtonStats> {
    if sys.factor(x).is_err() {
        return None;
    }
    sys.find_pinned_modes();
    let mut pinned = x.clone();
    if sys.pinned_modes() > 0
        && let Ok(stats) = newton(sys, &mut pinned, opts, true)
    {
        *x = pinned;
        return Some(stats);
    }
    sys.disable_pinning();
    None
}

/// Builds the public solution from a converged state.
pub(crate) fn finish<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: State,
    mesh: Mesh,
    newton: NewtonStats,
) -> Result<Solution> {
    let mut r: Residual = sys.zero_residual();
    sys.residual(&x, &mut r)?;
    let mut sol = Solution {
        mesh,
        tab: sys.tab.clone(),
        n: sys.n,
        y: x.y,
        k: x.k,
        p: x.p,
        residual_norm: r.max_norm(),
        error_estimate: f64::NAN,
        newton,
        boundaries: Some(sys.nbc),
    };
    sol.error_estimate = sol.estimate_error();
    Ok(sol)
}
