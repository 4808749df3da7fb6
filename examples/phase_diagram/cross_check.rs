//! `--cross-check`: the diagram's count against direct pulls on a coarse
//! grid over both of its planes (issue 13: "direct pulls on a coarse grid
//! of scenes must give the pop-out counts the diagram predicts").
//!
//! Every scene is pulled from rest to F/((2πn)²B) = [`FORCE`] with the
//! default adaptive rod. A pull that sees more pop-outs than the diagram
//! counts contradicts it; one that sees fewer does not (the diagram counts
//! pop-outs at any force, and at negative ν they come far above the
//! reference's forces), nor does one within 0.1° in θ0 of a cusp line
//! (where the count read 0.1° either side differs: the reading's own
//! error, docs/ACCURACY.md).

use std::error::Error;

use hockle::rod::PhaseDiagram;

/// The example's error type.
type Fallible<T> = Result<T, Box<dyn Error + Send + Sync>>;

/// The force the scenes are pulled to, F/((2πn)²B).
pub const FORCE: f64 = 3.0;
/// θ0 of both planes (degrees).
pub const THETA0_DEG: [f64; 6] = [86.0, 87.0, 88.0, 89.0, 89.5, 89.8];
/// A/B of the plane ν = 0.05.
pub const A_OVER_B: [f64; 5] = [1.0, 3.0, 10.0, 30.0, 100.0];
/// ν of the plane A/B = 10.
pub const NU: [f64; 6] = [-0.2, -0.1, 0.0, 0.1, 0.2, 0.3];

/// Prints one line per scene, `cross theta0=<deg> a_over_b=<x> nu=<x>
/// diagram=<count|unknown> pulled=<count> reached=<bool> near_line=<bool>`
/// (`reached`: whether the pull reached its force; one that stopped short
/// counts its pop-outs so far), and a summary on standard error; an error
/// if a pull contradicts the diagram.
pub fn run(coils: u32, diagram: &PhaseDiagram) -> Fallible<()> {
    let scenes = THETA0_DEG.iter().flat_map(|&t| {
        let plane_nu = A_OVER_B.iter().map(move |&a| (t, a, 0.05));
        let plane_ab = NU.iter().map(move |&nu| (t, 10.0, nu));
        plane_nu.chain(plane_ab)
    });
    let (mut equal, mut fewer, mut near, mut unknown) = (0, 0, 0, 0);
    let mut contradicted = Vec::new();
    for (t, a, nu) in scenes {
        let read = |deg: f64| diagram.pop_outs(deg.to_radians(), a, nu).ok();
        let count = read(t);
        let near_line = count != read(t - 0.1) || count != read((t + 0.1).min(89.999));
        let response = super::pulls::pulled(coils, (t, a, nu), FORCE)?;
        let pulled = response.pop_outs().len();
        let reached = response.reached_target();
        let shown = count.map_or("unknown".to_string(), |c| c.to_string());
        println!(
            "cross theta0={t} a_over_b={a} nu={nu} diagram={shown} pulled={pulled} reached={reached} near_line={near_line}"
        );
        match count {
            None => unknown += 1,
            Some(_) if near_line => near += 1,
            Some(c) if pulled == c => equal += 1,
            Some(c) if pulled < c => fewer += 1,
            Some(_) => contradicted.push((t, a, nu)),
        }
    }
    eprintln!(
        "n = {coils}: {equal} scenes as the diagram counts, {fewer} with fewer pop-outs below \
         F/((2πn)²B) = {FORCE}, {near} within 0.1° of a line, {unknown} not resolved by the \
         diagram, {} contradicting it",
        contradicted.len()
    );
    if contradicted.is_empty() {
        Ok(())
    } else {
        Err(format!("pulls see more pop-outs than the diagram counts at {contradicted:?}").into())
    }
}
