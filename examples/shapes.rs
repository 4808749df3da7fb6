//! The paper's Fig. shapes: centrelines along the pulled spring's curve
//! (n = 4, θ0 = 89.8°, A/B = 10, ν = 0.05), each seen in the plane through
//! the force axis that fits it best (top row) and edge-on to that plane
//! (bottom row), the force axis vertical.
//!
//! ```text
//! cargo run --release --example shapes [-- --out DIR]
//! ```
//!
//! Writes `shapes.svg` into DIR (default `$CARGO_TARGET_DIR/hockle`, else `target/hockle` under the crate).

use std::error::Error;
use std::ops::ControlFlow;
use std::path::PathBuf;

use hockle::continuation::{Point, PointKind};
use hockle::nalgebra::{Matrix2, SymmetricEigen, Vector2, Vector3};
use hockle::rod::{Equilibrium, Pull, Rod};
use hockle::{Stiffness, Target};
use plotters::prelude::*;

/// Collects the shapes: a few points on the way up, and every fold.
struct Collect {
    rod: Rod,
    marks: Vec<f64>,
    shapes: Vec<(String, Equilibrium)>,
    last_dl: f64,
}

impl Collect {
    fn point(&mut self, p: &Point) -> ControlFlow<()> {
        let e = Equilibrium::new(self.rod, p.solution().clone()).expect("a rod solution");
        if p.kind() == PointKind::Fold {
            let what = if self.last_dl > 0.0 { "max" } else { "min" };
            self.shapes.push((
                format!("{what} fold, F/((2πn)²B) = {:.3}", e.force_scaled()),
                e,
            ));
            return ControlFlow::Continue(());
        }
        self.last_dl = p.dparameter_ds();
        if let Some(&m) = self.marks.first()
            && e.force_scaled() >= m
        {
            self.marks.remove(0);
            self.shapes
                .push((format!("F/((2πn)²B) = {:.3}", e.force_scaled()), e));
        }
        ControlFlow::Continue(())
    }
}

const USAGE: &str = "\
usage: cargo run --release --example shapes -- [OPTIONS]
  --out DIR      where shapes.svg goes (default target/hockle)
  --help         this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("shapes", run())
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
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    std::fs::create_dir_all(&out)?;
    let rod = Rod::new(4, 89.8_f64.to_radians(), Stiffness::nikolai(10.0, 0.05)?)?;
    let mut collect = Collect {
        rod,
        marks: vec![0.0, 0.006, 0.3, 1.99],
        shapes: Vec::new(),
        last_dl: 0.0,
    };
    let run = Pull::new(rod, Target::Force(2.0)).run(|p: &Point| collect.point(p))?;
    println!("{run}");
    let mut shapes = collect.shapes;
    // Order along the curve: the marks come first on the way up, the folds
    // in order; the last point closes the series.
    shapes.sort_by(|a, b| {
        let ia = run
            .curve()
            .points()
            .iter()
            .position(|p| p.extension >= a.1.extension())
            .unwrap_or(0);
        let ib = run
            .curve()
            .points()
            .iter()
            .position(|p| p.extension >= b.1.extension())
            .unwrap_or(0);
        ia.cmp(&ib)
    });

    let path = out.join("shapes.svg");
    let cols = shapes.len();
    let root = SVGBackend::new(&path, (170 * cols as u32, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let rows = root.split_evenly((2, cols));
    for (i, (label, e)) in shapes.iter().enumerate() {
        let pts = e.centreline_samples(600)?;
        // The best plane through the z-axis: normal = smallest-moment
        // direction of (x, y).
        let mut m = Matrix2::zeros();
        for p in &pts {
            let v = Vector2::new(p.x, p.y);
            m += v * v.transpose();
        }
        let eig = SymmetricEigen::new(m);
        let imin = if eig.eigenvalues[0] <= eig.eigenvalues[1] {
            0
        } else {
            1
        };
        let nrm = eig.eigenvectors.column(imin).into_owned();
        let inplane = Vector3::new(-nrm.y, nrm.x, 0.0);
        let normal = Vector3::new(nrm.x, nrm.y, 0.0);
        let zmax = pts.iter().map(|p| p.z).fold(0.0_f64, f64::max);
        let hmax = pts
            .iter()
            .map(|p| p.dot(&inplane).abs().max(p.dot(&normal).abs()))
            .fold(0.0_f64, f64::max);
        // Equal scales on both axes in a 170 × 280 panel.
        let height = 1.15 * zmax.max(2.2 * hmax);
        let half = 0.5 * height * 170.0 / 280.0;
        let z0 = 0.5 * (zmax - height);
        for (row, axis, title) in [(0, inplane, label.as_str()), (1, normal, "edge-on")] {
            let area = &rows[row * cols + i];
            let mut chart = ChartBuilder::on(area)
                .caption(title, ("sans-serif", 11))
                .margin(6)
                .build_cartesian_2d(-half..half, z0..z0 + height)?;
            chart.draw_series(LineSeries::new(
                pts.iter().map(|p| (p.dot(&axis), p.z)),
                BLACK.stroke_width(1),
            ))?;
            chart.draw_series(LineSeries::new(
                [(0.0, z0), (0.0, z0 + height)],
                RED.mix(0.3),
            ))?;
        }
    }
    root.present()?;
    println!("wrote {} ({} shapes)", path.display(), cols);
    Ok(())
}
