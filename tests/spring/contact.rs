//! Self-contact: the paper's claim that none of its shapes touches itself
//! for a narrow strip, while the slinky (A/B = 1/10) crosses itself at very
//! small force.

use std::ops::ControlFlow;

use hockle::Stiffness;
use hockle::bvp::Solution;
use hockle::continuation::{Point, PointKind};
use hockle::rod::{Equilibrium, Pull};
use hockle::spring::{RodModel, Spring, Target};

/// The closest approach of the unstressed helix: the coils one pitch
/// apart, minimised over the offset δ of the second point from one full
/// turn (closed form of the helix r = (R0 sin φ, R0(1 − cos φ), c s),
/// independent of the rod): distance² = (2 R0 sin(πnδ))² + c²(1/n + δ)².
fn helix_pitch_distance(n: f64, theta0: f64) -> f64 {
    let (sn, c) = theta0.sin_cos();
    let r0 = sn / (2.0 * core::f64::consts::PI * n);
    let d2 = |delta: f64| {
        (2.0 * r0 * (core::f64::consts::PI * n * delta).sin()).powi(2)
            + (c * (1.0 / n + delta)).powi(2)
    };
    // golden-section search on |δ| ≤ 1e-3 (the minimum is at δ ≈ −c²/n)
    let (mut a, mut b) = (-1e-3, 1e-3);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if d2(x1) < d2(x2) {
            b = x2;
        } else {
            a = x1;
        }
    }
    d2(0.5 * (a + b)).sqrt()
}

#[test]
fn no_shape_of_the_paper_spring_comes_closer_than_its_rest_pitch() {
    let pitch = helix_pitch_distance(4.0, 89.8_f64.to_radians());
    // A strip narrower than the rest pitch never touches itself; one wider
    // touches at rest already.
    let narrow = Spring::paper().with_strip_width(0.99 * pitch).unwrap();
    let pull = RodModel::default()
        .pull_with_contact(&narrow, Target::Force(3.0), ())
        .unwrap();
    assert!(pull.reached_target(), "{pull}");
    let closest = pull.closest_approach();
    assert!(closest.iter().all(Option::is_some));
    // At rest the collocation helix is exact to rounding and Newton's
    // refinement finds the minimum to ~1e-12; 1e-9 relative is safe.
    let rest = closest[0].unwrap();
    assert!((rest / pitch - 1.0).abs() < 1e-9, "{rest} vs {pitch}");
    // Every later shape keeps its parts farther apart (measured minimum
    // over the 828 points: the rest state itself).
    let min = closest
        .iter()
        .flatten()
        .copied()
        .fold(f64::INFINITY, f64::min);
    assert!(min >= pitch * (1.0 - 1e-9), "{min} vs {pitch}");
    assert_eq!(pull.first_contact(), None);
    let wide = pull
        .clone()
        .with_closest_approach(closest.to_vec(), Some(1.01 * pitch))
        .unwrap();
    assert_eq!(wide.first_contact(), Some(0));
}

#[test]
fn the_slinky_crosses_itself_at_very_small_force() {
    let slinky = Spring::from_degrees(4, 89.8, Stiffness::nikolai(0.1, 0.05).unwrap())
        .unwrap()
        .with_strip_width(1e-4)
        .unwrap();
    let rod = RodModel::rod(&slinky).unwrap();
    let pull = RodModel::default()
        .pull_with_contact(&slinky, Target::Force(0.01), ())
        .unwrap();
    assert!(pull.reached_target(), "{pull}");
    // A strip of width 1e-4 (an eighth of the rest pitch) touches itself
    // within F/((2πn)²B) < 0.01.
    let first = pull.first_contact().expect("the slinky touches itself");
    let scale = slinky.force_scale();
    assert!(pull.curve().points()[first].force / scale < 0.01);
    // It crosses itself: on the same pull with steps of at most 0.01 in
    // arclength (the tolerance alone takes steps over which the closest
    // pair of strands moves), the signed separation of the two closest strands
    // along their common normal, (r(t) − r(s))·(d3(s) × d3(t))/|…|,
    // changes sign between consecutive points whose closest pairs are the
    // same strands (arclengths within 0.01); the distance then passes
    // through zero, whatever the strip's width.
    let mut shapes: Vec<Solution> = Vec::new();
    Pull::new(rod, Target::Force(0.01))
        .step(1e-3, 1e-7, 0.01)
        .run(|p: &Point| {
            if p.kind() != PointKind::Fold {
                shapes.push(p.solution().clone());
            }
            ControlFlow::Continue(())
        })
        .unwrap();
    let signed: Vec<(f64, f64, f64)> = shapes
        .iter()
        .map(|sol| {
            let eq = Equilibrium::new(rod, sol.clone()).unwrap();
            let c = eq.closest_approach().unwrap();
            let (rs, rt) = (eq.centreline(c.s).unwrap(), eq.centreline(c.t).unwrap());
            let ts = eq.frame(c.s).unwrap() * hockle::nalgebra::Vector3::z();
            let tt = eq.frame(c.t).unwrap() * hockle::nalgebra::Vector3::z();
            let n = ts.cross(&tt);
            ((rt - rs).dot(&n) / n.norm(), c.s, c.t)
        })
        .collect();
    let crossings = signed
        .windows(2)
        .filter(|w| {
            w[0].0 * w[1].0 < 0.0
                && (w[0].1 - w[1].1).abs() < 0.01
                && (w[0].2 - w[1].2).abs() < 0.01
        })
        .count();
    assert!(crossings >= 1, "{signed:?}");
}
