//! Self-contact: the closest approach of a rod's centreline to itself,
//! between parts that are not neighbours along the rod.
//!
//! ## Neighbours
//!
//! Every point is at distance zero from itself and close to the points
//! next to it, so "closest approach" needs a notion of parts that could
//! touch. Two points s < t are **neighbours** when the arc between them is
//! shorter than π times the smallest radius of curvature on it:
//!
//! ```text
//!   (t − s) · max_{σ∈[s,t]} κ(σ) < π.
//! ```
//!
//! On such an arc the distance from r(s) grows strictly with t: with
//! κ ≤ 1/ρ the tangent turns by at most (t − σ)/ρ < π between σ and t, so
//!
//! ```text
//!   d/dt ½|r(t) − r(s)|² = ∫ₛᵗ d3(σ)·d3(t) dσ ≥ ∫₀^(t−s) cos(x/ρ) dx = ρ sin((t − s)/ρ) > 0,
//! ```
//!
//! and no chord between neighbours is normal to the curve at its end: no
//! genuine approach (a local minimum of the distance) can lie between
//! neighbours. The bound is sharp for a circle, whose chord grows until the
//! points are antipodal (arc πρ). For the unstressed helix (ρ ≈ 1/(2πn))
//! the neighbours of a point are the half coil on either side; the next
//! coil is not one.
//!
//! ## Algorithm
//!
//! The centreline is sampled at [`SAMPLES`] + 1 equally spaced points with
//! its curvature; the distance of every non-neighbour pair of samples is
//! computed, and the grid's local minima within a few sample spacings of
//! the best are refined by Newton's method on ½|r(s) − r(t)|² with exact
//! derivatives (r′ = d3, d3′ = u2 d1 − u1 d2), kept in [0, 1]² and among
//! non-neighbours. The result is the least distance found: a distance
//! between two points of the collocation centreline (an upper bound of the
//! closest approach, which the refinement makes exact at interior minima).

use nalgebra::{Matrix2, Vector2, Vector3};

use super::Equilibrium;
use super::measure;
use super::quat::rot;

/// Samples of the centreline in the coarse search.
const SAMPLES: usize = 512;

/// Grid minima refined by Newton, at most.
const REFINED: usize = 32;

/// The closest approach of a centreline to itself between parts that are
/// not neighbours along the rod.
///
/// Two points s < t are **neighbours** when the arc between them is
/// shorter than π times the smallest radius of curvature on it,
/// (t − s)·max κ < π. On such an arc the distance from r(s) grows strictly
/// with t (d/dt ½|r(t) − r(s)|² ≥ ρ sin((t − s)/ρ) > 0 for κ ≤ 1/ρ), so no
/// genuine approach, a local minimum of the distance, lies between
/// neighbours; the bound is sharp for a circle. For the unstressed helix
/// the neighbours of a point are the half coil on either side.
/// [`Equilibrium::closest_approach`] computes it.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Contact {
    /// |r(s) − r(t)|, in units of the rod's length.
    pub distance: f64,
    /// The first arclength, s < t.
    pub s: f64,
    /// The second arclength.
    pub t: f64,
}

impl core::fmt::Display for Contact {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "closest approach {:.3e} between s = {:.6} and s = {:.6}",
            self.distance, self.s, self.t
        )
    }
}

/// Position, tangent and curvature vector of the centreline at s.
struct Local {
    r: Vector3<f64>,
    tangent: Vector3<f64>,
    bend: Vector3<f64>,
}

impl Equilibrium {
    /// The closest approach of the centreline to itself between parts that
    /// are not neighbours ([`Contact`]): `None` if every pair of points is
    /// a pair of neighbours (a rod bent by less than π overall).
    ///
    /// The unstressed helix comes closest between neighbouring coils, one
    /// pitch cos θ0 / n apart along the axis (tested). A strip of width w
    /// may touch itself where the distance is below w.
    ///
    /// Cost: about a millisecond (docs/PERFORMANCE.md); computed only when
    /// asked.
    #[must_use]
    pub fn closest_approach(&self) -> Option<Contact> {
        let m = SAMPLES;
        let h = 1.0 / m as f64;
        let theta0 = self.parameters()[2];
        let mut r = Vec::with_capacity(m + 1);
        let mut kappa = Vec::with_capacity(m + 1);
        for i in 0..=m {
            let y = self.eval(i as f64 * h);
            r.push(Vector3::new(y[0], y[1], y[2]));
            let u = measure::strains(self.rod(), theta0, &y);
            kappa.push(u.x.hypot(u.y));
        }
        // d[i][j − first[i]] for non-neighbours j ≥ first[i].
        let mut first = vec![m + 1; m + 1];
        for (i, f) in first.iter_mut().enumerate() {
            let mut kmax = kappa[i];
            for (j, k) in kappa.iter().enumerate().skip(i + 1) {
                kmax = kmax.max(*k);
                if (j - i) as f64 * h * kmax >= core::f64::consts::PI {
                    *f = j;
                    break;
                }
            }
        }
        let dist = |i: usize, j: usize| (r[i] - r[j]).norm();
        let pair_ok = |i: usize, j: usize| i <= m && j <= m && j >= first[i];
        let mut best: Option<Contact> = None;
        let mut minima: Vec<(f64, usize, usize)> = Vec::new();
        for (i, &from) in first.iter().enumerate() {
            for j in from..=m {
                let d = dist(i, j);
                if best.is_none_or(|b| d < b.distance) {
                    best = Some(Contact {
                        distance: d,
                        s: i as f64 * h,
                        t: j as f64 * h,
                    });
                }
                let lower = [
                    (-1, -1),
                    (-1, 0),
                    (-1, 1),
                    (0, -1),
                    (0, 1),
                    (1, -1),
                    (1, 0),
                    (1, 1),
                ]
                .iter()
                .all(|&(di, dj)| {
                    let (a, b) = (i as i64 + di, j as i64 + dj);
                    a < 0
                        || b < 0
                        || !pair_ok(a as usize, b as usize)
                        || dist(a as usize, b as usize) >= d
                });
                if lower {
                    minima.push((d, i, j));
                }
            }
        }
        let mut best = best?;
        minima.sort_by(|a, b| a.0.total_cmp(&b.0));
        let cutoff = best.distance + 4.0 * h;
        for &(_, i, j) in minima.iter().take_while(|c| c.0 <= cutoff).take(REFINED) {
            if let Some(c) = self.refine(i as f64 * h, j as f64 * h, h)
                && c.distance < best.distance
                && self.not_neighbours(c.s, c.t, &kappa, h)
            {
                best = c;
            }
        }
        Some(best)
    }

    fn local(&self, s: f64) -> Local {
        let y = self.eval(s);
        let frame = rot(&y[3..7]);
        let u = measure::strains(self.rod(), self.parameters()[2], &y);
        let (d1, d2, d3) = (
            frame.column(0).into_owned(),
            frame.column(1).into_owned(),
            frame.column(2).into_owned(),
        );
        Local {
            r: Vector3::new(y[0], y[1], y[2]),
            tangent: d3,
            bend: d1 * u.y - d2 * u.x,
        }
    }

    /// Newton's method on ½|r(s) − r(t)|² from (s, t), steps at most 4h.
    fn refine(&self, mut s: f64, mut t: f64, h: f64) -> Option<Contact> {
        for _ in 0..30 {
            let (a, b) = (self.local(s), self.local(t));
            let delta = a.r - b.r;
            let g = Vector2::new(delta.dot(&a.tangent), -delta.dot(&b.tangent));
            let c = -a.tangent.dot(&b.tangent);
            let hess = Matrix2::new(1.0 + delta.dot(&a.bend), c, c, 1.0 - delta.dot(&b.bend));
            let mut step = match hess.cholesky() {
                Some(ch) => -ch.solve(&g),
                None => -g,
            };
            let len = step.norm();
            if !len.is_finite() {
                return None;
            }
            if len > 4.0 * h {
                step *= 4.0 * h / len;
            }
            let (s1, t1) = ((s + step.x).clamp(0.0, 1.0), (t + step.y).clamp(0.0, 1.0));
            let moved = (s1 - s).abs().max((t1 - t).abs());
            (s, t) = (s1, t1);
            if moved < 1e-14 {
                break;
            }
        }
        if s >= t {
            return None;
        }
        let d = (self.local(s).r - self.local(t).r).norm();
        Some(Contact { distance: d, s, t })
    }

    /// The neighbour test of the module docs on the sampled curvature (and
    /// the curvature at the ends of the arc).
    fn not_neighbours(&self, s: f64, t: f64, kappa: &[f64], h: f64) -> bool {
        let theta0 = self.parameters()[2];
        let end = |x: f64| {
            let u = measure::strains(self.rod(), theta0, &self.eval(x));
            u.x.hypot(u.y)
        };
        let (i0, i1) = (
            (s / h).floor() as usize,
            ((t / h).ceil() as usize).min(kappa.len() - 1),
        );
        let kmax = kappa[i0..=i1]
            .iter()
            .copied()
            .fold(end(s).max(end(t)), f64::max);
        (t - s) * kmax >= core::f64::consts::PI
    }
}
