//! Benches of the collocation solver and continuation.
//!
//! Run: `cargo bench --bench bvp -- --warm-up-time 1 --measurement-time 3`

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use hockle::bvp::Collocation;
use hockle::continuation::Continuation;

#[path = "../tests/bvp/problems.rs"]
#[allow(dead_code)]
mod problems;
use problems::{Bratu, Coupled13, Troesch};

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

/// The SciPy comparison problems at matched mesh-point accuracy (see
/// benches/scipy_bvp.py): Bratu λ = 1 (lower branch) and Troesch μ = 5.
fn versus_scipy(c: &mut Criterion) {
    let bratu = Bratu { analytic: true };
    let s1 = Collocation::new().intervals(8);
    c.bench_function("scipy_match_bratu_lambda1", |b| {
        b.iter(|| {
            s1.solve(&bratu, |_s: f64| [0.0, 0.0], black_box(&[1.0]))
                .unwrap()
        })
    });
    let s2 = Collocation::new().intervals(24);
    c.bench_function("scipy_match_troesch_mu5", |b| {
        b.iter(|| {
            s2.solve(&Troesch, |s: f64| [s, 1.0], black_box(&[5.0]))
                .unwrap()
        })
    });
}

criterion_group!(benches, newton_step_13, bratu_continuation, versus_scipy);
criterion_main!(benches);
