//! Where each pop-out exists: the folds of a pull continued in θ0, A/B and
//! ν to the cusps where the two folds of a pop-out meet ([`CuspSearch`]).
//!
//! A pop-out of a pull is a pair of force folds: a maximum F at which the
//! loop lets go and a minimum at which the curve turns back. Continued in a
//! second parameter μ (θ0, A/B or ν, [`NikolaiRod`]) the two folds are the
//! two halves of one fold curve, which they leave through a cusp: there the
//! maximum and the minimum meet and the pop-out vanishes. The cusp's μ
//! bounds the range of μ where the pop-out exists.
//!
//! ```text
//!   pull (force control) → folds (F_max,1, F_min,1), (F_max,2, F_min,2), …
//!   F_max,i continued in μ  →  fold curve  →  first cusp: μ_c,i
//! ```
//!
//! [`CuspSearch::follow`] continues a fold to a requested value of one
//! parameter and reports the first cusp met on the way (with a
//! [`CuspSearch::tolerance`], checked against its mesh); [`CuspSearch::carry`]
//! carries it to another spring (θ0, A/B, ν): the force of a pop-out there;
//! [`CuspSearch::pop_outs`] pulls a spring and pairs its folds;
//! [`CuspSearch::cusp_curve`] traces the curve of cusps in a third
//! parameter (`examples/phase_diagram`).
//!
//! ```no_run
//! use hockle::rod::{CuspSearch, Followed, NikolaiRod, Rod};
//! use hockle::Stiffness;
//! // The paper's spring: where does its first pop-out vanish as θ0 falls?
//! let rod = Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
//! let family = NikolaiRod::new(rod, 0.05)?;
//! // found on a coarse mesh, checked on halved ones to 1e-9 rad
//! let search = CuspSearch::new().intervals(16).tolerance(1e-9);
//! let pops = search.pop_outs(&family, 3.0)?; // three pairs (max, min)
//! let Followed::Cusp(cusp) = search.follow(&family, &pops[0][0], Rod::THETA0, 1.0)? else {
//!     panic!("a cusp above θ0 = 1 rad");
//! };
//! assert!(cusp.mesh_change().is_some_and(|moved| moved <= 1e-9)); // on 64 intervals
//! assert!((cusp.parameter() - 1.526908532739).abs() < 2e-9); // docs/ACCURACY.md
//! # Ok::<(), hockle::Error>(())
//! ```

use std::ops::ControlFlow;

use super::{NikolaiRod, Pull, Rod};
use crate::bvp::{Collocation, Solution};
use crate::continuation::{
    Continuation, FoldContinuation, FoldObserver, FoldPoint, FoldPointKind, Point, PointKind,
    Termination,
};
use crate::error::{Error, Result};
use crate::load::Target;
use crate::stiffness::Stiffness;

/// Newton's tolerance on a cusp curve (relative to 1 + ‖x‖∞).
const CUSP_NEWTON_TOLERANCE: f64 = 1e-7;

mod cusp_curve;
mod mesh_check;

pub use mesh_check::MeshChecked;

/// Settings of the fold continuations of [`crate::rod::cascade`] (module
/// docs), a builder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CuspSearch {
    intervals: usize,
    ds_max: f64,
    curve_ds_max: f64,
    curve_max_angle: f64,
    max_steps: usize,
    stairs: usize,
    tolerance: Option<f64>,
}

/// How a fold followed in one parameter ended ([`CuspSearch::follow`]).
#[derive(Debug, Clone)]
pub enum Followed {
    /// The fold reached the requested value: the fold curve's point there
    /// (its [`FoldPoint::solution`] a solution of the [`NikolaiRod`] at a
    /// fold in its force, F/((2πn)²B) its
    /// [`FoldPoint::fold_parameter`]).
    Reached(Box<FoldPoint>),
    /// The fold met a cusp first: the two folds of its pop-out meet here
    /// and the pop-out vanishes beyond it.
    Cusp(Box<FoldPoint>),
    /// The continuation ended otherwise (step limit, Newton failure).
    Ended(Termination),
}

impl Default for CuspSearch {
    fn default() -> Self {
        Self::new()
    }
}

impl CuspSearch {
    /// The defaults:
    ///
    /// | setting | default |
    /// |---|---|
    /// | [`intervals`](Self::intervals) | 48 uniform intervals, 4 Gauss points (the pull's) |
    /// | [`ds_max`](Self::ds_max) | 0.5: the largest step of a fold curve |
    /// | [`curve_ds_max`](Self::curve_ds_max) | 5: the largest step of a cusp curve |
    /// | [`curve_max_angle`](Self::curve_max_angle) | 0.35 rad (the continuation's): the largest angle between tangents of a cusp curve |
    /// | [`max_steps`](Self::max_steps) | 400 per fold curve |
    /// | [`stairs`](Self::stairs) | 4 rounds of [`carry`](Self::carry)'s legs |
    /// | [`tolerance`](Self::tolerance) | none: what is found on the mesh is returned unchecked |
    ///
    /// The fold curves use the pull's solution weights (r, q: 1; F:
    /// 1/((2πn)²B)²; M: 1e-3) and weight 1 for the parameters (the force
    /// scaled by (2πn)²B, [`NikolaiRod`]); turns and cusps are located to
    /// 1e-9 in arclength.
    #[must_use]
    pub fn new() -> Self {
        Self {
            intervals: 48,
            ds_max: 0.5,
            curve_ds_max: 5.0,
            curve_max_angle: 0.35,
            max_steps: 400,
            stairs: 4,
            tolerance: None,
        }
    }

    /// The accuracy asked of what [`follow`](Self::follow) and
    /// [`carry`](Self::carry) return (positive and finite, checked there):
    /// a fold's force F/((2πn)²B), a cusp's parameter (θ0 in radians,
    /// ln A/B or ν). The fold curves run on the search's mesh
    /// ([`intervals`](Self::intervals)); the fold or cusp they end at is
    /// then located again with every interval halved until it moves by at
    /// most `tol` (at most [`MAX_HALVINGS`](Self::MAX_HALVINGS) times:
    /// [`mesh_checked`](Self::mesh_checked),
    /// [`cusp_mesh_checked`](Self::cusp_mesh_checked)), and returned on the
    /// finest mesh with how far it moved last
    /// ([`FoldPoint::mesh_change`]: at most `tol`, or above it where three
    /// halvings did not get there, `∞` where the finer mesh did not find
    /// it). With m Gauss points a converged location moves as h^(2m), so
    /// the change overestimates the returned point's own error by up to
    /// 2^(2m) − 1 (255 for m = 4). A coarse mesh with a tolerance is the
    /// cheap way to a converged cusp: pop-out 1's cusp in θ0 found on 16
    /// intervals is 2.4e-8 rad off; checked to 1e-9 it is found on 64,
    /// 1e-12 from the cusp found directly on 48 (docs/ACCURACY.md).
    ///
    /// A cusp curve ([`cusp_curve`](Self::cusp_curve)) from a checked cusp
    /// runs on the cusp's (finer) mesh; its own points are not checked.
    #[must_use]
    pub fn tolerance(mut self, tol: f64) -> Self {
        self.tolerance = Some(tol);
        self
    }

    /// Uniform mesh intervals of the pull and of every fold curve.
    #[must_use]
    pub fn intervals(mut self, n: usize) -> Self {
        self.intervals = n;
        self
    }

    /// The largest step of a fold curve.
    #[must_use]
    pub fn ds_max(mut self, ds: f64) -> Self {
        self.ds_max = ds;
        self
    }

    /// The largest step of a cusp curve ([`CuspSearch::cusp_curve`]).
    #[must_use]
    pub fn curve_ds_max(mut self, ds: f64) -> Self {
        self.curve_ds_max = ds;
        self
    }

    /// The largest angle (radians) between successive tangents of a cusp
    /// curve ([`Continuation::max_angle`]). Near swallowtails the cusp
    /// curve's tangent is noise (its Jacobian differences the fold
    /// problem's, whose second derivatives are differences): measured on
    /// n = 8, it turned by 0.35–1.4 rad even at Δs = 1e-8, a bend no curve
    /// makes in that arclength. With a larger angle the steps stay long
    /// enough to pass such places (`examples/phase_diagram` uses 1.2).
    #[must_use]
    pub fn curve_max_angle(mut self, angle: f64) -> Self {
        self.curve_max_angle = angle;
        self
    }

    /// The step limit of each fold curve.
    #[must_use]
    pub fn max_steps(mut self, n: usize) -> Self {
        self.max_steps = n;
        self
    }

    /// The most rounds of [`carry`](Self::carry)'s staircase.
    pub const MAX_STAIRS: usize = 64;

    /// Rounds of the three legs of [`carry`](Self::carry), 1..=
    /// [`MAX_STAIRS`](Self::MAX_STAIRS) (checked by `carry`): one goes the
    /// whole way in each parameter in turn.
    #[must_use]
    pub fn stairs(mut self, n: usize) -> Self {
        self.stairs = n;
        self
    }

    /// The number of mesh intervals.
    #[must_use]
    pub fn mesh_intervals(&self) -> usize {
        self.intervals
    }

    fn pull(&self, family: &NikolaiRod, target: f64) -> Pull {
        Pull::new(*family.rod(), Target::Force(target)).intervals(self.intervals)
    }

    fn solver(&self, family: &NikolaiRod) -> Result<Collocation> {
        self.pull(family, 3.0).check()
    }

    /// Pulls the family's rod to F/((2πn)²B) = `max_force_scaled` and
    /// returns its pop-outs as pairs (maximum, minimum) of located folds,
    /// as solutions of `family`.
    ///
    /// # Errors
    /// As [`Pull::run`]; [`Error::InvalidArgument`] if the folds do not
    /// alternate maximum, minimum (a pull that ended between the two folds
    /// of a pop-out drops the unpaired one).
    pub fn pop_outs(
        &self,
        family: &NikolaiRod,
        max_force_scaled: f64,
    ) -> Result<Vec<[Solution; 2]>> {
        let mut folds: Vec<(f64, Solution)> = Vec::new();
        self.pull(family, max_force_scaled).run(|p: &Point| {
            if p.kind() == PointKind::Fold {
                folds.push((p.dparameter_ds(), p.solution().clone()));
            }
            ControlFlow::Continue(())
        })?;
        let mut pairs = Vec::new();
        let mut it = folds.into_iter();
        while let (Some((_, max)), Some((_, min))) = (it.next(), it.next()) {
            let (fmax, fmin) = (max.parameters()[Rod::FORCE], min.parameters()[Rod::FORCE]);
            if fmax <= fmin {
                return Err(Error::InvalidArgument {
                    name: "pop-out fold force",
                    value: fmax,
                    allowed: "a maximum of F above the minimum that follows it",
                });
            }
            pairs.push([family.extend(&max), family.extend(&min)]);
        }
        Ok(pairs)
    }

    /// Continues the fold `start` (a solution of `family` at a fold in the
    /// scaled force) in `parameter` ([`Rod::THETA0`],
    /// [`NikolaiRod::LN_A_OVER_B`] or [`NikolaiRod::NU`]) towards `to`, and
    /// stops at the first cusp or at `to`, whichever comes first (a
    /// `start` already at `to` is corrected on its mesh and returned as
    /// `Reached`). With a [`tolerance`](Self::tolerance) the cusp or fold
    /// it ends at is checked against its mesh.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for another parameter;
    /// [`Error::InvalidArgument`] for a [`tolerance`](Self::tolerance)
    /// that is not positive and finite;
    /// [`Error::LengthMismatch`] if `start` is not a solution of a
    /// [`NikolaiRod`] (e.g. the [`Rod`]'s own); the errors of
    /// [`FoldContinuation::run`] at the start.
    pub fn follow(
        &self,
        family: &NikolaiRod,
        start: &Solution,
        parameter: usize,
        to: f64,
    ) -> Result<Followed> {
        self.check_tolerance()?;
        let followed = self.follow_on_mesh(family, start, parameter, to)?;
        Ok(self.checked_end(family, followed, parameter))
    }

    /// [`follow`](Self::follow) on the search's mesh, unchecked.
    fn follow_on_mesh(
        &self,
        family: &NikolaiRod,
        start: &Solution,
        parameter: usize,
        to: f64,
    ) -> Result<Followed> {
        a_spring_parameter("fold-curve parameter", parameter)?;
        of_the_family(start)?;
        let from = start.parameters()[parameter];
        let w = family.rod().norm_weights();
        let settings = Continuation::new(parameter)
            .solver(self.solver(family)?)
            .weights(&w)
            .step((to - from).signum() * 0.01)
            .step_bounds(1e-8, self.ds_max)
            .locate_tolerance(1e-9)
            .stop_at(to)
            .max_steps(self.max_steps);
        let fold = FoldContinuation::new(NikolaiRod::FORCE_SCALED, settings);
        if from == to {
            // already there: the start, corrected as a point of its fold curve
            let here = fold.locate_on(family, start, start.mesh())?;
            return Ok(Followed::Reached(Box::new(here)));
        }
        let mut first = FirstCusp(None);
        let curve = fold.run(family, start, &mut first)?;
        if let Some(c) = first.0 {
            return Ok(Followed::Cusp(Box::new(c)));
        }
        Ok(match curve.termination() {
            Termination::ParameterValue(_) => Followed::Reached(Box::new(
                curve
                    .last()
                    .expect("a run that reached its stop has points")
                    .clone(),
            )),
            t => Followed::Ended(t.clone()),
        })
    }

    /// [`Error::InvalidArgument`] unless the [`tolerance`](Self::tolerance)
    /// is unset, or positive and finite.
    fn check_tolerance(&self) -> Result<()> {
        self.tolerance.map_or(Ok(()), |tol| {
            a_tolerance(
                "tolerance",
                tol,
                "a positive finite accuracy of a fold's F/((2πn)²B) or a cusp's parameter",
            )
        })
    }

    /// With a [`tolerance`](Self::tolerance), the fold or cusp `followed`
    /// ended at (a fold curve in `parameter`) checked against its mesh.
    fn checked_end(&self, family: &NikolaiRod, followed: Followed, parameter: usize) -> Followed {
        let Some(tol) = self.tolerance else {
            return followed;
        };
        match followed {
            Followed::Reached(p) => {
                Followed::Reached(Box::new(self.checked(family, *p, parameter, tol)))
            }
            Followed::Cusp(p) => Followed::Cusp(Box::new(self.checked(family, *p, parameter, tol))),
            ended => ended,
        }
    }

    /// Carries the fold `start` (a solution of `family` at a fold in the
    /// scaled force) to the scene (θ0 in radians, A/B, ν) along a
    /// staircase about the straight line from `start`'s parameters in
    /// (θ0, ln A/B, ν): [`stairs`](Self::stairs) rounds of three legs, in
    /// θ0, then ln(A/B), then ν ([`follow`](Self::follow)), each round
    /// covering its share of the way in each. `Reached` gives the fold at the scene, so its
    /// force F/((2πn)²B) ([`NikolaiRod::FORCE_SCALED`]); carrying both folds
    /// of a pop-out gives its maximum and minimum force there, the width of
    /// its hysteresis loop. `Cusp` says the pop-out vanishes on this path
    /// (its two folds meet): the count at a scene is the diagram's
    /// ([`super::PhaseDiagram::pop_outs`]), since a region need not contain
    /// the whole path. Returned with the parameter of the leg that ended
    /// it ([`NikolaiRod::NU`] when the scene was reached). Legs that have
    /// nothing to go are skipped, but the last (in ν) is always followed.
    /// With a [`tolerance`](Self::tolerance) only what ends the carry (the
    /// fold at the scene, or the cusp met) is checked against its mesh; the
    /// legs run on the search's mesh.
    ///
    /// Why a staircase: with one round the path goes the whole way in θ0
    /// at the reference's ν before it moves ν, and a region that reaches
    /// the scene need not reach that corner: carried so to (87°, 10, −0.3),
    /// pop-outs 1 and 2 vanished at θ0 = 87.485° and 87.176° (their cusps
    /// at ν = 0.05), ν first met the re-pairings near 90° instead; four
    /// rounds carry them to 3.3935 and 5.2553, the pull's 3.3937 and
    /// 5.2539 within the 48 intervals' error at these forces, and eight
    /// rounds give the same to the printed digits (docs/ACCURACY.md).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for [`stairs`](Self::stairs) outside
    /// 1..=[`MAX_STAIRS`](Self::MAX_STAIRS); [`Error::InvalidArgument`]
    /// for a [`tolerance`](Self::tolerance) that is not positive and
    /// finite; the errors of
    /// [`Stiffness::nikolai`] and [`Rod::new`] for a scene
    /// that is not a spring (θ0 outside (0, π/2], A/B not positive and
    /// finite, ν outside (−1, ½]); [`Error::LengthMismatch`] for a `start`
    /// that is not a solution of a [`NikolaiRod`]; those of
    /// [`follow`](Self::follow).
    pub fn carry(
        &self,
        family: &NikolaiRod,
        start: &Solution,
        (theta0, a_over_b, nu): (f64, f64, f64),
    ) -> Result<(usize, Followed)> {
        if !(1..=Self::MAX_STAIRS).contains(&self.stairs) {
            return Err(Error::InvalidCount {
                name: "stairs",
                value: self.stairs as u64,
                allowed: "1..=64 rounds of the three legs (CuspSearch::MAX_STAIRS)",
            });
        }
        Rod::new(
            family.rod().coils(),
            theta0,
            Stiffness::nikolai(a_over_b, nu)?,
        )?;
        of_the_family(start)?;
        let mut at = start.clone();
        let p = start.parameters();
        let legs = [
            (Rod::THETA0, p[Rod::THETA0], theta0),
            (
                NikolaiRod::LN_A_OVER_B,
                p[NikolaiRod::LN_A_OVER_B],
                a_over_b.ln(),
            ),
            (NikolaiRod::NU, p[NikolaiRod::NU], nu),
        ];
        self.check_tolerance()?;
        let stairs = self.stairs;
        for k in 1..=stairs {
            for &(parameter, from, to) in &legs {
                let to = if k == stairs {
                    to
                } else {
                    from + (to - from) * k as f64 / stairs as f64
                };
                if k == stairs && parameter == NikolaiRod::NU {
                    break; // the last leg, below
                }
                if at.parameters()[parameter] == to {
                    continue;
                }
                match self.follow_on_mesh(family, &at, parameter, to)? {
                    Followed::Reached(fold) => at = fold.solution().clone(),
                    ended => return Ok((parameter, self.checked_end(family, ended, parameter))),
                }
            }
        }
        let last = self.follow_on_mesh(family, &at, NikolaiRod::NU, nu)?;
        Ok((
            NikolaiRod::NU,
            self.checked_end(family, last, NikolaiRod::NU),
        ))
    }
}

/// [`Error::InvalidCount`] unless `parameter` is one of the spring's:
/// θ0, ln A/B or ν.
fn a_spring_parameter(name: &'static str, parameter: usize) -> Result<()> {
    if [Rod::THETA0, NikolaiRod::LN_A_OVER_B, NikolaiRod::NU].contains(&parameter) {
        return Ok(());
    }
    Err(Error::InvalidCount {
        name,
        value: parameter as u64,
        allowed: "Rod::THETA0, NikolaiRod::LN_A_OVER_B or NikolaiRod::NU",
    })
}

/// [`Error::InvalidArgument`] unless `tol` is positive and finite.
fn a_tolerance(name: &'static str, tol: f64, allowed: &'static str) -> Result<()> {
    if tol > 0.0 && tol.is_finite() {
        return Ok(());
    }
    Err(Error::InvalidArgument {
        name,
        value: tol,
        allowed,
    })
}

/// [`Error::LengthMismatch`] unless `start` has a [`NikolaiRod`]'s
/// parameters (a fold of the [`Rod`] itself has three).
fn of_the_family(start: &Solution) -> Result<()> {
    if start.parameters().len() == NikolaiRod::PARAMETERS {
        return Ok(());
    }
    Err(Error::LengthMismatch {
        name: "parameters of the fold (a solution of the NikolaiRod)",
        found: start.parameters().len() as u64,
        expected: NikolaiRod::PARAMETERS as u64,
    })
}

/// Stops a fold curve at its first cusp.
struct FirstCusp(Option<FoldPoint>);

impl FoldObserver for &mut FirstCusp {
    fn cusp(&mut self, cusp: &FoldPoint) -> ControlFlow<()> {
        debug_assert_eq!(cusp.kind(), FoldPointKind::Cusp);
        self.0 = Some(cusp.clone());
        ControlFlow::Break(())
    }
}
