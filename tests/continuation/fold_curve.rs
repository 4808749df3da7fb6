//! Two-parameter continuation of folds against closed forms: the Bratu
//! fold in the domain length, and the folds of a cubic with a known cusp.

use hockle::bvp::classic::BratuLength;
use hockle::bvp::{Collocation, Problem, Solution};
use hockle::continuation::{Continuation, FoldContinuation, FoldPointKind, Termination};

use super::BRATU_FOLD;

/// The first fold of a run in p[`fold`] from `start` (solved by `solver`).
fn first_fold<P: Problem>(
    p: &P,
    fold: usize,
    solver: &Collocation,
    start: &Solution,
    step: f64,
) -> Solution {
    let run = Continuation::new(fold)
        .solver(solver.clone())
        .step(step)
        .max_steps(100)
        .run(p, start, ())
        .unwrap();
    run.folds().next().expect("a fold").solution().clone()
}

#[test]
fn bratu_fold_follows_lambda_star_over_l_squared() {
    let p = BratuLength;
    let solver = Collocation::new().intervals(20);
    let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0, 1.0]).unwrap();
    let fold = first_fold(&p, 0, &solver, &start, 0.1);
    for (step, stop) in [(0.1, 3.0), (-0.1, 0.5)] {
        let curve = FoldContinuation::new(
            0,
            Continuation::new(1)
                .solver(solver.clone())
                .step(step)
                .stop_at(stop),
        )
        .run(&p, &fold, ())
        .unwrap();
        assert_eq!(curve.termination(), &Termination::ParameterValue(stop));
        eprintln!(
            "bratu fold in L to {stop}: {} points, {} steps, {} Newton iterations",
            curve.points().len(),
            curve.accepted(),
            curve.newton_iterations()
        );
        assert!(curve.points().len() > 5);
        // λ is monotone in L: no turns, no cusps.
        assert!(curve.points().iter().all(|q| matches!(
            q.kind(),
            FoldPointKind::Start | FoldPointKind::Regular | FoldPointKind::ParameterValue
        )));
        let mut worst_lambda: f64 = 0.0;
        let mut worst_slope: f64 = 0.0;
        for q in curve.points() {
            let l = q.parameter();
            // In s = x/L the problem is Bratu with λL²: the same collocation
            // error at every L (m = 4, N = 20: O(h^8) ~ 1e-11, as in
            // bratu_fold_is_located) and the fold condition's directional
            // differences (~1e-10 relative): 1e-9.
            worst_lambda = worst_lambda.max((q.fold_parameter() * l * l / BRATU_FOLD - 1.0).abs());
            // dy/dx(0) = (dy/ds(0))/L = 4/L: linear in the position along the
            // branch, so the same budget plus the reference's 4 exactly; 1e-8.
            let slope = q.solution().at_mesh(0)[1] / l;
            worst_slope = worst_slope.max((slope * l / 4.0 - 1.0).abs());
        }
        eprintln!("worst relative errors: λ L² {worst_lambda:.2e}, y'(0) L {worst_slope:.2e}");
        assert!(worst_lambda < 1e-9, "{worst_lambda:e}");
        assert!(worst_slope < 1e-8, "{worst_slope:e}");
        let end = curve.last().unwrap();
        assert_eq!(end.parameter(), stop);
        // The null vector satisfies the linearised boundary conditions
        // v(0) = 0 (to Newton's tolerance) and is not zero.
        assert!(end.null_vector_at_mesh(0)[0].abs() < 1e-9);
        assert!(end.null_vector_at_mesh(0)[1].abs() > 0.1);
    }
}

/// A BVP whose solutions are the constants y ≡ x with x³ − a x + b = 0:
/// y′ = 0, y(0)³ − a y(0) + b = 0, with a = p₀ + c p₁, b = p₁ − c p₀
/// (c = `mix`); `analytic` gives the boundary Jacobian (else the solver and
/// the fold's linearisation take differences). Its folds are 3x² = a, i.e. (a, b) = (3x², 2x³), the curve
/// 4a³ = 27b², with the cusp at a = b = 0 (x = 0). `jacobian_error` is
/// added to the analytic ∂g/∂x (0 for the true Jacobian; `merged_cusp`
/// skews it).
pub(crate) struct Cubic {
    pub(crate) mix: f64,
    pub(crate) analytic: bool,
    pub(crate) jacobian_error: f64,
}

impl Cubic {
    fn ab(&self, p: &[f64]) -> (f64, f64) {
        (p[0] + self.mix * p[1], p[1] - self.mix * p[0])
    }
}

impl Problem for Cubic {
    fn dim(&self) -> usize {
        1
    }
    fn parameter_count(&self) -> usize {
        2
    }
    fn boundary_count(&self) -> usize {
        1
    }
    fn rhs(&self, _s: f64, _y: &[f64], _p: &[f64], f: &mut [f64]) {
        f[0] = 0.0;
    }
    fn boundary(&self, y0: &[f64], _y1: &[f64], p: &[f64], g: &mut [f64]) {
        let (a, b) = self.ab(p);
        g[0] = y0[0].powi(3) - a * y0[0] + b;
    }
    fn boundary_jacobian(
        &self,
        y0: &[f64],
        _y1: &[f64],
        p: &[f64],
        mut dg0: hockle::nalgebra::DMatrixViewMut<'_, f64>,
        _dg1: hockle::nalgebra::DMatrixViewMut<'_, f64>,
        mut dgp: hockle::nalgebra::DMatrixViewMut<'_, f64>,
    ) -> bool {
        if !self.analytic {
            return false;
        }
        let (a, _) = self.ab(p);
        let x = y0[0];
        dg0[(0, 0)] = 3.0 * x * x - a + self.jacobian_error;
        // ∂a/∂p = (1, c), ∂b/∂p = (−c, 1).
        dgp[(0, 0)] = -x - self.mix;
        dgp[(0, 1)] = -self.mix * x + 1.0;
        true
    }
}

/// The fold in λ of `p` reached by a run with decreasing λ from the
/// solution near `guess` at `parameters`, with the solver (N = 4).
fn cubic_fold(p: &Cubic, guess: f64, parameters: &[f64]) -> (Collocation, Solution) {
    let solver = Collocation::new().intervals(4);
    let start = solver.solve(p, |_s: f64| [guess], parameters).unwrap();
    let fold = first_fold(p, 0, &solver, &start, -0.1);
    (solver, fold)
}

/// Checks every point against the closed-form fold curve and returns the
/// kinds of the special points with their x.
fn check_cubic(
    problem: &Cubic,
    curve: &hockle::continuation::FoldCurve,
) -> Vec<(FoldPointKind, f64)> {
    let mut special = Vec::new();
    for q in curve.points() {
        let x = q.solution().at_mesh(0)[0];
        let (a, b) = problem.ab(q.parameters());
        // Constants are exact in collocation. Without the analytic Jacobian
        // the fold condition's directional difference has error δ² (g‴ = 6,
        // δ ≈ 6e-6 (1 + max(|x|, |a|, |b|))) ≈ 4e-11 (1 + 3)² < 1e-9 on the
        // un-rotated run; with it, only Newton's 1e-10 relative to
        // 1 + ‖x‖∞ ≤ 17 on the rotated one: 1e-8 for both.
        let tol = 1e-8;
        assert!((a - 3.0 * x * x).abs() < tol, "a = {a}, x = {x}");
        assert!((b - 2.0 * x * x * x).abs() < tol, "b = {b}, x = {x}");
        // The curve 4a³ = 27b² itself, relative to its terms.
        let scale = 1.0 + 4.0 * a.abs().powi(3);
        assert!((4.0 * a.powi(3) - 27.0 * b * b).abs() < 10.0 * tol * scale);
        if !matches!(q.kind(), FoldPointKind::Start | FoldPointKind::Regular) {
            special.push((q.kind(), x));
        }
    }
    special
}

#[test]
fn cusp_of_the_cubic_at_the_origin() {
    // a = λ, b = μ. At b = 2 the folds in a are at x = 1, a = 3; continue in
    // b from 2 down to −2 (x from 1 to −1) through the cusp a = b = 0, where
    // a = 3x² turns and b = 2x³ does not (a non-generic cusp for b).
    let p = Cubic {
        mix: 0.0,
        analytic: false,
        jacobian_error: 0.0,
    };
    let (solver, fold) = cubic_fold(&p, 1.7, &[4.0, 2.0]);
    assert!((fold.parameters()[0] - 3.0).abs() < 1e-8);
    let curve = FoldContinuation::new(
        0,
        Continuation::new(1).solver(solver).step(-0.1).stop_at(-2.0),
    )
    .run(&p, &fold, ())
    .unwrap();
    assert_eq!(curve.termination(), &Termination::ParameterValue(-2.0));
    let special = check_cubic(&p, &curve);
    assert_eq!(special.len(), 2, "{special:?}");
    assert_eq!(special[0].0, FoldPointKind::Cusp);
    let cusp = curve.cusps().next().unwrap();
    // Located to 1e-10 in arclength: x = O(1e-10), a = 3x² + 4e-11, b = 2x³.
    let (a, b) = p.ab(cusp.parameters());
    eprintln!(
        "cubic cusp: a = {a:.2e}, b = {b:.2e}, x = {:.2e}",
        special[0].1
    );
    assert!(a.abs() < 1e-9 && b.abs() < 1e-9, "a = {a}, b = {b}");
    assert!(special[0].1.abs() < 1e-8);
    let (da, db) = cusp.velocity().unwrap();
    assert!(da.abs() < 1e-8 && db.abs() < 1e-8);
    // And the curve ends on the other branch of the cusp: x = −1, a = 3.
    let end = curve.last().unwrap();
    assert!((end.solution().at_mesh(0)[0] + 1.0).abs() < 1e-8);
    assert!((end.fold_parameter() - 3.0).abs() < 1e-8);
}

#[test]
fn turns_and_a_generic_cusp_of_the_rotated_cubic() {
    // a = λ + μ, b = μ − λ: along the fold curve λ = (3x² − 2x³)/2,
    // μ = (3x² + 2x³)/2. From x = 2 (λ = −2, μ = 14) towards x < 0: λ turns
    // at x = 1 (μ = 2.5), both turn at the cusp x = 0, μ turns at x = −1
    // (λ = 2.5); the run stops at μ = −1.
    let p = Cubic {
        mix: 1.0,
        analytic: true,
        jacobian_error: 0.0,
    };
    let (solver, fold) = cubic_fold(&p, 2.5, &[-1.0, 14.0]);
    assert!((fold.parameters()[0] + 2.0).abs() < 1e-8);
    let mut cusps_seen = 0;
    let curve = FoldContinuation::new(
        0,
        Continuation::new(1).solver(solver).step(-0.1).stop_at(-1.0),
    )
    .run(&p, &fold, |q: &hockle::continuation::FoldPoint| {
        if q.kind() == FoldPointKind::Cusp {
            cusps_seen += 1;
        }
        std::ops::ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(curve.termination(), &Termination::ParameterValue(-1.0));
    let special = check_cubic(&p, &curve);
    let kinds: Vec<_> = special.iter().map(|s| s.0).collect();
    assert_eq!(
        kinds,
        [
            FoldPointKind::Turn(0),
            FoldPointKind::Cusp,
            FoldPointKind::Turn(1),
            FoldPointKind::ParameterValue
        ],
        "{special:?}"
    );
    assert_eq!(cusps_seen, 1);
    // Turns are located to 1e-10 in arclength where the rate is linear in
    // x: x to ~1e-10 (plus the fold condition's 4e-11 relative); 1e-8.
    for ((_, x), exact) in special.iter().zip([1.0, 0.0, -1.0]) {
        assert!((x - exact).abs() < 1e-8, "x = {x}, expected {exact}");
    }
}

#[test]
fn bad_fold_parameters_are_refused_before_work() {
    let p = BratuLength;
    let start = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0, 1.0])
        .unwrap();
    for fold in [1, 2] {
        let e = FoldContinuation::new(fold, Continuation::new(1))
            .run(&p, &start, ())
            .unwrap_err();
        assert!(matches!(e, hockle::Error::InvalidCount { .. }), "{e}");
    }
    let free = Continuation::new(1).solver(Collocation::new().free_parameters(&[0]));
    let e = FoldContinuation::new(0, free)
        .run(&p, &start, ())
        .unwrap_err();
    assert!(matches!(e, hockle::Error::InvalidCount { .. }), "{e}");
    let e = FoldContinuation::new(0, Continuation::new(1).step(f64::NAN))
        .run(&p, &start, ())
        .unwrap_err();
    assert!(matches!(e, hockle::Error::InvalidArgument { .. }), "{e}");
    // Far from a fold (λ = 0, y = 0) the start is refused with a typed
    // error, or the extended Newton (λ free) finds the fold itself.
    match FoldContinuation::new(0, Continuation::new(1).max_steps(1)).run(&p, &start, ()) {
        Err(e) => assert!(
            matches!(
                e,
                hockle::Error::NewtonNotConverged { .. }
                    | hockle::Error::NewtonDiverged { .. }
                    | hockle::Error::SingularJacobian { .. }
            ),
            "{e}"
        ),
        Ok(c) => {
            let q = &c.points()[0];
            let l = q.parameter();
            // As in bratu_fold_follows_lambda_star_over_l_squared (N = 10).
            assert!((q.fold_parameter() * l * l / BRATU_FOLD - 1.0).abs() < 1e-7);
        }
    }
}

/// Stops at the first cusp and records the termination it is given.
struct StopAtCusp<'a> {
    points: &'a mut usize,
    finished: &'a mut Option<Termination>,
}

impl hockle::continuation::FoldObserver for StopAtCusp<'_> {
    fn point(&mut self, _point: &hockle::continuation::FoldPoint) -> std::ops::ControlFlow<()> {
        *self.points += 1;
        std::ops::ControlFlow::Continue(())
    }
    fn cusp(&mut self, _cusp: &hockle::continuation::FoldPoint) -> std::ops::ControlFlow<()> {
        std::ops::ControlFlow::Break(())
    }
    fn finish(&mut self, termination: &Termination) {
        *self.finished = Some(termination.clone());
    }
}

#[test]
fn an_observer_stops_at_the_cusp_and_keeps_the_points() {
    let p = Cubic {
        mix: 0.0,
        analytic: true,
        jacobian_error: 0.0,
    };
    let (solver, fold) = cubic_fold(&p, 1.7, &[4.0, 2.0]);
    let (mut points, mut finished) = (0, None);
    let obs = StopAtCusp {
        points: &mut points,
        finished: &mut finished,
    };
    let curve = FoldContinuation::new(
        0,
        Continuation::new(1).solver(solver).step(-0.1).stop_at(-2.0),
    )
    .run(&p, &fold, obs)
    .unwrap();
    assert_eq!(curve.termination(), &Termination::Stopped);
    assert_eq!(finished, Some(Termination::Stopped));
    assert_eq!(curve.last().unwrap().kind(), FoldPointKind::Cusp);
    assert_eq!(points, curve.points().len());
    assert!(curve.points().len() > 3);
}

/// [`BratuLength`] with a free parameter c (p₂) fixed by the integral
/// condition ∫₀¹ (y − c) ds = 0: the fold in λ is unchanged, but its null
/// vector has a δc and the extended problem linearises an integral
/// condition (by differences: no integrand Jacobian).
struct BratuMean;

impl Problem for BratuMean {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        3
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn integral_count(&self) -> usize {
        1
    }
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        BratuLength.rhs(s, y, &p[..2], f);
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        BratuLength.boundary(y0, y1, &p[..2], g);
    }
    fn integrand(&self, _s: f64, y: &[f64], _r: &[f64], p: &[f64], h: &mut [f64]) {
        h[0] = y[0] - p[2];
    }
}

#[test]
fn a_free_parameter_and_an_integral_condition_ride_along() {
    let p = BratuMean;
    let solver = Collocation::new().intervals(20).free_parameters(&[2]);
    let start = solver
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0, 1.0, 0.0])
        .unwrap();
    let fold = first_fold(&p, 0, &solver, &start, 0.1);
    let curve = FoldContinuation::new(
        0,
        Continuation::new(1).solver(solver).step(0.1).stop_at(2.0),
    )
    .run(&p, &fold, ())
    .unwrap();
    assert_eq!(curve.termination(), &Termination::ParameterValue(2.0));
    for q in curve.points() {
        let l = q.parameter();
        // As in bratu_fold_follows_lambda_star_over_l_squared, with the
        // integral's directional difference (~1e-10 relative) added: 1e-9.
        let e = (q.fold_parameter() * l * l / BRATU_FOLD - 1.0).abs();
        assert!(e < 1e-9, "L = {l}: {e:e}");
        // c is the mean of y, which at the fold depends on λL² alone: the
        // same value along the whole curve (to the same budget).
        let c0 = curve.points()[0].parameters()[2];
        assert!((q.parameters()[2] - c0).abs() < 1e-9 * c0.abs().max(1.0));
    }
}

/// The cost at rod size (not a check: prints the time per step). The
/// paper's spring (n = 4, θ0 = 89.8°, A/B = 10, ν = 0.05) is pulled to its
/// first force fold, which is then continued in θ0 down to 85° (at most 100 steps):
/// `cargo test --release --test continuation rod_fold_curve_cost -- --ignored --nocapture`.
#[test]
#[ignore = "a timing, run by hand"]
fn rod_fold_curve_cost() {
    use hockle::rod::Rod;
    let rod = spring(89.8_f64.to_radians());
    let clock = std::time::Instant::now();
    let (solver, fold) = first_rod_fold(rod);
    let to_fold = clock.elapsed();
    let scale = rod.scale().value();
    // The pull's weights (src/rod/pull.rs): F scaled by the force scale,
    // M by 1e-3 (parameter weight 1: with 1/scale² as the pull has, the
    // steps took 6× longer for 1.6× the progress in θ0).
    let mut weights = [1.0; 13];
    weights[7..10].fill(1.0 / (scale * scale));
    weights[10..13].fill(1e-3);
    let clock = std::time::Instant::now();
    let curve = FoldContinuation::new(
        Rod::FORCE,
        Continuation::new(Rod::THETA0)
            .solver(solver)
            .weights(&weights)
            .step(-0.01)
            .step_bounds(1e-8, 0.5)
            .locate_tolerance(1e-9)
            .stop_at(85.0_f64.to_radians())
            .max_steps(100),
    )
    .run(&rod, &fold, ())
    .unwrap();
    let t = clock.elapsed();
    let (first, last) = (&curve.points()[0], curve.last().unwrap());
    eprintln!(
        "rod: N = {}, pull to the first fold {:.3} s; fold curve {} steps ({} rejected, {} corrector iterations) in {:.3} s = {:.1} ms per step; θ0 {:.4}° → {:.4}°, F/scale {:.5} → {:.5}; {}",
        fold.mesh().intervals(),
        to_fold.as_secs_f64(),
        curve.accepted(),
        curve.rejected(),
        curve.newton_iterations(),
        t.as_secs_f64(),
        1e3 * t.as_secs_f64() / curve.accepted().max(1) as f64,
        first.parameter().to_degrees(),
        last.parameter().to_degrees(),
        first.fold_parameter() / scale,
        last.fold_parameter() / scale,
        curve.termination()
    );
}

/// The paper's spring (n = 4, A/B = 10, ν = 0.05) at `theta0_deg`.
fn spring(theta0: f64) -> hockle::rod::Rod {
    hockle::rod::Rod::new(4, theta0, hockle::Stiffness::nikolai(10.0, 0.05).unwrap()).unwrap()
}

/// The first located force fold of a pull of `rod` to F/((2πn)²B) = 3.
fn first_rod_fold(rod: hockle::rod::Rod) -> (Collocation, Solution) {
    let pull = hockle::rod::Pull::new(rod, hockle::Target::Force(3.0));
    let solver = pull.check().unwrap();
    let fold = pull
        .start()
        .unwrap()
        .steps()
        .unwrap()
        .find(|p| p.kind() == hockle::continuation::PointKind::Fold)
        .expect("a fold")
        .solution()
        .clone();
    (solver, fold)
}

#[test]
fn rod_fold_curve_agrees_with_one_parameter_pulls() {
    // A second model: the fold force of a pull at the fold curve's last θ0
    // (sign change of dF/ds located by arclength on the one-parameter
    // branch) against the fold curve's (the extended system).
    use hockle::rod::Rod;
    let (solver, fold) = first_rod_fold(spring(89.8_f64.to_radians()));
    let curve = FoldContinuation::new(
        Rod::FORCE,
        Continuation::new(Rod::THETA0)
            .solver(solver)
            .step(-0.05)
            .locate_tolerance(1e-9)
            .max_steps(8),
    )
    .run(&spring(89.8_f64.to_radians()), &fold, ())
    .unwrap();
    let last = curve.last().unwrap();
    let theta0 = last.parameter();
    assert!(
        theta0 < 89.79_f64.to_radians(),
        "θ0 = {}°",
        theta0.to_degrees()
    );
    let (_, check) = first_rod_fold(spring(theta0));
    assert_eq!(check.mesh(), last.solution().mesh());
    let f = check.parameters()[Rod::FORCE];
    let e = (last.fold_parameter() / f - 1.0).abs();
    eprintln!(
        "rod fold at θ0 = {:.5}°: fold curve F = {:.12e}, pull F = {f:.12e}, relative difference {e:.2e}",
        theta0.to_degrees(),
        last.fold_parameter()
    );
    // Same mesh, same collocation: both are the zero of the same discrete
    // fold condition, located to 1e-9 in arclength (quadratic in F at a
    // fold: ~1e-18) and corrected to Newton's 1e-10 relative to 1 + ‖x‖∞
    // (F ≈ 400, so ~4e-8 absolute, 1e-10 relative), the extended
    // linearisation's differences ~1e-10: 1e-8 relative.
    assert!(e < 1e-8, "{e:e}");
}
