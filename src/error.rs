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

    // ----- bvp -----------------------------------------------------------

    // ----- continuation --------------------------------------------------

    // ----- rod, spring ---------------------------------------------------
}
