//! The exact helix's error without the spring's rod: its two end layers,
//! measured on a short rod and scaled to the spring's coils.
//!
//! Pulled through its ends, a spring of n coils is the exact helix (loaded
//! on its axis) plus two end layers in which the ends move onto the force
//! line. Once the layers are apart, their excess extension at a load
//! f = F/((2πn)²B) does not depend on n:
//!
//! Δz_n(f) − Δz_helix(f) = E(f)/n,
//!
//! the same n·(Δz_n − Δz_helix) for n = 2 … 8 to four or five digits from
//! f ≈ 0.1 on (docs/ACCURACY.md, "Why the helix is not certified"). A rod
//! of n_s = [`SHORT_COILS`] coils with the spring's θ0, A, B and C, pulled
//! to the same f, measures E(f)/n_s, so the spring's curve is predicted as
//!
//! Δz_n(f) ≈ Δz_helix(f) + (n_s/n)(Δz_{n_s}(f) − Δz_helix(f)),
//!
//! and the helix's error is estimated as [`SAFETY`] times the distance,
//! both ways, between the helix's curve and that prediction, plus the
//! short rod's own error scaled by n_s/n and the chords of the helix's
//! polyline. The short rod costs about n_s/n of the spring's.
//!
//! Where the layers still overlap (small f, where the excess is the linear
//! one and the same for every n), the prediction is low by up to n/n_s,
//! but there the two curves are within about f of each other in the max
//! norm.
//!
//! Near a pop-out the layers do not scale: a spring of n coils softens
//! towards its first pop-out, which a short rod has at another force (at
//! 0.24 to 1.05 times the 2-coil rod's first fold over 32 low-pitch scenes
//! with n 2–12, and at 0.62 to 1.4 times the helix's force maximum where it
//! has one; docs/ACCURACY.md). So the helix is not certified where either
//! of those lies within [`POP_OUT_MARGIN`] times the load (the short rod is
//! pulled that far), nor where the prediction is not single-valued.

use crate::error::{Error, Result};
use crate::helix::Helix;
use crate::load::Target;

use super::answer::SetAside;
use super::plane_distance::{PlanePoint, both_ways_rising};
use super::{HelixModel, Model, Response, RodModel, Spring};

/// Coils of the short rod that measures the end layers: two, the fewest
/// whose layers are apart from f ≈ 0.1 on (one coil's are 5 % off at
/// f = 0.1 and 30 % at f = 0.01, docs/ACCURACY.md).
pub(super) const SHORT_COILS: u32 = 2;

/// The estimate is this times the distance between the helix and the
/// prediction. Over the 137 of 150 scenes (the grid of 48, 80
/// random ones with n 2–8, θ0 60–89.9°, A/B 0.1–20, ν 0–0.4, and 22
/// hostile and long ones: θ0 down to 20°, A/B 0.02–100, ν −0.8–0.49, n up
/// to 30) where neither the helix's force nor the short rod folds below
/// F/((2πn)²B) = 1, the helix's
/// true error against the converged rod was 0.68 to 1.0008 times that
/// distance (docs/ACCURACY.md, "The helix certified by its end layers");
/// 1.05 leaves sixty times the largest excess seen for scenes not seen.
pub(super) const SAFETY: f64 = 1.05;

/// The least n·(true error of the helix)/sin²θ0 measured on the scenes of
/// [`SAFETY`] was 0.022 (at A/B = 0.02; the end layers' lever is the coil
/// radius R0 = sin θ0/(2πn)): where n·tolerance/[`SAFETY`] is below a
/// tenth less than this, times sin²θ0, the check cannot certify the helix
/// and is not run. A saving only: a check run anyway would set the helix
/// aside.
const LEAST_SCALED_ERROR: f64 = 0.02;

/// A spring's first pop-out may come this many times below the 2-coil
/// rod's first fold or the helix's force maximum (module docs): where
/// either is below this times the load, the helix is not certified.
/// Measured (`examples/models --pop-out-margin`): the first pop-out of a
/// spring without a helix force maximum was at least 0.67 times the 2-coil
/// rod's first fold, and of one with a maximum at least 0.62 times that
/// maximum (so 2 leaves a margin of a quarter over both); where the helix
/// has a maximum, its 2-coil rod folded at up to 4 times the spring's first
/// pop-out, so the maximum guards those.
const POP_OUT_MARGIN: f64 = 2.0;

/// Samples of the helix's answer; the check also pulls twice as many to
/// measure their chords.
const HELIX_SAMPLES: usize = 200;

/// The short rod runs at the tolerance over this, so that its own error,
/// scaled by n_s/n and doubled (as the rod's in `Spring::answer`), takes at
/// most a fifteenth of the tolerance.
const SHORT_ROD_DIVISOR: f64 = 30.0;

/// What the check says of the helix.
pub(super) enum Verdict {
    /// The helix meets the tolerance: its curve, carrying its estimated
    /// error.
    Certified(Box<Response>),
    /// It does not, or cannot be shown to.
    SetAside(SetAside),
}

/// Whether the check can certify the helix for `spring` at `tolerance`
/// ([`LEAST_SCALED_ERROR`]), with a rod shorter than the spring's.
pub(super) fn worth_checking(spring: &Spring, tolerance: f64) -> bool {
    let lever = spring.helix_angle().sin().powi(2);
    spring.coils() > SHORT_COILS
        && f64::from(spring.coils()) * tolerance / SAFETY >= LEAST_SCALED_ERROR * lever
}

/// The helix's answer for a pull of `spring` to `target` (a pull, checked
/// by the caller) and whether it meets `tolerance` (module docs).
///
/// # Errors
/// Those of the helix's and the short rod's pulls.
pub(super) fn check(spring: &Spring, target: Target, tolerance: f64) -> Result<Verdict> {
    let scale = spring.force_scale();
    let plane = |r: &Response| -> Vec<PlanePoint> {
        r.curve()
            .points()
            .iter()
            .map(|p| [p.extension, p.force / scale])
            .collect()
    };
    let answer = HelixModel::new(HELIX_SAMPLES)?.pull_to(spring, target)?;
    // the same angles and one between each pair: its polyline is about
    // four times closer to the helix than the answer's
    let fine = HelixModel::new(2 * HELIX_SAMPLES - 1)?.pull_to(spring, target)?;
    let (coarse, fine) = (plane(&answer), plane(&fine));
    if !rises(&fine) {
        // (a force maximum of the helix below the load, caught below as
        // well: this one also catches a force that turns at the rest state)
        return Ok(Verdict::SetAside(SetAside::NoBound));
    }
    let chords = 2.0 * both_ways_rising(&coarse, &fine);

    let top = fine.last().map_or(f64::NAN, |p| p[1]);
    let reach = POP_OUT_MARGIN * top;
    if let Some(peak) = helix_force_maximum(spring)?
        && peak <= reach
    {
        return Ok(Verdict::SetAside(SetAside::NearAPopOut { force: peak }));
    }
    let short_spring = Spring::new(SHORT_COILS, spring.helix_angle(), spring.stiffness())?;
    let short_tolerance = (tolerance / SHORT_ROD_DIVISOR).max(super::choice::MIN_ROD_TOLERANCE);
    let short = RodModel::default()
        .tolerance(short_tolerance)
        .pull_to(&short_spring, Target::Force(reach))?;
    let short_scale = short_spring.force_scale();
    if let Some(fold) = short.folds().first() {
        return Ok(Verdict::SetAside(SetAside::NearAPopOut {
            force: fold.point.force / short_scale,
        }));
    }
    let short_error = short.estimated_error().unwrap_or(f64::INFINITY);
    if !short.reached_target() || !short_error.is_finite() {
        return Ok(Verdict::SetAside(SetAside::NoBound));
    }
    let weight = f64::from(SHORT_COILS) / f64::from(spring.coils());
    let Some(predicted) = predict(&fine, &short, short_scale, weight, target) else {
        return Ok(Verdict::SetAside(SetAside::NoBound));
    };
    let estimate = SAFETY * both_ways_rising(&fine, &predicted)
        + weight * super::choice::ROD_ESTIMATE_SAFETY * short_error
        + chords;
    Ok(if estimate <= tolerance {
        Verdict::Certified(Box::new(answer.with_estimated_error(estimate)))
    } else {
        Verdict::SetAside(SetAside::EndLayers { estimate })
    })
}

/// The spring's curve predicted from the helix's points `fine` and the short
/// rod's curve (`short`, forces in units of `short_scale`) by
/// Δz_helix + `weight`·(Δz_short − Δz_helix) at the helix's forces, ended
/// on the extension of an extension `target`; `None` where the short rod
/// has other than one extension at a force, or (under extension control)
/// the prediction, stiffer than the helix, stops short of the target.
fn predict(
    fine: &[PlanePoint],
    short: &Response,
    short_scale: f64,
    weight: f64,
    target: Target,
) -> Option<Vec<PlanePoint>> {
    let mut predicted: Vec<PlanePoint> = Vec::with_capacity(fine.len());
    for &[dz, f] in fine {
        let [dz_short] = short.curve().extension_at(f * short_scale)[..] else {
            return None;
        };
        let point = [dz + weight * (dz_short - dz), f];
        if let (Target::Extension(end), Some(last)) = (target, predicted.last().copied())
            && point[0] >= end
        {
            // the prediction reaches the extension asked below the helix's
            // force there: it ends on it
            let t = (end - last[0]) / (point[0] - last[0]);
            predicted.push([end, last[1] + t * (point[1] - last[1])]);
            return Some(predicted);
        }
        predicted.push(point);
    }
    match target {
        Target::Extension(_) => None,
        Target::Force(_) => Some(predicted),
    }
}

/// Samples of the scan for the helix's force maximum, uniform in Δz from
/// rest to 1 (the helix's force has at most a few turning points, far
/// apart in Δz).
const MAXIMUM_SCAN: usize = 2048;

/// The first maximum of the exact helix's force F/((2πn)²B) from rest
/// towards Δz = 1, if it has one (found on a scan uniform in Δz; the force
/// grows without bound as Δz → 1, so a scan that overflows has passed
/// every maximum).
fn helix_force_maximum(spring: &Spring) -> Result<Option<f64>> {
    let helix = Helix::new(spring.coils(), spring.helix_angle(), spring.stiffness())?;
    let rest = spring.helix_angle().cos();
    let mut previous = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for i in 1..MAXIMUM_SCAN {
        let dz = rest + (1.0 - rest) * i as f64 / MAXIMUM_SCAN as f64;
        let force = match helix.force(dz.acos()) {
            Ok(f) => f,
            Err(Error::Overflow { .. }) => return Ok(None),
            Err(e) => return Err(e),
        };
        if previous.1 > previous.0 && previous.1 >= force {
            return Ok(Some(previous.1 / spring.force_scale()));
        }
        previous = (previous.1, force);
    }
    Ok(None)
}

/// Whether the forces rise strictly along `line`.
fn rises(line: &[PlanePoint]) -> bool {
    line.windows(2).all(|w| w[1][1] > w[0][1])
}
