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

/// Max-norm distance in (Δz, F/((2πn)²B)) from `p` to the interpolant of
/// `reference` ([`hermite`]): the three nearest segments by nine samples
/// each, then golden section on each eighth of them.
pub fn distance_to_curve(reference: &hockle::ForceExtension, p: [f64; 2]) -> f64 {
    let d = |q: [f64; 2]| (q[0] - p[0]).abs().max((q[1] - p[1]).abs());
    let mut near: Vec<(f64, usize)> = (0..reference.len() - 1)
        .map(|i| {
            let best = (0..=8)
                .map(|k| d(hermite(reference, i, f64::from(k) / 8.0)))
                .fold(f64::INFINITY, f64::min);
            (best, i)
        })
        .collect();
    near.sort_by(|a, b| a.0.total_cmp(&b.0));
    let g = 0.618_033_988_749_895;
    let mut best = f64::INFINITY;
    for &(_, i) in near.iter().take(3) {
        for k in 0..8 {
            let (mut lo, mut hi) = (f64::from(k) / 8.0, f64::from(k + 1) / 8.0);
            for _ in 0..60 {
                let (a, b) = (hi - g * (hi - lo), lo + g * (hi - lo));
                if d(hermite(reference, i, a)) < d(hermite(reference, i, b)) {
                    hi = b;
                } else {
                    lo = a;
                }
            }
            best = best.min(d(hermite(reference, i, 0.5 * (lo + hi))));
        }
    }
    best
}

/// The largest distance from the interpolant of `curve` (its points and
/// the midpoints of its segments, where the interpolant's error peaks) to
/// the interpolant of `reference`.
pub fn curve_distance(curve: &hockle::ForceExtension, reference: &hockle::ForceExtension) -> f64 {
    let mut worst: f64 = 0.0;
    for i in 0..curve.len() - 1 {
        for t in [0.0, 0.5] {
            worst = worst.max(distance_to_curve(reference, hermite(curve, i, t)));
        }
    }
    worst
}

/// Uniform numbers in [0, 1) on a grid of 1e-6 from Marsaglia's xorshift
/// (13, 7, 17): the fresh random scenes of the tests and examples, from a
/// seed chosen once and written beside each use.
pub fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 1_000_000) as f64 / 1e6
    }
}

/// The closed form of Troesch's problem at μ = 10 at 20 points, denser in
/// the layer at s = 1: (s, y, y′) from tests/data/troesch_mu10.py (mpmath,
/// 40 digits, printed to 20).
pub fn troesch_mu10() -> Vec<[f64; 3]> {
    include_str!("../data/troesch_mu10.csv")
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2]]
        })
        .collect()
}

/// The largest |Δy|, |Δy′| of a Troesch solution at the points of
/// [`troesch_mu10`].
pub fn troesch_mu10_error(sol: &hockle::bvp::Solution, table: &[[f64; 3]]) -> f64 {
    table
        .iter()
        .map(|&[s, y, dy]| {
            let v = sol.eval(s);
            (v[0] - y).abs().max((v[1] - dy).abs())
        })
        .fold(0.0, f64::max)
}

/// Each fold of `run` within `bound` of the same fold of `other` in
/// (Δz, F/((2πn)²B)), max norm; as many folds, of the same kinds.
pub fn assert_same_folds(run: &hockle::rod::PullRun, other: &hockle::rod::PullRun, bound: f64) {
    assert_eq!(run.folds().len(), other.folds().len(), "{run}\n{other}");
    let scale = run.curve().force_scale();
    for (a, b) in run.folds().iter().zip(other.folds()) {
        assert_eq!(a.kind, b.kind);
        let df = (a.point.force - b.point.force).abs() / scale;
        let dz = (a.point.extension - b.point.extension).abs();
        assert!(
            df.max(dz) <= bound,
            "{a:?} against {b:?}: {df:e}, {dz:e} > {bound:e}"
        );
    }
}
