//! `--helix-data [--random N] [--seed S] [--scene N,THETA0_DEG,A_OVER_B,NU]…`:
//! what a certificate of the exact helix has to bound (docs/ACCURACY.md,
//! "Why the helix is not certified", "The helix certified by its end
//! layers"). For the issue's 48 grid scenes (or the scenes given), then N fresh random scenes
//! (n 2–8, θ0 60–89.9°, A/B 0.1–20 log-uniform, ν 0–0.4; none used to
//! choose anything), one CSV row per scene: the helix's true error to
//! F/((2πn)²B) = 1 (both ways, max norm in (Δz, F/((2πn)²B)), against the
//! rod converged on 10 intervals per coil with m = 7 at tolerance 1e-8), the
//! largest Δz_rod − Δz_helix at one force over f = 0.02 … 1 (first
//! crossing), the pop-outs below 1, and the two closed-form slopes at rest
//! (the rod's, the helix's, in units of (2πn)²B), from which candidate
//! bounds are formed offline; and the helix's error as `Spring::answer`
//! estimates it from its end layers on a 2-coil rod at tolerance 1e-2
//! (`folds` where a pop-out may come near the load, `-`
//! where the check is not run: n ≤ 2, or n·tolerance too small); and,
//! computed here independently of the library's check, the distance d (both
//! ways) between the helix and the curve its end layers predict,
//! Δz_helix + (2/n)(Δz_2 − Δz_helix) at the helix's samples, with Δz_2 from
//! a 2-coil rod converged as the reference (empty where it or the helix's
//! force folds below the load).

use hockle::Stiffness;
use hockle::curve::{ForceExtension, ForcePoint};
use hockle::helix::Helix;
use hockle::spring::{
    Choice, HelixModel, Model, Question, Reason, Response, RodModel, SetAside, Spring,
};

use crate::measure::{bare, both_ways, drawn, grid_scenes};

/// A scene: n, θ0 in degrees, A/B, ν.
type Scene = (u32, f64, f64, f64);

/// Fresh scenes from an xorshift generator.
fn random_scenes(seed: u64, count: usize) -> Vec<Scene> {
    let mut rnd = crate::common::uniform(seed);
    (0..count)
        .map(|_| {
            let n = 2 + (rnd() * 7.0) as u32;
            let theta0 = 60.0 + rnd() * 29.9;
            let a_over_b = 10f64.powf(-1.0 + rnd() * (1.0 + 20f64.log10()));
            let nu = rnd() * 0.4;
            (n, theta0, a_over_b, nu)
        })
        .collect()
}

/// `--helix-data`.
pub fn run(args: &[String]) -> Result<(), String> {
    let (mut count, mut seed, mut given) = (0usize, 0x14c0_ffee_u64, Vec::new());
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or_else(|| format!("{flag} needs a value"));
        match flag.as_str() {
            "--random" => {
                let value = value()?;
                // each scene pulls the rod (seconds): a larger count is a
                // typo, and its list would not fit in memory
                count = value
                    .parse()
                    .ok()
                    .filter(|n| *n <= 100_000)
                    .ok_or_else(|| format!("--random {value}: a count of scenes up to 100000"))?;
            }
            "--seed" => {
                let value = value()?;
                seed = value.parse().map_err(|_| format!("--seed {value}"))?;
            }
            "--scene" => given.push(crate::parse_scene(value()?)?),
            other => return Err(crate::cli::unknown(other, crate::USAGE)),
        }
    }
    // scenes given replace the grid
    let fixed = if given.is_empty() {
        grid_scenes().into_iter().map(|s| ("grid", s)).collect()
    } else {
        given.into_iter().map(|s| ("given", s)).collect::<Vec<_>>()
    };
    let scenes: Vec<(&str, Scene)> = fixed
        .into_iter()
        .chain(
            random_scenes(seed, count)
                .into_iter()
                .map(|s| ("random", s)),
        )
        .collect();
    println!(
        "set,n,theta0,a_over_b,nu,helix_true,dz_excess_max,f_at_max,pop_outs,k_rod,k_helix,end_layer_estimate,end_layer_distance"
    );
    for (set, (n, theta0, a_over_b, nu)) in scenes {
        let stiffness = Stiffness::nikolai(a_over_b, nu).map_err(|e| e.to_string())?;
        let s = Spring::from_degrees(n, theta0, stiffness).map_err(|e| e.to_string())?;
        let scale = s.force_scale();
        let reference = converged(&s)?;
        if !reference.reached_target() {
            println!("{set},{n},{theta0},{a_over_b},{nu},stopped,,,,,,,");
            continue;
        }
        let helix = HelixModel::new(2000)
            .map_err(|e| e.to_string())?
            .pull(&s, 1.0)
            .map_err(|e| e.to_string())?;
        let truth = both_ways(&drawn(&helix), &drawn(&reference));
        let (mut worst, mut at) = (f64::NEG_INFINITY, f64::NAN);
        for j in 1..=50 {
            let f = f64::from(j) / 50.0;
            let first = |r: &hockle::spring::Response| {
                r.curve()
                    .extension_at(f * scale)
                    .first()
                    .copied()
                    .unwrap_or(f64::NAN)
            };
            let d = first(&reference) - first(&helix);
            if d > worst {
                (worst, at) = (d, f);
            }
        }
        let k_rod = s.spring_constant().map_err(|e| e.to_string())? / scale;
        let k_helix = Helix::new(n, s.helix_angle(), stiffness)
            .and_then(|h| h.spring_constant())
            .map_err(|e| e.to_string())?
            / scale;
        println!(
            "{set},{n},{theta0:.3},{a_over_b:.4},{nu:.3},{truth:.4e},{worst:.4e},{at},{},{k_rod:.5},{k_helix:.5},{},{}",
            reference.pop_outs().len(),
            end_layer_estimate(&s)?,
            end_layer_distance(&s)?
                .map(|d| format!("{d:.4e}"))
                .unwrap_or_default()
        );
    }
    Ok(())
}

/// The helix's error as `Spring::answer` estimates it from its end layers
/// for the curve to F/((2πn)²B) = 1 at tolerance 1e-2: the helix's answer's
/// estimate where it was chosen, else the estimate that set it aside.
fn end_layer_estimate(spring: &Spring) -> Result<String, String> {
    let answer = spring
        .answer(&Question::Curve { max_force: 1.0 }, 1e-2)
        .map_err(|e| e.to_string())?;
    Ok(match (answer.choice(), answer.reason()) {
        (Choice::Helix, _) => format!("{:.4e}", answer.estimated_error()),
        (
            _,
            Reason::RodNeeded {
                helix: SetAside::EndLayers { estimate },
                ..
            },
        ) => format!("{estimate:.4e}"),
        (
            _,
            Reason::RodNeeded {
                helix: SetAside::NearAPopOut { .. },
                ..
            },
        ) => "folds".to_owned(),
        _ => "-".to_owned(),
    })
}

/// The distance both ways between the spring's helix pulled to
/// F/((2πn)²B) = 1 and the curve its end layers predict (module docs), or
/// `None` where the helix's force or the 2-coil rod folds below the load
/// (where `Spring::answer` sets the helix aside unchecked).
fn end_layer_distance(spring: &Spring) -> Result<Option<f64>, String> {
    const SHORT: u32 = 2;
    // (200 samples: the distance between two polylines of 2000 costs
    // half a minute here)
    let helix = HelixModel::new(200)
        .and_then(|m| m.pull(spring, 1.0))
        .map_err(|e| e.to_string())?;
    let short_spring =
        Spring::new(SHORT, spring.helix_angle(), spring.stiffness()).map_err(|e| e.to_string())?;
    let short = converged(&short_spring)?;
    let rises = helix
        .curve()
        .points()
        .windows(2)
        .all(|w| w[1].force > w[0].force);
    if !rises || !short.reached_target() || !short.folds().is_empty() {
        return Ok(None);
    }
    let weight = f64::from(SHORT) / f64::from(spring.coils());
    let mut predicted = ForceExtension::new("predicted", "force", spring.scale());
    for p in helix.curve().points() {
        let f = p.force / spring.force_scale();
        let [dz] = short.curve().extension_at(f * short_spring.force_scale())[..] else {
            return Ok(None);
        };
        predicted.push(ForcePoint {
            extension: p.extension + weight * (dz - p.extension),
            force: p.force,
            parameter: p.force,
        });
    }
    Ok(Some(both_ways(&bare(helix.curve()), &bare(&predicted))))
}

/// The rod pulled to F/((2πn)²B) = 1 converged: 10 intervals per coil,
/// m = 7, tolerance 1e-8 (the reference of `tests/spring/choice.rs`).
fn converged(spring: &Spring) -> Result<Response, String> {
    RodModel::default()
        .tolerance(1e-8)
        .intervals(10 * spring.coils() as usize)
        .points(7)
        .pull(spring, 1.0)
        .map_err(|e| e.to_string())
}
