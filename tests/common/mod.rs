//! Shared test helpers: the tolerance policy and error measures.
//!
//! Every tolerance in a test is a named constant here or next to the test,
//! with one reason each. Failures print the error in units of ε (ulps).
#![allow(dead_code)]

/// Relative error |x − r| / |r| (absolute when r = 0).
pub fn rel_err(x: f64, r: f64) -> f64 {
    if r == 0.0 {
        x.abs()
    } else {
        ((x - r) / r).abs()
    }
}

/// Error of `x` against the reference `r` in units of ε·|r| (ulps of the
/// reference; for r = 0 in units of the smallest normal number).
pub fn ulps(x: f64, r: f64) -> f64 {
    if x == r {
        return 0.0;
    }
    if r == 0.0 {
        return x.abs() / f64::MIN_POSITIVE;
    }
    ((x - r) / r).abs() / f64::EPSILON
}

/// A point of the Hermite interpolant of segment `i` of `c` at τ ∈ [0, 1],
/// in (Δz, F/((2πn)²B)), written out in the Hermite basis from the points,
/// slopes and curvatures (not through the crate's own interpolant, which
/// uses the power basis): quintic where both ends carry a curvature, cubic
/// where both carry a slope, linear otherwise.
pub fn hermite(c: &hockle::ForceExtension, i: usize, t: f64) -> [f64; 2] {
    let (a, b) = (c.points()[i], c.points()[i + 1]);
    let scale = c.force_scale();
    let h = b.parameter - a.parameter;
    let (s, u) = (t, 1.0 - t);
    match (c.slope(i), c.slope(i + 1)) {
        (Some(sa), Some(sb)) if h > 0.0 => {
            if let (Some(ca), Some(cb)) = (c.curvature(i), c.curvature(i + 1)) {
                // triple nodes at 0 and 1
                let h0 = u.powi(3) * (1.0 + 3.0 * s + 6.0 * s * s);
                let h1 = s * u.powi(3) * (1.0 + 3.0 * s);
                let h2 = 0.5 * s * s * u.powi(3);
                let g0 = s.powi(3) * (1.0 + 3.0 * u + 6.0 * u * u);
                let g1 = -u * s.powi(3) * (1.0 + 3.0 * u);
                let g2 = 0.5 * u * u * s.powi(3);
                let q = |p: [f64; 6]| {
                    h0 * p[0]
                        + h1 * h * p[1]
                        + h2 * h * h * p[2]
                        + g0 * p[3]
                        + g1 * h * p[4]
                        + g2 * h * h * p[5]
                };
                let x = q([
                    a.extension,
                    sa.extension,
                    ca.extension,
                    b.extension,
                    sb.extension,
                    cb.extension,
                ]);
                let f = q([a.force, sa.force, ca.force, b.force, sb.force, cb.force]);
                return [x, f / scale];
            }
            let (t2, t3) = (t * t, t * t * t);
            let (h00, h10) = (2.0 * t3 - 3.0 * t2 + 1.0, t3 - 2.0 * t2 + t);
            let (h01, h11) = (-2.0 * t3 + 3.0 * t2, t3 - t2);
            let x = h00 * a.extension
                + h10 * h * sa.extension
                + h01 * b.extension
                + h11 * h * sb.extension;
            let f = h00 * a.force + h10 * h * sa.force + h01 * b.force + h11 * h * sb.force;
            [x, f / scale]
        }
        _ => [
            a.extension + t * (b.extension - a.extension),
            (a.force + t * (b.force - a.force)) / scale,
        ],
    }
}
