//! Benches of the 3D rod: one solve, and the paper's whole curve.
//!
//! Run: `cargo bench --bench rod -- --warm-up-time 1 --measurement-time 20`

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use hockle::bvp::Collocation;
use hockle::rod::{Pull, Rod};

fn rod() -> Rod {
    Rod::new(
        4,
        89.8_f64.to_radians(),
        hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .expect("valid rod")
}

/// One Newton solve from the unstressed helix at F = 20 (48 intervals,
/// m = 4): the unit cost of a continuation step.
fn solve(c: &mut Criterion) {
    let rod = rod();
    let solver = Collocation::new().intervals(48);
    let mut p = rod.parameters_at_rest();
    p[Rod::FORCE] = 20.0;
    c.bench_function("rod_solve_from_helix_F20_N48", |b| {
        b.iter(|| {
            let s = solver.solve(&rod, |s: f64| rod.unstressed(s), black_box(&p));
            black_box(s.map(|s| s.newton().iterations))
        })
    });
}

/// The paper's Fig. spring: the whole curve from rest to F/(2πn)² = 3,
/// three pop-outs located (the main job without its output files).
fn cascade(c: &mut Criterion) {
    let mut g = c.benchmark_group("rod_pull");
    g.sample_size(10);
    let pull = Pull::new(rod(), hockle::Target::Force(3.0));
    g.bench_function("cascade_n4_to_3_default", |b| {
        b.iter(|| black_box(pull.run(()).map(|r| r.folds().len())))
    });
    g.finish();
}

criterion_group!(benches, solve, cascade);
criterion_main!(benches);
