//! The true error of a curve against a converged reference, measured here
//! and not by the crate, and the grid of scenes: shared by
//! `tests/spring/choice.rs` and `examples/models.rs` (which includes this
//! file by path).
//!
//! A curve is what a [`Response`] returns: its points joined by their
//! Hermite interpolant (`common::hermite`, written out from the points,
//! slopes and curvatures; linear where a slope is missing), and its located
//! folds as points of their own (the
//! curve's points exclude them; folds read off the curve itself are not
//! drawn). Distances are
//! max-norm in (Δz, F/((2πn)²B)).
#![allow(dead_code)]

use std::ops::ControlFlow;

use hockle::bvp::{Collocation, Mesh, Solution};
use hockle::continuation::Point;
use hockle::curve::ForceExtension;
use hockle::rod::Equilibrium;
use hockle::spring::{Response, RodModel, Spring, Target};
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

/// Steps of a converged reference that may stay within [`CRAWL_SPAN`] of
/// their force before it is given up: a whole reference to F/((2πn)²B) = 1
/// took 83–309 steps on five springs (n = 2–8, θ0 = 88–89.9°, A/B =
/// 0.5–20, ν = 0–0.4, the paper's among them); where loops slide along the rod
/// (negative ν, high force) its fixed mesh gives spurious folds and then
/// steps of 1e-7 relative, 13 000 of them in 8 minutes at (7, 88°, 5,
/// −0.3) before Newton failed.
pub const CRAWL_STEPS: usize = 1000;

/// The relative span of force that [`CRAWL_STEPS`] steps must exceed.
pub const CRAWL_SPAN: f64 = 1e-3;

/// Stops a pull whose last [`CRAWL_STEPS`] points lie within a relative
/// [`CRAWL_SPAN`] of their largest load (the continuation parameter: the
/// force, or Δz under extension control; an observer's `point` hook,
/// [`Crawl::see`]).
#[derive(Default)]
pub struct Crawl {
    recent: std::collections::VecDeque<f64>,
    /// The load where the pull was given up, if it was.
    pub stalled_at: Option<f64>,
}

impl Crawl {
    /// Sees a point: `Break` once the pull crawls.
    pub fn see(&mut self, point: &Point) -> ControlFlow<()> {
        let f = point.parameter();
        self.recent.push_back(f);
        if self.recent.len() > CRAWL_STEPS {
            self.recent.pop_front();
            let (lo, hi) = self
                .recent
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                    (lo.min(*v), hi.max(*v))
                });
            if hi - lo <= CRAWL_SPAN * hi.abs() {
                self.stalled_at = Some(f);
                return ControlFlow::Break(());
            }
        }
        ControlFlow::Continue(())
    }
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

/// The grid: n ∈ {2, 3, 4, 6} × θ0 ∈ {60, 70, 80, 86, 89, 89.9}°,
/// two (A/B, ν) per pair from A/B ∈ {0.1, 0.5, 1, 3, 10, 20} (index
/// i + ⌊i/12⌋ mod 6 of scene i) and ν ∈ {0, 0.1, 0.2, 0.3, 0.4} (3i mod 5),
/// chosen by index, not tuned: 48 scenes (n, θ0 in degrees, A/B, ν).
pub fn grid_scenes() -> Vec<(u32, f64, f64, f64)> {
    let ratios = [0.1, 0.5, 1.0, 3.0, 10.0, 20.0];
    let nus = [0.0, 0.1, 0.2, 0.3, 0.4];
    let mut scenes = Vec::new();
    for n in [2u32, 3, 4, 6] {
        for theta0 in [60.0, 70.0, 80.0, 86.0, 89.0, 89.9] {
            for _ in 0..2 {
                let i = scenes.len();
                // each n shifts the ratios by one, so every θ0 sees most
                // of them across the four n
                scenes.push((n, theta0, ratios[(i + i / 12) % 6], nus[(i * 3) % 5]));
            }
        }
    }
    scenes
}

// Shapes (tests/spring/shape.rs, examples/models --shapes): a converged
// equilibrium at one load and the distance between two centrelines.

/// Intervals per coil of the reference's final solve (m = 7): the
/// collocation error between mesh points is O((2πn h)^8 / 8!) with
/// 2πn h = 2π/40 ≈ 0.16, far below 1e-9; `the_reference_is_converged`
/// measures it against twice as many.
pub const SHAPE_REFERENCE_INTERVALS_PER_COIL: usize = 40;

/// The largest distance between the reference and the same solve on a mesh
/// twice as fine that the reference may have: 100 times below the smallest
/// tolerance tested (1e-6), so its own error cannot hide an answer's.
pub const SHAPE_REFERENCE_CONVERGED: f64 = 1e-8;

/// Centreline samples along s for a distance.
pub const SAMPLES: usize = 2000;

/// The last point of a pull of `spring` to `at` (fixed mesh, module docs),
/// solved again on `per_coil` intervals per coil.
pub fn shape_reference(spring: &Spring, at: Target, per_coil: usize) -> Equilibrium {
    try_shape_reference(spring, at, per_coil).unwrap()
}

/// [`shape_reference`], or why there is none (a pull that fails or stops
/// before `at`, a mesh too large): for the command line of
/// `examples/models`, which must not panic on a scene the reference cannot
/// do.
pub fn try_shape_reference(
    spring: &Spring,
    at: Target,
    per_coil: usize,
) -> Result<Equilibrium, String> {
    let driver = RodModel::default()
        .tolerance(1e-8)
        .intervals(10 * spring.coils() as usize)
        .points(7)
        .driver(spring, at)
        .map_err(|e| e.to_string())?;
    let rod = *driver.rod();
    let mut last: Option<Solution> = None;
    let mut crawl = Crawl::default();
    let run = driver
        .run(|p: &Point| {
            last = Some(p.solution().clone());
            crawl.see(p)
        })
        .map_err(|e| e.to_string())?;
    if let Some(at) = crawl.stalled_at {
        return Err(format!(
            "the reference of {spring} crawled ({CRAWL_STEPS} steps within {CRAWL_SPAN:e} of its \
             load near {at:.6e}; sliding loops, docs/ROADMAP.md)"
        ));
    }
    if !run.reached_target() {
        return Err(format!(
            "the reference of {spring} stopped before {at}: {}",
            run.termination()
        ));
    }
    let last = last.ok_or("the reference has no point")?;
    let intervals = per_coil
        .checked_mul(spring.coils() as usize)
        .ok_or("too many intervals for the reference")?;
    let fine = Collocation::new()
        .points(7)
        .mesh(Mesh::uniform(intervals).map_err(|e| e.to_string())?)
        .newton_tolerance(1e-13)
        .solve(&rod, &last, last.parameters())
        .map_err(|e| e.to_string())?;
    Equilibrium::new(rod, fine).map_err(|e| e.to_string())
}

pub fn centreline(eq: &Equilibrium) -> Vec<[f64; 3]> {
    (0..=SAMPLES)
        .map(|i| {
            let r = eq.centreline(i as f64 / SAMPLES as f64).unwrap();
            [r.x, r.y, r.z]
        })
        .collect()
}

/// max_s |R_z(α) a(s) − b(s)| for the turn α about the force line (z)
/// that makes it least: a scan of 720 turns, then golden sections on the
/// two neighbouring intervals of the best.
pub fn distance_up_to_a_turn(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    let at = |alpha: f64| {
        let (s, c) = alpha.sin_cos();
        a.iter()
            .zip(b)
            .map(|(p, q)| {
                let x = c * p[0] - s * p[1] - q[0];
                let y = s * p[0] + c * p[1] - q[1];
                (x * x + y * y + (p[2] - q[2]).powi(2)).sqrt()
            })
            .fold(0.0, f64::max)
    };
    let step = 2.0 * std::f64::consts::PI / 720.0;
    let best = (0..720)
        .map(|i| -std::f64::consts::PI + i as f64 * step)
        .min_by(|x, y| at(*x).total_cmp(&at(*y)))
        .unwrap();
    let (mut lo, mut hi) = (best - step, best + step);
    for _ in 0..80 {
        let g = 0.618_033_988_749_895;
        let (x, y) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if at(x) < at(y) {
            hi = y;
        } else {
            lo = x;
        }
    }
    at(0.5 * (lo + hi)).min(at(best))
}
