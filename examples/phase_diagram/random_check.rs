//! `--random K`: the diagram against direct pulls at K fresh random scenes
//! (docs/ACCURACY.md, "At random scenes").

use std::error::Error;

use hockle::rod::PhaseDiagram;

use super::pulls::{NEAR_DEG, STRETCH_TO, peak_forces, pulled, read_near_line, stretched_past};

/// The ranges of the random scenes: θ0 in degrees, log10 A/B, ν; about
/// the reference, where the regions are.
const THETA0_DEG: (f64, f64) = (84.0, 89.95);
/// See [`THETA0_DEG`].
const LOG10_A_OVER_B: (f64, f64) = (-0.3, 2.0);
/// See [`THETA0_DEG`].
const NU: (f64, f64) = (-0.3, 0.45);

/// Pulls `count` random scenes (xorshift from `seed`) to F/((2πn)²B) =
/// `force` and prints one line each, `random theta0=<deg> a_over_b=<x>
/// nu=<x> diagram=<count|unknown> pulled=<count> reached=<bool>
/// near_line=<bool> max_forces=<F;…>`, and a summary on standard error:
/// how many as the diagram counts, fewer (pop-outs above the force, or not
/// on the pull's path), near a line, and more (a contradiction, also
/// returned as an error). The scenes with fewer are stretched to Δz =
/// [`STRETCH_TO`] too (`stretch …` lines, [`stretched_past`]).
pub fn run(
    coils: u32,
    diagram: &PhaseDiagram,
    count: usize,
    seed: u64,
    force: f64,
) -> Result<(), Box<dyn Error + Send + Sync>> {
    let mut rnd = crate::common::uniform(seed);
    let mut draw = |(lo, hi): (f64, f64)| lo + (hi - lo) * rnd();
    let (mut equal, mut near, mut unknown) = (0, 0, 0);
    let mut fewer = Vec::new();
    let mut more = Vec::new();
    for _ in 0..count {
        let t = draw(THETA0_DEG);
        let a = 10_f64.powf(draw(LOG10_A_OVER_B));
        let nu = draw(NU);
        let (counted, near_line) = read_near_line(diagram, (t, a, nu));
        let response = pulled(coils, (t, a, nu), force)?;
        let peaks = peak_forces(&response);
        let shown = counted.map_or("unknown".to_string(), |c| c.to_string());
        println!(
            "random theta0={t:.3} a_over_b={a:.3} nu={nu:.3} diagram={shown} pulled={} reached={} near_line={near_line} max_forces={}",
            peaks.len(),
            response.reached_target(),
            peaks.join(";")
        );
        match counted {
            None => unknown += 1,
            Some(_) if near_line => near += 1,
            Some(c) if peaks.len() == c => equal += 1,
            Some(c) if peaks.len() < c => fewer.push(((t, a, nu), c, peaks.len())),
            Some(_) => more.push((t, a, nu)),
        }
    }
    let stretch = stretched_past(coils, &fewer, &mut more)?;
    eprintln!(
        "n = {coils}, {count} random scenes (seed {seed}) pulled to F/((2πn)²B) = {force}: {equal} \
         as the diagram counts, {} with fewer (stretched to Δz = {STRETCH_TO}: {} see the \
         diagram's count, {} fewer, {} stop short), {near} within {NEAR_DEG}° of a line, \
         {unknown} not resolved by the diagram, {} with more",
        fewer.len(),
        stretch.confirmed,
        stretch.fewer,
        stretch.short,
        more.len()
    );
    if more.is_empty() {
        Ok(())
    } else {
        Err(format!("pulls see more pop-outs than the diagram counts at {more:?}").into())
    }
}
