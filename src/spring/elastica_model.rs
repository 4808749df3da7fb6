//! [`ElasticaModel`]: the spring flattened into the plane.

use crate::curve::ForceExtension;
use crate::elastica::{Branch, Trace, secondary_fold};
use crate::error::Result;

use super::{Model, Response, Spring, check_samples, check_target};

/// The spring held flat, as between two glass plates (the paper's
/// introduction): the planar elastica with intrinsic curvature 2πn and
/// zero end moments, pulled along its primary υ-branch. Its loops have
/// nowhere to go, so it never pops one; pitch, anisotropy and torsion do
/// not enter (B only).
///
/// Its [`scaffold`](ElasticaModel::scaffold) is what the 3D spring visits
/// between pop-outs: the primary υ-branch and the secondary υ-branches
/// j = n − 1, …, 1 (Section 3.2.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ElasticaModel {
    samples: usize,
}

impl Default for ElasticaModel {
    /// 400 samples per branch.
    fn default() -> Self {
        Self { samples: 400 }
    }
}

impl ElasticaModel {
    /// An elastica model sampling each branch at `samples` points.
    ///
    /// # Errors
    /// [`Error::InvalidCount`](crate::Error::InvalidCount) if `samples < 2`.
    pub fn new(samples: usize) -> Result<Self> {
        Ok(Self {
            samples: check_samples(samples)?,
        })
    }

    /// The branches a spring of n coils can visit up to the target force:
    /// the primary υ-branch, then the whole secondary υ-branches j = n − 1
    /// down to 1 (both arms, lower arm first), each scaled by the spring's
    /// (2πn)². A secondary branch whose fold lies above the target is left
    /// out.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`](crate::Error::InvalidArgument) for a bad target.
    pub fn scaffold(&self, spring: &Spring, max_force_scaled: f64) -> Result<Vec<ForceExtension>> {
        let target = check_target(max_force_scaled)?;
        let n = spring.coils();
        let trace = Trace::new()
            .points(self.samples)
            .max_force_scaled(target)
            .scale_coils(n);
        let mut branches = vec![in_units_of_b(trace.run(n, Branch::Upsilon)?, spring)];
        for j in (1..n).rev() {
            if secondary_fold(n, j)?.force() * spring.stiffness().b()
                < target * spring.force_scale()
            {
                branches.push(in_units_of_b(trace.secondary(n, j)?, spring));
            }
        }
        Ok(branches)
    }
}

impl Model for ElasticaModel {
    fn name(&self) -> &str {
        "elastica"
    }

    /// # Errors
    /// [`Error::InvalidArgument`](crate::Error::InvalidArgument) for a bad target.
    fn pull(&self, spring: &Spring, max_force_scaled: f64) -> Result<Response> {
        let target = check_target(max_force_scaled)?;
        let n = spring.coils();
        let curve = Trace::new()
            .points(self.samples)
            .max_force_scaled(target)
            .scale_coils(n)
            .run(n, Branch::Upsilon)?;
        let curve = in_units_of_b(curve, spring);
        let loops = vec![n; curve.len()];
        Ok(Response::from_curve(self.name(), curve).with_loops(loops))
    }
}

/// The elastica is solved with B = 1: forces scale with the spring's B
/// (extensions do not), and so does the cut-off force.
fn in_units_of_b(curve: ForceExtension, spring: &Spring) -> ForceExtension {
    let b = spring.stiffness().b();
    if b == 1.0 {
        return curve;
    }
    let mut scaled =
        ForceExtension::new(curve.label(), curve.parameter_name(), curve.scale_coils())
            .expect("the curve's own scale coils are valid");
    scaled.extend(curve.points().iter().map(|p| crate::curve::ForcePoint {
        force: p.force * b,
        ..*p
    }));
    scaled
}
