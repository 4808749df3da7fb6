//! Carlson's symmetric integrals R_F and R_D by duplication (DLMF 19.36.1,
//! 19.36.2; Carlson, Numer. Algorithms 10 (1995) 13–26), crate-private.
//!
//! ```text
//! R_F(x,y,z) = ½ ∫0^∞ dt / √((t+x)(t+y)(t+z))
//! R_D(x,y,z) = 3/2 ∫0^∞ dt / (√((t+x)(t+y)) (t+z)^{3/2})
//! ```
//! Each duplication step replaces (x, y, z) by ((x+λ)/4, …) with
//! λ = √x√y + √y√z + √z√x, shrinking the spread by 4; once the spread is
//! below ~ε^{1/8} the 7th-order Taylor series of DLMF 19.36.1/2 ends it.

/// Relative spread below which the series is exact to rounding:
/// the first neglected term is O(Δ⁸), so Δ ≤ 2.4e-3 gives Δ⁸ ≤ 1.1e-21.
const TOL_RF: f64 = 2.4e-3;
/// The same for R_D (its first neglected term is O(Δ⁶) with a small
/// coefficient): Δ⁶ ≤ 1e-18 at Δ = 1e-3.
const TOL_RD: f64 = 1.0e-3;

/// R_F(x, y, z) for x, y, z ≥ 0, at most one of them zero.
pub(crate) fn rf(x: f64, y: f64, z: f64) -> f64 {
    let (x0, y0) = (x, y);
    let (mut x, mut y, mut z) = (x, y, z);
    let a0 = (x + y + z) / 3.0;
    let mut a = a0;
    let q = (a0 - x).abs().max((a0 - y).abs()).max((a0 - z).abs()) / TOL_RF;
    let mut scale = 1.0; // 4^-n
    while scale * q >= a {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        a = 0.25 * (a + lambda);
        scale *= 0.25;
    }
    let xx = (a0 - x0) * scale / a;
    let yy = (a0 - y0) * scale / a;
    let zz = -(xx + yy);
    let e2 = xx * yy - zz * zz;
    let e3 = xx * yy * zz;
    // DLMF 19.36.1 through 7th order.
    let s = e2 * (-1.0 / 10.0 + e2 * (1.0 / 24.0 - 5.0 / 208.0 * e2))
        + e3 * (1.0 / 14.0 + e2 * (-3.0 / 44.0 + e2 / 16.0) + 3.0 / 104.0 * e3);
    (1.0 + s) / a.sqrt()
}

/// R_D(x, y, z) for x, y ≥ 0 (at most one zero), z > 0.
pub(crate) fn rd(x: f64, y: f64, z: f64) -> f64 {
    let (x0, y0) = (x, y);
    let (mut x, mut y, mut z) = (x, y, z);
    let a0 = (x + y + 3.0 * z) / 5.0;
    let mut a = a0;
    let q = (a0 - x).abs().max((a0 - y).abs()).max((a0 - z).abs()) / TOL_RD;
    let mut scale = 1.0;
    let mut sum = 0.0;
    while scale * q >= a {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        sum += scale / (sz * (z + lambda));
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        a = 0.25 * (a + lambda);
        scale *= 0.25;
    }
    let xx = (a0 - x0) * scale / a;
    let yy = (a0 - y0) * scale / a;
    let zz = -(xx + yy) / 3.0;
    let xy = xx * yy;
    let z2 = zz * zz;
    let e2 = xy - 6.0 * z2;
    let e3 = (3.0 * xy - 8.0 * z2) * zz;
    let e4 = 3.0 * (xy - z2) * z2;
    let e5 = xy * z2 * zz;
    // DLMF 19.36.2.
    let s =
        -3.0 / 14.0 * e2 + e3 / 6.0 + 9.0 / 88.0 * e2 * e2 - 3.0 / 22.0 * e4 - 9.0 / 52.0 * e2 * e3
            + 3.0 / 26.0 * e5;
    scale * (1.0 + s) / (a * a.sqrt()) + 3.0 * sum
}
