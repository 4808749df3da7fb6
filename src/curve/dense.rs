//! Dense output: the Hermite interpolant of a curve whose points carry
//! their slopes (and curvatures), and what a user reads off it.
//!
//! Between points i and i+1, with parameter step h = t_{i+1} − t_i, in
//! τ = (t − t_i)/h, each axis x (the extension or the force) is the
//! polynomial Σ c_k τ^k that matches the ends' values, slopes x′ = dx/dt
//! (v = h x′) and, where both ends carry them, curvatures x″ = d²x/dt²
//! (a = h² x″), with Δ = x_{i+1} − x_i:
//!
//! ```text
//!   quintic:  c = (x_i, v_i, a_i/2, 10Δ − 6v_i − 4v_{i+1} − (3a_i − a_{i+1})/2,
//!                  −15Δ + 8v_i + 7v_{i+1} + (3a_i − 2a_{i+1})/2,
//!                  6Δ − 3v_i − 3v_{i+1} − (a_i − a_{i+1})/2)
//!   cubic:    c = (x_i, v_i, 3Δ − 2v_i − v_{i+1}, −2Δ + v_i + v_{i+1})
//! ```
//!
//! The quintic's error is h⁶ ‖x⁽⁶⁾‖ / 46080, the cubic's h⁴ ‖x⁗‖ / 384. A
//! segment next to a point without a finite slope, whose parameter does
//! not increase, or whose end slopes reach over 32 times its chord in the
//! plane (the parameter moved where the plane does not see it), is linear
//! in τ.

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

/// The second derivative of a curve point along the curve's parameter t:
/// (d²Δz/dt², d²F/dt²).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Curvature {
    /// d²Δz/dt².
    pub extension: f64,
    /// d²F/dt² (the physical force, as [`ForcePoint::force`]).
    pub force: f64,
}

/// The most a segment's end slopes may reach, over its parameter step,
/// beyond its chord in the plane before the segment is drawn linear
/// ([`ForceExtension::slopes_overreach`]). A smooth step reaches about its
/// chord; measured on pulls of five springs at tolerances 1e-2 … 1e-8 (the
/// paper's, a slinky, n = 6, ν = −0.5 pinned): at most 4.5 (short
/// segments at located folds), and 6·10⁴ on the segment that wandered to
/// Δz = 3·10⁴. 32 is seven times the first and far below the second.
const OVERREACH: f64 = 32.0;

/// Subintervals of [0, 1] on which a segment's derivative is sampled for
/// sign changes when the segment is a quintic (a pair of turning points
/// closer than 1/64 of a segment, a wiggle far below any interpolant's
/// accuracy, may be seen as none).
const TURNING_SAMPLES: usize = 64;

/// Above this largest coefficient a segment is summed scaled by it (a
/// power of two, 2⁹⁰⁰: six terms of at most 2¹²⁴ after scaling cannot
/// overflow, and dividing by a power of two is exact unless a coefficient
/// is below 2⁻¹²², negligible beside the largest, above 2⁹⁰⁰).
const HORNER_SCALED_ABOVE: f64 = 8.452_712_498_170_644e270;

/// The polynomial x(τ) = Σ c_k τ^k (degree ≤ 5) of one axis on one segment,
/// and its value at τ = 1: the next node's, exactly. (Σ c_k rounds a few
/// ulps away from it, and a value between the two would be crossed by
/// neither of the segments that meet there, or by both.)
#[derive(Debug, Clone, Copy)]
struct Segment([f64; 6], f64);

impl Segment {
    fn quintic(x: (f64, f64), v: (f64, f64), a: (f64, f64)) -> Self {
        let d = x.1 - x.0;
        Segment(
            [
                x.0,
                v.0,
                0.5 * a.0,
                10.0 * d - 6.0 * v.0 - 4.0 * v.1 - 0.5 * (3.0 * a.0 - a.1),
                -15.0 * d + 8.0 * v.0 + 7.0 * v.1 + 0.5 * (3.0 * a.0 - 2.0 * a.1),
                6.0 * d - 3.0 * v.0 - 3.0 * v.1 - 0.5 * (a.0 - a.1),
            ],
            x.1,
        )
    }

    fn cubic(x: (f64, f64), v: (f64, f64)) -> Self {
        let d = x.1 - x.0;
        Segment(
            [
                x.0,
                v.0,
                3.0 * d - 2.0 * v.0 - v.1,
                -2.0 * d + v.0 + v.1,
                0.0,
                0.0,
            ],
            x.1,
        )
    }

    fn linear(x0: f64, x1: f64) -> Self {
        Segment([x0, x1 - x0, 0.0, 0.0, 0.0, 0.0], x1)
    }

    /// Whether every coefficient is finite (a Hermite segment of finite
    /// data near the ends of the double range can overflow: it is then
    /// read at a lower degree).
    fn is_finite(&self) -> bool {
        self.0.iter().all(|c| c.is_finite())
    }

    fn at(&self, t: f64) -> f64 {
        if t >= 1.0 {
            return self.1;
        }
        let big = self.0.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
        if big.is_infinite() {
            // a line whose rise overflows: (1 − τ) x₀ + τ x₁ does not
            return (1.0 - t) * self.0[0] + t * self.1;
        }
        if big > HORNER_SCALED_ABOVE {
            // Horner's partial sums of coefficients near the largest double
            // overflow (∞ − ∞ = NaN) where the value does not: sum them
            // scaled by a power of two, exactly
            let scale = HORNER_SCALED_ABOVE;
            let sum = self.0.iter().rev().fold(0.0, |acc, c| acc * t + c / scale);
            return sum * scale;
        }
        self.0.iter().rev().fold(0.0, |acc, c| acc * t + c)
    }

    fn derivative_at(&self, t: f64) -> f64 {
        self.0
            .iter()
            .enumerate()
            .skip(1)
            .rev()
            .fold(0.0, |acc, (k, c)| acc * t + k as f64 * c)
    }

    /// The turning points τ ∈ (0, 1), in increasing order: the real roots
    /// of the derivative, in closed form for a cubic, by bisection of its
    /// sign changes on [`TURNING_SAMPLES`] subintervals for a quintic.
    fn turning_points(&self) -> Vec<f64> {
        let [_, b, c, d, e, f] = self.0;
        let mut crit = Vec::new();
        if e != 0.0 || f != 0.0 {
            let mut lo = 0.0;
            let mut flo = self.derivative_at(lo);
            for i in 1..=TURNING_SAMPLES {
                let hi = i as f64 / TURNING_SAMPLES as f64;
                let fhi = self.derivative_at(hi);
                if opposite(flo, fhi) {
                    crit.push(bisect(|t| self.derivative_at(t), lo, hi, flo));
                } else if fhi == 0.0 && i < TURNING_SAMPLES {
                    crit.push(hi);
                }
                (lo, flo) = (hi, fhi);
            }
            return crit;
        }
        // x'(τ) = b + 2cτ + 3dτ², divided by its largest coefficient (the
        // discriminant's squares underflow for a segment of forces ~1e-200
        // and overflow for ~1e200; the roots are the same)
        let big = (3.0 * d).abs().max((2.0 * c).abs()).max(b.abs());
        if !(big > 0.0 && big.is_finite()) {
            return crit;
        }
        let (qa, qb, qc) = (3.0 * d / big, 2.0 * c / big, b / big);
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
        crit.retain(|t| *t > 0.0 && *t < 1.0);
        crit
    }

    /// The τ ∈ [0, 1] where the segment equals `v`, in increasing order:
    /// bisection on each monotone piece between its turning points.
    fn solve(&self, v: f64) -> Vec<f64> {
        let mut cuts = vec![0.0];
        cuts.extend(self.turning_points());
        cuts.push(1.0);
        let mut roots: Vec<f64> = Vec::new();
        for w in cuts.windows(2) {
            let (lo, hi) = (w[0], w[1]);
            let (flo, fhi) = (self.at(lo) - v, self.at(hi) - v);
            if flo == 0.0 {
                roots.push(lo);
                continue;
            }
            if fhi == 0.0 {
                roots.push(hi);
                continue;
            }
            if !opposite(flo, fhi) {
                continue;
            }
            roots.push(bisect(|t| self.at(t) - v, lo, hi, flo));
        }
        roots.dedup_by(|a, b| (*a - *b).abs() <= 4.0 * f64::EPSILON);
        roots
    }
}

/// Whether `a` and `b` are non-zero and of opposite signs (not by their
/// product, which underflows to 0 for two tiny values, e.g. 1e-300 and
/// −1e-30, and then looked like a root between them).
fn opposite(a: f64, b: f64) -> bool {
    (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0)
}

/// The root of `f` in [lo, hi) (f(lo) = `flo`, f(hi) of the other sign),
/// by bisection to the last bit. Never `hi` itself: a root there (f(hi) =
/// 0) is the caller's to report, and a crossing between the last two
/// floats below `hi` belongs to this interval, not to the one starting at
/// `hi`.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, flo: f64) -> f64 {
    let end = hi;
    // (1100: from [0, 1] down to the smallest subnormal takes 1075)
    for _ in 0..1100 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let fmid = f(mid);
        if fmid == 0.0 {
            return mid;
        }
        if !opposite(fmid, flo) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let mid = 0.5 * (lo + hi);
    if mid >= end { lo } else { mid }
}

impl ForceExtension {
    /// Appends a point with its slope along the parameter (the data of the
    /// cubic dense output).
    pub fn push_with_slope(&mut self, point: ForcePoint, slope: Slope) {
        self.align_derivatives();
        self.points.push(point);
        self.slopes.push(Some(slope));
        self.curvatures.push(None);
    }

    /// Appends a point with its slope and curvature along the parameter
    /// (the data of the quintic dense output, used on the segments whose
    /// both ends have them).
    pub fn push_with_curvature(&mut self, point: ForcePoint, slope: Slope, curvature: Curvature) {
        self.align_derivatives();
        self.points.push(point);
        self.slopes.push(Some(slope));
        self.curvatures.push(Some(curvature));
    }

    /// The slope of point `i`, or `None` where none was given (or past the
    /// end).
    #[must_use]
    pub fn slope(&self, i: usize) -> Option<Slope> {
        self.slopes.get(i).copied().flatten()
    }

    /// The curvature of point `i`, or `None` where none was given (or
    /// past the end).
    #[must_use]
    pub fn curvature(&self, i: usize) -> Option<Curvature> {
        self.curvatures.get(i).copied().flatten()
    }

    /// Whether the end slopes of segment i, over its parameter step `h`,
    /// reach more than [`OVERREACH`] times its chord in the plane
    /// (Δz, F/((2πn)²B)): the parameter then moved mostly along
    /// directions the plane does not see (a loop sliding, where a failing
    /// run's last steps spent arclengths of 10³ on chords of 10⁻⁴), the
    /// slopes do not describe the segment, and its Hermite polynomial would
    /// wander far off it (measured: to Δz = 3·10⁴ on such a segment).
    fn slopes_overreach(&self, i: usize, h: f64, (sa, sb): (Slope, Slope)) -> bool {
        let (a, b) = (self.points[i], self.points[i + 1]);
        let scale = self.force_scale();
        let chord = (b.extension - a.extension)
            .abs()
            .max((b.force - a.force).abs() / scale);
        let reach = |s: Slope| h * s.extension.abs().max(s.force.abs() / scale);
        reach(sa).max(reach(sb)) > OVERREACH * chord
    }

    /// The two polynomials (extension, force) of segment i (points i, i+1).
    fn segment(&self, i: usize) -> (Segment, Segment) {
        let (a, b) = (self.points[i], self.points[i + 1]);
        let h = b.parameter - a.parameter;
        let ends = (a.extension, b.extension);
        let forces = (a.force, b.force);
        let (Some(sa), Some(sb)) = (self.slope(i), self.slope(i + 1)) else {
            return (
                Segment::linear(ends.0, ends.1),
                Segment::linear(forces.0, forces.1),
            );
        };
        if !(sa.is_finite() && sb.is_finite() && h > 0.0 && h.is_finite())
            || self.slopes_overreach(i, h, (sa, sb))
        {
            return (
                Segment::linear(ends.0, ends.1),
                Segment::linear(forces.0, forces.1),
            );
        }
        let v = (
            (h * sa.extension, h * sb.extension),
            (h * sa.force, h * sb.force),
        );
        if let (Some(ca), Some(cb)) = (self.curvature(i), self.curvature(i + 1)) {
            let h2 = h * h;
            let quintic = (
                Segment::quintic(ends, v.0, (h2 * ca.extension, h2 * cb.extension)),
                Segment::quintic(forces, v.1, (h2 * ca.force, h2 * cb.force)),
            );
            if quintic.0.is_finite() && quintic.1.is_finite() {
                return quintic;
            }
        }
        let cubic = (Segment::cubic(ends, v.0), Segment::cubic(forces, v.1));
        if cubic.0.is_finite() && cubic.1.is_finite() {
            return cubic;
        }
        (
            Segment::linear(ends.0, ends.1),
            Segment::linear(forces.0, forces.1),
        )
    }

    /// The point of the interpolant on segment `i` (points i, i+1) at
    /// τ ∈ [0, 1] (module docs), or `None` past the last segment or for τ
    /// outside [0, 1] (no extrapolation).
    ///
    /// ```
    /// use hockle::curve::Slope;
    /// use hockle::{ForceExtension, ForcePoint, ForceScale};
    /// let mut c = ForceExtension::new("cubic", "t", ForceScale::of_coils(1)?);
    /// c.push_with_slope(ForcePoint { extension: 0.0, force: 0.0, parameter: 0.0 },
    ///                   Slope { extension: 1.0, force: 0.0 });
    /// c.push_with_slope(ForcePoint { extension: 1.0, force: 1.0, parameter: 1.0 },
    ///                   Slope { extension: 1.0, force: 3.0 });
    /// let p = c.at(0, 0.5).unwrap();
    /// assert!((p.extension - 0.5).abs() < 1e-15 && (p.force - 0.125).abs() < 1e-15);
    /// # Ok::<(), hockle::Error>(())
    /// ```
    #[must_use]
    pub fn at(&self, segment: usize, tau: f64) -> Option<ForcePoint> {
        if segment + 1 >= self.points.len() || !(0.0..=1.0).contains(&tau) {
            return None;
        }
        let (x, f) = self.segment(segment);
        let (a, b) = (self.points[segment], self.points[segment + 1]);
        Some(ForcePoint {
            extension: x.at(tau),
            force: f.at(tau),
            parameter: a.parameter + tau * (b.parameter - a.parameter),
        })
    }

    /// Every τ ∈ [0, 1] at which the interpolant of segment `i` has the
    /// force (`force_axis`) or the extension `v`, in increasing order; none
    /// past the last segment.
    pub(crate) fn crossings_on(&self, i: usize, v: f64, force_axis: bool) -> Vec<f64> {
        if i + 1 >= self.points.len() || !v.is_finite() {
            return Vec::new();
        }
        let (x, f) = self.segment(i);
        if force_axis { f.solve(v) } else { x.solve(v) }
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
    /// a multivalued stretch, none outside the curve. Read off the Hermite
    /// interpolant of the points, their slopes and curvatures (module docs;
    /// cubic where curvatures are unknown, linear where slopes are
    /// unknown).
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

    /// With curvatures the interpolant is the quintic: x = t, F = t⁵ − t²
    /// sampled at t = 0 and 1 with slopes and curvatures is read back
    /// exactly, and a turning point inside the segment is seen (F = t⁵ − t²
    /// falls to −0.3257 at t = (2/5)^(1/3) and rises again).
    #[test]
    fn quintic_with_curvatures() {
        let mut c = ForceExtension::new("quintic", "t", ForceScale::of_coils(1).unwrap());
        for t in [0.0_f64, 1.0] {
            c.push_with_curvature(
                ForcePoint {
                    extension: t,
                    force: t.powi(5) - t * t,
                    parameter: t,
                },
                Slope {
                    extension: 1.0,
                    force: 5.0 * t.powi(4) - 2.0 * t,
                },
                Curvature {
                    extension: 0.0,
                    force: 20.0 * t.powi(3) - 2.0,
                },
            );
        }
        for t in [0.1, 0.37, 0.8] {
            let p = c.at(0, t).unwrap();
            assert!((p.force - (t.powi(5) - t * t)).abs() < 1e-15, "{p:?}");
            assert_eq!(c.force_at(t).len(), 1);
        }
        // outside the segment (or past the last one) there is no point
        assert!(c.at(0, 1.5).is_none() && c.at(0, f64::NAN).is_none() && c.at(1, 0.5).is_none());
        let low = 0.4_f64.cbrt();
        let f_low = low.powi(5) - low * low;
        // F = −0.2 is crossed twice, before and after the turning point
        let x = c.extension_at(-0.2);
        assert_eq!(x.len(), 2, "{x:?}");
        assert!(x[0] < low && x[1] > low);
        assert!(c.extension_at(f_low - 1e-9).is_empty());
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

    #[test]
    fn slopes_that_overreach_the_chord_give_a_line() {
        // the last segment of a failing pull of the paper's spring with 32
        // coils (tol 1e-6, F in units of (2πn)²B, scale 1): a chord of
        // 7.9e-5 over a parameter step of 1690 with slopes of 2.9e-3 in
        // Δz; its cubic reached Δz = 3·10⁴
        let mut c = ForceExtension::new("slide", "t", ForceScale::of_coils(1).unwrap());
        let scale = c.force_scale();
        c.push_with_slope(
            ForcePoint {
                extension: 0.976_882_5,
                force: 0.9665 * scale,
                parameter: 324.7,
            },
            Slope {
                extension: 2.916e-3,
                force: 0.1937 * scale,
            },
        );
        c.push_with_slope(
            ForcePoint {
                extension: 0.976_961_2,
                force: 0.9694 * scale,
                parameter: 2015.0,
            },
            Slope {
                extension: 2.939e-3,
                force: 0.1973 * scale,
            },
        );
        for k in 0..=10 {
            let p = c.at(0, f64::from(k) / 10.0).unwrap();
            // linear: between the ends (to rounding)
            assert!(p.extension >= 0.976_882_5 - 1e-15 && p.extension <= 0.976_961_2 + 1e-15);
        }
        assert!(c.extension_at(10.0 * scale).is_empty());
        // the same ends with slopes that match the chord keep the cubic
        let mut d = ForceExtension::new("cubic", "t", ForceScale::of_coils(1).unwrap());
        d.push_with_slope(
            ForcePoint {
                extension: 0.0,
                force: 0.0,
                parameter: 0.0,
            },
            Slope {
                extension: 1.0,
                force: 0.0,
            },
        );
        d.push_with_slope(
            ForcePoint {
                extension: 1.0,
                force: scale,
                parameter: 1.0,
            },
            Slope {
                extension: 1.0,
                force: 3.0 * scale,
            },
        );
        // F = Δz³ exactly: a cubic, not the line's 0.5
        assert!((d.force_at(0.5)[0] / scale - 0.125).abs() < 1e-15);
    }
}
