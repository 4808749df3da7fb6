//! Where the cascade exists: the number of pop-outs of a spring over
//! (θ0, A/B) at ν = 0.05 and over (θ0, ν) at A/B = 10, bounded by the cusp
//! curves of its pop-outs, traced by continuation (`rod::cascade`).
//!
//! ```sh
//! cargo run --release --example phase_diagram [-- --coils N] [--out DIR] [--compute]
//! cargo run --release --example phase_diagram -- --coils 8 --extend docs/data/phase_diagram_n8.csv
//! cargo run --release --example phase_diagram -- --check   # convergence, docs/ACCURACY.md
//! cargo run --release --example phase_diagram -- --scene 89.8,10,0.05 [--scene …] [--pull F] [--stretch DZ] [--forces]
//! cargo run --release --example phase_diagram -- --coils 5 --scene 89,10,0.05 --fold-cusps
//! ```
//!
//! Without `--compute`, n = 4 is read from the committed diagram
//! `docs/data/phase_diagram_n4.csv` (what `--compute` writes), other n from
//! `docs/data/phase_diagram_n<N>.csv` where committed (n = 2, 3, 5, 6, 7, 8), else
//! computed. `--compute` pulls the paper's spring at θ0 = 89.8°, A/B = 10,
//! ν = 0.05 (n coils), continues each pop-out's two folds down in θ0 to
//! where it vanishes (the lower of their first cusps: where they differ,
//! the folds change partners on the way), and from there traces the curve
//! of cusps in A/B (at
//! ν = 0.05 and at the other ν of the reading grid, reached along A/B =
//! 100) and in ν (at A/B = 10): `phase_diagram_n<N>.csv` and `.svg` in the
//! output folder (default `$CARGO_TARGET_DIR/hockle`, else `target/hockle`).
//! Where a spring loses fewer loops by a fold at the reference than it can
//! (n = 8: 3 of 7), the other pop-outs are seeded from a scene where they
//! exist (`SEEDS`: n = 8 at θ0 = 89.5°, A/B = 50): their cusps in θ0 at that
//! A/B start the same lines. While the diagram still maps fewer than n − 1,
//! the first of the check scenes at ν = 0.05 (`CHECK_SCENES`) where a pull
//! to F/((2πn)²B) = 3 sees more pop-outs than it counts is a seed too
//! (n = 7: 5 of 6 at the reference, the sixth seeded at (89°, 20)).
//! `--extend FILE` takes the lines of a diagram computed before (the
//! committed n = 8 file of the reference pop-outs) instead of recomputing
//! them, and adds the seeded pop-outs' lines.
//!
//! `--pull F` pulls each `--scene` too (the adaptive default rod, from rest
//! to F/((2πn)²B) = F) and prints, after its line, one line
//! `pulled pop_outs=<count> to=<F> reached=<bool> max_forces=<f1;f2;…>
//! steps=<accepted> rejected=<count> tolerance=<tol> relaxed_to=<tol>
//! estimate=<error>` with each pop-out's maximum force, the continuation's
//! steps, the loosest tolerance it went on at (its own where it did not)
//! and the curve's estimated error: a cross-check of the diagram, which
//! counts the pop-outs that exist at any force (docs/ACCURACY.md: at
//! negative ν the maximum-force folds rise far above the reference's).
//! `--symmetric` solves every pull's and stretch's rod on its half
//! (`Rod::symmetric`: the equilibria symmetric end to end, without the
//! antisymmetric modes along which loops slide).
//!
//! `--stretch DZ` stretches each `--scene` from rest under extension
//! control to Δz = DZ instead (at most 2000 steps) and prints
//! `stretched pop_outs=<count> to=<DZ> reached=<bool> past_pop_outs=<bool>
//! end_force=<F> max_forces=<…> steps=<accepted> rejected=<count>
//! tolerance=<tol> relaxed_to=<tol> estimate=<error>` (a stretch that stops
//! short is run again at 1e-5, then 1e-4, and the first that reaches Δz
//! kept; where none does, last, the default goes on from its failure up to
//! 1e-4, `Pull::relax_to`): along
//! the same path, a stretch passes the pop-outs' maximum forces however
//! high; at Δz = 0.99 a rod past its
//! pop-outs pulls with F/((2πn)²B) of 1.0–2.6 (n = 8 to 2), one that still holds a loop
//! with forces of order 10² (`past_pop_outs`: it ends below its last
//! maximum force).
//!
//! `--forces` carries the reference pull's pop-outs (their two folds each,
//! [`hockle::rod::CuspSearch::carry`]: along a staircase about the straight
//! line in (θ0, ln A/B, ν), four rounds of a leg in each) to each
//! `--scene`, checks each fold there against its mesh
//! ([`hockle::rod::CuspSearch::mesh_checked`]: every interval halved until
//! its force moves by at most 1e-6, at most three times) and prints, after
//! the scene's line, one line per pop-out,
//! `carried pop_out=<i> max=<F> min=<F> change=<ΔF>` (F/((2πn)²B) of its
//! maximum- and minimum-force folds there: the hysteresis loop; ΔF the
//! larger of the two folds' moves in their last halving, above 1e-6 where
//! three halvings did not get there, `inf` where the fold was not found on
//! the halved mesh: the forces printed are then the 48 intervals'), or
//! `vanished` with the
//! parameter and value of the cusp where its folds met on the way, or
//! `ended` with the reason: the forces that the diagram's count does not
//! give, without pulling the scene to them.
//!
//! `--force-map` maps the reference pop-outs' maximum and minimum forces
//! over a grid of (θ0, ν) at A/B = 10 (`force_map.rs`): one line per grid
//! point and pop-out, `force_map theta0=<deg> nu=<x> pop_out=<i> max=<F>
//! min=<F> change=<ΔF>` (`-` where the fold is reached neither along the
//! grid's lines nor by a carry of its own; every fold reached checked
//! against its mesh as `--forces` does, ΔF as there), and a Markdown table
//! per pop-out on standard error. `--force-map-a-over-b` does the same over
//! (θ0, A/B) at ν = 0.05, A/B ∈ {2, 3, 5, 10, 20, 50, 100}, its lines with
//! `a_over_b=<x>` in place of `nu=<x>`.
//!
//! `--cross-check` pulls a coarse grid over both planes (θ0 86–89.8°, A/B
//! 1–100 at ν = 0.05, ν −0.2–0.3 at A/B = 10) to F/((2πn)²B) = 3 and
//! prints the diagram's count beside each pull's (`cross_check.rs`): the
//! full-grid cross-check, which fails where a pull sees more. Where a pull
//! sees fewer, the reference's pop-outs are carried to the scene and a
//! line `beyond … carried_max=<F;…> vanished=<k> accounted=<yes|partly|no>`
//! says whether those that peak above the pull's force make up the
//! difference (the carried forces checked against their mesh as
//! `--forces` does), and a line `stretch … stretched=<count>
//! reached=<bool> past_pop_outs=<bool> …` gives the count of the scene
//! stretched to Δz = 0.99 (as `--stretch`). `--random` stretches its scenes with fewer the same way.
//!
//! `--random K [--seed S] [--pull F]` pulls K random scenes about the
//! reference (θ0 84–89.95°, A/B 0.5–100, ν −0.3–0.45; xorshift from S,
//! default 4242) to F/((2πn)²B) = F (default 3) and prints the diagram's
//! count beside each pull's (`random_check.rs`); an error if a pull away
//! from the lines sees more.
//!
//! `--fold-cusps` (with `--scene`, any n, no diagram read) pulls each scene
//! on the lines' 24 intervals and follows each pop-out's two folds in θ0
//! both ways to their first cusp (`fold_cusps.rs`): the cusps a reading
//! crosses, and whether a fold pair is born or lost across each.
//!
//! `--scene THETA0_DEG,A_OVER_B,NU` (repeatable) prints one line per scene,
//! `scene theta0=<deg> a_over_b=<x> nu=<x> pop_outs=<count>`, read off the
//! diagram ([`hockle::rod::PhaseDiagram::pop_outs`]), not from a pull;
//! `pop_outs=unknown` where the diagram does not resolve the scene
//! (`hockle::Error::NotMapped`), `pop_outs=at_least_<count>` from a diagram
//! that maps fewer pop-outs than the spring has loops but one
//! ([`hockle::rod::PhaseDiagram::is_complete`]: n = 8). A diagram computed
//! here (no committed one for n) is first checked against pulls to
//! F/((2πn)²B) = 3 at 14 scenes about the reference (`CHECK_SCENES`);
//! where a pull sees more pop-outs than a complete diagram counts, every
//! scene prints `pop_outs=unknown` and why (n = 5 did, when its lines were
//! traced from its maximum-force folds alone: docs/ACCURACY.md, "n = 5").

use std::error::Error;
use std::path::PathBuf;

use hockle::bvp::Solution;
use hockle::rod::{Fixed, Followed, NikolaiRod, PhaseDiagram, Rod};

/// The committed diagram of n = 4.
const N4: &str = include_str!("../../docs/data/phase_diagram_n4.csv");

const USAGE: &str = "\
usage: cargo run --release --example phase_diagram -- [OPTIONS]
  --coils N                      the spring's number of coils n (default 4)
  --out DIR                      where a computed diagram's CSV and the diagram's SVG go
                                 (default target/hockle)
  --compute                      compute the diagram instead of reading the committed one
  --extend CSV                   compute it from the lines of the diagram CSV computed before,
                                 adding the seeded pop-outs' lines
  --check                        the convergence checks of docs/ACCURACY.md instead
  --scene THETA0_DEG,A_OVER_B,NU (repeatable) the scene's number of pop-outs read off the diagram
  --pull F                       pull each scene too, to F/((2πn)²B) = F; with --random, the
                                 force of its pulls (default 3)
  --stretch DZ                   stretch each scene too, under extension control to Δz = DZ
  --symmetric                    pulls and stretches solve the rod on its half (Rod::symmetric)
  --forces                       each scene's pop-out forces, the reference's carried there
  --force-map                    the reference pop-outs' forces over (θ0, ν) at A/B = 10
  --force-map-a-over-b           the same over (θ0, A/B) at ν = 0.05
  --cross-check                  the diagram's count against pulls on a coarse grid of both planes
  --fold-cusps                   each scene's pop-outs' folds followed in θ0 to their first cusps
                                 (no diagram read)
  --random K                     the diagram's count against pulls at K random scenes
  --seed S                       the seed of --random's scenes (default 4242)
  --help                         this text
";

#[path = "../support/exit.rs"]
mod exit;

#[path = "../support/cli.rs"]
mod cli;

fn main() -> std::process::ExitCode {
    exit::report("phase_diagram", run())
}

fn run() -> Result<(), Box<dyn Error + Send + Sync>> {
    if cli::help(USAGE) {
        return Ok(());
    }
    let mut out = std::env::var_os("CARGO_TARGET_DIR")
        .map_or_else(
            || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target"),
            PathBuf::from,
        )
        .join("hockle");
    let (mut coils, mut force, mut scenes, mut checks) = (4_u32, false, Vec::new(), false);
    let mut pull_to: Option<f64> = None;
    let mut stretch_to: Option<f64> = None;
    let mut carry = false;
    let mut map = false;
    let mut map_axis = force_map::Axis::Nu;
    let mut cross = false;
    let mut cusps = false;
    let mut random: Option<usize> = None;
    let mut seed: u64 = 4242;
    let mut extend: Option<PathBuf> = None;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out = PathBuf::from(args.next().ok_or("--out needs a directory")?),
            "--compute" => force = true,
            "--pull" => {
                let v = args.next().ok_or("--pull needs a force F/((2πn)²B)")?;
                pull_to = Some(
                    v.parse::<f64>()
                        .ok()
                        .filter(|f| *f > 0.0 && f.is_finite())
                        .ok_or(format!("--pull {v}: a finite positive force F/((2πn)²B)"))?,
                );
            }
            "--symmetric" => pulls::SYMMETRIC.store(true, std::sync::atomic::Ordering::Relaxed),
            "--stretch" => {
                let v = args.next().ok_or("--stretch needs an extension Δz")?;
                stretch_to = Some(
                    v.parse::<f64>()
                        .ok()
                        .filter(|z| *z > 0.0 && *z < 1.0)
                        .ok_or(format!("--stretch {v}: an extension Δz in (0, 1)"))?,
                );
            }
            "--extend" => {
                extend = Some(PathBuf::from(
                    args.next().ok_or("--extend needs a phase-diagram CSV")?,
                ));
                force = true;
            }
            "--check" => checks = true,
            "--forces" => carry = true,
            "--force-map" => {
                map = true;
                map_axis = force_map::Axis::Nu;
            }
            "--force-map-a-over-b" => {
                map = true;
                map_axis = force_map::Axis::AOverB;
            }
            "--cross-check" => cross = true,
            "--fold-cusps" => cusps = true,
            "--random" => {
                let v = args.next().ok_or("--random needs a number of scenes")?;
                random = Some(
                    v.parse()
                        .ok()
                        .filter(|k| *k > 0)
                        .ok_or(format!("--random {v}: a positive number of scenes"))?,
                );
            }
            "--seed" => {
                let v = args.next().ok_or("--seed needs a number")?;
                seed = v
                    .parse()
                    .map_err(|_| format!("--seed {v}: a whole number"))?;
            }
            "--coils" => {
                let v = args.next().ok_or("--coils needs a number")?;
                coils = v
                    .parse()
                    .ok()
                    .filter(|n| *n > 0)
                    .ok_or(format!("--coils {v}: a positive whole number of coils"))?;
            }
            "--scene" => {
                let v = args.next().ok_or("--scene needs THETA0_DEG,A_OVER_B,NU")?;
                let f: Vec<f64> = v
                    .split(',')
                    .map(|x| x.trim().parse::<f64>())
                    .collect::<Result<_, _>>()
                    .map_err(|_| format!("--scene {v}: three numbers THETA0_DEG,A_OVER_B,NU"))?;
                let [t, a, nu] = f[..] else {
                    return Err(format!("--scene {v}: three numbers THETA0_DEG,A_OVER_B,NU").into());
                };
                scenes.push((t, a, nu));
            }
            other => return Err(cli::unknown(other, USAGE).into()),
        }
    }
    if checks {
        return check(coils);
    }
    if map {
        let family = reference_family(coils)?;
        let search = carry_search();
        let pops = search.pop_outs(&family, 3.0)?;
        return force_map::print(&search, &family, &pops, map_axis, (A_OVER_B, NU));
    }
    for &(t, a, nu) in &scenes {
        let check = |ok: bool, what: &str| -> Result<(), Box<dyn Error + Send + Sync>> {
            if ok {
                Ok(())
            } else {
                Err(format!("--scene {t},{a},{nu}: {what}").into())
            }
        };
        check(t > 0.0 && t < 90.0, "θ0 must be in (0°, 90°)")?;
        check(a > 0.0 && a.is_finite(), "A/B must be finite and positive")?;
        check(nu > -1.0 && nu < 0.5, "ν must be in (−1, 0.5)")?;
    }
    if cusps {
        if scenes.is_empty() {
            return Err("--fold-cusps needs at least one --scene THETA0_DEG,A_OVER_B,NU".into());
        }
        for &scene in &scenes {
            fold_cusps::print(coils, scene)?;
        }
        return Ok(());
    }
    let committed = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("docs/data")
        .join(format!("phase_diagram_n{coils}.csv"));
    // a computed diagram that pulls contradict answers no scene
    let mut untrusted = None;
    let diagram = if coils == 4 && !force {
        PhaseDiagram::from_csv(4, N4)?
    } else if let (false, Ok(csv)) = (force, std::fs::read_to_string(&committed)) {
        PhaseDiagram::from_csv(coils, &csv)?
    } else {
        let reference = match &extend {
            Some(f) => {
                let text = std::fs::read_to_string(f)
                    .map_err(|e| format!("--extend {}: {e}", f.display()))?;
                Some(
                    PhaseDiagram::from_csv(coils, &text)
                        .map_err(|e| format!("--extend {}: {e}", f.display()))?,
                )
            }
            None => None,
        };
        if !force {
            eprintln!(
                "no committed diagram for n = {coils} ({} not found; committed: n = 2, 3, 4, 5, 6, 7, 8): \
                 computing it, which takes tens of minutes or more (n = 7: 18 minutes; n = 9 had \
                 not finished after 50 minutes on a two-core machine)",
                committed.display()
            );
        }
        // (the folder first: an --out that cannot be written fails now,
        // not after the minutes of the computation)
        std::fs::create_dir_all(&out).map_err(|e| format!("--out {}: {e}", out.display()))?;
        let d = compute(coils, reference)
            .map_err(|e| format!("computing the diagram of n = {coils}: {e}"))?;
        let csv = out.join(format!("phase_diagram_n{coils}.csv"));
        std::fs::write(&csv, d.to_csv())?;
        eprintln!("wrote {}", csv.display());
        if !scenes.is_empty() {
            untrusted = contradicted_by_pulls(coils, &d)?;
        }
        d
    };
    if cross {
        return cross_check::run(coils, &diagram);
    }
    if let Some(count) = random {
        return random_check::run(coils, &diagram, count, seed, pull_to.unwrap_or(3.0));
    }
    if scenes.is_empty() {
        // The reading (lines at fixed ν, interpolated in ν) against the
        // line traced in ν at A/B = 10.
        let mut worst = (0.0_f64, 0.0, 0);
        for l in diagram
            .lines()
            .iter()
            .filter(|l| matches!(l.fixed, Fixed::AOverB(_)))
        {
            for p in l.points.iter().filter(|p| p.theta0 < HALF_PI - 1e-5) {
                let read = diagram.cusp_theta0(l.pop_out, p.a_over_b, p.nu)?;
                if read.start() != read.end() {
                    continue; // not resolved there: counted below
                }
                let e = (read.start() - p.theta0).to_degrees().abs();
                if e > worst.0 {
                    worst = (e, p.nu, l.pop_out);
                }
            }
        }
        println!(
            "reading off the lines at fixed ν against the line in ν at A/B = 10: θ0_c within {:.3}° (worst: pop-out {} at ν = {:.3})",
            worst.0, worst.2, worst.1
        );
        std::fs::create_dir_all(&out)?;
        let svg = out.join(format!("phase_diagram_n{coils}.svg"));
        std::fs::write(&svg, svg::draw(&diagram))?;
        println!("wrote {}", svg.display());
    }
    let reference = if carry && !scenes.is_empty() {
        let family = reference_family(coils)?;
        let pops = carry_search().pop_outs(&family, 3.0)?;
        Some((family, pops))
    } else {
        None
    };
    for (t, a, nu) in scenes {
        match untrusted {
            Some(why) => {
                println!("scene theta0={t} a_over_b={a} nu={nu} pop_outs=unknown");
                eprintln!("  {why}");
            }
            None => match diagram.pop_outs(t.to_radians(), a, nu) {
                Ok(n) if diagram.is_complete() => {
                    println!("scene theta0={t} a_over_b={a} nu={nu} pop_outs={n}");
                }
                // the other loops of the spring may pop out here too
                Ok(n) => println!("scene theta0={t} a_over_b={a} nu={nu} pop_outs=at_least_{n}"),
                Err(e @ hockle::Error::NotMapped { .. }) => {
                    println!("scene theta0={t} a_over_b={a} nu={nu} pop_outs=unknown");
                    eprintln!("  {e}");
                }
                Err(e) => return Err(e.into()),
            },
        }
        if let Some(to) = pull_to {
            pull_scene(coils, (t, a, nu), to)?;
        }
        if let Some(to) = stretch_to {
            stretch_scene(coils, (t, a, nu), to)?;
        }
        if let Some((family, pops)) = &reference {
            carry_to_scene(family, pops, (t, a, nu))?;
        }
    }
    Ok(())
}

/// `--forces`: each reference pop-out's two folds carried to the scene.
fn carry_to_scene(
    family: &NikolaiRod,
    pops: &[[Solution; 2]],
    (t, a, nu): (f64, f64, f64),
) -> Result<(), Box<dyn Error + Send + Sync>> {
    let search = carry_search();
    for (i, pair) in pops.iter().enumerate() {
        let mut forces = Vec::new();
        let mut change: f64 = 0.0;
        let mut stopped = None;
        for fold in pair {
            let (leg, followed) = search.carry(family, fold, (t.to_radians(), a, nu))?;
            match followed {
                Followed::Reached(at) => {
                    let checked = checked_force(&search, family, at.solution());
                    forces.push(checked.force);
                    change = change.max(checked.change);
                }
                Followed::Cusp(c) => {
                    let (name, value) = match leg {
                        Rod::THETA0 => ("theta0", c.parameter().to_degrees()),
                        NikolaiRod::LN_A_OVER_B => ("a_over_b", c.parameter().exp()),
                        _ => ("nu", c.parameter()),
                    };
                    stopped = Some(format!("vanished {name}={value:.6}"));
                    break;
                }
                Followed::Ended(why) => {
                    stopped = Some(format!("ended ({why})"));
                    break;
                }
            }
        }
        match stopped {
            Some(how) => println!("carried pop_out={} {how}", i + 1),
            None => println!(
                "carried pop_out={} max={:.6} min={:.6} change={change:.1e}",
                i + 1,
                forces[0],
                forces[1]
            ),
        }
    }
    Ok(())
}

mod checked;
mod compute;
mod convergence;
mod cross_check;
mod fold_cusps;
mod random_check;

#[path = "../../tests/common/mod.rs"]
mod common;
mod pulls;

mod force_map;
mod svg;

use checked::checked_force;
use convergence::check;

use compute::{A_OVER_B, HALF_PI, NU, carry_search, compute, reference_family};
use pulls::{contradicted_by_pulls, pull_scene, stretch_scene};
