//! `--trade`: CPU time against true error for every model and every
//! tolerance, on the five springs of docs/ACCURACY.md's table and the
//! issue's 48-scene grid, each pulled from rest to F/((2πn)²B) = 1.
//!
//! Models: the linear response (the rod's tangent at rest, Castigliano's
//! closed form), the exact helix (200 samples), the flat elastica (its
//! default samples), and `Spring::answer` for the curve at 1e-2, 1e-4 and
//! 1e-6 (which model it chose is printed).
//! True error: both ways, max norm in (Δz, F/((2πn)²B)), against the rod
//! converged on a fixed mesh of 10 intervals per coil with m = 7 at
//! tolerance 1e-8 (`measure.rs`). Time: on-CPU seconds of the thread
//! (`/proc/self/schedstat`) per call, over calls repeated for at least
//! 0.2 s; the reference is not counted.
//!
//! `--on-demand`: the cost of what a curve does not compute: the paper's
//! spring and a slinky pulled to F/((2πn)²B) = 1 at tolerance 1e-4, the
//! curve alone, then with the loop count, the closest approach (contact)
//! and the sampled centreline of every point, the stability labels carried
//! along the curve, and the direct stability test of every point.

use std::fmt::Write as _;
use std::ops::ControlFlow;
use std::path::PathBuf;

use hockle::Stiffness;
use hockle::continuation::{Point, PointKind};
use hockle::curve::{ForceExtension, ForcePoint};
use hockle::rod::Equilibrium;
use hockle::spring::{
    Control, ElasticaModel, HelixModel, Model, Question, RodModel, Spring, Target, Value,
};

use crate::measure::{bare, both_ways, drawn, grid_scenes};

/// The load of every pull.
const MAX_FORCE: f64 = 1.0;

/// The answer's tolerances.
pub const TOLERANCES: [f64; 3] = [1e-2, 1e-4, 1e-6];

/// The least CPU time over which a model is timed (repeated calls).
const WINDOW: f64 = 0.2;

/// The series of the plot and the tables: three closed forms, then the
/// answer at each tolerance.
pub const SERIES: [&str; 6] = [
    "linear",
    "helix",
    "elastica",
    "answer 1e-2",
    "answer 1e-4",
    "answer 1e-6",
];

/// Okabe–Ito colours, one per series.
pub const COLOURS: [&str; 6] = [
    "#E69F00", "#009E73", "#CC79A7", "#56B4E9", "#0072B2", "#D55E00",
];

/// The main thread's time on a CPU, seconds (first field of
/// `/proc/self/schedstat`, nanoseconds).
fn on_cpu() -> f64 {
    std::fs::read_to_string("/proc/self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |ns| ns * 1e-9)
}

/// The CPU seconds per call of `f`, and its last value: `/proc/self/schedstat`
/// advances in scheduler ticks (4 ms at 250 Hz), so `f` is called until
/// the calls have taken at least [`WINDOW`] seconds (two calls at least),
/// which keeps the tick's share of the total below 4 %.
pub fn time_per_call<T>(mut f: impl FnMut() -> T) -> (T, f64) {
    let start = on_cpu();
    let mut calls = 0u32;
    loop {
        let value = f();
        calls += 1;
        let spent = on_cpu() - start;
        if calls >= 2 && spent >= WINDOW {
            return (value, spent / f64::from(calls));
        }
    }
}

/// One spring's row: per series, (CPU seconds, true error); and per
/// answer, (model name, reported estimate).
pub struct Row {
    name: String,
    /// Per series: (CPU seconds, true error).
    pub cells: [(f64, f64); 6],
    answers: [(&'static str, f64); 3],
}

fn spring(n: u32, theta0: f64, a_over_b: f64, nu: f64) -> Result<Spring, String> {
    let stiffness = Stiffness::nikolai(a_over_b, nu).map_err(|e| e.to_string())?;
    Spring::from_degrees(n, theta0, stiffness).map_err(|e| e.to_string())
}

fn measure_spring(name: String, s: &Spring) -> Result<Row, String> {
    let reference = RodModel::default()
        .tolerance(1e-8)
        .intervals(10 * s.coils() as usize)
        .points(7)
        .pull(s, MAX_FORCE)
        .map_err(|e| e.to_string())?;
    if !reference.reached_target() {
        return Err(format!("{name}: the reference stopped: {reference}"));
    }
    let r = drawn(&reference);
    let scale = s.force_scale();
    let (line, t_line) = time_per_call(|| {
        let k = s.spring_constant().expect("a helical spring");
        let mut line = ForceExtension::new("linear", "force", s.scale());
        for f in [0.0, MAX_FORCE * scale] {
            line.push(ForcePoint {
                extension: s.helix_angle().cos() + f / k,
                force: f,
                parameter: f,
            });
        }
        line
    });
    let pull = |m: &dyn Model| m.pull(s, MAX_FORCE).expect("a helical spring pulls");
    let (helix, t_helix) = time_per_call(|| pull(&HelixModel::default()));
    let (flat, t_flat) = time_per_call(|| pull(&ElasticaModel::default()));
    let mut cells = [(0.0, 0.0); 6];
    cells[0] = (t_line, both_ways(&bare(&line), &r));
    cells[1] = (t_helix, both_ways(&drawn(&helix), &r));
    cells[2] = (t_flat, both_ways(&drawn(&flat), &r));
    let mut answers = [("", 0.0); 3];
    for (i, tol) in TOLERANCES.iter().enumerate() {
        let (answer, seconds) = time_per_call(|| {
            s.answer(
                &Question::Curve {
                    max_force: MAX_FORCE,
                },
                *tol,
            )
        });
        let answer = answer.map_err(|e| e.to_string())?;
        let Value::Curve(curve) = answer.value() else {
            return Err("a curve question answered without a curve".into());
        };
        let truth = if answer.reached_target() {
            both_ways(&drawn(curve), &r)
        } else {
            f64::INFINITY
        };
        cells[3 + i] = (seconds, truth);
        answers[i] = (answer.choice().name(), answer.estimated_error());
    }
    Ok(Row {
        name,
        cells,
        answers,
    })
}

/// `--trade [--out DIR]`.
pub fn run(args: &[String]) -> Result<(), String> {
    let mut out = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(|| PathBuf::from("target"), PathBuf::from)
        .join("hockle");
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        match flag.as_str() {
            "--out" => out = it.next().ok_or("--out needs a directory")?.into(),
            other => return Err(crate::cli::unknown(other, crate::USAGE)),
        }
    }
    // (before the minutes of pulls, not after)
    std::fs::create_dir_all(&out).map_err(|e| format!("--out {}: {e}", out.display()))?;
    let five = [
        ("paper: 89.8°, A/B = 10", 89.8, 10.0),
        ("89°, A/B = 10", 89.0, 10.0),
        ("60°, A/B = 10", 60.0, 10.0),
        ("89.8°, A/B = 1", 89.8, 1.0),
        ("89.8°, A/B = 0.1 (slinky)", 89.8, 0.1),
    ];
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load average before: {}", load.trim());
    let mut named = Vec::new();
    for (name, theta0, a_over_b) in five {
        named.push(measure_spring(
            name.to_owned(),
            &spring(4, theta0, a_over_b, 0.05)?,
        )?);
    }
    let mut grid = Vec::new();
    for (n, theta0, a_over_b, nu) in grid_scenes() {
        let name = format!("{n}, {theta0}°, {a_over_b}, {nu}");
        grid.push(measure_spring(name, &spring(n, theta0, a_over_b, nu)?)?);
        eprint!(".");
    }
    eprintln!();
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load average after: {}", load.trim());
    print_named(&named);
    print_summary(&grid);
    std::fs::create_dir_all(&out).map_err(|e| e.to_string())?;
    let svg = out.join("models_trade.svg");
    let all: Vec<&Row> = named.iter().chain(&grid).collect();
    std::fs::write(&svg, crate::plot::plot(&all)).map_err(|e| e.to_string())?;
    println!("wrote {}", svg.display());
    Ok(())
}

fn print_named(rows: &[Row]) {
    println!();
    let mut head = String::from("| spring (n = 4, ν = 0.05) |");
    let mut rule = String::from("|---|");
    for s in SERIES {
        let _ = write!(head, " {s} |");
        rule.push_str("---|");
    }
    println!("{head}\n{rule}");
    for row in rows {
        let mut line = format!("| {} |", row.name);
        for (i, (t, e)) in row.cells.iter().enumerate() {
            let who = if i >= 3 {
                format!(" ({})", row.answers[i - 3].0)
            } else {
                String::new()
            };
            let _ = write!(line, " {} / {e:.1e}{who} |", seconds(*t));
        }
        println!("{line}");
    }
}

/// Seconds in a short human unit.
pub fn seconds(t: f64) -> String {
    if t < 1e-3 {
        format!("{:.0} µs", t * 1e6)
    } else if t < 1.0 {
        format!("{:.0} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}

pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn print_summary(rows: &[Row]) {
    println!(
        "\n| model (grid, {} scenes) | CPU time: median / max | true error: median / max | meets 1e-2 | meets 1e-4 | meets 1e-6 |",
        rows.len()
    );
    println!("|---|---|---|---|---|---|");
    for (i, s) in SERIES.iter().enumerate() {
        let times: Vec<f64> = rows.iter().map(|r| r.cells[i].0).collect();
        let errors: Vec<f64> = rows.iter().map(|r| r.cells[i].1).collect();
        let max = |v: &[f64]| v.iter().copied().fold(0.0, f64::max);
        let meets = |tol: f64| errors.iter().filter(|e| **e <= tol).count();
        println!(
            "| {s} | {} / {} | {:.1e} / {:.1e} | {} | {} | {} |",
            seconds(median(times.clone())),
            seconds(max(&times)),
            median(errors.clone()),
            max(&errors),
            meets(1e-2),
            meets(1e-4),
            meets(1e-6)
        );
    }
}

/// `--on-demand`: the curve alone against the curve with each extra
/// computed at every point (module docs).
pub fn on_demand() -> Result<(), String> {
    let springs = [
        ("paper (4, 89.8°, A/B = 10, ν = 0.05)", Spring::paper()),
        (
            "slinky (4, 89.8°, A/B = 0.1, ν = 0.05)",
            spring(4, 89.8, 0.1, 0.05)?,
        ),
    ];
    let tol = 1e-4;
    let target = Target::Force(MAX_FORCE);
    println!("| spring | what is computed | CPU time | points |");
    println!("|---|---|---|---|");
    for (name, s) in springs {
        let model = RodModel::default().tolerance(tol);
        let rod = RodModel::rod(&s).map_err(|e| e.to_string())?;
        let row = |what: &str, seconds: f64, points: usize| {
            println!(
                "| {name} | {what} | {} | {points} |",
                self::seconds(seconds)
            );
        };
        // the curve alone (what `Spring::answer` runs)
        let t = on_cpu();
        let curve = model.pull_to(&s, target).map_err(|e| e.to_string())?;
        row(
            "curve (folds, loop counts)",
            on_cpu() - t,
            curve.curve().len(),
        );
        // every extra in an observer of the same pull
        let extra = |what: &str, per_point: &dyn Fn(&Equilibrium)| -> Result<(), String> {
            let mut error = None;
            let t = on_cpu();
            let observer = |p: &Point| {
                if p.kind() != PointKind::Fold {
                    match Equilibrium::new(rod, p.solution().clone()) {
                        Ok(eq) => per_point(&eq),
                        Err(e) => {
                            error = Some(e.to_string());
                            return ControlFlow::Break(());
                        }
                    }
                }
                ControlFlow::Continue(())
            };
            let r = model
                .pull_observed(&s, target, observer)
                .map_err(|e| e.to_string())?;
            if let Some(e) = error {
                return Err(e);
            }
            row(what, on_cpu() - t, r.curve().len());
            Ok(())
        };
        extra("+ the equilibrium of every point (no use)", &|_| {})?;
        extra("+ closest approach (contact) of every point", &|eq| {
            let _ = eq.closest_approach();
        })?;
        extra("+ centreline of every point (400 samples)", &|eq| {
            let _ = eq.centreline_samples(400);
        })?;
        extra("+ energy of every point", &|eq| {
            let _ = eq.energy();
        })?;
        extra("+ direct stability test of every point", &|eq| {
            let _ = eq.stability(Control::Force);
        })?;
        let (labels, t) = time_per_call(|| curve.stability(Control::Force));
        row(
            "stability labels carried along the curve (after it)",
            t,
            labels.len(),
        );
        let (jumps, t) = time_per_call(|| curve.jumps(Control::Force));
        row("jumps under force control (after it)", t, jumps.len());
    }
    Ok(())
}

/// `--ends THETA0_DEG,A_OVER_B,NU`: the rod's excess extension over the
/// exact helix at the same load, times n, for n = 1 … 8 (docs/ACCURACY.md,
/// "why the helix is not certified"): constant in n where the excess is
/// two end layers, E(f)/n; the same for every n (not times n) in the
/// linear regime at small loads.
pub fn ends(scene: &str) -> Result<(), String> {
    let parts: Vec<f64> = scene
        .split(',')
        .map(|p| p.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("--ends {scene}: expected THETA0_DEG,A_OVER_B,NU"))?;
    let [theta0, a_over_b, nu] = parts[..] else {
        return Err(format!("--ends {scene}: expected THETA0_DEG,A_OVER_B,NU"));
    };
    let loads = [0.001, 0.01, 0.1, 0.3, 0.5, 0.7];
    let mut head = String::from("| n |");
    for f in loads {
        let _ = write!(head, " f = {f} |");
    }
    println!("n·(Δz_rod − Δz_helix) at F/((2πn)²B) = f, rod at tolerance 1e-8\n\n{head}");
    println!("|---|{}", "---|".repeat(loads.len()));
    for n in [1u32, 2, 3, 4, 6, 8] {
        let s = spring(n, theta0, a_over_b, nu)?;
        let scale = s.force_scale();
        let rod = RodModel::default()
            .tolerance(1e-8)
            .pull(&s, 0.8)
            .map_err(|e| e.to_string())?;
        let helix = HelixModel::new(4000)
            .map_err(|e| e.to_string())?
            .pull(&s, 0.8)
            .map_err(|e| e.to_string())?;
        let mut line = format!("| {n} |");
        for f in loads {
            let at = |r: &hockle::spring::Response| {
                r.curve()
                    .extension_at(f * scale)
                    .first()
                    .copied()
                    .unwrap_or(f64::NAN)
            };
            let _ = write!(line, " {:.4e} |", f64::from(n) * (at(&rod) - at(&helix)));
        }
        println!("{line}");
    }
    Ok(())
}
