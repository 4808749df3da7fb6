//! The paper's parameter sweeps, Figs. th0, aniso and helix: the 3D rod
//! (solid) for several helix angles and anisotropies, against the
//! exact-helix model (dashed) where the paper draws it.
//!
//! ```sh
//! cargo run --release --example sweeps [-- --out DIR]
//! ```
//!
//! Writes `sweep_theta0.svg`, `sweep_anisotropy.svg` and `sweep_helix.svg`
//! (default `$CARGO_TARGET_DIR/hockle`, else `target/hockle` under the crate) and prints, for every spring, its
//! pop-outs and the run time.

use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;

use hockle::Stiffness;
use hockle::spring::{HelixModel, Model, Response, RodModel, Spring};
use plotters::prelude::*;

const MAX_FORCE_SCALED: f64 = 3.0;

/// One curve of a figure: a label, the rod's response and, where the paper
/// draws it, the helix model's.
struct Curve {
    label: String,
    rod: Response,
    helix: Option<Response>,
}

fn pull(theta0_degrees: f64, a_over_b: f64, with_helix: bool) -> Result<Curve, Box<dyn Error>> {
    let spring = Spring::from_degrees(4, theta0_degrees, Stiffness::nikolai(a_over_b, 0.05)?)?;
    let start = Instant::now();
    let rod = RodModel::default().pull(&spring, MAX_FORCE_SCALED)?;
    let label = format!("θ0 = {theta0_degrees}°, A/B = {a_over_b}");
    println!(
        "{label:<26} {} pop-outs, {} points, {:>6.0} ms{}",
        rod.pop_outs().len(),
        rod.curve().len(),
        start.elapsed().as_secs_f64() * 1e3,
        if rod.reached_target() {
            String::new()
        } else {
            format!(" (stopped: {})", rod.termination())
        }
    );
    let helix = if with_helix {
        Some(HelixModel::new(400)?.pull(&spring, MAX_FORCE_SCALED)?)
    } else {
        None
    };
    Ok(Curve { label, rod, helix })
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

fn main() -> Result<(), Box<dyn Error>> {
    let mut out = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(
            || std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
            PathBuf::from,
        )
        .join("hockle");
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            other => {
                return Err(format!("unknown argument {other}; usage: sweeps [--out DIR]").into());
            }
        }
    }
    std::fs::create_dir_all(&out)?;

    let theta0: Vec<Curve> = [89.8, 89.5, 89.0, 88.0]
        .into_iter()
        .map(|t| pull(t, 10.0, false))
        .collect::<Result<_, _>>()?;
    plot(
        "Fig. th0: helix angles (n = 4, A/B = 10, ν = 0.05)",
        &theta0,
        &out.join("sweep_theta0.svg"),
    )?;

    let aniso: Vec<Curve> = [
        (10.0, false),
        (8.0, false),
        (6.0, false),
        (4.0, false),
        (1.0, true),
        (0.1, true),
    ]
    .into_iter()
    .map(|(a, h)| pull(89.8, a, h))
    .collect::<Result<_, _>>()?;
    plot(
        "Fig. aniso: anisotropies (n = 4, θ0 = 89.8°, ν = 0.05)",
        &aniso,
        &out.join("sweep_anisotropy.svg"),
    )?;

    let helix: Vec<Curve> = [88.0, 60.0]
        .into_iter()
        .map(|t| pull(t, 10.0, true))
        .collect::<Result<_, _>>()?;
    plot(
        "Fig. helix: the rod against the exact helix (n = 4, A/B = 10)",
        &helix,
        &out.join("sweep_helix.svg"),
    )?;
    Ok(())
}
