//! `--check`: how far the cusps are converged (docs/ACCURACY.md).

use std::error::Error;

use hockle::Stiffness;
use hockle::rod::{CuspSearch, Followed, NikolaiRod, Rod};

use super::compute::{A_OVER_B, INTERVALS, NU, THETA0_DEG, trace};

/// The convergence and consistency checks of docs/ACCURACY.md, on the
/// line at ν = 0.05 of every pop-out: (1) the cusp in θ0 at A/B = 10 from
/// the maximum-force fold and from the minimum-force fold (the same point
/// reached from both sides), on 16, 24, 48 and 96 intervals; (2) the cusp
/// in A/B at θ0 = 89.8° found by a fold curve in A/B (a second path),
/// against the cusp curve from (1) stopped at that A/B, whose θ0 must be
/// 89.8°; (3) the cusps of (1) found on 16 intervals with a tolerance of
/// [`CHECKED_TO`] rad (`CuspSearch::tolerance`: checked on halved meshes),
/// with the mesh they end on and how far they moved last.
pub(crate) fn check(coils: u32) -> Result<(), Box<dyn Error + Send + Sync>> {
    let rod = Rod::new(
        coils,
        THETA0_DEG.to_radians(),
        Stiffness::nikolai(A_OVER_B, NU)?,
    )?;
    let family = NikolaiRod::new(rod, NU)?;
    let down = 45_f64.to_radians();
    for n in [16, 24, 48, 96] {
        let search = CuspSearch::new().intervals(n);
        let pops = search.pop_outs(&family, 3.0)?;
        for (i, [max, min]) in pops.iter().enumerate() {
            let from_max = search.follow(&family, max, Rod::THETA0, down)?;
            let from_min = search.follow(&family, min, Rod::THETA0, down)?;
            let (Followed::Cusp(a), Followed::Cusp(b)) = (from_max, from_min) else {
                return Err(format!("N = {n}, pop-out {i}: no cusp from both folds").into());
            };
            let line = format!(
                "N = {n:3} pop-out {i}: cusp θ0 = {:.12} rad (from the max), {:.12} (from the min), f = {:.10}",
                a.parameter(),
                b.parameter(),
                a.fold_parameter()
            );
            if n != INTERVALS {
                println!("{line}");
                continue;
            }
            let Followed::Cusp(c) =
                search.follow(&family, max, NikolaiRod::LN_A_OVER_B, 0.01_f64.ln())?
            else {
                println!("{line}; no cusp in A/B at θ0 = {THETA0_DEG}°");
                continue;
            };
            let a_c = c.parameter();
            let traced = trace(&search, &family, a.extended(), NikolaiRod::LN_A_OVER_B, a_c)?;
            let end = traced.points.last().ok_or("empty")?;
            println!(
                "{line}; in A/B at θ0 = {THETA0_DEG}°: A/B_c = {:.10}, the cusp curve there has θ0 = {:.10}° (difference {:.2e}°)",
                a_c.exp(),
                end.theta0.to_degrees(),
                end.theta0.to_degrees() - THETA0_DEG
            );
        }
    }
    let search = CuspSearch::new().intervals(16).tolerance(CHECKED_TO);
    for (i, [max, _]) in search.pop_outs(&family, 3.0)?.iter().enumerate() {
        let Followed::Cusp(c) = search.follow(&family, max, Rod::THETA0, down)? else {
            return Err(format!("N = 16 checked, pop-out {i}: no cusp").into());
        };
        println!(
            "N =  16 checked to {CHECKED_TO:.0e} pop-out {i}: cusp θ0 = {:.12} rad on {} intervals, moved {:.1e} last",
            c.parameter(),
            c.solution().mesh().intervals(),
            c.mesh_change().unwrap_or(f64::NAN)
        );
    }
    Ok(())
}

/// The accuracy (rad) the `--check` run asks of its checked cusps.
const CHECKED_TO: f64 = 1e-9;
