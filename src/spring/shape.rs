//! [`Shape`]: the answer to [`Question::Shape`](super::Question::Shape),
//! the rod's equilibrium at one load with its loop count, and how
//! [`Spring::answer`](super::Spring::answer) computes it and estimates its
//! error.
//!
//! The rod is pulled from rest to the load at the tolerance asked (the
//! pull only follows the branch; its error estimate is in the plane of the
//! curve, not along the rod). Its last point is then solved again, at the
//! same load, on the mesh with every interval halved (Gauss collocation
//! with the same m, Newton from the coarse solution, whose quaternion is
//! the phase condition's reference, so the two are not turned about the
//! force line). The finer solution is the answer; its error is estimated
//! by the largest distance between the two centrelines. Between mesh
//! points the collocation polynomial's error is O(h^(m+1)) (de Boor &
//! Swartz 1973), so the coarse error is 2^(m+1) ≥ 8 times the fine one and
//! the distance, about the coarse error, overestimates the fine error by
//! 2^(m+1) − 1 ≥ 7 once the meshes are in the asymptotic regime: that
//! factor is the estimate's margin (checked against the converged rod in
//! `tests/spring/shape.rs`). Until the distance meets the tolerance and the
//! two loop counts agree, the mesh is halved again.

use core::ops::ControlFlow;
use std::time::Instant;

use nalgebra::Vector3;

use crate::bvp::{Collocation, Mesh, Solution};
use crate::continuation::Point;
use crate::error::{Error, Result};
use crate::load::Target;
use crate::rod::{Equilibrium, Rod};

use super::answer::{Answer, Choice, Reason, SetAside, Value};
use super::choice::MIN_ROD_TOLERANCE;
use super::{HelixModel, Model, RodModel, Spring};

/// The shape of a spring at one load: the rod's equilibrium there (its
/// centreline, frame, strains and energy on demand, [`Equilibrium`]) and
/// its loop count.
///
/// The rod's equilibria are defined up to a rigid turn about the force line
/// (the z axis, through both ends): the answer's error is the largest
/// distance between its centreline and the exact one turned to fit best.
///
/// ```
/// use hockle::Stiffness;
/// use hockle::spring::{Question, Spring, Target, Value};
/// let spring = Spring::from_degrees(2, 60.0, Stiffness::nikolai(0.1, 0.0)?)?;
/// let answer = spring.answer(&Question::Shape { at: Target::Force(0.5) }, 1e-4)?;
/// assert!(answer.meets_tolerance());
/// let Value::Shape(shape) = answer.value() else { unreachable!() };
/// assert!((shape.force_scaled() - 0.5).abs() < 1e-9);
/// assert!(shape.centreline(0.0)?.norm() < 1e-12); // r(0) = 0, on the force line
/// println!("{} loops; {}", shape.loops().unwrap_or(0), answer.why());
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct LoadedShape {
    equilibrium: Equilibrium,
    loops: Option<u32>,
}

impl LoadedShape {
    /// The equilibrium (the rod's collocation solution at the load).
    #[must_use]
    pub fn equilibrium(&self) -> &Equilibrium {
        &self.equilibrium
    }

    /// The loop count ([`Equilibrium::loops`]): the same on the answer's
    /// mesh and on the mesh twice as coarse, or the answer says its
    /// tolerance is not met; `None` where the count is not defined (a 3D
    /// excursion).
    #[must_use]
    pub fn loops(&self) -> Option<u32> {
        self.loops
    }

    /// The centreline r(s), s ∈ [0, 1].
    ///
    /// # Errors
    /// [`crate::Error::InvalidArgument`] unless s ∈ [0, 1].
    pub fn centreline(&self, s: f64) -> Result<Vector3<f64>> {
        self.equilibrium.centreline(s)
    }

    /// F/((2πn)²B) at the shape.
    #[must_use]
    pub fn force_scaled(&self) -> f64 {
        self.equilibrium.force_scaled()
    }

    /// Δz at the shape.
    #[must_use]
    pub fn extension(&self) -> f64 {
        self.equilibrium.extension()
    }
}

impl PartialEq for LoadedShape {
    /// The same rod, mesh, parameters and collocation values.
    fn eq(&self, other: &Self) -> bool {
        let (a, b) = (self.equilibrium.solution(), other.equilibrium.solution());
        self.loops == other.loops
            && self.equilibrium.rod() == other.equilibrium.rod()
            && a.mesh() == b.mesh()
            && a.parameters() == b.parameters()
            && a.mesh_values() == b.mesh_values()
            && a.collocation_values() == b.collocation_values()
    }
}

/// The finest mesh tried is the pull's halved this many times (64 times as
/// many intervals): beyond it the answer says its tolerance is not met.
const MAX_HALVINGS: u32 = 6;

/// Samples of the centreline per interval of the coarser mesh at which the
/// two solutions are compared (the collocation polynomials have degree
/// m ≤ 7 per interval, so their difference has at most 7 extrema there).
const SAMPLES_PER_INTERVAL: usize = 16;

impl Spring {
    /// [`Question::Shape`](super::Question::Shape) (module docs).
    pub(super) fn answer_shape(
        &self,
        at: Target,
        tolerance: f64,
        clock: Instant,
    ) -> Result<Answer> {
        let helix = self.helix_misses_the_ends(at, tolerance);
        let rod_tolerance = tolerance.max(MIN_ROD_TOLERANCE);
        let pull = RodModel::default()
            .tolerance(rod_tolerance)
            .driver(self, at)?;
        let rod = *pull.rod();
        let mut last: Option<Solution> = None;
        let run = pull.run(|p: &Point| {
            last = Some(p.solution().clone());
            ControlFlow::<()>::Continue(())
        })?;
        let reached = run.reached_target();
        let termination = run.termination().clone();
        let pop_outs = RodModel::response(run)?.pop_outs().len();
        // a run observes its start point at least
        let mut coarse = last.ok_or(Error::InvalidCount {
            name: "points of the pull",
            value: 0,
            allowed: "at least the start point",
        })?;
        let m = coarse.points_per_interval();
        let solver = |mesh: Mesh| {
            Collocation::new()
                .points(m)
                .mesh(mesh)
                .newton_tolerance((tolerance * 1e-3).clamp(1e-14, 1e-10))
        };
        let mut answer = (coarse.clone(), f64::INFINITY);
        for _ in 0..MAX_HALVINGS {
            let fine = match coarse
                .mesh()
                .halved()
                .and_then(|mesh| solver(mesh).solve(&rod, &coarse, coarse.parameters()))
            {
                Ok(fine) => fine,
                Err(_) => break,
            };
            let distance = centreline_distance(&coarse, &fine);
            let same_count = loops(rod, &coarse)? == loops(rod, &fine)?;
            answer = (
                fine.clone(),
                if same_count { distance } else { f64::INFINITY },
            );
            if distance <= tolerance && same_count {
                break;
            }
            coarse = fine;
        }
        let (solution, estimated_error) = answer;
        let equilibrium = Equilibrium::new(rod, solution)?;
        let loops = equilibrium.loops();
        Ok(Answer {
            value: Value::Shape(Box::new(LoadedShape { equilibrium, loops })),
            estimated_error,
            tolerance,
            choice: Choice::Rod {
                tolerance: rod_tolerance,
            },
            reason: Reason::RodNeeded {
                helix,
                elastica: SetAside::NotAnswered,
                pop_outs,
            },
            reached,
            termination: Some(termination),
            elapsed: clock.elapsed(),
        })
    }

    /// Why the exact helix cannot give the shape at `at`: about the force
    /// line, its ends lie its radius R off it, the spring's on it; if R is
    /// within the tolerance, no bound on its error in the interior is known.
    fn helix_misses_the_ends(&self, at: Target, tolerance: f64) -> SetAside {
        if !self.is_helical() {
            return SetAside::NotHelical;
        }
        let Ok(helix) = HelixModel::new(2).and_then(|m| m.pull_to(self, at)) else {
            return SetAside::NotAnswered;
        };
        let theta = helix
            .curve()
            .points()
            .last()
            .map_or(f64::NAN, |p| p.parameter);
        let radius = theta.sin() / (2.0 * core::f64::consts::PI * f64::from(self.coils()));
        if radius > tolerance {
            SetAside::MissesTheEnds {
                lower_bound: radius,
            }
        } else {
            SetAside::NoBound
        }
    }
}

/// The largest distance between the centrelines of two solutions,
/// sampled [`SAMPLES_PER_INTERVAL`] times per interval of the coarser.
fn centreline_distance(coarse: &Solution, fine: &Solution) -> f64 {
    let (mut a, mut b) = ([0.0; Rod::DIM], [0.0; Rod::DIM]);
    let p = coarse.mesh().points();
    let mut worst = 0.0_f64;
    for w in p.windows(2) {
        for k in 0..=SAMPLES_PER_INTERVAL {
            let s = w[0] + (w[1] - w[0]) * k as f64 / SAMPLES_PER_INTERVAL as f64;
            coarse.eval_into(s, &mut a);
            fine.eval_into(s, &mut b);
            let d = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            worst = worst.max(d);
        }
    }
    worst
}

fn loops(rod: Rod, solution: &Solution) -> Result<Option<u32>> {
    Ok(Equilibrium::new(rod, solution.clone())?.loops())
}
