//! The planar elastica with intrinsic curvature 2πn (the paper's Section 3).
//!
//! Not yet implemented: see `docs/ROADMAP.md`.
