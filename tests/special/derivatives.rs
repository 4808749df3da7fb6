//! Derivatives in m (`*_dm`) against the mpmath tables
//! (`python3 tests/data/gen_special_dm.py`) and as property tests of the
//! identities they must satisfy.
//!
//! Errors in ulps of the true derivative; "norm." divides by 1 + the
//! relative condition number of the derivative in m and in φ or u (stored
//! in the tables), as for the functions themselves.

use hockle::special::{
    FixedModulus, Modulus, ellip_e, ellip_e_dm, ellip_e_inc, ellip_e_inc_dm, ellip_f, ellip_f_dm,
    ellip_k, ellip_k_dm, jacobi, jacobi_dm, jacobi_epsilon,
};
use proptest::prelude::*;

use super::table::{line, read, report, stats, ulps_dd, worst};

/// Bar for dK/dm, dE/dm: ≤ 2 ulp (one R_D or a benign closed form in K, E).
const BAR_COMPLETE_DM: f64 = 2.0;
/// Bar for the other derivatives, normalised: ≤ 4 ulp (a value of the
/// function, one R_D and two or three products).
const BAR_DM: f64 = 4.0;

#[test]
fn accuracy_dm_complete() {
    let rows = read("special_dm_complete.tsv");
    let (mut ek, mut ee, mut ctx) = (vec![], vec![], vec![]);
    for r in &rows {
        ek.push(ulps_dd(ellip_k_dm(r.modulus), r.nums[0], r.nums[1]));
        ee.push(ulps_dd(ellip_e_dm(r.modulus), r.nums[2], r.nums[3]));
        ctx.push(format!("{} = {:e}", r.kind, r.x));
    }
    let (sk, se) = (stats(&ek), stats(&ee));
    report(
        "m-derivatives of K, E (ulps)",
        "derivative",
        &[line("dK/dm", &sk, None), line("dE/dm", &se, None)],
    );
    worst("dK/dm", &ek, &ctx);
    worst("dE/dm", &ee, &ctx);
    assert!(sk.max <= BAR_COMPLETE_DM, "dK/dm: max {} ulp", sk.max);
    assert!(se.max <= BAR_COMPLETE_DM, "dE/dm: max {} ulp", se.max);
}

#[test]
fn accuracy_dm_incomplete() {
    let rows = read("special_dm_incomplete.tsv");
    let (mut raw, mut norm, mut ctx) = (vec![vec![]; 2], vec![vec![]; 2], vec![]);
    for r in &rows {
        let phi = r.nums[0];
        let got = [ellip_f_dm(phi, r.modulus), ellip_e_inc_dm(phi, r.modulus)];
        for i in 0..2 {
            let e = ulps_dd(got[i], r.nums[1 + 2 * i], r.nums[2 + 2 * i]);
            raw[i].push(e);
            norm[i].push(e / (1.0 + r.nums[5 + i]));
        }
        ctx.push(format!("{} = {:e}, phi = {:e}", r.kind, r.x, phi));
    }
    let names = ["∂F/∂m", "∂E(φ)/∂m"];
    let s: Vec<_> = (0..2).map(|i| (stats(&raw[i]), stats(&norm[i]))).collect();
    report(
        "m-derivatives of F, E(φ) (ulps)",
        "derivative",
        &(0..2)
            .map(|i| line(names[i], &s[i].0, Some(&s[i].1)))
            .collect::<Vec<_>>(),
    );
    for i in 0..2 {
        worst(names[i], &norm[i], &ctx);
        assert!(
            s[i].1.max <= BAR_DM,
            "{}: normalised max {}",
            names[i],
            s[i].1.max
        );
    }
}

#[test]
fn accuracy_dm_jacobi() {
    let rows = read("special_dm_jacobi.tsv");
    let (mut raw, mut norm, mut ctx) = (vec![vec![]; 4], vec![vec![]; 4], vec![]);
    for r in &rows {
        let u = r.nums[0];
        let (_, d) = jacobi_dm(u, r.modulus);
        let got = [d.sn, d.cn, d.dn, d.am];
        for i in 0..4 {
            let e = ulps_dd(got[i], r.nums[1 + 2 * i], r.nums[2 + 2 * i]);
            raw[i].push(e);
            norm[i].push(e / (1.0 + r.nums[9 + i]));
        }
        ctx.push(format!("{} = {:e}, u = {:e}", r.kind, r.x, u));
    }
    let names = ["∂sn/∂m", "∂cn/∂m", "∂dn/∂m", "∂am/∂m"];
    let s: Vec<_> = (0..4).map(|i| (stats(&raw[i]), stats(&norm[i]))).collect();
    report(
        "m-derivatives of sn, cn, dn, am at fixed u (ulps)",
        "derivative",
        &(0..4)
            .map(|i| line(names[i], &s[i].0, Some(&s[i].1)))
            .collect::<Vec<_>>(),
    );
    for i in 0..4 {
        worst(names[i], &norm[i], &ctx);
    }
    for i in 0..4 {
        assert!(
            s[i].1.max <= BAR_DM,
            "{}: normalised max {}",
            names[i],
            s[i].1.max
        );
    }
}

const EPS: f64 = f64::EPSILON;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// dK/dm = (E − m₁K)/(2 m m₁) and dE/dm = (E − K)/(2m) (DLMF 19.4.1),
    /// checked where the closed forms do not cancel badly (the code uses
    /// R_D there, so the two sides are computed differently). The closed
    /// form's own error: K, E ≤ 1 ulp each, so the numerator is within
    /// 2ε(E + m₁K) (or 2ε(E + K)) plus roundings; the derivative ≤ 2 ulp.
    #[test]
    fn complete_dm_closed_forms(m in 0.05f64..0.95) {
        let md = Modulus::from_m(m).unwrap();
        let (k, e, mc) = (ellip_k(md), ellip_e(md), md.complement());
        let kdm = ellip_k_dm(md);
        let closed = (e - mc * k) / (2.0 * m * mc);
        let tol = 4.0 * EPS * ((e + mc * k) / (2.0 * m * mc) + kdm.abs());
        prop_assert!((kdm - closed).abs() <= tol, "dK/dm {kdm} vs {closed}");
        let edm = ellip_e_dm(md);
        let closed = (e - k) / (2.0 * m);
        let tol = 4.0 * EPS * ((e + k) / (2.0 * m) + edm.abs());
        prop_assert!((edm - closed).abs() <= tol, "dE/dm {edm} vs {closed}");
    }

    /// ∂am/∂m = [m sn cn − dn (ε(u) − m₁u)]/(2 m m₁) (from DLMF 19.4.2 with
    /// F(am u) = u), which uses ε instead of R_D. The closed form cancels
    /// by up to |ε| + m₁|u| + m|sn cn| over its value; each input carries
    /// ≤ 2 ulp normalised (|u| ≤ 20 keeps the condition numbers ≤ 20),
    /// so the bound is 50ε times those terms, over 2 m m₁, plus 8 ulp of
    /// the derivative.
    #[test]
    fn am_dm_against_epsilon(m in 0.05f64..0.95, u in -20.0f64..20.0) {
        let md = Modulus::from_m(m).unwrap();
        let mc = md.complement();
        let (j, d) = jacobi_dm(u, md);
        let eps = jacobi_epsilon(u, md);
        let closed = (m * j.sn * j.cn - j.dn * (eps - mc * u)) / (2.0 * m * mc);
        let scale = (m * (j.sn * j.cn).abs() + eps.abs() + mc * u.abs()) / (2.0 * m * mc);
        prop_assert!(
            (d.am - closed).abs() <= 50.0 * EPS * scale + 8.0 * EPS * d.am.abs(),
            "∂am/∂m {} vs {closed}", d.am
        );
    }

    /// am(K(m), m) = π/2 for every m, so ∂am/∂m at u = K equals −dn(K)·dK/dm
    /// = −k′ dK/dm. u = fl(K) is off by ≤ ½ ulp of K, which moves ∂am/∂m by
    /// at most |∂²am/∂u∂m|·ε K/2 = |∂dn/∂m| ε K/2 ≤ (K/2) ε sn²/(2dn)…; the
    /// bound 8ε(1 + K)|k′ dK/dm| covers it with the 4-ulp bars.
    #[test]
    fn am_dm_at_quarter_period(m in 0.01f64..0.99) {
        let md = Modulus::from_m(m).unwrap();
        let k = ellip_k(md);
        let (_, d) = jacobi_dm(k, md);
        let want = -md.k_prime() * ellip_k_dm(md);
        prop_assert!(
            (d.am - want).abs() <= 8.0 * EPS * (1.0 + k) * want.abs() / md.k_prime(),
            "∂am/∂m(K) {} vs −k′ dK/dm {want}", d.am
        );
    }

    /// ∂E(φ)/∂m = (E(φ) − F(φ))/(2m) and ∂F/∂m = (E(φ) − m₁F(φ))/(2 m m₁)
    /// − sin φ cos φ/(2 m₁ Δ) (DLMF 19.4.2), against the R_D forms the code
    /// uses. F, E(φ) carry ≤ 1.5 ulp normalised (condition ≤ 2 here), so
    /// each closed form is within 8ε times the sum of its terms' sizes.
    #[test]
    fn incomplete_dm_closed_forms(m in 0.1f64..0.9, phi in 0.3f64..1.5) {
        let md = Modulus::from_m(m).unwrap();
        let mc = md.complement();
        let (f, e) = (ellip_f(phi, md), ellip_e_inc(phi, md));
        let closed = (e - f) / (2.0 * m);
        let got = ellip_e_inc_dm(phi, md);
        prop_assert!(
            (got - closed).abs() <= 8.0 * EPS * ((e + f) / (2.0 * m) + got.abs()),
            "∂E(φ)/∂m {got} vs {closed}"
        );
        let (s, c) = phi.sin_cos();
        let delta = (c * c + mc * s * s).sqrt();
        let t = s * c / (2.0 * mc * delta);
        let closed = (e - mc * f) / (2.0 * m * mc) - t;
        let got = ellip_f_dm(phi, md);
        prop_assert!(
            (got - closed).abs() <= 8.0 * EPS * ((e + mc * f) / (2.0 * m * mc) + t + got.abs()),
            "∂F/∂m {got} vs {closed}"
        );
    }

    /// ∂F/∂m at φ = π/2 is dK/dm (R_D(0, 1, m₁) either way, but through the
    /// incomplete path's reduction and sin/cos kernels): fl(π/2) is within
    /// 6.2e-17 of π/2, where ∂²F/∂φ∂m = ∂(1/Δ)/∂m = sin²φ/(2Δ³) = 1/(2 m₁^{3/2}).
    #[test]
    fn f_dm_at_half_pi(m in 0.0f64..0.99) {
        let md = Modulus::from_m(m).unwrap();
        let (a, b) = (ellip_f_dm(std::f64::consts::FRAC_PI_2, md), ellip_k_dm(md));
        let mc = md.complement();
        let tol = 8.0 * EPS * b + 6.2e-17 / (2.0 * mc * mc.sqrt());
        prop_assert!((a - b).abs() <= tol, "∂F/∂m(π/2) {a} vs dK/dm {b}");
    }

    /// A central difference in m with Richardson extrapolation,
    /// D(h) = [f(m + h) − f(m − h)]/2h, (4D(h/2) − D(h))/3, h = 1e-3: the
    /// truncation is O(h⁴ f⁽⁵⁾) ≲ 1e-10 for m ∈ [0.1, 0.9], |u| ≤ 3, and the
    /// rounding of the function values (≤ 2 ulp normalised, |f| ≤ 1,
    /// cond ≤ 3) adds ≤ 4·8ε/h ≈ 7e-12.
    #[test]
    fn jacobi_dm_against_differences(m in 0.1f64..0.9, u in -3.0f64..3.0) {
        let md = Modulus::from_m(m).unwrap();
        let (_, d) = FixedModulus::new(md).jacobi_dm(u);
        let at = |dm: f64| jacobi(u, Modulus::from_m(m + dm).unwrap());
        let diff = |h: f64, f: &dyn Fn(hockle::special::Jacobi) -> f64| {
            (f(at(h)) - f(at(-h))) / (2.0 * h)
        };
        let rich = |f: &dyn Fn(hockle::special::Jacobi) -> f64| {
            (4.0 * diff(5e-4, f) - diff(1e-3, f)) / 3.0
        };
        let tol = 2e-10;
        prop_assert!((d.sn - rich(&|j| j.sn)).abs() <= tol, "∂sn/∂m {}", d.sn);
        prop_assert!((d.cn - rich(&|j| j.cn)).abs() <= tol, "∂cn/∂m {}", d.cn);
        prop_assert!((d.dn - rich(&|j| j.dn)).abs() <= tol, "∂dn/∂m {}", d.dn);
        prop_assert!((d.am - rich(&|j| j.am)).abs() <= tol, "∂am/∂m {}", d.am);
    }
}
