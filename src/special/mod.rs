//! Jacobi elliptic functions and elliptic integrals.
//!
//! Everything takes a [`Modulus`], which holds the modulus k, the parameter
//! m = k² and the complementary parameter m₁ = 1 − m exactly: functions
//! read m₁ from it and never form 1 − m, so k → 1 (m₁ down to 1e-300) loses
//! nothing.
//!
//! | function | math | DLMF |
//! |---|---|---|
//! | [`ellip_k`], [`ellip_e`] | complete integrals K(k), E(k) | 19.2.8 |
//! | [`ellip_f`], [`ellip_e_inc`] | incomplete F(φ, k), E(φ, k), any real φ | 19.2.4, 19.2.5 |
//! | [`jacobi`] | sn, cn, dn and the amplitude am (continuous) | 22.2, 22.16.1 |
//! | [`jacobi_epsilon`] | ε(u) = ∫0^u dn² = E(am u, k), the paper's E(u, k) | 22.16.14 |
//! | [`jacobi_zeta`] | Z(u) = ε(u) − uE/K | 22.16.32 |
//!
//! # Methods
//! - Carlson's symmetric integrals R_F, R_D by duplication (DLMF 19.36)
//!   give K, E, F and E(φ); 1 − m sin²φ is formed as cos²φ + m₁ sin²φ and
//!   E(φ) as a sum of three non-negative terms (DLMF 19.25.9), never the
//!   cancelling R_F − (m/3) R_D.
//! - φ is reduced modulo π with π in double-double; F(φ + jπ) = F(φ) + 2jK.
//! - sn, cn, dn: u is reduced modulo 2K, folded to [0, K/2] by the
//!   quarter-period shift, halved to ≤ 1/32, expanded in Maclaurin series
//!   and doubled back with duplication formulas written as sums of positive
//!   terms (one benign difference).
//! - ε(u) on [0, K] is m₁u + (m m₁/3) sn³ R_D(cn², 1, dn²) + m sn cn/dn
//!   (DLMF 19.25.9 at φ = am u), plus 2jE for the periods.
//!
//! # Errors
//! Only [`Modulus`] construction can fail ([`crate::Error::InvalidModulus`]);
//! the functions are total: a NaN or infinite φ or u gives NaN.

mod carlson;
mod complete;
mod epsilon;
mod incomplete;
mod jacobi;
mod modulus;

pub use complete::{ellip_e, ellip_k};
pub use epsilon::{jacobi_epsilon, jacobi_zeta};
pub use incomplete::{ellip_e_inc, ellip_f};
pub use jacobi::{Jacobi, jacobi};
pub use modulus::Modulus;
