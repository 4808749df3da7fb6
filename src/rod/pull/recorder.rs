//! Continuation points turned into the rod's curve, folds and loop counts.

use crate::bvp::Solution;
use crate::continuation::{Point, PointKind};
use crate::curve::{Curvature, Fold, FoldKind, ForceExtension, ForcePoint, Slope};
use crate::error::{Error, Result};
use crate::load::Control;

use super::super::{Equilibrium, Rod};
use super::Start;

/// Turns continuation points into the curve, the folds and the loop counts.
pub(super) struct Recorder {
    rod: Rod,
    pub(super) curve: ForceExtension,
    pub(super) folds: Vec<Fold>,
    pub(super) loops: Vec<Option<u32>>,
    locate_folds: bool,
    /// dλ/ds at the last curve point.
    last_dl: f64,
    /// The pull's tolerance: the slack of |Δz| ≤ 1 (robust10b).
    tolerance: f64,
    /// Whether to keep the last curve point's solution
    /// ([`Pull::relax_to`](super::Pull::relax_to)).
    keep_last: bool,
    /// The last curve point, where a looser run can go on from.
    pub(super) last: Option<LastPoint>,
}

/// The last point of the curve as a looser run needs it.
pub(super) struct LastPoint {
    pub(super) solution: Solution,
    pub(super) arclength: f64,
    /// dλ/ds there: the direction to go on in.
    pub(super) dparameter: f64,
    /// The arclength from the point before it: the step to go on with.
    pub(super) step: f64,
}

impl Recorder {
    pub(super) fn new(start: &Start, locate_folds: bool, tolerance: f64, keep_last: bool) -> Self {
        Self {
            tolerance,
            keep_last,
            last: None,
            rod: start.rod,
            curve: ForceExtension::new("rod", "arclength", start.rod.scale()),
            folds: Vec::new(),
            loops: Vec::new(),
            locate_folds,
            last_dl: 0.0,
        }
    }

    pub(super) fn record(&mut self, p: &Point) -> Result<()> {
        // (the start of a run going on from the last point is that point)
        if p.kind() == PointKind::Start && !self.curve.is_empty() {
            return Ok(());
        }
        let eq = Equilibrium::new(self.rod, p.solution().clone())?;
        // (robust10b) |Δz| > 1 beyond the tolerance is no rod: the run ends
        // `Failed` with `NotARod` instead of keeping the point
        if eq.extension().abs() > 1.0 + self.tolerance {
            return Err(Error::NotARod {
                extension: eq.extension(),
                intervals: p.solution().mesh().intervals() as u64,
            });
        }
        let dl = p.dparameter_ds();
        let at = ForcePoint {
            extension: eq.extension(),
            force: eq.force(),
            parameter: p.arclength(),
        };
        let located = p.kind() == PointKind::Fold;
        let detected = !self.locate_folds && self.last_dl * dl < 0.0;
        if located || detected {
            let kind = match (self.rod.control(), self.last_dl > 0.0) {
                (Control::Force, true) => FoldKind::MaxForce,
                (Control::Force, false) => FoldKind::MinForce,
                (Control::Extension, true) => FoldKind::MaxExtension,
                (Control::Extension, false) => FoldKind::MinExtension,
            };
            let index = self.curve.len().saturating_sub(1);
            let point = if located {
                at
            } else {
                self.curve.points()[index]
            };
            self.folds.push(Fold { kind, index, point });
        }
        if !located {
            let [dl, dg] = p.diagram_slope();
            let scale = self.curve.force_scale();
            // (Δz, F) from the diagram's (λ, g): (F/scale, Δz) under force
            // control, (Δz, F_z/scale) under extension control
            let control = self.rod.control();
            let physical = |[l, g]: [f64; 2]| match control {
                Control::Force => (g, l * scale),
                Control::Extension => (l, g * scale),
            };
            let (extension, force) = physical([dl, dg]);
            let slope = Slope { extension, force };
            match p.diagram_curvature() {
                Some(c) => {
                    let (extension, force) = physical(c);
                    self.curve
                        .push_with_curvature(at, slope, Curvature { extension, force });
                }
                None => self.curve.push_with_slope(at, slope),
            }
            self.loops.push(eq.loops());
            self.last_dl = dl;
            if self.keep_last {
                let step = self
                    .last
                    .as_ref()
                    .map_or(0.0, |l| p.arclength() - l.arclength);
                self.last = Some(LastPoint {
                    solution: p.solution().clone(),
                    arclength: p.arclength(),
                    dparameter: p.dparameter_ds(),
                    step,
                });
            }
        }
        Ok(())
    }
}
