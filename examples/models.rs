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

use std::time::{Duration, Instant};

use hockle::Stiffness;
use hockle::spring::{ElasticaModel, HelixModel, Model, Response, RodModel, Spring};

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
