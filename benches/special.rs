//! hockle::special side by side with the `ellip` crate on the same inputs.
//!
//! `cargo bench --bench special -- --warm-up-time 0.5 --measurement-time 1`
//!
//! Each benchmark evaluates a batch of 1024 inputs (throughput is reported
//! per element, so criterion's "time/elem" is the time per call). hockle's
//! timings include building the `Modulus` from m (validation and √m) at
//! every call, as `ellip` validates m at every call.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use hockle::special::{Modulus, ellip_e, ellip_e_inc, ellip_f, ellip_k, jacobi};

const N: usize = 1024;

/// A small deterministic generator (64-bit LCG, top 53 bits).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// (m, φ, u) triples: "uniform" (m ∈ [0, 1), φ ∈ [0, π/2], u ∈ [0, 10]) or
/// "extreme" (1 − m = 10^−U(0,15) exactly representable, φ = π/2 − 10^−U(0,8),
/// u ∈ [0, 100]).
fn inputs(extreme: bool) -> Vec<(f64, f64, f64)> {
    let mut g = Lcg(20_260_122);
    (0..N)
        .map(|_| {
            if extreme {
                let mc = 10f64.powf(-15.0 * g.next());
                let m = 1.0 - mc;
                let phi = std::f64::consts::FRAC_PI_2 - 10f64.powf(-8.0 * g.next());
                (m, phi, 100.0 * g.next())
            } else {
                (
                    g.next(),
                    std::f64::consts::FRAC_PI_2 * g.next(),
                    10.0 * g.next(),
                )
            }
        })
        .collect()
}

fn bench(c: &mut Criterion) {
    for (set, extreme) in [("uniform", false), ("extreme", true)] {
        let xs = inputs(extreme);
        let mut g = c.benchmark_group(format!("special/{set}"));
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("K/hockle", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, _, _)| ellip_k(Modulus::from_m(black_box(m)).unwrap()))
                    .sum::<f64>()
            })
        });
        let mods: Vec<Modulus> = xs
            .iter()
            .map(|&(m, _, _)| Modulus::from_m(m).unwrap())
            .collect();
        g.bench_function("K/hockle-premod", |b| {
            b.iter(|| mods.iter().map(|&md| ellip_k(black_box(md))).sum::<f64>())
        });
        g.bench_function("K/ellip", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, _, _)| ellip::ellipk(black_box(m)).unwrap())
                    .sum::<f64>()
            })
        });
        g.bench_function("E/hockle", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, _, _)| ellip_e(Modulus::from_m(black_box(m)).unwrap()))
                    .sum::<f64>()
            })
        });
        g.bench_function("E/ellip", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, _, _)| ellip::ellipe(black_box(m)).unwrap())
                    .sum::<f64>()
            })
        });
        g.bench_function("F/hockle", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, p, _)| ellip_f(black_box(p), Modulus::from_m(black_box(m)).unwrap()))
                    .sum::<f64>()
            })
        });
        g.bench_function("F/ellip", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, p, _)| ellip::ellipf(black_box(p), black_box(m)).unwrap())
                    .sum::<f64>()
            })
        });
        g.bench_function("Einc/hockle", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, p, _)| {
                        ellip_e_inc(black_box(p), Modulus::from_m(black_box(m)).unwrap())
                    })
                    .sum::<f64>()
            })
        });
        g.bench_function("Einc/ellip", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, p, _)| ellip::ellipeinc(black_box(p), black_box(m)).unwrap())
                    .sum::<f64>()
            })
        });
        g.bench_function("sncndn/hockle", |b| {
            b.iter(|| {
                xs.iter()
                    .map(|&(m, _, u)| {
                        let j = jacobi(black_box(u), Modulus::from_m(black_box(m)).unwrap());
                        j.sn + j.cn + j.dn
                    })
                    .sum::<f64>()
            })
        });
        g.finish();
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
