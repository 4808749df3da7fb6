//! The true error of a curve against a converged reference, measured here
//! and not by the crate: shared by `tests/spring/choice.rs` and
//! `examples/models.rs` (which includes this file by path).
//!
//! A curve is what a [`Response`] returns: its points joined by their
//! Hermite interpolant (`common::hermite`, written out from the points,
//! slopes and curvatures; linear where a slope is missing), and its located
//! folds as points of their own (the
//! curve's points exclude them; folds read off the curve itself are not
//! drawn). Distances are
//! max-norm in (Δz, F/((2πn)²B)).
#![allow(dead_code)]

use hockle::curve::ForceExtension;
use hockle::spring::Response;
use hockle::{Control, FoldKind};

/// One piece of a curve: a Hermite segment of the curve, or a line.
#[derive(Clone, Copy)]
enum Piece {
    Segment(usize),
    Line([f64; 2], [f64; 2]),
}

/// A curve as pieces, ready to measure.
pub struct Drawn<'a> {
    curve: &'a ForceExtension,
    pieces: Vec<Piece>,
}

/// The pieces of a response's curve with its located folds (module docs).
pub fn drawn(response: &Response) -> Drawn<'_> {
    let curve = response.curve();
    let scale = curve.force_scale();
    let mut pieces: Vec<Piece> = (0..curve.len().saturating_sub(1))
        .map(Piece::Segment)
        .collect();
    pieces.extend(
        response
            .folds()
            .iter()
            .filter(|f| located(response.target().control(), f.kind))
            .map(|f| {
                let p = [f.point.extension, f.point.force / scale];
                Piece::Line(p, p)
            }),
    );
    Drawn { curve, pieces }
}

/// Whether a fold of `kind` is one the pull located (a fold of its
/// controlled load); the others are read off the curve.
fn located(control: Control, kind: FoldKind) -> bool {
    match control {
        Control::Force => matches!(kind, FoldKind::MaxForce | FoldKind::MinForce),
        Control::Extension => matches!(kind, FoldKind::MaxExtension | FoldKind::MinExtension),
    }
}

/// The pieces of a bare curve (no folds).
pub fn bare(curve: &ForceExtension) -> Drawn<'_> {
    Drawn {
        curve,
        pieces: (0..curve.len().saturating_sub(1))
            .map(Piece::Segment)
            .collect(),
    }
}

impl Drawn<'_> {
    /// The point of piece `k` at τ ∈ [0, 1].
    fn at(&self, k: usize, t: f64) -> [f64; 2] {
        match self.pieces[k] {
            Piece::Segment(i) => hermite(self.curve, i, t),
            Piece::Line(a, b) => [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])],
        }
    }

    /// Max-norm distance from `p` to these pieces: each piece sampled at 9
    /// points; a piece can come no closer than its nearest sample minus half
    /// its largest gap between samples, so pieces are refined (golden
    /// section on each eighth) in the order of that bound until it exceeds
    /// the best distance found.
    pub fn distance_to(&self, p: [f64; 2]) -> f64 {
        let d = |q: [f64; 2]| (q[0] - p[0]).abs().max((q[1] - p[1]).abs());
        let mut bounds: Vec<(f64, usize)> = (0..self.pieces.len())
            .map(|k| {
                let samples: Vec<[f64; 2]> =
                    (0..=8).map(|j| self.at(k, f64::from(j) / 8.0)).collect();
                let nearest = samples.iter().map(|q| d(*q)).fold(f64::INFINITY, f64::min);
                let gap = samples
                    .windows(2)
                    .map(|w| (w[0][0] - w[1][0]).abs().max((w[0][1] - w[1][1]).abs()))
                    .fold(0.0, f64::max);
                (nearest - gap, k)
            })
            .collect();
        bounds.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut best = f64::INFINITY;
        for &(bound, k) in &bounds {
            if bound > best {
                break;
            }
            for j in 0..8 {
                let (mut lo, mut hi) = (f64::from(j) / 8.0, f64::from(j + 1) / 8.0);
                for _ in 0..50 {
                    let a = hi - 0.618_033_988_749_895 * (hi - lo);
                    let b = lo + 0.618_033_988_749_895 * (hi - lo);
                    if d(self.at(k, a)) < d(self.at(k, b)) {
                        hi = b;
                    } else {
                        lo = a;
                    }
                }
                best = best
                    .min(d(self.at(k, 0.5 * (lo + hi))))
                    .min(d(self.at(k, f64::from(j) / 8.0)));
            }
            best = best.min(d(self.at(k, 1.0)));
        }
        best
    }

    /// The largest distance from these pieces (each sampled at 9 points)
    /// to `other`.
    pub fn distance(&self, other: &Drawn<'_>) -> f64 {
        self.farthest(other).0
    }

    /// The largest distance from these pieces to `other`, and the sample
    /// where it is reached.
    pub fn farthest(&self, other: &Drawn<'_>) -> (f64, [f64; 2]) {
        let mut worst = (0.0, [f64::NAN; 2]);
        for k in 0..self.pieces.len() {
            for j in 0..=8 {
                let p = self.at(k, f64::from(j) / 8.0);
                let d = other.distance_to(p);
                if d > worst.0 {
                    worst = (d, p);
                }
            }
        }
        worst
    }
}

/// The distance between two curves both ways (the larger): what one curve
/// claims and what it leaves out.
pub fn both_ways(a: &Drawn<'_>, b: &Drawn<'_>) -> f64 {
    a.distance(b).max(b.distance(a))
}

pub use crate::common::hermite;
