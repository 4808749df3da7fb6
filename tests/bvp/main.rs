//! Integration tests of the collocation BVP solver against closed forms and
//! published values.

#[path = "../common/mod.rs"]
mod common;
#[allow(dead_code)]
mod problems;

use hockle::bvp::{Collocation, LinearSolver, Mesh};
use problems::{Bratu, Linear, bratu_lambda};

#[test]
fn linear_problem_is_accurate_on_a_coarse_mesh() {
    let sol = Collocation::new()
        .intervals(10)
        .solve(&Linear, |_s: f64| [0.0, 0.0], &[])
        .unwrap();
    let mut err: f64 = 0.0;
    for (j, t) in sol.mesh().points().iter().enumerate() {
        let e = Linear::exact(*t);
        err = err.max((sol.at_mesh(j)[0] - e[0]).abs());
        err = err.max((sol.at_mesh(j)[1] - e[1]).abs());
    }
    // m = 4, h = 0.1: superconvergent error ~ C h^8 ≈ 1e-12 (C ~ 1e-5 for
    // this smooth solution); 1e-11 leaves room without hiding an order loss.
    assert!(err < 1e-11, "mesh error {err:e}");
}

#[test]
fn bratu_lambda_one_both_branches() {
    let lower = Collocation::new()
        .intervals(20)
        .solve(&Bratu { analytic: true }, |_s: f64| [0.0, 0.0], &[1.0])
        .unwrap();
    // Reference 0.54935272877527082 (tests/data/bvp_references.py). m = 4,
    // h = 1/20: O(h^8) = 3.9e-11 times a constant well below 1 for this
    // smooth solution (measured 2.1e-12), so 1e-11.
    // The discrete equations themselves are solved: Newton stops at a scaled
    // correction of 1e-10 and the chord contraction (≤ 1/8) leaves the
    // residual (stage equations in units of y′ ≈ 0.5) far below 1e-9.
    assert!(lower.residual_norm() < 1e-9, "{}", lower);
    let e = (lower.at_mesh(0)[1] - 0.549_352_728_775_270_8).abs();
    assert!(e < 1e-11, "{e:e}");
    let guess = |s: f64| [14.0 * s * (1.0 - s), 14.0 * (1.0 - 2.0 * s)];
    let upper = Collocation::new()
        .intervals(40)
        .solve(&Bratu { analytic: false }, guess, &[1.0])
        .unwrap();
    // y'(0) = 10.846899019389 on the upper branch; finite-difference
    // Jacobian only changes the Newton path, not the converged point.
    // Reference 10.846899019389452; the upper solution is steeper, h = 1/40
    // gives O(h^8)·C; 1e-9 relative to a value of 10.8.
    let e = (upper.at_mesh(0)[1] - 10.846_899_019_389_452).abs();
    eprintln!("bratu upper N=40 y'(0) error {e:.2e}");
    assert!(e < 1e-8, "{e:e}");
}

#[test]
fn bratu_exact_solution_check() {
    // Independent reference: the closed form with θ from a bisection.
    let theta = {
        let (mut a, mut b) = (0.0_f64, 4.0 * 2.0_f64.ln() * 2.0); // lower branch θ < θ*
        for _ in 0..200 {
            let c = 0.5 * (a + b);
            if bratu_lambda(c) < 1.0 { a = c } else { b = c }
        }
        0.5 * (a + b)
    };
    let sol = Collocation::new()
        .intervals(16)
        .solve(&Bratu { analytic: true }, |_s: f64| [0.0, 0.0], &[1.0])
        .unwrap();
    let exact = |s: f64| -2.0 * (((s - 0.5) * theta / 2.0).cosh() / (theta / 4.0).cosh()).ln();
    for s in [0.13, 0.5, 0.77] {
        // Between mesh points the error is O(h^(m+1)) = O(16^-5) ~ 1e-6·C.
        assert!((sol.eval(s)[0] - exact(s)).abs() < 1e-7);
    }
}

#[test]
fn sparse_reference_agrees_with_condensed() {
    let p = Bratu { analytic: true };
    let guess = |s: f64| [14.0 * s * (1.0 - s), 14.0 * (1.0 - 2.0 * s)];
    let a = Collocation::new()
        .intervals(30)
        .solve(&p, guess, &[1.0])
        .unwrap();
    let b = Collocation::new()
        .intervals(30)
        .linear_solver(LinearSolver::SparseLu)
        .solve(&p, guess, &[1.0])
        .unwrap();
    for j in 0..=30 {
        for i in 0..2 {
            // Both converge the same discrete equations to Newton tolerance
            // 1e-10 (then quadratically further): agreement far below 1e-9.
            assert!((a.at_mesh(j)[i] - b.at_mesh(j)[i]).abs() < 1e-9);
        }
    }
    let _ = Mesh::uniform(3).unwrap();
}

/// Max error at the mesh points and at θ = 0.3 inside every interval (the
/// leading O(h^(m+1)) error term vanishes at θ = ½ for even m, so the
/// midpoint would overstate the order).
fn linear_errors(m: usize, n: usize) -> (f64, f64) {
    let sol = Collocation::new()
        .points(m)
        .intervals(n)
        .newton_tolerance(1e-14)
        .solve(&Linear, |_s: f64| [0.0, 0.0], &[])
        .unwrap();
    let (mut at, mut between) = (0.0_f64, 0.0_f64);
    let pts = sol.mesh().points().to_vec();
    for (j, t) in pts.iter().enumerate() {
        for i in 0..2 {
            at = at.max((sol.at_mesh(j)[i] - Linear::exact(*t)[i]).abs());
        }
        if j < n {
            let s = t + 0.3 * (pts[j + 1] - t);
            for i in 0..2 {
                between = between.max((sol.eval(s)[i] - Linear::exact(s)[i]).abs());
            }
        }
    }
    (at, between)
}

#[test]
fn convergence_orders_match_theory() {
    // Meshes chosen so that the finer error stays above 1e-13 (rounding).
    for (m, n) in [(2usize, 8usize), (3, 4), (4, 2), (5, 1)] {
        let (a1, b1) = linear_errors(m, n);
        let (a2, b2) = linear_errors(m, 2 * n);
        let order_at = (a1 / a2).log2();
        let order_between = (b1 / b2).log2();
        eprintln!(
            "m={m} N={n}: {order_at:.3} {order_between:.3} ({a1:e} → {a2:e}) ({b1:e} → {b2:e})"
        );
        // Theory: 2m at mesh points, m + 1 between (Ascher–Mattheij–Russell
        // §5.4); ±0.3 allows the pre-asymptotic O(h) correction.
        assert!(
            (order_at - 2.0 * m as f64).abs() < 0.3,
            "m={m}: order at mesh points {order_at} ({a1:e} → {a2:e})"
        );
        assert!(
            (order_between - (m + 1) as f64).abs() < 0.3,
            "m={m}: order between {order_between} ({b1:e} → {b2:e})"
        );
    }
}

#[test]
fn troesch_mu5_uniform_and_mu10_adaptive() {
    use problems::Troesch;
    // μ = 5 on a uniform mesh of 40 intervals; reference 0.045750461406318739
    // (closed form through sc(μx|m), tests/data/bvp_references.py).
    let e_at = |n: usize| {
        let sol = Collocation::new()
            .intervals(n)
            .solve(&Troesch, |s: f64| [s, 1.0], &[5.0])
            .unwrap();
        ((sol.at_mesh(0)[1] - 0.045_750_461_406_318_74).abs(), sol)
    };
    let (e40, _) = e_at(40);
    assert!(e40 < 1e-8, "mu=5, N=40: {e40:e}");
    let (e, sol) = e_at(80);
    // y'(0) is 0.046 while y'(1) ≈ 12: the absolute error in the slope at 0
    // inherits O(h^8) of the layer; 1e-10 is 2e-9 relative.
    assert!(e < 1e-10, "mu=5: {e:e}");
    // μ = 10: the layer at s = 1 needs the adaptive mesh. Start from the μ = 5
    // solution (a standard parameter step) and ask for 1e-8.
    let sol10 = Collocation::new()
        .tolerance(1e-8)
        .solve(&Troesch, &sol, &[10.0])
        .unwrap();
    let e10 = (sol10.at_mesh(0)[1] - 3.583_377_846_308_137e-4).abs();
    // The tolerance is relative to 1 + max|y| (y'(1) ≈ 148), so it promises
    // ~1.5e-6 absolute; y'(0) = 3.58e-4 sits in the quiet region where the
    // error is far smaller: ask for 1e-3 relative to the tiny slope.
    assert!(sol10.error_estimate() <= 1e-8 * 150.0);
    assert!(e10 < 3.6e-7, "mu=10: {e10:e} ({sol10})");
}

#[test]
fn free_parameter_with_integral_condition() {
    let guess = |s: f64| [4.0 * s * (1.0 - s), 4.0 - 8.0 * s];
    let sol = Collocation::new()
        .intervals(20)
        .free_parameters(&[0])
        .solve(&problems::Eigen, guess, &[8.0, 0.5])
        .unwrap();
    let pi2 = std::f64::consts::PI.powi(2);
    // Eigenvalue error of Gauss collocation O(h^(2m)) ≈ (π/20)^8·C ≈ 4e-7·C,
    // C ~ 1e-4 here (measured 1e-11 relative); 1e-9 relative.
    assert!(
        (sol.parameters()[0] / pi2 - 1.0).abs() < 1e-9,
        "{}",
        sol.parameters()[0]
    );
    // Shape: sin(πs) to the mesh-point accuracy.
    for j in 0..=20 {
        let s = j as f64 / 20.0;
        assert!((sol.at_mesh(j)[0] - (std::f64::consts::PI * s).sin()).abs() < 1e-9);
    }
}

#[test]
fn finite_difference_jacobian_matches_analytic() {
    let guess = |s: f64| [14.0 * s * (1.0 - s), 14.0 * (1.0 - 2.0 * s)];
    let solver = Collocation::new().intervals(30).free_parameters(&[]);
    let a = solver
        .solve(&Bratu { analytic: true }, guess, &[1.0])
        .unwrap();
    let f = solver
        .solve(&Bratu { analytic: false }, guess, &[1.0])
        .unwrap();
    // Same discrete equations, converged past the 1e-10 Newton tolerance:
    // agreement to rounding of the converged iterate (~1e-13 of y' ≈ 10).
    for j in 0..=30 {
        for i in 0..2 {
            assert!((a.at_mesh(j)[i] - f.at_mesh(j)[i]).abs() < 1e-11);
        }
    }
    // Central differences (relative error ~ε^(2/3) ≈ 4e-11) keep Newton's
    // quadratic convergence: the same iteration count.
    assert_eq!(
        a.newton().iterations,
        f.newton().iterations,
        "{} vs {}",
        a.newton(),
        f.newton()
    );
}

#[test]
fn error_estimate_tracks_the_true_error() {
    for n in [4usize, 8, 16] {
        let sol = Collocation::new()
            .intervals(n)
            .solve(&Linear, |_s: f64| [0.0, 0.0], &[])
            .unwrap();
        let mut err: f64 = 0.0;
        for q in 0..=2000 {
            let s = q as f64 / 2000.0;
            let e = Linear::exact(s);
            let u = sol.eval(s);
            err = err.max((u[0] - e[0]).abs()).max((u[1] - e[1]).abs());
        }
        let ratio = sol.error_estimate() / err;
        eprintln!("estimate/true N={n}: {ratio:.3}");
        // An asymptotic estimate: within a factor 3 either way on these
        // meshes (measured ratios are printed on failure).
        assert!(
            (1.0 / 3.0..3.0).contains(&ratio),
            "N={n}: estimate {:e}, true {err:e}",
            sol.error_estimate()
        );
    }
}

#[test]
fn adaptive_mesh_meets_tolerance_with_few_intervals() {
    let tol = 1e-9;
    let sol = Collocation::new()
        .intervals(4)
        .tolerance(tol)
        .solve(&Linear, |_s: f64| [0.0, 0.0], &[])
        .unwrap();
    let mut err: f64 = 0.0;
    for q in 0..=2000 {
        let s = q as f64 / 2000.0;
        let e = Linear::exact(s);
        let u = sol.eval(s);
        err = err.max((u[0] - e[0]).abs()).max((u[1] - e[1]).abs());
    }
    let ymax = 1.0_f64.cosh() / 1.0_f64.sinh();
    // The true error meets the tolerance (the estimate is within a factor 3,
    // test above) …
    assert!(
        err <= 3.0 * tol * (1.0 + ymax),
        "error {err:e} with {}",
        sol.mesh()
    );
    // … with a mesh no finer than needed: h^5 error scaling means halving N
    // multiplies the error by 32, so N/2 could not meet it.
    let n = sol.mesh().intervals();
    eprintln!("adaptive tol {tol:e}: {}, true error {err:.2e}", sol.mesh());
    let half = Collocation::new()
        .intervals((n / 2).max(1))
        .solve(&Linear, |_s: f64| [0.0, 0.0], &[])
        .unwrap();
    assert!(
        half.error_estimate() > tol * (1.0 + ymax),
        "N = {n} is not the coarsest"
    );
}

#[test]
fn invalid_settings_are_typed_errors() {
    use hockle::Error;
    let g = |_s: f64| [0.0, 0.0];
    assert!(matches!(
        Collocation::new().points(8).solve(&Linear, g, &[]),
        Err(Error::InvalidCount {
            name: "points",
            value: 8,
            ..
        })
    ));
    assert!(matches!(
        Collocation::new().solve(&Linear, g, &[1.0]),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        Collocation::new()
            .free_parameters(&[0])
            .solve(&Bratu { analytic: true }, g, &[1.0]),
        Err(Error::IllPosed { .. })
    ));
    assert!(matches!(
        Collocation::new().tolerance(-1.0).solve(&Linear, g, &[]),
        Err(Error::InvalidArgument { .. })
    ));
    assert!(Mesh::from_points(vec![0.0, 0.5, 0.4, 1.0]).is_err());
    assert!(Mesh::from_points(vec![0.1, 1.0]).is_err());
    assert!(Mesh::uniform(0).is_err());
    assert!(matches!(
        Collocation::new().intervals(0).solve(&Linear, g, &[]),
        Err(Error::InvalidCount {
            name: "intervals",
            value: 0,
            ..
        })
    ));
}

/// A problem whose counts are whatever the test says (the equations are
/// never evaluated: every case is refused before any work).
struct Counts {
    dim: usize,
    boundary: usize,
    integral: usize,
}

impl hockle::bvp::Problem for Counts {
    fn dim(&self) -> usize {
        self.dim
    }
    fn parameter_count(&self) -> usize {
        0
    }
    fn boundary_count(&self) -> usize {
        self.boundary
    }
    fn integral_count(&self) -> usize {
        self.integral
    }
    fn rhs(&self, _s: f64, _y: &[f64], _p: &[f64], f: &mut [f64]) {
        f.fill(0.0);
    }
    fn boundary(&self, _y0: &[f64], _y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g.fill(0.0);
    }
}

/// Huge counts are typed errors before anything is allocated (before this
/// change they aborted on allocation or panicked on an integer wrap), and
/// `points(8)`/`intervals(0)` are refused before the first solve.
#[test]
fn hostile_counts_are_typed_errors() {
    use hockle::Error;
    let g = |_s: f64| [0.0, 0.0];
    for n in [0, usize::MAX, u32::MAX as usize, Mesh::MAX_INTERVALS + 1] {
        assert!(
            matches!(
                Mesh::uniform(n),
                Err(Error::InvalidCount {
                    name: "intervals",
                    ..
                })
            ),
            "Mesh::uniform({n})"
        );
        let r = Collocation::new().intervals(n).solve(&Linear, g, &[]);
        assert!(
            matches!(
                r,
                Err(Error::InvalidCount {
                    name: "intervals",
                    ..
                })
            ),
            "intervals({n}): {r:?}"
        );
        let r = Collocation::new()
            .max_intervals(n)
            .tolerance(1e-300)
            .solve(&Linear, g, &[]);
        assert!(
            matches!(
                r,
                Err(Error::InvalidCount {
                    name: "max_intervals",
                    ..
                })
            ),
            "max_intervals({n}): {r:?}"
        );
    }
    assert!(Mesh::uniform(Mesh::MAX_INTERVALS).is_ok());
    for m in [0, 1, 8, usize::MAX] {
        let r = Collocation::new().points(m).solve(&Linear, g, &[]);
        assert!(
            matches!(r, Err(Error::InvalidCount { name: "points", .. })),
            "{r:?}"
        );
    }
    let r = Collocation::new()
        .max_newton(u32::MAX)
        .solve(&Linear, g, &[]);
    assert!(
        matches!(
            r,
            Err(Error::InvalidCount {
                name: "max_newton",
                ..
            })
        ),
        "{r:?}"
    );
    // Counts whose sums wrap: the ill-posed error, not a panic.
    for (dim, boundary, integral) in [
        (2, usize::MAX, 0),
        (2, usize::MAX, 3),
        (2, 1, usize::MAX),
        (usize::MAX, 1, 1),
        (usize::MAX, usize::MAX, 1),
    ] {
        let p = Counts {
            dim,
            boundary,
            integral,
        };
        let r = Collocation::new().intervals(4).solve(&p, g, &[]);
        assert!(
            matches!(r, Err(Error::IllPosed { .. })),
            "{dim} {boundary} {integral}: {r:?}"
        );
    }
    // Well posed but too big to allocate: refused with the size it needed.
    for (dim, intervals) in [(usize::MAX / 2, 4), (1 << 40, 4), (13, Mesh::MAX_INTERVALS)] {
        let p = Counts {
            dim,
            boundary: dim,
            integral: 0,
        };
        let r = Collocation::new()
            .intervals(intervals)
            .points(7)
            .solve(&p, g, &[]);
        assert!(
            matches!(r, Err(Error::SystemTooLarge { bytes, limit, .. }) if bytes > limit),
            "dim {dim}, N = {intervals}: {r:?}"
        );
    }
}

/// Peak resident memory of one Newton step of the 13-dimensional system.
/// Run once per N, e.g.
/// `HOCKLE_N=800 cargo test --release --test bvp peak_memory -- --ignored --nocapture`.
#[test]
#[ignore = "memory probe for docs/PERFORMANCE.md"]
fn peak_memory_probe() {
    let hwm = || {
        std::fs::read_to_string("/proc/self/status")
            .ok()
            .and_then(|s| {
                s.lines().find(|l| l.starts_with("VmHWM")).map(|l| {
                    l.split_whitespace()
                        .nth(1)
                        .unwrap_or("0")
                        .parse::<u64>()
                        .unwrap_or(0)
                })
            })
            .unwrap_or(0)
    };
    let before = hwm();
    let n: usize = std::env::var("HOCKLE_N")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(50);
    let problem = problems::Coupled13::new();
    let r =
        Collocation::new()
            .intervals(n)
            .max_newton(1)
            .solve(&problem, |_s: f64| [0.0; 13], &[0.3]);
    assert!(r.is_err());
    eprintln!("N={n}: VmHWM before {before} kB, after {} kB", hwm());
}

/// y'' = a² y, y(0) = c0, y(1) = c1 with exact solution
/// (c0 sinh(a(1 − s)) + c1 sinh(a s)) / sinh(a).
struct Hyperbolic {
    a: f64,
    c0: f64,
    c1: f64,
}

impl hockle::bvp::Problem for Hyperbolic {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        0
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], _p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = self.a * self.a * y[0];
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0] - self.c0;
        g[1] = y1[0] - self.c1;
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
    /// Any such problem, any m in 2..=7 with N = 12: the mesh values match the
    /// closed form to the superconvergent bound (a h)^(2m)·max|y| (a ≤ 3,
    /// h = 1/12 gives ≤ 0.25^(2m) ≤ 4e-3·… for m = 2, far smaller above),
    /// plus Newton/rounding 1e-12.
    #[test]
    fn linear_problems_match_closed_form(a in 0.1f64..3.0, c0 in -2.0f64..2.0, c1 in -2.0f64..2.0, m in 2usize..=7) {
        let p = Hyperbolic { a, c0, c1 };
        let sol = Collocation::new().points(m).intervals(12).solve(&p, |s: f64| [c0 + (c1 - c0) * s, c1 - c0], &[]).unwrap();
        let ymax = c0.abs().max(c1.abs()).max(1e-3) * a.cosh();
        let bound = (a / 12.0).powi(2 * m as i32) * ymax + 1e-12;
        for (j, s) in sol.mesh().points().to_vec().iter().enumerate() {
            let exact = (c0 * (a * (1.0 - s)).sinh() + c1 * (a * s).sinh()) / a.sinh();
            let e = (sol.at_mesh(j)[0] - exact).abs();
            proptest::prop_assert!(e <= bound, "a={a} m={m} s={s}: error {e:e} > bound {bound:e}");
        }
    }
}

/// u″ = −u + a·noise(u), u(0) = 0, u(1) = 1: a right-hand side whose value
/// carries a deterministic pseudo-random error of size `a` (as a model
/// evaluated by an inner iteration, or rounding in a long sum), so
/// Newton's correction cannot fall below about `a`.
struct Noisy(f64);

impl hockle::bvp::Problem for Noisy {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        0
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], _p: &[f64], f: &mut [f64]) {
        let bits = y[0].to_bits().wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let noise = (bits >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
        f[0] = y[1];
        f[1] = -y[0] + self.0 * noise;
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0] - 1.0;
    }
}

/// A Newton stalled by a rounding floor within ten times its tolerance
/// keeps its iterate (and says how far it is); beyond that it is an error.
#[test]
fn newton_stalled_at_its_rounding_floor_converges() {
    let tol = 1e-11;
    let solve = |a: f64| {
        Collocation::new()
            .intervals(20)
            .newton_tolerance(tol)
            .solve(&Noisy(a), |s: f64| [s, 1.0], &[])
    };
    // a = 4e-9: the correction stalls at 4.1e-11 (measured), which damping
    // cannot reduce; before the floor was accepted this was NewtonDiverged.
    let s = solve(4e-9).expect("a stall within 10× the tolerance converges");
    let c = s.newton().correction;
    assert!(c > tol && c <= 10.0 * tol, "stalled correction {c:e}");
    // The exact solution is sin s / sin 1; the noise moves it by about a
    // (the Green's function of u″ + u on [0, 1] is below 1), the
    // collocation error on 20 intervals with m = 4 is ~1e-12: 1e-7 leaves
    // 25× room and fails on any wrong iterate.
    let err = (0..=10)
        .map(|i| {
            let t = f64::from(i) / 10.0;
            (s.eval(t)[0] - t.sin() / 1f64.sin()).abs()
        })
        .fold(0.0, f64::max);
    assert!(err < 1e-7, "error {err:e}");
    // a = 1.6e-8: the floor (1.3e-10) is more than 10× the tolerance.
    assert!(matches!(
        solve(1.6e-8),
        Err(hockle::Error::NewtonDiverged { .. })
    ));
}
