//! The main job: pull the paper's spring (n = 4, θ0 = 89.8°, A/B = 10,
//! ν = 0.05) from rest to F/(2πn)² = 3 and watch it lose its loops.
//!
//! ```text
//! cargo run --release --example unlooping [-- --out DIR] [--intervals N]
//! ```
//!
//! Writes `unlooping.csv` (one row per continuation point, in order) and
//! `unlooping.svg` (the 3D curve, the elastica branches it visits, the folds)
//! into DIR (default `target/hockle/`).

use std::error::Error;
use std::io::Write;
use std::ops::ControlFlow;
use std::path::PathBuf;
use std::time::Instant;

use hockle::ForceExtension;
use hockle::elastica::{Branch, Trace};
use hockle::rod::{Equilibrium, FoldKind, Pull, PullPoint, PullRun, Rod};
use plotters::prelude::*;

const N: u32 = 4;
const MAX_FORCE_SCALED: f64 = 3.0;

fn main() -> Result<(), Box<dyn Error>> {
    let mut out = PathBuf::from("target/hockle");
    let mut intervals = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            "--intervals" => intervals = Some(args.next().ok_or("--intervals needs N")?.parse()?),
            other => return Err(format!("unknown argument {other}").into()),
        }
    }
    std::fs::create_dir_all(&out)?;

    let rod = Rod::nikolai(N, 89.8_f64.to_radians(), 10.0, 0.05)?;
    eprintln!("pulling {rod} to F/(2πn)² = {MAX_FORCE_SCALED}");
    let mut pull = Pull::new(rod).to_force_scaled(MAX_FORCE_SCALED);
    if let Some(n) = intervals {
        pull = pull.intervals(n);
    }
    let start = Instant::now();
    let mut count = 0usize;
    let run = pull.run(|_: &Equilibrium, p: &PullPoint| {
        count += 1;
        if count % 20 == 0 {
            let done = (p.force_scaled / MAX_FORCE_SCALED).clamp(0.0, 1.0);
            eprint!(
                "\r  step {count:5}  Δz = {:.4}  F/(2πn)² = {:.4}  loops {}  [{:<30}] {:.1} s ",
                p.extension,
                p.force_scaled,
                p.loops,
                "#".repeat((30.0 * done) as usize),
                start.elapsed().as_secs_f64()
            );
        }
        ControlFlow::Continue(())
    });
    eprintln!();

    // The elastica branches the curve visits: the primary υ-branch and the
    // secondary υ-branches j = 3, 2, 1 (hockle::elastica).
    let trace = Trace::new().points(400).max_force_scaled(MAX_FORCE_SCALED);
    let mut branches = vec![(4, trace.run(N, Branch::Upsilon)?)];
    for j in (1..N).rev() {
        branches.push((j, trace.secondary(N, j)?));
    }

    summary(&run, &branches);
    write_csv(&run, &out.join("unlooping.csv"))?;
    plot(&run, &branches, &out.join("unlooping.svg"))?;
    println!(
        "wrote {} and {}",
        out.join("unlooping.csv").display(),
        out.join("unlooping.svg").display()
    );
    Ok(())
}

/// Distance in the plot's plane (Δz, F/(2πn)²) from a point to a polyline.
fn distance(curve: &ForceExtension, x: f64, y: f64) -> f64 {
    let scale = curve.force_scale();
    let pts: Vec<(f64, f64)> = curve
        .points()
        .iter()
        .map(|p| (p.extension, p.force / scale))
        .collect();
    pts.windows(2)
        .map(|w| {
            let ((x0, y0), (x1, y1)) = (w[0], w[1]);
            let (dx, dy) = (x1 - x0, y1 - y0);
            let l2 = dx * dx + dy * dy;
            let t = if l2 > 0.0 {
                (((x - x0) * dx + (y - y0) * dy) / l2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            ((x0 + t * dx - x).powi(2) + (y0 + t * dy - y).powi(2)).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

fn summary(run: &PullRun, branches: &[(u32, ForceExtension)]) {
    println!("{run}");
    println!("pop-outs (maximum-force fold → minimum-force fold):");
    for (i, (a, b)) in run.pop_outs().iter().enumerate() {
        println!(
            "  {}: Δz {:.6} → {:.6}, F/(2πn)² {:.6} → {:.6}",
            i + 1,
            a.point.extension,
            b.point.extension,
            a.point.force_scaled(N),
            b.point.force_scaled(N)
        );
    }
    println!("stretches and the elastica branch nearest to their near-planar part:");
    for (i, s) in run.stretches().into_iter().enumerate() {
        // Stretches that start at a maximum-force fold are the 3D excursions.
        if i % 2 == 1 {
            println!(
                "  points {:4}..={:4}: 3D excursion (pop-out), planarity ≥ {:.1e}",
                s.first, s.last, s.planarity
            );
            continue;
        }
        // The near-planar part: points within 3× the stretch's best planarity.
        let pts: Vec<&PullPoint> = run.points[s.first..=s.last]
            .iter()
            .filter(|p| p.planarity <= (3.0 * s.planarity).max(1e-3) && p.force_scaled > 0.05)
            .collect();
        let best = branches
            .iter()
            .map(|(j, c)| {
                let d = pts
                    .iter()
                    .map(|p| distance(c, p.extension, p.force_scaled))
                    .fold(0.0, f64::max);
                (*j, d)
            })
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match best {
            Some((j, d)) if !pts.is_empty() => println!(
                "  points {:4}..={:4}: {} loops, nearest branch j = {j} (largest distance {d:.2e} over {} near-planar points)",
                s.first,
                s.last,
                s.loops,
                pts.len()
            ),
            _ => println!(
                "  points {:4}..={:4}: {} loops (no near-planar point)",
                s.first, s.last, s.loops
            ),
        }
    }
    println!(
        "loops lost: {}, steps: {} ({} rejected), Newton iterations: {}, mesh: {} intervals, run time {:.2?}",
        run.loops_lost(),
        run.steps,
        run.rejected,
        run.newton_iterations,
        run.intervals,
        run.elapsed
    );
}

fn write_csv(run: &PullRun, path: &std::path::Path) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(f, "extension,force,force_scaled,arclength,loops,planarity")?;
    for p in &run.points {
        writeln!(
            f,
            "{:e},{:e},{:e},{:e},{},{:e}",
            p.extension, p.force, p.force_scaled, p.arclength, p.loops, p.planarity
        )?;
    }
    f.flush()
}

fn plot(
    run: &PullRun,
    branches: &[(u32, ForceExtension)],
    path: &std::path::Path,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (900, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Cascade unlooping: n = 4, θ0 = 89.8°, A/B = 10, ν = 0.05",
            ("sans-serif", 22),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..1.0, 0.0..MAX_FORCE_SCALED)?;
    chart
        .configure_mesh()
        .x_desc("extension Δz")
        .y_desc("force F/(2πn)²B")
        .draw()?;
    let colours = [BLUE, GREEN, MAGENTA, CYAN];
    for (i, (j, c)) in branches.iter().enumerate() {
        let scale = c.force_scale();
        let colour = colours[i % colours.len()];
        chart
            .draw_series(LineSeries::new(
                c.points()
                    .iter()
                    .map(|p| (p.extension, p.force / scale))
                    .filter(|p| p.1 <= MAX_FORCE_SCALED),
                colour.stroke_width(1),
            ))?
            .label(if *j == N {
                "primary υ elastica (j = 4)".to_string()
            } else {
                format!("secondary υ elastica j = {j}")
            })
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
    }
    chart
        .draw_series(LineSeries::new(
            run.points.iter().map(|p| (p.extension, p.force_scaled)),
            BLACK.stroke_width(3),
        ))?
        .label("3D rod (this run)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(3)));
    chart
        .draw_series(run.folds.iter().map(|f| {
            let colour = if f.kind == FoldKind::MaxForce {
                RED
            } else {
                BLACK
            };
            Circle::new(
                (f.point.extension, f.point.force_scaled(N)),
                5,
                colour.filled(),
            )
        }))?
        .label("folds (red: maximum force, black: minimum)")
        .legend(|(x, y)| Circle::new((x + 10, y), 4, RED.filled()));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
