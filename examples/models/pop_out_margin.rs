//! `--pop-out-margin`: how far below a short rod's first fold, and below
//! the exact helix's force maximum, a spring's first pop-out can come
//! (`Spring::answer`'s helix check sets the helix aside within twice the
//! load of either; docs/ACCURACY.md, "The helix certified by its end
//! layers"). For seven low-pitch scenes of the grid and the paper, then 25
//! random ones (n ∈ {2, 3, 4, 6, 8, 12}, θ0 86–89.95°, A/B 2–100
//! log-uniform, ν 0–0.3; seed fixed before the run), one CSV row each: the
//! helix's first force maximum (empty if none), the first pop-out of the
//! spring and of a 2-coil rod with the same θ0, A, B, C (the rod at
//! tolerance 1e-4 pulled to F/((2πn)²B) = 3; empty if none), and their
//! ratios. About a minute.

use hockle::spring::{HelixModel, Model, RodModel, Spring};
use hockle::{Stiffness, Target};

/// The first maximum of the helix's force, on 4000 samples uniform in Δz
/// from rest to 0.999.
fn helix_maximum(spring: &Spring) -> Result<Option<f64>, String> {
    let helix = HelixModel::new(4000)
        .and_then(|m| m.pull_to(spring, Target::Extension(0.999)))
        .map_err(|e| e.to_string())?;
    let p = helix.curve().points();
    Ok(p.windows(3)
        .find(|w| w[1].force > w[0].force && w[1].force >= w[2].force)
        .map(|w| w[1].force / spring.force_scale()))
}

/// The first pop-out's maximum force of `coils` coils, F/((2πn)²B).
fn first_pop_out(coils: u32, theta0: f64, stiffness: Stiffness) -> Result<Option<f64>, String> {
    let s = Spring::from_degrees(coils, theta0, stiffness).map_err(|e| e.to_string())?;
    let pull = RodModel::default()
        .tolerance(1e-4)
        .pull(&s, 3.0)
        .map_err(|e| e.to_string())?;
    Ok(pull
        .pop_outs()
        .first()
        .map(|p| p.max.point.force / s.force_scale()))
}

/// `--pop-out-margin`.
pub fn run() -> Result<(), String> {
    let mut scenes = vec![
        (4u32, 89.8, 10.0, 0.05),
        (2, 89.0, 3.0, 0.2),
        (3, 89.0, 10.0, 0.3),
        (4, 89.0, 10.0, 0.1),
        (6, 89.0, 20.0, 0.2),
        (4, 89.0, 20.0, 0.4),
        (3, 89.0, 3.0, 0.0),
    ];
    let mut rnd = crate::common::uniform(0x5eed_1234);
    for _ in 0..25 {
        let n = [2u32, 3, 4, 6, 8, 12][(rnd() * 6.0) as usize];
        let theta0 = 86.0 + rnd() * 3.95;
        let a_over_b = 10f64.powf(0.3 + rnd() * 1.7);
        let nu = rnd() * 0.3;
        scenes.push((n, theta0, a_over_b, nu));
    }
    let show = |x: Option<f64>| x.map(|v| format!("{v:.4}")).unwrap_or_default();
    let ratio = |a: Option<f64>, b: Option<f64>| show(a.zip(b).map(|(a, b)| a / b));
    println!(
        "n,theta0,a_over_b,nu,helix_maximum,first_pop_out,first_pop_out_2_coils,pop_out_over_2_coils,pop_out_over_helix_maximum"
    );
    for (n, theta0, a_over_b, nu) in scenes {
        let stiffness = Stiffness::nikolai(a_over_b, nu).map_err(|e| e.to_string())?;
        let spring = Spring::from_degrees(n, theta0, stiffness).map_err(|e| e.to_string())?;
        let peak = helix_maximum(&spring)?;
        let pop = first_pop_out(n, theta0, stiffness)?;
        let pop2 = first_pop_out(2, theta0, stiffness)?;
        println!(
            "{n},{theta0:.3},{a_over_b:.3},{nu:.3},{},{},{},{},{}",
            show(peak),
            show(pop),
            show(pop2),
            ratio(pop, pop2),
            ratio(pop, peak)
        );
    }
    Ok(())
}
