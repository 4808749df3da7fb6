//! Speed of the closed-form models: `cargo bench --bench elastica`.
use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use hockle::Stiffness;
use hockle::elastica::{Branch, Elastica, Trace, bifurcation};
use hockle::helix::Helix;

fn bench(c: &mut Criterion) {
    for k in [0.1, 0.5, 0.9, 0.99] {
        c.bench_function(&format!("symmetric(4, {k})"), |b| {
            b.iter(|| Elastica::symmetric(black_box(4), black_box(k)).unwrap())
        });
    }
    c.bench_function("nonsymmetric(4, 3, 0.99)", |b| {
        b.iter(|| Elastica::nonsymmetric(black_box(4), black_box(3), black_box(0.99)).unwrap())
    });
    c.bench_function("secondary(4, 3, 0.95)", |b| {
        b.iter(|| Elastica::secondary(black_box(4), black_box(3), black_box(0.95)).unwrap())
    });
    c.bench_function("bifurcation(4, 3)", |b| {
        b.iter(|| bifurcation(black_box(4), black_box(3)).unwrap())
    });
    c.bench_function("bifurcation(10, 1)", |b| {
        b.iter(|| bifurcation(black_box(10), black_box(1)).unwrap())
    });
    c.bench_function("bifurcation(1, 7)", |b| {
        b.iter(|| bifurcation(black_box(1), black_box(7)).unwrap())
    });
    let trace = Trace::new()
        .points(1000)
        .scale_coils(4)
        .max_force_scaled(2.0);
    c.bench_function("trace υ n=4, 1000 points", |b| {
        b.iter(|| trace.run(black_box(4), Branch::Upsilon).unwrap())
    });
    c.bench_function("trace secondary j=3 n=4, 1000 points", |b| {
        b.iter(|| trace.secondary(black_box(4), black_box(3)).unwrap())
    });
    let h = Helix::new(
        4,
        88f64.to_radians(),
        Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    c.bench_function("helix force", |b| {
        b.iter(|| h.force(black_box(1.2)).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(std::time::Duration::from_secs(1)).warm_up_time(std::time::Duration::from_millis(300)).sample_size(20);
    targets = bench
}
criterion_main!(benches);
