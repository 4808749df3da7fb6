//! Integration tests of pseudo-arclength continuation: folds, branch points,
//! branch switching, events and failure paths, against closed forms.

#[path = "../common/mod.rs"]
mod common;
#[path = "../bvp/problems.rs"]
#[allow(dead_code)]
mod problems;

mod fold_curve;
mod merged_cusp;
mod observer;
mod settings;
mod stops;
mod tolerance;

use std::ops::ControlFlow;

use hockle::bvp::{Collocation, Problem};
use hockle::continuation::{BranchSide, Continuation, PointKind, Termination};
use problems::Bratu;

/// λ* and y(½) at the fold, from tests/data/bvp_references.py (closed form,
/// 40 digits); y'(0) = 4 exactly there.
const BRATU_FOLD: f64 = 3.513_830_719_125_161;
const BRATU_FOLD_MID: f64 = 1.186_842_168_634_389;

#[test]
fn bratu_fold_is_located() {
    let p = Bratu { analytic: true };
    let solver = Collocation::new().intervals(20);
    let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0]).unwrap();
    let branch = Continuation::new(0)
        .solver(solver)
        .step(0.1)
        .max_steps(100)
        .stop_when(|s| s.at_mesh(0)[1] - 10.846_899_019_389_452)
        .run(&p, &start, ())
        .unwrap();
    let folds: Vec<_> = branch.folds().collect();
    assert_eq!(folds.len(), 1);
    let f = folds[0];
    let sol = f.solution();
    // m = 4, N = 20: discretisation O(h^8) ≈ 4e-11·C; location to 1e-10 in
    // arclength moves λ by O(1e-20) at a fold (quadratic there).
    assert!(
        (f.parameter() - BRATU_FOLD).abs() < 1e-9,
        "{:e}",
        f.parameter() - BRATU_FOLD
    );
    // y'(0) and y(½) vary linearly along the branch: location error 1e-10 in
    // arclength plus discretisation; 1e-8.
    assert!(
        (sol.at_mesh(0)[1] - 4.0).abs() < 1e-8,
        "{}",
        sol.at_mesh(0)[1]
    );
    assert!((sol.eval(0.5)[0] - BRATU_FOLD_MID).abs() < 1e-8);
    // The run ends where y'(0) = 10.846899019389452, which is λ = 1 on the
    // upper branch (closed form): the event location to 1e-10 in arclength
    // and the discretisation O(h^8) of the steeper solution; 1e-8.
    assert_eq!(branch.termination(), &Termination::Event(0));
    let last = branch.last().unwrap();
    assert_eq!(last.kind(), PointKind::Event(0));
    assert!(
        (last.parameter() - 1.0).abs() < 1e-8,
        "{:e}",
        last.parameter() - 1.0
    );
}

#[test]
fn branch_points_of_the_trivial_branch_and_switching() {
    use problems::Quadratic;
    let solver = Collocation::new().intervals(40);
    let start = solver
        .solve(&Quadratic, |_s: f64| [0.0, 0.0], &[0.5])
        .unwrap();
    let cont = Continuation::new(0)
        .solver(solver)
        .step(0.1)
        .step_bounds(1e-8, 0.25)
        .stop_at(5.5);
    let branch = cont.run(&Quadratic, &start, ()).unwrap();
    let bps: Vec<_> = branch.branch_points().collect();
    assert_eq!(bps.len(), 5, "{branch}");
    for (k, bp) in bps.iter().enumerate() {
        let exact = (k + 1) as f64;
        eprintln!(
            "quadratic BP {}: error {:.2e}",
            k + 1,
            bp.parameter() - exact
        );
        // Gauss collocation eigenvalue error ~ (kπh)^(2m) C: for k = 5,
        // h = 1/40, m = 4 that is ≈ 6e-4·C with C ~ 1e-4; location to 1e-10.
        // Measured errors are below 1e-8 for k ≤ 5.
        assert!(
            (bp.parameter() - exact).abs() < 1e-7,
            "BP {k}: {}",
            bp.parameter()
        );
    }
    assert!(branch.folds().next().is_none());
    // Switch at p = 1 in both directions. Lyapunov–Schmidt on sin(πs):
    // p² − 1 ≈ ε ∫sin³/(π² ∫sin²) = 8ε/(3π³) with ε ≈ u(½) (first order).
    let slope = 8.0 / (3.0 * std::f64::consts::PI.powi(3));
    let mut eps_by_dir = Vec::new();
    for dir in [BranchSide::Positive, BranchSide::Negative] {
        let cont1 = cont.clone().step(0.02).max_steps(3);
        let b = cont1
            .run_from_branch_point(&Quadratic, bps[0], dir, ())
            .unwrap();
        assert_eq!(b.points().len(), 4);
        let p1 = &b.points()[1];
        let eps = p1.solution().eval(0.5)[0];
        assert!(eps.abs() > 1e-3, "left the trivial branch: u(1/2) = {eps}");
        let ratio = (p1.parameter().powi(2) - 1.0) / eps;
        eprintln!(
            "switch {dir:?}: u(1/2) = {eps:.3e}, (p²−1)/u(½) / (8/(3π³)) = {:.4}",
            ratio / slope
        );
        // First-order bifurcation formula: relative error O(ε) ≈ 2%.
        assert!(
            (ratio / slope - 1.0).abs() < 0.05,
            "ratio {ratio} vs {slope}"
        );
        // Each direction moves away from the trivial branch monotonically.
        let e2 = b.points()[3].solution().eval(0.5)[0];
        assert!(e2 * eps > 0.0 && e2.abs() > eps.abs());
        eps_by_dir.push(eps);
    }
    // The two directions go to opposite signs of ε.
    assert!(eps_by_dir[0] * eps_by_dir[1] < 0.0);
}

#[test]
fn euler_buckling_loads_and_post_buckled_branch() {
    use problems::{Euler, ellip_k_agm};
    let solver = Collocation::new().intervals(40);
    let start = solver.solve(&Euler, |_s: f64| [0.0, 0.0], &[1.0]).unwrap();
    let cont = Continuation::new(0)
        .solver(solver)
        .step(0.5)
        .step_bounds(1e-8, 2.0)
        .stop_at(45.0);
    let branch = cont.run(&Euler, &start, ()).unwrap();
    let bps: Vec<_> = branch.branch_points().collect();
    assert_eq!(bps.len(), 2, "{branch}");
    let pi2 = std::f64::consts::PI.powi(2);
    for (k, bp) in bps.iter().enumerate() {
        let exact = ((k + 1) * (k + 1)) as f64 * pi2;
        eprintln!(
            "euler BP {}: relative error {:.2e}",
            k + 1,
            bp.parameter() / exact - 1.0
        );
        // Relative: collocation eigenvalue error (kπh)^8·C ≲ 1e-9.
        assert!(
            (bp.parameter() / exact - 1.0).abs() < 1e-8,
            "BP {k}: {}",
            bp.parameter()
        );
    }
    // The determinant sign of the regular points flips exactly once at each
    // buckling load (the located points sit on the flip).
    let signs: Vec<f64> = branch
        .points()
        .iter()
        .filter(|p| !p.is_special())
        .map(|p| p.determinant_sign())
        .collect();
    let flips = signs.windows(2).filter(|w| w[0] != w[1]).count();
    assert_eq!(flips, 2);
    // Post-buckled branch from P = π², up to θ(0) = 2.5.
    let post = cont
        .clone()
        .step(0.1)
        .max_steps(200)
        .stop_when(|s| s.at_mesh(0)[0].abs() - 2.5)
        .run_from_branch_point(&Euler, bps[0], BranchSide::Positive, ())
        .unwrap();
    assert_eq!(post.termination(), &Termination::Event(0));
    let mut worst: f64 = 0.0;
    for p in post.points().iter().skip(1) {
        let theta0 = p.solution().at_mesh(0)[0];
        let k = (0.5 * theta0).sin().abs();
        let exact = 4.0 * ellip_k_agm(k).powi(2);
        worst = worst.max((p.parameter() / exact - 1.0).abs());
    }
    eprintln!(
        "euler post-buckled: {} points, worst relative error {worst:.2e}",
        post.points().len()
    );
    // m = 4, N = 40, solutions up to θ(0) = 2.5 (k = 0.95): O(h^8) relative
    // error measured ~1e-10; 1e-8 bounds it.
    assert!(worst < 1e-8, "worst relative error {worst:e}");
}

/// Bratu with a right-hand side that turns NaN for λ > `nan_above`, and a
/// boundary Jacobian that is reported as exactly zero for λ > `singular_above`.
struct Faulty {
    nan_above: f64,
    singular_above: f64,
}

impl Problem for Faulty {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn rhs(&self, _s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1];
        f[1] = -p[0] * y[0].exp();
        if p[0] > self.nan_above {
            f[1] = f64::NAN;
        }
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], _p: &[f64], g: &mut [f64]) {
        g[0] = y0[0];
        g[1] = y1[0];
    }
    fn boundary_jacobian(
        &self,
        _y0: &[f64],
        _y1: &[f64],
        p: &[f64],
        mut dg0: hockle::nalgebra::DMatrixViewMut<'_, f64>,
        mut dg1: hockle::nalgebra::DMatrixViewMut<'_, f64>,
        _dgp: hockle::nalgebra::DMatrixViewMut<'_, f64>,
    ) -> bool {
        if p[0] <= self.singular_above {
            dg0[(0, 0)] = 1.0;
            dg1[(1, 0)] = 1.0;
        }
        true
    }
}

/// Continues `p` from its rest state at λ = 0 in steps of 0.1.
fn run_faulty(p: &Faulty) -> hockle::continuation::Run {
    let start = Collocation::new()
        .intervals(10)
        .solve(p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    Continuation::new(0)
        .step(0.1)
        .step_bounds(1e-6, 0.5)
        .run(p, &start, ())
        .unwrap()
}

#[test]
fn nan_right_hand_side_ends_the_run_and_keeps_the_points() {
    let p = Faulty {
        nan_above: 1.0,
        singular_above: f64::INFINITY,
    };
    let b = run_faulty(&p);
    assert!(
        matches!(
            b.termination(),
            Termination::Failed {
                error: hockle::Error::NonFinite { .. },
                ..
            }
        ),
        "{}",
        b.termination()
    );
    assert!(b.points().len() > 5);
    assert!(b.points().iter().all(|pt| pt.parameter() <= 1.0));
    // The last point is within a few minimum steps of the NaN boundary.
    assert!(b.last().unwrap().parameter() > 0.99);
}

#[test]
fn singular_jacobian_ends_the_run_and_keeps_the_points() {
    let p = Faulty {
        nan_above: f64::INFINITY,
        singular_above: 0.5,
    };
    let b = run_faulty(&p);
    assert!(
        matches!(
            b.termination(),
            Termination::Failed {
                error: hockle::Error::SingularJacobian { .. },
                ..
            }
        ),
        "{}",
        b.termination()
    );
    assert!(b.points().len() > 3);
    assert!(b.points().iter().all(|pt| pt.parameter() <= 0.5));
    // A plain solve reports the same as a typed error.
    let e = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.7])
        .unwrap_err();
    assert!(matches!(e, hockle::Error::SingularJacobian { .. }), "{e}");
}

#[test]
fn newton_failure_at_minimum_step_keeps_the_points() {
    // A single corrector iteration (plus the final check) cannot reach 1e-10
    // from a predictor whose error is O(ds²) ~ 1e-3 at ds_min = 0.05, so the
    // first step fails at the minimum step.
    let p = Bratu { analytic: true };
    let start = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    let b = Continuation::new(0)
        .step(0.1)
        .step_bounds(0.05, 0.5)
        .max_newton(1)
        .run(&p, &start, ())
        .unwrap();
    match b.termination() {
        Termination::Failed {
            ds,
            error: hockle::Error::NewtonNotConverged { .. } | hockle::Error::NewtonDiverged { .. },
        } => assert_eq!(*ds, 0.05),
        t => panic!("unexpected termination: {t}"),
    }
    assert!(!b.points().is_empty());
    assert_eq!(b.points()[0].kind(), PointKind::Start);
    // Beyond the fold Bratu has no solution: a plain solve fails with a
    // typed Newton error.
    let e = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[4.0])
        .unwrap_err();
    assert!(
        matches!(
            e,
            hockle::Error::NewtonDiverged { .. } | hockle::Error::NewtonNotConverged { .. }
        ),
        "{e}"
    );
}

#[test]
fn observer_stop_and_iterator() {
    let p = Bratu { analytic: true };
    let start = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    let cont = Continuation::new(0).step(0.1);
    let mut seen = 0;
    let b = cont
        .run(&p, &start, |_pt: &hockle::continuation::Point| {
            seen += 1;
            if seen == 5 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        })
        .unwrap();
    assert_eq!(b.termination(), &Termination::Stopped);
    assert_eq!(b.points().len(), 5);
    // The iterator gives the same points.
    let pts: Vec<_> = cont.steps(&p, &start).unwrap().take(5).collect();
    for (a, c) in pts.iter().zip(b.points()) {
        assert_eq!(a.parameter(), c.parameter());
    }
    // Termination reasons print.
    assert_eq!(Termination::Stopped.to_string(), "stopped by the observer");
}

#[test]
fn continuation_with_a_free_parameter_and_an_integral_condition() {
    let solver = Collocation::new().intervals(20).free_parameters(&[0]);
    let start = solver
        .solve(
            &problems::Eigen,
            |s: f64| [(std::f64::consts::PI * s).sin(), 0.0],
            &[9.0, 0.5],
        )
        .unwrap();
    let b = Continuation::new(1)
        .solver(solver)
        .step(0.1)
        .stop_at(2.0)
        .run(&problems::Eigen, &start, ())
        .unwrap();
    assert_eq!(b.termination(), &Termination::ParameterValue(2.0));
    let pi = std::f64::consts::PI;
    for p in b.points() {
        // The eigenvalue stays π² (collocation error ~1e-11 relative at N = 20,
        // see free_parameter_with_integral_condition) and y(½) = √(2 p₁).
        assert!((p.parameters()[0] / (pi * pi) - 1.0).abs() < 1e-9);
        let amp = (2.0 * p.parameter()).sqrt();
        assert!((p.solution().eval(0.5)[0] - amp).abs() < 1e-9 * amp.max(1.0));
    }
}

/// An observer that records rejected steps: why, and the step tried next.
struct Rejections<'a>(&'a mut Vec<(hockle::continuation::Rejection, f64)>);

impl hockle::continuation::Observer for Rejections<'_> {
    fn step_rejected(
        &mut self,
        because: &hockle::continuation::Rejection,
        new_ds: f64,
    ) -> ControlFlow<()> {
        self.0.push((because.clone(), new_ds));
        ControlFlow::Continue(())
    }
}

#[test]
fn angle_check_rejects_steps_and_reports() {
    // The Bratu branch turns (dλ/ds decreases from 0.957); an angle limit of
    // 1e-9 rad cannot be met once the tangent turns, so the step halves down
    // to ds_min and the run fails with StepAngleTooLarge, keeping its points.
    let p = Bratu { analytic: true };
    let start = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    let mut rejected = Vec::new();
    let b = Continuation::new(0)
        .step(0.1)
        .step_bounds(1e-3, 0.5)
        .max_angle(1e-9)
        .run(&p, &start, Rejections(&mut rejected))
        .unwrap();
    assert!(
        matches!(
            b.termination(),
            Termination::Failed {
                error: hockle::Error::StepAngleTooLarge { .. },
                ..
            }
        ),
        "{}",
        b.termination()
    );
    assert!(!b.points().is_empty());
    // 0.1 → 0.05 → … → 1e-3 is seven halvings (the last clamps to ds_min),
    // each for the turn of the tangent
    assert!(rejected.len() >= 7, "{rejected:?}");
    for (because, ds) in &rejected {
        let hockle::continuation::Rejection::Turn { angle, max_angle } = because else {
            panic!("rejected for the angle, not {because}");
        };
        assert!(*max_angle == 1e-9 && *angle > *max_angle, "{because}");
        assert!((1e-3..0.1).contains(ds), "{ds}");
        assert!(because.to_string().contains("tangent turned"), "{because}");
    }
}

/// With a tolerance, a first step far too long for the diagram's
/// interpolant is rejected for it, and says so.
#[test]
fn a_step_too_long_for_the_tolerance_is_rejected_for_its_interpolant() {
    let p = Bratu { analytic: true };
    let solver = Collocation::new().intervals(8);
    let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0]).unwrap();
    let mut rejected = Vec::new();
    let run = Continuation::new(0)
        .solver(solver)
        .step(3.0)
        .step_bounds(1e-6, 3.0)
        .tolerance(1e-6)
        .max_steps(3)
        .run(&p, &start, Rejections(&mut rejected))
        .unwrap();
    assert!(!run.points().is_empty());
    let interpolant: Vec<_> = rejected
        .iter()
        .filter_map(|(because, _)| match because {
            hockle::continuation::Rejection::Interpolant { error, allowed, .. } => {
                Some((*error, *allowed))
            }
            _ => None,
        })
        .collect();
    assert!(!interpolant.is_empty(), "{rejected:?}");
    for (error, allowed) in interpolant {
        assert_eq!(allowed, 0.5e-6);
        assert!(error > allowed, "{error:e}");
    }
}

#[test]
fn the_iterator_counts_steps_rejections_and_iterations() {
    // Driving the Steps by hand gives the same counts as the observer of
    // `run`: accepted steps = regular points, rejections = step_rejected
    // calls, and at least the corrector iterations of the accepted points.
    let p = Bratu { analytic: true };
    let start = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    // (a first step of 0.5 turns the tangent by more than 0.002 rad)
    let cont = Continuation::new(0)
        .step(0.5)
        .step_bounds(1e-3, 0.5)
        .max_angle(0.002)
        .max_steps(40);
    let mut rejections = Vec::new();
    let b = cont.run(&p, &start, Rejections(&mut rejections)).unwrap();
    let rejected = rejections.len();
    let mut trace = cont.steps(&p, &start).unwrap();
    let pts: Vec<_> = trace.by_ref().collect();
    assert_eq!(pts.len(), b.points().len());
    let regular = pts
        .iter()
        .filter(|q| q.kind() == PointKind::Regular)
        .count();
    assert_eq!(trace.accepted(), regular);
    assert_eq!(trace.accepted(), 40);
    // The angle limit rejects the first step.
    assert!(rejected > 0);
    assert_eq!(trace.rejected(), rejected);
    let accepted: u64 = pts.iter().map(|q| u64::from(q.newton_iterations())).sum();
    assert!(trace.newton_iterations() >= accepted);
    assert!(trace.newton_iterations() > 0);
    // The run reports the same counts.
    assert_eq!(b.accepted(), trace.accepted());
    assert_eq!(b.rejected(), trace.rejected());
    assert_eq!(b.newton_iterations(), trace.newton_iterations());
}

#[test]
fn without_branch_points_the_fold_is_the_same_with_fewer_factorisations() {
    // With branch-point detection off, steps whose chord corrector converged
    // fast keep the old factorisation and refine the tangent on it.
    let p = Bratu { analytic: true };
    let solver = Collocation::new().intervals(20);
    let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0]).unwrap();
    let cont = Continuation::new(0)
        .solver(solver)
        .step(0.1)
        .stop_when(|s| s.at_mesh(0)[1] - 10.846_899_019_389_452);
    let full = cont.run(&p, &start, ()).unwrap();
    let fast = cont
        .clone()
        .detect_branch_points(false)
        .run(&p, &start, ())
        .unwrap();
    let f = fast.folds().next().expect("fold");
    // Same discretisation and location tolerance as bratu_fold_is_located.
    assert!(
        (f.parameter() - BRATU_FOLD).abs() < 1e-9,
        "{:e}",
        f.parameter() - BRATU_FOLD
    );
    assert!((f.solution().at_mesh(0)[1] - 4.0).abs() < 1e-8);
    assert_eq!(fast.termination(), &Termination::Event(0));
    assert!((fast.last().unwrap().parameter() - 1.0).abs() < 1e-8);
    // Step control is not penalised much (measured counts are printed).
    eprintln!(
        "points: full {}, without branch points {}",
        full.points().len(),
        fast.points().len()
    );
    assert!(fast.points().len() <= full.points().len() * 3 / 2);
    // The first step is identical (same ds): its tangent agrees with the
    // factorised one to the refinement tolerance.
    let (a, b) = (&full.points()[1], &fast.points()[1]);
    assert!((a.parameter() - b.parameter()).abs() < 1e-12);
    assert!(
        (a.dparameter_ds() - b.dparameter_ds()).abs() < 1e-8,
        "{:e}",
        a.dparameter_ds() - b.dparameter_ds()
    );
}

#[test]
fn distance_is_the_arclength_norm() {
    // Pseudo-arclength puts the first point at ⟨x₁ − x₀, τ₀⟩ = Δs, so its
    // distance from the start is Δs / cos α, α the angle between the secant
    // and the tangent: α = O(Δs κ) ≈ 0.01 on the Bratu branch near λ = 0,
    // so the two agree to ~α²/2 ≈ 1e-4 relative (bound 1e-3). Scaling every
    // weight and θ by 4 doubles the norm exactly (homogeneity), up to
    // rounding (1e-14).
    let p = Bratu { analytic: true };
    let start = Collocation::new()
        .intervals(10)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    let cont = Continuation::new(0).step(0.01);
    let pts: Vec<_> = cont.steps(&p, &start).unwrap().take(2).collect();
    let (a, b) = (pts[0].solution(), pts[1].solution());
    let d = cont.distance(a, b).unwrap();
    assert!(
        ((d - pts[1].arclength()) / d).abs() < 1e-3,
        "{d} vs {}",
        pts[1].arclength()
    );
    assert_eq!(cont.distance(a, a).unwrap(), 0.0);
    assert_eq!(cont.distance(a, b).unwrap(), cont.distance(b, a).unwrap());
    let heavy = Continuation::new(0)
        .weights(&[4.0, 4.0])
        .parameter_weight(4.0);
    let d4 = heavy.distance(a, b).unwrap();
    assert!((d4 / d - 2.0).abs() < 1e-14, "{}", d4 / d);
    // A solution on another mesh is refused.
    let other = Collocation::new()
        .intervals(7)
        .solve(&p, |_s: f64| [0.0, 0.0], &[0.0])
        .unwrap();
    assert!(cont.distance(a, &other).is_err());
}
