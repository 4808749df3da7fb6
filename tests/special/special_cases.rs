//! Limits, special values and bad input.
