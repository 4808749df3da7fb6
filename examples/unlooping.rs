//! The main job: pull the paper's spring (n = 4, θ0 = 89.8°, A/B = 10,
//! ν = 0.05) from rest to F/((2πn)²B) = 3 and watch it lose its loops.
//!
//! ```text
//! cargo run --release --example unlooping [-- --out DIR] [--tolerance TOL] [--intervals N] [--no-contact]
//!                                         [--spring N,THETA0_DEG,A_OVER_B,NU] [--to F] [--whole] [--help]
//! ```
//!
//! The rod is solved on its half (`RodModel::symmetric`), the paper's
//! symmetric branches; `--whole` solves the whole rod (the same curve).
//!
//! `--spring` pulls another spring (C by the Nikolai equality, as the
//! paper's), `--to` to another F/((2πn)²B).
//!
//! Written on the `spring` scene: the 3D rod answers the spring, the
//! elastica model gives the branches it visits. Prints the stretches that
//! are unstable under force and under extension control and the jumps they
//! cause, and the closest approach of the strip to itself. Writes
//! `unlooping.csv` (one row per continuation point, in order; with
//! `--no-contact` the self-contact check is skipped and its column left
//! empty; columns
//! `extension,force,force_scaled,arclength,loops,stable_force_control,
//! stable_extension_control,closest_approach`) and `unlooping.svg` (the 3D curve,
//! dashed where a dead load cannot hold it, the elastica branches, the folds, the elastica's out-of-plane instability
//! points ("diamonds", `elastica::OutOfPlane`) on the branches drawn) into DIR (default
//! `$CARGO_TARGET_DIR/hockle`, else `target/hockle` under the crate).

use std::error::Error;
use std::fmt::Write as _;
use std::io::Write;
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::time::Instant;

use hockle::continuation::Point;
use hockle::elastica::{Branch, Diamond, OutOfPlane};
use hockle::rod::Pull;
use hockle::spring::{Control, Direction, ElasticaModel, RodModel, Spring, Target};
use hockle::{FoldKind, ForceExtension, Stiffness};

/// The paper's load, F/((2πn)²B) = 3.
const PAPER_FORCE_SCALED: f64 = 3.0;

const USAGE: &str = "\
usage: cargo run --release --example unlooping -- [OPTIONS]
  --spring N,THETA0_DEG,A_OVER_B,NU  the spring (default the paper's: 4,89.8,10,0.05; C by the Nikolai equality)
  --to F                             pull to F/((2πn)²B) = F (default 3)
  --tolerance TOL                    accuracy of the curve and its folds in (Δz, F/((2πn)²B)) (default 1e-6)
  --intervals N                      a fixed mesh of N intervals instead of the adaptive one (on the half: 2N on the rod)
  --no-contact                       skip the self-contact check
  --whole                            solve the whole rod, not its half (Rod::symmetric: the same curve, twice the unknowns)
  --out DIR                          where unlooping.csv and unlooping.svg go (default target/hockle)
  --help                             this text
";

#[path = "support/exit.rs"]
mod exit;

#[path = "support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("unlooping", run())
}

fn run() -> Result<(), Box<dyn Error>> {
    let mut out = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(
            || Path::new(env!("CARGO_MANIFEST_DIR")).join("target"),
            PathBuf::from,
        )
        .join("hockle");
    // (the half: the equilibria symmetric end to end, which the pull
    // follows on the whole rod too, at half the cost)
    let mut model = RodModel::default().symmetric(true);
    let mut tolerance = Pull::DEFAULT_TOLERANCE;
    let mut contact = true;
    let mut scene = Scene::paper();
    let mut max_force_scaled = PAPER_FORCE_SCALED;
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            "--intervals" => {
                let n = args.next().ok_or("--intervals needs N")?;
                model = model.intervals(n.parse().map_err(|e| format!("--intervals {n}: {e}"))?)
            }
            "--tolerance" => {
                let t = args.next().ok_or("--tolerance needs TOL")?;
                tolerance = t.parse().map_err(|e| format!("--tolerance {t}: {e}"))?;
                model = model.tolerance(tolerance);
            }
            "--no-contact" => contact = false,
            "--whole" => model = model.symmetric(false),
            "--spring" => {
                scene = Scene::parse(
                    &args
                        .next()
                        .ok_or("--spring needs N,THETA0_DEG,A_OVER_B,NU")?,
                )?
            }
            "--to" => {
                let f = args.next().ok_or("--to needs F")?;
                max_force_scaled = f.parse().map_err(|e| format!("--to {f}: {e}"))?;
                if !(max_force_scaled > 0.0 && max_force_scaled.is_finite()) {
                    return Err(format!("--to {f}: a positive finite force F/((2πn)²B)").into());
                }
            }
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    std::fs::create_dir_all(&out).map_err(|e| format!("--out {}: {e}", out.display()))?;

    let spring = scene.spring()?;
    let scale = spring.force_scale();
    eprintln!("pulling the {spring} to F/((2πn)²B) = {max_force_scaled}");
    let start = Instant::now();
    let mut count = 0usize;
    let progress = |p: &Point| {
        count += 1;
        if count.is_multiple_of(20) {
            let f = p.parameter() / scale;
            let done = (f / max_force_scaled).clamp(0.0, 1.0);
            eprint!(
                "\r  step {count:5}  F/((2πn)²B) = {f:.4}  [{:<30}] {:.1} s ",
                "#".repeat((30.0 * done) as usize),
                start.elapsed().as_secs_f64()
            );
        }
        ControlFlow::Continue(())
    };
    let target = Target::Force(max_force_scaled);
    let response = if contact {
        model.pull_with_contact(&spring, target, progress)?
    } else {
        model.pull_observed(&spring, target, progress)?
    };
    let elapsed = start.elapsed();
    eprintln!();
    let scaffold = ElasticaModel::default().scaffold(&spring, max_force_scaled)?;
    // the diamonds on the branches of the scaffold: primary υ (j = n) and
    // the secondary υ-branches j < n
    let n = spring.coils();
    let diamonds: Vec<Diamond> = OutOfPlane::new(n, spring.stiffness())?
        .all_diamonds(max_force_scaled)?
        .into_iter()
        .filter(|d| d.branch() != Branch::Alpha)
        .collect();

    println!("{response} in {elapsed:.2?}");
    if let Some(e) = response.estimated_error() {
        println!("estimated error of the curve and its folds in (Δz, F/((2πn)²B)): {e:.1e}");
        if e.is_nan() || e > tolerance {
            println!(
                "  NOT within the tolerance {tolerance:e} (a fixed mesh too coarse, or a run that could not refine)"
            );
        }
    }
    let s = spring.scale();
    println!("pop-outs (maximum-force fold → minimum-force fold):");
    for (i, p) in response.pop_outs().iter().enumerate() {
        println!(
            "  {}: Δz {:.6} → {:.6}, F/((2πn)²B) {:.6} → {:.6}",
            i + 1,
            p.max.point.extension,
            p.min.point.extension,
            p.max.point.force_scaled(s),
            p.min.point.force_scaled(s)
        );
    }
    println!("stretches between pop-outs and the elastica branch nearest to each:");
    for (stretch, near) in response
        .stretches()
        .iter()
        .zip(response.match_branches(&scaffold))
    {
        let loops = stretch.loops.map_or("?".to_string(), |l| l.to_string());
        match near.first() {
            Some(b) => println!(
                "  points {:4}..{:4}: {loops} loops, nearest {} (rms {:.1e}, largest {:.1e})",
                stretch.range.start, stretch.range.end, b.label, b.rms_distance, b.max_distance
            ),
            None => println!(
                "  points {:4}..{:4}: {loops} loops",
                stretch.range.start, stretch.range.end
            ),
        }
    }
    for d in &diamonds {
        let j = match d.branch() {
            Branch::Secondary { j, .. } => j,
            _ => n,
        };
        println!(
            "diamond j={j} extension={:.10} force_scaled={:.10}",
            d.extension(),
            d.force_scaled()
        );
    }
    for control in [Control::Force, Control::Extension] {
        let labels = response.stability(control);
        let mut stretches = Vec::new();
        let mut i = 0;
        while i < labels.len() {
            if labels[i].is_stable() {
                i += 1;
                continue;
            }
            let j = (i..labels.len())
                .find(|&j| labels[j].is_stable())
                .unwrap_or(labels.len());
            let (a, b) = (
                response.curve().points()[i],
                response.curve().points()[j - 1],
            );
            stretches.push(format!(
                "Δz {:.4}..{:.4} (F/((2πn)²B) {:.4}..{:.4})",
                a.extension,
                b.extension,
                a.force_scaled(s),
                b.force_scaled(s)
            ));
            i = j;
        }
        println!("unstable under {control}: {}", stretches.join(", "));
        for jump in response.jumps(control) {
            let dir = match jump.direction {
                Direction::Loading => "loading",
                Direction::Unloading => "unloading",
            };
            println!(
                "  {dir} jump: Δz {:.4} → {:.4}, F/((2πn)²B) {:.4} → {:.4}",
                jump.from.extension,
                jump.to.extension,
                jump.from.force_scaled(s),
                jump.to.force_scaled(s)
            );
        }
    }
    if let Some((i, d)) = response
        .closest_approach()
        .iter()
        .enumerate()
        .filter_map(|(i, d)| d.map(|d| (i, d)))
        .min_by(|a, b| a.1.total_cmp(&b.1))
    {
        let p = response.curve().points()[i];
        println!(
            "closest approach of the strip to itself: {d:.3e} (rod lengths) at Δz = {:.4}, F/((2πn)²B) = {:.4}",
            p.extension,
            p.force_scaled(s)
        );
    }
    match response.loops_lost() {
        Some(l) => println!("loops lost: {l}"),
        None => println!("loops lost: not defined (a stretch without a loop count)"),
    }

    let csv = out.join("unlooping.csv");
    let svg = out.join("unlooping.svg");
    write_csv(&response, &csv).map_err(|e| format!("{}: {e}", csv.display()))?;
    let figure = Figure {
        title: scene.to_string(),
        max_force_scaled,
    };
    std::fs::write(&svg, plot(&figure, &response, &scaffold, &diamonds))
        .map_err(|e| format!("{}: {e}", svg.display()))?;
    println!("wrote {} and {}", csv.display(), svg.display());
    Ok(())
}

fn write_csv(response: &hockle::spring::Response, path: &Path) -> std::io::Result<()> {
    let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(
        f,
        "extension,force,force_scaled,arclength,loops,stable_force_control,stable_extension_control,closest_approach"
    )?;
    let scale = response.curve().scale();
    let force = response.stability(Control::Force);
    let hard = response.stability(Control::Extension);
    for (i, (p, l)) in response
        .curve()
        .points()
        .iter()
        .zip(response.loops())
        .enumerate()
    {
        let loops = l.map(|l| l.to_string()).unwrap_or_default();
        let closest = response.closest_approach()[i]
            .map(|d| format!("{d:e}"))
            .unwrap_or_default();
        writeln!(
            f,
            "{:e},{:e},{:e},{:e},{loops},{},{},{closest}",
            p.extension,
            p.force,
            p.force_scaled(scale),
            p.parameter,
            force[i].is_stable(),
            hard[i].is_stable()
        )?;
    }
    f.flush()
}

/// The Okabe–Ito palette: distinct for colour-blind readers, legible on white.
const PALETTE: [&str; 4] = ["#0072B2", "#009E73", "#CC79A7", "#E69F00"];

/// The figure as SVG, written directly so that every coordinate keeps three
/// decimals of a pixel (no staircase on the steep stretches).
/// The spring pulled: n, θ0 (degrees), A/B and ν, C by the Nikolai equality.
struct Scene {
    coils: u32,
    theta0_deg: f64,
    a_over_b: f64,
    nu: f64,
}

impl Scene {
    fn paper() -> Self {
        Self {
            coils: 4,
            theta0_deg: 89.8,
            a_over_b: 10.0,
            nu: 0.05,
        }
    }

    /// `N,THETA0_DEG,A_OVER_B,NU`; the values are checked by [`Scene::spring`].
    fn parse(text: &str) -> Result<Self, String> {
        let fields: Vec<&str> = text.split(',').collect();
        let [n, theta0, a_over_b, nu] = fields[..] else {
            return Err(format!(
                "--spring {text}: four values N,THETA0_DEG,A_OVER_B,NU"
            ));
        };
        let number = |what: &str, v: &str| -> Result<f64, String> {
            v.trim()
                .parse()
                .map_err(|e| format!("--spring {text}: {what} {v}: {e}"))
        };
        Ok(Self {
            coils: n
                .trim()
                .parse()
                .map_err(|e| format!("--spring {text}: N {n}: {e}"))?,
            theta0_deg: number("THETA0_DEG", theta0)?,
            a_over_b: number("A_OVER_B", a_over_b)?,
            nu: number("NU", nu)?,
        })
    }

    /// The spring, or why not (the error names `--spring`).
    fn spring(&self) -> Result<Spring, String> {
        Stiffness::nikolai(self.a_over_b, self.nu)
            .and_then(|s| Spring::from_degrees(self.coils, self.theta0_deg, s))
            .map_err(|e| format!("--spring {self}: {e}"))
    }
}

impl std::fmt::Display for Scene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "n = {}, θ0 = {}°, A/B = {}, ν = {}",
            self.coils, self.theta0_deg, self.a_over_b, self.nu
        )
    }
}

/// The figure's title and force range.
struct Figure {
    title: String,
    max_force_scaled: f64,
}

/// The figure as SVG, written directly so that every coordinate keeps three
/// decimals of a pixel (no staircase on the steep stretches).
fn plot(
    figure: &Figure,
    response: &hockle::spring::Response,
    scaffold: &[ForceExtension],
    diamonds: &[Diamond],
) -> String {
    let max_force = figure.max_force_scaled;
    let (w, h) = (900.0, 640.0);
    let (left, right, top, bottom) = (70.0, 20.0, 50.0, 90.0);
    let (pw, ph) = (w - left - right, h - top - bottom);
    let x = |dz: f64| left + dz * pw;
    let y = |f: f64| top + (1.0 - f / max_force) * ph;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="sans-serif">"#
    );
    let _ = writeln!(s, r#"<rect width="{w}" height="{h}" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="28" font-size="20" text-anchor="middle">Cascade unlooping: {}</text>"#,
        w / 2.0,
        figure.title
    );
    for i in 0..=10 {
        let t = f64::from(i) / 10.0;
        let f = t * max_force;
        let _ = writeln!(
            s,
            r##"<line x1="{:.3}" y1="{top}" x2="{:.3}" y2="{:.3}" stroke="#e6e6e6"/><text x="{:.3}" y="{:.3}" font-size="12" text-anchor="middle">{t:.1}</text>"##,
            x(t),
            x(t),
            top + ph,
            x(t),
            top + ph + 16.0
        );
        let _ = writeln!(
            s,
            r##"<line x1="{left}" y1="{:.3}" x2="{:.3}" y2="{:.3}" stroke="#e6e6e6"/><text x="{:.3}" y="{:.3}" font-size="12" text-anchor="end">{f:.1}</text>"##,
            y(f),
            left + pw,
            y(f),
            left - 6.0,
            y(f) + 4.0
        );
    }
    let _ = writeln!(
        s,
        r#"<rect x="{left}" y="{top}" width="{pw}" height="{ph}" fill="none" stroke="black"/>"#
    );
    let _ = writeln!(
        s,
        r#"<text x="{:.3}" y="{:.3}" font-size="14" text-anchor="middle">extension Δz</text>"#,
        left + pw / 2.0,
        top + ph + 36.0
    );
    let _ = writeln!(
        s,
        r#"<text transform="translate(18 {:.3}) rotate(-90)" font-size="14" text-anchor="middle">force F/((2πn)²B)</text>"#,
        top + ph / 2.0
    );
    let _ = writeln!(
        s,
        r##"<text x="{left}" y="{:.3}" font-size="11" fill="#444">F is the physical tension F = dU/dΔz: half the force of the paper's Section 3 formulas.</text>"##,
        h - 14.0
    );
    let polyline = |pts: &mut dyn Iterator<Item = (f64, f64)>, colour: &str, width: f64| {
        let mut d = String::new();
        for (dz, f) in pts.filter(|p| p.1 <= max_force && p.1 >= 0.0) {
            let _ = write!(d, "{:.3},{:.3} ", x(dz), y(f));
        }
        format!(
            r#"<polyline points="{d}" fill="none" stroke="{colour}" stroke-width="{width}" stroke-linejoin="round"/>"#
        )
    };
    let mut legend = Vec::new();
    for (i, c) in scaffold.iter().enumerate() {
        let colour = PALETTE[i % PALETTE.len()];
        let scale = c.scale();
        s += &polyline(
            &mut c
                .points()
                .iter()
                .map(|p| (p.extension, p.force_scaled(scale))),
            colour,
            1.5,
        );
        s.push('\n');
        legend.push((format!("elastica: {}", c.label()), colour, "line"));
    }
    let scale = response.curve().scale();
    // The rod's curve: solid where a dead load can hold it, dashed where it
    // is unstable under force control (each run shares its end points with
    // the next, so the pieces join).
    let labels = response.stability(Control::Force);
    let pts = response.curve().points();
    let mut from = 0;
    while from + 1 < pts.len() {
        let stable = labels[from + 1].is_stable();
        let mut to = from + 1;
        while to + 1 < pts.len() && labels[to + 1].is_stable() == stable {
            to += 1;
        }
        let piece = polyline(
            &mut pts[from..=to.min(pts.len() - 1)]
                .iter()
                .map(|p| (p.extension, p.force_scaled(scale))),
            "black",
            2.5,
        );
        s += &if stable {
            piece
        } else {
            piece.replace("/>", r#" stroke-dasharray="6 4"/>"#)
        };
        s.push('\n');
        from = to;
    }
    legend.push(("3D rod (this run), stable".to_string(), "black", "line"));
    legend.push((
        "3D rod, unstable under dead load".to_string(),
        "black",
        "dashed",
    ));
    for f in response.folds() {
        let colour = match f.kind {
            FoldKind::MaxForce => "#D55E00",
            FoldKind::MinForce => "#56B4E9",
            FoldKind::MaxExtension | FoldKind::MinExtension => continue,
        };
        let _ = writeln!(
            s,
            r#"<circle cx="{:.3}" cy="{:.3}" r="5" fill="{colour}" stroke="black" stroke-width="0.8"/>"#,
            x(f.point.extension),
            y(f.point.force_scaled(scale))
        );
    }
    for d in diamonds {
        let (cx, cy) = (x(d.extension()), y(d.force_scaled()));
        let _ = writeln!(
            s,
            r#"<polygon points="{:.3},{cy:.3} {cx:.3},{:.3} {:.3},{cy:.3} {cx:.3},{:.3}" fill="white" stroke="black" stroke-width="1.2"/>"#,
            cx - 6.0,
            cy - 6.0,
            cx + 6.0,
            cy + 6.0
        );
    }
    legend.push(("maximum-force fold".to_string(), "#D55E00", "dot"));
    legend.push(("minimum-force fold".to_string(), "#56B4E9", "dot"));
    legend.push((
        "elastica out-of-plane instability (diamond)".to_string(),
        "white",
        "diamond",
    ));
    let (lx, ly) = (left + 12.0, top + 12.0);
    let _ = writeln!(
        s,
        r#"<rect x="{lx}" y="{ly}" width="330" height="{}" fill="white" fill-opacity="0.9" stroke="black"/>"#,
        18.0 * legend.len() as f64 + 8.0
    );
    for (i, (label, colour, kind)) in legend.iter().enumerate() {
        let yy = ly + 16.0 + 18.0 * i as f64;
        if *kind == "line" || *kind == "dashed" {
            let dash = if *kind == "dashed" {
                r#" stroke-dasharray="6 4""#
            } else {
                ""
            };
            let _ = write!(
                s,
                r#"<line x1="{}" y1="{yy}" x2="{}" y2="{yy}" stroke="{colour}" stroke-width="2.5"{dash}/>"#,
                lx + 8.0,
                lx + 32.0
            );
        } else if *kind == "diamond" {
            let cx = lx + 20.0;
            let _ = write!(
                s,
                r#"<polygon points="{:.3},{yy} {cx},{:.3} {:.3},{yy} {cx},{:.3}" fill="{colour}" stroke="black" stroke-width="1.2"/>"#,
                cx - 6.0,
                yy - 6.0,
                cx + 6.0,
                yy + 6.0
            );
        } else {
            let _ = write!(
                s,
                r#"<circle cx="{}" cy="{yy}" r="5" fill="{colour}" stroke="black" stroke-width="0.8"/>"#,
                lx + 20.0
            );
        }
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}" font-size="12">{label}</text>"#,
            lx + 40.0,
            yy + 4.0
        );
    }
    s += "</svg>\n";
    s
}
