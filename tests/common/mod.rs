//! Shared test helpers: the tolerance policy and error measures.
//!
//! Every tolerance in a test is a named constant here or next to the test,
//! with one reason each. Failures print the error in units of ε (ulps).
#![allow(dead_code)]

/// Relative error |x − r| / |r| (absolute when r = 0).
pub fn rel_err(x: f64, r: f64) -> f64 {
    if r == 0.0 {
        x.abs()
    } else {
        ((x - r) / r).abs()
    }
}

/// Error of `x` against the reference `r` in units of ε·|r| (ulps of the
/// reference; for r = 0 in units of the smallest normal number).
pub fn ulps(x: f64, r: f64) -> f64 {
    if x == r {
        return 0.0;
    }
    if r == 0.0 {
        return x.abs() / f64::MIN_POSITIVE;
    }
    ((x - r) / r).abs() / f64::EPSILON
}
