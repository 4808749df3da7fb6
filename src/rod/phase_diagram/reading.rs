//! Reading θ0_c of a pop-out off the lines at fixed ν: along each line in
//! ln A/B, between lines in ν with their tips aligned.

use std::ops::RangeInclusive;

use super::{CuspAt, CuspLine, Fixed, LineEnd, PhaseDiagram};

impl PhaseDiagram {
    /// [`Self::cusp_theta0`] and, where it is a range, why.
    pub(super) fn bounds(
        &self,
        i: usize,
        a_over_b: f64,
        nu: f64,
    ) -> (RangeInclusive<f64>, &'static str) {
        let mut at: Vec<(f64, &CuspLine)> = self
            .lines
            .iter()
            .filter(|l| l.pop_out == i)
            .filter_map(|l| match l.fixed {
                Fixed::Nu(v) => Some((v, l)),
                Fixed::AOverB(_) => None,
            })
            .collect();
        at.sort_by(|a, b| a.0.total_cmp(&b.0));
        let half_pi = core::f64::consts::FRAC_PI_2;
        let x = a_over_b.ln();
        let b = match at.iter().position(|(v, _)| *v >= nu) {
            None => at.last().map_or(Bounds::exact(half_pi), |a| along(a.1, x)),
            Some(0) => along(at[0].1, x),
            Some(k) => {
                let ((v0, l0), (v1, l1)) = (at[k - 1], at[k]);
                let t = (nu - v0) / (v1 - v0);
                match aligned(l0, l1, t, x) {
                    None => Bounds::exact(half_pi),
                    Some([x0, x1]) => {
                        let (b0, b1) = (along(l0, x0), along(l1, x1));
                        Bounds {
                            lo: b0.lo + t * (b1.lo - b0.lo),
                            hi: b0.hi + t * (b1.hi - b0.hi),
                            why: b0.why.or(b1.why),
                        }
                    }
                }
            }
        };
        (b.lo..=b.hi, b.why.unwrap_or(""))
    }
}

/// Where θ0_c lies, and why it is a range.
#[derive(Debug, Clone, Copy)]
struct Bounds {
    lo: f64,
    hi: f64,
    why: Option<&'static str>,
}

impl Bounds {
    fn exact(t: f64) -> Self {
        Self {
            lo: t,
            hi: t,
            why: None,
        }
    }
}

/// θ0_c along a line at fixed ν at x = ln(A/B), linear in x on each segment of
/// the polyline: beyond the ends as their [`LineEnd`]s say; where several
/// segments cover the A/B (the line turns back at swallowtails), the range
/// of their values.
fn along(line: &CuspLine, x: f64) -> Bounds {
    let half_pi = core::f64::consts::FRAC_PI_2;
    let points = &line.points;
    let beyond = |end: LineEnd, p: &CuspAt| match end {
        LineEnd::Tip => Bounds::exact(half_pi),
        LineEnd::Range => Bounds::exact(p.theta0),
        LineEnd::Unfinished(_) => Bounds {
            lo: 0.0,
            hi: half_pi,
            why: Some("the continuation of its cusp line ended before this scene"),
        },
    };
    let (Some(first), Some(last)) = (points.first(), points.last()) else {
        return Bounds::exact(half_pi);
    };
    if x < first.a_over_b.ln() {
        return beyond(line.ends[0], first);
    }
    if x > last.a_over_b.ln() || points.len() == 1 {
        return beyond(line.ends[1], last);
    }
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for w in points.windows(2) {
        let (x0, x1) = (w[0].a_over_b.ln(), w[1].a_over_b.ln());
        if x < x0.min(x1) || x > x0.max(x1) {
            continue;
        }
        let t = if x1 == x0 { 0.0 } else { (x - x0) / (x1 - x0) };
        let v = w[0].theta0 + t * (w[1].theta0 - w[0].theta0);
        lo = lo.min(v);
        hi = hi.max(v);
    }
    // A/B is between the first and the last point, so some segment covers it.
    Bounds {
        lo,
        hi,
        why: (hi > lo).then_some(
            "its cusp line turns back over this A/B (swallowtails of the cusp curve) and θ0 lies between its branches",
        ),
    }
}

/// Where to read two lines at fixed ν0 < ν1 for the scene x = ln(A/B) at
/// ν = ν0 + t (ν1 − ν0): at the same relative place between their ends,
/// `None` where the pop-out does not exist there.
///
/// A region of a pop-out ends at a tip in A/B (the cusp curve reaches
/// θ0 = 90°, [`LineEnd::Tip`]), and the tip moves with ν: read at the
/// scene's own A/B, the line whose tip lies above it says 90° and the
/// other a θ0_c well below, so that interpolating the two in ν put a
/// shallow ramp where the region has a steep edge (n = 4 at
/// (89.943°, A/B = 2.89, ν = −0.061): read 89.72° and counted 3, where a
/// pull sees 2). So where both lines end at a tip on the
/// same side, the tip is interpolated in ν (in ln A/B) and each line is
/// read at the scene's relative place between the interpolated ends,
/// mapped onto its own ends (an affine map in ln A/B); beyond an
/// interpolated tip the pop-out does not exist. An end that is not a tip
/// on both lines is a common anchor (the smaller first, the larger last
/// ln A/B of the two), so that the map is the identity where neither end
/// is. Outside the anchored span the reading is shifted with its nearest
/// end. Leave-one-out on the committed diagrams (a line at fixed ν read
/// from its neighbours, ν spacing ≤ 0.2): the largest error of θ0_c falls
/// from 0.55°, 1.04°, 1.02°, 0.96°, 0.98° to 0.22°, 0.16°, 0.30°, 0.53°,
/// 0.47° for n = 2, 3, 4, 6, 8, and the scenes read on the wrong side of
/// a tip from 62, 213, 478, 1946, 4214 to 2, 11, 64, 653, 1781 of
/// 2406–16842 (docs/ACCURACY.md).
fn aligned(l0: &CuspLine, l1: &CuspLine, t: f64, x: f64) -> Option<[f64; 2]> {
    let ends = |l: &CuspLine| -> Option<(f64, f64)> {
        Some((
            l.points.first()?.a_over_b.ln(),
            l.points.last()?.a_over_b.ln(),
        ))
    };
    let (Some((a0, b0)), Some((a1, b1))) = (ends(l0), ends(l1)) else {
        return Some([x, x]);
    };
    let tip = |l: &CuspLine, side: usize| l.ends[side] == LineEnd::Tip;
    let (low_tips, high_tips) = (tip(l0, 0) && tip(l1, 0), tip(l0, 1) && tip(l1, 1));
    let low = if low_tips { [a0, a1] } else { [a0.min(a1); 2] };
    let high = if high_tips { [b0, b1] } else { [b0.max(b1); 2] };
    let lerp = |e: [f64; 2]| e[0] + t * (e[1] - e[0]);
    let (lo, hi) = (lerp(low), lerp(high));
    if (low_tips && x < lo) || (high_tips && x > hi) {
        return None;
    }
    let read = |k: usize| {
        if x < lo {
            x - lo + low[k]
        } else if x > hi {
            x - hi + high[k]
        } else if hi > lo {
            low[k] + (x - lo) * (high[k] - low[k]) / (hi - lo)
        } else {
            low[k]
        }
    };
    Some([read(0), read(1)])
}
