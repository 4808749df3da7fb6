//! `--force-map` and `--force-map-a-over-b`: the maximum and minimum force
//! of every reference pop-out over a grid of (θ0, ν) at the reference A/B,
//! or of (θ0, A/B) at the reference ν ([`Axis`]), by fold continuation
//! along the grid's lines.
//!
//! Each fold is followed from the reference spring in ν or ln A/B (both
//! ways) at the grid's θ0 nearest the reference's, then along each row in
//! θ0 (both ways) ([`CuspSearch::follow`]): one short leg per cell instead of a
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

/// The grid: θ0 in degrees, and ν or A/B ([`Axis`]).
pub const THETA0_DEG: [f64; 8] = [87.0, 87.4, 87.8, 88.2, 88.6, 89.0, 89.4, 89.8];
/// See [`THETA0_DEG`]: ν at the reference's A/B.
pub const NU: [f64; 6] = [-0.3, -0.2, -0.1, 0.0, 0.1, 0.2];
/// See [`THETA0_DEG`]: A/B at the reference's ν.
pub const A_OVER_B: [f64; 7] = [2.0, 3.0, 5.0, 10.0, 20.0, 50.0, 100.0];

/// The second axis of a map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// ν over [`NU`], at the reference's A/B.
    Nu,
    /// A/B over [`A_OVER_B`], at the reference's ν (followed in ln A/B).
    AOverB,
}

impl Axis {
    /// The family's parameter the rows are walked in.
    fn parameter(self) -> usize {
        match self {
            Self::Nu => NikolaiRod::NU,
            Self::AOverB => NikolaiRod::LN_A_OVER_B,
        }
    }

    /// The grid's values, as printed.
    fn values(self) -> &'static [f64] {
        match self {
            Self::Nu => &NU,
            Self::AOverB => &A_OVER_B,
        }
    }

    /// A grid value as the family's parameter (ln A/B for A/B).
    fn coordinate(self, v: f64) -> f64 {
        match self {
            Self::Nu => v,
            Self::AOverB => v.ln(),
        }
    }

    /// The grid's values as the family's parameter.
    fn coordinates(self) -> Vec<f64> {
        self.values().iter().map(|&v| self.coordinate(v)).collect()
    }

    /// The scene (θ0 in radians, A/B, ν) at `theta0` and the grid value `v`,
    /// the other material parameter the reference's (`a_over_b`, `nu`).
    fn scene(self, theta0: f64, v: f64, (a_over_b, nu): (f64, f64)) -> (f64, f64, f64) {
        match self {
            Self::Nu => (theta0, a_over_b, v),
            Self::AOverB => (theta0, v, nu),
        }
    }

    /// The axis's name in the printed lines.
    fn name(self) -> &'static str {
        match self {
            Self::Nu => "nu",
            Self::AOverB => "a_over_b",
        }
    }

    /// The axis's label in the tables.
    fn label(self) -> &'static str {
        match self {
            Self::Nu => "ν",
            Self::AOverB => "A/B",
        }
    }
}

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
/// not reached: `map[j][i]` at (θ0 = [`THETA0_DEG`]`[i]`, the axis's
/// `j`-th value). From the fold at the reference's value of the axis,
/// walked along the axis both ways at the grid's θ0 nearest the
/// reference's, then along each row in θ0 both ways; the other material
/// parameter stays the reference's (`material`: its A/B and ν, `fold`'s).
fn map_fold(
    search: &CuspSearch,
    family: &NikolaiRod,
    fold: &Solution,
    axis: Axis,
    material: (f64, f64),
) -> Fallible<Vec<Vec<Option<Solution>>>> {
    let p = fold.parameters();
    let (theta0, along) = (p[Rod::THETA0].to_degrees(), p[axis.parameter()]);
    let column = THETA0_DEG
        .iter()
        .copied()
        .min_by(|a, b| (a - theta0).abs().total_cmp(&(b - theta0).abs()))
        .expect("a grid");
    let here = (column.to_radians(), material.0, material.1);
    let start = match search.carry(family, fold, here)? {
        (_, Followed::Reached(at)) => Some(at.solution().clone()),
        _ => None,
    };
    let values = axis.values();
    let mut map = vec![vec![None; THETA0_DEG.len()]; values.len()];
    for side in sides(&axis.coordinates(), along) {
        for (j, row_start) in walk(
            search,
            family,
            start.clone(),
            axis.parameter(),
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
    for (j, &v) in values.iter().enumerate() {
        for (i, &t) in THETA0_DEG.iter().enumerate() {
            if map[j][i].is_none()
                && let (_, Followed::Reached(at)) =
                    search.carry(family, fold, axis.scene(t.to_radians(), v, material))?
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
    axis: Axis,
    material: (f64, f64),
) -> Fallible<Vec<Vec<Option<CheckedForce>>>> {
    Ok(map_fold(search, family, fold, axis, material)?
        .into_iter()
        .map(|row| {
            row.into_iter()
                .map(|cell| cell.map(|at| checked_force(search, family, &at)))
                .collect()
        })
        .collect())
}

/// Prints `force_map theta0=<deg> nu=<x> pop_out=<i> max=<F> min=<F>
/// change=<ΔF>` (`a_over_b=<x>` in place of `nu=` on the A/B axis) for every
/// grid point and pop-out (`-` where the fold is not reached, ΔF `-` where
/// neither is; ΔF the larger of the two folds' moves in their last halving,
/// above 1e-6 where three halvings did not get there, `inf` where the fold
/// was not found on the halved mesh), and a Markdown table per pop-out on
/// standard error ("max (max − min)", marked `*` where a fold's force is
/// not resolved to 1e-6). The two folds of a pop-out are mapped in two
/// threads; the material parameter off the axis is the reference's
/// (`material`: its A/B and ν).
pub fn print(
    search: &CuspSearch,
    family: &NikolaiRod,
    pops: &[[Solution; 2]],
    axis: Axis,
    material: (f64, f64),
) -> Fallible<()> {
    let show = |f: Option<CheckedForce>| f.map_or("-".to_string(), |v| format!("{:.6}", v.force));
    for (k, [max, min]) in pops.iter().enumerate() {
        let (up, down) = std::thread::scope(|s| {
            let up = s.spawn(|| checked_map(search, family, max, axis, material));
            let down = checked_map(search, family, min, axis, material);
            (up.join().expect("no panic"), down)
        });
        let (up, down) = (up?, down?);
        eprintln!(
            "\npop-out {}: maximum force (hysteresis: maximum − minimum)\n",
            k + 1
        );
        let head: Vec<String> = THETA0_DEG.iter().map(|t| format!("{t}°")).collect();
        eprintln!("| {} \\ θ0 | {} |", axis.label(), head.join(" | "));
        eprintln!("|---|{}", "---|".repeat(THETA0_DEG.len()));
        for (j, &v) in axis.values().iter().enumerate() {
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
                    "force_map theta0={t} {}={v} pop_out={} max={} min={} change={change}",
                    axis.name(),
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
            eprintln!("| {v} | {} |", cells.join(" | "));
        }
    }
    Ok(())
}
