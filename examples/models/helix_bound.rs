//! `--helix-data [--random N] [--seed S]`: what a certificate of the exact
//! helix would have to bound (docs/ACCURACY.md, "Why the helix is not
//! certified"). For the issue's 48 grid scenes, then N fresh random scenes
//! (n 2–8, θ0 60–89.9°, A/B 0.1–20 log-uniform, ν 0–0.4; none used to
//! choose anything), one CSV row per scene: the helix's true error to
//! F/((2πn)²B) = 1 (both ways, max norm in (Δz, F/((2πn)²B)), against the
//! rod converged on 10 intervals per coil with m = 7 at tolerance 1e-8), the
//! largest Δz_rod − Δz_helix at one force over f = 0.02 … 1 (first
//! crossing), the pop-outs below 1, and the two closed-form slopes at rest
//! (the rod's, the helix's, in units of (2πn)²B), from which candidate
//! bounds are formed offline.

use hockle::Stiffness;
use hockle::helix::Helix;
use hockle::spring::{HelixModel, Model, RodModel, Spring};

use crate::measure::{both_ways, drawn, grid_scenes};

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
    let (mut count, mut seed) = (0usize, 0x14c0_ffee_u64);
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let value = it.next().ok_or_else(|| format!("{flag} needs a value"))?;
        match flag.as_str() {
            "--random" => {
                // each scene pulls the rod (seconds): a larger count is a
                // typo, and its list would not fit in memory
                count = value
                    .parse()
                    .ok()
                    .filter(|n| *n <= 100_000)
                    .ok_or_else(|| format!("--random {value}: a count of scenes up to 100000"))?;
            }
            "--seed" => seed = value.parse().map_err(|_| format!("--seed {value}"))?,
            other => return Err(format!("unknown flag {other} (--random N, --seed S)")),
        }
    }
    let scenes: Vec<(&str, Scene)> = grid_scenes()
        .into_iter()
        .map(|s| ("grid", s))
        .chain(
            random_scenes(seed, count)
                .into_iter()
                .map(|s| ("random", s)),
        )
        .collect();
    println!("set,n,theta0,a_over_b,nu,helix_true,dz_excess_max,f_at_max,pop_outs,k_rod,k_helix");
    for (set, (n, theta0, a_over_b, nu)) in scenes {
        let stiffness = Stiffness::nikolai(a_over_b, nu).map_err(|e| e.to_string())?;
        let s = Spring::from_degrees(n, theta0, stiffness).map_err(|e| e.to_string())?;
        let scale = s.force_scale();
        let reference = RodModel::default()
            .tolerance(1e-8)
            .intervals(10 * n as usize)
            .points(7)
            .pull(&s, 1.0)
            .map_err(|e| e.to_string())?;
        if !reference.reached_target() {
            println!("{set},{n},{theta0},{a_over_b},{nu},stopped,,,,,");
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
            "{set},{n},{theta0:.3},{a_over_b:.4},{nu:.3},{truth:.4e},{worst:.4e},{at},{},{k_rod:.5},{k_helix:.5}",
            reference.pop_outs().len()
        );
    }
    Ok(())
}
