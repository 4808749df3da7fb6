//! Gauss–Legendre collocation for two-point boundary-value problems.
//!
//! [`Problem`] says *what* is solved (y′ = f(s, y, p) on [0, 1], boundary
//! conditions g(y(0), y(1), p) = 0, integral conditions); [`Collocation`]
//! says *how*; [`Solution`] is the result.
//!
//! ## Main types
//!
//! | type | role |
//! |---|---|
//! | [`Problem`] | the equations (dimension, right-hand side, boundary and integral conditions, optional Jacobians) |
//! | [`Collocation`] | the solver settings (builder; every default listed in [`Collocation::new`]) and [`Collocation::solve`] |
//! | [`InitialGuess`] | a closure s ↦ y(s) or a previous [`Solution`] |
//! | [`Solution`] | mesh values, collocation polynomial ([`Solution::eval`], [`Solution::derivative`]), parameters, residual, error estimate, [`NewtonStats`] |
//! | [`Mesh`] | interval boundaries on [0, 1] |
//! | [`LinearSolver`] | condensed O(N) elimination (default) or faer's sparse LU reference |
//!
//! Continuation of solution families is in [`crate::continuation`];
//! classical problems with known answers are in [`classic`].
//!
//! ## The method
//!
//! On a mesh 0 = t₀ < … < t_N = 1 the solution is approximated by a
//! continuous piecewise polynomial u of degree m that satisfies the ODE at the
//! m Gauss–Legendre points z_jk = t_j + c_k h_j of every interval:
//!
//! ```text
//!   u′(z_jk) = f(z_jk, u(z_jk), p),   k = 1..m, j = 0..N−1
//!   g(u(0), u(1), p) = 0,   Σ_j h_j Σ_k b_k h(z_jk, u(z_jk), y_ref, p) = 0
//! ```
//!
//! This is the m-stage Gauss Runge–Kutta method: the error is O(h^(2m)) at
//! the mesh points (superconvergence) and O(h^(m+1)) in between
//! (Ascher, Mattheij & Russell, *Numerical Solution of BVPs for ODEs*, §5.4).
//!
//! Newton's method on the collocation equations is damped by the natural
//! monotonicity test and keeps the factorisation while it contracts (chord
//! steps). Each Newton step costs O(N): every interval's m·n stage unknowns
//! are condensed with a dense LU, and the remaining block-bidiagonal system
//! in the mesh values is eliminated with partial pivoting before a small
//! dense system in (y(0), y(1), free parameters) with the boundary and
//! integral rows (the structure of AUTO-07p's `solvebv`). faer's sparse LU
//! on the full system is kept as the reference ([`LinearSolver::SparseLu`]).
//! With the `rayon` feature the per-interval work (Jacobian blocks,
//! condensation, the condensed right-hand sides) runs on rayon's pool; the
//! results are the same bit for bit as on one thread (docs/PERFORMANCE.md
//! has the speed-up: 1.2–1.5× on two cores).
//!
//! With [`Collocation::tolerance`] the mesh is adapted: the error between
//! mesh points behaves like C_m h^(m+1) |y^(m+1)|, so the mesh that
//! equidistributes |y^(m+1)|^(1/(m+1)) (AUTO's IAD) with just enough
//! intervals for the tolerance is the coarsest that meets it.
//!
//! A system can pin near-null modes (`system/pin.rs`): where Newton fails
//! on a Jacobian with a few singular values 10⁴ and more below the rest (a
//! loop sliding along a rod under tension), those modes are found from
//! random solves and every later solve drops its components along them.
//! Continuation with a tolerance uses it on request (`Continuation::pin_slides`);
//! a plain [`Collocation`] solve never pins: its solution solves the
//! equations, not a problem unfolded along the modes.

#![allow(clippy::needless_range_loop)]

pub(crate) mod adapt;
pub mod classic;
mod collocation;
pub(crate) mod guess;
mod mesh;
mod newton;
mod problem;
mod solution;
pub(crate) mod system;
mod tableau;

pub use collocation::Collocation;
pub use guess::InitialGuess;
pub use mesh::Mesh;
pub use problem::Problem;
pub use solution::{NewtonStats, Solution};
pub use system::LinearSolver;

pub(crate) use adapt::{density, equidistribute};
pub(crate) use guess::state_on_mesh;
pub(crate) use newton::{
    NewtonOptions, ROUNDOFF_STALL, finish, newton, newton_pinned, scaled_norm,
};
