//! Stability and self-contact along the paper's pull, and what they cost.
//!
//! ```text
//! cargo run --release --example stability [-- --every N] [--segments N] [--slinky] [--contact-only]
//! ```
//!
//! Pulls the paper's spring (n = 4, θ0 = 89.8°, A/B = 10, ν = 0.05; with
//! `--slinky` A/B = 0.1) to F/((2πn)²B) = 3, keeps the equilibrium of every
//! N-th curve point (default 25), and prints for each: the index carried
//! along the curve ([`Response::stability`]) and the direct test
//! ([`Equilibrium::second_variation`]) under both controls, the lowest
//! eigenvalue, and the closest approach of the shape to itself. Ends with
//! the time of the pull, of the direct tests and of the contact checks.

use std::error::Error;
use std::ops::ControlFlow;
use std::time::{Duration, Instant};

use hockle::Stiffness;
use hockle::bvp::Solution;
use hockle::continuation::{Point, PointKind};
use hockle::rod::Equilibrium;
use hockle::spring::{Control, RodModel, Spring, Target};

const USAGE: &str = "\
usage: cargo run --release --example stability -- [OPTIONS]
  --every N        keep and test the equilibrium of every N-th curve point (default 25)
  --segments N     segments of the direct test's discretisation (default 200)
  --slinky         the slinky (A/B = 0.1) instead of the paper's spring (A/B = 10)
  --contact-only   skip the direct test: the carried index and the contact check only
  --help           this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("stability", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut every = 25usize;
    let mut segments = hockle::rod::STABILITY_SEGMENTS;
    let mut spring = Spring::paper();
    let mut contact_only = false;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--every" => every = args.next().ok_or("--every needs N")?.parse()?,
            "--segments" => segments = args.next().ok_or("--segments needs N")?.parse()?,
            "--contact-only" => contact_only = true,
            "--slinky" => {
                spring = Spring::from_degrees(4, 89.8, Stiffness::nikolai(0.1, 0.05)?)?;
            }
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    let model = RodModel::default();
    let rod = RodModel::rod(&spring)?;
    let mut kept: Vec<(usize, Solution)> = Vec::new();
    let mut index = 0usize;
    let clock = Instant::now();
    let response = model.pull_observed(&spring, Target::Force(3.0), |p: &Point| {
        if p.kind() != PointKind::Fold {
            if index.is_multiple_of(every) {
                kept.push((index, p.solution().clone()));
            }
            index += 1;
        }
        ControlFlow::Continue(())
    })?;
    let pull_time = clock.elapsed();
    let carried_f = response.stability(Control::Force);
    let carried_e = response.stability(Control::Extension);
    let scale = spring.force_scale();
    println!("{response} in {pull_time:.2?}");
    println!(
        "{:>5} {:>9} {:>9} | force: carried direct λ_min | extension: carried direct λ_min | contact",
        "point", "Δz", "F/(2πn)²"
    );
    let (mut t_stab, mut t_index, mut t_contact) = (Duration::ZERO, Duration::ZERO, Duration::ZERO);
    let mut index_differs = 0;
    let mut disagree = 0;
    let mut failed = 0;
    for (i, sol) in &kept {
        let eq = Equilibrium::new(rod.with_control(Control::Force), sol.clone())?;
        let t = Instant::now();
        let direct = [Control::Force, Control::Extension].map(|c| {
            if contact_only {
                Err(hockle::Error::InvalidCount {
                    name: "segments",
                    value: 0,
                    allowed: "skipped (--contact-only)",
                })
            } else {
                eq.second_variation(c, segments)
            }
        });
        t_stab += t.elapsed();
        // the index alone, in O(N) (`Equilibrium::stability`)
        let t = Instant::now();
        let index = [Control::Force, Control::Extension].map(|c| eq.stability(c));
        t_index += t.elapsed();
        for (i, d) in index.iter().zip(&direct) {
            if let (Ok(a), Ok(b)) = (i, d) {
                index_differs += usize::from(*a != b.stability());
            }
        }
        let t = Instant::now();
        let contact = eq.closest_approach();
        t_contact += t.elapsed();
        let p = response.curve().points()[*i];
        let mut cells = Vec::new();
        let mut differs = false;
        for (d, carried) in direct.iter().zip([&carried_f, &carried_e]) {
            match d {
                Ok(v) => {
                    differs |= v.stability() != carried[*i];
                    cells.push(format!(
                        "{:>7} {:>6} {:10.3e}",
                        carried[*i].index(),
                        v.stability().index(),
                        v.lowest_eigenvalues()[0]
                    ));
                }
                Err(e) => {
                    failed += 1;
                    cells.push(format!("{:>7} {e}", carried[*i].index()));
                }
            }
        }
        if differs {
            disagree += 1;
        }
        println!(
            "{i:5} {:9.5} {:9.5} | {} | {} | {}{}",
            p.extension,
            p.force / scale,
            cells[0],
            cells[1],
            contact.map_or("none".to_string(), |c| format!("{:.3e}", c.distance)),
            if differs { " ≠" } else { "" }
        );
    }
    let k = kept.len().max(1) as u32;
    println!(
        "{} sampled points, {disagree} disagreements, {failed} direct tests failed; pull {pull_time:.2?}; direct test \
         ({segments} segments) {:.2?} per point and control; its index alone (`Equilibrium::stability`, \
         {} segments, O(N)) {:.2?}, {index_differs} different from the eigenvalues'; contact {:.2?} per point",
        kept.len(),
        t_stab / (2 * k),
        hockle::rod::STABILITY_SEGMENTS,
        t_index / (2 * k),
        t_contact / k
    );
    Ok(())
}
