//! [`Answer`]: what [`Spring::answer`](super::Spring::answer) returns: the
//! value asked for, its estimated error, the model that computed it and
//! why that model.

use std::time::Duration;

use super::{Jump, LoadedShape, PopOut, Response};
use crate::continuation::Termination;

/// The value of an [`Answer`], one variant per
/// [`Question`](super::Question).
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Value {
    /// The pull from rest to the load, with its curve, folds and loop
    /// counts ([`Response`]).
    Curve(Box<Response>),
    /// For each extension asked, every F/((2πn)²B) at which the curve
    /// passes through it, in curve order (empty where the pull never has
    /// that extension).
    Forces(Vec<Vec<f64>>),
    /// For each force asked, every Δz at which the curve has it, in curve
    /// order.
    Extensions(Vec<Vec<f64>>),
    /// dF/dΔz at rest (physical force per unit extension).
    SpringConstant(f64),
    /// The pop-outs below the load and the jumps of a force-controlled test
    /// (loading and unloading).
    PopOuts {
        /// In curve order.
        pop_outs: Vec<PopOut>,
        /// [`Response::jumps`] under force control.
        jumps: Vec<Jump>,
    },
    /// The equilibrium at the load and its loop count ([`LoadedShape`]).
    Shape(Box<LoadedShape>),
}

/// The model that answered.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Choice {
    /// A closed form of the linear response at rest
    /// ([`Spring::spring_constant`](super::Spring::spring_constant)).
    LinearResponse,
    /// The exact helix ([`HelixModel`](super::HelixModel)), its error
    /// estimated from its end layers measured on a rod of
    /// [`Choice::HELIX_CHECK_COILS`] coils.
    Helix,
    /// The 3D rod ([`RodModel`](super::RodModel)) at this tolerance.
    Rod {
        /// The tolerance the rod was run at.
        tolerance: f64,
    },
}

impl Choice {
    /// Coils of the short rod whose end layers, scaled to the spring's
    /// coils, estimate the exact helix's error ([`Reason::EndLayersScaled`]).
    pub const HELIX_CHECK_COILS: u32 = super::helix_check::SHORT_COILS;

    /// A short name for tables: `linear`, `helix` or `rod`.
    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Choice::LinearResponse => "linear",
            Choice::Helix => "helix",
            Choice::Rod { .. } => "rod",
        }
    }
}

impl core::fmt::Display for Choice {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Choice::LinearResponse => f.write_str("linear response (closed form)"),
            Choice::Helix => f.write_str("exact helix"),
            Choice::Rod { tolerance } => write!(f, "rod at tolerance {tolerance:.0e}"),
        }
    }
}

/// Why a cheaper model than the one chosen was not used.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum SetAside {
    /// The model assumes the spring's intrinsic strains are its helix's
    /// and they are not.
    NotHelical,
    /// The exact helix is loaded on its own axis (end plates), the spring
    /// through its ends: the two leave the rest state with different
    /// slopes, so the helix is off at first order in the force.
    LoadedOnItsAxis {
        /// The spring's slope at rest over the helix's (both closed forms:
        /// [`Spring::spring_constant`](super::Spring::spring_constant),
        /// [`Helix::spring_constant`](crate::helix::Helix::spring_constant)).
        slope_ratio: f64,
    },
    /// The flat elastica starts from Δz = 0, the spring from cos θ0: its
    /// curve passes at least this far (max norm in (Δz, F/((2πn)²B))) from
    /// the spring's rest state, which is exact.
    MissesTheRestState {
        /// A lower bound on the elastica's error.
        lower_bound: f64,
    },
    /// No bound on the model's error is known without running the rod (the
    /// elastica ignores pitch, A and C, and knows no pop-out). A rod check
    /// would bound it only by the check's own error plus the distance
    /// between the two, so the check's curve would be a better answer than
    /// the cheap model's at the same cost.
    NoBound,
    /// The question is not one this model answers (e.g. a push).
    NotAnswered,
    /// The helix's end layers, measured on a rod of
    /// [`Choice::HELIX_CHECK_COILS`] coils and scaled to the spring's coils
    /// ([`Reason::EndLayersScaled`]), put its error above the tolerance.
    EndLayers {
        /// The helix's estimated error.
        estimate: f64,
    },
    /// A pop-out may come near the load, where the end layers do not
    /// scale: the helix's force peaks, or the short rod that measures its
    /// end layers ([`SetAside::EndLayers`]) folds, within twice the load.
    NearAPopOut {
        /// That force maximum or fold, F/((2πn)²B).
        force: f64,
    },
    /// The spring's ends lie on the force line, the helix's (about that
    /// line) at its radius R = sin θ/(2πn) at the load: its shape is at
    /// least R off at the ends, whatever its turn about the line.
    MissesTheEnds {
        /// A lower bound on the helix's shape error (units of the rod's
        /// length).
        lower_bound: f64,
    },
}

impl core::fmt::Display for SetAside {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            SetAside::NotHelical => {
                f.write_str("the spring's intrinsic strains are not its helix's")
            }
            SetAside::LoadedOnItsAxis { slope_ratio } => write!(
                f,
                "loaded on its axis, not through the ends, so {:.2} times too stiff at rest",
                1.0 / slope_ratio
            ),
            SetAside::MissesTheRestState { lower_bound } => write!(
                f,
                "starts flat, at least {lower_bound:.1e} from the spring's rest state"
            ),
            SetAside::NoBound => f.write_str("no error bound without the rod"),
            SetAside::NotAnswered => f.write_str("does not answer this question"),
            SetAside::EndLayers { estimate } => write!(
                f,
                "its end layers, measured on a {}-coil rod, put its error at {estimate:.1e}",
                Choice::HELIX_CHECK_COILS
            ),
            SetAside::NearAPopOut { force } => write!(
                f,
                "a pop-out may come near the load: it or a {}-coil rod folds at F/((2πn)²B) = {force:.3}, \
                 within twice the load, where its end layers do not scale",
                Choice::HELIX_CHECK_COILS
            ),
            SetAside::MissesTheEnds { lower_bound } => write!(
                f,
                "its ends lie {lower_bound:.1e} off the force line, the spring's on it"
            ),
        }
    }
}

/// Why the chosen model answered.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Reason {
    /// The linear response at rest is a closed form, exact up to rounding.
    ClosedForm,
    /// The exact helix meets the tolerance: the spring is the helix plus
    /// two end layers whose excess extension falls as 1/n; they were
    /// measured on a rod of [`Choice::HELIX_CHECK_COILS`] coils, scaled to
    /// the spring's `coils`, and give the estimated error.
    EndLayersScaled {
        /// The spring's coils.
        coils: u32,
    },
    /// Neither cheap model can be certified at the tolerance: the rod
    /// answered, the cheapest rod that meets it: for a curve, run at half
    /// the tolerance asked (its estimate is reported doubled); for a shape,
    /// run at the tolerance and its last point refined ([`LoadedShape`]).
    RodNeeded {
        /// Why not the exact helix.
        helix: SetAside,
        /// Why not the flat elastica.
        elastica: SetAside,
        /// Pop-outs the rod found below the load (0 if the question needs
        /// no force-controlled pull).
        pop_outs: usize,
    },
}

/// The answer to a [`Question`](super::Question) at a tolerance: the value,
/// its estimated error, the model used and why.
///
/// The error is the model's own estimate: for the rod, the largest
/// distance (max norm in (Δz, F/((2πn)²B))) between what it returns (its
/// points, folds and interpolant, and the values read off it) and the exact
/// curve ([`crate::rod::PullRun::estimate`]); for the spring constant, a
/// relative error; for a shape, the largest distance between its
/// centreline and the exact one (units of the rod's length, up to a turn
/// about the force line: [`LoadedShape`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    pub(super) value: Value,
    pub(super) estimated_error: f64,
    pub(super) tolerance: f64,
    pub(super) choice: Choice,
    pub(super) reason: Reason,
    pub(super) reached: bool,
    pub(super) termination: Option<Termination>,
    pub(super) elapsed: Duration,
}

impl Answer {
    /// The value asked for.
    #[must_use]
    pub fn value(&self) -> &Value {
        &self.value
    }

    /// The estimated error (type docs).
    #[must_use]
    pub fn estimated_error(&self) -> f64 {
        self.estimated_error
    }

    /// The tolerance asked for.
    #[must_use]
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Whether the estimated error is within the tolerance and the pull
    /// (if any) reached its target.
    #[must_use]
    pub fn meets_tolerance(&self) -> bool {
        self.reached && self.estimated_error <= self.tolerance
    }

    /// Whether the pull (if any) reached its target; a pull that stopped
    /// early answers with the points it has (see the [`Response`] of a
    /// curve for why).
    #[must_use]
    pub fn reached_target(&self) -> bool {
        self.reached
    }

    /// How the pull that computed the answer ended (`None` for a closed
    /// form): where it stopped before its target, why (a Newton failure at
    /// the smallest step, the step limit, …), typed; what it computed up
    /// to there is the answer's value.
    #[must_use]
    pub fn termination(&self) -> Option<&Termination> {
        self.termination.as_ref()
    }

    /// The model that answered.
    #[must_use]
    pub fn choice(&self) -> Choice {
        self.choice
    }

    /// Why that model (typed; [`Answer::why`] in words).
    #[must_use]
    pub fn reason(&self) -> Reason {
        self.reason
    }

    /// Wall-clock time of the answer.
    #[must_use]
    pub fn elapsed(&self) -> Duration {
        self.elapsed
    }

    /// The reason in one sentence, e.g. "linear response: closed form,
    /// estimated error 1e-13 (relative)".
    #[must_use]
    pub fn why(&self) -> String {
        match self.reason {
            Reason::ClosedForm => format!(
                "linear response: closed form (Castigliano on the rest helix), estimated error {:.0e} (relative)",
                self.estimated_error
            ),
            Reason::EndLayersScaled { coils } => format!(
                "{}: its end layers, measured on a {}-coil rod and scaled to {coils} coils, put its error at {:.1e}",
                self.choice,
                Choice::HELIX_CHECK_COILS,
                self.estimated_error
            ),
            Reason::RodNeeded {
                helix,
                elastica,
                pop_outs,
            } => {
                let folds = match pop_outs {
                    0 => String::new(),
                    1 => ", 1 pop-out below the load".to_owned(),
                    k => format!(", {k} pop-outs below the load"),
                };
                format!(
                    "{}: helix set aside: {helix}; elastica set aside: {elastica}; estimated error {:.1e}{folds}",
                    self.choice, self.estimated_error
                )
            }
        }
    }
}

impl core::fmt::Display for Answer {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.why())?;
        if !self.reached {
            match &self.termination {
                Some(t) => write!(f, " (the pull stopped before its target: {t})")?,
                None => f.write_str(" (the pull stopped before its target)")?,
            }
        }
        Ok(())
    }
}
