//! The unstressed helix is an exact solution at F = 0.

use core::f64::consts::PI;

use hockle::bvp::Problem;
use hockle::rod::Rod;

/// Residuals of the closed-form helix are rounding errors of O(1) quantities
/// times at most the largest derivative scale 2πn ≈ 25: 1e-14 absolute.
const EXACT: f64 = 1e-14;

/// y′(s) of the closed form, differentiated by hand (independently of the
/// rhs): r′ = d3 = (S cos φ, S sin φ, c), q′ = β′ (−sin β cos a, −sin β sin a,
/// cos β sin a, cos β cos a) with β′ = πn.
fn derivative(rod: &Rod, s: f64) -> [f64; 13] {
    let n = f64::from(rod.coils());
    let phi = 2.0 * PI * n * s;
    let (sn, cs) = rod.theta0().sin_cos();
    let beta = (phi + PI / 2.0) / 2.0;
    let (sb, cb) = beta.sin_cos();
    let (sa, ca) = (rod.theta0() / 2.0).sin_cos();
    let bp = PI * n;
    let mut d = [0.0; 13];
    d[0] = sn * phi.cos();
    d[1] = sn * phi.sin();
    d[2] = cs;
    d[3] = -bp * sb * ca;
    d[4] = -bp * sb * sa;
    d[5] = bp * cb * sa;
    d[6] = bp * cb * ca;
    d
}

fn rods() -> Vec<Rod> {
    vec![
        Rod::new(
            4,
            89.8_f64.to_radians(),
            hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
        )
        .unwrap(),
        Rod::new(
            1,
            60_f64.to_radians(),
            hockle::Stiffness::nikolai(0.1, 0.3).unwrap(),
        )
        .unwrap(),
        Rod::new(
            7,
            88_f64.to_radians(),
            hockle::Stiffness::new(3.0, 1.0, 0.5).unwrap(),
        )
        .unwrap(),
    ]
}

#[test]
fn ode_residual_is_rounding() {
    for rod in rods() {
        let p = rod.parameters_at_rest();
        let mut f = [0.0; 13];
        let mut worst = 0.0_f64;
        for i in 0..=200 {
            let s = f64::from(i) / 200.0;
            let y = rod.unstressed(s);
            rod.rhs(s, &y, &p, &mut f);
            let d = derivative(&rod, s);
            for k in 0..13 {
                worst = worst.max((f[k] - d[k]).abs());
            }
        }
        assert!(worst < EXACT, "{rod}: ODE residual {worst:e}");
    }
}

#[test]
fn boundary_and_phase_residuals_are_rounding() {
    for rod in rods() {
        let p = rod.parameters_at_rest();
        let mut g = [0.0; 12];
        rod.boundary(&rod.unstressed(0.0), &rod.unstressed(1.0), &p, &mut g);
        let worst = g.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
        assert!(worst < EXACT, "{rod}: BC residual {worst:e}");
        // The phase condition against itself vanishes pointwise (G is
        // antisymmetric).
        let mut h = [0.0];
        for i in 0..=50 {
            let y = rod.unstressed(f64::from(i) / 50.0);
            rod.integrand(0.0, &y, &y, &p, &mut h);
            assert!(h[0].abs() < 1e-16);
        }
    }
}

#[test]
fn the_helix_has_the_intended_geometry() {
    // Frame from the quaternion: d1 = (−sin φ, cos φ, 0), d3 = (S cos φ, S sin φ, c).
    let rod = Rod::new(
        4,
        89.8_f64.to_radians(),
        hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let (sn, cs) = rod.theta0().sin_cos();
    for i in 0..=40 {
        let s = f64::from(i) / 40.0;
        let y = rod.unstressed(s);
        let q = hockle::nalgebra::UnitQuaternion::from_quaternion(
            hockle::nalgebra::Quaternion::new(y[3], y[4], y[5], y[6]),
        );
        let phi = 2.0 * PI * 4.0 * s;
        let d1 = q * hockle::nalgebra::Vector3::x();
        let d3 = q * hockle::nalgebra::Vector3::z();
        assert!((d1 - hockle::nalgebra::Vector3::new(-phi.sin(), phi.cos(), 0.0)).norm() < 1e-14);
        assert!(
            (d3 - hockle::nalgebra::Vector3::new(sn * phi.cos(), sn * phi.sin(), cs)).norm()
                < 1e-14
        );
    }
}

#[test]
fn outputs_of_the_solved_helix() {
    use hockle::bvp::Collocation;
    use hockle::rod::Equilibrium;
    let rod = Rod::new(
        4,
        89.8_f64.to_radians(),
        hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let p = rod.parameters_at_rest();
    let sol = Collocation::new()
        .intervals(40)
        .solve(&rod, |s: f64| rod.unstressed(s), &p)
        .unwrap();
    let e = Equilibrium::new(rod, sol).unwrap();
    // At F = 0 Newton keeps M = F = 0 exactly and u = u0; only the
    // collocation error of the frame's rotation remains: O(h⁸) at mesh
    // points (measured 1.2e-13 in Δz with 40 intervals), O(h⁵) between them
    // (measured 1.5e-11 in the turning number from 320 samples).
    assert!(e.force().abs() < 1e-12);
    assert!((e.extension() - rod.theta0().cos()).abs() < 1e-11);
    assert!(e.energy() < 1e-20);
    assert_eq!(e.loops(), Some(4));
    assert!((e.axial_turns() - 4.0).abs() < 1e-9);
    assert!((e.turning_number() - 4.0).abs() < 1e-9);
    // Distance from the best plane through the axis: the radius R0.
    let r0 = rod.theta0().sin() / (8.0 * PI);
    // Sampled at the mesh and Gauss points: the largest gap is 0.33 h, a
    // turn of 2π·4·0.33/40 = 0.21 rad, so the max is missed by at most
    // 1 − cos(0.105) = 5.4e-3 relative.
    assert!(
        (e.planarity() - r0).abs() < 1e-2 * r0,
        "{} vs {r0}",
        e.planarity()
    );
    assert!((e.curvature(0.3).unwrap() - 8.0 * PI * rod.theta0().sin()).abs() < 1e-12);
    assert!((e.twist(0.3).unwrap() - 8.0 * PI * rod.theta0().cos()).abs() < 1e-12);
    assert!(e.quaternion_drift() < 1e-15);
    assert!(e.state(1.5).is_err());
}

#[test]
fn the_force_is_the_energy_derivative() {
    // dU/dΔz = F_z along a force-controlled branch: U(F ± h), Δz(F ± h) by
    // central differences (O(h²): measured 6.7e-6 relative with h = 0.5 and
    // 2.9e-7 with h = 0.1 at F = 60,
    // with the solutions converged to 1e-10).
    use hockle::bvp::Collocation;
    use hockle::rod::Equilibrium;
    let rod = Rod::new(
        4,
        89.8_f64.to_radians(),
        hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let solver = Collocation::new().intervals(60);
    let mut p = rod.parameters_at_rest();
    let mut sol = solver.solve(&rod, |s: f64| rod.unstressed(s), &p).unwrap();
    for f in [20.0, 40.0, 59.9] {
        p[0] = f;
        sol = solver.solve(&rod, &sol, &p).unwrap();
    }
    let e_m = Equilibrium::new(rod, sol.clone()).unwrap();
    p[0] = 60.1;
    let e_p = Equilibrium::new(rod, solver.solve(&rod, &sol, &p).unwrap()).unwrap();
    let du = e_p.energy() - e_m.energy();
    let dz = e_p.extension() - e_m.extension();
    assert!(
        ((du / dz) / 60.0 - 1.0).abs() < 1e-5,
        "dU/dΔz = {}",
        du / dz
    );
}
