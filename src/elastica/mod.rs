//! The planar elastica with intrinsic curvature 2πn (the paper's Section 3).
//!
//! A twist-free inextensible rod of unit length and bending stiffness B = 1
//! whose unstressed shape is the n-times covered ring (κ0 = 2πn), pulled by a
//! force along the line through its ends, with zero end moments. With ϑ the
//! angle between the tangent and the force and γ = cos ϑ (eq2–eq5):
//!
//! ```text
//! ϑ'' = −F sin ϑ                      (moment balance; F the tension)
//! κ² = H + 2Fγ                        (first integral; the paper writes H + Fγ)
//! γ = 1 − 2 sn²(Ωs, k),  κ = 2Ω dn(Ωs, k),  F = k²Ω²
//! x = (2/(k²Ω)) dn(Ωs),  z = (1 − 2/k²) s + (2/(k²Ω)) ε(Ωs)          (eq5)
//! ends s1, s2 = s1 + 1:  πn = Ω dn(Ωs_i)                              (eq6, κ(s_i) = κ0)
//! ```
//!
//! k is the elliptic **modulus** (m = k² the parameter), ε(u) = ∫0^u dn² the
//! Jacobi epsilon (the paper's E(u, k)), K = K(k).
//!
//! # The force: physical tension, half the paper's F
//!
//! From ϑ'' = −F sin ϑ, ½ϑ'² = F cos ϑ + c, so κ² = 2Fγ + 2c: the paper's
//! eq3 (κ² = H + Fγ) uses a constant that is **twice** the tension, and its
//! "F = 2k²Ω²" is 2× the physical F = k²Ω². hockle's [`Elastica::force`] is
//! the physical tension, checked as F = dU/dΔz with U = ½∫(κ − κ0)² ds by
//! finite differences on every branch (`tests/elastica`, and at 50 digits in
//! `tests/data/gen_elastica.py`). [`Elastica::force_scaled`] is F/(2πn)². The
//! paper's force–extension figures therefore have twice hockle's vertical
//! values at the same extension.
//!
//! # The branches
//!
//! | type | what | paper |
//! |---|---|---|
//! | [`Elastica::symmetric`] → [`Symmetric`] | the primary υ (opened) and α (tightened) shapes through the ring | eq7, eq8 |
//! | [`Elastica::nonsymmetric`] | ϑ-shapes with j periods, Ω = 2jK, every root s1 of eq81 | eq81, eq82 |
//! | [`Elastica::secondary`], [`Elastica::secondary_arm`] | the secondary symmetric branches (υ for j < n, α for j > n), both [`Arm`]s | eq7 with m = j, j + 1 |
//! | [`bifurcation`] → [`Bifurcation`] | where secondary j meets ϑ_j | K = πn/(2j), K k′ = πn/(2j) |
//! | [`secondary_fold`] → [`SecondaryFold`] | the fold (smallest k) of a secondary branch | — |
//! | [`Trace`] | a whole branch as a [`ForceExtension`](crate::ForceExtension) | figures |
//! | [`series`] | small-k expansions and linear responses | eq9–eq12 |
//! | [`OutOfPlane`] → [`Diamond`] | out-of-plane instability points of the planar branches | Fig. spring (diamonds) |
//!
//! **One family, two arms.** Put the end of the rod at a distance t (in
//! u = Ωs) from a curvature extremum. Then eq7 becomes
//!
//! ```text
//! υ-family c:  Ω = 2(cK − t),  πn = Ω dn t       (ends near maxima)
//! α-family c:  Ω = 2(cK + t),  πn = Ω k′ nd t    (ends near minima)
//! ```
//!
//! The primary υ and α are c = n with t ∈ [0, K] (monotone, one root for
//! every k ∈ [0, 1)); the secondary branch j is c = j. Its equation has an
//! extremum t* ∈ (−K, 0); the branch is born where that extremum reaches πn
//! (the fold, k_f) and has two arms, t ∈ [t*, K] (through t = 0, the
//! bifurcation point with ϑ_j: [`Arm::bifurcating`]) and t ∈ [−K, t*]. As
//! k → 1 the υ arms approach ϑ_(j−1) and ϑ_(j+1) (a coil lost or gained) and
//! both α arms approach ϑ_j, as the paper describes.
//!
//! # Numerics
//!
//! Every solution is found directly at its k (no continuation from k = 0):
//! Halley steps safeguarded by bisection on a bracket where the equation is
//! monotone. As k → 0 the closed forms cancel (Δz = O(k²) from terms of size
//! 2/k²; U = O(k⁴); Ω − πn = O(k⁶) on υ); hockle evaluates them without
//! cancellation: the root equation as a sum of O(k²) terms with
//! K − π/2 from its series, the extension by parts as
//! 2 sn cn/dn(t)/Ω + (m/4Ω)∫ sin²2φ/Δ³ dφ, the energy by Gauss–Legendre
//! quadrature. Take the modulus as a [`Modulus`](crate::special::Modulus)
//! (`*_with` constructors) to reach k′ = √(1 − k²) down to 1e-150.
//!
//! # Accuracy
//!
//! Against 50-digit mpmath tables (`tests/data/gen_elastica.py`): Ω and F
//! ≤ 1.1e-15 relative, Δz ≤ 2.2e-14, U ≤ 8.4e-15, bifurcation points
//! ≤ 4.1e-15, for k from 1e-3 to k′ = 1e-10 (docs/ACCURACY.md). The closed
//! forms also agree with a direct RK4 integration of ϑ'' = −F sin ϑ (ends on
//! the force line, end curvature 2πn, extension).
//!
//! # Example
//! ```
//! use hockle::elastica::{Elastica, bifurcation, series};
//! // the opened coil for n = 4 at k = 0.5
//! let s = Elastica::symmetric(4, 0.5)?;
//! assert!(s.upsilon.extension() > 0.0 && s.upsilon.force() > 0.0);
//! // small k: the linear response 8π²n²/3 (the paper's 16π²n²/3 is 2F)
//! let e = Elastica::symmetric(4, 1e-3)?.upsilon;
//! assert!((e.force() / e.extension() / series::symmetric_stiffness(4) - 1.0).abs() < 1e-6);
//! // where the spring lands after losing a loop: secondary j = 3
//! let b = bifurcation(4, 3)?;
//! let on = Elastica::secondary(4, 3, 0.9)?;
//! assert!(on.modulus() > b.modulus());
//! # Ok::<(), hockle::Error>(())
//! ```
//!
//! # The paper's print
//!
//! - F: the printed F = 2k²Ω², 8k²K²j² and the linear responses are twice
//!   the tension (above).
//! - eq9, eq10: the k⁶ coefficients of the extension are 175/1024 and
//!   79/1024, not 1225/8192 and 457/8192 (see [`series`]).
//! - Everything else checked (eq5–eq8, eq81, eq82, eq11, eq12, the Ω
//!   expansions, the factor 3) holds.
//!
//! # References
//! E. L. Starostin, G. H. M. van der Heijden, *Cascade unlooping of a
//! low-pitch helical spring under tension*, J. Mech. Phys. Solids 57 (2009);
//! A. E. H. Love, *A Treatise on the Mathematical Theory of Elasticity*
//! (1927) §262; DLMF §22.

mod bifurcation;
mod family;
mod integrals;
mod nonsymmetric;
mod out_of_plane;
mod secondary;
pub mod series;
mod solution;
mod symmetric;
mod trace;

pub use bifurcation::{Bifurcation, bifurcation};
pub use out_of_plane::{Diamond, OutOfPlane};
pub use secondary::{SecondaryFold, secondary_fold};
pub use solution::{Arm, Branch, Elastica, Shape};
pub use symmetric::Symmetric;
pub use trace::Trace;

// Every model, setting and result type of this layer can cross threads.
const _: fn() = || {
    fn send_sync<T: Send + Sync>() {}
    send_sync::<Elastica>();
    send_sync::<Symmetric>();
    send_sync::<Bifurcation>();
    send_sync::<SecondaryFold>();
    send_sync::<Trace>();
    send_sync::<Arm>();
    send_sync::<Branch>();
    send_sync::<Shape>();
    send_sync::<OutOfPlane>();
    send_sync::<Diamond>();
};
