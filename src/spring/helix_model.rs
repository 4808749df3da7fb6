//! [`HelixModel`]: the spring stays an exact helix (the paper's Appendix).

use crate::continuation::Termination;
use crate::curve::{ForceExtension, ForcePoint};
use crate::error::Result;
use crate::helix::Helix;
use crate::load::Target;

use super::{Model, Response, Spring, check_samples, check_simple_target};

/// The spring as an exact helix with zero axial moment throughout
/// ([`crate::helix`]): instant, exact for θ0 far from 90° and for isotropic
/// or slinky rods, blind to pop-outs (its loop count is n everywhere, so its
/// force folds, where the helix force turns, are never pop-outs).
///
/// The curve is sampled uniformly in extension from the rest state
/// Δz = cos θ0 to the target; its last point is the target to rounding.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct HelixModel {
    samples: usize,
}

impl Default for HelixModel {
    /// 200 samples.
    fn default() -> Self {
        Self { samples: 200 }
    }
}

impl HelixModel {
    /// A helix model sampling its curve at `samples` points.
    ///
    /// # Errors
    /// [`crate::Error::InvalidCount`] unless 2 ≤ `samples` ≤
    /// [`MAX_POINTS`](crate::error::MAX_POINTS).
    pub fn new(samples: usize) -> Result<Self> {
        Ok(Self {
            samples: check_samples(samples)?,
        })
    }
}

impl Model for HelixModel {
    fn name(&self) -> &str {
        "helix"
    }

    /// # Errors
    /// [`crate::Error::UnreachableTarget`] for a bad target;
    /// [`crate::Error::OutsideModel`] for a push, or if the spring's
    /// intrinsic strains are not those of its helix (the model assumes
    /// them).
    fn pull_to(&self, spring: &Spring, target: Target) -> Result<Response> {
        let target = check_simple_target("helix", spring, target)?;
        let helix = Helix::new(spring.coils(), spring.helix_angle(), spring.stiffness())?;
        let (theta_end, stop) = match target {
            Target::Force(f) => {
                let force = f * spring.force_scale();
                (angle_at_force(&helix, force)?, force)
            }
            Target::Extension(dz) => (dz.acos(), dz),
        };
        let (z0, z1) = (spring.helix_angle().cos(), theta_end.cos());
        let mut curve = ForceExtension::new(self.name(), "theta", spring.scale());
        for i in 0..self.samples {
            let t = i as f64 / (self.samples - 1) as f64;
            let theta = if i == 0 {
                spring.helix_angle()
            } else if i + 1 == self.samples {
                theta_end
            } else {
                (z0 + t * (z1 - z0)).acos()
            };
            curve.push(ForcePoint {
                extension: helix.extension(theta)?,
                force: helix.force(theta)?,
                parameter: theta,
            });
        }
        let loops = vec![Some(spring.coils()); curve.len()];
        Response::new(
            self.name(),
            target,
            curve,
            Termination::ParameterValue(stop),
        )
        .with_loops(loops)
    }
}

/// Scan resolution of [`angle_at_force`]: the helix force has at most a
/// few turning points between rest and Δz → 1, far apart in Δz.
const SCAN: usize = 4096;

/// The first helix angle θ, going from θ0 towards 0 (extension increasing),
/// at which the helix carries `force`: the first bracket on a scan uniform
/// in Δz, then bisection. F grows without bound as θ → 0, so a bracket
/// exists for every finite force.
///
/// The helix force need not be monotone (at θ0 = 89.8°, A/B = 10 it peaks
/// at F/((2πn)²B) ≈ 0.66 near Δz ≈ 0.68): plain bisection on (0, θ0) could
/// return a later crossing.
fn angle_at_force(helix: &Helix, force: f64) -> Result<f64> {
    let z0 = helix.theta0().cos();
    let mut hi = helix.theta0();
    let mut lo = 0.0_f64;
    for i in 1..=SCAN {
        let z = z0 + (1.0 - z0) * i as f64 / SCAN as f64;
        let theta = z.min(1.0).acos();
        if theta <= 0.0 || helix.force(theta)? >= force {
            lo = theta;
            break;
        }
        hi = theta;
    }
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if helix.force(mid)? >= force {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(hi)
}
