//! Branch switching at a located branch point.

use super::run::drive;
use super::{Continuation, Observer, Point, PointKind, Run, Steps};
use crate::bvp::Problem;
use crate::bvp::system::State;
use crate::error::{Error, Result};

/// BranchSide of a bifurcating branch relative to the second null vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BranchSide {
    /// Along +φ.
    Positive,
    /// Along −φ.
    Negative,
}

impl Continuation {
    /// Starts the bifurcating branch at a located branch point `bp` along
    /// ±φ, φ the second null vector, and runs it like [`Continuation::run`].
    ///
    /// # Errors
    /// [`Error::NotABranchPoint`] unless `bp` is a located branch point of a
    /// run with the same problem; otherwise as [`Continuation::steps`].
    pub fn run_from_branch_point<P: Problem + ?Sized, O: Observer>(
        &self,
        problem: &P,
        bp: &Point,
        direction: BranchSide,
        observer: O,
    ) -> Result<Run> {
        let steps = self.switch_branch(problem, bp, direction)?;
        Ok(drive(steps, observer))
    }

    /// The iterator form of [`Continuation::run_from_branch_point`].
    ///
    /// # Errors
    /// As [`Continuation::run_from_branch_point`].
    pub fn switch_branch<'a, P: Problem + ?Sized>(
        &'a self,
        problem: &'a P,
        bp: &Point,
        direction: BranchSide,
    ) -> Result<Steps<'a, P>> {
        let Some(tangent) = bp
            .tangent
            .as_ref()
            .filter(|_| bp.kind == PointKind::BranchPoint)
        else {
            return Err(Error::NotABranchPoint {
                arclength: bp.arclength,
                kind: bp.kind.name(),
            });
        };
        Steps::new(
            self,
            problem,
            &bp.solution,
            Some((tangent.clone(), direction, bp.arclength)),
        )
    }
}

impl<P: Problem + ?Sized> Steps<'_, P> {
    /// Starts at a located branch point along ±φ, φ the second null vector
    /// of [F_x; τᵀ] (one solve with the nearly singular factorisation,
    /// orthogonalised against τ).
    pub(super) fn start_on_bifurcating_branch(
        &mut self,
        tangent: State,
        direction: BranchSide,
        arclength: f64,
    ) -> Result<()> {
        self.arclength = arclength;
        let x0 = self.x0.clone();
        self.t0 = tangent;
        self.set_tangent_border(0.0);
        if let Err(e) = self.sys.factor(&x0) {
            // Exactly singular at the located point: the null
            // vector of a neighbour 1e-7 along the branch is as good.
            if !matches!(e, Error::SingularJacobian { .. }) {
                return Err(e);
            }
            let mut shifted = x0.clone();
            let t0 = self.t0.clone();
            shifted.axpy(1e-7, &t0, &self.sys.free.clone());
            self.sys.factor(&shifted)?;
        }
        // One solve with the nearly singular matrix gives its null
        // vector; remove the τ component.
        let mut r = self.sys.zero_residual();
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 + 0.5
        };
        for v in r
            .stage
            .iter_mut()
            .chain(r.cont.iter_mut())
            .chain(r.bc.iter_mut())
            .chain(r.dense.iter_mut())
        {
            *v = next();
        }
        let mut phi = self.sys.zero_state();
        self.sys.solve(&r, &mut phi)?;
        let a = self.inner(&phi, &self.t0.clone()) / self.inner(&self.t0.clone(), &self.t0.clone());
        let t0 = self.t0.clone();
        phi.axpy(-a, &t0, &self.sys.free.clone());
        let nrm = self.norm(&phi);
        let sgn = if direction == BranchSide::Positive {
            1.0
        } else {
            -1.0
        };
        phi.scale(sgn / nrm);
        self.t0 = phi;
        self.set_tangent_border(0.0);
        // [F_x; φᵀ] is singular at the branch point itself (τ is its
        // null vector): the first corrector factorises afresh, and
        // detection restarts after the first step.
        self.factored_at_x0 = false;
        self.skip_detection = true;
        Ok(())
    }
}
