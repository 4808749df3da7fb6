//! The primary symmetric branches υ and α through the unstressed ring (eq7, eq8).

use core::f64::consts::FRAC_PI_2;

use super::family::{Family, Member};
use super::integrals::SMALL_M;
use super::solution::{Branch, Elastica, check_modulus, check_n, modulus_from_k};
use crate::error::Result;
use crate::special::{Modulus, ellip_e, ellip_k, jacobi};

/// The two primary symmetric solutions at one modulus k (same k, different Ω).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Symmetric {
    /// The opened coil (υ): ends near curvature maxima.
    pub upsilon: Elastica,
    /// The tightened coil (α): ends near curvature minima.
    pub alpha: Elastica,
}

impl core::fmt::Display for Symmetric {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{}; {}", self.upsilon, self.alpha)
    }
}

impl Elastica {
    /// The two primary symmetric solutions (υ and α) through the unstressed
    /// n-covered ring, at modulus k ∈ [0, 1).
    ///
    /// ```text
    /// πn = Ω dn(Ω/2)          m even      (eq7)
    /// πn = Ω k' nd(Ω/2)       m odd
    /// υ: m ≡ n (mod 2),  α: m ≡ n + 1 (mod 2);  Ω = πn at k = 0
    /// ```
    ///
    /// Solved in the end distance t from the nearest curvature extremum
    /// (υ: Ω = 2(nK − t), α: Ω = 2(nK + t), t ∈ [0, K], where the equation is
    /// monotone), by Newton steps safeguarded by bisection, so every k is
    /// solved directly without continuation from k = 0. Convention: modulus
    /// k (not m = k²); F = k²Ω² is the physical tension.
    ///
    /// # Errors
    /// [`Error::InvalidCount`](crate::Error::InvalidCount) if n = 0;
    /// [`Error::InvalidModulus`](crate::Error::InvalidModulus) if k is NaN or
    /// outside [0, 1]; [`Error::ModulusNotBelowOne`](crate::Error::ModulusNotBelowOne)
    /// if k = 1. Use [`Elastica::symmetric_with`] and
    /// [`Modulus::from_complement`] to go as close to 1 as m₁ = 1e-300.
    ///
    /// # Accuracy
    /// Ω and force ≤ 1.4e-15 relative, extension ≤ 2e-14 relative for every
    /// k from 1e-3 to k′ = 1e-10 (n = 1..8) against the 50-digit mpmath tables
    /// (`tests/elastica`); no loss as k → 0 (see the [module docs](super)).
    ///
    /// # Example
    /// ```
    /// use hockle::elastica::Elastica;
    /// let s = Elastica::symmetric(4, 0.5)?;
    /// // both ends keep the intrinsic curvature 2πn (zero end moment)
    /// let kappa0 = 8.0 * std::f64::consts::PI;
    /// for e in [s.upsilon, s.alpha] {
    ///     let [a, b] = e.end_curvatures();
    ///     assert!((a - kappa0).abs() < 1e-12 && (b - kappa0).abs() < 1e-12);
    /// }
    /// // the α-shape needs more force for the same k
    /// assert!(s.alpha.force() > s.upsilon.force());
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn symmetric(n: u32, k: f64) -> Result<Symmetric> {
        check_n(n)?;
        Self::symmetric_with(n, modulus_from_k(k)?)
    }

    /// [`Elastica::symmetric`] with the modulus given as a [`Modulus`]
    /// (exact complement, for k → 1).
    ///
    /// # Errors
    /// As [`Elastica::symmetric`].
    pub fn symmetric_with(n: u32, modulus: Modulus) -> Result<Symmetric> {
        check_n(n)?;
        let modulus = check_modulus(modulus)?;
        let big_k = ellip_k(modulus);
        // both shapes need E(k) for the extension when m ≥ ¼: compute it once
        let big_e = if modulus.m() >= SMALL_M {
            ellip_e(modulus)
        } else {
            f64::NAN
        };
        Ok(Symmetric {
            upsilon: primary_with(n, modulus, Family::Upsilon, big_k, big_e),
            alpha: primary_with(n, modulus, Family::Alpha, big_k, big_e),
        })
    }

    /// Only the primary υ-solution (half the work of [`Elastica::symmetric`]).
    ///
    /// # Errors
    /// As [`Elastica::symmetric`].
    pub fn upsilon(n: u32, modulus: Modulus) -> Result<Elastica> {
        check_n(n)?;
        Ok(primary(n, check_modulus(modulus)?, Family::Upsilon))
    }

    /// Only the primary α-solution.
    ///
    /// # Errors
    /// As [`Elastica::symmetric`].
    pub fn alpha(n: u32, modulus: Modulus) -> Result<Elastica> {
        check_n(n)?;
        Ok(primary(n, check_modulus(modulus)?, Family::Alpha))
    }
}

/// Below this m the small-k guess t ≈ n(K − π/2) is used.
const GUESS_SWITCH: f64 = 0.45;

/// Near k = 1, dn t ≈ sech t away from K: the υ end solves
/// 2(nK − t) sech t = πn and the α end τ = K − t solves
/// 2((n + 1)K − τ) sech τ = πn; three fixed-point steps of
/// t = acosh(2(cK − t)/(πn)).
fn asymptotic_guess(n: u32, big_k: f64, family: Family) -> f64 {
    let pn = core::f64::consts::PI * f64::from(n);
    let c = match family {
        Family::Upsilon => f64::from(n),
        Family::Alpha => f64::from(n) + 1.0,
    };
    let mut t = 0.0_f64;
    for _ in 0..3 {
        t = (2.0 * (c * big_k - t) / pn).max(1.0).acosh();
    }
    match family {
        Family::Upsilon => t,
        Family::Alpha => big_k - t,
    }
}

pub(crate) fn primary(n: u32, modulus: Modulus, family: Family) -> Elastica {
    primary_with(n, modulus, family, ellip_k(modulus), f64::NAN)
}

fn primary_with(n: u32, modulus: Modulus, family: Family, big_k: f64, big_e: f64) -> Elastica {
    let mut member = Member::new(family, n, n, big_k, modulus);
    member.big_e = big_e;
    let branch = match family {
        Family::Upsilon => Branch::Upsilon,
        Family::Alpha => Branch::Alpha,
    };
    let (t, jac) = if modulus.m() == 0.0 {
        (0.0, jacobi(0.0, modulus))
    } else {
        // t ≈ n(K − π/2) for small k (both families); near k = 1 the end
        // sits about ln(4K/π) from the extremum.
        let guess = if modulus.m() < GUESS_SWITCH {
            f64::from(n) * (big_k - FRAC_PI_2)
        } else {
            asymptotic_guess(n, big_k, family)
        };
        // υ: g(0) = 2nK − πn ≥ 0 decreasing; α: g(0) = 2nKk' − πn ≤ 0 increasing
        member.solve(0.0, big_k, family == Family::Upsilon, guess)
    };
    Elastica::from_parts(
        n,
        modulus,
        big_k,
        member.omega(t),
        member.excess(t),
        member.start(t),
        member.ends(jac),
        branch,
    )
}
