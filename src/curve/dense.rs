//! Dense output: the cubic Hermite interpolant of a curve whose points
//! carry their slopes, and what a user reads off it.
//!
//! Between points i and i+1, with parameter step h = t_{i+1} − t_i and
//! slopes x′ = dx/dt (x the extension or the force), in τ = (t − t_i)/h:
//!
//! ```text
//!   x(τ) = x_i + h x′_i τ + (3 (x_{i+1} − x_i) − h (2 x′_i + x′_{i+1})) τ²
//!              + (2 (x_i − x_{i+1}) + h (x′_i + x′_{i+1})) τ³
//! ```
//!
//! A segment next to a point without a finite slope, or whose parameter
//! does not increase, is linear in τ.

use super::{ForceExtension, ForcePoint};

/// The derivative of a curve point along the curve's parameter t:
/// (dΔz/dt, dF/dt).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Slope {
    /// dΔz/dt.
    pub extension: f64,
    /// dF/dt (the physical force, as [`ForcePoint::force`]).
    pub force: f64,
}

impl Slope {
    fn is_finite(&self) -> bool {
        self.extension.is_finite() && self.force.is_finite()
    }
}

/// The cubic (or linear) x(τ) = c₀ + c₁τ + c₂τ² + c₃τ³ of one axis on one
/// segment.
#[derive(Debug, Clone, Copy)]
struct Cubic([f64; 4]);

impl Cubic {
    fn hermite(x0: f64, x1: f64, d0: f64, d1: f64) -> Self {
        Cubic([
            x0,
            d0,
            3.0 * (x1 - x0) - 2.0 * d0 - d1,
            2.0 * (x0 - x1) + d0 + d1,
        ])
    }

    fn linear(x0: f64, x1: f64) -> Self {
        Cubic([x0, x1 - x0, 0.0, 0.0])
    }

    fn at(&self, t: f64) -> f64 {
        let [a, b, c, d] = self.0;
        a + t * (b + t * (c + t * d))
    }

    /// The τ ∈ [0, 1] where the cubic equals `v`, in increasing order:
    /// bisection on each monotone piece between the zeros of its
    /// derivative.
    fn solve(&self, v: f64) -> Vec<f64> {
        let [_, b, c, d] = self.0;
        let mut cuts = vec![0.0];
        // x'(τ) = b + 2cτ + 3dτ²
        let (qa, qb, qc) = (3.0 * d, 2.0 * c, b);
        let mut crit = Vec::new();
        if qa.abs() > 1e-14 * (qb.abs() + qc.abs()) {
            let disc = qb * qb - 4.0 * qa * qc;
            if disc >= 0.0 {
                let r = disc.sqrt();
                let q = -0.5 * (qb + qb.signum() * r);
                if q != 0.0 {
                    crit.push(q / qa);
                    crit.push(qc / q);
                }
            }
        } else if qb != 0.0 {
            crit.push(-qc / qb);
        }
        crit.sort_by(f64::total_cmp);
        cuts.extend(crit.into_iter().filter(|t| *t > 0.0 && *t < 1.0));
        cuts.push(1.0);
        let mut roots: Vec<f64> = Vec::new();
        for w in cuts.windows(2) {
            let (mut lo, mut hi) = (w[0], w[1]);
            let (flo, fhi) = (self.at(lo) - v, self.at(hi) - v);
            if flo == 0.0 {
                roots.push(lo);
                continue;
            }
            if fhi == 0.0 {
                roots.push(hi);
                continue;
            }
            if flo * fhi > 0.0 {
                continue;
            }
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                if (self.at(mid) - v) * flo > 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            roots.push(0.5 * (lo + hi));
        }
        roots.dedup_by(|a, b| (*a - *b).abs() <= 4.0 * f64::EPSILON);
        roots
    }
}

impl ForceExtension {
    /// Appends a point with its slope along the parameter (the data of the
    /// dense output).
    pub fn push_with_slope(&mut self, point: ForcePoint, slope: Slope) {
        self.points.push(point);
        self.slopes.push(Some(slope));
    }

    /// The slope of point `i`, or `None` where none was given (or past the
    /// end).
    #[must_use]
    pub fn slope(&self, i: usize) -> Option<Slope> {
        self.slopes.get(i).copied().flatten()
    }

    /// The two cubics (extension, force) of segment i (points i, i+1).
    fn segment(&self, i: usize) -> (Cubic, Cubic) {
        let (a, b) = (self.points[i], self.points[i + 1]);
        let h = b.parameter - a.parameter;
        if let (Some(sa), Some(sb)) = (self.slope(i), self.slope(i + 1))
            && sa.is_finite()
            && sb.is_finite()
            && h > 0.0
            && h.is_finite()
        {
            (
                Cubic::hermite(a.extension, b.extension, h * sa.extension, h * sb.extension),
                Cubic::hermite(a.force, b.force, h * sa.force, h * sb.force),
            )
        } else {
            (
                Cubic::linear(a.extension, b.extension),
                Cubic::linear(a.force, b.force),
            )
        }
    }

    /// Every point of the interpolant where `axis(point) = v`, in curve
    /// order, as (extension, force).
    fn crossings(&self, v: f64, force_axis: bool) -> Vec<(f64, f64)> {
        let mut out = Vec::new();
        if !v.is_finite() {
            return out;
        }
        let last = self.points.len().saturating_sub(1);
        for i in 0..last {
            let (x, f) = self.segment(i);
            let (on, other) = if force_axis { (f, x) } else { (x, f) };
            for t in on.solve(v) {
                // a node belongs to the segment it starts
                if t >= 1.0 && i + 1 < last {
                    continue;
                }
                let pair = if force_axis {
                    (other.at(t), v)
                } else {
                    (v, other.at(t))
                };
                out.push(pair);
            }
        }
        if last == 0
            && let Some(p) = self.points.first()
        {
            let at = if force_axis { p.force } else { p.extension };
            if at == v {
                out.push((p.extension, p.force));
            }
        }
        out
    }

    /// Every force F (physical, as [`ForcePoint::force`]) at which the
    /// curve passes through the extension Δz, in curve order: several on
    /// a multivalued stretch, none outside the curve. Read off the cubic
    /// Hermite interpolant of the points and their slopes (module docs;
    /// linear where slopes are unknown).
    ///
    /// ```
    /// use hockle::curve::Slope;
    /// use hockle::{ForceExtension, ForcePoint, ForceScale};
    /// // F = Δz³ sampled at Δz = 0, 1 with its slopes along t = Δz
    /// let mut c = ForceExtension::new("cubic", "t", ForceScale::of_coils(1)?);
    /// c.push_with_slope(ForcePoint { extension: 0.0, force: 0.0, parameter: 0.0 },
    ///                   Slope { extension: 1.0, force: 0.0 });
    /// c.push_with_slope(ForcePoint { extension: 1.0, force: 1.0, parameter: 1.0 },
    ///                   Slope { extension: 1.0, force: 3.0 });
    /// let f = c.force_at(0.5);
    /// assert_eq!(f.len(), 1);
    /// assert!((f[0] - 0.125).abs() < 1e-15); // exact for a cubic
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn force_at(&self, extension: f64) -> Vec<f64> {
        self.crossings(extension, false)
            .into_iter()
            .map(|(_, f)| f)
            .collect()
    }

    /// Every extension Δz at which the curve passes through the force F
    /// (physical), in curve order ([`Self::force_at`]'s converse).
    #[must_use]
    pub fn extension_at(&self, force: f64) -> Vec<f64> {
        self.crossings(force, true)
            .into_iter()
            .map(|(x, _)| x)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ForceScale;

    fn circle(points: usize) -> ForceExtension {
        // the unit circle x = cos t, F = sin t, t ∈ [0, 2π]
        let mut c = ForceExtension::new("circle", "t", ForceScale::of_coils(1).unwrap());
        for i in 0..=points {
            let t = std::f64::consts::TAU * i as f64 / points as f64;
            c.push_with_slope(
                ForcePoint {
                    extension: t.cos(),
                    force: t.sin(),
                    parameter: t,
                },
                Slope {
                    extension: -t.sin(),
                    force: t.cos(),
                },
            );
        }
        c
    }

    /// A multivalued curve gives every branch, each to the Hermite error
    /// h⁴/384 of the circle (h = 2π/64: 1.6e-7; checked to 1e-6).
    #[test]
    fn circle_both_branches() {
        let c = circle(64);
        let f = c.force_at(0.3);
        assert_eq!(f.len(), 2, "{f:?}");
        let exact = (1.0 - 0.09_f64).sqrt();
        assert!(
            (f[0] - exact).abs() < 1e-6 && (f[1] + exact).abs() < 1e-6,
            "{f:?}"
        );
        let x = c.extension_at(-0.5);
        assert_eq!(x.len(), 2, "{x:?}");
        assert!(x.iter().all(|v| (v.abs() - 0.75_f64.sqrt()).abs() < 1e-6));
        assert!(c.force_at(1.5).is_empty());
        assert!(c.force_at(f64::NAN).is_empty());
    }

    /// Nodes are reported once.
    #[test]
    fn nodes_once() {
        let c = circle(4); // nodes at x = 1, 0, −1, 0, 1
        assert_eq!(c.force_at(-1.0).len(), 1);
    }

    /// Without slopes the interpolant is linear.
    #[test]
    fn linear_without_slopes() {
        let mut c = ForceExtension::new("line", "t", ForceScale::of_coils(1).unwrap());
        c.push(ForcePoint {
            extension: 0.0,
            force: 0.0,
            parameter: 0.0,
        });
        c.push(ForcePoint {
            extension: 1.0,
            force: 2.0,
            parameter: 1.0,
        });
        assert_eq!(c.force_at(0.25), vec![0.5]);
    }
}
