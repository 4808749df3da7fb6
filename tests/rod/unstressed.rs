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
        Rod::nikolai(4, 89.8_f64.to_radians(), 10.0, 0.05).unwrap(),
        Rod::nikolai(1, 60_f64.to_radians(), 0.1, 0.3).unwrap(),
        Rod::new(7, 88_f64.to_radians(), 3.0, 1.0, 0.5).unwrap(),
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
    let rod = Rod::nikolai(4, 89.8_f64.to_radians(), 10.0, 0.05).unwrap();
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
