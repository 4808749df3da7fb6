//! The paper's elastica figures as SVG: force–extension branches and shapes.
//!
//! ```text
//! cargo run --release --example elastica_branches [-- --out DIR]
//! ```
//!
//! Writes into DIR (default `$CARGO_TARGET_DIR/hockle`, else `target/hockle` under the crate):
//! - `f_z_sym.svg`: primary υ (solid) and α (dashed) branches, n = 1..8;
//! - `f_z_nonsym.svg`: ϑ_j, j = 1..7, with the bifurcation points for n = 1..10;
//! - `f_z_nonsym_n.svg`: ϑ_j (dashed) and the secondary branches for n = 1..10;
//! - `f_z_nonsym_symm_n4.svg`: n = 4: primary, secondary (solid) and ϑ (dashed);
//! - `elastica_shapes.svg`: υ and α for n = 1, the bifurcation shapes for n = 4,
//!   j = 3 and 5, and a ϑ-shape for n = 3, j = 3.
//!
//! Forces are F/(8π)² (the paper scales every elastica figure with n = 4);
//! F is the physical tension, half the paper's printed F, so the vertical
//! scale is half the paper's.
use std::error::Error;
use std::path::PathBuf;

use hockle::ForceExtension;
use hockle::elastica::{Branch, Elastica, Trace, bifurcation};
use plotters::prelude::*;

const FMAX: f64 = 1.5;

const USAGE: &str = "\
usage: cargo run --release --example elastica_branches -- [OPTIONS]
  --out DIR      where the SVG files go (default target/hockle)
  --help         this text
";

/// The output folder of the command line, or the argument it does not take.
fn out_dir() -> Result<PathBuf, String> {
    let mut args = std::env::args().skip(1);
    let mut dir = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(
            || std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
            PathBuf::from,
        )
        .join("hockle");
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => dir = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            other => return Err(cli::unknown(other, USAGE)),
        }
    }
    Ok(dir)
}

fn series(c: &ForceExtension) -> Vec<(f64, f64)> {
    let s = c.force_scale();
    c.points()
        .iter()
        .map(|p| (p.extension, p.force / s))
        .collect()
}

type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

fn chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    title: &str,
) -> Result<Chart<'a, 'b>, Box<dyn Error>> {
    root.fill(&WHITE)?;
    let mut ch = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(36)
        .y_label_area_size(48)
        .build_cartesian_2d(0.0..1.0, 0.0..FMAX)?;
    ch.configure_mesh()
        .x_desc("extension Δz")
        .y_desc("F / (8π)²")
        .light_line_style(WHITE)
        .draw()?;
    Ok(ch)
}

fn solid(
    ch: &mut Chart<'_, '_>,
    c: &ForceExtension,
    color: RGBColor,
) -> Result<(), Box<dyn Error>> {
    ch.draw_series(LineSeries::new(series(c), color.stroke_width(2)))?;
    Ok(())
}

fn dashed(
    ch: &mut Chart<'_, '_>,
    c: &ForceExtension,
    color: RGBColor,
) -> Result<(), Box<dyn Error>> {
    ch.draw_series(DashedLineSeries::new(
        series(c),
        6,
        4,
        color.stroke_width(2),
    ))?;
    Ok(())
}

fn palette(i: usize) -> RGBColor {
    const C: [RGBColor; 10] = [
        RGBColor(31, 119, 180),
        RGBColor(255, 127, 14),
        RGBColor(44, 160, 44),
        RGBColor(214, 39, 40),
        RGBColor(148, 103, 189),
        RGBColor(140, 86, 75),
        RGBColor(227, 119, 194),
        RGBColor(127, 127, 127),
        RGBColor(188, 189, 34),
        RGBColor(23, 190, 207),
    ];
    C[i % C.len()]
}

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("elastica_branches", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let trace = Trace::new()
        .points(400)
        .scale_coils(4)
        .max_force_scaled(FMAX);
    let scale = (8.0 * std::f64::consts::PI).powi(2);

    // f_z_sym
    let path = dir.join("f_z_sym.svg");
    {
        let root = SVGBackend::new(&path, (720, 540)).into_drawing_area();
        let mut ch = chart(
            &root,
            "primary symmetric branches, n = 1..8 (υ solid, α dashed)",
        )?;
        for n in 1..=8u32 {
            solid(
                &mut ch,
                &trace.run(n, Branch::Upsilon)?,
                palette(n as usize),
            )?;
            dashed(&mut ch, &trace.run(n, Branch::Alpha)?, palette(n as usize))?;
        }
        root.present()?;
    }
    println!("wrote {}", path.display());

    // f_z_nonsym
    let path = dir.join("f_z_nonsym.svg");
    {
        let root = SVGBackend::new(&path, (720, 540)).into_drawing_area();
        let mut ch = chart(
            &root,
            "non-symmetric branches ϑ_j, j = 1..7, bifurcation points n = 1..10",
        )?;
        for j in 1..=7u32 {
            solid(
                &mut ch,
                &trace.run(j, Branch::Theta { j })?,
                palette(j as usize),
            )?;
        }
        let mut pts = Vec::new();
        for n in 1..=10u32 {
            for j in 1..=7u32 {
                if j != n {
                    let b = bifurcation(n, j)?;
                    pts.push((b.extension(), b.force() / scale));
                }
            }
        }
        ch.draw_series(
            pts.into_iter()
                .filter(|p| p.1 <= FMAX)
                .map(|p| Circle::new(p, 3, BLACK.filled())),
        )?;
        root.present()?;
    }
    println!("wrote {}", path.display());

    // f_z_nonsym_n
    let path = dir.join("f_z_nonsym_n.svg");
    {
        let root = SVGBackend::new(&path, (720, 540)).into_drawing_area();
        let mut ch = chart(
            &root,
            "ϑ_j (dashed) and secondary branches (solid), n = 1..10, j = 1..7",
        )?;
        for j in 1..=7u32 {
            dashed(
                &mut ch,
                &trace.run(j, Branch::Theta { j })?,
                palette(j as usize),
            )?;
        }
        let small = trace.points(200);
        for n in 1..=10u32 {
            for j in 1..=7u32 {
                if j == n {
                    continue;
                }
                // a secondary branch whose fold lies above the plot is skipped
                if let Ok(c) = small.secondary(n, j) {
                    solid(&mut ch, &c, palette(j as usize))?;
                }
                let b = bifurcation(n, j)?;
                if b.force() / scale <= FMAX {
                    ch.draw_series(std::iter::once(Circle::new(
                        (b.extension(), b.force() / scale),
                        3,
                        BLACK.filled(),
                    )))?;
                }
            }
        }
        root.present()?;
    }
    println!("wrote {}", path.display());

    // f_z_nonsym_symm_n4
    let path = dir.join("f_z_nonsym_symm_n4.svg");
    {
        let root = SVGBackend::new(&path, (720, 540)).into_drawing_area();
        let mut ch = chart(
            &root,
            "n = 4: primary and secondary symmetric (solid), ϑ_j (dashed), j = 1..7",
        )?;
        solid(&mut ch, &trace.run(4, Branch::Upsilon)?, BLACK)?;
        solid(&mut ch, &trace.run(4, Branch::Alpha)?, BLACK)?;
        for j in 1..=7u32 {
            // the realisable part of ϑ_j for n = 4 starts at its bifurcation point
            if let Ok(c) = trace.run(4, Branch::Theta { j }) {
                dashed(&mut ch, &c, palette(j as usize))?;
            }
            if j != 4 {
                if let Ok(c) = trace.secondary(4, j) {
                    solid(&mut ch, &c, palette(j as usize))?;
                }
                let b = bifurcation(4, j)?;
                if b.force() / scale <= FMAX {
                    ch.draw_series(std::iter::once(Circle::new(
                        (b.extension(), b.force() / scale),
                        4,
                        BLACK.filled(),
                    )))?;
                }
            }
        }
        root.present()?;
    }
    println!("wrote {}", path.display());

    // shapes gallery
    let path = dir.join("elastica_shapes.svg");
    {
        let s1 = Elastica::symmetric(1, 0.9)?;
        let shapes: Vec<(String, Elastica)> = vec![
            ("υ, n = 1, k = 0.9".into(), s1.upsilon),
            ("α, n = 1, k = 0.9".into(), s1.alpha),
            (
                "bifurcation n = 4, j = 3 (υ)".into(),
                bifurcation(4, 3)?.solution(),
            ),
            (
                "bifurcation n = 4, j = 5 (α)".into(),
                bifurcation(4, 5)?.solution(),
            ),
            (
                "ϑ, n = 3, j = 3, k = 0.9".into(),
                Elastica::nonsymmetric(3, 3, 0.9)?[0],
            ),
        ];
        let root = SVGBackend::new(&path, (1200, 300)).into_drawing_area();
        root.fill(&WHITE)?;
        let panels = root.split_evenly((1, shapes.len()));
        for (panel, (title, e)) in panels.iter().zip(shapes.iter()) {
            let pts = e.centreline(801)?;
            // the force acts horizontally: z to the right, x up
            let (mut z0, mut z1, mut x0, mut x1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
            for p in &pts {
                z0 = z0.min(p.y);
                z1 = z1.max(p.y);
                x0 = x0.min(p.x);
                x1 = x1.max(p.x);
            }
            let half = 0.55 * (z1 - z0).max(x1 - x0);
            let (zc, xc) = (0.5 * (z0 + z1), 0.5 * (x0 + x1));
            let mut ch = ChartBuilder::on(panel)
                .caption(title.as_str(), ("sans-serif", 14))
                .margin(8)
                .build_cartesian_2d(zc - half..zc + half, xc - half..xc + half)?;
            ch.draw_series(LineSeries::new(
                pts.iter().map(|p| (p.y, p.x)),
                BLUE.stroke_width(2),
            ))?;
            ch.draw_series(
                [pts[0], pts[pts.len() - 1]]
                    .into_iter()
                    .map(|p| Circle::new((p.y, p.x), 3, RED.filled())),
            )?;
        }
        root.present()?;
    }
    println!("wrote {}", path.display());
    Ok(())
}
