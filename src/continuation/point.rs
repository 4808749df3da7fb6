//! The points of a branch and their kinds.

use std::fmt;

use crate::bvp::Solution;
use crate::bvp::system::State;

/// The kind of a point on a branch.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum PointKind {
    /// The first point of a run.
    Start,
    /// An ordinary step.
    Regular,
    /// A located fold (limit point): dλ/ds = 0.
    Fold,
    /// A located branch point: det [F_x; τᵀ] = 0.
    BranchPoint,
    /// A located point where λ reached a requested value.
    ParameterValue,
    /// A located zero of the user event with this index.
    Event(usize),
}

impl PointKind {
    pub(super) fn name(self) -> &'static str {
        match self {
            PointKind::Start => "start point",
            PointKind::Regular => "regular point",
            PointKind::Fold => "fold",
            PointKind::BranchPoint => "branch point",
            PointKind::ParameterValue => "parameter value",
            PointKind::Event(_) => "event",
        }
    }
}

impl fmt::Display for PointKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PointKind::Event(i) => write!(f, "event {i}"),
            k => f.write_str(k.name()),
        }
    }
}

/// One point of a branch.
#[derive(Debug, Clone)]
pub struct Point {
    pub(super) solution: Solution,
    pub(super) parameter: f64,
    pub(super) arclength: f64,
    pub(super) newton_iterations: u32,
    pub(super) dparameter: f64,
    pub(super) determinant_sign: f64,
    pub(super) kind: PointKind,
    pub(super) tangent: Option<State>,
    pub(super) diagram: [f64; 2],
    pub(super) diagram_slope: [f64; 2],
    pub(super) diagram_curvature: [f64; 2],
}

impl Point {
    /// The collocation solution at this point.
    #[must_use]
    pub fn solution(&self) -> &Solution {
        &self.solution
    }

    /// The continuation parameter λ.
    #[must_use]
    pub fn parameter(&self) -> f64 {
        self.parameter
    }

    /// Every parameter of the problem at this point.
    #[must_use]
    pub fn parameters(&self) -> &[f64] {
        self.solution.parameters()
    }

    /// Arclength from the start of the run (in the weighted integral norm).
    #[must_use]
    pub fn arclength(&self) -> f64 {
        self.arclength
    }

    /// Newton iterations of the corrector that produced the point.
    #[must_use]
    pub fn newton_iterations(&self) -> u32 {
        self.newton_iterations
    }

    /// dλ/ds, the parameter component of the unit tangent (its sign changes
    /// at folds).
    #[must_use]
    pub fn dparameter_ds(&self) -> f64 {
        self.dparameter
    }

    /// The sign (±1) of det [F_x; τᵀ] of the discretised system; it changes
    /// at branch points. Along a branch of stable equilibria of a variational
    /// problem it changes exactly when a mode crosses zero, so the count of
    /// changes since a known-stable point tracks the index.
    #[must_use]
    pub fn determinant_sign(&self) -> f64 {
        self.determinant_sign
    }

    /// The point (σ_λ λ, σ_g g) in the plane of the diagram
    /// ([`Continuation::diagram`](super::Continuation::diagram)).
    #[must_use]
    pub fn diagram(&self) -> [f64; 2] {
        self.diagram
    }

    /// Its derivative along the branch, d/ds of [`Self::diagram`] (s the
    /// arclength): with the points, the data of the branch's Hermite
    /// interpolant.
    #[must_use]
    pub fn diagram_slope(&self) -> [f64; 2] {
        self.diagram_slope
    }

    /// Its second derivative along the branch, d²/ds² of
    /// [`Self::diagram`], at every point of a run with a
    /// [`tolerance`](super::Continuation::tolerance) below 1e-3, whose
    /// interpolant between points is the quintic Hermite polynomial of the
    /// points, slopes and curvatures. `None` in runs without a tolerance,
    /// at tolerances of 1e-3 and looser (their interpolant is the cubic of
    /// the points and slopes), and where x'' could not be had.
    #[must_use]
    pub fn diagram_curvature(&self) -> Option<[f64; 2]> {
        let [a, b] = self.diagram_curvature;
        (a.is_finite() && b.is_finite()).then_some(self.diagram_curvature)
    }

    /// What the point is.
    #[must_use]
    pub fn kind(&self) -> PointKind {
        self.kind
    }

    /// Whether the point is a located special point (not start or regular).
    #[must_use]
    pub fn is_special(&self) -> bool {
        !matches!(self.kind, PointKind::Start | PointKind::Regular)
    }
}

impl fmt::Display for Point {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} lambda={:.15e} s={:.6e} dlambda/ds={:+.3e} det_sign={:+} newton={}",
            self.kind,
            self.parameter,
            self.arclength,
            self.dparameter,
            self.determinant_sign,
            self.newton_iterations
        )
    }
}
