//! The pop-outs of a [`Response`] and the stretches between them: which
//! pairs of force folds lose loops, read off the loop counts around them.

use core::ops::Range;

use super::Response;
use crate::curve::{Fold, FoldKind};

/// A loop popping out: a maximum-force fold followed by a minimum-force fold.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PopOut {
    /// Where the force peaks before the loop pops out.
    pub max: Fold,
    /// Where the force bottoms out after it.
    pub min: Fold,
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

impl Response {
    /// The pop-outs (type docs), in curve order.
    #[must_use]
    pub fn pop_outs(&self) -> Vec<PopOut> {
        let pairs = self.force_fold_pairs();
        // the loop counts between consecutive pairs (before the first,
        // after the last), and the settled count of each
        let between: Vec<&[Option<u32>]> = (0..=pairs.len())
            .map(|k| {
                let from = if k == 0 { 0 } else { pairs[k - 1].1.index + 1 };
                let until = pairs.get(k).map_or(self.curve().len(), |p| p.0.index + 1);
                &self.loops()[from.min(until)..until]
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
        for fold in self.folds() {
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
        cuts.push(self.curve().len());
        cuts.chunks(2)
            .filter(|c| c[0] < c[1])
            .map(|c| Stretch {
                range: c[0]..c[1],
                loops: mode(&self.loops()[c[0]..c[1]]),
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

#[cfg(test)]
mod tests {
    use super::super::response::test_curves::s_curve;
    use super::*;
    use crate::continuation::Termination;
    use crate::curve::{ForceExtension, ForcePoint};
    use crate::load::Target;

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
}
