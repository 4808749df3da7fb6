//! [`ElasticaModel`]: the spring flattened into the plane.

use crate::continuation::Termination;
use crate::curve::{ForceExtension, ForcePoint, ForceScale};
use crate::elastica::{Branch, Elastica, Trace, secondary_fold};
use crate::error::Result;
use crate::load::Target;
use crate::special::Modulus;

use super::{Model, Response, Spring, check_samples, check_simple_target};

/// The spring held flat, as between two glass plates (the paper's
/// introduction): the planar elastica with intrinsic curvature 2πn and
/// zero end moments, pulled along its primary υ-branch. Its loops have
/// nowhere to go, so it never pops one (its loop count is n everywhere);
/// pitch, anisotropy and torsion do not enter (B only).
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
    /// The most coils [`scaffold`](Self::scaffold) draws the branches of:
    /// 221, the largest n whose secondary branch j = 1 the elastica
    /// locates in double precision (n/j < 222, [`secondary_fold`]); one
    /// fold search per secondary branch, n − 1 of them.
    pub const MAX_SCAFFOLD_COILS: u32 = 221;

    /// How closely a pull's last F/((2πn)²B) keeps, in the spring's units,
    /// the value the elastica (B = 1) ended at, relative: the conversion
    /// F·B/((2πn)²B) costs a few ulps where the physical force is a normal
    /// double; 1e-13 leaves a margin of 100 over that, as
    /// [`HelixModel::FORCE_ACCURACY`](super::HelixModel::FORCE_ACCURACY)
    /// does. A subnormal physical force (B ≲ 1e-290) misses it: the pull is
    /// refused. (The elastica itself ends on its force limit to 1e-9, see
    /// [`Trace`].)
    pub const FORCE_ACCURACY: f64 = 1e-13;

    /// An elastica model sampling each branch at `samples` points.
    ///
    /// # Errors
    /// [`Error::InvalidCount`](crate::Error::InvalidCount) unless
    /// 2 ≤ `samples` ≤ [`MAX_POINTS`](crate::error::MAX_POINTS).
    pub fn new(samples: usize) -> Result<Self> {
        Ok(Self {
            samples: check_samples(samples)?,
        })
    }

    /// The branches a spring of n coils can visit up to the force
    /// F/((2πn)²B) = `max_force_scaled`: the primary υ-branch, then the whole
    /// secondary υ-branches j = n − 1 down to 1 (both arms, lower arm
    /// first), in the spring's force scale. A secondary branch whose fold
    /// lies above the target is left out.
    ///
    /// # Errors
    /// [`Error::UnreachableTarget`](crate::Error::UnreachableTarget) unless
    /// the force is finite and positive;
    /// [`Error::InvalidCount`](crate::Error::InvalidCount) for more than
    /// [`ElasticaModel::MAX_SCAFFOLD_COILS`] coils, fewer than 3 samples
    /// with more than one coil, or more than
    /// [`MAX_POINTS`](crate::error::MAX_POINTS) points in all (n branches of `samples` points).
    pub fn scaffold(&self, spring: &Spring, max_force_scaled: f64) -> Result<Vec<ForceExtension>> {
        let target = max_force_scaled;
        if !(target.is_finite() && target > 0.0) {
            return Err(crate::Error::UnreachableTarget {
                target: Target::Force(target),
                rest_extension: spring.helix_angle().cos(),
            });
        }
        let n = spring.coils();
        let points = (n as usize).saturating_mul(self.samples);
        if n > Self::MAX_SCAFFOLD_COILS || points > crate::error::MAX_POINTS {
            return Err(crate::Error::InvalidCount {
                name: "coils",
                value: u64::from(n),
                allowed: "at most ElasticaModel::MAX_SCAFFOLD_COILS = 221 coils (n/j < 222), and \
                          coils × samples at most error::MAX_POINTS = 2^22 points",
            });
        }
        if n > 1 && self.samples < 3 {
            // (a secondary branch is drawn with both ends and its fold)
            return Err(crate::Error::InvalidCount {
                name: "samples",
                value: self.samples as u64,
                allowed: "at least 3 samples for a scaffold of more than one coil (a secondary \
                          branch has both ends and its fold)",
            });
        }
        let trace = Trace::new()
            .points(self.samples)
            .max_force_scaled(target)
            .scale_coils(n);
        let mut branches = vec![in_units_of_b(trace.run(n, Branch::Upsilon)?, spring)];
        for j in (1..n).rev() {
            if secondary_fold(n, j)?.force() < target * ForceScale::of_coils(n)?.value() {
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
    /// [`crate::Error::UnreachableTarget`] for a bad target;
    /// [`crate::Error::InvalidArgument`] named "target" for a force the
    /// elastica cannot meet to 1e-9 (subnormal, [`Trace`]);
    /// [`crate::Error::OutsideModel`] for a push, a spring whose
    /// intrinsic strains are not those of its helix, or one whose physical
    /// forces (2πn)²B·F are subnormal (they would miss the target by more
    /// than [`ElasticaModel::FORCE_ACCURACY`]).
    fn pull_to(&self, spring: &Spring, target: Target) -> Result<Response> {
        let target = check_simple_target("elastica", spring, target)?;
        let n = spring.coils();
        let force_scaled = match target {
            Target::Force(f) => f,
            Target::Extension(dz) => {
                upsilon_at_extension(n, dz, spring.helix_angle().cos())?.force_scaled()
            }
        };
        let curve = Trace::new()
            .points(self.samples)
            .max_force_scaled(force_scaled)
            .scale_coils(n)
            .run(n, Branch::Upsilon)
            .map_err(|e| match e {
                // the trace's limit is the user's target
                crate::Error::InvalidArgument {
                    name: "max_force_scaled",
                    allowed,
                    ..
                } => crate::Error::InvalidArgument {
                    name: "target",
                    value: target.value(),
                    allowed,
                },
                e => e,
            })?;
        let traced = curve.force_scaled(curve.len() - 1);
        let curve = in_units_of_b(curve, spring);
        let converted = curve.force_scaled(curve.len() - 1);
        let off = match (traced, converted) {
            (Some(a), Some(b)) => (b - a).abs() / a.abs(),
            _ => f64::NAN,
        };
        if off.is_nan() || off > Self::FORCE_ACCURACY {
            // the physical forces (2πn)²B·F are subnormal: fewer than 53 bits
            return Err(crate::Error::OutsideModel {
                model: "elastica",
                assumption: "forces in the spring's units keep their value to 1e-13 in double \
                             precision; at this stiffness the physical force (2πn)²B·F is below \
                             the smallest normal double (2.2e-308) and has fewer than 53 bits: \
                             use a larger bending stiffness B",
            });
        }
        let stop = match target {
            Target::Force(_) => force_scaled * spring.force_scale(),
            Target::Extension(dz) => dz,
        };
        let loops = vec![Some(n); curve.len()];
        Response::new(
            self.name(),
            target,
            curve,
            Termination::ParameterValue(stop),
        )
        .with_loops(loops)
    }
}

/// How far [`upsilon_at_extension`] follows the υ-branch: to m₁ = e^−690,
/// as [`Trace`] does.
const Q_REACH: f64 = 690.0;

/// The primary υ elastica of n coils with extension `dz` ∈ (0, 1): Δz grows
/// from 0 (the ring, k = 0) towards 1 (k → 1) along the branch; bisection
/// in q = −ln m₁ ∈ [0, 690] (in k it resolved m₁ near k = 1 only to
/// ~1e-16/m₁ and stopped at k = 1 − 2⁻⁵³, up to 0.1 short of dz).
///
/// # Errors
/// [`crate::Error::UnreachableTarget`] if the branch stays below `dz` up to
/// m₁ = e^−690 (where its force is beyond any the trace reaches).
fn upsilon_at_extension(n: u32, dz: f64, rest_extension: f64) -> Result<Elastica> {
    let at = |q: f64| -> Result<Elastica> {
        Elastica::upsilon(n, Modulus::from_complement((-q).exp())?)
    };
    if at(Q_REACH)?.extension() < dz {
        return Err(crate::Error::UnreachableTarget {
            target: Target::Extension(dz),
            rest_extension,
        });
    }
    let (mut lo, mut hi) = (0.0_f64, Q_REACH);
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if at(mid)?.extension() < dz {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    at(hi)
}

/// The elastica is solved with B = 1: forces scale with the spring's B
/// (extensions do not).
fn in_units_of_b(curve: ForceExtension, spring: &Spring) -> ForceExtension {
    let b = spring.stiffness().b();
    let mut scaled = ForceExtension::new(curve.label(), curve.parameter_name(), spring.scale());
    scaled.extend(curve.points().iter().map(|p| ForcePoint {
        force: p.force * b,
        ..*p
    }));
    scaled
}
