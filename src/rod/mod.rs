//! The 3D anisotropic Kirchhoff rod with zero-moment ends (the paper's Section 2).
//!
//! Not yet implemented: see `docs/ROADMAP.md`.
