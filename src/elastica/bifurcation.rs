//! Where a secondary symmetric branch meets the ϑ-branch it is born from.

use core::f64::consts::{FRAC_PI_2, PI};

use super::integrals::k_minus_half_pi;
use super::solution::{Branch, Elastica, Ends, check_j, check_n};
use crate::error::{Error, Result};
use crate::special::{Modulus, ellip_e, ellip_k};

/// The bifurcation point of secondary branch j with ϑ_j for n coils.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Bifurcation {
    n: u32,
    j: u32,
    modulus: Modulus,
    big_k: f64,
    force: f64,
    extension: f64,
}

impl Bifurcation {
    /// Coils n.
    #[must_use]
    pub fn coils(&self) -> u32 {
        self.n
    }

    /// Periods j.
    #[must_use]
    pub fn periods(&self) -> u32 {
        self.j
    }

    /// The modulus k at the bifurcation.
    #[must_use]
    pub fn modulus(&self) -> f64 {
        self.modulus.k()
    }

    /// The modulus with its exact complement m₁ = 1 − k².
    #[must_use]
    pub fn elliptic_modulus(&self) -> Modulus {
        self.modulus
    }

    /// Physical tension F = k²Ω², Ω = 2jK: k²π²n² for j < n, π²n²k²/k′² for
    /// j > n.
    #[must_use]
    pub fn force(&self) -> f64 {
        self.force
    }

    /// F/(2πn)².
    #[must_use]
    pub fn force_scaled(&self) -> f64 {
        let s = 2.0 * PI * f64::from(self.n);
        self.force / (s * s)
    }

    /// Extension Δz (eq82).
    #[must_use]
    pub fn extension(&self) -> f64 {
        self.extension
    }

    /// The solution at the bifurcation point (a ϑ-shape whose ends sit at a
    /// curvature extremum: maxima for j < n, minima for j > n; it is also the
    /// secondary symmetric solution there).
    #[must_use]
    pub fn solution(&self) -> Elastica {
        let modulus = self.elliptic_modulus();
        let u1 = if self.j < self.n { 0.0 } else { self.big_k };
        Elastica::from_parts(
            self.n,
            modulus,
            self.big_k,
            2.0 * f64::from(self.j) * self.big_k,
            2.0 * f64::from(self.j) * k_minus_half_pi(modulus.m(), self.big_k)
                + PI * (f64::from(self.j) - f64::from(self.n)),
            u1,
            Ends::Periodic { j: self.j },
            Branch::Theta { j: self.j },
        )
    }
}

impl core::fmt::Display for Bifurcation {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "bifurcation n = {}, j = {}: k = {}, F = {}, Δz = {}",
            self.n,
            self.j,
            self.modulus.k(),
            self.force,
            self.extension
        )
    }
}

/// The bifurcation point where the secondary symmetric branch j meets the
/// non-symmetric branch ϑ_j, for a rod of n coils: where eq81 gets its
/// double root (the ends at a curvature extremum).
///
/// ```text
/// j < n:  2jK(k) = πn        (ends at curvature maxima, υ)
/// j > n:  2jK(k) k' = πn     (ends at curvature minima, α)
/// F = k²(2jK)² ,  Δz = (2/k²)(1 − E/K) − 1   (eq82)
/// ```
///
/// These are the closed forms: one transcendental equation in k each,
/// solved by Newton's method in x = ln m₁ (m₁ = 1 − k²; the unknown spans
/// decades as n/j grows) with a bisection safeguard, to full precision.
///
/// # Errors
/// [`Error::InvalidCount`] if n = 0 or j = 0, or if n/j ≥ 222 (the
/// modulus would have 1 − k² below the smallest double);
/// [`Error::SecondaryNeedsOtherPeriods`] if j = n.
///
/// # Accuracy
/// k, force and extension within 1e-14 relative of the mpmath table for
/// n = 1..10, j = 1..7 (`tests/elastica`).
///
/// # Example
/// ```
/// use hockle::elastica::bifurcation;
/// let b = bifurcation(4, 3)?;
/// // for j < n, Ω = πn exactly, so F = k²π²n²
/// let pn = 4.0 * std::f64::consts::PI;
/// assert!((b.force() - b.modulus().powi(2) * pn * pn).abs() < 1e-12 * b.force());
/// assert!((b.modulus() - 0.844_167_424_54).abs() < 1e-10);
/// # Ok::<(), hockle::Error>(())
/// ```
pub fn bifurcation(n: u32, j: u32) -> Result<Bifurcation> {
    check_n(n)?;
    check_j(j)?;
    if j == n {
        return Err(Error::SecondaryNeedsOtherPeriods { n });
    }
    let target = PI * f64::from(n) / (2.0 * f64::from(j));
    let upsilon = j < n;
    // K(k) = target needs m₁ ≈ 16 e^(−2 target): below the smallest double
    // once target > 350
    if upsilon && target > 350.0 {
        return Err(Error::InvalidCount {
            name: "n",
            value: u64::from(n),
            allowed: "n/j < 222 (πn/(2j) < 350), so that the bifurcation modulus 1 − k² is above the smallest double",
        });
    }
    // f(x) = K(m₁ = e^x) − target (υ) or K k' − target (α); f decreases in
    // m (increases as x decreases) for υ, the other way for α.
    let eval = |x: f64| -> Result<(f64, f64, Modulus)> {
        let mc = x.exp();
        let modulus = Modulus::from_complement(mc)?;
        let m = modulus.m();
        let kk = ellip_k(modulus);
        let ee = ellip_e(modulus);
        // dK/dm₁ · m₁ = −(E − m₁K)/(2m)
        let dk_dx = -(ee - mc * kk) / (2.0 * m);
        Ok(if upsilon {
            (kk - target, dk_dx, modulus)
        } else {
            let kp = mc.sqrt();
            (kk * kp - target, kp * (dk_dx + 0.5 * kk), modulus)
        })
    };
    // bracket in x: x → 0 (k → 0) gives π/2 − target (< 0 for υ, > 0 for α);
    // x = −1400 (m₁ = e^−1400 underflows: use −700) gives K ≈ 350 (υ > 0),
    // K k' ≈ 0 (α < 0).
    let (mut lo, mut hi) = (-700.0_f64, -1e-300_f64);
    // initial guess from K ≈ ½ ln(16/m₁) (υ) or K k' = target solved with
    // the same asymptotic (α), else a small-m guess.
    let mut x = if upsilon {
        if target > 2.0 {
            16f64.ln() - 2.0 * target
        } else {
            (1.0 - 4.0 * (target / FRAC_PI_2 - 1.0)).max(1e-3).ln()
        }
    } else if target < 1.0 {
        // k' ln(4/k') = target
        let mut kp = target / 4.0;
        for _ in 0..8 {
            kp = target / (4.0 / kp).ln();
        }
        2.0 * kp.ln()
    } else {
        (1.0 - 4.0 * (1.0 - target / FRAC_PI_2)).max(1e-3).ln()
    };
    x = x.clamp(lo, hi);
    let mut modulus = eval(x)?.2;
    for _ in 0..200 {
        let (f, df, md) = eval(x)?;
        modulus = md;
        // υ: f > 0 ⇔ x too small (m₁ too small); α: f < 0 ⇔ x too small
        if (f > 0.0) == upsilon {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - f / df;
        let (next, ok) = if newton > lo && newton < hi && newton.is_finite() {
            (newton, true)
        } else {
            (0.5 * (lo + hi), false)
        };
        let dx = (next - x).abs();
        x = next;
        if ok && dx <= 1e-10 * x.abs().max(1.0) {
            modulus = eval(x)?.2;
            break;
        }
        if hi - lo <= 4.0 * f64::EPSILON * x.abs().max(1.0) {
            break;
        }
    }
    let big_k = ellip_k(modulus);
    let big_e = ellip_e(modulus);
    let m = modulus.m();
    let omega = 2.0 * f64::from(j) * big_k;
    Ok(Bifurcation {
        n,
        j,
        modulus,
        big_k,
        force: m * omega * omega,
        extension: 2.0 / m * (1.0 - big_e / big_k) - 1.0,
    })
}
