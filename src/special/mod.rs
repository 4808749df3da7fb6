//! Jacobi elliptic functions and elliptic integrals.
//!
//! Not yet implemented: see `docs/ROADMAP.md`.
