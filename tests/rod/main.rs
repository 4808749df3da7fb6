//! Tests of the 3D rod: the exact unstressed helix, the analytic Jacobians,
//! and (with the continuation) the paper's cascade.

#[path = "../common/mod.rs"]
mod common;

mod cascade;
mod diamonds;
mod input;
mod jacobians;
mod long_springs;
mod phase_diagram;
mod planar;
mod planar_guess;
mod relax;
mod slides;
mod stability;
mod symmetry;
mod tolerance;
mod unstressed;
