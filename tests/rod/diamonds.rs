//! The diamonds of `hockle::elastica::OutOfPlane` (shooting on the
//! linearised out-of-plane equations along the closed-form elastica)
//! against the 3D rod at θ0 = 90° (quaternion collocation and
//! pseudo-arclength continuation with branch-point detection): two
//! independent models of the same instability.

use core::f64::consts::PI;

use hockle::Stiffness;
use hockle::bvp::Collocation;
use hockle::continuation::{Continuation, PointKind};
use hockle::elastica::{Branch, Diamond, Elastica, OutOfPlane};
use hockle::rod::{Equilibrium, Rod};

use super::planar_guess::planar_guess;
use hockle::special::Modulus;

/// The rod's branch point is located to 1e-10 in arclength on a
/// 128-interval mesh whose O(h⁸) force error is ~1e-10 relative here
/// (tests/rod/planar.rs); the diamond is located to 1e-10 in k, ~1e-9 in F.
/// The brief's bar, 1e-6 in force, leaves two orders of margin.
const DIAMOND_FORCE_REL: f64 = 1e-6;

/// The forces of the 3D rod's branch points (θ0 = 90°, 128 collocation
/// intervals) on the planar branch through `e`, continued in the force from
/// `e` towards `stop`.
fn rod_branch_points(stiffness: Stiffness, e: Elastica, stop: f64) -> Vec<f64> {
    let scale = (8.0 * PI).powi(2);
    let rod = Rod::new(4, PI / 2.0, stiffness).unwrap();
    let solver = Collocation::new().intervals(128);
    let start = solver
        .solve(&rod, planar_guess(e), &[e.force(), e.extension(), PI / 2.0])
        .unwrap();
    let first = Equilibrium::new(rod, start.clone()).unwrap();
    assert!(
        (first.force() / e.force() - 1.0).abs() < 1e-8 && first.planarity() < 1e-12,
        "{e}: the rod converged elsewhere (F = {})",
        first.force()
    );
    let w = rod.norm_weights();
    let branch = Continuation::new(Rod::FORCE)
        .solver(solver)
        .weights(&w)
        .parameter_weight(1.0 / (scale * scale))
        .step(if stop > e.force() { 0.01 } else { -0.01 })
        .step_bounds(1e-9, 0.05)
        .max_steps(300)
        .stop_at(stop)
        .run(&rod, &start, ())
        .unwrap();
    branch
        .points()
        .iter()
        .filter(|p| p.kind() == PointKind::BranchPoint)
        .map(|p| Equilibrium::new(rod, p.solution().clone()).unwrap())
        .inspect(|e| assert!(e.planarity() < 1e-10))
        .map(|e| e.force())
        .collect()
}

/// Asserts that the rod has exactly the diamonds `want` between the
/// start `e` and `stop`, each to [`DIAMOND_FORCE_REL`].
fn assert_rod_agrees(stiffness: Stiffness, e: Elastica, stop: f64, want: &[Diamond]) {
    let got = rod_branch_points(stiffness, e, stop);
    assert_eq!(got.len(), want.len(), "{e}: rod {got:?}, diamonds {want:?}");
    for (f, d) in got.iter().zip(want) {
        let rel = (f / d.force() - 1.0).abs();
        assert!(rel < DIAMOND_FORCE_REL, "{d}: rod {f}, {rel:e}");
        eprintln!("{d}: rod vs elastica {rel:e} in force");
    }
}

#[test]
fn the_primary_diamonds_are_the_rods_out_of_plane_branch_points() {
    let scale = (8.0 * PI).powi(2);
    let m = |k: f64| Modulus::from_k(k).unwrap();
    // (stiffness, branch, start k, stop F/(2πn)²): the paper's rod on υ and
    // α, and a softer twist (C/B = 1.1) whose υ diamond sits at low force
    let cases = [
        (
            Stiffness::nikolai(10.0, 0.05).unwrap(),
            Branch::Upsilon,
            0.96,
            0.8,
        ),
        (
            Stiffness::nikolai(10.0, 0.05).unwrap(),
            Branch::Alpha,
            0.8,
            0.45,
        ),
        (
            Stiffness::new(10.0, 1.0, 1.1).unwrap(),
            Branch::Upsilon,
            0.4,
            0.09,
        ),
    ];
    for (stiffness, branch, k, stop) in cases {
        let e = match branch {
            Branch::Upsilon => Elastica::upsilon(4, m(k)),
            _ => Elastica::alpha(4, m(k)),
        }
        .unwrap();
        let want: Vec<Diamond> = OutOfPlane::new(4, stiffness)
            .unwrap()
            .diamonds(branch, stop)
            .unwrap()
            .into_iter()
            .filter(|d| d.force() > e.force())
            .collect();
        assert_eq!(want.len(), 1, "{branch}: {want:?}");
        assert_rod_agrees(stiffness, e, stop * scale, &want);
    }
}

/// The rod's branch points near `diamond` on its secondary branch: the rod
/// is started from the planar solution at q = −ln(1 − k²) a little before
/// the diamond (q − 0.2, or half-way to the fold) and continued in the
/// force 5 % past it.
fn check_secondary(stiffness: Stiffness, diamond: Diamond) {
    let Branch::Secondary { j, arm } = diamond.branch() else {
        unreachable!()
    };
    let q_of = |m: Modulus| -m.complement().ln();
    let q_d = q_of(diamond.solution().elliptic_modulus());
    let fold = hockle::elastica::secondary_fold(4, j).unwrap();
    let q = q_d - (0.5 * (q_d - q_of(fold.solution().elliptic_modulus()))).min(0.2);
    let md = Modulus::from_complement((-q).exp()).unwrap();
    let e = Elastica::secondary_arm(4, j, arm, md).unwrap();
    let stop = diamond.force()
        * if diamond.force() > e.force() {
            1.05
        } else {
            0.95
        };
    assert_rod_agrees(stiffness, e, stop, &[diamond]);
}

#[test]
fn the_secondary_diamonds_are_the_rods_branch_points() {
    use hockle::elastica::Arm;
    let stiffness = Stiffness::nikolai(10.0, 0.05).unwrap();
    let oop = OutOfPlane::new(4, stiffness).unwrap();
    let mut checked = 0;
    for (j, arm, max) in [
        (3, Arm::Lower, 0.6),
        (3, Arm::Upper, 0.6),
        (2, Arm::Lower, 0.6),
        (1, Arm::Lower, 0.3),
    ] {
        for d in oop.diamonds(Branch::Secondary { j, arm }, max).unwrap() {
            check_secondary(stiffness, d);
            checked += 1;
        }
    }
    assert!(checked >= 5, "{checked} diamonds checked");
}

/// The diamonds of the non-symmetric ϑ_j branches (`OutOfPlane::diamonds`
/// on `Branch::Theta`, the first root of eq81) against the rod's branch
/// points: the rod is started from the planar ϑ_j shape a little before
/// each diamond (q − 0.2 in q = −ln(1 − k²)) and continued in the force
/// 5 % past it. The in-plane bifurcations of ϑ_j with its secondary
/// branches (closed form, `bifurcation`) lie outside every such window
/// (asserted), so the rod's branch points there are out of plane.
#[test]
fn the_theta_diamonds_are_the_rods_branch_points() {
    let stiffness = Stiffness::nikolai(10.0, 0.05).unwrap();
    let oop = OutOfPlane::new(4, stiffness).unwrap();
    let q_of = |m: Modulus| -m.complement().ln();
    let mut checked = 0;
    // (ϑ_3 has none below F/(2πn)² = 1; ϑ_7 and up start above it)
    for j in [1, 2, 4, 5, 6] {
        for d in oop.diamonds(Branch::Theta { j }, 1.0).unwrap() {
            let q = q_of(d.solution().elliptic_modulus()) - 0.2;
            let md = Modulus::from_complement((-q).exp()).unwrap();
            let e = Elastica::nonsymmetric_with(4, j, md).unwrap()[0];
            let stop = d.force() * if d.force() > e.force() { 1.05 } else { 0.95 };
            let window = e.force().min(stop)..=e.force().max(stop);
            if let Ok(b) = hockle::elastica::bifurcation(4, j) {
                assert!(!window.contains(&b.force()), "{b} in the window of {d}");
            }
            assert_rod_agrees(stiffness, e, stop, &[d]);
            checked += 1;
        }
    }
    // one each (measured: 1.1e-13 … 6.3e-11 relative in force)
    assert_eq!(checked, 5, "diamonds checked");
}
