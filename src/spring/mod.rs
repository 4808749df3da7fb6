//! The scene: a spring, answered by every model with a [`crate::ForceExtension`].
//!
//! Not yet implemented: see `docs/ROADMAP.md`.
