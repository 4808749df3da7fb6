//! Mesh adaptation: the coarsest equidistributed mesh that meets a
//! tolerance.

use super::collocation::Collocation;
use super::mesh::Mesh;
use super::problem::Problem;
use super::solution::Solution;
use super::tableau::Tableau;
use crate::error::{Error, Result};

impl Collocation {
    pub(super) fn adapt<P: Problem + ?Sized>(
        &self,
        problem: &P,
        mut sol: Solution,
        tol: f64,
        tab: &Tableau,
    ) -> Result<Solution> {
        let mut best: Option<Solution> = None;
        for _round in 0..12 {
            let ymax = sol.y.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            let atol = tol * (1.0 + ymax);
            let est = sol.error_estimate;
            let ok = est <= atol;
            let nn = sol.mesh.intervals();
            // Equidistribute φ = ‖y^(m+1)‖^(1/(m+1)); the estimate on an
            // equidistributed mesh is C_m (I/N)^(m+1).
            let phi = density(&sol);
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
                // Coarsen only when clearly possible.
                if target * 10 >= nn * 8
                    || best.as_ref().is_some_and(|b| b.mesh.intervals() <= target)
                {
                    return Ok(best.unwrap_or(sol));
                }
            } else {
                target = target.max(nn + nn / 5 + 1);
            }
            if target > self.max_intervals {
                if let Some(b) = best {
                    return Ok(b);
                }
                return Err(Error::ToleranceNotMet {
                    tolerance: tol,
                    estimate: est,
                    intervals: nn as u64,
                });
            }
            let mesh = equidistribute(&sol.mesh, &phi, target)?;
            let p = sol.p.clone();
            match self.solve_on(problem, &sol, &p, mesh, tab) {
                Ok(s) => sol = s,
                Err(e) => {
                    if let Some(b) = best {
                        return Ok(b);
                    }
                    return Err(e);
                }
            }
        }
        if let Some(b) = best {
            return Ok(b);
        }
        Err(Error::ToleranceNotMet {
            tolerance: tol,
            estimate: sol.error_estimate,
            intervals: sol.mesh.intervals() as u64,
        })
    }
}

/// The mesh density φ_j = ‖y^(m+1)‖^(1/(m+1)) on each interval of `sol`
/// (floored at 1e-6 of its maximum and smoothed over neighbours), whose
/// equidistribution balances the local error estimate.
pub(crate) fn density(sol: &Solution) -> Vec<f64> {
    let d = sol.derivative_m1();
    let m1 = (sol.tab.m + 1) as f64;
    let dmax = d.iter().fold(0.0_f64, |a, v| a.max(*v));
    let mut phi: Vec<f64> = d
        .iter()
        .map(|v| v.max(1e-6 * dmax).max(1e-300).powf(1.0 / m1))
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
