//! [`Spring::answer`]: the cheapest model that meets a tolerance for a
//! question, and why.
//!
//! The models, cheapest first, and what decides between them (derived in
//! `docs/ACCURACY.md`, section "spring: what each model costs"):
//!
//! | question | model | when |
//! |---|---|---|
//! | spring constant | linear response (closed form, [`Spring::spring_constant`]) | helical intrinsic strains |
//! | a curve, forces or extensions | exact helix | its two end layers, measured on a 2-coil rod and scaled to the spring's n coils, put its error within the tolerance (`helix_check`; tried where n·tolerance/sin²θ0 can allow it) |
//! | pop-outs | exact helix | never: it has none |
//! | anything else | flat elastica | never certified: it passes ≥ 0.4 cos θ0 from the rest state, ignores pitch, A, C and pop-outs, and no bound on its error is known without the rod |
//! | shape at one load | exact helix | never: about the force line its ends are its radius R off the spring's ([`SetAside::MissesTheEnds`](super::SetAside::MissesTheEnds)), and no bound on its interior is known |
//! | shape at one load | rod at the tolerance, its last point solved again on halved meshes until the centrelines agree to the tolerance | always ([`LoadedShape`](super::LoadedShape)) |
//! | anything else | rod at half the tolerance asked | always: twice its own estimate ([`crate::rod::PullRun::estimate`]) |
//!
//! The rod pulls only as far as the question needs: to the largest load or
//! extension asked about (pop-outs: to the load, then stops), with no
//! shapes, stability or contact computed on the way.

use std::time::Instant;

use crate::error::{Error, Result};
use crate::helix::Helix;
use crate::load::{Control, Target};

use super::answer::{Answer, Choice, Reason, SetAside, Value};
use super::helix_check::{self, Verdict};
use super::plane_distance;
use super::{ElasticaModel, Model, Question, Response, RodModel, Spring};

/// The closed form's relative error: a dozen roundings and sin θ0, cos θ0
/// (≤ 20 ε ≈ 4.4e-15), with a margin (`tests/spring/choice.rs` measures it
/// against a quadrature of Castigliano's integral).
const CLOSED_FORM_ERROR: f64 = 1e-14;

/// The answer reports the rod's own estimate
/// ([`crate::rod::PullRun::estimate`]) times this: the rod's estimate is
/// asymptotic, and on the springs of the fast test in
/// `tests/spring/choice.rs` the true error of the curve was up to 1.5
/// times it (n = 3, θ0 = 80°, A/B = 2, ν = 0.3: 1.07 at tolerance 1e-6;
/// the paper's spring to F/((2πn)²B) = 0.7: 1.46 at 1e-6). The factor was
/// set on those springs alone; the grid of 48 scenes (docs/ACCURACY.md)
/// checks it.
pub(super) const ROD_ESTIMATE_SAFETY: f64 = 2.0;

/// The rod is run at the tolerance over [`ROD_ESTIMATE_SAFETY`]; if the
/// reported error still exceeds the tolerance, it is run once more at a
/// tolerance this many times smaller.
const RETRY_DIVISOR: f64 = 10.0;

/// The rod's smallest tolerance ([`crate::rod::Pull::tolerance`]).
pub(super) const MIN_ROD_TOLERANCE: f64 = 1e-12;

/// The rod's largest tolerance ([`crate::rod::Pull::tolerance`]), and so
/// the largest of every answer the rod computes.
const MAX_ROD_TOLERANCE: f64 = 1e-1;

/// The elastica's lower bound is taken this much below the distance
/// measured to its sampled curve (the chords of 400 samples over
/// F/((2πn)²B) ≤ 2 cos θ0 are far closer than this).
const LOWER_BOUND_MARGIN: f64 = 0.99;

impl Spring {
    /// Answers `question` to within `tolerance` with the cheapest model
    /// that can be shown to meet it, and says which and why
    /// ([`Answer::why`]; the choices are tabled in the module docs of
    /// [`crate::spring`]).
    ///
    /// The tolerance is in the plane (Δz, F/((2πn)²B)) of the paper's
    /// plots (max norm), as for [`RodModel::tolerance`]; for the spring
    /// constant it is relative; for a shape it is the largest distance
    /// between centrelines, in units of the rod's length ([`LoadedShape`](super::LoadedShape)).
    ///
    /// ```no_run
    /// use hockle::spring::{Choice, Question, Spring};
    /// let spring = Spring::paper();
    /// let k = spring.answer(&Question::SpringConstant, 1e-6)?;
    /// assert_eq!(k.choice(), Choice::LinearResponse);
    /// let pops = spring.answer(&Question::PopOuts { max_force: 1.0 }, 1e-3)?;
    /// assert!(pops.meets_tolerance());
    /// println!("{}", pops.why()); // rod at tolerance 1e-3: helix set aside (...)
    /// # Ok::<(), hockle::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] for a tolerance that is not finite and
    /// positive, or above 1e-1 (the rod's loosest) for any question but
    /// the spring constant (a tolerance below the rod's tightest, 1e-12, is
    /// answered at 1e-12 and reported as not met where its estimate says
    /// so), and for a bad
    /// question ([`Question::check`], [`Question::target`]); the errors of
    /// [`Spring::spring_constant`] (a spring constant of a spring with
    /// custom intrinsic strains) and of [`RodModel`]'s pull. A pull that
    /// stops before its target answers with what it has
    /// ([`Answer::reached_target`]).
    pub fn answer(&self, question: &Question, tolerance: f64) -> Result<Answer> {
        let clock = Instant::now();
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                allowed: "a finite, positive tolerance",
            });
        }
        let rest = self.helix_angle().cos();
        let rest = if self.is_helical() { rest } else { f64::NAN };
        let Some(target) = question.target(rest)? else {
            return Ok(Answer {
                value: Value::SpringConstant(self.spring_constant()?),
                estimated_error: CLOSED_FORM_ERROR,
                tolerance,
                choice: Choice::LinearResponse,
                reason: Reason::ClosedForm,
                reached: true,
                termination: None,
                elapsed: clock.elapsed(),
            });
        };
        if tolerance > MAX_ROD_TOLERANCE {
            // (checked here, not by the rod, which is run at another
            // tolerance and would name that one)
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                allowed: "a finite, positive tolerance, at most 1e-1 (the rod's loosest) \
                          for every question but the spring constant",
            });
        }
        if let Question::Shape { .. } = question {
            return self.answer_shape(target, tolerance, clock);
        }
        // (why the cheap models are set aside is said, not needed: where
        // their own closed form or pull fails, e.g. a spring constant
        // beyond the double range, the rod still answers)
        let helix = match self.helix_verdict(question, target, tolerance) {
            Ok(Verdict::Certified(response)) => {
                let estimated_error = response.estimated_error().unwrap_or(f64::INFINITY);
                return Ok(Answer {
                    value: value_of(question, &response, self.force_scale()),
                    estimated_error,
                    tolerance,
                    choice: Choice::Helix,
                    reason: Reason::EndLayersScaled {
                        coils: self.coils(),
                    },
                    reached: response.reached_target(),
                    termination: Some(response.termination().clone()),
                    elapsed: clock.elapsed(),
                });
            }
            Ok(Verdict::SetAside(why)) => why,
            Err(_) => SetAside::NoBound,
        };
        let elastica = self
            .elastica_set_aside(target, tolerance)
            .unwrap_or(SetAside::NoBound);

        let pull = |tol: f64| -> Result<crate::rod::PullRun> {
            RodModel::default()
                .tolerance(tol)
                .driver(self, target)?
                .run(())
        };
        // the rod aims its own estimate at the tolerance, the answer reports
        // ROD_ESTIMATE_SAFETY times it: ask the rod for that much less
        let mut rod_tolerance = (tolerance / ROD_ESTIMATE_SAFETY).max(MIN_ROD_TOLERANCE);
        let mut run = pull(rod_tolerance)?;
        let reported = |run: &crate::rod::PullRun| match question {
            // the folds are located points: their error is the mesh's
            Question::PopOuts { .. } => {
                ROD_ESTIMATE_SAFETY * (run.estimate().mesh + run.estimate().solves())
            }
            _ => ROD_ESTIMATE_SAFETY * run.estimate().curve(),
        };
        if reported(&run) > tolerance && rod_tolerance / RETRY_DIVISOR >= MIN_ROD_TOLERANCE {
            rod_tolerance /= RETRY_DIVISOR;
            run = pull(rod_tolerance)?;
        }
        let estimated_error = reported(&run);
        let reached = run.reached_target();
        let termination = run.termination().clone();
        let response = RodModel::response(run)?;
        let pop_outs = response.pop_outs().len();
        let value = value_of(question, &response, self.force_scale());
        Ok(Answer {
            value,
            estimated_error,
            tolerance,
            choice: Choice::Rod {
                tolerance: rod_tolerance,
            },
            reason: Reason::RodNeeded {
                helix,
                elastica,
                pop_outs,
            },
            reached,
            termination: Some(termination),
            elapsed: clock.elapsed(),
        })
    }

    /// Whether the exact helix answers `question`, a pull to `target`,
    /// within `tolerance`: checked by its end layers (`helix_check`) for
    /// the questions a curve answers where the check can pass, else why
    /// not.
    fn helix_verdict(
        &self,
        question: &Question,
        target: Target,
        tolerance: f64,
    ) -> Result<Verdict> {
        let read_off_a_curve = matches!(
            question,
            Question::Curve { .. } | Question::ForcesAt(_) | Question::ExtensionsAt(_)
        );
        let set_aside = self.helix_set_aside(target)?;
        if read_off_a_curve
            && matches!(set_aside, SetAside::LoadedOnItsAxis { .. })
            && helix_check::worth_checking(self, tolerance)
        {
            helix_check::check(self, target, tolerance)
        } else {
            Ok(Verdict::SetAside(set_aside))
        }
    }

    /// Why the exact helix cannot answer a pull to `target` unchecked.
    fn helix_set_aside(&self, target: Target) -> Result<SetAside> {
        if !self.is_helical() {
            return Ok(SetAside::NotHelical);
        }
        if !pulls(target, self.helix_angle().cos()) {
            return Ok(SetAside::NotAnswered);
        }
        let helix = Helix::new(self.coils(), self.helix_angle(), self.stiffness())?;
        Ok(SetAside::LoadedOnItsAxis {
            slope_ratio: self.spring_constant()? / helix.spring_constant()?,
        })
    }

    /// Why the flat elastica cannot answer a pull to `target` within
    /// `tolerance`: its distance from the exact rest state (cos θ0, 0) when
    /// that exceeds the tolerance, else no bound.
    fn elastica_set_aside(&self, target: Target, tolerance: f64) -> Result<SetAside> {
        if !self.is_helical() {
            return Ok(SetAside::NotHelical);
        }
        let c = self.helix_angle().cos();
        if !pulls(target, c) {
            return Ok(SetAside::NotAnswered);
        }
        if c <= 0.0 {
            return Ok(SetAside::NoBound);
        }
        // The max-norm ball of radius c about (c, 0) holds only points with
        // F/((2πn)²B) ≤ c: the curve up to 2c holds the nearest one.
        let flat = ElasticaModel::default().pull(self, 2.0 * c)?;
        let scale = self.force_scale();
        let pts = flat.curve().points();
        let distance = pts
            .windows(2)
            .map(|w| {
                let a = [w[0].extension, w[0].force / scale];
                let b = [w[1].extension, w[1].force / scale];
                plane_distance::to_segment([c, 0.0], a, b)
            })
            .fold(f64::INFINITY, f64::min);
        let lower_bound = LOWER_BOUND_MARGIN * distance;
        Ok(if lower_bound > tolerance {
            SetAside::MissesTheRestState { lower_bound }
        } else {
            SetAside::NoBound
        })
    }
}

/// Whether `target` pulls (a positive force, an extension above rest).
fn pulls(target: Target, rest: f64) -> bool {
    match target {
        Target::Force(f) => f > 0.0,
        Target::Extension(dz) => dz > rest,
    }
}

/// The value `question` asks for, read off `response` (forces in units of
/// `scale`, (2πn)²B).
fn value_of(question: &Question, response: &Response, scale: f64) -> Value {
    let curve = response.curve();
    match question {
        Question::ForcesAt(extensions) => Value::Forces(
            extensions
                .iter()
                .map(|&dz| curve.force_at(dz).iter().map(|f| f / scale).collect())
                .collect(),
        ),
        Question::ExtensionsAt(forces) => Value::Extensions(
            forces
                .iter()
                .map(|&f| curve.extension_at(f * scale))
                .collect(),
        ),
        Question::PopOuts { .. } => Value::PopOuts {
            jumps: response.jumps(Control::Force),
            pop_outs: response.pop_outs(),
        },
        _ => Value::Curve(Box::new(response.clone())),
    }
}
