//! Gauss–Legendre collocation for two-point boundary-value problems.
//!
//! [`Problem`] says *what* is solved; the solver (not yet implemented: see
//! `docs/ROADMAP.md`) says *how*.

mod problem;

pub use problem::Problem;
