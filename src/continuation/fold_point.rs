//! What a fold-curve run gives: its points ([`FoldPoint`], of a
//! [`FoldPointKind`]), the hooks that see them ([`FoldObserver`]) and the
//! finished curve ([`FoldCurve`]).

use std::fmt;
use std::ops::ControlFlow;

use super::Termination;
use crate::bvp::Solution;

/// The kind of a point on a fold curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FoldPointKind {
    /// The first point (the start fold, corrected).
    Start,
    /// An ordinary step.
    Regular,
    /// A located cusp: dλ/ds = dμ/ds = 0, two folds meet and vanish.
    Cusp,
    /// A located turn of the curve in the parameter with this index (its
    /// rate is zero, the other's is not).
    Turn(usize),
    /// The second parameter reached a requested value
    /// ([`Continuation::stop_at`](super::Continuation::stop_at)).
    ParameterValue,
    /// A located zero of the user event with this index
    /// ([`Continuation::stop_when`](super::Continuation::stop_when), evaluated on the extended solution).
    Event(usize),
}

/// One point of a fold curve.
#[derive(Debug, Clone)]
pub struct FoldPoint {
    pub(super) solution: Solution,
    pub(super) extended: Solution,
    pub(super) fold: usize,
    pub(super) second: usize,
    pub(super) arclength: f64,
    pub(super) velocity: Option<(f64, f64)>,
    pub(super) kind: FoldPointKind,
    pub(super) mesh_change: Option<f64>,
}

impl FoldPoint {
    /// The solution of the problem at the fold.
    #[must_use]
    pub fn solution(&self) -> &Solution {
        &self.solution
    }

    /// The solution of the extended problem: components 0..n are y, n..2n
    /// the null vector v; parameters p, then δq.
    #[must_use]
    pub fn extended(&self) -> &Solution {
        &self.extended
    }

    /// The null vector v (∫ v·v + δq·δq = 1) at mesh point `j`.
    ///
    /// # Panics
    /// If `j` is past the last mesh point.
    #[must_use]
    pub fn null_vector_at_mesh(&self, j: usize) -> &[f64] {
        let n = self.solution.dim();
        &self.extended.at_mesh(j)[n..]
    }

    /// Every parameter of the problem.
    #[must_use]
    pub fn parameters(&self) -> &[f64] {
        self.solution.parameters()
    }

    /// λ, the parameter of the fold.
    #[must_use]
    pub fn fold_parameter(&self) -> f64 {
        self.solution.parameters()[self.fold]
    }

    /// μ, the second (continuation) parameter.
    #[must_use]
    pub fn parameter(&self) -> f64 {
        self.solution.parameters()[self.second]
    }

    /// Arclength from the start of the curve (the continuation's norm on
    /// the extended problem).
    #[must_use]
    pub fn arclength(&self) -> f64 {
        self.arclength
    }

    /// (dλ/ds, dμ/ds) in the unit tangent; `None` at a stop value or event
    /// (located for the stop alone).
    #[must_use]
    pub fn velocity(&self) -> Option<(f64, f64)> {
        self.velocity
    }

    /// What the point is.
    #[must_use]
    pub fn kind(&self) -> FoldPointKind {
        self.kind
    }

    /// How far the located quantity moved when the point was located again
    /// on its mesh with every interval halved, the last time it was
    /// (`None` for a point not checked so; a search with a tolerance checks
    /// what it returns: [`crate::rod::CuspSearch::tolerance`]). The located
    /// quantity is λ ([`fold_parameter`](Self::fold_parameter)) for a fold,
    /// μ ([`parameter`](Self::parameter)) for a cusp. `∞` where the point
    /// was not found on the halved mesh.
    #[must_use]
    pub fn mesh_change(&self) -> Option<f64> {
        self.mesh_change
    }

    /// The same point on a finer mesh: `solution` and `extended` there,
    /// `change` how far the located quantity moved to get there
    /// ([`mesh_change`](Self::mesh_change)).
    pub(crate) fn on_finer_mesh(self, solution: Solution, extended: Solution, change: f64) -> Self {
        Self {
            solution,
            extended,
            mesh_change: Some(change),
            ..self
        }
    }

    /// The point as it was found, marked as not found on the halved mesh
    /// (its [`mesh_change`](Self::mesh_change) `∞`).
    pub(crate) fn unresolved(self) -> Self {
        Self {
            mesh_change: Some(f64::INFINITY),
            ..self
        }
    }
}

impl fmt::Display for FoldPoint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{:?} lambda={:.15e} mu={:.15e} s={:.6e}",
            self.kind,
            self.fold_parameter(),
            self.parameter(),
            self.arclength
        )?;
        match self.mesh_change {
            Some(change) => write!(
                f,
                " mesh_change={change:.1e} ({} intervals)",
                self.solution.mesh().intervals()
            ),
            None => Ok(()),
        }
    }
}

/// Hooks of a fold-curve run: [`point`](Self::point) for every point in
/// order, [`cusp`](Self::cusp) after it for a cusp, [`finish`](Self::finish)
/// once. `Break` ends the run with [`Termination::Stopped`], keeping the
/// points so far. Implemented for `()` and for closures
/// `FnMut(&FoldPoint) -> ControlFlow<()>`.
pub trait FoldObserver {
    /// Every point, in order.
    fn point(&mut self, point: &FoldPoint) -> ControlFlow<()> {
        let _ = point;
        ControlFlow::Continue(())
    }
    /// Every located cusp, after [`point`](Self::point).
    fn cusp(&mut self, cusp: &FoldPoint) -> ControlFlow<()> {
        let _ = cusp;
        ControlFlow::Continue(())
    }
    /// Once, with the termination.
    fn finish(&mut self, termination: &Termination) {
        let _ = termination;
    }
}

impl FoldObserver for () {}

impl<F: FnMut(&FoldPoint) -> ControlFlow<()>> FoldObserver for F {
    fn point(&mut self, point: &FoldPoint) -> ControlFlow<()> {
        self(point)
    }
}

/// A fold curve: every point in order, why it ended, and the work it took.
#[derive(Debug, Clone)]
pub struct FoldCurve {
    pub(super) points: Vec<FoldPoint>,
    pub(super) termination: Termination,
    pub(super) accepted: usize,
    pub(super) rejected: usize,
    pub(super) newton_iterations: u64,
}

impl FoldCurve {
    /// Every point, in order.
    #[must_use]
    pub fn points(&self) -> &[FoldPoint] {
        &self.points
    }

    /// Why the run ended.
    #[must_use]
    pub fn termination(&self) -> &Termination {
        &self.termination
    }

    /// The located cusps.
    pub fn cusps(&self) -> impl Iterator<Item = &FoldPoint> {
        self.points.iter().filter(|p| p.kind == FoldPointKind::Cusp)
    }

    /// The last point.
    #[must_use]
    pub fn last(&self) -> Option<&FoldPoint> {
        self.points.last()
    }

    /// Accepted steps.
    #[must_use]
    pub fn accepted(&self) -> usize {
        self.accepted
    }

    /// Rejected (halved and retried) steps.
    #[must_use]
    pub fn rejected(&self) -> usize {
        self.rejected
    }

    /// Corrector iterations of every step and location.
    #[must_use]
    pub fn newton_iterations(&self) -> u64 {
        self.newton_iterations
    }
}
