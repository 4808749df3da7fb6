//! What a tolerance buys: the paper's spring (n = 4, θ0 = 89.8°, A/B = 10,
//! ν = 0.05) pulled from rest to F/((2πn)²B) = 3 at tol = 1e-2 … 1e-9 and
//! on a few fixed meshes, each run timed and its folds compared with a
//! converged reference computed here (issue 11, "Measured, not asserted").
//!
//! ```text
//! cargo run --release --example tolerance_trade [-- --out DIR] [--repeat R] [--memory]
//! cargo run --release --example tolerance_trade -- --one TOL
//! cargo run --release --example tolerance_trade -- --folds SETTING [--repeat R]
//! cargo run --release --example tolerance_trade -- --symmetric   # the runs on the rod's half
//! ```
//!
//! Per run: user CPU seconds of the run alone (the process's `utime` from
//! `/proc/self/stat` before and after, in clock ticks of 1/100 s), on-CPU
//! seconds of the thread (`/proc/self/schedstat`, nanoseconds, user + system),
//! wall seconds, each the median of R repetitions (default 3); steps,
//! rejected steps, m, mesh intervals at the end and at most, the run's
//! estimated fold and curve errors (`PullRun::estimate`) and the true fold
//! error: max over the six folds of max(|ΔΔz|, |ΔF/((2πn)²B)|) against the
//! reference (48 fixed intervals, m = 7, tolerance 1e-9), itself checked
//! against a second one (64 intervals, m = 7, tolerance 1e-10); and the true
//! curve error (largest distance from the run's interpolant, at its points
//! and segment midpoints, to the reference's).
//!
//! Writes `tolerance_trade.csv` and `tolerance_pareto.svg` (CPU time against
//! true fold error, log-log) into DIR (default `$CARGO_TARGET_DIR/hockle`,
//! else `target/hockle` under the crate). `--memory` makes one default
//! pull and prints the peak resident memory (`VmHWM` of `/proc/self/status`)
//! instead. `--one TOL` makes one pull at TOL and prints it (the run to
//! count instructions of, under `valgrind --tool=cachegrind`; docs/PERFORMANCE.md).
//! `--folds SETTING` (`TOL`, or `N,M,TOL` for a fixed mesh) makes R pulls
//! and prints, machine-readably, the median on-CPU seconds (`cpu S`), the
//! steps, and every fold (`fold KIND F/((2πn)²B) Δz`, 13 digits): the hockle
//! side of `benches/auto07p/side_by_side.py`, which times AUTO-07p beside it.
//! Other processes share the machine: the load average
//! (`/proc/loadavg`) is printed before and after.

use std::error::Error;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use hockle::rod::{Pull, PullRun, Rod};
use hockle::{Stiffness, Target};

#[path = "../tests/common/mod.rs"]
mod common;

/// How a run is set: by a tolerance, or by a fixed mesh (N, m) with the
/// tolerance that sets its steps.
#[derive(Clone, Copy)]
enum Setting {
    Tolerance(f64),
    Fixed { n: usize, m: usize, tol: f64 },
}

impl Setting {
    fn pull(self, rod: Rod) -> Pull {
        let p = Pull::new(rod, Target::Force(3.0));
        match self {
            Setting::Tolerance(tol) => p.tolerance(tol),
            Setting::Fixed { n, m, tol } => p.tolerance(tol).intervals(n).points(m),
        }
    }

    fn label(self) -> String {
        match self {
            Setting::Tolerance(tol) => format!("tol {tol:.0e}"),
            Setting::Fixed { n, m, tol } => format!("N={n} m={m} (tol {tol:.0e})"),
        }
    }
}

/// The tolerances of the sweep: the decades, and 5e-6 and 3e-7 where the
/// decade's run is the first to pass an accuracy tier of issue 11 (1e-6,
/// 1e-8) with a large margin (the fold estimate is about twice the true
/// fold error, so tol = 1e-5 misses 1e-6 and tol 1e-7 reaches 3e-9).
const TOLERANCES: [f64; 10] = [1e-2, 1e-3, 1e-4, 1e-5, 5e-6, 1e-6, 3e-7, 1e-7, 1e-8, 1e-9];

/// Fixed meshes: the issue's hand-tuned settings and the former default,
/// with the tolerance (steps, Newton, location) of their accuracy tier.
const FIXED: [(usize, usize, f64); 4] =
    [(12, 5, 1e-3), (16, 7, 1e-6), (48, 4, 1e-6), (48, 5, 1e-8)];

/// The reference and its check: fixed uniform meshes, m = 7.
const REFERENCE: (usize, usize, f64) = (48, 7, 1e-9);
const CHECK: (usize, usize, f64) = (64, 7, 1e-10);

fn paper_rod() -> Result<Rod, hockle::Error> {
    Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)
}

/// The process's user CPU time, seconds (`utime`, field 14 of
/// `/proc/self/stat`, in ticks of 1/100 s: `getconf CLK_TCK` is 100 on
/// Linux x86-64).
fn user_cpu() -> f64 {
    let stat = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    // fields after the command name "(…)": state is field 3, utime field 14
    let rest = stat.rsplit_once(')').map_or("", |r| r.1);
    rest.split_whitespace()
        .nth(11)
        .and_then(|v| v.parse::<f64>().ok())
        .map_or(f64::NAN, |t| t / 100.0)
}

/// The main thread's time on a CPU, seconds (first field of
/// `/proc/self/schedstat`, nanoseconds; user and system).
fn on_cpu() -> f64 {
    std::fs::read_to_string("/proc/self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |ns| ns * 1e-9)
}

fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .map(|s| s.trim().to_string())
        .unwrap_or_else(|_| "unavailable".to_string())
}

fn peak_memory() -> String {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM"))
                .map(|l| l.trim().to_string())
        })
        .unwrap_or_else(|| "VmHWM unavailable".to_string())
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// One setting, timed `repeat` times: the last run and the medians of
/// (user CPU, on-CPU, wall) seconds.
fn timed(setting: Setting, rod: Rod, repeat: usize) -> Result<(PullRun, [f64; 3]), Box<dyn Error>> {
    let pull = setting.pull(rod);
    let (mut user, mut cpu, mut wall) = (Vec::new(), Vec::new(), Vec::new());
    let mut last = None;
    for _ in 0..repeat {
        let (u0, c0, w0) = (user_cpu(), on_cpu(), Instant::now());
        let run = pull.run(())?;
        wall.push(w0.elapsed().as_secs_f64());
        cpu.push(on_cpu() - c0);
        user.push(user_cpu() - u0);
        last = Some(run);
    }
    let run = last.ok_or("no repetition")?;
    Ok((run, [median(user), median(cpu), median(wall)]))
}

/// The largest distance between the folds of two runs in
/// (Δz, F/((2πn)²B)); NaN when they do not have the same folds.
fn fold_error(run: &PullRun, reference: &PullRun) -> f64 {
    if run.folds().len() != reference.folds().len() {
        return f64::NAN;
    }
    let scale = run.curve().scale();
    let mut worst: f64 = 0.0;
    for (a, b) in run.folds().iter().zip(reference.folds()) {
        if a.kind != b.kind {
            return f64::NAN;
        }
        let d = (a.point.extension - b.point.extension)
            .abs()
            .max((a.point.force_scaled(scale) - b.point.force_scaled(scale)).abs());
        worst = worst.max(d);
    }
    worst
}

/// The largest distance from the run's interpolant (points and segment
/// midpoints) to the reference's (`tests/common`'s measure, shared with
/// `tests/rod/tolerance.rs`).
fn curve_error(run: &PullRun, reference: &PullRun) -> f64 {
    common::curve_distance(run.curve(), reference.curve())
}

/// `TOL` or `N,M,TOL`.
fn parse_setting(text: &str) -> Result<Setting, Box<dyn Error>> {
    let parts: Vec<&str> = text.split(',').collect();
    match parts.as_slice() {
        [tol] => Ok(Setting::Tolerance(tol.parse()?)),
        [n, m, tol] => Ok(Setting::Fixed {
            n: n.parse()?,
            m: m.parse()?,
            tol: tol.parse()?,
        }),
        _ => Err(format!("a setting is TOL or N,M,TOL, not {text}").into()),
    }
}

/// `--folds`: the median on-CPU time of `repeat` pulls, their steps and the
/// last pull's folds, one per line.
fn print_folds(setting: Setting, rod: Rod, repeat: usize) -> Result<(), Box<dyn Error>> {
    let (run, [_, cpu, _]) = timed(setting, rod, repeat)?;
    if !run.reached_target() {
        return Err(format!("{} did not reach the target:\n{run}", setting.label()).into());
    }
    println!("setting {}", setting.label());
    println!("cpu {cpu:.4}");
    println!("steps {}", run.steps());
    let scale = run.curve().scale();
    for fold in run.folds() {
        println!(
            "fold {:?} {:.13} {:.13}",
            fold.kind,
            fold.point.force_scaled(scale),
            fold.point.extension
        );
    }
    Ok(())
}

/// One measured row.
struct Row {
    setting: Setting,
    user: f64,
    cpu: f64,
    wall: f64,
    steps: usize,
    rejected: usize,
    m: usize,
    intervals: usize,
    max_intervals: usize,
    folds: usize,
    est_fold: f64,
    est_curve: f64,
    est_mesh: f64,
    est_interpolation: f64,
    true_fold: f64,
    true_curve: f64,
}

const USAGE: &str = "\
usage: cargo run --release --example tolerance_trade -- [OPTIONS]
  --out DIR        where tolerance_trade.csv and tolerance_pareto.svg go (default target/hockle)
  --repeat R       time each run as the median of R repetitions (default 3)
  --memory         one default pull and its peak resident memory instead
  --one TOL        one pull at tolerance TOL, printed, instead
  --folds SETTING  R pulls at SETTING (TOL, or N,M,TOL for a fixed mesh) and their folds,
                   machine-readably, instead
  --symmetric      the runs solve the rod's half (Rod::symmetric); the references stay whole
  --help           this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("tolerance_trade", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut out = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(
            || Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
            PathBuf::from,
        )
        .join("hockle");
    let mut repeat = 3;
    let mut memory = false;
    let mut one = None;
    let mut folds = None;
    let mut symmetric = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            "--repeat" => repeat = args.next().ok_or("--repeat needs R")?.parse()?,
            "--memory" => memory = true,
            "--symmetric" => symmetric = true,
            "--one" => one = Some(args.next().ok_or("--one needs TOL")?.parse::<f64>()?),
            "--folds" => {
                folds = Some(parse_setting(
                    &args.next().ok_or("--folds needs TOL or N,M,TOL")?,
                )?)
            }
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    if repeat == 0 {
        return Err("--repeat needs R ≥ 1".into());
    }
    // the references are the whole rod's; with --symmetric the timed runs
    // solve its half
    let rod = paper_rod()?;
    let pulled = if symmetric { rod.symmetric()? } else { rod };
    if let Some(setting) = folds {
        return print_folds(setting, pulled, repeat);
    }
    if let Some(tol) = one {
        let run = Pull::new(pulled, Target::Force(3.0))
            .tolerance(tol)
            .run(())?;
        println!("{run}");
        return Ok(());
    }
    if memory {
        let before = peak_memory();
        let run = Pull::new(pulled, Target::Force(3.0)).run(())?;
        println!("{run}");
        println!(
            "peak resident memory before the pull: {before}; after one default pull: {}",
            peak_memory()
        );
        return Ok(());
    }
    std::fs::create_dir_all(&out)?;
    println!(
        "load average before (1, 5, 15 min; runnable/total; last pid): {}",
        load_average()
    );

    let reference_of = |(n, m, tol): (usize, usize, f64)| {
        Pull::new(rod, Target::Force(3.0))
            .tolerance(tol)
            .intervals(n)
            .points(m)
            .run(())
    };
    let clock = Instant::now();
    let reference = reference_of(REFERENCE)?;
    let t_ref = clock.elapsed().as_secs_f64();
    let check = reference_of(CHECK)?;
    let t_check = clock.elapsed().as_secs_f64() - t_ref;
    if !(reference.reached_target() && check.reached_target()) {
        return Err(format!("a reference did not reach the target:\n{reference}{check}").into());
    }
    let agreement = fold_error(&reference, &check);
    println!(
        "reference N = {}, m = {}, tol {:.0e}: {} folds, {} steps, {t_ref:.1} s wall",
        REFERENCE.0,
        REFERENCE.1,
        REFERENCE.2,
        reference.folds().len(),
        reference.steps()
    );
    println!(
        "check     N = {}, m = {}, tol {:.0e}: {} steps, {t_check:.1} s wall; folds agree to {agreement:.1e}, curves to {:.1e}",
        CHECK.0,
        CHECK.1,
        CHECK.2,
        check.steps(),
        curve_error(&check, &reference)
    );
    print!("{reference}");
    if symmetric {
        println!(
            "the runs below solve the rod's half (Rod::symmetric; N counts the half's intervals)"
        );
    }

    let settings: Vec<Setting> = TOLERANCES
        .iter()
        .map(|&t| Setting::Tolerance(t))
        .chain(
            FIXED
                .iter()
                .map(|&(n, m, tol)| Setting::Fixed { n, m, tol }),
        )
        .collect();
    println!(
        "\n{:<24} {:>7} {:>7} {:>7} {:>6} {:>4} {:>2} {:>4} {:>4} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "run (median of repeats)",
        "user s",
        "cpu s",
        "wall s",
        "steps",
        "rej",
        "m",
        "N",
        "maxN",
        "est fold",
        "true fold",
        "est/true",
        "est curve",
        "true crv"
    );
    let mut rows = Vec::new();
    for &setting in &settings {
        let (run, [user, cpu, wall]) = timed(setting, pulled, repeat)?;
        let e = run.estimate();
        let row = Row {
            setting,
            user,
            cpu,
            wall,
            steps: run.steps(),
            rejected: run.rejected(),
            m: run.points_per_interval(),
            intervals: e.intervals,
            max_intervals: e.max_intervals,
            folds: run.folds().len(),
            est_fold: e.located,
            est_curve: e.curve(),
            est_mesh: e.mesh,
            est_interpolation: e.interpolation,
            true_fold: fold_error(&run, &reference),
            true_curve: curve_error(&run, &reference),
        };
        println!(
            "{:<24} {:>7.3} {:>7.3} {:>7.3} {:>6} {:>4} {:>2} {:>4} {:>4} {:>9.1e} {:>9.1e} {:>9.2} {:>9.1e} {:>9.1e}{}",
            setting.label(),
            row.user,
            row.cpu,
            row.wall,
            row.steps,
            row.rejected,
            row.m,
            row.intervals,
            row.max_intervals,
            row.est_fold,
            row.true_fold,
            row.est_fold / row.true_fold,
            row.est_curve,
            row.true_curve,
            if run.reached_target() && row.folds == 6 {
                String::new()
            } else {
                format!("  ({} folds; {})", row.folds, run.termination())
            }
        );
        rows.push(row);
    }
    println!("load average after: {}", load_average());
    println!("peak resident memory of the whole sweep: {}", peak_memory());

    let csv = out.join("tolerance_trade.csv");
    let svg = out.join("tolerance_pareto.svg");
    write_csv(&rows, &csv)?;
    std::fs::write(&svg, plot(&rows))?;
    println!("wrote {} and {}", csv.display(), svg.display());
    Ok(())
}

fn write_csv(rows: &[Row], path: &Path) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(
        f,
        "kind,tolerance,intervals_fixed,m,user_s,cpu_s,wall_s,steps,rejected,intervals_end,intervals_max,folds,estimated_fold_error,true_fold_error,estimated_curve_error,true_curve_error,estimated_mesh_error,estimated_interpolation_error"
    )?;
    for r in rows {
        let (kind, tol, n) = match r.setting {
            Setting::Tolerance(t) => ("tolerance", t, String::new()),
            Setting::Fixed { n, tol, .. } => ("fixed", tol, n.to_string()),
        };
        writeln!(
            f,
            "{kind},{tol:e},{n},{},{:.4},{:.4},{:.4},{},{},{},{},{},{:e},{:e},{:e},{:e},{:e},{:e}",
            r.m,
            r.user,
            r.cpu,
            r.wall,
            r.steps,
            r.rejected,
            r.intervals,
            r.max_intervals,
            r.folds,
            r.est_fold,
            r.true_fold,
            r.est_curve,
            r.true_curve,
            r.est_mesh,
            r.est_interpolation
        )?;
    }
    f.flush()
}

/// Okabe–Ito colours of the two series.
const TOLERANCE_COLOUR: &str = "#0072B2";
const FIXED_COLOUR: &str = "#D55E00";

/// The issue's targets: (fold accuracy, CPU seconds).
const TARGETS: [(f64, f64); 3] = [(1e-3, 0.10), (1e-6, 0.35), (1e-8, 0.70)];

/// CPU time (on-CPU seconds) against true fold error, log-log, as SVG.
fn plot(rows: &[Row]) -> String {
    let (w, h) = (860.0, 600.0);
    let (left, right, top, bottom) = (80.0, 30.0, 50.0, 80.0);
    let (pw, ph) = (w - left - right, h - top - bottom);
    // decades of the axes: error 1e-12 … 1e-2, time 1e-2 … 1e1 s
    let (e_lo, e_hi, t_lo, t_hi) = (-12.0, -2.0, -2.0, 1.0);
    let x = |e: f64| left + (e.clamp(1e-12, 1e-2).log10() - e_lo) / (e_hi - e_lo) * pw;
    let y = |t: f64| top + (1.0 - (t.max(1e-2).log10() - t_lo) / (t_hi - t_lo)) * ph;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="28" font-size="18" text-anchor="middle">The paper's spring pulled to F/((2πn)²B) = 3: CPU time against fold error</text>"#,
        w / 2.0
    );
    for k in (e_lo as i32)..=(e_hi as i32) {
        let xx = x(10f64.powi(k));
        let _ = writeln!(
            s,
            r##"<line x1="{xx:.3}" y1="{top}" x2="{xx:.3}" y2="{:.3}" stroke="#e6e6e6"/><text x="{xx:.3}" y="{:.3}" font-size="12" text-anchor="middle">1e{k}</text>"##,
            top + ph,
            top + ph + 16.0
        );
    }
    for k in (t_lo as i32)..=(t_hi as i32) {
        let yy = y(10f64.powi(k));
        let label = 10f64.powi(k);
        let _ = writeln!(
            s,
            r##"<line x1="{left}" y1="{yy:.3}" x2="{:.3}" y2="{yy:.3}" stroke="#e6e6e6"/><text x="{:.3}" y="{:.3}" font-size="12" text-anchor="end">{label} s</text>"##,
            left + pw,
            left - 6.0,
            yy + 4.0
        );
    }
    let _ = writeln!(
        s,
        r#"<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="black"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.3}" y="{:.3}" font-size="14" text-anchor="middle">true fold error: max over the six folds of max(|ΔΔz|, |ΔF/((2πn)²B)|)</text>"#,
        left + pw / 2.0,
        top + ph + 40.0
    );
    let _ = writeln!(
        s,
        r#"<text transform="translate(20 {:.3}) rotate(-90)" font-size="14" text-anchor="middle">CPU time of the run, s (median of repeats, one thread)</text>"#,
        top + ph / 2.0
    );
    // the issue's targets
    for &(e, t) in &TARGETS {
        let (cx, cy) = (x(e), y(t));
        let _ = writeln!(
            s,
            r##"<path d="M{:.3},{cy:.3}H{:.3}M{cx:.3},{:.3}V{:.3}" stroke="#666666" stroke-width="2"/>"##,
            cx - 7.0,
            cx + 7.0,
            cy - 7.0,
            cy + 7.0
        );
    }
    // tolerance runs: a line through them in order, circles, labels
    let tol_rows: Vec<&Row> = rows
        .iter()
        .filter(|r| matches!(r.setting, Setting::Tolerance(_)) && r.true_fold.is_finite())
        .collect();
    let mut d = String::new();
    for r in &tol_rows {
        let _ = write!(d, "{:.3},{:.3} ", x(r.true_fold), y(r.cpu));
    }
    let _ = writeln!(
        s,
        r#"<polyline points="{d}" fill="none" stroke="{TOLERANCE_COLOUR}" stroke-width="1.5"/>"#
    );
    for (i, r) in tol_rows.iter().enumerate() {
        let (cx, cy) = (x(r.true_fold), y(r.cpu));
        // labels alternate above and below the line
        let dy = if i % 2 == 0 { -8.0 } else { 16.0 };
        let _ = writeln!(
            s,
            r#"<circle cx="{cx:.3}" cy="{cy:.3}" r="5" fill="{TOLERANCE_COLOUR}" stroke="black" stroke-width="0.8"/><text x="{:.3}" y="{:.3}" font-size="11" fill="{TOLERANCE_COLOUR}">{}</text>"#,
            cx + 7.0,
            cy + dy,
            r.setting.label()
        );
    }
    for r in rows
        .iter()
        .filter(|r| matches!(r.setting, Setting::Fixed { .. }) && r.true_fold.is_finite())
    {
        let (cx, cy) = (x(r.true_fold), y(r.cpu));
        let Setting::Fixed { n, m, .. } = r.setting else {
            continue;
        };
        let _ = writeln!(
            s,
            r#"<rect x="{:.3}" y="{:.3}" width="10" height="10" fill="{FIXED_COLOUR}" stroke="black" stroke-width="0.8"/><text x="{:.3}" y="{:.3}" font-size="11" fill="{FIXED_COLOUR}">N = {n}, m = {m}</text>"#,
            cx - 5.0,
            cy - 5.0,
            cx + 7.0,
            cy + 16.0
        );
    }
    let legend = [
        (
            "tolerance runs (adaptive mesh, m from tol)",
            TOLERANCE_COLOUR,
            "dot",
        ),
        (
            "fixed uniform meshes (N intervals, m points)",
            FIXED_COLOUR,
            "square",
        ),
        ("issue 11's targets (≤ time at accuracy)", "#666666", "plus"),
    ];
    let (lx, ly) = (left + pw - 340.0, top + 12.0);
    let _ = writeln!(
        s,
        r#"<rect x="{lx}" y="{ly}" width="330" height="{}" fill="white" fill-opacity="0.9" stroke="black"/>"#,
        18.0 * legend.len() as f64 + 8.0
    );
    for (i, (label, colour, kind)) in legend.iter().enumerate() {
        let yy = ly + 16.0 + 18.0 * i as f64;
        let cx = lx + 20.0;
        match *kind {
            "dot" => {
                let _ = write!(
                    s,
                    r#"<circle cx="{cx}" cy="{yy}" r="5" fill="{colour}" stroke="black" stroke-width="0.8"/>"#
                );
            }
            "square" => {
                let _ = write!(
                    s,
                    r#"<rect x="{}" y="{}" width="10" height="10" fill="{colour}" stroke="black" stroke-width="0.8"/>"#,
                    cx - 5.0,
                    yy - 5.0
                );
            }
            _ => {
                let _ = write!(
                    s,
                    r#"<path d="M{},{yy}H{}M{cx},{}V{}" stroke="{colour}" stroke-width="2"/>"#,
                    cx - 7.0,
                    cx + 7.0,
                    yy - 7.0,
                    yy + 7.0
                );
            }
        }
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}" font-size="12">{label}</text>"#,
            lx + 40.0,
            yy + 4.0
        );
    }
    s += "</svg>\n";
    s
}
