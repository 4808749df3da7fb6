//! The merged-cusp rule of [`FoldContinuation`]: a cusp whose two zeros
//! (of dλ/ds and of dμ/ds) an error of the fold condition has pulled a
//! short arclength apart is one cusp when both fall in one step and the
//! curve's direction in the (λ, μ) plane reverses in it.
//!
//! On the rod (the n = 8 cusp curves) the fold condition of the cusp system
//! is built from a Jacobian of differences, not the exact derivative of
//! the residual, and near a cusp its two zeros are 1e-4 to 1e-3 apart in
//! arclength. The same mechanism, of a known size, is put into a scalar
//! problem here: the rotated cubic g = x³ − a x + b (a = λ + μ, b = μ − λ,
//! as in `fold_curve.rs`) whose boundary Jacobian is off by ε in ∂g/∂x.
//! Newton still converges to roots of the cubic (the residual is exact; the
//! Jacobian's error only slows it to a linear rate), but the fold condition
//! (∂g/∂x + ε) v = 0 moves the curve of folds to the closed form
//!
//! ```text
//!   a = 3x² + ε,  b = 2x³ + εx,   λ = (a − b)/2,  μ = (a + b)/2,
//!   dλ/dx = (6x − 6x² − ε)/2,     dμ/dx = (6x + 6x² + ε)/2.
//! ```
//!
//! For ε = 0 this is the generic cusp at x = 0; for ε > 0 a hairpin whose
//! λ-turn x_λ = (1 − √(1 − 2ε/3))/2 ≈ ε/6 and μ-turn
//! x_μ = (−1 + √(1 − 2ε/3))/2 ≈ −ε/6 are ε/3 apart. Stepping across both
//! in one step, the rule must report one cusp at x_μ (where μ turns back:
//! the end of the region of the λ-folds' hysteresis); stepping in steps
//! shorter than ε/3 it must report the two turns it resolved.

use hockle::bvp::Collocation;

use crate::fold_curve::Cubic;
use hockle::continuation::{Continuation, FoldContinuation, FoldCurve, FoldPointKind, Termination};

/// (λ, μ) on the curve of folds at x (module docs).
fn on_curve(error: f64, x: f64) -> (f64, f64) {
    let (a, b) = (3.0 * x * x + error, 2.0 * x.powi(3) + error * x);
    ((a - b) / 2.0, (a + b) / 2.0)
}

/// The fold curve from the fold at x = 0.05 towards smaller x, first step
/// and longest step `step`, to μ = `stop`. The parameters' weight in the
/// norm is 0.1, so that x carries the tangent (as the rod's state does
/// near its cusps) and the arclength is x's to within 1 %: the first step
/// ends near x = 0.05 − `step`.
fn skewed_curve(error: f64, step: f64, stop: f64) -> FoldCurve {
    // the rotated cubic (a = λ + μ, b = μ − λ) with ∂g/∂x off by `error`
    let p = Cubic {
        mix: 1.0,
        analytic: true,
        jacobian_error: error,
    };
    let solver = Collocation::new().intervals(4);
    let (lambda, mu) = on_curve(error, 0.05);
    // A root of the cubic near the fold (λ moved off it: at the fold the
    // skewed Jacobian is singular); the extended Newton, λ free, finds it.
    let start = solver
        .solve(&p, |_s: f64| [0.05], &[lambda + 1e-3, mu])
        .expect("a root of the cubic near x = 0.05");
    FoldContinuation::new(
        0,
        Continuation::new(1)
            .solver(solver)
            .parameter_weight(0.1)
            .step(-step)
            .step_bounds(1e-9, step)
            .max_steps(2000)
            .stop_at(stop),
    )
    .run(&p, &start, ())
    .expect("the extended start converges")
}

/// The zeros of dλ/dx (the smaller one) and of dμ/dx (the larger one) near
/// x = 0, and the other two, near x = 1 and x = −1 (module docs).
fn zeros(error: f64) -> [f64; 4] {
    let r = (1.0 - 2.0 * error / 3.0).sqrt();
    [
        (1.0 + r) / 2.0,
        (1.0 - r) / 2.0,
        (-1.0 + r) / 2.0,
        (-1.0 - r) / 2.0,
    ]
}

/// The special points of a curve as (kind, x), each point checked against
/// the closed form.
fn special(error: f64, curve: &FoldCurve) -> Vec<(FoldPointKind, f64)> {
    let mut out = Vec::new();
    for q in curve.points() {
        let x = q.solution().at_mesh(0)[0];
        let (l, m) = (q.fold_parameter(), q.parameter());
        let (a, b) = (l + m, m - l);
        // Constants are exact in collocation; Newton stops at 1e-10
        // relative to 1 + ‖x‖∞ ≤ 17 (its rate is linear here, so its last
        // correction bounds the error by a factor of a few): 1e-8.
        assert!((a - 3.0 * x * x - error).abs() < 1e-8, "a = {a}, x = {x}");
        assert!(
            (b - 2.0 * x.powi(3) - error * x).abs() < 1e-8,
            "b = {b}, x = {x}"
        );
        if !matches!(q.kind(), FoldPointKind::Start | FoldPointKind::Regular) {
            out.push((q.kind(), x));
        }
    }
    out
}

#[test]
fn two_zeros_in_one_reversing_step_are_one_cusp_at_the_mu_turn() {
    let error = 0.05;
    let curve = skewed_curve(error, 0.1, -1.0);
    assert_eq!(curve.termination(), &Termination::ParameterValue(-1.0));
    // The first step, from x = 0.05 to about −0.05, holds both zeros.
    assert!(curve.points()[1].arclength() < 0.1);
    let found = special(error, &curve);
    let kinds: Vec<_> = found.iter().map(|s| s.0).collect();
    assert_eq!(
        kinds,
        [
            FoldPointKind::Cusp,
            FoldPointKind::Turn(1),
            FoldPointKind::ParameterValue
        ],
        "{found:?}"
    );
    // Located to 1e-10 in arclength where the rate is linear in x: 1e-8.
    // The cusp is at the μ-turn, the later turn (in a step that does not
    // reverse) is a turn.
    let z = zeros(error);
    for ((_, x), exact) in found.iter().zip([z[2], z[3]]) {
        assert!((x - exact).abs() < 1e-8, "x = {x}, expected {exact}");
    }
}

#[test]
fn a_hairpin_resolved_by_short_steps_is_two_turns() {
    let error = 0.05;
    let stop = on_curve(error, -0.1).1;
    let curve = skewed_curve(error, 0.004, stop);
    assert_eq!(curve.termination(), &Termination::ParameterValue(stop));
    let found = special(error, &curve);
    let kinds: Vec<_> = found.iter().map(|s| s.0).collect();
    assert_eq!(
        kinds,
        [
            FoldPointKind::Turn(0),
            FoldPointKind::Turn(1),
            FoldPointKind::ParameterValue
        ],
        "{found:?}"
    );
    let z = zeros(error);
    for ((_, x), exact) in found.iter().zip([z[1], z[2]]) {
        assert!((x - exact).abs() < 1e-8, "x = {x}, expected {exact}");
    }
}
