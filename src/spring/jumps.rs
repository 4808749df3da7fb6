//! The stability of a [`Response`]'s points and the jumps of a
//! quasi-static test under force or extension control (the hysteresis).

use super::Response;
use crate::curve::{FoldKind, ForcePoint};
use crate::load::Control;
use crate::stability::{self, Stability};

/// Loading (the controlled quantity increases) or unloading.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Direction {
    /// The controlled quantity increases.
    Loading,
    /// The controlled quantity decreases.
    Unloading,
}

/// A jump of the spring from the last stable point it can hold to a stable
/// point with the same value of the controlled quantity (**Breaking**: the
/// jump now starts at a point, where it used to start at a fold).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Jump {
    /// The controlled quantity.
    pub control: Control,
    /// Loading or unloading.
    pub direction: Direction,
    /// Where the spring leaves the curve: the located fold of the
    /// controlled quantity where stability is lost at one, else the last
    /// stable point.
    pub from: ForcePoint,
    /// The last stable curve point before it leaves (in the direction of
    /// travel).
    pub from_index: usize,
    /// Where it lands: on the curve's dense output (the Hermite
    /// interpolant of the points, good to the run's tolerance), at the
    /// same controlled value.
    pub to: ForcePoint,
    /// The first stable curve point at or past the landing point (in the
    /// direction of travel).
    pub to_index: usize,
}

impl Response {
    /// The index of every curve point under `control`, carried from the
    /// first point (taken stable: the rest state) through the folds of
    /// force and extension ([`crate::stability`] explains why that is
    /// enough, and [`crate::rod::Equilibrium::stability`] is the direct
    /// test it is checked against).
    ///
    /// Labels next to a fold are only as sure as the fold's position: a
    /// point within the fold's location error of it may carry the label of
    /// the other side.
    #[must_use]
    pub fn stability(&self, control: Control) -> Vec<Stability> {
        stability::carried(self.curve(), self.folds(), &[], control)
    }

    /// The jumps a quasi-static test makes under `control`, loading from the
    /// first point and unloading from the last, read off the stability
    /// labels ([`Self::stability`]).
    ///
    /// Loading follows the curve while the next point is stable and the
    /// controlled quantity does not fall; the spring then leaves (at the
    /// fold where stability is lost at one) and lands at the first later
    /// stable point that regains the value it left at. Unloading does the
    /// same backwards from the last stable point. A spring that finds no
    /// stable landing on the computed curve ends its path there. The
    /// difference between the two paths is the hysteresis.
    #[must_use]
    pub fn jumps(&self, control: Control) -> Vec<Jump> {
        let labels = self.stability(control);
        let pts = self.curve().points();
        let n = pts.len();
        let value = |p: &ForcePoint| controlled(control, p);
        let stable = |i: usize| labels[i].is_stable();
        let (max_kind, min_kind) = match control {
            Control::Force => (FoldKind::MaxForce, FoldKind::MinForce),
            Control::Extension => (FoldKind::MaxExtension, FoldKind::MinExtension),
        };
        let fold_after = |i: usize, kind: FoldKind| {
            self.folds()
                .iter()
                .find(|f| f.index == i && f.kind == kind)
                .map(|f| f.point)
        };
        let mut jumps = Vec::new();

        let Some(mut i) = (0..n).find(|&i| stable(i)) else {
            return jumps;
        };
        loop {
            while i + 1 < n && stable(i + 1) && value(&pts[i + 1]) >= value(&pts[i]) {
                i += 1;
            }
            if i + 1 >= n {
                break;
            }
            let from = fold_after(i, max_kind).unwrap_or(pts[i]);
            let level = value(&from);
            let landing = (i + 2..n)
                .find(|&j| stable(j) && value(&pts[j - 1]) < level && value(&pts[j]) >= level);
            let Some(j) = landing else { break };
            jumps.push(Jump {
                control,
                direction: Direction::Loading,
                from,
                from_index: i,
                to: self.landing(j - 1, level, control, Direction::Loading),
                to_index: j,
            });
            i = j;
        }

        let Some(mut i) = (0..n).rev().find(|&i| stable(i)) else {
            return jumps;
        };
        loop {
            while i > 0 && stable(i - 1) && value(&pts[i - 1]) <= value(&pts[i]) {
                i -= 1;
            }
            if i == 0 {
                break;
            }
            let from = fold_after(i - 1, min_kind).unwrap_or(pts[i]);
            let level = value(&from);
            let landing = (1..i.saturating_sub(1))
                .rev()
                .find(|&j| stable(j - 1) && value(&pts[j]) > level && value(&pts[j - 1]) <= level);
            let Some(j) = landing else { break };
            jumps.push(Jump {
                control,
                direction: Direction::Unloading,
                from,
                from_index: i,
                to: self.landing(j - 1, level, control, Direction::Unloading),
                to_index: j - 1,
            });
            i = j - 1;
        }
        jumps
    }
}

impl Response {
    /// Where a jump lands on segment `i` (points i, i + 1) at the
    /// controlled value `level`: on the curve's dense output (module docs
    /// of [`crate::curve`]), the first crossing in the direction of travel,
    /// with the controlled coordinate exactly `level`; linearly between the
    /// points where the interpolant does not cross it.
    fn landing(&self, i: usize, level: f64, control: Control, direction: Direction) -> ForcePoint {
        let curve = self.curve();
        let roots = curve.crossings_on(i, level, control == Control::Force);
        let tau = match direction {
            Direction::Loading => roots.first(),
            Direction::Unloading => roots.last(),
        };
        let pts = curve.points();
        let mut to = tau.and_then(|&t| curve.at(i, t)).unwrap_or_else(|| {
            interpolate(&pts[i], &pts[i + 1], level, |p| controlled(control, p))
        });
        match control {
            Control::Force => to.force = level,
            Control::Extension => to.extension = level,
        }
        to
    }
}

/// The quantity `control` prescribes at `p`: its force or its extension.
fn controlled(control: Control, p: &ForcePoint) -> f64 {
    match control {
        Control::Force => p.force,
        Control::Extension => p.extension,
    }
}

fn interpolate(
    a: &ForcePoint,
    b: &ForcePoint,
    level: f64,
    value: impl Fn(&ForcePoint) -> f64,
) -> ForcePoint {
    let (va, vb) = (value(a), value(b));
    let t = if vb == va {
        0.0
    } else {
        (level - va) / (vb - va)
    };
    ForcePoint {
        extension: a.extension + t * (b.extension - a.extension),
        force: a.force + t * (b.force - a.force),
        parameter: a.parameter + t * (b.parameter - a.parameter),
    }
}

#[cfg(test)]
mod tests {
    use super::super::response::test_curves::s_curve;
    use super::*;

    #[test]
    fn force_control_jumps_over_the_unstable_part_both_ways() {
        let pull = s_curve(601);
        let jumps = pull.jumps(Control::Force);
        assert_eq!(jumps.len(), 2);
        let load = jumps
            .iter()
            .find(|j| j.direction == Direction::Loading)
            .unwrap();
        let unload = jumps
            .iter()
            .find(|j| j.direction == Direction::Unloading)
            .unwrap();
        // Linear interpolation between points 0.01 apart on a curve with
        // F″ = 12 at the landing: error ≤ h²·F″/8 / F′ ≈ 2e-5.
        assert!((load.to.extension - 2.0).abs() < 1e-4, "{load:?}");
        assert!((unload.to.extension + 2.0).abs() < 1e-4, "{unload:?}");
        assert!(pull.jumps(Control::Extension).is_empty());
    }
}
