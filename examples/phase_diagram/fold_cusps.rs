//! `--fold-cusps`: where the folds of a scene's pop-outs meet cusps in θ0,
//! both ways: the cusp lines a reading must cross between the scene and
//! θ0 = 45° or 90° (docs/ACCURACY.md, "n = 5").

use std::error::Error;

use hockle::Stiffness;
use hockle::bvp::Solution;
use hockle::rod::{CuspSearch, Followed, NikolaiRod, Rod};

// the mesh of the pull and of the fold curves: the diagram's lines' own
use super::compute::INTERVALS;

/// Where the folds are followed to: down to 45°, up to 1e-4° short of 90°.
const DOWN_DEG: f64 = 45.0;
/// See [`DOWN_DEG`].
const UP_DEG: f64 = 90.0 - 1e-4;

/// Pulls the scene (n coils, C by the Nikolai equality) to
/// F/((2πn)²B) = 3 on [`INTERVALS`] and prints, per pop-out, one line
/// `fold_cusps pop_out=<i> max=<F> min=<F> max_down=<…> max_up=<…>
/// min_down=<…> min_up=<…>`: each fold followed in θ0 to its first cusp
/// (`cusp:<θ0°>@<F>`, the cusp's θ0 and force), `reached` where it gets to
/// [`DOWN_DEG`] or [`UP_DEG`], `ended` otherwise. A fold that meets a cusp
/// going down was born there going up (the number of fold pairs rises by
/// one across it), one that meets a cusp going up dies there.
pub fn print(coils: u32, (t, a, nu): (f64, f64, f64)) -> Result<(), Box<dyn Error + Send + Sync>> {
    let rod = Rod::new(coils, t.to_radians(), Stiffness::nikolai(a, nu)?)?;
    let family = NikolaiRod::new(rod, nu)?;
    let search = CuspSearch::new().intervals(INTERVALS);
    let force = |s: &Solution| s.parameters()[NikolaiRod::FORCE_SCALED];
    for (i, [max, min]) in search.pop_outs(&family, 3.0)?.iter().enumerate() {
        let mut ways = Vec::new();
        for (name, fold) in [("max", max), ("min", min)] {
            for (way, to) in [("down", DOWN_DEG), ("up", UP_DEG)] {
                let end = match search.follow(&family, fold, Rod::THETA0, to.to_radians())? {
                    Followed::Cusp(c) => format!(
                        "cusp:{:.5}@{:.5}",
                        c.parameter().to_degrees(),
                        c.fold_parameter()
                    ),
                    Followed::Reached(_) => "reached".to_string(),
                    Followed::Ended(_) => "ended".to_string(),
                };
                ways.push(format!("{name}_{way}={end}"));
            }
        }
        println!(
            "fold_cusps pop_out={} max={:.5} min={:.5} {}",
            i + 1,
            force(max),
            force(min),
            ways.join(" ")
        );
    }
    Ok(())
}
