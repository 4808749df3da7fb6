//! Troesch's problem at μ = 10 (y″ = μ sinh(μ y), y(0) = 0, y(1) = 1: a
//! layer at s = 1 where y′ = 148) solved by `Collocation::tolerance` from
//! the μ = 5 solution on 40 uniform intervals, at tol = 1e-2 … 1e-9: the
//! hockle side of `benches/scipy_bvp.py`'s adaptive comparison (issue 11).
//!
//! ```text
//! cargo run --release --example troesch [-- --points M] [--repeat R]
//! ```
//!
//! Per tolerance: the best wall time of R solves (default 20), the mesh,
//! the true error (largest |Δy|, |Δy′| at the 20 points of the closed form
//! in `tests/data/troesch_mu10.csv`, mpmath), the solution's estimate and
//! what the tolerance allows, tol·(1 + max|y|).

use std::error::Error;
use std::time::Instant;

use hockle::bvp::Collocation;
use hockle::bvp::classic::Troesch;

#[path = "../tests/common/mod.rs"]
mod common;

const USAGE: &str = "\
usage: cargo run --release --example troesch -- [OPTIONS]
  --points M     collocation points per interval (default 4)
  --repeat R     time each tolerance as the best of R solves (default 20)
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("troesch", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let (mut points, mut repeat) = (4, 20);
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--points" => points = args.next().ok_or("--points needs M")?.parse()?,
            "--repeat" => repeat = args.next().ok_or("--repeat needs R")?.parse()?,
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    if repeat == 0 {
        return Err("--repeat needs R ≥ 1".into());
    }
    let table = common::troesch_mu10();
    let size = 1.0 + table.last().ok_or("empty table")?[2];
    let start = Collocation::new()
        .intervals(40)
        .solve(&Troesch, |s: f64| [s, 1.0], &[5.0])?;
    println!("| tol | time | intervals | true error | estimate | allowed |");
    println!("|---|---|---|---|---|---|");
    for tol in [1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9] {
        let solver = Collocation::new().points(points).tolerance(tol);
        let mut best = f64::INFINITY;
        let mut last = None;
        for _ in 0..repeat {
            let clock = Instant::now();
            let sol = solver.solve(&Troesch, &start, &[10.0])?;
            best = best.min(clock.elapsed().as_secs_f64());
            last = Some(sol);
        }
        let sol = last.ok_or("no solve")?;
        let error = common::troesch_mu10_error(&sol, &table);
        println!(
            "| {tol:.0e} | {:.2} ms | {} (m = {}) | {error:.1e} | {:.1e} | {:.1e} |",
            best * 1e3,
            sol.mesh().intervals(),
            sol.points_per_interval(),
            sol.error_estimate(),
            tol * size
        );
    }
    Ok(())
}
