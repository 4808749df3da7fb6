//! The two one-parameter families of symmetric solutions and their root solve.
//!
//! With the end of the rod at a distance t (in u = Ωs) from a curvature
//! extremum, eq6/eq7 become one equation in t for each family and integer c:
//!
//! ```text
//! υ-family:  Ω = 2(cK − t),   g(t) = Ω dn t − πn = 0,   ends at u = t and 2cK − t
//! α-family:  Ω = 2(cK + t),   g(t) = Ω k' nd t − πn = 0, ends at u = K − t and (2c+1)K + t
//! ```
//!
//! The primary branches are c = n (υ on t ∈ [0, K], g decreasing; α on
//! t ∈ [0, K], g increasing); the secondary branch j is c = j, split at the
//! extremum t* of g in (−K, 0) into two arms on [−K, t*] and [t*, K].

use core::f64::consts::PI;

use super::integrals::k_minus_half_pi;
use super::solution::Ends;
use crate::special::{Jacobi, Modulus, jacobi};

/// Which family.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Family {
    /// Ends near a curvature maximum (υ-type).
    Upsilon,
    /// Ends near a curvature minimum (α-type).
    Alpha,
}

/// One member of a family at one modulus.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Member {
    pub family: Family,
    pub c: f64,
    pub target: f64,
    pub big_k: f64,
    pub kp: f64,
    /// K − π/2, without cancellation for small m.
    pub d: f64,
    /// E(k) if already known (NaN otherwise), for the extension.
    pub big_e: f64,
    pub modulus: Modulus,
}

impl Member {
    pub fn new(family: Family, c: u32, n: u32, big_k: f64, modulus: Modulus) -> Self {
        Self {
            family,
            c: f64::from(c),
            target: PI * f64::from(n),
            big_k,
            kp: modulus.k_prime(),
            d: k_minus_half_pi(modulus.m(), big_k),
            big_e: f64::NAN,
            modulus,
        }
    }

    /// Ω − πn, without cancellation: 2cD + (c − n)π ∓ 2t.
    pub fn excess(&self, t: f64) -> f64 {
        let base = 2.0 * self.c * self.d + (self.c * PI - self.target);
        match self.family {
            Family::Upsilon => base - 2.0 * t,
            Family::Alpha => base + 2.0 * t,
        }
    }

    /// Ω at end distance t.
    pub fn omega(&self, t: f64) -> f64 {
        match self.family {
            Family::Upsilon => 2.0 * (self.c * self.big_k - t),
            Family::Alpha => 2.0 * (self.c * self.big_k + t),
        }
    }

    /// The start u1 of the rod in u = Ωs (the rod spans [u1, u1 + Ω]).
    pub fn start(&self, t: f64) -> f64 {
        match self.family {
            Family::Upsilon => t,
            Family::Alpha => self.big_k - t,
        }
    }

    /// The [`Ends`] of the member at t (with the Jacobi functions at t).
    pub fn ends(&self, jac: Jacobi) -> Ends {
        match self.family {
            Family::Upsilon => Ends::Upsilon {
                c: self.c,
                jac,
                e: self.big_e,
            },
            Family::Alpha => Ends::Alpha {
                c: self.c,
                jac,
                e: self.big_e,
            },
        }
    }

    /// g(t), g'(t), g''(t).
    pub fn eval(&self, t: f64) -> (f64, f64, f64) {
        self.eval_with(t, &jacobi(t, self.modulus))
    }

    /// g(t), g'(t), g''(t) from the Jacobi functions at t.
    pub fn eval_with(&self, t: f64, j: &Jacobi) -> (f64, f64, f64) {
        let m = self.modulus.m();
        let (sn, cn, dn) = (j.sn, j.cn, j.dn);
        let om = self.omega(t);
        // g = (Ω − πn) + Ω (dn − 1) (υ) or (Ω − πn) + Ω (k' nd − 1) (α), with
        // dn − 1 = −m sn²/(1 + dn) and k' nd − 1 = −m cn²/(dn (k' + dn)):
        // every term is O(k²) and computed to relative accuracy, so the root
        // t is found to relative accuracy even as k → 0.
        let ex = self.excess(t);
        match self.family {
            Family::Upsilon => {
                let d1 = -m * sn * cn;
                let d2 = -m * dn * (cn * cn - sn * sn);
                (
                    ex - om * m * sn * sn / (1.0 + dn),
                    -2.0 * dn + om * d1,
                    -4.0 * d1 + om * d2,
                )
            }
            Family::Alpha => {
                // near t = K, cn and dn are O(k'): for k' ≈ 1e-162 (m₁
                // subnormal) their products underflow, so everything is
                // written with the O(1) ratios k' nd and cd = cn/dn
                let kn = self.kp / dn;
                let cd = cn / dn;
                (
                    ex - om * m * cd * (cn / (self.kp + dn)),
                    kn * (2.0 + om * m * sn * cd),
                    m * kn
                        * (4.0 * sn * cd
                            + om * ((cn * cn - sn * sn) + 2.0 * m * sn * sn * cd * cd)),
                )
            }
        }
    }

    /// The root of g in [a, b] where g(a) and g(b) have opposite signs
    /// (given as `a_positive`), by Halley steps kept inside the bracket with
    /// bisection as the fallback, from `guess`. Returns the root and the
    /// Jacobi functions there: Newton runs until its step is below 8ε|t|,
    /// and the point where the functions were last evaluated is returned
    /// (its error is that step).
    pub fn solve(&self, mut a: f64, mut b: f64, a_positive: bool, guess: f64) -> (f64, Jacobi) {
        let mut x = guess.clamp(a, b);
        let mut last = (
            x,
            Jacobi {
                sn: f64::NAN,
                cn: f64::NAN,
                dn: f64::NAN,
                am: f64::NAN,
            },
        );
        let mut dx_prev = f64::INFINITY;
        for _ in 0..200 {
            let jac = jacobi(x, self.modulus);
            last = (x, jac);
            let (g, g1, g2) = self.eval_with(x, &jac);
            if g == 0.0 {
                return last;
            }
            if (g > 0.0) == a_positive {
                a = x;
            } else {
                b = x;
            }
            // Halley's step (cubic convergence; g'' comes almost free)
            let newton = x - 2.0 * g * g1 / (2.0 * g1 * g1 - g * g2);
            let (next, newton_ok) = if newton >= a && newton <= b && newton.is_finite() {
                (newton, true)
            } else {
                (0.5 * (a + b), false)
            };
            let dx = (next - x).abs();
            // relative to |t|: t → 0 as k → 0 and the extension needs t to
            // relative accuracy. Newton's steps shrink quadratically until
            // they reach the rounding noise of g; a step at the 1e-10 level
            // that is not at least 4 times smaller than the previous one is
            // that noise.
            if newton_ok
                && (dx <= 8.0 * f64::EPSILON * x.abs()
                    || (dx <= 1e-10 * x.abs() && dx >= 0.25 * dx_prev))
            {
                return last;
            }
            dx_prev = if newton_ok { dx } else { f64::INFINITY };
            if (b - a) <= 4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE) {
                return last;
            }
            x = next;
        }
        last
    }

    /// The extremum t* of g in (−K, 0) nearest to 0 (the maximum for the
    /// υ-family, the minimum for the α-family), or `None` if g has no
    /// extremum there.
    pub fn extremum(&self) -> Option<f64> {
        // sign of g' at 0: υ −2 < 0, α 2k' > 0; t* is where g' first takes the
        // other sign going left from 0.
        let s0 = self.eval(0.0).1 > 0.0;
        const N: usize = 32;
        let mut hi = 0.0;
        let mut lo = None;
        for i in 1..N {
            let t = -self.big_k * i as f64 / N as f64;
            if (self.eval(t).1 > 0.0) != s0 {
                lo = Some(t);
                break;
            }
            hi = t;
        }
        let mut a = lo?;
        let mut b = hi;
        // Newton on g' inside [a, b], bisection fallback.
        let mut x = 0.5 * (a + b);
        let scale = self.big_k.max(1.0);
        for _ in 0..200 {
            let (_, g1, g2) = self.eval(x);
            if (g1 > 0.0) == s0 {
                b = x;
            } else {
                a = x;
            }
            let newton = x - g1 / g2;
            let (next, ok) = if newton >= a && newton <= b && newton.is_finite() {
                (newton, true)
            } else {
                (0.5 * (a + b), false)
            };
            let dx = (next - x).abs();
            x = next;
            if (ok && dx <= 1e-9 * scale) || (b - a) <= 4.0 * f64::EPSILON * scale {
                return Some(x);
            }
        }
        Some(x)
    }
}
