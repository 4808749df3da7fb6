//! # hockle
//!
//! Mechanics of coiled elastic rods — springs, ribbons, cables and nanocoils
//! pulled until their loops pop out — after Starostin & van der Heijden,
//! *Cascade unlooping of a low-pitch helical spring under tension*,
//! J. Mech. Phys. Solids 57 (2009).
//!
//! ## Layers
//!
//! Lower layers never import higher ones.
//!
//! | module | what it does |
//! |---|---|
//! | [`special`] | Jacobi elliptic functions and elliptic integrals |
//! | [`elastica`] | planar elastica with intrinsic curvature: υ, α, ϑ and secondary branches |
//! | [`helix`] | closed-form helical response (the paper's Appendix) |
//! | [`bvp`] | Gauss–Legendre collocation boundary-value solver |
//! | [`continuation`] | pseudo-arclength continuation with fold and branch-point detection |
//! | [`rod`] | the 3D anisotropic Kirchhoff rod with zero-moment ends |
//! | [`spring`] | the scene: one spring, answered by every model with a [`ForceExtension`] |
//! | [`curve`] | [`ForceExtension`], the one output type of every model |
//! | [`stability`] | the index of an equilibrium under force or extension control, carried along a curve through its folds |
//!
//! ## Main types
//!
//! | type | what it is |
//! |---|---|
//! | [`spring::Spring`] | a spring: coils, helix angle, stiffnesses |
//! | [`spring::HelixModel`], [`spring::ElasticaModel`], [`spring::RodModel`] | three models of it, cheapest first; each answers [`spring::Model::pull`] |
//! | [`spring::Response`] | a model's answer: the curve, folds, loop counts, stability under either control, pop-outs, stretches, jumps, self-contact, the typed termination |
//! | [`stability::Stability`] | the index of an equilibrium under one [`Control`] (0: a real spring can sit there) |
//! | [`Target`], [`Control`], [`ForceScale`], [`Stiffness`] | the load, the force scale (2πn)²B and the stiffnesses A, B, C, defined once for every model |
//! | [`ForceExtension`] | a force–extension curve, the one output type of every model |
//! | [`elastica::Elastica`] | one planar equilibrium; [`elastica::Trace`] a whole branch |
//! | [`helix::Helix`], [`Stiffness`] | the exact-helix response, and the stiffnesses A, B, C |
//! | [`rod::Rod`], [`rod::Pull`] | the 3D rod as a boundary-value problem, and its pull driver (run, or step by step) |
//! | [`bvp::Problem`], [`bvp::Collocation`] | any two-point BVP, and the collocation solver |
//! | [`continuation::Continuation`] | pseudo-arclength continuation of a [`bvp::Problem`] |
//! | [`special::Modulus`], [`special::jacobi`] | elliptic modulus and Jacobi functions |
//!
//! ```
//! use hockle::spring::{HelixModel, Model, Spring};
//!
//! let spring = Spring::paper(); // n = 4, θ0 = 89.8°, A/B = 10, ν = 0.05
//! let response = HelixModel::default().pull(&spring, 0.5)?;
//! let last = response.curve().points().last().unwrap();
//! assert!((last.force / spring.force_scale() - 0.5).abs() < 1e-9);
//! # Ok::<(), hockle::Error>(())
//! ```
//!
//! ## Conventions
//!
//! - **Units.** Rod length 1 and bending stiffness B = 1 unless given: forces
//!   are in units of B/L², moments in B/L.
//! - **Force** is the physical tension that balances the end load, positive
//!   when pulling: F = dU/dΔz. The paper's elastica formulas (eq4 onwards)
//!   write a constant that is twice this: from eq2/eq3 with B = 1 the energy
//!   derivative gives F = k²Ω², not the printed 2k²Ω². Every `force()` in
//!   hockle is the physical one; `force_scaled()` is F/((2πn)²B), the
//!   scale of the paper's plots ([`ForceScale`], B = 1 in the elastica).
//! - **Load.** A pull ends at a [`Target`]: a force F/((2πn)²B) under force
//!   control (dead load) or an extension Δz under extension control (hard
//!   device); [`Control`] names which.
//! - **Extension** Δz is the end-to-end distance along the force per unit
//!   length, Δz ∈ [−1, 1].
//! - **Modulus.** k is the modulus, m = k² the parameter, m₁ = 1 − m the
//!   complementary parameter; [`special::Modulus`] holds all three exactly so
//!   that k → 1 loses nothing.
//! - **Angles** are in radians. The helix angle θ is the angle between the
//!   tangent and the helix axis (θ0 = 89.8° is a pitch angle of 0.2°).
//! - **Stiffness.** A about d1, B about d2, C in torsion.
//!
//! ## Errors
//!
//! Bad input never panics: every fallible function returns [`Result`] with an
//! [`Error`] that names the offending value and what is allowed.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub use nalgebra;

pub mod bvp;
pub mod continuation;
pub mod curve;
pub mod elastica;
pub mod error;
pub mod helix;
pub mod load;
pub mod rod;
pub mod special;
pub mod spring;
pub mod stability;
mod stiffness;

pub(crate) mod linalg;
pub(crate) mod quadrature;

pub use curve::{Fold, FoldKind, ForceExtension, ForcePoint, ForceScale};
pub use load::{Control, Target};
pub use stiffness::Stiffness;

/// The README's code, compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
pub use error::{Error, Result};
