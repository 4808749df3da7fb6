//! Sliding loops, with and without pinning (`Pull::pin_slides`,
//! experimental): pulls where loops left in the rod slide at high tension,
//! each run unpinned and pinned, one line per run (docs/ACCURACY.md,
//! "Sliding loops, pinned").
//!
//! ```text
//! cargo run --release --example slides            # all scenes (≈ 6 min, mostly the unpinned runs)
//! cargo run --release --example slides -- --pinned-only
//! ```
//!
//! Per run: the spring (n, θ0, A/B, ν), the load asked for
//! (F/((2πn)²B)) and the tolerance, whether it pinned, the wall seconds,
//! steps, how it ended (the load reached, or where and why it stopped),
//! whether its estimate meets the tolerance, the estimate (with its pinned
//! part) and the extension at F/((2πn)²B) = 10 where the run got there.

use std::error::Error;
use std::time::Instant;

use hockle::continuation::Termination;
use hockle::rod::{Pull, Rod};
use hockle::{Stiffness, Target};

/// A spring, the load asked for, the tolerance and a step limit that
/// bounds the slowest unpinned run (1000: the unpinned runs that reach
/// their load take at most 400).
struct Scene {
    coils: u32,
    nu: f64,
    force: f64,
    tol: f64,
    max_steps: usize,
}

const SCENES: [Scene; 6] = [
    // the paper's spring at ν = −0.5: three loops slide past F ≈ 8
    Scene {
        coils: 4,
        nu: -0.5,
        force: 14.0,
        tol: 1e-4,
        max_steps: 1000,
    },
    Scene {
        coils: 4,
        nu: -0.5,
        force: 14.0,
        tol: 1e-6,
        max_steps: 1000,
    },
    Scene {
        coils: 3,
        nu: -0.5,
        force: 14.0,
        tol: 1e-6,
        max_steps: 1000,
    },
    // springs whose loops stop sliding freely (near a pop-out, or an
    // interaction at higher force): pinning fails there
    Scene {
        coils: 16,
        nu: 0.05,
        force: 1.3,
        tol: 1e-6,
        max_steps: 1000,
    },
    Scene {
        coils: 4,
        nu: -0.5,
        force: 100.0,
        tol: 1e-6,
        max_steps: 400,
    },
    // the paper's spring with 32 coils after its cascade: a loop left in
    // the middle tightens and slides
    Scene {
        coils: 32,
        nu: 0.05,
        force: 1.0,
        tol: 1e-6,
        max_steps: 1000,
    },
];

const USAGE: &str = "\
usage: cargo run --release --example slides -- [OPTIONS]
  --pinned-only  the pinned runs only (default: each scene unpinned, then pinned)
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("slides", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    cli::only_flags(&["--pinned-only"], USAGE)?;
    let pinned_only = std::env::args().any(|a| a == "--pinned-only");
    for s in &SCENES {
        let rod = Rod::new(
            s.coils,
            89.8_f64.to_radians(),
            Stiffness::nikolai(10.0, s.nu)?,
        )?;
        let modes: &[bool] = if pinned_only { &[true] } else { &[false, true] };
        for &pin in modes {
            let t = Instant::now();
            let run = Pull::new(rod, Target::Force(s.force))
                .tolerance(s.tol)
                .max_steps(s.max_steps)
                .pin_slides(pin)
                .run(())?;
            let seconds = t.elapsed().as_secs_f64();
            let curve = run.curve();
            let scale = curve.force_scale();
            let last = curve.points().last().map_or(f64::NAN, |p| p.force / scale);
            let end = match run.termination() {
                _ if run.reached_target() => "reached".to_string(),
                Termination::Failed { error, .. } => format!("failed at {last:.4}: {error}"),
                other => format!("stopped at {last:.4}: {other:?}"),
            };
            let at10 = curve.extension_at(10.0 * scale);
            let e = run.estimate();
            println!(
                "n={} nu={} force={} tol={:.0e} pinned={pin} seconds={seconds:.2} steps={} meets={} \
                 estimate={:.1e} (pinned {:.1e}) dz(10)={} | {end}",
                s.coils,
                s.nu,
                s.force,
                s.tol,
                run.steps(),
                run.meets_tolerance(),
                e.located.max(e.curve()),
                e.pinned,
                at10.first().map_or("-".to_string(), |v| format!("{v:.10}")),
            );
        }
    }
    Ok(())
}
