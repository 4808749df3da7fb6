//! Folds and cusps checked against their mesh: located again with every
//! interval halved ([`CuspSearch::mesh_checked`], [`CuspSearch::cusp_mesh_checked`]).

use super::{CUSP_NEWTON_TOLERANCE, CuspSearch, a_spring_parameter, a_tolerance, of_the_family};
use crate::bvp::Solution;
use crate::continuation::{
    Continuation, FoldContinuation, FoldPoint, FoldPointKind, FoldProblem, restricted,
};
use crate::error::Result;
use crate::rod::{NikolaiRod, Rod};
#[cfg(doc)]
use {super::Followed, crate::error::Error};

/// Newton's iterations for a fold located on a finer mesh
/// ([`CuspSearch::mesh_checked`]): from a coarse fold whose force is
/// 0.016 off (the paper's spring's first pop-out carried to F/((2πn)²B) ≈
/// 4.7 on 48 intervals) the damped iteration on 96 intervals takes 14.
const FINER_NEWTON: u32 = 40;

/// Newton's tolerance on a finer mesh ([`CuspSearch::mesh_checked`]) as a
/// fraction of the force tolerance (within [1e-12, 1e-8]): the extended
/// problem's rounding floor rises with the intervals (measured: 1.1e-9 on
/// 384 intervals at F/((2πn)²B) ≈ 5), and a correction a thousandth of the
/// force tolerance moves the fold's force by far less than the tolerance.
const FINER_NEWTON_FRACTION: f64 = 1e-3;

impl CuspSearch {
    /// The most halvings of [`mesh_checked`](Self::mesh_checked).
    pub const MAX_HALVINGS: u32 = 3;

    /// A fold of `family` (as [`carry`](Self::carry) returns one) checked
    /// against its mesh: located again with every interval halved
    /// ([`FoldContinuation::locate_on`]: same parameters, F/((2πn)²B) and
    /// the shape free), and halved again while its scaled force moved by
    /// more than `tol`, at most [`MAX_HALVINGS`](Self::MAX_HALVINGS) times.
    ///
    /// The answer is the fold on the finest mesh; [`MeshChecked::change`] is
    /// how far the force moved in the last halving. With m Gauss points the
    /// fold's force converges as h^(2m) once the mesh resolves the loops, so
    /// the change overestimates the finer fold's error by up to 2^(2m) − 1;
    /// a change above `tol` after the last halving says the tolerance was
    /// not met. Measured (docs/ACCURACY.md): the paper's spring's first
    /// pop-out carried to (89.944°, 22.075, −0.029), where it peaks at
    /// F/((2πn)²B) ≈ 4.74, sits 0.016 above its converged force on the
    /// default 48 intervals.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a `tol` that is not positive and
    /// finite; [`Error::LengthMismatch`] for a `fold` that is not a
    /// solution of a [`NikolaiRod`]; a Newton error where the finer fold is
    /// not found from the coarser one.
    pub fn mesh_checked(
        &self,
        family: &NikolaiRod,
        fold: &Solution,
        tol: f64,
    ) -> Result<MeshChecked> {
        a_tolerance(
            "fold force tolerance",
            tol,
            "a positive finite change of F/((2πn)²B)",
        )?;
        of_the_family(fold)?;
        self.fold_halved(family, fold, tol).map(mesh_checked_of)
    }

    /// A cusp of the cascade (the [`FoldPoint::extended`] of a
    /// [`Followed::Cusp`] met by [`follow`](Self::follow) in `parameter`)
    /// checked against its mesh: the cusp is a fold in `parameter` of the
    /// fold problem ([`crate::continuation::FoldProblem`]; what
    /// [`cusp_curve`](Self::cusp_curve) continues), located again with every
    /// interval halved ([`FoldContinuation::locate_on`], the other
    /// parameters fixed) while its `parameter` moved by more than `tol`, at
    /// most [`MAX_HALVINGS`](Self::MAX_HALVINGS) times. The answer's
    /// [`MeshChecked::fold`] is the fold problem's solution at the cusp on
    /// the finest mesh, its [`MeshChecked::change`] the move of `parameter`
    /// (θ0 in radians, ln A/B or ν) in the last halving. Measured: the
    /// paper's spring's first pop-out, its cusp in θ0 found on 24 intervals,
    /// moves by 5.2e-10 rad to 48 and 1e-12 to 96 (0.3 s and 0.7 s).
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for another `parameter` than
    /// [`Rod::THETA0`], [`NikolaiRod::LN_A_OVER_B`] or [`NikolaiRod::NU`];
    /// [`Error::InvalidArgument`] for a `tol` that is not positive and
    /// finite; a length error for a `cusp` that is not a solution of the
    /// family's fold problem; a Newton error where the finer cusp is not
    /// found from the coarser one.
    pub fn cusp_mesh_checked(
        &self,
        family: &NikolaiRod,
        cusp: &Solution,
        parameter: usize,
        tol: f64,
    ) -> Result<MeshChecked> {
        a_spring_parameter("cusp parameter", parameter)?;
        a_tolerance(
            "cusp tolerance",
            tol,
            "a positive finite change of the cusp's parameter",
        )?;
        self.cusp_halved(family, cusp, parameter, tol)
            .map(mesh_checked_of)
    }

    /// [`mesh_checked`](Self::mesh_checked)'s halvings, on checked input:
    /// the fold of `family` on the finest mesh.
    fn fold_halved(
        &self,
        family: &NikolaiRod,
        fold: &Solution,
        tol: f64,
    ) -> Result<(FoldPoint, f64, u32)> {
        let locate = FoldContinuation::new(
            NikolaiRod::FORCE_SCALED,
            Continuation::new(Rod::THETA0).solver(
                self.solver(family)?
                    .max_newton(FINER_NEWTON)
                    .newton_tolerance((FINER_NEWTON_FRACTION * tol).clamp(1e-12, 1e-8)),
            ),
        );
        halved_until(&locate, family, fold, NikolaiRod::FORCE_SCALED, tol)
    }

    /// [`cusp_mesh_checked`](Self::cusp_mesh_checked)'s halvings, on
    /// checked input: the fold in `parameter` of the fold problem on the
    /// finest mesh (its [`FoldPoint::solution`] is the fold problem's).
    fn cusp_halved(
        &self,
        family: &NikolaiRod,
        cusp: &Solution,
        parameter: usize,
        tol: f64,
    ) -> Result<(FoldPoint, f64, u32)> {
        // (the fold problem's continuation parameter, fixed here)
        let fixed = if parameter == Rod::THETA0 {
            NikolaiRod::LN_A_OVER_B
        } else {
            Rod::THETA0
        };
        let problem = FoldProblem::new(family, &[]);
        let locate = FoldContinuation::new(
            parameter,
            Continuation::new(fixed).solver(
                self.solver(family)?
                    .free_parameters(&[NikolaiRod::FORCE_SCALED])
                    .max_newton(FINER_NEWTON)
                    .newton_tolerance(CUSP_NEWTON_TOLERANCE),
            ),
        );
        halved_until(&locate, &problem, cusp, parameter, tol)
    }

    /// `point`, a fold (of a fold curve in `parameter`) or a cusp that
    /// [`follow`](Self::follow) found, checked against its mesh to `tol`
    /// ([`mesh_checked`](Self::mesh_checked) on a fold's force,
    /// [`cusp_mesh_checked`](Self::cusp_mesh_checked) on a cusp's
    /// `parameter`): the point on the finest mesh with its
    /// [`FoldPoint::mesh_change`], or the point as found with a change of
    /// `∞` where the finer mesh did not find it (a Newton failure there, or
    /// a mesh past [`crate::bvp::Mesh::MAX_INTERVALS`]).
    pub(super) fn checked(
        &self,
        family: &NikolaiRod,
        point: FoldPoint,
        parameter: usize,
        tol: f64,
    ) -> FoldPoint {
        let finer = if point.kind() == FoldPointKind::Cusp {
            self.cusp_halved(family, point.extended(), parameter, tol)
                .and_then(|(at, change, _)| {
                    let extended = at.solution().clone();
                    Ok((restricted(family, &[], &extended)?, extended, change))
                })
        } else {
            self.fold_halved(family, point.solution(), tol)
                .map(|(at, change, _)| (at.solution().clone(), at.extended().clone(), change))
        };
        match finer {
            Ok((solution, extended, change)) => point.on_finer_mesh(solution, extended, change),
            Err(_) => point.unresolved(),
        }
    }
}

/// `start` located again by `locate` on its mesh halved, while the
/// parameter `watched` moves by more than `tol`, at most
/// [`CuspSearch::MAX_HALVINGS`] times: the point on the finest mesh, how far
/// `watched` moved in the last halving, and the number of halvings.
fn halved_until<P: crate::bvp::Problem + ?Sized>(
    locate: &FoldContinuation,
    problem: &P,
    start: &Solution,
    watched: usize,
    tol: f64,
) -> Result<(FoldPoint, f64, u32)> {
    let value = |s: &Solution| s.parameters()[watched];
    let (mut at, mut change, mut halvings) = (None::<FoldPoint>, f64::INFINITY, 0);
    while halvings < CuspSearch::MAX_HALVINGS && change > tol {
        let coarse = at.as_ref().map_or(start, FoldPoint::solution);
        let finer = locate.locate_on(problem, coarse, &coarse.mesh().halved()?)?;
        change = (value(finer.solution()) - value(coarse)).abs();
        halvings += 1;
        at = Some(finer);
    }
    let at = at.expect("MAX_HALVINGS ≥ 1 and an infinite change: one halving at least");
    Ok((at, change, halvings))
}

/// A fold or a cusp checked against its mesh ([`CuspSearch::mesh_checked`],
/// [`CuspSearch::cusp_mesh_checked`]).
#[derive(Debug, Clone)]
pub struct MeshChecked {
    /// The fold on the finest mesh (a solution of the [`NikolaiRod`]; for
    /// a cusp, of its fold problem).
    pub fold: Solution,
    /// How far the checked parameter moved between the last two meshes:
    /// |ΔF|/((2πn)²B) for a fold, the cusp's parameter for a cusp.
    pub change: f64,
    /// How many times the mesh was halved.
    pub halvings: u32,
}

/// The [`MeshChecked`] of [`halved_until`]'s finest point, last change and
/// halvings.
fn mesh_checked_of((at, change, halvings): (FoldPoint, f64, u32)) -> MeshChecked {
    MeshChecked {
        fold: at.solution().clone(),
        change,
        halvings,
    }
}
