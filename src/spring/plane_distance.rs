//! Distances in the plane (Δz, F/((2πn)²B)) of the paper's plots, in the
//! max norm of every tolerance in [`crate::spring`].

/// A point of the plane: (Δz, F/((2πn)²B)).
pub(super) type PlanePoint = [f64; 2];

/// Max-norm distance from `p` to the segment [a, b], exactly.
///
/// Along the segment, g(t) = max(|u + t dx|, |v + t dy|) with
/// (u, v) = a − p and (dx, dy) = b − a is convex and piecewise linear: its
/// minimum over [0, 1] lies at an end, where one of the two terms vanishes,
/// or where they are equal (u + t dx = ±(v + t dy)).
pub(super) fn to_segment(p: PlanePoint, a: PlanePoint, b: PlanePoint) -> f64 {
    let (u, v) = (a[0] - p[0], a[1] - p[1]);
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let g = |t: f64| (u + t * dx).abs().max((v + t * dy).abs());
    let candidates = [
        (dx != 0.0).then(|| -u / dx),
        (dy != 0.0).then(|| -v / dy),
        (dx != dy).then(|| (v - u) / (dx - dy)),
        (dx != -dy).then(|| -(u + v) / (dx + dy)),
    ];
    candidates
        .into_iter()
        .flatten()
        .filter(|t| t.is_finite())
        .map(|t| g(t.clamp(0.0, 1.0)))
        .fold(g(0.0).min(g(1.0)), f64::min)
}

/// Max-norm distance from `p` to the polyline through `line` (infinite for
/// an empty line, the distance to the point for one point).
fn to_polyline(p: PlanePoint, line: &[PlanePoint]) -> f64 {
    match line {
        [] => f64::INFINITY,
        [q] => to_segment(p, *q, *q),
        _ => line
            .windows(2)
            .map(|w| to_segment(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min),
    }
}

/// The larger of the two one-way distances between polylines `a` and `b`
/// whose forces (second coordinates) rise along them (what one claims that
/// the other lacks, both ways), each measured from the vertices and segment
/// midpoints of one polyline to the other.
///
/// Only the segments of `to` whose forces lie within the best distance so
/// far of a point's force can be nearer: they are searched outward from
/// the point's force, so a pass costs O(N log N) for curves that do not
/// fold back in force.
pub(super) fn both_ways_rising(a: &[PlanePoint], b: &[PlanePoint]) -> f64 {
    let one_way = |from: &[PlanePoint], to: &[PlanePoint]| {
        let midpoints = from
            .windows(2)
            .map(|w| [0.5 * (w[0][0] + w[1][0]), 0.5 * (w[0][1] + w[1][1])]);
        from.iter()
            .copied()
            .chain(midpoints)
            .map(|p| to_rising(p, to))
            .fold(0.0, f64::max)
    };
    one_way(a, b).max(one_way(b, a))
}

/// [`to_polyline`] for a polyline whose forces rise along it.
fn to_rising(p: PlanePoint, line: &[PlanePoint]) -> f64 {
    if line.len() < 2 {
        return to_polyline(p, line);
    }
    let segments = line.len() - 1;
    // the first segment whose upper end is at or above p's force
    let first = line[1..].partition_point(|q| q[1] < p[1]).min(segments - 1);
    let mut best = f64::INFINITY;
    for j in (0..=first).rev() {
        if p[1] - line[j + 1][1] >= best {
            break;
        }
        best = best.min(to_segment(p, line[j], line[j + 1]));
    }
    for j in first + 1..segments {
        if line[j][1] - p[1] >= best {
            break;
        }
        best = best.min(to_segment(p, line[j], line[j + 1]));
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The segment's distance against a dense scan of it (the scan is
    /// above the minimum by at most the max-norm step of its samples).
    #[test]
    fn the_closed_form_is_the_minimum_along_the_segment() {
        let cases = [
            ([0.3, 0.7], [0.0, 0.0], [1.0, 0.2]),
            ([2.0, -1.0], [0.0, 0.0], [1.0, 0.2]),
            ([0.5, 0.5], [0.0, 1.0], [1.0, 0.0]),
            ([0.1, 0.1], [0.2, 0.3], [0.2, 0.3]),
            ([-0.4, 3.0], [0.0, 0.0], [0.0, 1.0]),
        ];
        for (p, a, b) in cases {
            let steps = 100_000;
            let scanned = (0..=steps)
                .map(|i| {
                    let t = f64::from(i) / f64::from(steps);
                    let q = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
                    (q[0] - p[0]).abs().max((q[1] - p[1]).abs())
                })
                .fold(f64::INFINITY, f64::min);
            let exact = to_segment(p, a, b);
            assert!(exact <= scanned + 1e-15, "{p:?} {a:?} {b:?}");
            assert!(
                scanned - exact <= 2e-5,
                "{p:?} {a:?} {b:?}: {exact} {scanned}"
            );
        }
    }

    #[test]
    fn two_parallel_lines_are_their_offset_apart_both_ways() {
        let a: Vec<PlanePoint> = (0..=10).map(|i| [0.0, f64::from(i) * 0.1]).collect();
        let b: Vec<PlanePoint> = (0..=10).map(|i| [0.25, f64::from(i) * 0.1]).collect();
        assert_eq!(both_ways_rising(&a, &b), 0.25);
        // a shorter line is close one way, not the other
        assert_eq!(both_ways_rising(&a, &a[..6]), 0.5);
    }

    /// The outward search finds what a search of every segment finds, on a
    /// curve rising in force that wanders in Δz.
    #[test]
    fn the_outward_search_is_the_full_search() {
        let line: Vec<PlanePoint> = (0..60)
            .map(|i| {
                let f = f64::from(i) / 59.0;
                [0.3 * (7.0 * f).sin() + f, f * f]
            })
            .collect();
        for j in 0..200 {
            let t = f64::from(j) / 199.0;
            let p = [1.5 * (13.0 * t).cos(), 1.4 * t - 0.2];
            assert_eq!(to_rising(p, &line), to_polyline(p, &line), "{p:?}");
        }
    }
}
