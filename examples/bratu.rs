//! Traces the Bratu branch y'' + λ e^y = 0, y(0) = y(1) = 0 from λ = 0
//! through its fold and up the upper branch until y(½) = 4, printing
//! every special point (through the observer's hooks), every 20th point as
//! progress, and writing the branch as CSV.
//!
//! Run: `cargo run --release --example bratu [-- OUT.csv]`
//! (default output `target/hockle/bratu.csv`).

use std::io::Write;
use std::ops::ControlFlow;

use hockle::bvp::Collocation;
use hockle::bvp::classic::Bratu;
use hockle::continuation::{Continuation, Observer, Point, Termination};

/// Prints the folds, branch points and the end of the run.
#[derive(Default)]
struct Report {
    folds: usize,
}

impl Observer for Report {
    fn start(&mut self, settings: &Continuation, start: &Point) -> ControlFlow<()> {
        println!("{settings}\nstart lambda={}", start.parameter());
        ControlFlow::Continue(())
    }

    fn fold(&mut self, p: &Point) -> ControlFlow<()> {
        self.folds += 1;
        println!(
            "fold lambda={:.15} y'(0)={:.12} y(1/2)={:.12} s={:.6}",
            p.parameter(),
            p.solution().at_mesh(0)[1],
            p.solution().eval(0.5)[0],
            p.arclength()
        );
        ControlFlow::Continue(())
    }

    fn branch_point(&mut self, p: &Point) -> ControlFlow<()> {
        println!(
            "branch-point lambda={:.15} s={:.6}",
            p.parameter(),
            p.arclength()
        );
        ControlFlow::Continue(())
    }

    fn finish(&mut self, termination: &Termination) {
        println!("{} fold(s); {termination}", self.folds);
    }
}

/// Progress: one line per point it is shown.
fn progress(p: &Point) -> ControlFlow<()> {
    println!("  {p}");
    ControlFlow::Continue(())
}

const USAGE: &str = "\
usage: cargo run --release --example bratu -- [OUT.csv]
  OUT.csv        where the branch is written as CSV (default target/hockle/bratu.csv)
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("bratu", run())
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut out = None;
    for a in std::env::args().skip(1) {
        match a.as_str() {
            other if other.starts_with('-') || out.is_some() => {
                return Err(cli::unknown(other, USAGE).into());
            }
            _ => out = Some(a),
        }
    }
    let out = out.unwrap_or_else(|| "target/hockle/bratu.csv".to_string());
    if let Some(dir) = std::path::Path::new(&out).parent() {
        std::fs::create_dir_all(dir)?;
    }
    let solver = Collocation::new().points(4).intervals(20);
    let start = solver.solve(&Bratu::default(), |_s: f64| [0.0, 0.0], &[0.0])?;
    let cont = Continuation::new(0)
        .solver(solver)
        .step(0.1)
        .max_steps(400)
        // Stop on the upper branch where y(½) = 4 (λ ≈ 0.6).
        .stop_when(|sol| sol.eval(0.5)[0] - 4.0);
    let t = std::time::Instant::now();
    let run = cont.run(&Bratu::default(), &start, Report::default())?;
    let elapsed = t.elapsed();
    // The same run, showing every 20th point (and the special ones).
    cont.run(&Bratu::default(), &start, progress.every(20))?;
    let mut f = std::io::BufWriter::new(std::fs::File::create(&out)?);
    writeln!(f, "arclength,lambda,dy0,y_half,kind,newton_iterations")?;
    for p in run.points() {
        writeln!(
            f,
            "{},{},{},{},{},{}",
            p.arclength(),
            p.parameter(),
            p.solution().at_mesh(0)[1],
            p.solution().eval(0.5)[0],
            p.kind(),
            p.newton_iterations()
        )?;
    }
    println!(
        "{} points in {:.3} ms; CSV: {out}",
        run.points().len(),
        elapsed.as_secs_f64() * 1e3,
    );
    Ok(())
}
