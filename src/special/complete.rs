//! Complete elliptic integrals K(k) and E(k).

use super::Modulus;
use super::carlson::{rd, rf};

/// Complete elliptic integral of the first kind K(k).
///
/// ```text
/// K(k) = ∫0^{π/2} dθ / √(1 − m sin²θ) = R_F(0, m₁, 1)        DLMF 19.2.8, 19.25.1
/// ```
/// with m = k², m₁ = 1 − m read exactly from the [`Modulus`].
///
/// # Special cases
/// K(0) = π/2; K(1) = +∞ (m₁ = 0); K ~ ½ ln(16/m₁) as m₁ → 0, finite for
/// every m₁ > 0 including subnormals.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_k};
/// let k = ellip_k(Modulus::from_m(0.5)?);
/// assert!((k - 1.854_074_677_301_372).abs() < 1e-15); // mpmath ellipk(0.5)
/// assert_eq!(ellip_k(Modulus::from_k(1.0)?), f64::INFINITY);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §19.2, §19.25; B. C. Carlson, Numer. Algorithms 10 (1995) 13–26.
#[must_use]
pub fn ellip_k(modulus: Modulus) -> f64 {
    let mc = modulus.complement();
    if mc == 0.0 {
        return f64::INFINITY;
    }
    rf(0.0, mc, 1.0)
}

/// Complete elliptic integral of the second kind E(k).
///
/// ```text
/// E(k) = ∫0^{π/2} √(1 − m sin²θ) dθ
///      = m₁ K(k) + (m m₁ / 3) R_D(0, 1, m₁)                      DLMF 19.2.8, 19.25.9 at φ = π/2
/// ```
/// Both terms are positive, so the sum loses nothing as m → 1 (the textbook
/// R_F − (m/3) R_D cancels there).
///
/// # Special cases
/// E(0) = π/2; E(1) = 1.
///
/// # Examples
/// ```
/// use hockle::special::{Modulus, ellip_e};
/// let e = ellip_e(Modulus::from_m(0.5)?);
/// assert!((e - 1.350_643_881_047_675_5).abs() < 1e-15); // mpmath ellipe(0.5)
/// assert_eq!(ellip_e(Modulus::from_k(1.0)?), 1.0);
/// # Ok::<(), hockle::Error>(())
/// ```
///
/// # References
/// DLMF §19.2, §19.25.
#[must_use]
pub fn ellip_e(modulus: Modulus) -> f64 {
    let (m, mc) = (modulus.m(), modulus.complement());
    if mc == 0.0 {
        return 1.0;
    }
    mc * rf(0.0, mc, 1.0) + m * mc / 3.0 * rd(0.0, 1.0, mc)
}
