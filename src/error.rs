//! The crate's one error type.
//!
//! Every variant carries the offending value(s) and says what is allowed.
//! Each layer owns a group of variants below; add new ones to your layer's
//! group so the groups stay apart.

/// Result alias used throughout hockle.
pub type Result<T, E = Error> = core::result::Result<T, E>;

/// Everything that can go wrong in hockle.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    // ----- general -------------------------------------------------------
    /// A real argument is NaN, infinite, or outside its domain.
    #[error("{name} = {value} is not allowed: {allowed}")]
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
    #[error("{name} = {value} is not a valid elliptic modulus: {name} must lie in [0, 1]")]
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
        "modulus k = {k} (m1 = 1 - k^2 = {complement}) is not allowed: the elastica needs 0 <= k < 1"
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
        "secondary branch j = {j} of n = {n} coils has no solution at k = {k}: it exists only for k >= {fold} (its fold)"
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
    // ----- bvp -----------------------------------------------------------

    // ----- continuation --------------------------------------------------

    // ----- rod, spring ---------------------------------------------------
}
