//! The crate's one error type.
//!
//! Every variant carries the offending value(s) and says what is allowed.
//! Each layer owns a group of variants below; add new ones to your layer's
//! group so the groups stay apart.

/// The largest number of points, samples or intervals any entry of hockle
/// computes in one call (2²², about 4.2 million): larger counts are refused
/// with [`Error::InvalidCount`] before anything is allocated, so a mistaken
/// `usize::MAX` costs an error, not an allocation abort or an hour of work.
pub const MAX_POINTS: usize = 1 << 22;

/// Checks a count of points or samples: from 2 to [`MAX_POINTS`].
pub(crate) fn check_points(name: &'static str, value: usize) -> Result<usize> {
    if (2..=MAX_POINTS).contains(&value) {
        Ok(value)
    } else {
        Err(Error::InvalidCount {
            name,
            value: value as u64,
            allowed: "from 2 to MAX_POINTS = 2^22 = 4194304 points",
        })
    }
}

/// A real number in a message: as Rust prints it where that is short
/// (1e-5 ≤ |v| < 1e16, zero, NaN, ∞), else in exponent form, where the
/// plain form runs to hundreds of digits (`1e-300` rather than 300 zeros).
/// Both forms are the shortest that read back to the same double.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Compact(pub(crate) f64);

impl core::fmt::Display for Compact {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let v = self.0;
        if v == 0.0 || !v.is_finite() || (1e-5..1e16).contains(&v.abs()) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

/// Result alias used throughout hockle.
pub type Result<T, E = Error> = core::result::Result<T, E>;

/// Everything that can go wrong in hockle.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    // ----- general -------------------------------------------------------
    /// A real argument is NaN, infinite, or outside its domain.
    #[error("{name} = {} is not allowed: {allowed}", Compact(*.value))]
    InvalidArgument {
        /// The argument's name as documented.
        name: &'static str,
        /// The value that was given.
        value: f64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    /// An integer argument is outside its domain.
    #[error("{name} = {value} is not allowed: {allowed}")]
    InvalidCount {
        /// The argument's name as documented.
        name: &'static str,
        /// The value that was given.
        value: u64,
        /// The allowed range, in words.
        allowed: &'static str,
    },
    // ----- special -------------------------------------------------------
    /// A modulus k, parameter m or complementary parameter m1 is NaN or
    /// outside [0, 1].
    #[error(
        "{name} = {} is not a valid elliptic modulus: {name} must lie in [0, 1]",
        Compact(*.value)
    )]
    InvalidModulus {
        /// Which argument: `"k"`, `"m"` or `"m1"`.
        name: &'static str,
        /// The value that was given.
        value: f64,
    },
    // ----- elastica, helix -----------------------------------------------
    /// The elastica needs a modulus k in [0, 1): k = 1 is the homoclinic
    /// limit, reached only asymptotically.
    #[error(
        "modulus k = {} (m1 = 1 - k^2 = {}) is not allowed: the elastica needs 0 <= k < 1",
        Compact(*.k),
        Compact(*.complement)
    )]
    ModulusNotBelowOne {
        /// The modulus given.
        k: f64,
        /// Its complementary parameter 1 − k² (0 means k = 1).
        complement: f64,
    },
    /// Secondary branches and bifurcation points exist only for j ≠ n: the
    /// ϑ-branch with j = n periods passes through the unstressed ring.
    #[error(
        "j = n = {n}: the non-symmetric branch with as many periods as coils starts at the ring and has no secondary branch; use j != n"
    )]
    SecondaryNeedsOtherPeriods {
        /// The number of coils (= j).
        n: u32,
    },
    /// The secondary branch j of an n-coil rod exists only from its fold
    /// k_fold on.
    #[error(
        "secondary branch j = {j} of n = {n} coils has no solution at k = {}: it exists only for k >= {} (its fold)",
        Compact(*.k),
        Compact(*.fold)
    )]
    BelowFold {
        /// Coils.
        n: u32,
        /// Periods of the ϑ-branch it bifurcates from.
        j: u32,
        /// The modulus given.
        k: f64,
        /// The modulus of the fold, where the branch begins.
        fold: f64,
    },
    /// The fold of a secondary branch could not be located in double
    /// precision: near its bifurcation point the branch's extremum stays
    /// equal to πn up to rounding (not seen for any n ≤ 50, j < 2³²).
    #[error(
        "the fold of secondary branch j = {j} for n = {n} coils cannot be located in double precision: \
         rounding hides the branch near its bifurcation point"
    )]
    FoldNotFound {
        /// Coils.
        n: u32,
        /// Periods of the ϑ-branch the branch bifurcates from.
        j: u32,
    },
    /// An elastica branch traced to a force beyond what it reaches with a
    /// representable modulus.
    #[error(
        "max_force_scaled = {} is beyond the branch's reach: it is followed up to \
         m1 = 1 - k^2 = e^-690 (about 1e-300), where F/(2πn)^2 = {}",
        Compact(*.requested),
        Compact(*.reachable)
    )]
    ForceOutOfReach {
        /// The scaled force limit asked for.
        requested: f64,
        /// The largest scaled force on the branch (at m₁ = e^−690).
        reachable: f64,
    },
    /// The result exists but is not representable: beyond the largest
    /// double, or a positive quantity below the smallest (it would round to
    /// zero).
    #[error(
        "the {quantity} at {name} = {} is not representable: beyond the largest double (about 1.8e308) or, positive, below the smallest (about 4.9e-324)",
        Compact(*.value)
    )]
    Overflow {
        /// What was asked for ("force", "spring constant", …).
        quantity: &'static str,
        /// The argument it was asked at.
        name: &'static str,
        /// The argument's value.
        value: f64,
    },
    // ----- bvp -----------------------------------------------------------
    /// The problem's counts do not give a square system.
    #[error(
        "ill-posed problem: {conditions} boundary and integral conditions (plus {extra} extra rows) \
         but {unknowns} = dim + free parameters: the two must be equal"
    )]
    IllPosed {
        /// n_bc + n_int.
        conditions: u64,
        /// Extra (bordering) rows added by the caller, e.g. 1 for continuation.
        extra: u64,
        /// n + the number of free parameters (+ extra).
        unknowns: u64,
    },
    /// A slice or vector argument has the wrong length.
    #[error("{name} has length {found}; it must have length {expected}")]
    LengthMismatch {
        /// The argument's name as documented.
        name: &'static str,
        /// The length given.
        found: u64,
        /// The length required.
        expected: u64,
    },
    /// The problem returned a NaN or infinite value.
    #[error(
        "the {what} returned a non-finite value at s = {s}: problems must return finite values"
    )]
    NonFinite {
        /// Which function: "right-hand side", "boundary conditions", "integrand", "Jacobian".
        what: &'static str,
        /// Where (s ∈ [0, 1]; NaN when not tied to a point).
        s: f64,
    },
    /// The linearised collocation system is singular.
    #[error(
        "singular Jacobian in the {block} (block {index}): the linearised problem has no unique solution there"
    )]
    SingularJacobian {
        /// "interval block", "mesh elimination", "boundary block" or "sparse system".
        block: &'static str,
        /// The interval or row index where the zero pivot appeared.
        index: u64,
    },
    /// Newton's method stopped decreasing the correction even with damping.
    #[error(
        "Newton diverged at iteration {iteration}: correction {correction:e} could not be reduced by damping"
    )]
    NewtonDiverged {
        /// The iteration at which damping failed.
        iteration: u32,
        /// The (scaled) correction norm at that point.
        correction: f64,
    },
    /// Newton's method used all its iterations.
    #[error(
        "Newton did not converge in {iterations} iterations: correction {correction:e} > tolerance {tolerance:e}"
    )]
    NewtonNotConverged {
        /// Iterations performed.
        iterations: u32,
        /// Last (scaled) correction norm.
        correction: f64,
        /// The tolerance asked for.
        tolerance: f64,
    },
    /// A point pinned along near-null modes (a loop sliding along the rod)
    /// lies farther across the branch from the equilibrium the modes would
    /// slide to than the tolerance allows.
    #[error(
        "a point pinned along near-null modes is {across:e} across the branch from the \
         equilibrium they slide to (at most {allowed:e} allowed): a shorter step is tried"
    )]
    SlideNotNegligible {
        /// The first-order distance across the branch, in the diagram's plane.
        across: f64,
        /// The most allowed (a fraction of the tolerance).
        allowed: f64,
    },
    /// The adaptive mesh could not meet the tolerance within the interval limit.
    #[error(
        "error estimate {estimate:e} > tolerance {tolerance:e} with {intervals} intervals \
         (the limit): raise max_intervals or the tolerance"
    )]
    ToleranceNotMet {
        /// The tolerance asked for.
        tolerance: f64,
        /// The best error estimate reached.
        estimate: f64,
        /// The number of intervals used.
        intervals: u64,
    },

    /// The collocation system would need more memory than hockle allows
    /// itself for one system.
    #[error(
        "a collocation system of {intervals} intervals for {dim} ODEs needs about {bytes} bytes \
         of workspace; the limit is {limit} bytes: use fewer intervals or collocation points"
    )]
    SystemTooLarge {
        /// Mesh intervals N.
        intervals: u64,
        /// ODEs n.
        dim: u64,
        /// Workspace the system would need (saturated at `u64::MAX`).
        bytes: u64,
        /// The limit, 2³¹ bytes.
        limit: u64,
    },

    // ----- continuation --------------------------------------------------
    /// Branch switching was asked at a point that is not a located branch point.
    #[error(
        "the point at arclength {arclength} is a {kind}, not a branch point: switching needs a branch point"
    )]
    NotABranchPoint {
        /// The point's arclength.
        arclength: f64,
        /// The point's kind, in words.
        kind: &'static str,
    },
    /// The tangent turned by more than the maximum angle between two
    /// continuation steps, even at the minimum step size.
    #[error(
        "the tangent turned by {angle:.3e} rad in one step (the limit is {max_angle:.3e} rad) even at the minimum step"
    )]
    StepAngleTooLarge {
        /// The angle between successive tangents, radians.
        angle: f64,
        /// The limit ([`crate::continuation::Continuation::max_angle`]).
        max_angle: f64,
    },
    /// Even at the minimum step, the corrector's Newton stopped at its
    /// rounding floor farther from its predictor than a step on the branch
    /// can move (a nearly free mode, such as a loop sliding along a rod,
    /// let it wander): its points would be noise along that mode, with
    /// folds where the noise turns. A looser tolerance often passes there:
    /// its corrector's Newton tolerance lies above the floor (the rod
    /// stretched at n = 6, (89.5°, A/B = 100, ν = 0.05) ends so after four
    /// pop-outs at the default 1e-6 and passes all five at 1e-4).
    #[error(
        "Newton left the point at its rounding floor {drift:.3e} steps from its predictor at \
         the minimum step (at most {allowed} allowed): it slides along a nearly free mode, not \
         along the branch"
    )]
    CorrectorDrifted {
        /// The distance from the predictor, in steps.
        drift: f64,
        /// The most allowed.
        allowed: f64,
    },
    /// Accepted continuation steps stopped moving the solution: the
    /// parameter and both coordinates of the diagram came out within their
    /// rounding (4 ulp) of the previous point's on successive steps. The step is
    /// below their rounding (for a rod pull: forces so large that the
    /// tolerance asked, absolute in F/((2πn)²B), is below the force's last
    /// digits), and the curve cannot be continued in double precision at
    /// this tolerance.
    #[error(
        "{steps} successive steps of Δs = {ds:e} left the parameter at {parameter:e} and the \
         diagram's point unchanged: the step is below their rounding (ask for a looser \
         tolerance or a nearer target)"
    )]
    NoProgress {
        /// The parameter where the run stopped moving.
        parameter: f64,
        /// The step size of the last step.
        ds: f64,
        /// The successive steps that did not move.
        steps: u32,
    },
    // ----- rod, spring ---------------------------------------------------
    /// A pull's target cannot be reached: a non-finite value, a force of 0
    /// or one whose physical value f·(2πn)²B overflows, an extension equal
    /// to the rest extension (the rest state itself), or an extension
    /// outside (−1, 1) (|Δz| = 1 is the straight rod).
    #[error(
        "the target {target} cannot be reached: forces must be non-zero, with a finite \
         physical value F = f·(2πn)²B, extensions in (-1, 1) and different from the rest \
         extension {}",
        Compact(*.rest_extension)
    )]
    UnreachableTarget {
        /// The target given.
        target: crate::Target,
        /// The extension of the unloaded spring.
        rest_extension: f64,
    },
    /// A rod solution whose end is farther from its start than the rod is
    /// long, |Δz| > 1 + the pull's tolerance: no inextensible rod of unit
    /// length; a spurious collocation solution of a fixed mesh too coarse
    /// for the shape (robust10b).
    #[error(
        "the solution on {intervals} mesh intervals has |Δz| = {extension} > 1: no inextensible \
         rod of unit length reaches that far; the mesh is too coarse for the shape (use more \
         intervals, or the adaptive default)"
    )]
    NotARod {
        /// The extension Δz of the solution.
        extension: f64,
        /// The mesh intervals of the solution.
        intervals: u64,
    },
    /// A phase diagram was read at a scene it does not resolve: the
    /// pop-out's cusp angle θ0_c is only known to lie in a range that
    /// contains the scene's θ0 ([`crate::rod::PhaseDiagram::pop_outs`]).
    #[error(
        "pop-out {pop_out} is not mapped at this scene: its cusp angle lies somewhere in \
         [{from_deg}°, {to_deg}°], which holds the scene's θ0, because {why}"
    )]
    NotMapped {
        /// The pop-out (0 for the first of the pull).
        pop_out: u64,
        /// The range of θ0_c, in degrees.
        from_deg: f64,
        /// (its upper end)
        to_deg: f64,
        /// Why the diagram does not know θ0_c there.
        why: &'static str,
    },
    /// A model was asked about a spring outside what it assumes.
    #[error("the {model} model cannot answer this: {assumption}")]
    OutsideModel {
        /// The model's name.
        model: &'static str,
        /// What the model assumes, and what to use instead.
        assumption: &'static str,
    },
}

#[cfg(test)]
mod tests {
    use super::Error;

    /// The value as an error message shows it.
    fn shown(value: f64) -> String {
        Error::InvalidArgument {
            name: "x",
            value,
            allowed: "anything",
        }
        .to_string()
    }

    /// Extreme values print in exponent form (Rust's plain form of 1e-300
    /// has 300 zeros), ordinary ones as Rust prints them, and both read
    /// back to the same double.
    #[test]
    fn numbers_in_messages_stay_short_and_exact() {
        for (v, text) in [
            (1e-300, "1e-300"),
            (-1e300, "-1e300"),
            (5e-324, "5e-324"),
            (f64::MAX, "1.7976931348623157e308"),
            (0.5, "0.5"),
            (123456.0, "123456"),
            (1e-5, "0.00001"),
            (9.999e-6, "9.999e-6"),
            (0.0, "0"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ] {
            let message = shown(v);
            assert_eq!(message, format!("x = {text} is not allowed: anything"));
            if v.is_finite() {
                assert_eq!(text.parse::<f64>(), Ok(v));
            }
        }
    }
}
