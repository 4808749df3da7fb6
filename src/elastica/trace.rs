//! Whole branches as [`ForceExtension`] curves, sampled adaptively.

use std::collections::BinaryHeap;

use super::bifurcation::bifurcation;
use super::family::Family;
use super::secondary::secondary_fold;
use super::solution::{Arm, Branch, Elastica, check_j, check_n};
use super::symmetric::primary;
use crate::curve::{ForceExtension, ForcePoint, ForceScale};
use crate::error::{Error, Result, check_points};
use crate::special::Modulus;

/// Traces elastica branches into [`ForceExtension`] curves.
///
/// The branch is followed in q = ln(1/m₁) = −ln(1 − k²), which is ≈ k² near
/// k = 0 and ≈ 2K(k) − ln 16 near k = 1, so force and extension are smooth
/// functions of q at both ends (F ∝ q and Δz ∝ q at the ring, F ∝ q² and
/// 1 − Δz ∝ 1/q as k → 1); on a secondary arm q = q_fold + (q_end −
/// q_fold)σ² so that the square-root turn at the fold is smooth in σ. Half
/// the points are spread uniformly in that parameter; the rest are inserted
/// one at a time into the longest segment of the plot (Δz and F/(2πn)²
/// normalised by their ranges), so the curve is evenly resolved where it
/// bends. Points are returned in order of the parameter, which is stored as
/// k.
///
/// Defaults ([`Trace::new`]): 400 points, up to F/(2πn)² = 2 (n the
/// branch's coils, or [`Trace::scale_coils`]).
///
/// ```
/// use hockle::elastica::{Trace, Branch};
/// let c = Trace::new().points(200).max_force_scaled(1.0).run(4, Branch::Upsilon)?;
/// assert_eq!(c.len(), 200);
/// let p = c.points();
/// assert_eq!((p[0].force, p[0].extension), (0.0, 0.0)); // starts at the ring
/// assert!((c.force_scaled(199).unwrap() - 1.0).abs() < 1e-9);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trace {
    points: usize,
    max_force_scaled: f64,
    scale_coils: Option<u32>,
}

impl Default for Trace {
    fn default() -> Self {
        Self::new()
    }
}

/// The last point of a trace meets the force limit to this relative
/// tolerance, or the trace is an error.
const END_TOLERANCE: f64 = 1e-9;

/// Largest q = ln(1/m₁) followed (m₁ ≈ 1e-300).
const Q_MAX: f64 = 690.0;

impl Trace {
    /// 400 points, up to F/(2πn)² = 2, scaled by the branch's own n.
    #[must_use]
    pub fn new() -> Self {
        Self {
            points: 400,
            max_force_scaled: 2.0,
            scale_coils: None,
        }
    }

    /// Number of points (at least 2).
    #[must_use]
    pub fn points(mut self, points: usize) -> Self {
        self.points = points;
        self
    }

    /// Where the branch is cut: F/(2π n_scale)² (positive, finite).
    #[must_use]
    pub fn max_force_scaled(mut self, f: f64) -> Self {
        self.max_force_scaled = f;
        self
    }

    /// The number of coils whose (2πn)² scales the force (the paper uses 4
    /// for every elastica figure); defaults to the branch's n.
    #[must_use]
    pub fn scale_coils(mut self, n: u32) -> Self {
        self.scale_coils = Some(n);
        self
    }

    fn check(&self, n: u32) -> Result<(u32, f64)> {
        check_n(n)?;
        check_points("points", self.points)?;
        if !(self.max_force_scaled.is_finite() && self.max_force_scaled > 0.0) {
            return Err(Error::InvalidArgument {
                name: "max_force_scaled",
                value: self.max_force_scaled,
                allowed: "a finite positive scaled force",
            });
        }
        let sc = self.scale_coils.unwrap_or(n);
        check_n(sc)?;
        Ok((sc, ForceScale::of_coils(sc)?.value()))
    }

    /// The branch `branch` of an n-coil rod from where it starts (the ring
    /// for υ, α and ϑ_n; the bifurcation point for ϑ_j, j ≠ n; the fold for
    /// a secondary arm) up to the force limit.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for n = 0, j = 0, `points` < 2 or > [`MAX_POINTS`](crate::error::MAX_POINTS), or
    /// `scale_coils` = 0; [`Error::InvalidArgument`] for a bad force limit or
    /// one at or below the branch's starting force;
    /// [`Error::SecondaryNeedsOtherPeriods`] for a secondary branch with
    /// j = n.
    pub fn run(&self, n: u32, branch: Branch) -> Result<ForceExtension> {
        let (sc, scale) = self.check(n)?;
        let limit = self.max_force_scaled;
        let path = Path::new(n, branch)?;
        let mut curve =
            ForceExtension::new(format!("{branch}, n = {n}"), "k", ForceScale::of_coils(sc)?);
        curve.extend(path.sample(limit, scale, self.points)?);
        Ok(curve)
    }

    /// The whole secondary branch j of an n-coil rod as one curve: the
    /// lower arm from the force limit down to the fold, then the upper arm
    /// back up (the parameter k therefore first decreases, then increases).
    /// `points` (at least 3) is shared between the arms; the curve has
    /// exactly `points` points (before issue 10 it had one fewer).
    ///
    /// # Errors
    /// As [`Trace::run`]; [`Error::InvalidCount`] for `points` < 3.
    pub fn secondary(&self, n: u32, j: u32) -> Result<ForceExtension> {
        let (sc, scale) = self.check(n)?;
        let limit = self.max_force_scaled;
        check_j(j)?;
        let lower = Path::new(n, Branch::Secondary { j, arm: Arm::Lower })?;
        let upper = Path::new(n, Branch::Secondary { j, arm: Arm::Upper })?;
        if self.points < 3 {
            return Err(Error::InvalidCount {
                name: "points",
                value: self.points as u64,
                allowed: "at least 3 points for a whole secondary branch (both ends and the fold)",
            });
        }
        // the fold is the last point of one arm and the first of the other
        let lower_points = self.points.div_ceil(2);
        let mut a = lower.sample(limit, scale, lower_points)?;
        let b = upper.sample(limit, scale, self.points + 1 - lower_points)?;
        a.reverse();
        let mut curve = ForceExtension::new(
            format!("secondary j = {j}, n = {n}"),
            "k",
            ForceScale::of_coils(sc)?,
        );
        curve.extend(a);
        // the fold point is on both arms: keep it once
        curve.extend(b.into_iter().skip(1));
        Ok(curve)
    }
}

/// A branch as a function of the parameter σ ∈ [0, 1].
pub(crate) struct Path {
    n: u32,
    branch: Branch,
    q0: f64,
    squared: bool,
}

impl Path {
    pub(crate) fn new(n: u32, branch: Branch) -> Result<Self> {
        let (q0, squared) = match branch {
            Branch::Upsilon | Branch::Alpha => (0.0, false),
            Branch::Theta { j } => {
                check_j(j)?;
                if j == n {
                    (0.0, false)
                } else {
                    (
                        -bifurcation(n, j)?.elliptic_modulus().complement().ln(),
                        false,
                    )
                }
            }
            Branch::Secondary { j, .. } => {
                let f = secondary_fold(n, j)?;
                (-f.solution().elliptic_modulus().complement().ln(), true)
            }
        };
        Ok(Self {
            n,
            branch,
            q0,
            squared,
        })
    }

    pub(crate) fn at_q(&self, q: f64) -> Result<Elastica> {
        // m = 1 − e^−q from expm1 while it is small: forces down to
        // F ∝ q ≈ 1e-300 stay resolved
        let md = if q < core::f64::consts::LN_2 {
            Modulus::from_m(-(-q).exp_m1())?
        } else {
            Modulus::from_complement((-q).exp())?
        };
        match self.branch {
            Branch::Upsilon => Ok(primary(self.n, md, Family::Upsilon)),
            Branch::Alpha => Ok(primary(self.n, md, Family::Alpha)),
            Branch::Theta { j } => {
                let v = Elastica::nonsymmetric_with(self.n, j, md)?;
                // at the bifurcation point itself rounding may leave no root:
                // fall back to the bifurcation solution
                match v.first() {
                    Some(e) => Ok(*e),
                    None => Ok(bifurcation(self.n, j)?.solution()),
                }
            }
            Branch::Secondary { j, arm } => Elastica::secondary_arm(self.n, j, arm, md),
        }
    }

    pub(crate) fn q_of(&self, sigma: f64, q_end: f64) -> f64 {
        let s = if self.squared { sigma * sigma } else { sigma };
        self.q0 + (q_end - self.q0) * s
    }

    /// The parameter q where the force reaches `limit_scaled`·`scale`.
    pub(crate) fn q_end(&self, limit_scaled: f64, scale: f64) -> Result<f64> {
        let fmax = limit_scaled * scale;
        let start = self.at_q(self.q0)?;
        if start.force() >= fmax {
            return Err(Error::InvalidArgument {
                name: "max_force_scaled",
                value: limit_scaled,
                allowed: "a limit above the force where the branch starts",
            });
        }
        // followed to m₁ = e^−690, or no further than its start when a
        // branch begins beyond (a bifurcation with n/j near 222)
        let cap = Q_MAX.max(self.q0);
        let mut lo = self.q0;
        let mut hi = (self.q0 + 1.0).max(2.0 * self.q0).min(cap);
        while self.at_q(hi)?.force() < fmax {
            if hi >= cap {
                return Err(Error::ForceOutOfReach {
                    requested: limit_scaled,
                    reachable: self.at_q(cap)?.force() / scale,
                });
            }
            lo = hi;
            hi = (2.0 * hi).min(cap);
        }
        // to the resolution of q (from [0, 1] that is ~1100 halvings for a
        // limit of 1e-300, 60 near 1)
        for _ in 0..1200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if self.at_q(mid)?.force() < fmax {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let reached = self.at_q(hi)?.force();
        let miss = (reached / fmax - 1.0).abs();
        if miss.is_nan() || miss > END_TOLERANCE {
            return Err(Error::InvalidArgument {
                name: "max_force_scaled",
                value: limit_scaled,
                allowed: "a limit the branch meets to 1e-9 in double precision (a modulus m = 1 - e^-q above the subnormal range)",
            });
        }
        Ok(hi)
    }

    fn sample(&self, limit_scaled: f64, scale: f64, points: usize) -> Result<Vec<ForcePoint>> {
        let q_end = self.q_end(limit_scaled, scale)?;
        let eval = |sigma: f64| -> Result<ForcePoint> {
            let e = self.at_q(self.q_of(sigma, q_end))?;
            Ok(ForcePoint {
                extension: e.extension(),
                force: e.force(),
                parameter: e.modulus(),
            })
        };
        let uniform = (points / 2).max(2);
        let mut pts: Vec<(f64, ForcePoint)> = Vec::with_capacity(points);
        for i in 0..uniform {
            let s = i as f64 / (uniform - 1) as f64;
            pts.push((s, eval(s)?));
        }
        let (mut zmin, mut zmax, mut fmin, mut fmx) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for (_, p) in &pts {
            zmin = zmin.min(p.extension);
            zmax = zmax.max(p.extension);
            fmin = fmin.min(p.force);
            fmx = fmx.max(p.force);
        }
        let zs = (zmax - zmin).max(f64::MIN_POSITIVE);
        let fs = (fmx - fmin).max(f64::MIN_POSITIVE);
        let len = |a: &ForcePoint, b: &ForcePoint| {
            ((b.extension - a.extension) / zs).hypot((b.force - a.force) / fs)
        };
        let mut heap = BinaryHeap::new();
        for w in pts.windows(2) {
            heap.push(Segment::new(len(&w[0].1, &w[1].1), w[0], w[1]));
        }
        while pts.len() < points {
            let Some(seg) = heap.pop() else { break };
            let s = 0.5 * (seg.a.0 + seg.b.0);
            let p = eval(s)?;
            pts.push((s, p));
            heap.push(Segment::new(len(&seg.a.1, &p), seg.a, (s, p)));
            heap.push(Segment::new(len(&p, &seg.b.1), (s, p), seg.b));
        }
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(pts.into_iter().map(|(_, p)| p).collect())
    }
}

struct Segment {
    len: f64,
    a: (f64, ForcePoint),
    b: (f64, ForcePoint),
}

impl Segment {
    fn new(len: f64, a: (f64, ForcePoint), b: (f64, ForcePoint)) -> Self {
        Self { len, a, b }
    }
}

impl PartialEq for Segment {
    fn eq(&self, other: &Self) -> bool {
        self.len.total_cmp(&other.len).is_eq()
    }
}
impl Eq for Segment {}
impl PartialOrd for Segment {
    fn partial_cmp(&self, other: &Self) -> Option<core::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Segment {
    fn cmp(&self, other: &Self) -> core::cmp::Ordering {
        self.len.total_cmp(&other.len)
    }
}
