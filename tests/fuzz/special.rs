//! `special`: the modulus constructors and the total functions.

use core::f64::consts::FRAC_PI_2;

use hockle::Error;
use hockle::special::{
    Modulus, ellip_e, ellip_e_inc, ellip_f, ellip_k, jacobi, jacobi_epsilon, jacobi_zeta,
};

use crate::hostile::{Gen, Report, finite};

/// About 0.2 µs per call: a few seconds in release.
pub const CI_CALLS: u64 = 1_000_000;

/// A modulus from any of the three constructors, checked against its
/// domain [0, 1]; `None` when the argument was outside (and refused).
pub fn modulus(g: &mut Gen, r: &mut Report) -> Option<Modulus> {
    let x = g.arg(0.0, 1.0);
    let which = g.u64() % 3;
    let made = r.call(
        || format!("Modulus::from_* #{which}({x:e})"),
        || match which {
            0 => Modulus::from_k(x),
            1 => Modulus::from_m(x),
            _ => Modulus::from_complement(x),
        },
    )?;
    let inside = (0.0..=1.0).contains(&x);
    match made {
        Ok(md) => {
            r.check(inside, || format!("Modulus #{which} accepted {x:e}"));
            let parts = [md.k(), md.m(), md.complement(), md.k_prime()];
            r.check(parts.iter().all(|v| (0.0..=1.0).contains(v)), || {
                format!("Modulus #{which}({x:e}) has parts {parts:?} outside [0, 1]")
            });
            let c = md.complementary();
            r.check(c.m() == md.complement() && c.complement() == md.m(), || {
                format!("Modulus #{which}({x:e}).complementary() swaps wrongly")
            });
            Some(md)
        }
        Err(e) => {
            r.check(!inside && matches!(e, Error::InvalidModulus { .. }), || {
                format!("Modulus #{which}({x:e}) refused: {e}")
            });
            None
        }
    }
}

/// Documented: only the modulus can fail; NaN or infinite φ, u give NaN;
/// K(1) = ∞ and F(φ | 1) = ±∞ for |φ| ≥ π/2; every other value is finite,
/// except F(φ) ≈ 2Kφ/π itself beyond the largest double (|φ| > 1e300).
pub fn fuzz(g: &mut Gen, r: &mut Report, calls: u64) {
    while r.calls < calls {
        let Some(md) = modulus(g, r) else { continue };
        let unit = md.complement() == 0.0;
        let x = match g.u64() % 3 {
            0 => g.arg(-1e6, 1e6),
            1 => g.arg(-FRAC_PI_2, FRAC_PI_2),
            _ => g.any_f64(),
        };
        let m1 = md.complement();
        let what = |f: &str| format!("{f}(x = {x:e}, m1 = {m1:e})");
        if let Some(k) = r.call(|| what("K"), || ellip_k(md)) {
            r.check(
                if unit {
                    k == f64::INFINITY
                } else {
                    k.is_finite()
                },
                || format!("{} = {k}", what("K")),
            );
        }
        if let Some(e) = r.call(|| what("E"), || ellip_e(md)) {
            r.check(e.is_finite(), || format!("{} = {e}", what("E")));
        }
        let on_input = |v: f64, total_inf: bool| {
            if x.is_finite() {
                v.is_finite() || total_inf
            } else {
                v.is_nan()
            }
        };
        if let Some(f) = r.call(|| what("F"), || ellip_f(x, md)) {
            let may_be_inf = (unit && x.abs() >= FRAC_PI_2) || x.abs() > 1e300;
            r.check(on_input(f, may_be_inf && f.is_infinite()), || {
                format!("{} = {f}", what("F"))
            });
        }
        if let Some(e) = r.call(|| what("E(φ)"), || ellip_e_inc(x, md)) {
            r.check(on_input(e, false), || format!("{} = {e}", what("E(φ)")));
        }
        if let Some(j) = r.call(|| what("jacobi"), || jacobi(x, md)) {
            let v = [j.sn, j.cn, j.dn, j.am];
            let ok = if x.is_finite() {
                finite(&v)
            } else {
                v.iter().all(|y| y.is_nan())
            };
            r.check(ok, || format!("{} = {j:?}", what("jacobi")));
        }
        if let Some(e) = r.call(|| what("ε"), || jacobi_epsilon(x, md)) {
            r.check(on_input(e, false), || format!("{} = {e}", what("ε")));
        }
        if let Some(z) = r.call(|| what("Z"), || jacobi_zeta(x, md)) {
            r.check(on_input(z, false), || format!("{} = {z}", what("Z")));
        }
    }
}
