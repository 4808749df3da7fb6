//! The [`Modulus`] type: k, m = k² and m₁ = 1 − m held together exactly.

use core::fmt;

use crate::error::{Error, Result};

/// The modulus of a Jacobi elliptic function or elliptic integral, held as
/// the modulus k, the parameter m = k² and the complementary parameter
/// m₁ = 1 − m = k′², all three stored.
///
/// ```text
/// m = k²,   m₁ = 1 − m = k′²,   0 ≤ k, m, m₁ ≤ 1
/// ```
///
/// **k or m?** DLMF writes the functions of the modulus k (`sn(u, k)`,
/// `K(k)`); Abramowitz–Stegun, SciPy, Boost's `*_m` functions and the `ellip`
/// crate take the parameter m = k². Pick the constructor that matches your
/// formula: [`Modulus::from_k`], [`Modulus::from_m`] or
/// [`Modulus::from_complement`].
///
/// **Why the complement.** Near k = 1 the functions depend on m₁, not on m:
/// K ≈ ½ ln(16/m₁). Rounding m = 1 − 10⁻²⁰ to a double gives m = 1 and
/// K = ∞. [`Modulus::from_complement`] keeps m₁ exact (down to the smallest
/// subnormal), and every function in [`crate::special`] reads m₁ from here,
/// never 1 − m.
///
/// The constructor validates once; every function taking a `Modulus` is then
/// infallible.
///
/// # Examples
/// ```
/// use hockle::special::Modulus;
/// let a = Modulus::from_k(0.5)?;
/// assert_eq!((a.m(), a.complement()), (0.25, 0.75));
/// let b = Modulus::from_complement(1e-300)?; // k → 1 without losing m₁
/// assert_eq!(b.m(), 1.0);
/// assert_eq!(b.complement(), 1e-300);
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(
    feature = "serde",
    derive(serde::Serialize, serde::Deserialize),
    serde(try_from = "ModulusParts", into = "ModulusParts")
)]
pub struct Modulus {
    k: f64,
    m: f64,
    mc: f64,
}

/// The serialized form of a [`Modulus`]: all three numbers, so that a round
/// trip is exact (m₁ near 1e-300 cannot be recovered from m).
#[cfg(feature = "serde")]
#[derive(serde::Serialize, serde::Deserialize)]
struct ModulusParts {
    k: f64,
    m: f64,
    m1: f64,
}

#[cfg(feature = "serde")]
impl From<Modulus> for ModulusParts {
    fn from(md: Modulus) -> Self {
        Self {
            k: md.k,
            m: md.m,
            m1: md.mc,
        }
    }
}

#[cfg(feature = "serde")]
impl TryFrom<ModulusParts> for Modulus {
    type Error = Error;

    /// Accepts the parts of a modulus that one of the constructors could
    /// have made: each in [0, 1], m + m₁ = 1 and k² = m to a few roundings.
    fn try_from(p: ModulusParts) -> Result<Self> {
        for (name, value) in [("k", p.k), ("m", p.m), ("m1", p.m1)] {
            if !(0.0..=1.0).contains(&value) {
                return Err(Error::InvalidModulus { name, value });
            }
        }
        let tol = 4.0 * f64::EPSILON;
        if (p.m + p.m1 - 1.0).abs() > tol || (p.k * p.k - p.m).abs() > tol {
            return Err(Error::InvalidModulus {
                name: "m1",
                value: p.m1,
            });
        }
        Ok(Self {
            k: p.k,
            m: p.m,
            mc: p.m1,
        })
    }
}

impl Modulus {
    /// From the modulus k ∈ [0, 1]; m = k², m₁ = (1 − k)(1 + k) (no
    /// cancellation: 1 − k is exact for k ≥ ½).
    ///
    /// # Errors
    /// [`Error::InvalidModulus`] if k is NaN or outside [0, 1].
    #[inline]
    pub fn from_k(k: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&k) {
            return Err(Error::InvalidModulus {
                name: "k",
                value: k,
            });
        }
        Ok(Self {
            k,
            m: k * k,
            mc: (1.0 - k) * (1.0 + k),
        })
    }

    /// From the parameter m = k² ∈ [0, 1]; m₁ = 1 − m (exact for m ≥ ½).
    ///
    /// # Errors
    /// [`Error::InvalidModulus`] if m is NaN or outside [0, 1].
    #[inline]
    pub fn from_m(m: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&m) {
            return Err(Error::InvalidModulus {
                name: "m",
                value: m,
            });
        }
        Ok(Self {
            k: m.sqrt(),
            m,
            mc: 1.0 - m,
        })
    }

    /// From the complementary parameter m₁ = 1 − m = k′² ∈ [0, 1], kept
    /// exactly: the way to reach k → 1.
    ///
    /// # Errors
    /// [`Error::InvalidModulus`] if m₁ is NaN or outside [0, 1].
    #[inline]
    pub fn from_complement(mc: f64) -> Result<Self> {
        if !(0.0..=1.0).contains(&mc) {
            return Err(Error::InvalidModulus {
                name: "m1",
                value: mc,
            });
        }
        let m = 1.0 - mc;
        Ok(Self { k: m.sqrt(), m, mc })
    }

    /// The modulus k.
    #[must_use]
    #[inline]
    pub fn k(self) -> f64 {
        self.k
    }

    /// The parameter m = k².
    #[must_use]
    #[inline]
    pub fn m(self) -> f64 {
        self.m
    }

    /// The complementary parameter m₁ = 1 − m = k′².
    #[must_use]
    #[inline]
    pub fn complement(self) -> f64 {
        self.mc
    }

    /// The complementary modulus k′ = √m₁.
    #[must_use]
    #[inline]
    pub fn k_prime(self) -> f64 {
        self.mc.sqrt()
    }

    /// The complementary `Modulus` (k ↔ k′, m ↔ m₁), so that
    /// `ellip_k(m.complementary())` is K′ = K(k′).
    #[must_use]
    #[inline]
    pub fn complementary(self) -> Self {
        Self {
            k: self.mc.sqrt(),
            m: self.mc,
            mc: self.m,
        }
    }
}

impl fmt::Display for Modulus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "k = {}, m = {}, m1 = {}", self.k, self.m, self.mc)
    }
}
