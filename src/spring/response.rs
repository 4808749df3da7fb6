//! [`Response`]: a model's answer to "pull this spring", and what can be read
//! off it: folds, pop-outs, stretches between them, the loop count on each,
//! the elastica branch each follows, the stability of every point and the
//! jumps (hysteresis) under force or displacement control, and self-contact.
//!
//! Everything here is computed from the curve itself, so it means the same
//! for every model. The readings have files of their own: the pop-outs and
//! stretches (`pop_outs.rs`), stability and jumps (`jumps.rs`), the
//! branches followed (`branch_match.rs`).

use crate::continuation::Termination;
use crate::curve::{Fold, FoldKind, ForceExtension};
use crate::error::{Error, Result};
use crate::load::{Control, Target};
use crate::rod::Relaxation;

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
    relaxations: Vec<Relaxation>,
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
            relaxations: Vec::new(),
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

    /// The same pull with where the model went on from a failure at a
    /// looser tolerance ([`crate::rod::Pull::relax_to`]): from each
    /// [`Relaxation::from_point`] on, the curve's points were computed at
    /// that relaxation's tolerance.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] if a relaxation's point is past the end of
    /// the curve, or before the previous relaxation's (the same point
    /// twice is a looser segment that added no point before the next,
    /// looser still, went on from it).
    pub fn with_relaxations(mut self, relaxations: Vec<Relaxation>) -> Result<Self> {
        let mut after = None;
        for r in &relaxations {
            if r.from_point >= self.curve.len() || after.is_some_and(|a| r.from_point < a) {
                return Err(Error::InvalidCount {
                    name: "relaxation point",
                    value: r.from_point as u64,
                    allowed: "an index of the curve, not before the previous relaxation's",
                });
            }
            after = Some(r.from_point);
        }
        self.relaxations = relaxations;
        Ok(self)
    }

    /// Where the model went on at a looser tolerance, in curve order (empty
    /// where it did not: every model but a relaxed rod,
    /// [`RodModel::relax_to`](super::RodModel::relax_to)).
    #[must_use]
    pub fn relaxations(&self) -> &[Relaxation] {
        &self.relaxations
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
        if let Some(last) = self.relaxations.last() {
            write!(
                f,
                ", relaxed from point {} to tolerance {:.0e}",
                self.relaxations[0].from_point, last.tolerance
            )?;
        }
        if self.reached_target() {
            Ok(())
        } else {
            write!(f, " (stopped early: {})", self.termination)
        }
    }
}

/// Curves for the tests of the response's readings.
#[cfg(test)]
pub(super) mod test_curves {
    use super::*;
    use crate::curve::ForcePoint;

    /// Extension t, force t³ − 3t on t ∈ [−3, 3]: force folds at t = ∓1
    /// (F = ±2); under force control loading jumps from t = −1 to t = 2
    /// ((t − 2)(t + 1)² = 0) and unloading from t = 1 to t = −2.
    pub(in crate::spring) fn s_curve(points: usize) -> Response {
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
}

#[cfg(test)]
mod tests {
    use super::test_curves::s_curve;
    use super::*;

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
            pull.clone().with_loops(vec![Some(1); 60]),
            Err(Error::LengthMismatch { .. })
        ));
        let at = |from_point| Relaxation {
            from_point,
            tolerance: 1e-5,
            because: Error::NewtonDiverged {
                iteration: 3,
                correction: 1.0,
            },
        };
        for bad in [vec![at(61)], vec![at(30), at(20)]] {
            assert!(matches!(
                pull.clone().with_relaxations(bad),
                Err(Error::InvalidCount { .. })
            ));
        }
        // (a looser segment that failed at its first step leaves the next
        // relaxation at the same point: drive.rs)
        assert!(pull.clone().with_relaxations(vec![at(20), at(20)]).is_ok());
        let relaxed = pull.with_relaxations(vec![at(20), at(40)]).unwrap();
        assert_eq!(relaxed.relaxations().len(), 2);
        assert!(
            relaxed
                .to_string()
                .contains("relaxed from point 20 to tolerance 1e-5"),
            "{relaxed}"
        );
    }
}
