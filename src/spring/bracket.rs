//! The bracket: below its first fold the rod's curve lies between the
//! exact helix and its own tangent at rest, so for small loads the tangent
//! (the linear response, a closed form) answers a curve question with a
//! bound computed from two closed forms.
//!
//! In (Δz, f = F/((2πn)²B)), under a dead load f from rest,
//!
//! ```text
//! Δz_helix(f)  ≤  Δz_rod(f)  ≤  cos θ0 + f/k        (k: Spring::spring_constant / (2πn)²B)
//! ```
//!
//! for as long as the helix itself stays left of the tangent. The physics
//! (an argument checked on random scenes, not a theorem):
//!
//! - **Left.** Away from its ends the loaded rod is the exact helix with
//!   its axis on the force line; its ends, held on that line (the paper's
//!   boundary conditions), add compliance. At first order that is
//!   Castigliano's extra term, 1/k − 1/k_helix =
//!   R0²[1/(2A) + ½(cos²θ0/B + sin²θ0/C)] > 0 (see
//!   [`Spring::spring_constant`]); at finite load it is two end layers whose
//!   excess extension is E(f)/n with E independent of n (measured:
//!   n (Δz_rod − Δz_helix) agrees to 3 digits for n = 1 … 8 at f ≥ 0.1 on
//!   θ0 = 70°, A/B = 0.1, ν = 0.2; notes/models14b).
//! - **Right.** The tangent keeps the load's lever about the spring's axis
//!   at its rest value R0 = sin θ0/(2πn). Under tension the spring's axis
//!   bows toward the force line, as an eccentrically pulled beam-column
//!   whose lever decays over √(B_spring/F), so the lever, and with it the
//!   compliance, only falls (P-δ stiffening); the helix stiffens too while
//!   it stays left of the tangent.
//! - **Before the first fold.** Both sides are argued for the rod's first
//!   stretch; the rod is not run, so the bracket is used only below a load
//!   under every first pop-out the cascade maps know ([`MAX_LOAD`]), for
//!   2 … 16 coils, at tolerances up to the rod's own limit of 0.1, and
//!   never for the pop-outs themselves.
//!
//! Where the helix softens toward its own fold and reaches the tangent
//! (θ0 near 90° with A/B ≫ 1 at larger loads), the bracket is refused.
//! `tests/spring/bracket.rs` checks both sides and the bound against the
//! converged rod on random scenes.

use std::time::Instant;

use crate::continuation::Termination;
use crate::curve::{ForceExtension, ForcePoint};
use crate::error::Result;
use crate::load::Target;

use super::answer::{Answer, Choice, Reason, Value};
use super::{HelixModel, Model, Question, Response, Spring};

/// Samples of the helix between rest and the load: the bound is taken on
/// each interval between two samples, so more samples only tighten it.
const SAMPLES: usize = 400;

/// Both sides of the bracket are arguments about a spring with an
/// interior (end layers, a bowing axis): a single coil is all end, and on
/// one (θ0 = 59.8°, A/B = 44, ν = 0.04) its curve falls right of the
/// tangent by up to 6e-4 at f = 0.17 (second order, against a gap of
/// 4e-2 there; with two coils it does not).
const MIN_COILS: u32 = 2;

/// The bracket is argued before the rod's first fold, and is not checked
/// against one (the rod is not run): it is used only below this load
/// F/((2πn)²B), under the lowest first pop-out of the committed cascade
/// maps (docs/data/phase_diagram_n{2,3,4,6}.csv: 0.51, 0.43, 0.38, 0.33,
/// at ν = −0.9, A/B = 100) with a margin, and only up to [`MAX_COILS`]
/// coils: the lowest pop-out falls with n (about as n^−0.4 over those
/// maps, which would reach 0.2 near n = 20).
const MAX_LOAD: f64 = 0.2;

/// See [`MAX_LOAD`].
const MAX_COILS: u32 = 16;

/// The linear response with its bound, for one target.
#[derive(Debug, Clone, Copy)]
pub(super) struct Bracket {
    /// The largest horizontal gap between the helix and the tangent up to
    /// the load: every point of the tangent or the rod lies within it of
    /// the other at the same force.
    pub(super) bound: f64,
    /// The tangent's slope df/dΔz.
    slope: f64,
    /// cos θ0.
    rest: f64,
}

impl Spring {
    /// The bracket up to `target` (module docs), `None` where it does not
    /// hold or cannot be shown to: not a pull, intrinsic strains not the
    /// helix's, fewer than two or more than 16 coils, a load above 0.2, the
    /// helix turning back in force or reaching the tangent.
    ///
    /// On the helix's samples f_0 < f_1 < … (Δz_h increasing with f), for
    /// f ∈ [f_i, f_{i+1}] the gap cos θ0 + f/k − Δz_h(f) is at most
    /// cos θ0 + f_{i+1}/k − Δz_h(f_i): the bound is the largest of those.
    pub(super) fn bracket(&self, target: Target) -> Result<Option<Bracket>> {
        if !self.is_helical() || !(MIN_COILS..=MAX_COILS).contains(&self.coils()) {
            return Ok(None);
        }
        let rest = self.helix_angle().cos();
        let pulls = match target {
            Target::Force(f) => f > 0.0,
            Target::Extension(dz) => dz > rest,
        };
        if !pulls {
            return Ok(None);
        }
        let scale = self.force_scale();
        let slope = self.spring_constant()? / scale;
        // a helix the closed forms cannot pull (extreme loads) brackets
        // nothing: the rod answers
        let Ok(helix) = HelixModel::new(SAMPLES)?.pull_to(self, target) else {
            return Ok(None);
        };
        let points: Vec<(f64, f64)> = helix
            .curve()
            .points()
            .iter()
            .map(|p| (p.extension, p.force / scale))
            .collect();
        if points.last().is_none_or(|&(_, f)| f > MAX_LOAD) {
            return Ok(None);
        }
        let mut bound = 0.0_f64;
        for w in points.windows(2) {
            let ((x0, f0), (x1, f1)) = (w[0], w[1]);
            let left = x1 <= rest + f1 / slope;
            if !(f1 > f0 && x1 >= x0 && left) {
                return Ok(None);
            }
            bound = bound.max(rest + f1 / slope - x0);
        }
        Ok(bound.is_finite().then_some(Bracket { bound, slope, rest }))
    }
}

impl Bracket {
    /// The tangent's extension at force f.
    fn extension(&self, f: f64) -> f64 {
        self.rest + f / self.slope
    }

    /// The answer of the linear response to `question` (a pull inside the
    /// bracket); `None` for the questions it does not answer: pop-outs
    /// (the bracket argues there is none, but that is the rod's to show)
    /// and the spring constant (no pull).
    pub(super) fn answer(
        &self,
        spring: &Spring,
        question: &Question,
        tolerance: f64,
        clock: Instant,
    ) -> Option<Answer> {
        let value = match question {
            Question::ForcesAt(extensions) => Value::Forces(
                extensions
                    .iter()
                    .map(|dz| vec![self.slope * (dz - self.rest)])
                    .collect(),
            ),
            Question::ExtensionsAt(forces) => {
                Value::Extensions(forces.iter().map(|f| vec![self.extension(*f)]).collect())
            }
            Question::Curve { max_force } => Value::Curve(Box::new(self.line(spring, *max_force))),
            Question::PopOuts { .. } | Question::SpringConstant => return None,
        };
        Some(Answer {
            value,
            estimated_error: self.bound,
            tolerance,
            choice: Choice::LinearResponse,
            reason: Reason::Bracketed { gap: self.bound },
            reached: true,
            elapsed: clock.elapsed(),
        })
    }

    /// The tangent from rest to f = `max_force` as a two-point curve (its
    /// parameter the physical force).
    fn line(&self, spring: &Spring, max_force: f64) -> Response {
        let scale = spring.force_scale();
        let mut curve = ForceExtension::new("linear", "force", spring.scale());
        for f in [0.0, max_force] {
            curve.push(ForcePoint {
                extension: self.extension(f),
                force: f * scale,
                parameter: f * scale,
            });
        }
        let response = Response::new(
            "linear",
            Target::Force(max_force),
            curve,
            Termination::ParameterValue(max_force * scale),
        );
        response
            .clone()
            .with_loops(vec![Some(spring.coils()); 2])
            .unwrap_or(response)
    }
}
