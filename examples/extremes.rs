//! The extremes tables of docs/ACCURACY.md ("extremes" section): what
//! `special`, `elastica` and the 3D rod give at the ends of their domains.
//!
//! ```text
//! cargo run --release --example extremes            # special, elastica
//! cargo run --release --example extremes -- --rod   # the rod only (minutes)
//! cargo run --release --example extremes -- --long-springs   # n = 12 … 40, whole and half (minutes)
//! ```
//!
//! special: against the mpmath table `tests/data/special_extremes.csv`
//! (`python3 tests/data/gen_special_extremes.py`), errors in ulps of the
//! true value, raw and divided by 1 + the condition number |x f′/f|.
//! elastica: the residual of the end condition κ(s_i) = 2πn (eq6, evaluated
//! with `special::jacobi`, independent of the root solve), the centreline's
//! end against the closed-form extension, and traces to large forces.
//! rod: the paper's spring with one parameter moved at a time, pulled to
//! F/((2πn)²B) = 100 with the default settings (tolerance 1e-6, adaptive
//! mesh) and with tolerance 1e-7 (the reference); the difference of the
//! fold positions (or of the final extension) between the two against the
//! default pull's own estimate says whether the estimate covers its error
//! (over the folds both located, when the reference stopped early).

use core::f64::consts::PI;

use std::ops::ControlFlow;
use std::time::{Duration, Instant};

use hockle::continuation::{Point, Termination};
use hockle::elastica::{Branch, Elastica, Trace, secondary_fold};
use hockle::rod::{Equilibrium, Pull, PullRun, Rod};
use hockle::special::{Modulus, ellip_e, ellip_e_inc, ellip_f, ellip_k, jacobi};
use hockle::spring::RodModel;
use hockle::{Stiffness, Target};

const TABLE: &str = include_str!("../tests/data/special_extremes.csv");

fn ulps(x: f64, r: f64) -> f64 {
    if x == r {
        0.0
    } else {
        ((x - r) / r).abs() / f64::EPSILON
    }
}

fn special() {
    println!(
        "| m₁ | K (ulp) | E (ulp) | sn, cn, dn max (ulp) | sn, cn, dn max (norm.) | F(φ) max (norm.) | E(φ) max (norm.) | non-finite |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    let mut m1s: Vec<&str> = Vec::new();
    for line in TABLE.lines().skip(1) {
        let m1 = line.split(',').nth(1).unwrap();
        if !m1s.contains(&m1) {
            m1s.push(m1);
        }
    }
    for m1s_ in m1s {
        let md = Modulus::from_complement(m1s_.parse().unwrap()).unwrap();
        let m = md.m();
        let (mut k, mut e, mut jr, mut jn, mut fnorm, mut enorm, mut bad) =
            (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64, 0);
        for line in TABLE.lines().skip(1) {
            let f: Vec<&str> = line.split(',').collect();
            if f[1] != m1s_ {
                continue;
            }
            let r: f64 = f[3].parse().unwrap();
            let x: f64 = if f[2].is_empty() {
                0.0
            } else {
                f[2].parse().unwrap()
            };
            let j = jacobi(x, md);
            let (got, cond) = match f[0] {
                "K" => (ellip_k(md), 0.0),
                "E" => (ellip_e(md), 0.0),
                "sn" => (j.sn, (x * j.cn * j.dn / j.sn).abs()),
                "cn" => (j.cn, (x * j.sn * j.dn / j.cn).abs()),
                "dn" => (j.dn, (x * m * j.sn * j.cn / j.dn).abs()),
                "F" => {
                    let v = ellip_f(x, md);
                    let d = (1.0 - m * x.sin().powi(2)).sqrt();
                    (v, (x / (d * v)).abs())
                }
                _ => {
                    let v = ellip_e_inc(x, md);
                    let d = (1.0 - m * x.sin().powi(2)).sqrt();
                    (v, (x * d / v).abs())
                }
            };
            if !got.is_finite() {
                bad += 1;
                continue;
            }
            let u = ulps(got, r);
            let norm = u / (1.0 + cond);
            match f[0] {
                "K" => k = u,
                "E" => e = u,
                "sn" | "cn" | "dn" => {
                    jr = jr.max(u);
                    jn = jn.max(norm);
                }
                "F" => fnorm = fnorm.max(norm),
                _ => enorm = enorm.max(norm),
            }
        }
        println!(
            "| {m1s_} | {k:.2} | {e:.2} | {jr:.3e} | {jn:.2} | {fnorm:.2} | {enorm:.2} | {bad} |"
        );
    }
}

fn end_residual(e: &Elastica) -> f64 {
    let k0 = 2.0 * PI * f64::from(e.coils());
    e.end_curvatures()
        .iter()
        .map(|c| ((c - k0) / k0).abs())
        .fold(0.0, f64::max)
}

fn elastica() {
    println!(
        "| n | m₁ | υ: F/(2πn)² | υ: eq6 residual | υ: centreline end − Δz | α: F/(2πn)² | α: eq6 residual | α: centreline end − Δz |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for n in [1, 8, 50] {
        for m1 in [1e-300, 1e-310, 1e-320, 5e-324] {
            let s = Elastica::symmetric_with(n, Modulus::from_complement(m1).unwrap()).unwrap();
            let mut row = format!("| {n} | {m1:e} |");
            for e in [s.upsilon, s.alpha] {
                let c = e.centreline(200).unwrap();
                let end = c[199].y - e.extension();
                row += &format!(
                    " {:.4e} | {:.1e} | {:.1e} |",
                    e.force_scaled(),
                    end_residual(&e),
                    end.abs()
                );
            }
            println!("{row}");
        }
    }
    println!();
    println!("| n | branch | F/(2πn)² = 1e2 | 1e4 | 1e5 | 1e6 |");
    println!("|---|---|---|---|---|---|");
    for n in [1, 8, 50] {
        for branch in [Branch::Upsilon, Branch::Alpha, Branch::Theta { j: n }] {
            let mut row = format!("| {n} | {branch} |");
            for limit in [1e2, 1e4, 1e5, 1e6] {
                let cell = match Trace::new()
                    .points(20)
                    .max_force_scaled(limit)
                    .run(n, branch)
                {
                    Ok(c) => {
                        let last = c.force_scaled(c.len() - 1).unwrap();
                        let off = (last / limit - 1.0).abs();
                        if off == 0.0 {
                            " Ok, end exact |".to_string()
                        } else {
                            format!(" Ok, end {off:.0e} off |")
                        }
                    }
                    Err(hockle::Error::ForceOutOfReach { reachable, .. }) => {
                        format!(" ForceOutOfReach (reach {reachable:.3e}) |")
                    }
                    Err(e) => format!(" {e} |"),
                };
                row += &cell;
            }
            println!("{row}");
        }
    }
    println!();
    println!("| n | j | fold k′ = √m₁ | eq6 residual at the fold |");
    println!("|---|---|---|---|");
    for (n, j) in [
        (8, 36_960),
        (1, 100_000),
        (8, 273_537),
        (50, 2),
        (1, u32::MAX),
        (8, u32::MAX),
    ] {
        match secondary_fold(n, j) {
            Ok(f) => println!(
                "| {n} | {j} | {:.3e} | {:.1e} |",
                f.solution().elliptic_modulus().k_prime(),
                end_residual(&f.solution())
            ),
            Err(e) => println!("| {n} | {j} | {e} | |"),
        }
    }
}

/// The pull target of the rod table: F/((2πn)²B) = 100.
const ROD_TARGET: f64 = 100.0;

/// The tolerance of the rod table's reference pull.
const REFERENCE_TOLERANCE: f64 = 1e-7;

/// Wall-clock budget of a reference pull: stopped by its observer after
/// this (a reference at 1e-8 took 775 s for n = 8 on the shared machine).
const REFERENCE_BUDGET: Duration = Duration::from_secs(90);

/// One pull of the rod table: the default settings, or tolerance
/// `tolerance` within `REFERENCE_BUDGET`.
fn pull(
    n: u32,
    theta0_deg: f64,
    a_over_b: f64,
    nu: f64,
    tolerance: Option<f64>,
) -> hockle::Result<PullRun> {
    let rod = Rod::new(
        n,
        theta0_deg.to_radians(),
        Stiffness::nikolai(a_over_b, nu)?,
    )?;
    let pull = Pull::new(rod, Target::Force(ROD_TARGET));
    match tolerance {
        Some(tol) => {
            let clock = Instant::now();
            pull.tolerance(tol).run(|_p: &Point| {
                if clock.elapsed() > REFERENCE_BUDGET {
                    ControlFlow::Break(())
                } else {
                    ControlFlow::Continue(())
                }
            })
        }
        None => pull.run(()),
    }
}

/// The largest difference between the folds of two runs in the plot plane
/// (Δz, F/((2πn)²B)) over the folds both located, in order, when their
/// kinds agree (all of them, or the first ones when a run stopped early),
/// with the number compared; `None` when the kinds differ.
fn fold_difference(a: &PullRun, b: &PullRun) -> Option<(f64, usize)> {
    let both = a.folds().len().min(b.folds().len());
    let complete = a.folds().len() == b.folds().len();
    if (!complete && a.reached_target() && b.reached_target())
        || a.folds()
            .iter()
            .zip(b.folds())
            .any(|(x, y)| x.kind != y.kind)
    {
        return None;
    }
    let (sa, sb) = (a.curve().scale(), b.curve().scale());
    let d = a
        .folds()
        .iter()
        .zip(b.folds())
        .map(|(x, y)| {
            let dz = (x.point.extension - y.point.extension).abs();
            let df = (x.point.force_scaled(sa) - y.point.force_scaled(sb)).abs();
            dz.max(df)
        })
        .fold(0.0, f64::max);
    Some((d, both))
}

fn last_extension(run: &PullRun) -> f64 {
    run.curve()
        .points()
        .last()
        .map_or(f64::NAN, |p| p.extension)
}

/// Why a run ended, and for a run that reached its target whether its
/// estimate met its tolerance ([`PullRun::meets_tolerance`]).
fn termination(run: &PullRun) -> String {
    match run.termination() {
        Termination::ParameterValue(_) if !run.meets_tolerance() => {
            "reached, tolerance NOT met".into()
        }
        Termination::ParameterValue(_) => "reached".into(),
        Termination::MaxSteps(n) => format!("step limit ({n})"),
        Termination::Stopped => format!("stopped after {} s", REFERENCE_BUDGET.as_secs()),
        Termination::Failed { ds, error } => format!("Failed at ds = {ds:.1e}: {error}"),
        other => other.to_string(),
    }
}

fn rod() {
    println!(
        "| n | θ0 | A/B | ν | default: end | points | folds | pop-outs | estimate | intervals (max) | time | 1e-7: end | folds | time | default vs 1e-7: folds | end Δz |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    let paper = (4, 89.8, 10.0, 0.05);
    let mut cases = Vec::new();
    for n in [1, 2, 8, 16] {
        cases.push((n, paper.1, paper.2, paper.3));
    }
    for th in [30.0, 89.99, 90.0] {
        cases.push((paper.0, th, paper.2, paper.3));
    }
    for ab in [100.0, 0.01] {
        cases.push((paper.0, paper.1, ab, paper.3));
    }
    for nu in [-0.5, 0.0, 0.49] {
        cases.push((paper.0, paper.1, paper.2, nu));
    }
    for (n, th, ab, nu) in cases {
        let head = format!("| {n} | {th}° | {ab} | {nu} |");
        // the two tolerances on two threads
        let (coarse, fine) = std::thread::scope(|sc| {
            let fine = sc.spawn(|| pull(n, th, ab, nu, Some(REFERENCE_TOLERANCE)));
            let coarse = pull(n, th, ab, nu, None);
            (coarse, fine.join().expect("the reference pull panicked"))
        });
        let (run_default, run_ref) = match (coarse, fine) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(e), _) | (_, Err(e)) => {
                println!("{head} {e} | | | | | | | | | | | |");
                continue;
            }
        };
        let pop_outs = RodModel::response(run_default.clone()).map_or(0, |r| r.pop_outs().len());
        let folds = match fold_difference(&run_default, &run_ref) {
            Some((_, 0)) if !run_ref.reached_target() => "reference did not reach".to_string(),
            Some((d, k)) if !run_ref.reached_target() => format!(
                "{d:.1e} (the first {k} of {}; reference did not reach)",
                run_default.folds().len()
            ),
            Some((d, k)) if !run_default.reached_target() => {
                format!("{d:.1e} (the first {k}; default did not reach)")
            }
            Some(_) if run_default.folds().is_empty() => "—".to_string(),
            Some((d, _)) => format!("{d:.1e}"),
            None => format!(
                "fold kinds differ ({} vs {})",
                run_default.folds().len(),
                run_ref.folds().len()
            ),
        };
        let end = if run_default.reached_target() && run_ref.reached_target() {
            format!(
                "{:.1e}",
                (last_extension(&run_default) - last_extension(&run_ref)).abs()
            )
        } else {
            "—".to_string()
        };
        println!(
            "{head} {} (Δz = {:.8}) | {} | {} | {pop_outs} | {:.1e} | {} ({}) | {:.1} s | {} (Δz = {:.8}) | {} | {:.1} s | {folds} | {end} |",
            termination(&run_default),
            last_extension(&run_default),
            run_default.curve().len(),
            run_default.folds().len(),
            run_default.estimate().curve(),
            run_default.estimate().intervals,
            run_default.estimate().max_intervals,
            run_default.elapsed().as_secs_f64(),
            termination(&run_ref),
            last_extension(&run_ref),
            run_ref.folds().len(),
            run_ref.elapsed().as_secs_f64(),
        );
    }
}

/// The paper's spring with many coils (n = 12 … 40) pulled to
/// F/((2πn)²B) = 1 at five tolerances, the whole rod or (`half`) its half
/// (`Rod::symmetric`): where a long spring's pull reaches its load, and
/// where it fails (docs/ACCURACY.md, "Long springs").
fn long_springs(half: bool) {
    println!(
        "| n | tolerance | end | points | folds | Δz at the end | estimate | intervals (max) | time |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for n in [12, 16, 24, 32, 40] {
        for tol in [1e-2, 3e-3, 1e-3, 1e-4, 1e-6] {
            let rod = Rod::new(
                n,
                89.8_f64.to_radians(),
                Stiffness::nikolai(10.0, 0.05).expect("valid"),
            )
            .expect("valid");
            let rod = if half {
                rod.symmetric().expect("a helix is symmetric")
            } else {
                rod
            };
            let run = match Pull::new(rod, Target::Force(1.0)).tolerance(tol).run(()) {
                Ok(run) => run,
                Err(e) => {
                    println!("| {n} | {tol:.0e} | {e} | | | | | | |");
                    continue;
                }
            };
            println!(
                "| {n} | {tol:.0e} | {} | {} | {} | {:.6} | {:.1e} | {} ({}) | {:.1} s |",
                termination(&run),
                run.curve().len(),
                run.folds().len(),
                last_extension(&run),
                run.estimate().overall(),
                run.estimate().intervals,
                run.estimate().max_intervals,
                run.elapsed().as_secs_f64(),
            );
        }
    }
}

/// How far the whole rod's pulls of the long springs leave their symmetric
/// branch (`--long-springs`, last table): n = 24, 32, 40 pulled as in
/// [`long_springs`] at 1e-2, and at
/// every point the largest |κ(s) − κ(1 − s)| over s = 0, 0.01, …, 0.5 (κ the
/// curvature, the same at s and 1 − s on an equilibrium that the helix's
/// two-fold rotation about its midpoint normal maps onto itself, as the rest
/// state and the paper's elastica branches are). Prints every 50th point,
/// the first beyond 1e-6 and the last.
fn long_springs_symmetry() {
    println!("| n | point | Δz | F/((2πn)²B) | max abs(κ(s) − κ(1 − s)) |");
    println!("|---|---|---|---|---|");
    for n in [24, 32, 40] {
        let rod = Rod::new(
            n,
            89.8_f64.to_radians(),
            Stiffness::nikolai(10.0, 0.05).expect("valid"),
        )
        .expect("valid");
        let scale = rod.scale().value();
        let mut rows: Vec<(f64, f64, f64)> = Vec::new();
        let record = |p: &Point| {
            let asymmetry = Equilibrium::new(rod, p.solution().clone()).map_or(f64::NAN, |e| {
                (0..=50)
                    .map(|i| {
                        let s = f64::from(i) / 100.0;
                        match (e.curvature(s), e.curvature(1.0 - s)) {
                            (Ok(a), Ok(b)) => (a - b).abs(),
                            _ => f64::NAN,
                        }
                    })
                    .fold(0.0, f64::max)
            });
            rows.push((p.diagram()[1], p.parameter() / scale, asymmetry));
            ControlFlow::Continue(())
        };
        let run = Pull::new(rod, Target::Force(1.0))
            .tolerance(1e-2)
            .run(record);
        let first = rows.iter().position(|r| r.2 > 1e-6);
        for (i, (dz, f, a)) in rows.iter().enumerate() {
            if i % 50 == 0 || Some(i) == first || i + 1 == rows.len() {
                let mark = if Some(i) == first {
                    " (first > 1e-6)"
                } else {
                    ""
                };
                println!("| {n} | {i}{mark} | {dz:.6} | {f:.6} | {a:.1e} |");
            }
        }
        match run {
            Ok(run) => println!("| {n} | end: {} | | | |", termination(&run)),
            Err(e) => println!("| {n} | end: {e} | | | |"),
        }
    }
}

const USAGE: &str = "\
usage: cargo run --release --example extremes -- [OPTIONS]
  --rod            the rod's table only, instead of special's and elastica's (minutes)
  --long-springs   the long springs' tables only, n = 12 … 40 coils, the whole rod and its half (minutes)
  --help           this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("extremes", run())
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    cli::only_flags(&["--rod", "--long-springs"], USAGE)?;
    if std::env::args().any(|a| a == "--long-springs") {
        println!("#### The whole rod\n");
        long_springs(false);
        println!("\n#### On its half (`Rod::symmetric`)\n");
        long_springs(true);
        println!("\n#### The whole rod's distance from the symmetric branch\n");
        long_springs_symmetry();
        return Ok(());
    }
    if std::env::args().any(|a| a == "--rod") {
        println!("### rod\n");
        rod();
        return Ok(());
    }
    println!("### special\n");
    special();
    println!("\n### elastica\n");
    elastica();
    Ok(())
}
