//! Benches of the collocation solver and continuation.
//!
//! Run: `cargo bench --bench bvp -- --warm-up-time 1 --measurement-time 3`
//! The parallel condensation (`rayon` feature), 1 thread against 2:
//! `cargo bench --bench bvp --features rayon -- parallel --warm-up-time 1 --measurement-time 2`

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use hockle::bvp::Collocation;
use hockle::continuation::{Continuation, FoldContinuation};

use hockle::bvp::classic::{self as problems, Bratu, BratuLength, Coupled13, Troesch};

/// One damped Newton step of the 13-dimensional system (Jacobian at every
/// collocation point, condensation, elimination, two solves, two residual
/// evaluations): `max_newton(1)` stops right after it.
fn newton_step_13(c: &mut Criterion) {
    let problem = Coupled13::new();
    let mut g = c.benchmark_group("newton_step_13dim_m4");
    for n in [50usize, 100, 200, 400, 800] {
        let solver = Collocation::new().points(4).intervals(n).max_newton(1);
        g.bench_with_input(BenchmarkId::from_parameter(n), &n, |b, _| {
            b.iter(|| {
                let r = solver.solve(&problem, |_s: f64| [0.0; 13], black_box(&[0.3]));
                black_box(r.is_err())
            })
        });
    }
    g.finish();
}

/// AUTO-07p's Bratu regression run: 100 continuation steps through the fold
/// with N = 10, m = 4.
fn bratu_continuation(c: &mut Criterion) {
    let p = Bratu { analytic: true };
    let solver = Collocation::new().intervals(10);
    let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0]).unwrap();
    let cont = Continuation::new(0).solver(solver).step(0.1).max_steps(100);
    c.bench_function("bratu_continuation_100_steps_n10_m4", |b| {
        b.iter(|| {
            let br = cont.run(&p, black_box(&start), ()).unwrap();
            black_box(br.points().len())
        })
    });
}

/// The Bratu fold continued in the domain length L from 1 to 3 (N = 20,
/// m = 4; the curve of tests/continuation/fold_curve.rs), from the fold
/// located by a one-parameter run.
fn bratu_fold_curve(c: &mut Criterion) {
    let p = BratuLength;
    let solver = Collocation::new().intervals(20);
    let start = solver.solve(&p, |_s: f64| [0.0, 0.0], &[0.0, 1.0]).unwrap();
    let run = Continuation::new(0)
        .solver(solver.clone())
        .step(0.1)
        .max_steps(100)
        .run(&p, &start, ())
        .unwrap();
    let fold = run.folds().next().unwrap().solution().clone();
    let curve = FoldContinuation::new(
        0,
        Continuation::new(1).solver(solver).step(0.1).stop_at(3.0),
    );
    let r = curve.run(&p, &fold, ()).unwrap();
    eprintln!(
        "bratu fold curve L 1 → 3: {} points, {} steps, {} corrector iterations",
        r.points().len(),
        r.accepted(),
        r.newton_iterations()
    );
    c.bench_function("bratu_fold_curve_l_1_to_3_n20_m4", |b| {
        b.iter(|| {
            let r = curve.run(&p, black_box(&fold), ()).unwrap();
            black_box(r.points().len())
        })
    });
}

/// Bratu λ = 1 lower branch: max error of y at the mesh points against
/// the closed form.
fn bratu_mesh_error(sol: &hockle::bvp::Solution) -> f64 {
    let theta = {
        let (mut a, mut b) = (0.0_f64, 4.0_f64);
        for _ in 0..200 {
            let c = 0.5 * (a + b);
            if problems::bratu_lambda(c) < 1.0 {
                a = c
            } else {
                b = c
            }
        }
        0.5 * (a + b)
    };
    let exact = |s: f64| -2.0 * (((s - 0.5) * theta / 2.0).cosh() / (theta / 4.0).cosh()).ln();
    let pts = sol.mesh().points().to_vec();
    pts.iter()
        .enumerate()
        .map(|(j, s)| (sol.at_mesh(j)[0] - exact(*s)).abs())
        .fold(0.0, f64::max)
}

/// The SciPy comparison (benches/scipy_bvp.py) at matched accuracy: Bratu
/// λ = 1 (lower branch) and Troesch μ = 5 on uniform meshes whose error is
/// at or below SciPy's at tol = 1e-6 and 1e-8 (printed before timing).
fn versus_scipy(c: &mut Criterion) {
    let bratu = Bratu { analytic: true };
    for n in [2usize, 4] {
        let s = Collocation::new()
            .intervals(n)
            .solve(&bratu, |_s: f64| [0.0, 0.0], &[1.0])
            .unwrap();
        eprintln!(
            "hockle bratu N={n}: max mesh error {:.2e}",
            bratu_mesh_error(&s)
        );
    }
    for n in [48usize, 100] {
        let s = Collocation::new()
            .intervals(n)
            .solve(&Troesch, |s: f64| [s, 1.0], &[5.0])
            .unwrap();
        eprintln!(
            "hockle troesch N={n}: |y'(0) error| {:.2e}; {}",
            (s.at_mesh(0)[1] - 0.045_750_461_406_318_74).abs(),
            s.newton()
        );
    }
    for (name, n) in [
        ("scipy_match_bratu_1e-6", 2usize),
        ("scipy_match_bratu_1e-8", 4),
    ] {
        let solver = Collocation::new().intervals(n);
        c.bench_function(name, |b| {
            b.iter(|| {
                solver
                    .solve(&bratu, |_s: f64| [0.0, 0.0], black_box(&[1.0]))
                    .unwrap()
            })
        });
    }
    for (name, n) in [
        ("scipy_match_troesch_1e-6", 48usize),
        ("scipy_match_troesch_1e-8", 100),
    ] {
        let solver = Collocation::new().intervals(n);
        c.bench_function(name, |b| {
            b.iter(|| {
                solver
                    .solve(&Troesch, |s: f64| [s, 1.0], black_box(&[5.0]))
                    .unwrap()
            })
        });
    }
}

/// Rod-sized continuation: the 13-dimensional system, N = 50, m = 4, 100
/// steps in its forcing parameter with Δs capped at 0.05 (every step runs the
/// chord corrector, a factorisation and a tangent).
fn continuation_13(c: &mut Criterion) {
    let problem = Coupled13::new();
    let solver = Collocation::new().intervals(50);
    let start = solver.solve(&problem, |_s: f64| [0.0; 13], &[0.0]).unwrap();
    let cont = Continuation::new(0)
        .solver(solver)
        .step(0.05)
        .step_bounds(1e-8, 0.05)
        .max_steps(100);
    let mut g = c.benchmark_group("continuation_13dim");
    g.sample_size(10);
    g.bench_function("n50_m4_100_steps", |b| {
        b.iter(|| {
            let br = cont.run(&problem, black_box(&start), ()).unwrap();
            black_box(br.points().len())
        })
    });
    let fast = cont.clone().detect_branch_points(false);
    g.bench_function("n50_m4_100_steps_no_branch_points", |b| {
        b.iter(|| {
            let br = fast.run(&problem, black_box(&start), ()).unwrap();
            black_box(br.points().len())
        })
    });
    g.finish();
}

/// Minimum over `rounds` of the time of `f` on each pool, the pools taking
/// turns so that machine load hits both alike.
#[cfg(feature = "rayon")]
fn interleaved_min(pools: &[rayon::ThreadPool], rounds: usize, f: &(dyn Fn() + Sync)) -> Vec<f64> {
    let mut best = vec![f64::INFINITY; pools.len()];
    for _ in 0..rounds {
        for (b, pool) in best.iter_mut().zip(pools) {
            let t = std::time::Instant::now();
            pool.install(f);
            *b = b.min(t.elapsed().as_secs_f64());
        }
    }
    best
}

/// The `rayon` feature: the intervals are condensed on every thread of the
/// pool. One Newton step of the 13-dimensional system and a 100-step
/// continuation on pools of 1 and 2 threads: first the interleaved minimum
/// (printed), then criterion per pool.
#[cfg(feature = "rayon")]
fn parallel_condensation(c: &mut Criterion) {
    let problem = Coupled13::new();
    let pools: Vec<rayon::ThreadPool> = [1, 2]
        .iter()
        .map(|&k| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .unwrap()
        })
        .collect();
    let step = |n: usize| {
        let solver = Collocation::new().points(4).intervals(n).max_newton(1);
        move || {
            let r = solver.solve(&Coupled13::new(), |_s: f64| [0.0; 13], black_box(&[0.3]));
            black_box(r.is_err());
        }
    };
    for n in [50usize, 200, 800] {
        let t = interleaved_min(&pools, 20, &step(n));
        eprintln!(
            "parallel newton step 13-dim N={n}: 1 thread {:.3} ms, 2 threads {:.3} ms, speed-up {:.2}x",
            t[0] * 1e3,
            t[1] * 1e3,
            t[0] / t[1]
        );
    }
    let start = Collocation::new()
        .intervals(50)
        .solve(&problem, |_s: f64| [0.0; 13], &[0.0])
        .unwrap();
    let cont = Continuation::new(0)
        .solver(Collocation::new().intervals(50))
        .step(0.05)
        .step_bounds(1e-8, 0.05)
        .max_steps(100);
    let run = || {
        let br = cont.run(&problem, black_box(&start), ()).unwrap();
        black_box(br.points().len());
    };
    let t = interleaved_min(&pools, 5, &run);
    eprintln!(
        "parallel continuation 13-dim N=50, 100 steps: 1 thread {:.1} ms, 2 threads {:.1} ms, speed-up {:.2}x",
        t[0] * 1e3,
        t[1] * 1e3,
        t[0] / t[1]
    );
    let mut g = c.benchmark_group("parallel_newton_step_13dim_m4");
    for n in [50usize, 200, 800] {
        let f = step(n);
        for (k, pool) in pools.iter().enumerate() {
            g.bench_with_input(
                BenchmarkId::new(format!("threads_{}", k + 1), n),
                &n,
                |b, _| pool.install(|| b.iter(&f)),
            );
        }
    }
    g.finish();
}

#[cfg(not(feature = "rayon"))]
fn parallel_condensation(_c: &mut Criterion) {}

criterion_group!(
    benches,
    newton_step_13,
    bratu_continuation,
    bratu_fold_curve,
    versus_scipy,
    continuation_13,
    parallel_condensation
);
criterion_main!(benches);
