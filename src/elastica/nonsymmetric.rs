//! The non-symmetric ϑ-shapes: a whole number j of periods (eq81, eq82).

use core::f64::consts::PI;

use super::integrals::k_minus_half_pi;
use super::solution::{Branch, Elastica, Ends, check_j, check_modulus, check_n, modulus_from_k};
use crate::error::Result;
use crate::special::{Modulus, ellip_f, ellip_k};

impl Elastica {
    /// The non-symmetric ϑ-solutions with j periods for n coils at modulus
    /// k: every root s1 ∈ [0, 1/j) of eq81.
    ///
    /// ```text
    /// Ω = 2jK(k),   πn = 2jK dn(2jK s1)            (eq81)
    /// Δz = (2/k²)(1 − E/K) − 1                      (eq82, independent of n and s1)
    /// F = k²Ω² = 4k²K²j²                            (physical; the paper prints 8k²K²j²)
    /// ```
    ///
    /// With c = πn/(2jK) the roots exist for k′ ≤ c ≤ 1, i.e. always for
    /// j = n, from the bifurcation point on for j ≠ n
    /// ([`bifurcation`](super::bifurcation)). They come in mirror pairs
    /// u1 = u0 and 2K − u0 with dn u0 = c (the same force, extension and
    /// energy; one shape is the other reflected and traversed backwards);
    /// at c = 1 or c = k′ (the ring at k = 0, the bifurcation point) the pair
    /// merges into one root. Returns an empty vector where there is no root.
    ///
    /// # Errors
    /// [`Error::InvalidCount`](crate::Error::InvalidCount) if n = 0 or j = 0;
    /// [`Error::InvalidModulus`](crate::Error::InvalidModulus) /
    /// [`Error::ModulusNotBelowOne`](crate::Error::ModulusNotBelowOne) for k
    /// outside [0, 1).
    ///
    /// # Example
    /// ```
    /// use hockle::elastica::Elastica;
    /// let v = Elastica::nonsymmetric(3, 3, 0.9)?;
    /// assert_eq!(v.len(), 2);
    /// assert_eq!(v[0].force(), v[1].force());
    /// let kappa0 = 6.0 * std::f64::consts::PI;
    /// assert!((v[0].end_curvatures()[1] - kappa0).abs() < 1e-11);
    /// // ϑ_1 does not exist for n = 3 at k = 0.9 (it starts at k ≈ 0.9949)
    /// assert!(Elastica::nonsymmetric(3, 1, 0.9)?.is_empty());
    /// # Ok::<(), hockle::Error>(())
    /// ```
    pub fn nonsymmetric(n: u32, j: u32, k: f64) -> Result<Vec<Elastica>> {
        check_n(n)?;
        check_j(j)?;
        Self::nonsymmetric_with(n, j, modulus_from_k(k)?)
    }

    /// [`Elastica::nonsymmetric`] with a [`Modulus`] (k → 1).
    ///
    /// # Errors
    /// As [`Elastica::nonsymmetric`].
    pub fn nonsymmetric_with(n: u32, j: u32, modulus: Modulus) -> Result<Vec<Elastica>> {
        check_n(n)?;
        check_j(j)?;
        let modulus = check_modulus(modulus)?;
        let big_k = ellip_k(modulus);
        let omega = 2.0 * f64::from(j) * big_k;
        let c = PI * f64::from(n) / omega;
        let kp = modulus.k_prime();
        let branch = Branch::Theta { j };
        let excess = 2.0 * f64::from(j) * k_minus_half_pi(modulus.m(), big_k)
            + PI * (f64::from(j) - f64::from(n));
        // a few ulps of slack at the ends of the range (the ring, the
        // bifurcation point), where c is 1 or k' up to rounding
        const SLACK: f64 = 4.0 * f64::EPSILON;
        if c > 1.0 + SLACK || c < kp * (1.0 - SLACK) {
            return Ok(Vec::new());
        }
        let c = c.clamp(kp, 1.0);
        if modulus.m() == 0.0 {
            // the ring: every s1 is a root; report s1 = 0
            return Ok(vec![Elastica::from_parts(
                n,
                modulus,
                big_k,
                omega,
                excess,
                0.0,
                Ends::Periodic { j },
                branch,
            )]);
        }
        // dn u0 = c: sin φ = √((1 − c)(1 + c)/m), cos φ = √((c − k')(c + k')/m)
        let phi = ((1.0 - c) * (1.0 + c))
            .sqrt()
            .atan2(((c - kp) * (c + kp)).sqrt());
        let u0 = ellip_f(phi, modulus);
        let mut out = vec![Elastica::from_parts(
            n,
            modulus,
            big_k,
            omega,
            excess,
            u0,
            Ends::Periodic { j },
            branch,
        )];
        let mirror = 2.0 * big_k - u0;
        if u0 > 0.0 && mirror > u0 {
            out.push(Elastica::from_parts(
                n,
                modulus,
                big_k,
                omega,
                excess,
                mirror,
                Ends::Periodic { j },
                branch,
            ));
        }
        Ok(out)
    }
}
