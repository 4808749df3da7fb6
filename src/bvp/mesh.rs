//! The mesh: interval boundaries on [0, 1].

use std::fmt;

use crate::error::{Error, Result};

/// Interval boundaries 0 = t₀ < t₁ < … < t_N = 1.
///
/// ```
/// use hockle::bvp::Mesh;
/// let mesh = Mesh::uniform(4)?;
/// assert_eq!(mesh.intervals(), 4);
/// assert_eq!(mesh.points(), &[0.0, 0.25, 0.5, 0.75, 1.0]);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Mesh {
    points: Vec<f64>,
}

/// The interval-count check shared by the constructors.
fn check_intervals(intervals: usize) -> Result<()> {
    if (1..=Mesh::MAX_INTERVALS).contains(&intervals) {
        return Ok(());
    }
    Err(Error::InvalidCount {
        name: "intervals",
        value: intervals as u64,
        allowed: "1..=1_000_000 (Mesh::MAX_INTERVALS)",
    })
}

impl Mesh {
    /// The most intervals a mesh may have, 10⁶ (8 MB of mesh points; the
    /// collocation system on it is limited separately, to 2 GiB of
    /// workspace, see [`Error::SystemTooLarge`]).
    pub const MAX_INTERVALS: usize = 1_000_000;

    /// N equal intervals.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] unless 1 ≤ N ≤ [`Mesh::MAX_INTERVALS`].
    pub fn uniform(intervals: usize) -> Result<Mesh> {
        check_intervals(intervals)?;
        let n = intervals as f64;
        let mut points: Vec<f64> = (0..=intervals).map(|j| j as f64 / n).collect();
        points[intervals] = 1.0;
        Ok(Mesh { points })
    }

    /// A mesh from its boundaries.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] unless the points start at 0, end at 1 and
    /// strictly increase (at least two points);
    /// [`Error::InvalidCount`] for more than [`Mesh::MAX_INTERVALS`]
    /// intervals.
    pub fn from_points(points: Vec<f64>) -> Result<Mesh> {
        check_intervals(points.len().saturating_sub(1).max(1))?;
        if points.len() < 2 {
            return Err(Error::InvalidCount {
                name: "mesh points",
                value: points.len() as u64,
                allowed: "at least 2 (0 and 1)",
            });
        }
        if points[0] != 0.0 {
            return Err(Error::InvalidArgument {
                name: "first mesh point",
                value: points[0],
                allowed: "exactly 0",
            });
        }
        if points[points.len() - 1] != 1.0 {
            return Err(Error::InvalidArgument {
                name: "last mesh point",
                value: points[points.len() - 1],
                allowed: "exactly 1",
            });
        }
        for w in points.windows(2) {
            if w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater) {
                return Err(Error::InvalidArgument {
                    name: "mesh point",
                    value: w[1],
                    allowed: "strictly greater than the previous point",
                });
            }
        }
        Ok(Mesh { points })
    }

    /// Every interval split at its midpoint: 2N intervals, the mesh on
    /// which a solution's error is measured by comparison (the rod's
    /// halved-mesh check, `Collocation::tolerance`'s verification).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if 2N exceeds [`Mesh::MAX_INTERVALS`],
    /// [`Error::InvalidArgument`] if an interval is too narrow to split in
    /// floating point.
    pub fn halved(&self) -> Result<Mesh> {
        check_intervals(2 * self.intervals())?;
        let mut points = Vec::with_capacity(2 * self.points.len() - 1);
        for w in self.points.windows(2) {
            points.push(w[0]);
            points.push(0.5 * (w[0] + w[1]));
        }
        points.push(self.points[self.points.len() - 1]);
        Mesh::from_points(points)
    }

    /// The number of intervals N.
    #[must_use]
    pub fn intervals(&self) -> usize {
        self.points.len() - 1
    }

    /// The N + 1 boundaries.
    #[must_use]
    pub fn points(&self) -> &[f64] {
        &self.points
    }

    /// The width of interval j.
    ///
    /// # Panics
    /// If `j ≥ N`.
    #[must_use]
    pub fn width(&self, j: usize) -> f64 {
        self.points[j + 1] - self.points[j]
    }

    /// The interval holding s (clamped to [0, 1]) and the local coordinate
    /// θ = (s − t_j)/h_j ∈ [0, 1].
    pub(crate) fn locate(&self, s: f64) -> (usize, f64) {
        let s = s.clamp(0.0, 1.0);
        let n = self.intervals();
        let j = match self.points.binary_search_by(|p| p.total_cmp(&s)) {
            Ok(i) => i.min(n - 1),
            Err(i) => (i.max(1) - 1).min(n - 1),
        };
        (j, (s - self.points[j]) / self.width(j))
    }
}

impl fmt::Display for Mesh {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (mut lo, mut hi) = (f64::INFINITY, 0.0_f64);
        for j in 0..self.intervals() {
            lo = lo.min(self.width(j));
            hi = hi.max(self.width(j));
        }
        write!(
            f,
            "mesh of {} intervals, h ∈ [{lo:.3e}, {hi:.3e}]",
            self.intervals()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn halved_splits_every_interval_at_its_midpoint() {
        let mesh = Mesh::from_points(vec![0.0, 0.25, 0.5, 1.0]).unwrap();
        let half = mesh.halved().unwrap();
        // midpoints of dyadic intervals are exact in binary
        assert_eq!(
            half.points(),
            &[0.0, 0.125, 0.25, 0.375, 0.5, 0.75, 1.0][..]
        );
    }

    #[test]
    fn halving_past_the_interval_limit_is_refused_before_allocating() {
        let mesh = Mesh::uniform(Mesh::MAX_INTERVALS / 2 + 1).unwrap();
        assert!(matches!(mesh.halved(), Err(Error::InvalidCount { .. })));
    }
}
