//! Pseudo-arclength continuation of [`crate::bvp`] solution families.
//!
//! ## Main types
//!
//! | type | role |
//! |---|---|
//! | [`Continuation`] | the settings (builder; every default listed in [`Continuation::new`], all checked before any work) |
//! | [`Continuation::run`] → [`Run`] | every point computed, in order, with the [`Termination`] |
//! | [`Continuation::steps`] → [`Steps`] | the same run as a step-by-step iterator (drive the loop yourself) |
//! | [`Observer`] | hooks of a run: `start`, `point`, `fold`, `branch_point`, `step_rejected` (with its [`Rejection`]), `finish` (closures and `()` implement it; [`Every`] thins it) |
//! | [`Termination`] | why a run ended: step limit, stop value or event reached, stopped by the observer, or failed with a typed [`Error`](crate::Error) |
//! | [`Point`] | one solution on the branch, with arclength, dλ/ds, determinant sign and its [`PointKind`] |
//! | [`BranchSide`] | which side of a branch point [`Continuation::run_from_branch_point`] starts on |
//! | [`Continuation::tolerance`], [`Output`] → [`ErrorEstimate`] | the accuracy wanted in the plane of the bifurcation diagram (λ, an output of the solution), and what the run achieved |
//! | [`FoldContinuation`] → [`FoldCurve`] | a fold continued in a second parameter (the extended problem, AUTO's ISW = 2), its [`FoldPoint`]s with turns and cusps ([`FoldPointKind`]), [`FoldObserver`] hooks |
//!
//! The files: `settings` (the builder and its validation), `run` and
//! `steps` (the two ways to drive a run), `observer`, `termination`,
//! `point`, `norm` (the integral inner product), `corrector` (predictor,
//! chord Newton, tangent), `difference` (F_x·t by central differences),
//! `step_control`, `diagram` (the plane of a tolerance), `curvature` (x''
//! of the branch and a point's jet in that plane), `hermite` (the quintic
//! interpolant of a step and its error), `mesh_error` (the check against the halved mesh,
//! the remesh), `tolerance` (the checks of a step with a tolerance),
//! `locate` (special points),
//! `switch` (branch switching), `fold_extended` (the extended problem of a
//! fold) and `fold_curve` (its continuation in a second parameter, cusps).
//!
//! ## The method
//!
//! The unknowns x = (y(·), q, λ) (the solution, the solver's free parameters
//! and the continuation parameter λ) satisfy the collocation equations
//! F(x) = 0 plus the pseudo-arclength condition
//!
//! ```text
//!   ⟨x − x₀, τ₀⟩ = Δs,   ⟨a, b⟩ = Σ_i w_i ∫₀¹ a_i(s) b_i(s) ds + θ Σ_q a_q b_q
//! ```
//!
//! with x₀ the previous point, τ₀ its unit tangent in this mesh-independent
//! integral norm (per-variable weights w, parameter weight θ), integrals by
//! Gauss quadrature of the collocation polynomial. The predictor is
//! x₀ + Δs τ₀; the corrector is the chord Newton of [`crate::bvp`] on the
//! bordered system, whose factorisation at the new point also gives the new
//! tangent τ₁ (solve [F_x; τ₀ᵀ] τ₁ = e) and the sign of
//! det [F_x; τ₀ᵀ] (product of the pivots of every block of the condensed
//! elimination).
//!
//! With branch-point detection off ([`Continuation::detect_branch_points`])
//! the determinant is not needed: a step whose chord corrector converged in
//! at most four iterations on the previous factorisation keeps it, and the
//! tangent is refined on it (F_x τ by central differences of the residual)
//! instead of factorising at the new point, which saves about a third of
//! the time per step on rod-sized problems.
//!
//! Step control follows AUTO-07p: after a step with k corrector iterations
//! Δs is multiplied by 2 (k ≤ 4), 1.5 (k = 5), 1.1 (k = 6) or ½ (k ≥ 7),
//! within [Δs_min, Δs_max]. k counts chord iterations (the factorisation of
//! the previous point is reused) to the tight default tolerance 1e-10,
//! including the final one: about three more than AUTO counts with fresh
//! Jacobians at its looser EPSU = 1e-6, hence the shifted thresholds. The
//! growth is also limited so that the next angle between tangents is about
//! 0.6 of the maximum angle (the angle grows with Δs). A
//! failed corrector, or a tangent turning by more than the maximum angle,
//! halves Δs and retries. With a [`tolerance`](Continuation::tolerance)
//! the step also keeps the error of the quintic Hermite interpolant of the
//! branch in the diagram's plane (through the points, slopes and
//! curvatures; at tolerances of 1e-3 and looser the cubic through points
//! and slopes, whose steps the angle limit sets there as well) near a
//! fifth of it and never above half, the turn of that interpolant's
//! slope within the maximum angle, and the corrected point within 0.2 Δs
//! of the predictor; and the mesh follows the solution (see there). Folds are sign changes of dλ/ds,
//! branch points sign changes of det [F_x; τᵀ]; both are located by the
//! Illinois (modified regula falsi) iteration on the arclength of the step,
//! as are the stops: a requested value of λ (looked for on each piece of
//! the step between located folds, then corrected with λ fixed, so that
//! the run ends exactly on it) and the zeros of user events.
//! At a branch point the second null vector φ of [F_x; τᵀ] (one solve with
//! the nearly singular factorisation, orthogonalised against τ) starts the
//! bifurcating branch in either direction.
//!
//! References: E. Doedel et al., *AUTO-07P* (2007), §§ 8–10; H. B. Keller,
//! *Lectures on Numerical Methods in Bifurcation Problems* (1987).

mod corrector;
mod curvature;
mod diagram;
mod difference;
mod fold_curve;
mod fold_extended;
mod fold_point;
mod hermite;
mod locate;
mod mesh_error;
mod norm;
mod observer;
mod point;
mod rejection;
mod run;
mod settings;
mod step_control;
mod steps;
mod switch;
mod termination;
mod tolerance;

pub use diagram::Output;
pub use fold_curve::FoldContinuation;
pub(crate) use fold_curve::restricted;
pub use fold_extended::Extended as FoldProblem;
pub use fold_point::{FoldCurve, FoldObserver, FoldPoint, FoldPointKind};
pub use mesh_error::ErrorEstimate;
pub use observer::{Every, Observer};
pub use point::{Point, PointKind};
pub use rejection::Rejection;
pub use run::Run;
pub(crate) use run::drive_into;
pub use settings::Continuation;
pub use steps::Steps;
pub use switch::BranchSide;
pub use termination::Termination;
