//! Pseudo-arclength continuation of [`crate::bvp`] solution families.
//!
//! Not yet implemented: see `docs/ROADMAP.md`.
