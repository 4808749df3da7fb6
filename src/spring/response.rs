//! [`Response`]: a model's answer to "pull this spring", and what can be read
//! off it: folds, pop-outs, stretches between them, the loop count on each,
//! the elastica branch each follows, the stability of every point and the
//! jumps (hysteresis) under force or displacement control, and self-contact.
//!
//! Everything here is computed from the curve itself, so it means the same
//! for every model.

use core::ops::Range;

use crate::continuation::Termination;
use crate::curve::{Fold, FoldKind, ForceExtension, ForcePoint};
use crate::error::{Error, Result};
use crate::load::{Control, Target};
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

/// A loop popping out: a maximum-force fold followed by a minimum-force fold.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PopOut {
    /// Where the force peaks before the loop pops out.
    pub max: Fold,
    /// Where the force bottoms out after it.
    pub min: Fold,
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
    /// Where it lands (interpolated on the curve, same controlled value).
    pub to: ForcePoint,
    /// The first stable curve point at or past the landing point (in the
    /// direction of travel).
    pub to_index: usize,
}

/// A piece of the curve between pop-outs (from the start or a
/// minimum-force fold to the next maximum-force fold or the end).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Stretch {
    /// The curve points it covers.
    pub range: Range<usize>,
    /// The number of loops on it (the most common count of its points),
    /// where the model counts loops and no other count is as common.
    pub loops: Option<u32>,
}

/// How close a stretch lies to a reference branch (an elastica branch):
/// distances in the (Δz, F/(2πn)²) plane of the paper's plots.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BranchMatch {
    /// The branch's label.
    pub label: String,
    /// Root-mean-square distance of the stretch's points from the branch.
    pub rms_distance: f64,
    /// Largest distance of a stretch point from the branch.
    pub max_distance: f64,
}

/// A model's answer to a pull: the force–extension curve in the order the
/// model traced it, its folds, the loop count at every point, and why the
/// pull ended.
///
/// One vocabulary for every model:
///
/// - a **fold** is a turning point of the force or of the extension along
///   the curve ([`Fold`]); models that locate the folds of the controlled
///   load (continuation) report those, the others are found on the curve;
/// - the **loop count** of a point is the number of loops of its shape
///   ([`crate::rod::Equilibrium::loops`]): n on the helix and on the flat
///   primary branch, `None` where the shape leaves its plane;
/// - a **pop-out** is a maximum-force fold followed by the next
///   minimum-force fold across which the spring loses a loop. Between two
///   fold pairs (and before the first, after the last) the loop count is
///   *settled* where three in four of the known counts of the points there
///   agree (two known at least; the rod's count is undefined in its 3D
///   excursions and flickers between 0 and 1 late in a pull). A pair is no
///   pop-out where every known count on both sides is one and the same (an
///   exact helix has force folds but keeps its n loops, as the rod near
///   θ0 = 90° has small fold pairs that lose none). Where pairs follow one
///   another with no settled count between them, and the settled counts
///   before the first and after the last lose k ≥ 1 loops, fewer than
///   there are pairs, the k pairs of widest hysteresis (F_max − F_min) are
///   the pop-outs: n = 8 at (89.5°, 20, 0.05) has five pairs in a row, four
///   with hystereses 0.002–0.03 in F/((2πn)²B) and one with 1.4e-4, from
///   7 loops to 3. Every other pair is a pop-out (a count unknown or not
///   unanimous, loops gained, as many lost as there are pairs or more:
///   loops also unloop without a fold): an undefined count never hides
///   one;
/// - a **stretch** is a piece of the curve between pop-outs, with the most
///   common known loop count of its points (`None` where two are equally
///   common);
/// - the **stability** of a point under a [`Control`] is its index, carried
///   from the rest state through the folds ([`Response::stability`],
///   [`crate::stability`]): within the model's own degrees of freedom (the
///   helix's angle; the elastica's plane, whose out-of-plane instabilities
///   are [`crate::elastica::OutOfPlane`]'s diamonds; the rod's all);
/// - a **jump** leaves the last stable point a quasi-static test can hold
///   and lands on a stable point with the same controlled value
///   ([`Response::jumps`]);
/// - the **closest approach** of a shape to itself is known where the model
///   computed shapes and was asked to ([`crate::spring::RodModel::pull_with_contact`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Response {
    model: String,
    target: Target,
    curve: ForceExtension,
    folds: Vec<Fold>,
    loops: Vec<Option<u32>>,
    closest_approach: Vec<Option<f64>>,
    strip_width: Option<f64>,
    termination: Termination,
    estimated_error: Option<f64>,
}

impl Response {
    /// A model's answer to a pull to `target`: `curve` in the order the
    /// model traced it, how the run ended, and the folds found on the curve
    /// itself (local extrema of force and extension, each refined by the
    /// parabola through the three points around it). No loop counts until
    /// [`Response::with_loops`].
    #[must_use]
    pub fn new(
        model: impl Into<String>,
        target: Target,
        curve: ForceExtension,
        termination: Termination,
    ) -> Self {
        let folds = curve.folds();
        let loops = vec![None; curve.len()];
        let closest_approach = vec![None; curve.len()];
        Self {
            model: model.into(),
            target,
            curve,
            folds,
            loops,
            closest_approach,
            strip_width: None,
            termination,
            estimated_error: None,
        }
    }

    /// The same pull with the model's estimate of its own error: the
    /// largest distance, in (Δz, F/((2πn)²B)), between the returned curve
    /// (its points, folds and interpolant) and the exact one.
    #[must_use]
    pub fn with_estimated_error(mut self, error: f64) -> Self {
        self.estimated_error = Some(error);
        self
    }

    /// The model's estimate of its error in (Δz, F/((2πn)²B)), where the
    /// model measured one ([`Self::with_estimated_error`]).
    #[must_use]
    pub fn estimated_error(&self) -> Option<f64> {
        self.estimated_error
    }

    /// The same pull with the folds of the controlled load that the model
    /// located itself (e.g. by continuation), replacing those of the same
    /// kinds found on the curve.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if a fold's index is past the end of the
    /// curve.
    pub fn with_folds(mut self, located: Vec<Fold>) -> Result<Self> {
        if let Some(bad) = located.iter().find(|f| f.index >= self.curve.len()) {
            return Err(Error::InvalidCount {
                name: "fold index",
                value: bad.index as u64,
                allowed: "an index of a curve point (below the curve's length)",
            });
        }
        let controlled = |k: FoldKind| match self.target.control() {
            Control::Force => matches!(k, FoldKind::MaxForce | FoldKind::MinForce),
            Control::Extension => matches!(k, FoldKind::MaxExtension | FoldKind::MinExtension),
        };
        self.folds.retain(|f| !controlled(f.kind));
        self.folds.extend(located);
        self.folds.sort_by_key(|f| f.index);
        Ok(self)
    }

    /// The same pull with a loop count for every curve point.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] unless there is one count per point.
    pub fn with_loops(mut self, loops: Vec<Option<u32>>) -> Result<Self> {
        if loops.len() != self.curve.len() {
            return Err(Error::LengthMismatch {
                name: "loops",
                found: loops.len() as u64,
                expected: self.curve.len() as u64,
            });
        }
        self.loops = loops;
        Ok(self)
    }

    /// The same pull with the closest approach of every shape to itself
    /// ([`crate::rod::Equilibrium::closest_approach`]), `None` where it was
    /// not computed, and the width of the strip whose contact
    /// [`Self::first_contact`] flags (the spring's
    /// [`Spring::strip_width`](super::Spring::strip_width)).
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] unless there is one value per point;
    /// [`Error::InvalidArgument`] for a width that is not finite and
    /// positive.
    pub fn with_closest_approach(
        mut self,
        closest: Vec<Option<f64>>,
        strip_width: Option<f64>,
    ) -> Result<Self> {
        if closest.len() != self.curve.len() {
            return Err(Error::LengthMismatch {
                name: "closest approaches",
                found: closest.len() as u64,
                expected: self.curve.len() as u64,
            });
        }
        if let Some(w) = strip_width {
            super::scene::check_strip_width(w)?;
        }
        self.closest_approach = closest;
        self.strip_width = strip_width;
        Ok(self)
    }

    /// The closest approach of every point's centreline to itself, between
    /// parts that are not neighbours along the rod
    /// ([`crate::rod::Contact`]); `None` where it was not computed (models
    /// without shapes, or a pull that did not ask for it).
    #[must_use]
    pub fn closest_approach(&self) -> &[Option<f64>] {
        &self.closest_approach
    }

    /// The strip width the contact check used, if any.
    #[must_use]
    pub fn strip_width(&self) -> Option<f64> {
        self.strip_width
    }

    /// The first curve point where a strip of the spring's width would touch
    /// itself: its centreline comes closer to itself than the width (two
    /// halves of a width apart; conservative, since the strip's edges need
    /// not face each other). `None` if no computed point does, or without a
    /// width or closest approaches.
    #[must_use]
    pub fn first_contact(&self) -> Option<usize> {
        let w = self.strip_width?;
        self.closest_approach
            .iter()
            .position(|d| d.is_some_and(|d| d < w))
    }

    /// The model that answered.
    #[must_use]
    pub fn model(&self) -> &str {
        &self.model
    }

    /// The target of the pull.
    #[must_use]
    pub fn target(&self) -> Target {
        self.target
    }

    /// Why the pull ended: [`Termination::ParameterValue`] when its last
    /// point is the target; otherwise the typed reason it stopped early
    /// (every point so far is kept).
    #[must_use]
    pub fn termination(&self) -> &Termination {
        &self.termination
    }

    /// Whether the last point is the target.
    #[must_use]
    pub fn reached_target(&self) -> bool {
        matches!(self.termination, Termination::ParameterValue(_))
    }

    /// The force–extension curve.
    #[must_use]
    pub fn curve(&self) -> &ForceExtension {
        &self.curve
    }

    /// Every fold in curve order.
    #[must_use]
    pub fn folds(&self) -> &[Fold] {
        &self.folds
    }

    /// The loop count at every curve point (`None` where it is not defined
    /// or the model does not count).
    #[must_use]
    pub fn loops(&self) -> &[Option<u32>] {
        &self.loops
    }

    /// The pop-outs (type docs), in curve order.
    #[must_use]
    pub fn pop_outs(&self) -> Vec<PopOut> {
        let pairs = self.force_fold_pairs();
        // the loop counts between consecutive pairs (before the first,
        // after the last), and the settled count of each
        let between: Vec<&[Option<u32>]> = (0..=pairs.len())
            .map(|k| {
                let from = if k == 0 { 0 } else { pairs[k - 1].1.index + 1 };
                let until = pairs.get(k).map_or(self.curve.len(), |p| p.0.index + 1);
                &self.loops[from.min(until)..until]
            })
            .collect();
        let counts: Vec<Option<u32>> = between.iter().map(|b| settled(b)).collect();
        let mut popped = vec![false; pairs.len()];
        let mut a = 0;
        while a < pairs.len() {
            // a run of pairs with no settled count between them
            let mut b = a + 1;
            while b < pairs.len() && counts[b].is_none() {
                b += 1;
            }
            let lost = match (counts[a], counts[b]) {
                (Some(before), Some(after)) if after <= before => Some((before - after) as usize),
                _ => None,
            };
            match lost {
                Some(0) if b - a == 1 && unanimous(between[a]) && unanimous(between[b]) => {}
                Some(k) if k >= 1 && k < b - a => {
                    let mut widest: Vec<usize> = (a..b).collect();
                    widest
                        .sort_by(|&i, &j| hysteresis(&pairs[j]).total_cmp(&hysteresis(&pairs[i])));
                    for &i in widest.iter().take(k) {
                        popped[i] = true;
                    }
                }
                _ => popped[a..b].fill(true),
            }
            a = b;
        }
        pairs
            .into_iter()
            .zip(popped)
            .filter(|(_, p)| *p)
            .map(|((max, min), _)| PopOut { max, min })
            .collect()
    }

    /// Every maximum-force fold paired with the next minimum-force fold.
    fn force_fold_pairs(&self) -> Vec<(Fold, Fold)> {
        let mut out = Vec::new();
        let mut pending: Option<Fold> = None;
        for fold in &self.folds {
            match fold.kind {
                FoldKind::MaxForce => pending = Some(*fold),
                FoldKind::MinForce => {
                    if let Some(max) = pending.take() {
                        out.push((max, *fold));
                    }
                }
                FoldKind::MaxExtension | FoldKind::MinExtension => {}
            }
        }
        out
    }

    /// The stretches between pop-outs, with their loop counts.
    #[must_use]
    pub fn stretches(&self) -> Vec<Stretch> {
        let mut cuts = vec![0];
        for p in self.pop_outs() {
            cuts.push(p.max.index + 1);
            cuts.push(p.min.index + 1);
        }
        cuts.push(self.curve.len());
        cuts.chunks(2)
            .filter(|c| c[0] < c[1])
            .map(|c| Stretch {
                range: c[0]..c[1],
                loops: mode(&self.loops[c[0]..c[1]]),
            })
            .collect()
    }

    /// Loops lost from the first stretch to the last (negative if the spring
    /// gained loops), where both counts are known.
    #[must_use]
    pub fn loops_lost(&self) -> Option<i64> {
        let s = self.stretches();
        let first = s.first()?.loops?;
        let last = s.last()?.loops?;
        Some(i64::from(first) - i64::from(last))
    }

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
        stability::carried(&self.curve, &self.folds, &[], control)
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
        let pts = self.curve.points();
        let n = pts.len();
        let value = |p: &ForcePoint| match control {
            Control::Force => p.force,
            Control::Extension => p.extension,
        };
        let stable = |i: usize| labels[i].is_stable();
        let (max_kind, min_kind) = match control {
            Control::Force => (FoldKind::MaxForce, FoldKind::MinForce),
            Control::Extension => (FoldKind::MaxExtension, FoldKind::MinExtension),
        };
        let fold_after = |i: usize, kind: FoldKind| {
            self.folds
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
                to: interpolate(&pts[j - 1], &pts[j], level, value),
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
                to: interpolate(&pts[j - 1], &pts[j], level, value),
                to_index: j - 1,
            });
            i = j - 1;
        }
        jumps
    }

    /// How close each stretch lies to each of `branches`, nearest first.
    ///
    /// Distances are measured in the (Δz, F/(2πn)²) plane with the curve's
    /// own force scale, from each stretch point to the branch polyline.
    #[must_use]
    pub fn match_branches(&self, branches: &[ForceExtension]) -> Vec<Vec<BranchMatch>> {
        let scale = self.curve.force_scale();
        let pts = self.curve.points();
        self.stretches()
            .iter()
            .map(|stretch| {
                let mut matches: Vec<BranchMatch> = branches
                    .iter()
                    .filter(|b| b.len() >= 2)
                    .map(|b| {
                        let (mut sum, mut max) = (0.0, 0.0_f64);
                        for p in &pts[stretch.range.clone()] {
                            let d = distance_to_polyline(p, b.points(), scale);
                            sum += d * d;
                            max = max.max(d);
                        }
                        BranchMatch {
                            label: b.label().to_owned(),
                            rms_distance: (sum / stretch.range.len() as f64).sqrt(),
                            max_distance: max,
                        }
                    })
                    .collect();
                matches.sort_by(|a, b| a.rms_distance.total_cmp(&b.rms_distance));
                matches
            })
            .collect()
    }
}

impl core::fmt::Display for Response {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{}: {} points, {} folds, {} pop-outs",
            self.model,
            self.curve.len(),
            self.folds.len(),
            self.pop_outs().len()
        )?;
        if self.reached_target() {
            Ok(())
        } else {
            write!(f, " (stopped early: {})", self.termination)
        }
    }
}

/// The most common known value, `None` where none is known or two are
/// equally common.
fn mode(values: &[Option<u32>]) -> Option<u32> {
    let mut sorted: Vec<u32> = values.iter().flatten().copied().collect();
    sorted.sort_unstable();
    // (count, how many points have it, whether another count has as many)
    let mut best: Option<(u32, usize, bool)> = None;
    for run in sorted.chunk_by(|a, b| a == b) {
        match best {
            Some((_, n, _)) if run.len() < n => {}
            Some((v, n, _)) if run.len() == n => best = Some((v, n, true)),
            _ => best = Some((run[0], run.len(), false)),
        }
    }
    best.and_then(|(v, _, tied)| (!tied).then_some(v))
}

/// The loop count that at least three in four of the known counts agree
/// on, from two known counts up; `None` otherwise. The rod's count
/// flickers where its shape is three-dimensional (0 and 1 alternating
/// after the pop-outs of n = 4 at θ0 = 87.35°), and a count that a bare
/// majority holds there said that a pop-out lost no loop.
fn settled(values: &[Option<u32>]) -> Option<u32> {
    let known = values.iter().flatten().count();
    let v = mode(values)?;
    let agree = values.iter().flatten().filter(|&&c| c == v).count();
    (known >= 2 && 4 * agree >= 3 * known).then_some(v)
}

/// Whether every known count agrees (two known at least).
fn unanimous(values: &[Option<u32>]) -> bool {
    let known: Vec<u32> = values.iter().flatten().copied().collect();
    known.len() >= 2 && known.iter().all(|&c| c == known[0])
}

/// F_max − F_min of a pair of force folds.
fn hysteresis((max, min): &(Fold, Fold)) -> f64 {
    max.point.force - min.point.force
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

fn distance_to_polyline(p: &ForcePoint, line: &[ForcePoint], scale: f64) -> f64 {
    let (px, py) = (p.extension, p.force / scale);
    line.windows(2)
        .map(|w| {
            let (ax, ay) = (w[0].extension, w[0].force / scale);
            let (bx, by) = (w[1].extension, w[1].force / scale);
            let (dx, dy) = (bx - ax, by - ay);
            let len2 = dx * dx + dy * dy;
            let t = if len2 > 0.0 {
                (((px - ax) * dx + (py - ay) * dy) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (px - ax - t * dx).hypot(py - ay - t * dy)
        })
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Extension t, force t³ − 3t on t ∈ [−3, 3]: force folds at t = ∓1
    /// (F = ±2); under force control loading jumps from t = −1 to t = 2
    /// ((t − 2)(t + 1)² = 0) and unloading from t = 1 to t = −2.
    fn s_curve(points: usize) -> Response {
        let mut c = ForceExtension::new("s", "t", crate::ForceScale::of_coils(1).unwrap());
        for i in 0..points {
            let t = -3.0 + 6.0 * i as f64 / (points - 1) as f64;
            c.push(ForcePoint {
                extension: t,
                force: t * t * t - 3.0 * t,
                parameter: t,
            });
        }
        Response::new(
            "test",
            Target::Force(5.0),
            c,
            Termination::ParameterValue(18.0),
        )
    }

    #[test]
    fn folds_of_a_cubic_are_found_at_its_extrema() {
        let pull = s_curve(601);
        let kinds: Vec<_> = pull.folds().iter().map(|f| f.kind).collect();
        assert_eq!(kinds, [FoldKind::MaxForce, FoldKind::MinForce]);
        // The parabola through three points of a cubic locates its extremum
        // with an error O(h²) in t and O(h⁴) in the force; h = 0.01.
        assert!((pull.folds()[0].point.extension + 1.0).abs() < 1e-4);
        assert!((pull.folds()[0].point.force - 2.0).abs() < 1e-7);
        assert!((pull.folds()[1].point.extension - 1.0).abs() < 1e-4);
        // A fold pair is a pop-out unless the loop count is known and
        // constant around it.
        assert_eq!(pull.pop_outs().len(), 1);
        let same = vec![Some(2); pull.curve().len()];
        assert!(pull.with_loops(same).unwrap().pop_outs().is_empty());
    }

    /// Extension t ∈ [0, 4], force 0.05 t + A_k sin 2πt with amplitude A_k
    /// on [k, k + 1]: a fold pair in each of the first three periods
    /// (maximum at k + ¼ … k + 0.32 where 0.05 + 2πA_k cos 2πt = 0,
    /// minimum near k + ¾, hysteresis ≈ 2A_k), none in the last;
    /// `loops(t)` the loop count of each point.
    fn three_pairs(amplitudes: [f64; 3], loops: impl Fn(f64) -> Option<u32>) -> Response {
        let mut c = ForceExtension::new("w", "t", crate::ForceScale::of_coils(1).unwrap());
        let n = 801;
        let mut counts = Vec::new();
        for i in 0..n {
            let t = 4.0 * i as f64 / (n - 1) as f64;
            let a = amplitudes.get(t as usize).copied().unwrap_or(0.0);
            c.push(ForcePoint {
                extension: t,
                force: 0.05 * t + a * (2.0 * core::f64::consts::PI * t).sin(),
                parameter: t,
            });
            counts.push(loops(t));
        }
        Response::new(
            "test",
            Target::Force(1.0),
            c,
            Termination::ParameterValue(4.0),
        )
        .with_loops(counts)
        .unwrap()
    }

    /// Where the pop-outs of [`three_pairs`] with amplitudes 0.1, 0.02, 0.3
    /// peak (the extensions of their maximum-force folds).
    fn popped_at(loops: impl Fn(f64) -> Option<u32>) -> Vec<f64> {
        three_pairs([0.1, 0.02, 0.3], loops)
            .pop_outs()
            .iter()
            .map(|p| p.max.point.extension)
            .collect()
    }

    #[test]
    fn pairs_with_no_known_count_between_them_pop_as_many_loops_as_are_lost() {
        // 5 loops before the first pair, 3 after the last, unknown between:
        // two of the three popped, the two widest (A = 0.1 and 0.3).
        let outside = |before: u32, after: u32| {
            move |t: f64| match t {
                t if t < 0.2 => Some(before),
                t if t > 2.8 => Some(after),
                _ => None,
            }
        };
        assert_eq!(
            three_pairs([0.1, 0.02, 0.3], outside(5, 3))
                .force_fold_pairs()
                .len(),
            3
        );
        let at = popped_at(outside(5, 3));
        assert_eq!(at.len(), 2);
        assert!(
            (at[0] - 0.25).abs() < 0.1 && (at[1] - 2.25).abs() < 0.1,
            "{at:?}"
        );
        // no loop lost across the run, more lost than there are pairs
        // (loops unloop without a fold too), loops gained, or a count
        // unknown on one side: every pair popped
        assert_eq!(popped_at(outside(4, 4)).len(), 3);
        assert_eq!(popped_at(outside(7, 3)).len(), 3);
        assert_eq!(popped_at(outside(3, 5)).len(), 3);
        assert_eq!(popped_at(|t: f64| (t < 0.2).then_some(5)).len(), 3);
        // two counts equally common before the first pair: unknown there
        let tied = |t: f64| match t {
            t if t < 0.1 => Some(5),
            t if t < 0.2 => Some(6),
            t if t > 2.8 => Some(4),
            _ => None,
        };
        assert_eq!(popped_at(tied).len(), 3);
        // 5, then 0, then 0 and 1 flickering, then 0 (late in a rod's
        // pull): a count settled but not unanimous is no evidence that the
        // pairs on either side kept their loops, so all three popped
        let flicker = |t: f64| {
            Some(match t {
                t if t < 0.8 => 5,
                t if t < 1.8 => u32::from(t > 1.7),
                _ => 0,
            })
        };
        assert_eq!(popped_at(flicker).len(), 3);
        // known counts between the pairs decide each alone: 5, 5, 4, 3
        let known = |t: f64| {
            Some(match t {
                t if t < 1.8 => 5,
                t if t < 2.8 => 4,
                _ => 3,
            })
        };
        let at = popped_at(known);
        assert_eq!(at.len(), 2);
        assert!(
            (at[0] - 1.25).abs() < 0.1 && (at[1] - 2.25).abs() < 0.1,
            "{at:?}"
        );
    }

    #[test]
    fn a_settled_count_is_held_by_three_in_four_known_counts() {
        let (a, b, u) = (Some(0), Some(1), None);
        assert_eq!(settled(&[a, a, a, b, u, u]), Some(0));
        // a bare majority (four of seven) is the mode, not settled
        assert_eq!(mode(&[a, a, a, a, b, b, b]), Some(0));
        assert_eq!(settled(&[a, a, a, a, b, b, b]), None);
        // one known count is no evidence; equally common counts no mode
        assert_eq!(settled(&[u, a, u]), None);
        assert_eq!(mode(&[a, b]), None);
        assert_eq!(mode(&[u, u]), None);
    }

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

    #[test]
    fn stretches_split_at_pop_outs_and_carry_loop_counts() {
        let pull = s_curve(601);
        let n = pull.curve().len();
        let loops: Vec<_> = (0..n).map(|i| Some(if i < 300 { 2 } else { 1 })).collect();
        let pull = pull.with_loops(loops).unwrap();
        assert_eq!(pull.pop_outs().len(), 1);
        assert_eq!(pull.loops_lost(), Some(1));
        let stretches = pull.stretches();
        assert_eq!(stretches.len(), 2);
        assert_eq!(stretches[0].loops, Some(2));
        assert_eq!(stretches[1].loops, Some(1));
        assert!(stretches[0].range.end <= stretches[1].range.start);
    }

    #[test]
    fn fold_indices_and_loop_counts_must_fit_the_curve() {
        let pull = s_curve(61);
        let mut fold = pull.folds()[0];
        fold.index = 61;
        assert!(matches!(
            pull.clone().with_folds(vec![fold]),
            Err(Error::InvalidCount { .. })
        ));
        assert!(matches!(
            pull.with_loops(vec![Some(1); 60]),
            Err(Error::LengthMismatch { .. })
        ));
    }

    #[test]
    fn a_stretch_on_a_branch_is_at_distance_zero_from_it() {
        let pull = s_curve(61);
        let near = pull.match_branches(&[pull.curve().clone()]);
        assert!(near.iter().all(|m| m[0].max_distance == 0.0));
    }
}
