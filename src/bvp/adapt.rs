//! Mesh adaptation: the coarsest equidistributed mesh that meets a
//! tolerance.

use super::collocation::Collocation;
use super::mesh::Mesh;
use super::problem::Problem;
use super::solution::Solution;
use super::tableau::Tableau;
use crate::error::{Error, Result};

impl Collocation {
    /// Adapts the mesh of `sol` until its error meets `tol · (1 + max|y|)`.
    ///
    /// First the mesh is equidistributed in the local estimate
    /// C_m h^(m+1) ‖y^(m+1)‖ until that estimate meets the tolerance. It
    /// falls short of the true error on a mesh that does not yet resolve
    /// the solution (Troesch's layer at μ = 10 on 8 intervals: estimate 1.2,
    /// error 17), so the mesh it accepts is then verified on the halved
    /// mesh: with d the largest difference of the two solutions (at
    /// [`VERIFY_SAMPLES`] points per interval), the coarser one's error is
    /// at most 2d whenever halving at least halves the error
    /// (e_c ≤ d + e_f ≤ d + e_c/2), and 2d is its estimate. Where 2d
    /// exceeds the tolerance, the mesh is equidistributed again in the
    /// local density of the finer solution, with as many intervals as an
    /// error falling as N^-(m+1) needs, and verified again.
    pub(super) fn adapt<P: Problem + ?Sized>(
        &self,
        problem: &P,
        sol: Solution,
        tol: f64,
        tab: &Tableau,
    ) -> Result<Solution> {
        let mut candidate = self.locally_adapted(problem, sol, tol, tab)?;
        let m1 = (tab.m + 1) as f64;
        // the last verification that fell short: (2d, intervals), the
        // estimate a failure reports (the local one is known to fall short)
        let mut short = None;
        for _round in 0..MAX_ROUNDS {
            // checked here, not by `halved`, so that the limit says
            // `ToleranceNotMet` whatever it is
            if 2 * candidate.mesh.intervals() > self.max_intervals {
                break;
            }
            let mesh = candidate.mesh.halved()?;
            let fine = self.solve_on(problem, &candidate, &candidate.p, mesh, tab)?;
            let d = differences(&candidate, &fine);
            let worst = 2.0 * d.iter().fold(0.0_f64, |a, v| a.max(*v));
            let atol = tol * (1.0 + max_abs(&candidate));
            if worst <= atol {
                candidate.error_estimate = worst;
                return Ok(candidate);
            }
            let n = candidate.mesh.intervals();
            short = Some((worst, n));
            if !worst.is_finite() {
                break;
            }
            // the local estimate's shape on the finer solution, its size
            // from the difference: on an equidistributed mesh the error
            // falls as N^-(m+1)
            let target =
                ((n as f64 * (1.2 * worst / atol).powf(1.0 / m1)).ceil() as usize).max(n + 1);
            if target > self.max_intervals {
                break;
            }
            let mesh = equidistribute(
                &fine.mesh,
                &density_floored(&fine, collocation_floor(tab)),
                target,
            )?;
            candidate = self.solve_on(problem, &fine, &fine.p, mesh, tab)?;
        }
        let (estimate, intervals) =
            short.unwrap_or((candidate.error_estimate, candidate.mesh.intervals()));
        Err(Error::ToleranceNotMet {
            tolerance: tol,
            estimate,
            intervals: intervals as u64,
        })
    }

    /// The coarsest equidistributed mesh whose local estimate meets the
    /// tolerance (or the finest tried, when none does within the rounds).
    fn locally_adapted<P: Problem + ?Sized>(
        &self,
        problem: &P,
        mut sol: Solution,
        tol: f64,
        tab: &Tableau,
    ) -> Result<Solution> {
        // the most intervals seen to fall short: coarsening stays above
        // (equidistributed meshes of 6 and 8 intervals alternated forever)
        let mut too_coarse = 0_usize;
        let mut best: Option<Solution> = None;
        for _round in 0..MAX_ROUNDS {
            let atol = tol * (1.0 + max_abs(&sol));
            let ok = sol.error_estimate <= atol;
            let nn = sol.mesh.intervals();
            // Equidistribute φ = ‖y^(m+1)‖^(1/(m+1)); the estimate on an
            // equidistributed mesh is C_m (I/N)^(m+1).
            let phi = density_floored(&sol, collocation_floor(tab));
            let m1 = (tab.m + 1) as f64;
            let integral: f64 = phi
                .iter()
                .enumerate()
                .map(|(j, f)| f * sol.mesh.width(j))
                .sum();
            let mut target =
                (integral * (1.2 * tab.error_constant / atol).powf(1.0 / m1)).ceil() as usize;
            target = target.max(2);
            if ok {
                if best
                    .as_ref()
                    .is_none_or(|b| b.mesh.intervals() > sol.mesh.intervals())
                {
                    best = Some(sol.clone());
                }
                target = target.max(too_coarse + 1);
                // Coarsen only when clearly possible.
                if target * 10 >= nn * 8
                    || best.as_ref().is_some_and(|b| b.mesh.intervals() <= target)
                {
                    return Ok(best.unwrap_or(sol));
                }
            } else {
                too_coarse = too_coarse.max(nn);
                target = target.max(nn + nn / 5 + 1);
            }
            if target > self.max_intervals {
                break;
            }
            let mesh = equidistribute(&sol.mesh, &phi, target)?;
            let p = sol.p.clone();
            match self.solve_on(problem, &sol, &p, mesh, tab) {
                Ok(s) => sol = s,
                Err(e) => return best.ok_or(e),
            }
        }
        Ok(best.unwrap_or(sol))
    }
}

/// The floor of ‖y^(m+1)‖ relative to its maximum for `Collocation::tolerance`:
/// φ floored at 1e-3 of its maximum (see [`density_floored`]).
fn collocation_floor(tab: &Tableau) -> f64 {
    1e-3_f64.powi(tab.m as i32 + 1)
}

/// Rounds of each phase of `adapt`.
const MAX_ROUNDS: usize = 16;

/// Points per interval of the coarser solution at which a verification
/// compares it with the halved mesh's: k/6, k = 0..5 (and s = 1), so that
/// an interior bulge of a degree-7 polynomial is seen.
const VERIFY_SAMPLES: usize = 6;

/// max over components and mesh values of |y|.
fn max_abs(sol: &Solution) -> f64 {
    sol.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()))
}

/// The largest difference between two solutions of one problem on each
/// interval of `coarse`, over components, at [`VERIFY_SAMPLES`] points per
/// interval (the last interval also at s = 1); ∞ where either is not finite.
fn differences(coarse: &Solution, fine: &Solution) -> Vec<f64> {
    let n = coarse.dim();
    let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
    let mut at = |s: f64| {
        coarse.eval_into(s, &mut a);
        fine.eval_into(s, &mut b);
        a.iter().zip(&b).fold(0.0_f64, |w, (x, y)| {
            let d = (x - y).abs();
            if d.is_nan() { f64::INFINITY } else { w.max(d) }
        })
    };
    let p = coarse.mesh.points();
    let mut d: Vec<f64> = p
        .windows(2)
        .map(|w| {
            (0..VERIFY_SAMPLES)
                .map(|k| at(w[0] + (w[1] - w[0]) * k as f64 / VERIFY_SAMPLES as f64))
                .fold(0.0_f64, f64::max)
        })
        .collect();
    if let Some(last) = d.last_mut() {
        *last = last.max(at(1.0));
    }
    d
}

/// The mesh density φ_j = ‖y^(m+1)‖^(1/(m+1)) on each interval of `sol`
/// (‖y^(m+1)‖ floored at 1e-6 of its maximum and φ smoothed over
/// neighbours), whose equidistribution balances the local error estimate:
/// the continuation's remeshing.
pub(crate) fn density(sol: &Solution) -> Vec<f64> {
    density_floored(sol, 1e-6)
}

/// [`density`] with ‖y^(m+1)‖ floored at `floor` times its maximum. After
/// the (m+1)-th root a floor of 1e-6 is still 0.18 of the largest φ at
/// m = 7 (0.06 at m = 4), so intervals where the solution is flat are at
/// most 5.6 times wider than in its layer: Troesch at μ = 10 put half its
/// intervals in [0, ½], where y < 1e-3. `Collocation::tolerance` floors φ
/// at 1e-3 of its maximum instead ([`collocation_floor`]).
fn density_floored(sol: &Solution, floor: f64) -> Vec<f64> {
    let d = sol.derivative_m1();
    let m1 = (sol.tab.m + 1) as f64;
    let dmax = d.iter().fold(0.0_f64, |a, v| a.max(*v));
    let mut phi: Vec<f64> = d
        .iter()
        .map(|v| v.max(floor * dmax).max(1e-300).powf(1.0 / m1))
        .collect();
    if phi.len() > 2 {
        let raw = phi.clone();
        for j in 0..raw.len() {
            let a = raw[j.saturating_sub(1)];
            let c = raw[(j + 1).min(raw.len() - 1)];
            phi[j] = 0.25 * (a + 2.0 * raw[j] + c);
        }
    }
    phi
}

/// A mesh of `n` intervals equidistributing the piecewise-constant density
/// `phi` given on `old`.
pub(crate) fn equidistribute(old: &Mesh, phi: &[f64], n: usize) -> Result<Mesh> {
    let nn = old.intervals();
    let mut cum = vec![0.0; nn + 1];
    for j in 0..nn {
        cum[j + 1] = cum[j] + phi[j] * old.width(j);
    }
    let total = cum[nn];
    let mut pts = Vec::with_capacity(n + 1);
    pts.push(0.0);
    let mut j = 0;
    for i in 1..n {
        let target = total * i as f64 / n as f64;
        while j < nn - 1 && cum[j + 1] < target {
            j += 1;
        }
        let frac = if phi[j] > 0.0 {
            (target - cum[j]) / (phi[j] * old.width(j))
        } else {
            0.5
        };
        let t = old.points()[j] + frac.clamp(0.0, 1.0) * old.width(j);
        if t > *pts.last().unwrap_or(&0.0) && t < 1.0 {
            pts.push(t);
        }
    }
    pts.push(1.0);
    Mesh::from_points(pts)
}
