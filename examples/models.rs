//! What each model costs and how far it is from the 3D rod, for a few
//! springs: the table of `docs/ACCURACY.md` (section "spring").
//!
//! ```sh
//! cargo run --release --example models
//! ```
//!
//! For every spring the 3D rod is pulled to F/(2πn)² = 3 (or as far as it
//! gets), then each model's curve is compared with it in the (Δz,
//! F/(2πn)²) plane of the paper's plots: on the first stretch (from rest to
//! the first pop-out, where every model claims to be valid) and on the whole
//! curve.
//!
//! With `--scene`, the spring chooses ([`Spring::answer`]) instead:
//!
//! ```sh
//! cargo run --release --example models -- --scene 4,89.8,10,0.05 --scene 2,60,0.1,0 \
//!     --tolerance 1e-4 --max-force 1
//! ```
//!
//! prints one line per scene (n, θ0 in degrees, A/B, ν; C by the Nikolai
//! equality): `scene n=… theta0=… a_over_b=… nu=… model=… estimated=…
//! true=… seconds=…`. It answers the curve up to F/((2πn)²B) =
//! `--max-force` (default 1) at `--tolerance` (default 1e-4) and prints
//! its estimated error, its true error and the seconds the answer took.
//! The true error is the largest max-norm distance in (Δz, F/((2πn)²B))
//! between the answer (its cubic Hermite interpolant and located folds) and
//! the converged rod's, both ways; the rod is converged on a fixed mesh of
//! 10 intervals per coil with m = 7 at tolerance 1e-8.

use std::time::{Duration, Instant};

#[path = "../tests/common/mod.rs"]
mod common;
#[path = "../tests/spring/measure.rs"]
mod measure;

use hockle::Stiffness;
use hockle::spring::{
    ElasticaModel, HelixModel, Model, Question, Response, RodModel, Spring, Value,
};

fn timed(model: &dyn Model, spring: &Spring, target: f64) -> (Response, Duration) {
    let runs = if model.name() == "rod" { 1 } else { 20 };
    let start = Instant::now();
    let mut last = None;
    for _ in 0..runs {
        last = Some(model.pull(spring, target).expect("valid spring and target"));
    }
    (last.expect("at least one run"), start.elapsed() / runs)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.is_empty() {
        table();
    } else if let Err(e) = scenes(&args) {
        eprintln!("models: {e}");
        std::process::exit(2);
    }
}

/// One scene of the command line: n, θ0 (degrees), A/B, ν.
fn parse_scene(s: &str) -> Result<(u32, f64, f64, f64), String> {
    let parts: Vec<&str> = s.split(',').collect();
    let bad = || format!("--scene {s}: expected N,THETA0_DEG,A_OVER_B,NU");
    if parts.len() != 4 {
        return Err(bad());
    }
    let n = parts[0].trim().parse().map_err(|_| bad())?;
    let f = |i: usize| parts[i].trim().parse::<f64>().map_err(|_| bad());
    Ok((n, f(1)?, f(2)?, f(3)?))
}

fn scenes(args: &[String]) -> Result<(), String> {
    let (mut list, mut tol, mut max_force) = (Vec::new(), 1e-4, 1.0);
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let value = it.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--scene" => list.push(parse_scene(value)?),
            "--tolerance" => tol = value.parse().map_err(|_| format!("--tolerance {value}"))?,
            "--max-force" => {
                max_force = value.parse().map_err(|_| format!("--max-force {value}"))?;
            }
            other => {
                return Err(format!(
                    "unknown flag {other} (--scene N,THETA0_DEG,A_OVER_B,NU, --tolerance TOL, --max-force F)"
                ));
            }
        }
    }
    for (n, theta0, a_over_b, nu) in list {
        let stiffness = Stiffness::nikolai(a_over_b, nu).map_err(|e| e.to_string())?;
        let spring = Spring::from_degrees(n, theta0, stiffness).map_err(|e| e.to_string())?;
        let answer = spring
            .answer(&Question::Curve { max_force }, tol)
            .map_err(|e| e.to_string())?;
        let Value::Curve(response) = answer.value() else {
            return Err("a curve question answered without a curve".into());
        };
        let reference = RodModel::default()
            .tolerance(1e-8)
            .intervals(10 * n as usize)
            .points(7)
            .pull(&spring, max_force)
            .map_err(|e| e.to_string())?;
        let truth = if reference.reached_target() && answer.reached_target() {
            measure::both_ways(&measure::drawn(response), &measure::drawn(&reference))
        } else {
            f64::INFINITY
        };
        println!(
            "scene n={n} theta0={theta0} a_over_b={a_over_b} nu={nu} model={} estimated={:.3e} true={truth:.3e} seconds={:.3}",
            answer.choice().name(),
            answer.estimated_error(),
            answer.elapsed().as_secs_f64()
        );
    }
    Ok(())
}

fn table() {
    let nikolai = |a_over_b| Stiffness::nikolai(a_over_b, 0.05).expect("valid stiffness");
    let springs = [
        ("paper: 89.8°, A/B = 10", Spring::paper()),
        (
            "89°, A/B = 10",
            Spring::from_degrees(4, 89.0, nikolai(10.0)).unwrap(),
        ),
        (
            "60°, A/B = 10",
            Spring::from_degrees(4, 60.0, nikolai(10.0)).unwrap(),
        ),
        (
            "89.8°, A/B = 1",
            Spring::from_degrees(4, 89.8, nikolai(1.0)).unwrap(),
        ),
        (
            "89.8°, A/B = 0.1 (slinky)",
            Spring::from_degrees(4, 89.8, nikolai(0.1)).unwrap(),
        ),
    ];
    let target = 3.0;
    println!(
        "| spring | model | time | pop-outs | first stretch: rms / max distance | whole curve: rms distance |"
    );
    println!("|---|---|---|---|---|---|");
    for (name, spring) in springs {
        let (rod, rod_time) = timed(&RodModel::default(), &spring, target);
        let note = if rod.reached_target() {
            String::new()
        } else {
            format!(" (stopped: {})", rod.termination())
        };
        println!(
            "| {name} | rod{note} | {:.0} ms | {} | reference | reference |",
            rod_time.as_secs_f64() * 1e3,
            rod.pop_outs().len()
        );
        let models: [&dyn Model; 2] = [&HelixModel::default(), &ElasticaModel::default()];
        for model in models {
            let (answer, time) = timed(model, &spring, target);
            let per_stretch = rod.match_branches(std::slice::from_ref(answer.curve()));
            let first = &per_stretch[0][0];
            let n_pts: usize = rod.stretches().iter().map(|s| s.range.len()).sum();
            let whole = rod
                .stretches()
                .iter()
                .zip(&per_stretch)
                .map(|(s, m)| m[0].rms_distance.powi(2) * s.range.len() as f64)
                .sum::<f64>()
                / n_pts as f64;
            println!(
                "| {name} | {} | {:.1} µs | {} | {:.2e} / {:.2e} | {:.2e} |",
                model.name(),
                time.as_secs_f64() * 1e6,
                answer.pop_outs().len(),
                first.rms_distance,
                first.max_distance,
                whole.sqrt()
            );
        }
    }
}
