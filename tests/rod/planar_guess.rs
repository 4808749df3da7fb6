//! The rod's state for a planar elastica at θ0 = 90°, a starting guess
//! shared by the tests that start the 3D rod on a planar branch.

use std::f64::consts::PI;

use hockle::elastica::Elastica;

/// The rod's state (tests/rod/planar.rs: position, quaternion, force,
/// moment) for the planar solution `e`, as a starting guess only (Newton
/// polishes it): tangent t = sin φ i + cos φ k with φ(½) = π, the frame
/// turned by φ about j = d2, moment κ − κ0 about d2.
pub fn planar_guess(e: Elastica) -> impl Fn(f64) -> [f64; 13] {
    let samples = 4001;
    let c = e.centreline(samples).unwrap();
    let kappa0 = 8.0 * PI;
    let step = 1.0 / (samples - 1) as f64;
    // φ unwrapped from the Jacobi functions of the module docs, shifted so
    // that φ(½) = π (the υ-shape's midpoint tangent is against the force)
    let mut phi = Vec::with_capacity(samples);
    for i in 0..samples {
        let j = hockle::special::jacobi(
            e.omega() * (e.start() + i as f64 * step),
            e.elliptic_modulus(),
        );
        let raw = (-2.0 * j.sn * j.cn).atan2(2.0 * j.sn * j.sn - 1.0);
        let prev: f64 = phi.last().copied().unwrap_or(raw);
        phi.push(prev + (raw - prev + PI).rem_euclid(2.0 * PI) - PI);
    }
    let shift = ((PI - phi[samples / 2]) / (2.0 * PI)).round() * 2.0 * PI;
    let force = e.force();
    move |s: f64| {
        let i = ((s / step).round() as usize).min(samples - 1);
        let t = phi[i] + shift;
        let mut y = [0.0; 13];
        y[0] = -c[i].x;
        y[2] = c[i].y;
        y[3] = (t / 2.0).cos();
        y[5] = (t / 2.0).sin();
        y[9] = force;
        y[11] = e.curvature(i as f64 * step) - kappa0;
        y
    }
}
