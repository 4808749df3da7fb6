//! The paper's parameter sweeps, Figs. th0, aniso and helix: the 3D rod
//! (solid) for several helix angles and anisotropies, against the
//! exact-helix model (dashed) where the paper draws it.
//!
//! ```sh
//! cargo run --release --features rayon --example sweeps [-- --out DIR] [--serial]
//! ```
//!
//! Writes `sweep_theta0.svg`, `sweep_anisotropy.svg` and `sweep_helix.svg`
//! (default `$CARGO_TARGET_DIR/hockle`, else `target/hockle` under the crate) and prints, for every spring, its
//! pop-outs. Figs. th0 and aniso are one [`sweep`] of ten pulls (parallel
//! with the `rayon` feature; `--serial` runs them one after the other to
//! measure the speed-up, docs/PERFORMANCE.md).

use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;

use hockle::Stiffness;
use hockle::spring::{HelixModel, Model, Response, RodModel, Spring, Target, sweep, sweep_serial};
use plotters::prelude::*;

const MAX_FORCE_SCALED: f64 = 3.0;

/// One curve of a figure: a label, the rod's response and, where the paper
/// draws it, the helix model's.
struct Curve {
    label: String,
    rod: Response,
    helix: Option<Response>,
}

fn spring(theta0_degrees: f64, a_over_b: f64) -> Result<Spring, Box<dyn Error>> {
    Ok(Spring::from_degrees(
        4,
        theta0_degrees,
        Stiffness::nikolai(a_over_b, 0.05)?,
    )?)
}

/// Pulls every (θ0, A/B, with the helix) of both figures with one
/// [`sweep`] (in parallel with `--features rayon`, serially with
/// `--serial`) and returns the curves in input order.
fn pull_all(cases: &[(f64, f64, bool)], serial: bool) -> Result<Vec<Curve>, Box<dyn Error>> {
    let scenes: Vec<(Spring, Target)> = cases
        .iter()
        .map(|&(t, a, _)| Ok((spring(t, a)?, Target::Force(MAX_FORCE_SCALED))))
        .collect::<Result<_, Box<dyn Error>>>()?;
    let start = Instant::now();
    let report = |done: usize, total: usize| {
        eprintln!(
            "  {done}/{total} pulls done ({:.1} s)",
            start.elapsed().as_secs_f64()
        );
    };
    let rods = if serial {
        sweep_serial(&RodModel::default(), &scenes, report)
    } else {
        sweep(&RodModel::default(), &scenes, report)
    };
    println!(
        "{} rod pulls in {:.2} s ({})",
        scenes.len(),
        start.elapsed().as_secs_f64(),
        if serial {
            "serial"
        } else if cfg!(feature = "rayon") {
            "parallel, rayon"
        } else {
            "serial: built without the rayon feature"
        }
    );
    let mut curves = Vec::new();
    for (&(t, a, with_helix), rod) in cases.iter().zip(rods) {
        let rod = rod?;
        let label = format!("θ0 = {t}°, A/B = {a}");
        println!(
            "{label:<26} {} pop-outs, {} points{}",
            rod.pop_outs().len(),
            rod.curve().len(),
            if rod.reached_target() {
                String::new()
            } else {
                format!(" (stopped: {})", rod.termination())
            }
        );
        let helix = if with_helix {
            Some(HelixModel::new(400)?.pull(&spring(t, a)?, MAX_FORCE_SCALED)?)
        } else {
            None
        };
        curves.push(Curve { label, rod, helix });
    }
    Ok(curves)
}

fn scaled(r: &Response) -> Vec<(f64, f64)> {
    let scale = r.curve().force_scale();
    r.curve()
        .points()
        .iter()
        .map(|p| (p.extension, p.force / scale))
        .filter(|p| p.1 <= MAX_FORCE_SCALED)
        .collect()
}

fn plot(title: &str, curves: &[Curve], path: &Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (900, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..1.0, 0.0..MAX_FORCE_SCALED)?;
    chart
        .configure_mesh()
        .x_desc("extension Δz")
        .y_desc("force F/(2πn)²B")
        .draw()?;
    let colours = [BLACK, BLUE, RED, GREEN, MAGENTA, CYAN];
    for (curve, colour) in curves.iter().zip(colours.iter().cycle()) {
        let colour = *colour;
        let width = if std::ptr::eq(curve, &curves[0]) {
            3
        } else {
            1
        };
        chart
            .draw_series(LineSeries::new(
                scaled(&curve.rod),
                colour.stroke_width(width),
            ))?
            .label(format!("rod, {}", curve.label))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(width))
            });
        if let Some(helix) = &curve.helix {
            chart
                .draw_series(DashedLineSeries::new(
                    scaled(helix),
                    6,
                    4,
                    colour.stroke_width(1),
                ))?
                .label(format!("exact helix, {}", curve.label))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 8, y)], colour));
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    println!("wrote {}", path.display());
    Ok(())
}

const USAGE: &str = "\
usage: cargo run --release --features rayon --example sweeps -- [OPTIONS]
  --out DIR      where the SVG files go (default target/hockle)
  --serial       run the pulls one after the other (default: in parallel with the rayon
                 feature), to measure the speed-up
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("sweeps", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut out = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(
            || std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
            PathBuf::from,
        )
        .join("hockle");
    let mut serial = false;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            "--serial" => serial = true,
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    std::fs::create_dir_all(&out)?;

    // Figs. th0 and aniso in one sweep: four helix angles at A/B = 10,
    // then six anisotropies at θ0 = 89.8° (the helix drawn for the last two).
    let mut cases: Vec<(f64, f64, bool)> = [89.8, 89.5, 89.0, 88.0]
        .into_iter()
        .map(|t| (t, 10.0, false))
        .collect();
    cases.extend(
        [
            (10.0, false),
            (8.0, false),
            (6.0, false),
            (4.0, false),
            (1.0, true),
            (0.1, true),
        ]
        .map(|(a, h)| (89.8, a, h)),
    );
    let mut all = pull_all(&cases, serial)?;
    let aniso = all.split_off(4);
    let theta0 = all;
    plot(
        "Fig. th0: helix angles (n = 4, A/B = 10, ν = 0.05)",
        &theta0,
        &out.join("sweep_theta0.svg"),
    )?;

    plot(
        "Fig. aniso: anisotropies (n = 4, θ0 = 89.8°, ν = 0.05)",
        &aniso,
        &out.join("sweep_anisotropy.svg"),
    )?;

    let helix = pull_all(&[(88.0, 10.0, true), (60.0, 10.0, true)], serial)?;
    plot(
        "Fig. helix: the rod against the exact helix (n = 4, A/B = 10)",
        &helix,
        &out.join("sweep_helix.svg"),
    )?;
    Ok(())
}
