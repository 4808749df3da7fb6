//! Second-order jets: a value with its exact gradient and Hessian in N
//! variables, propagated through +, −, ×, ÷ and scalar functions by the
//! chain rule (forward-mode automatic differentiation to second order). The
//! second variation of the discrete rod ([`super::stability`]) is assembled
//! from them, exact to rounding.

use core::ops::{Add, Mul, Neg, Sub};

#[derive(Debug, Clone, Copy)]
pub(crate) struct Jet<const N: usize> {
    pub v: f64,
    pub g: [f64; N],
    pub h: [[f64; N]; N],
}

impl<const N: usize> Jet<N> {
    pub(crate) fn constant(v: f64) -> Self {
        Self {
            v,
            g: [0.0; N],
            h: [[0.0; N]; N],
        }
    }

    /// f(self) from f, f′, f″ at self's value.
    pub(crate) fn apply(self, f0: f64, f1: f64, f2: f64) -> Self {
        let mut out = Self::constant(f0);
        for a in 0..N {
            out.g[a] = f1 * self.g[a];
            for b in 0..N {
                out.h[a][b] = f1 * self.h[a][b] + f2 * self.g[a] * self.g[b];
            }
        }
        out
    }

    pub(crate) fn scale(mut self, c: f64) -> Self {
        self.v *= c;
        for a in 0..N {
            self.g[a] *= c;
            for b in 0..N {
                self.h[a][b] *= c;
            }
        }
        self
    }

    pub(crate) fn recip(self) -> Self {
        let x = self.v;
        self.apply(1.0 / x, -1.0 / (x * x), 2.0 / (x * x * x))
    }
}

impl<const N: usize> Add for Jet<N> {
    type Output = Self;
    fn add(mut self, o: Self) -> Self {
        self.v += o.v;
        for a in 0..N {
            self.g[a] += o.g[a];
            for b in 0..N {
                self.h[a][b] += o.h[a][b];
            }
        }
        self
    }
}

impl<const N: usize> Neg for Jet<N> {
    type Output = Self;
    fn neg(self) -> Self {
        self.scale(-1.0)
    }
}

impl<const N: usize> Sub for Jet<N> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        self + (-o)
    }
}

impl<const N: usize> Mul for Jet<N> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let mut out = Self::constant(self.v * o.v);
        for a in 0..N {
            out.g[a] = self.v * o.g[a] + o.v * self.g[a];
            for b in 0..N {
                out.h[a][b] = self.v * o.h[a][b]
                    + o.v * self.h[a][b]
                    + self.g[a] * o.g[b]
                    + o.g[a] * self.g[b];
            }
        }
        out
    }
}

/// A quaternion (w, x, y, z) of jets.
pub(crate) type QuatJet<const N: usize> = [Jet<N>; 4];

/// a ⊗ b.
pub(crate) fn quat_mul<const N: usize>(a: &QuatJet<N>, b: &QuatJet<N>) -> QuatJet<N> {
    let [aw, ax, ay, az] = *a;
    let [bw, bx, by, bz] = *b;
    [
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    ]
}

/// A constant quaternion as jets.
pub(crate) fn quat_const<const N: usize>(q: [f64; 4]) -> QuatJet<N> {
    q.map(Jet::constant)
}

/// exp(φ/2) to second order, (1 − |φ|²/8, φ/2), with φ the variables
/// `offset..offset + 3` (a rotation by |φ| about φ, in the body frame when
/// multiplied on the right).
pub(crate) fn rotation<const N: usize>(offset: usize) -> QuatJet<N> {
    let mut q = quat_const([1.0, 0.0, 0.0, 0.0]);
    for a in 0..3 {
        q[0].h[offset + a][offset + a] = -0.25;
        q[a + 1].g[offset + a] = 0.5;
    }
    q
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_and_quotients_carry_exact_second_derivatives() {
        // f(x, y) = x²y/(1 + y) at (2, 3): f = 3, f_x = 3, f_y = 0.25,
        // f_xx = 1.5, f_xy = 0.25, f_yy = −0.125 (by hand).
        let mut x = Jet::<2>::constant(2.0);
        x.g[0] = 1.0;
        let mut y = Jet::<2>::constant(3.0);
        y.g[1] = 1.0;
        let f = x * x * y * (Jet::constant(1.0) + y).recip();
        let expect = [3.0, 3.0, 0.25, 1.5, 0.25, -0.125];
        let got = [f.v, f.g[0], f.g[1], f.h[0][0], f.h[0][1], f.h[1][1]];
        for (g, e) in got.iter().zip(expect) {
            // a few roundings of numbers of order 1
            assert!((g - e).abs() < 1e-14, "{got:?}");
        }
        assert_eq!(f.h[0][1], f.h[1][0]);
    }
}
