//! Many evaluations at one modulus: [`FixedModulus`].

use super::Modulus;
use super::complete::{ellip_e_dd, ellip_k_dd};
use super::derivatives::{JacobiDm, ellip_k_dm, jacobi_dm_from};
use super::duplication::{MaclaurinHigh, Quarter};
use super::epsilon::{epsilon_assemble, epsilon_half_period};
use super::jacobi::{Jacobi, assemble, jacobi_special, sncndn_am_half_period};
use super::landen::{LANDEN_MC, LANDEN_MIN_V, LandenChain};
use super::period::Period;
use crate::error::{Error, Result};

/// A modulus together with everything that evaluating sn, cn, dn, am and ε
/// needs once per modulus: K and E in double-double, the constants that
/// reduce u modulo 2K, the Maclaurin coefficients of the doubling path and,
/// for m₁ ≤ 0.1, the ascending Landen chain that covers [0, K/2].
///
/// [`jacobi`](crate::special::jacobi) and
/// [`jacobi_epsilon`](crate::special::jacobi_epsilon) recompute all of this
/// at every call; for many u at one modulus (Newton or Halley steps in u,
/// sampling a shape, quadrature) build a `FixedModulus` once. Results agree
/// with the single-call functions to within their accuracy (both ≤ 2 ulp
/// normalised; the Landen chain here may take one step more).
///
/// # Examples
/// ```
/// use hockle::special::{FixedModulus, Jacobi, Modulus, jacobi};
/// let md = Modulus::from_complement(1e-6)?;
/// let fixed = FixedModulus::new(md);
/// let us: Vec<f64> = (0..100).map(|i| 0.1 * f64::from(i)).collect();
/// let mut out = vec![Jacobi::default(); us.len()];
/// fixed.jacobi_slice(&us, &mut out)?;
/// for (u, j) in us.iter().zip(&out) {
///     let single = jacobi(*u, md);
///     assert!((j.cn - single.cn).abs() <= 4.0 * f64::EPSILON * (1.0 + u));
/// }
/// assert!((fixed.k() - 8.294_051_463_615_44).abs() < 1e-14); // mpmath ellipk(1 - 1e-6)
/// # Ok::<(), hockle::Error>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct FixedModulus {
    modulus: Modulus,
    period: Period,
    e: (f64, f64),
    kp: f64,
    series: MaclaurinHigh,
    landen: Option<LandenChain>,
}

impl From<Modulus> for FixedModulus {
    fn from(modulus: Modulus) -> Self {
        Self::new(modulus)
    }
}

impl FixedModulus {
    /// Precomputes K, E, the reduction constants and the series or Landen
    /// chain for `modulus` (about the cost of two or three `jacobi` calls).
    #[must_use]
    pub fn new(modulus: Modulus) -> Self {
        let (m, mc) = (modulus.m(), modulus.complement());
        let k_dd = ellip_k_dd(modulus);
        let period = Period::from_dd(k_dd);
        let landen = (mc <= LANDEN_MC && mc > 0.0 && 0.5 * period.k >= LANDEN_MIN_V)
            .then(|| LandenChain::new(m, mc, 0.5 * period.k));
        Self {
            modulus,
            period,
            e: ellip_e_dd(modulus),
            kp: mc.sqrt(),
            series: MaclaurinHigh::new(m, mc),
            landen,
        }
    }

    /// The modulus.
    #[must_use]
    pub fn modulus(&self) -> Modulus {
        self.modulus
    }

    /// The complete integral K (the quarter period), as
    /// [`ellip_k`](crate::special::ellip_k).
    #[must_use]
    pub fn k(&self) -> f64 {
        self.period.k
    }

    /// The complete integral E, as [`ellip_e`](crate::special::ellip_e).
    #[must_use]
    pub fn e(&self) -> f64 {
        self.e.0 + self.e.1
    }

    /// (sn, cn, dn) on [0, K/2].
    #[inline(always)]
    fn quarter(&self, v: f64) -> Quarter {
        match &self.landen {
            Some(chain) if v >= LANDEN_MIN_V => {
                let (s, c, d) = chain.eval(v);
                (s, c, d, s, c, 1.0)
            }
            _ => self.series.eval(v),
        }
    }

    /// sn, cn, dn and am at u, as [`jacobi`](crate::special::jacobi).
    #[must_use]
    #[inline]
    pub fn jacobi(&self, u: f64) -> Jacobi {
        let (m, mc) = (self.modulus.m(), self.modulus.complement());
        if let Some(j) = jacobi_special(u, m, mc) {
            return j;
        }
        let red = self.period.reduce(u);
        let f = sncndn_am_half_period(red.r.abs(), &self.period, mc, self.kp, |v| self.quarter(v));
        assemble(&red, f)
    }

    /// Jacobi's ε(u) = E(am u, k), as
    /// [`jacobi_epsilon`](crate::special::jacobi_epsilon).
    #[must_use]
    #[inline]
    pub fn epsilon(&self, u: f64) -> f64 {
        let (m, mc) = (self.modulus.m(), self.modulus.complement());
        if !u.is_finite() {
            return f64::NAN;
        }
        if m == 0.0 {
            return u;
        }
        if mc == 0.0 {
            return u.tanh();
        }
        let red = self.period.reduce(u);
        let e_r = epsilon_half_period(red.r.abs(), &self.period, self.e(), m, mc, |v| {
            let (s, c, d, ..) = self.quarter(v);
            (s, c, d)
        });
        epsilon_assemble(red.j, red.r, e_r, self.e)
    }

    /// sn, cn, dn, am at u and their derivatives in m at fixed u, as
    /// [`jacobi_dm`](crate::special::jacobi_dm).
    #[must_use]
    pub fn jacobi_dm(&self, u: f64) -> (Jacobi, JacobiDm) {
        let value = self.jacobi(u);
        if !u.is_finite() {
            let nan = f64::NAN;
            return (
                value,
                JacobiDm {
                    sn: nan,
                    cn: nan,
                    dn: nan,
                    am: nan,
                },
            );
        }
        let m = self.modulus.m();
        let (j, r) = if self.modulus.complement() == 0.0 {
            (0.0, u)
        } else {
            let red = self.period.reduce(u);
            (red.j, red.r)
        };
        let d = jacobi_dm_from(&value, j, r, m, || ellip_k_dm(self.modulus));
        (value, d)
    }

    /// [`FixedModulus::jacobi`] at every u of a slice, written to `out`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] if `out` is not as long as `u` (nothing is
    /// written then).
    pub fn jacobi_slice(&self, u: &[f64], out: &mut [Jacobi]) -> Result<()> {
        check_len(u.len(), out.len())?;
        for (o, &x) in out.iter_mut().zip(u) {
            *o = self.jacobi(x);
        }
        Ok(())
    }

    /// [`FixedModulus::epsilon`] at every u of a slice, written to `out`.
    ///
    /// # Errors
    /// [`Error::LengthMismatch`] if `out` is not as long as `u` (nothing is
    /// written then).
    pub fn epsilon_slice(&self, u: &[f64], out: &mut [f64]) -> Result<()> {
        check_len(u.len(), out.len())?;
        for (o, &x) in out.iter_mut().zip(u) {
            *o = self.epsilon(x);
        }
        Ok(())
    }
}

fn check_len(expected: usize, found: usize) -> Result<()> {
    if expected == found {
        Ok(())
    } else {
        Err(Error::LengthMismatch {
            name: "out",
            found: found as u64,
            expected: expected as u64,
        })
    }
}
