//! `elastica::OutOfPlane`: the linearised out-of-plane equations against
//! exact solutions (the two rigid motions of a planar equilibrium), the
//! spatial balance laws (first integrals not used by the material-frame
//! equations), the diamonds' independence of the shooting tolerance, and
//! bad input. The cross-check with the 3D rod is in tests/rod/diamonds.rs.

use core::f64::consts::PI;

use hockle::elastica::{Arm, Branch, Elastica, OutOfPlane};
use hockle::special::{Modulus, jacobi};
use hockle::{Error, Stiffness};

/// The integration is controlled to 1e-13 relative to the largest
/// component; over the ≲ 100 steps of one pass the global error stays
/// below 1e-11 of the solution's size (measured ≤ 3e-13 here).
const EXACT_TOL: f64 = 1e-11;

/// The brief's location accuracy in k: the diamonds at the default
/// tolerance 1e-13 and at 1e-11 (100× looser) agree to this; the root finder
/// stops at a bracket of 1e-10 in k, so two runs may differ by that.
const K_AGREE: f64 = 2e-10;

/// The same in the force, relative: the bracket closes to 1e-12 in F;
/// measured agreement ≤ 1e-11 on j = 1 (1 − k ≈ 3e-8), where a step of
/// 1e-10 in k would be 1e-5 in F.
const F_AGREE: f64 = 1e-10;

fn oop() -> OutOfPlane {
    OutOfPlane::new(4, Stiffness::nikolai(10.0, 0.05).unwrap()).unwrap()
}

/// Test solutions on every kind of branch the module handles.
fn solutions() -> Vec<Elastica> {
    let m = |k: f64| Modulus::from_k(k).unwrap();
    vec![
        Elastica::upsilon(4, m(0.5)).unwrap(),
        Elastica::upsilon(4, m(0.99)).unwrap(),
        Elastica::alpha(4, m(0.9)).unwrap(),
        Elastica::secondary_arm(4, 3, Arm::Lower, m(0.95)).unwrap(),
        Elastica::secondary_arm(4, 2, Arm::Upper, m(0.99)).unwrap(),
    ]
}

/// sin φ, cos φ of the tangent t = sin φ i + cos φ k (module docs).
fn angle(e: &Elastica, s: f64) -> (f64, f64) {
    let j = jacobi(e.start() * e.omega() + e.omega() * s, e.elliptic_modulus());
    (-2.0 * j.sn * j.cn, 2.0 * j.sn * j.sn - 1.0)
}

/// The centreline (x, z) at s by the crate's own quadrature of eq5
/// (`Elastica::centreline`, checked against mpmath in tests/elastica), in
/// the frame t = sin φ i + cos φ k: `centreline` draws the mirror image
/// x → −x.
fn position(e: &Elastica, s: f64) -> (f64, f64) {
    let n = 1001;
    let c = e.centreline(n).unwrap();
    let i = (s * (n - 1) as f64).round() as usize;
    (-c[i].x, c[i].y)
}

#[test]
fn the_rigid_rotations_are_exact_solutions() {
    let oop = oop();
    for e in solutions() {
        let f = e.force();
        for s in [0.3, 0.7, 1.0] {
            let (sin0, cos0) = angle(&e, 0.0);
            let (sin, cos) = angle(&e, s);
            let (x, z) = position(&e, s);
            // about k: ψ = k = (k·d1, k·d3) = (−sin φ, cos φ), w = x, P = 0
            let y = oop
                .integrate(&e, [-sin0, cos0, 0.0, 0.0, 0.0], 0.0, s)
                .unwrap();
            let want = [-sin, cos, 0.0, 0.0, x];
            // about i: ψ = i = (cos φ, sin φ), w = −z, P = −F
            let y2 = oop
                .integrate(&e, [cos0, sin0, 0.0, 0.0, 0.0], -f, s)
                .unwrap();
            let want2 = [cos, sin, 0.0, 0.0, -z];
            for (got, want) in [(y, want), (y2, want2)] {
                // moments in units of F (the size of the forcing)
                let scale = [1.0, 1.0, f, f, 1.0];
                for i in 0..5 {
                    assert!(
                        (got[i] - want[i]).abs() < EXACT_TOL * scale[i],
                        "{e}, s = {s}, component {i}: {} vs {}",
                        got[i],
                        want[i]
                    );
                }
            }
        }
    }
}

#[test]
fn the_unit_force_solution_keeps_the_spatial_moment_balance() {
    // δM′ = −δt × F − t × δF integrates to k·δM = −P x and i·δM = P z − F w
    // (δM = δm + ψ × m_base, m_base = (0, κ − κ0, 0)): the global balance,
    // not the material-frame equations the module integrates.
    let oop = oop();
    for e in solutions() {
        let kappa0 = 8.0 * PI;
        let mut size: f64 = 1.0;
        for s in [0.25, 0.5, 0.75, 1.0] {
            let y = oop.integrate(&e, [0.0; 5], 1.0, s).unwrap();
            size = y.iter().fold(size, |a, v| a.max(v.abs()));
            let (sin, cos) = angle(&e, s);
            let (x, z) = position(&e, s);
            let mu = e.curvature(s) - kappa0;
            let dm1 = y[2] - y[1] * mu;
            let dm3 = y[3] + y[0] * mu;
            // k·d1 = −sin φ, k·d3 = cos φ; i·d1 = cos φ, i·d3 = sin φ
            let mz = -dm1 * sin + dm3 * cos;
            let mx = dm1 * cos + dm3 * sin;
            // x, z from the 1001-point centreline: s on its grid, exact
            let tol = EXACT_TOL * size.max(e.force());
            assert!((mz + x).abs() < tol, "{e}, s = {s}: k·δM {mz} vs {}", -x);
            assert!(
                (mx - (z - e.force() * y[4])).abs() < tol,
                "{e}, s = {s}: i·δM {mx}"
            );
        }
        // and D is i·δM(1)
        let y = oop.integrate(&e, [0.0; 5], 1.0, 1.0).unwrap();
        let (sin, cos) = angle(&e, 1.0);
        let d = oop.determinant(&e).unwrap();
        assert!((d - (y[2] * cos + y[3] * sin)).abs() <= 1e-15 * size);
    }
}

#[test]
fn the_diamonds_do_not_depend_on_the_shooting_tolerance() {
    let fine = oop();
    let coarse = oop().tolerance(1e-11).unwrap();
    for branch in [
        Branch::Upsilon,
        Branch::Alpha,
        Branch::Secondary {
            j: 3,
            arm: Arm::Lower,
        },
        Branch::Secondary {
            j: 3,
            arm: Arm::Upper,
        },
    ] {
        let a = fine.diamonds(branch, 1.5).unwrap();
        let b = coarse.diamonds(branch, 1.5).unwrap();
        assert!(!a.is_empty(), "{branch}");
        assert_eq!(a.len(), b.len(), "{branch}");
        for (x, y) in a.iter().zip(&b) {
            assert!(
                (x.modulus() - y.modulus()).abs() < K_AGREE
                    && (x.force() / y.force() - 1.0).abs() < F_AGREE,
                "{branch}: {x} vs {y}"
            );
            // D changes sign there: on each side of the bracket
            let k = x.modulus();
            let at = |k: f64| {
                let md = Modulus::from_k(k).unwrap();
                let e = match branch {
                    Branch::Upsilon => Elastica::upsilon(4, md),
                    Branch::Alpha => Elastica::alpha(4, md),
                    Branch::Secondary { j, arm } => Elastica::secondary_arm(4, j, arm, md),
                    _ => unreachable!(),
                };
                fine.determinant(&e.unwrap()).unwrap()
            };
            assert!(at(k - 1e-8) * at(k + 1e-8) < 0.0, "{x}");
        }
    }
}

#[test]
fn the_primary_diamond_is_on_the_paper_figure_and_only_its_location_depends_on_c() {
    // The paper's Fig. spring (A/B = 10, ν = 0.05) has its υ diamond just
    // above the spring's first pop-out (F/(2πn)² ≈ 0.60 in hockle's units,
    // the 3D rod's value; see tests/rod/planar.rs).
    let d = oop().diamonds(Branch::Upsilon, 1.2).unwrap();
    assert_eq!(d.len(), 1);
    assert!(d[0].force_scaled() > 0.6026 && d[0].force_scaled() < 0.8);
    // a softer twist moves it; the branch (force at a given k) is the same
    let stiff = OutOfPlane::new(4, Stiffness::new(10.0, 1.0, 1.0).unwrap()).unwrap();
    let d2 = stiff.diamonds(Branch::Upsilon, 1.2).unwrap();
    assert!((d2[0].modulus() - d[0].modulus()).abs() > 1e-3);
}

#[test]
fn bad_input_is_a_typed_error() {
    let s = Stiffness::nikolai(10.0, 0.05).unwrap();
    assert!(matches!(
        OutOfPlane::new(0, s),
        Err(Error::InvalidCount { name: "n", .. })
    ));
    for t in [0.0, -1.0, f64::NAN, 1.0, 1e-16] {
        assert!(matches!(
            oop().tolerance(t),
            Err(Error::InvalidArgument {
                name: "tolerance",
                ..
            })
        ));
    }
    assert!(oop().grid(1).is_err());
    let e3 = Elastica::upsilon(3, Modulus::from_k(0.5).unwrap()).unwrap();
    assert!(matches!(
        oop().determinant(&e3),
        Err(Error::InvalidCount { name: "coils", .. })
    ));
    let e = Elastica::upsilon(4, Modulus::from_k(0.5).unwrap()).unwrap();
    for end in [-0.1, 1.5, f64::NAN] {
        assert!(oop().integrate(&e, [0.0; 5], 1.0, end).is_err());
    }
    assert!(oop().integrate(&e, [f64::NAN; 5], 1.0, 1.0).is_err());
    assert!(oop().integrate(&e, [0.0; 5], f64::INFINITY, 1.0).is_err());
    for f in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(oop().diamonds(Branch::Upsilon, f).is_err(), "{f}");
    }
    assert!(
        oop()
            .diamonds(
                Branch::Secondary {
                    j: 4,
                    arm: Arm::Lower
                },
                1.0
            )
            .is_err()
    );
}
