//! [`HelixModel`]: the spring stays an exact helix (the paper's Appendix).

use crate::continuation::Termination;
use crate::curve::{ForceExtension, ForcePoint};
use crate::error::{Error, Result};
use crate::helix::Helix;
use crate::load::Target;

use super::{Model, Response, Spring, check_samples, check_simple_target};

/// The spring as an exact helix with zero axial moment throughout
/// ([`crate::helix`]): instant, exact for θ0 far from 90° and for isotropic
/// or slinky rods, blind to pop-outs (its loop count is n everywhere, so its
/// force folds, where the helix force turns, are never pop-outs).
///
/// The curve is sampled uniformly in extension from the rest state
/// Δz = cos θ0 to the target; its last point is the target (a force
/// target exactly, the closed form meeting it to
/// [`HelixModel::FORCE_ACCURACY`]).
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
    /// The accuracy to which [`Model::pull_to`] meets a force target
    /// F/((2πn)²B) = f on the last point of its curve, relative to
    /// max(|f|, 1), or refuses it: the closed form is accurate to 8e-16
    /// (`tests/helix`) and the bisection ends on neighbouring doubles of θ,
    /// which move f by about ε |θ ∂f/∂θ| ≈ ε (1 + f) (f ≈ θ0/θ − 1 as
    /// θ → 0); 1e-13 leaves a margin of 100 over that. Below it are
    /// helix angles or physical forces (2πn)²B·f under the smallest normal
    /// double, whose grain is coarser.
    pub const FORCE_ACCURACY: f64 = 1e-13;

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
    /// [`crate::Error::UnreachableTarget`] for a bad target, or a force
    /// whose physical value f·(2πn)²B is beyond the largest double;
    /// [`crate::Error::OutsideModel`] for a push, if the spring's
    /// intrinsic strains are not those of its helix (the model assumes
    /// them), or if a force target cannot be met to
    /// [`HelixModel::FORCE_ACCURACY`] in double precision (its helix
    /// angle, or the physical force, below the smallest normal double
    /// 2.2e-308).
    fn pull_to(&self, spring: &Spring, target: Target) -> Result<Response> {
        let target = check_simple_target("helix", spring, target)?;
        let helix = Helix::new(spring.coils(), spring.helix_angle(), spring.stiffness())?;
        // errors of the closed forms name θ, which the user never gave
        let named = |e: Error| match e {
            Error::Overflow { quantity, .. } => Error::Overflow {
                quantity,
                name: "target",
                value: target.value(),
            },
            e => e,
        };
        let (theta_end, stop) = match target {
            Target::Force(f) => {
                let force = f * spring.force_scale();
                if !force.is_finite() {
                    return Err(Error::UnreachableTarget {
                        target,
                        rest_extension: spring.helix_angle().cos(),
                    });
                }
                (angle_at_force(&helix, force).map_err(named)?, force)
            }
            Target::Extension(dz) => (dz.acos(), dz),
        };
        let mut curve = ForceExtension::new(self.name(), "theta", spring.scale());
        for i in 0..self.samples {
            let t = i as f64 / (self.samples - 1) as f64;
            let theta = if i == 0 {
                spring.helix_angle()
            } else if i + 1 == self.samples {
                theta_end
            } else {
                angle_between(spring.helix_angle(), theta_end, t)
            };
            let mut force = helix.force(theta).map_err(named)?;
            if let (Target::Force(f), true) = (target, i + 1 == self.samples) {
                let met = (force / spring.force_scale() - f).abs()
                    <= Self::FORCE_ACCURACY * f.abs().max(1.0);
                if !met {
                    return Err(Error::OutsideModel {
                        model: "helix",
                        assumption: "a force target is met to 1e-13 max(f, 1) in double precision; at \
                                 this force and stiffness the helix angle θ or the physical force \
                                 (2πn)²B·F is below the smallest normal double (2.2e-308) and has \
                                 fewer than 53 bits: use a smaller force or a larger stiffness",
                    });
                }
                // the curve ends on the load asked, as the rod's does, so
                // that it is read off there
                force = stop;
            }
            let extension = match (target, i + 1 == self.samples) {
                // cos(acos Δz) to rounding: the curve ends on it
                (Target::Extension(dz), true) => dz,
                _ => helix.extension(theta)?,
            };
            curve.push(ForcePoint {
                extension,
                force,
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

/// The helix angle a fraction `t` of the way from θa to θb uniformly in
/// Δz = cos θ: in w = 1 − Δz = 2 sin²(θ/2), which keeps its bits where
/// cos θ rounds to 1 (θ < 1e-7), with the sines scaled by the larger so
/// that their squares do not underflow (θ < 1e-154); clamped to [θa, θb].
fn angle_between(theta_a: f64, theta_b: f64, t: f64) -> f64 {
    let (sa, sb) = ((0.5 * theta_a).sin(), (0.5 * theta_b).sin());
    let big = sa.max(sb);
    let theta = if big > 0.0 {
        let (a, b) = (sa / big, sb / big);
        2.0 * (big * ((1.0 - t) * a * a + t * b * b).sqrt())
            .min(1.0)
            .asin()
    } else {
        0.0
    };
    theta.clamp(theta_a.min(theta_b), theta_a.max(theta_b))
}

/// Scan resolution of [`angle_at_force`]: the helix force has at most a
/// few turning points between rest and Δz → 1, far apart in Δz.
const SCAN: usize = 4096;

/// The first helix angle θ, going from θ0 towards 0 (extension increasing),
/// at which the helix carries `force`: the first bracket on a scan uniform
/// in Δz (see [`angle_between`]), then bisection to neighbouring
/// doubles. F grows without bound as θ → 0, so a bracket exists for every
/// finite force; a force that overflows is above every target.
///
/// The helix force need not be monotone (at θ0 = 89.8°, A/B = 10 it peaks
/// at F/((2πn)²B) ≈ 0.66 near Δz ≈ 0.68): plain bisection on (0, θ0) could
/// return a later crossing.
fn angle_at_force(helix: &Helix, force: f64) -> Result<f64> {
    let above = |theta: f64| match helix.force(theta) {
        Ok(f) => Ok(f >= force),
        Err(Error::Overflow { .. }) => Ok(true),
        Err(e) => Err(e),
    };
    let mut hi = helix.theta0();
    let mut lo = 0.0_f64;
    for i in 1..SCAN {
        let theta = angle_between(helix.theta0(), 0.0, i as f64 / SCAN as f64);
        if theta <= 0.0 || theta >= hi {
            continue;
        }
        if above(theta)? {
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
        if above(mid)? {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(hi)
}
