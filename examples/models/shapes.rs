//! `--shapes`: what a shape at one load costs (docs/ACCURACY.md, "The
//! shape at one load"; docs/PERFORMANCE.md). The five springs of the
//! table (n = 4, ν = 0.05) and a steep slinky (2, 60°, A/B = 0.1, ν = 0),
//! each at F/((2πn)²B) = 1, at tolerances 1e-2, 1e-4 and 1e-6: the CPU
//! time of `Spring::answer(Question::Shape)`, of the pull to the load
//! alone at the same tolerance (what the shape adds is the difference: the
//! last point solved again on halved meshes), and of the curve's answer to
//! the same load; the shape's reported error, its true error against the
//! converged equilibrium (`measure::shape_reference`, centrelines up to a
//! turn about the force line) and its loop count.

use hockle::Stiffness;
use hockle::spring::{Model, Question, RodModel, Spring, Target, Value};

use crate::measure::{
    SHAPE_REFERENCE_INTERVALS_PER_COIL, centreline, distance_up_to_a_turn, shape_reference,
};
use crate::trade::{seconds, time_per_call};

/// `--shapes`.
pub fn run() -> Result<(), String> {
    let spring = |n, theta0, a_over_b, nu| -> Result<Spring, String> {
        let stiffness = Stiffness::nikolai(a_over_b, nu).map_err(|e| e.to_string())?;
        Spring::from_degrees(n, theta0, stiffness).map_err(|e| e.to_string())
    };
    let springs = [
        ("paper: 89.8°, A/B = 10", spring(4, 89.8, 10.0, 0.05)?),
        ("89°, A/B = 10", spring(4, 89.0, 10.0, 0.05)?),
        ("60°, A/B = 10", spring(4, 60.0, 10.0, 0.05)?),
        ("89.8°, A/B = 1", spring(4, 89.8, 1.0, 0.05)?),
        ("89.8°, A/B = 0.1 (slinky)", spring(4, 89.8, 0.1, 0.05)?),
        ("n = 2, 60°, A/B = 0.1, ν = 0", spring(2, 60.0, 0.1, 0.0)?),
    ];
    let at = Target::Force(1.0);
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load average before: {}", load.trim());
    println!(
        "| spring | tol | shape: CPU / reported / true | loops (reference) | pull alone: CPU | curve answer: CPU |"
    );
    println!("|---|---|---|---|---|---|");
    for (name, s) in springs {
        let exact = shape_reference(&s, at, SHAPE_REFERENCE_INTERVALS_PER_COIL);
        let r = centreline(&exact);
        for tol in [1e-2, 1e-4, 1e-6] {
            let (answer, t_shape) = time_per_call(|| s.answer(&Question::Shape { at }, tol));
            let answer = answer.map_err(|e| e.to_string())?;
            let Value::Shape(shape) = answer.value() else {
                return Err("a shape question answered without a shape".into());
            };
            let truth = distance_up_to_a_turn(&centreline(shape.equilibrium()), &r);
            let (_, t_pull) = time_per_call(|| RodModel::default().tolerance(tol).pull_to(&s, at));
            let (_, t_curve) = time_per_call(|| s.answer(&Question::Curve { max_force: 1.0 }, tol));
            let loops = |l: Option<u32>| l.map_or_else(|| "none".to_owned(), |l| l.to_string());
            println!(
                "| {name} | {tol:.0e} | {} / {:.1e} / {truth:.1e} | {} ({}) | {} | {} |",
                seconds(t_shape),
                answer.estimated_error(),
                loops(shape.loops()),
                loops(exact.loops()),
                seconds(t_pull),
                seconds(t_curve)
            );
        }
    }
    let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
    println!("load average after: {}", load.trim());
    Ok(())
}
