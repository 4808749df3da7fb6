//! `--force-map`: the maximum and minimum force of every reference pop-out
//! over a grid of (θ0, ν) at the reference A/B, by fold continuation along
//! the grid's lines.
//!
//! Each fold is followed from the reference spring in ν (both ways) at the
//! grid's θ0 nearest the reference's, then along each row in θ0 (both
//! ways) ([`CuspSearch::follow`]): one short leg per cell instead of a
//! carry from the reference. Where a leg meets a cusp the pop-out has left
//! its region on that line; the cells beyond it on the line are then
//! carried from the reference one by one ([`CuspSearch::carry`], another
//! path), and `-` is left where neither path reaches the fold: "none on
//! these paths" (a region need not be convex). Every fold reached is then
//! checked against its mesh (`checked.rs`: located again with every
//! interval halved until its force moves by at most 1e-6, at most three
//! times): the map's forces are the finest mesh's.

use std::error::Error;

use hockle::bvp::Solution;
use hockle::rod::{CuspSearch, Followed, NikolaiRod, Rod};

use super::checked::{CheckedForce, checked_force};

/// The example's error type.
type Fallible<T> = Result<T, Box<dyn Error + Send + Sync>>;

/// The grid: θ0 in degrees and ν; the reference's A/B.
pub const THETA0_DEG: [f64; 8] = [87.0, 87.4, 87.8, 88.2, 88.6, 89.0, 89.4, 89.8];
/// See [`THETA0_DEG`].
pub const NU: [f64; 6] = [-0.3, -0.2, -0.1, 0.0, 0.1, 0.2];

/// The fold `at` followed in `parameter` to `to`, if it gets there.
fn leg(
    search: &CuspSearch,
    family: &NikolaiRod,
    at: &Solution,
    parameter: usize,
    to: f64,
) -> Fallible<Option<Solution>> {
    Ok(match search.follow(family, at, parameter, to)? {
        Followed::Reached(fold) => Some(fold.solution().clone()),
        Followed::Cusp(_) | Followed::Ended(_) => None,
    })
}

/// The fold `start` followed in `parameter` through `targets` in turn (each
/// leg from the last one's end), `None` from the first that is not reached.
fn walk(
    search: &CuspSearch,
    family: &NikolaiRod,
    start: Option<Solution>,
    parameter: usize,
    targets: impl Iterator<Item = (usize, f64)>,
) -> Fallible<Vec<(usize, Option<Solution>)>> {
    let mut at = start;
    let mut out = Vec::new();
    for (index, to) in targets {
        at = match &at {
            Some(a) => leg(search, family, a, parameter, to)?,
            None => None,
        };
        out.push((index, at.clone()));
    }
    Ok(out)
}

/// `values` split about `from`: the indices and values at or beyond it
/// going up, and those below it going down, each in walking order.
fn sides(values: &[f64], from: f64) -> [Vec<(usize, f64)>; 2] {
    let up = values
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, v)| *v >= from)
        .collect();
    let down = values
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, v)| *v < from)
        .rev()
        .collect();
    [up, down]
}

/// One fold at every grid point on `search`'s mesh, `None` where it is
/// not reached: `map[j][i]` at (θ0 = [`THETA0_DEG`]`[i]`, ν = [`NU`]`[j]`).
/// From the fold at the reference's ν, walked in ν both ways at the grid's
/// θ0 nearest the reference's, then along each row in θ0 both ways.
fn map_fold(
    search: &CuspSearch,
    family: &NikolaiRod,
    fold: &Solution,
    a_over_b: f64,
) -> Fallible<Vec<Vec<Option<Solution>>>> {
    let p = fold.parameters();
    let (theta0, nu) = (p[Rod::THETA0].to_degrees(), p[NikolaiRod::NU]);
    let column = THETA0_DEG
        .iter()
        .copied()
        .min_by(|a, b| (a - theta0).abs().total_cmp(&(b - theta0).abs()))
        .expect("a grid");
    let start = match search.carry(family, fold, (column.to_radians(), a_over_b, nu))? {
        (_, Followed::Reached(at)) => Some(at.solution().clone()),
        _ => None,
    };
    let mut map = vec![vec![None; THETA0_DEG.len()]; NU.len()];
    for side in sides(&NU, nu) {
        for (j, row_start) in walk(
            search,
            family,
            start.clone(),
            NikolaiRod::NU,
            side.into_iter(),
        )? {
            for way in sides(&THETA0_DEG, column) {
                let way = way.into_iter().map(|(i, t)| (i, t.to_radians()));
                for (i, at) in walk(search, family, row_start.clone(), Rod::THETA0, way)? {
                    map[j][i] = at;
                }
            }
        }
    }
    // the cells the walks did not reach, carried from the reference one by
    // one (another path: a region need not be convex)
    for (j, &nu) in NU.iter().enumerate() {
        for (i, &t) in THETA0_DEG.iter().enumerate() {
            if map[j][i].is_none()
                && let (_, Followed::Reached(at)) =
                    search.carry(family, fold, (t.to_radians(), a_over_b, nu))?
            {
                map[j][i] = Some(at.solution().clone());
            }
        }
    }
    Ok(map)
}

/// [`map_fold`] with every fold reached checked against its mesh.
fn checked_map(
    search: &CuspSearch,
    family: &NikolaiRod,
    fold: &Solution,
    a_over_b: f64,
) -> Fallible<Vec<Vec<Option<CheckedForce>>>> {
    Ok(map_fold(search, family, fold, a_over_b)?
        .into_iter()
        .map(|row| {
            row.into_iter()
                .map(|cell| cell.map(|at| checked_force(search, family, &at)))
                .collect()
        })
        .collect())
}

/// Prints `force_map theta0=<deg> nu=<x> pop_out=<i> max=<F> min=<F>
/// change=<ΔF>` for every grid point and pop-out (`-` where the fold is not
/// reached, ΔF `-` where neither is; ΔF the larger of the two folds' moves in their last halving,
/// above 1e-6 where three halvings did not get there, `inf` where the fold
/// was not found on the halved mesh), and a Markdown table per pop-out on
/// standard error ("max (max − min)", marked `*` where a fold's force is
/// not resolved to 1e-6). The two folds of a pop-out are mapped in two
/// threads.
pub fn print(
    search: &CuspSearch,
    family: &NikolaiRod,
    pops: &[[Solution; 2]],
    a_over_b: f64,
) -> Fallible<()> {
    let show = |f: Option<CheckedForce>| f.map_or("-".to_string(), |v| format!("{:.6}", v.force));
    for (k, [max, min]) in pops.iter().enumerate() {
        let (up, down) = std::thread::scope(|s| {
            let up = s.spawn(|| checked_map(search, family, max, a_over_b));
            let down = checked_map(search, family, min, a_over_b);
            (up.join().expect("no panic"), down)
        });
        let (up, down) = (up?, down?);
        eprintln!(
            "\npop-out {}: maximum force (hysteresis: maximum − minimum)\n",
            k + 1
        );
        let head: Vec<String> = THETA0_DEG.iter().map(|t| format!("{t}°")).collect();
        eprintln!("| ν \\ θ0 | {} |", head.join(" | "));
        eprintln!("|---|{}", "---|".repeat(THETA0_DEG.len()));
        for (j, &nu) in NU.iter().enumerate() {
            let mut cells = Vec::new();
            for (i, &t) in THETA0_DEG.iter().enumerate() {
                let (a, b) = (up[j][i], down[j][i]);
                let change = [a, b]
                    .iter()
                    .flatten()
                    .map(|f| f.change)
                    .reduce(f64::max)
                    .map_or("-".to_string(), |c| format!("{c:.1e}"));
                println!(
                    "force_map theta0={t} nu={nu} pop_out={} max={} min={} change={change}",
                    k + 1,
                    show(a),
                    show(b)
                );
                let mark = if [a, b].iter().flatten().all(CheckedForce::resolved) {
                    ""
                } else {
                    "*"
                };
                cells.push(match (a, b) {
                    (Some(a), Some(b)) => {
                        format!("{:.3} ({:.3}){mark}", a.force, a.force - b.force)
                    }
                    (Some(a), None) => format!("{:.3} (?){mark}", a.force),
                    _ => "–".to_string(),
                });
            }
            eprintln!("| {nu} | {} |", cells.join(" | "));
        }
    }
    Ok(())
}
