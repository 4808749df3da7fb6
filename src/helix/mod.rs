//! Closed-form helical response of the anisotropic rod (the paper's Appendix).
//!
//! Not yet implemented: see `docs/ROADMAP.md`.
