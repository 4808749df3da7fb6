use super::*;
use crate::bvp::classic::{Coupled13, Troesch};

/// Mean wall time of `f` over `reps` calls, in seconds.
fn mean_seconds(reps: u32, mut f: impl FnMut()) -> f64 {
    let t0 = std::time::Instant::now();
    for _ in 0..reps {
        f();
    }
    t0.elapsed().as_secs_f64() / f64::from(reps)
}

#[test]
#[ignore = "timing probe: cargo test --release --lib system::timing -- --ignored --nocapture"]
fn big_parts() {
    let nn = 50;
    let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
    let big = Coupled13::new();
    let mut sys = System::new(&big, t, Tableau::new(4), vec![0], 1).unwrap();
    let mut x = sys.zero_state();
    for (i, v) in x.y.iter_mut().enumerate() {
        *v = 0.01 * i as f64;
    }
    sys.border.coef_q[0] = 1.0;
    let mut r = sys.zero_residual();
    let mut d = sys.zero_state();
    let reps = 200;
    let tr = mean_seconds(reps, || {
        sys.residual(&x, &mut r).unwrap();
    });
    let tf = mean_seconds(reps, || {
        sys.factor(&x).unwrap();
    });
    let tc = mean_seconds(reps, || {
        sys.factor_border().unwrap();
    });
    let ts = mean_seconds(reps, || {
        sys.solve(&r, &mut d).unwrap();
    });
    eprintln!(
        "13-dim N=50: residual {:.1} µs, factor {:.1} µs, border rows {:.1} µs, solve {:.1} µs",
        tr * 1e6,
        tf * 1e6,
        tc * 1e6,
        ts * 1e6
    );
}

#[test]
#[ignore = "timing probe: cargo test --release --lib system::timing -- --ignored --nocapture"]
fn troesch_parts() {
    let nn = 48;
    let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
    let mut sys = System::new(&Troesch, t, Tableau::new(4), vec![], 0).unwrap();
    let mut x = sys.zero_state();
    x.p[0] = 5.0;
    for j in 0..=nn {
        x.y[2 * j] = j as f64 / nn as f64;
        x.y[2 * j + 1] = 1.0;
    }
    let mut r = sys.zero_residual();
    let mut d = sys.zero_state();
    let reps = 2000;
    let tr = mean_seconds(reps, || {
        sys.residual(&x, &mut r).unwrap();
    });
    let tf = mean_seconds(reps, || {
        sys.factor(&x).unwrap();
    });
    let ts = mean_seconds(reps, || {
        sys.solve(&r, &mut d).unwrap();
    });
    eprintln!(
        "residual {:.1} µs, factor {:.1} µs, solve {:.1} µs",
        tr * 1e6,
        tf * 1e6,
        ts * 1e6
    );
}

/// User + system CPU seconds of this process so far (from /proc/self/stat,
/// in clock ticks of 10 ms).
#[cfg(feature = "rayon")]
fn cpu_seconds() -> f64 {
    let s = std::fs::read_to_string("/proc/self/stat").unwrap_or_default();
    let after = s.rsplit(')').next().unwrap_or("");
    let f: Vec<f64> = after
        .split_whitespace()
        .map(|v| v.parse().unwrap_or(0.0))
        .collect();
    (f.get(11).copied().unwrap_or(0.0) + f.get(12).copied().unwrap_or(0.0)) / 100.0
}

#[test]
#[cfg(feature = "rayon")]
#[ignore = "timing probe: cargo test --release --features rayon --lib system::timing -- --ignored --nocapture"]
fn parallel_factor() {
    let big = Coupled13::new();
    for nn in [50usize, 200, 800] {
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let mut sys = System::new(&big, t, Tableau::new(4), vec![0], 1).unwrap();
        let mut x = sys.zero_state();
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.01 * i as f64;
        }
        sys.border.coef_q[0] = 1.0;
        let reps = (20_000 / nn) as u32;
        for threads in [1, 2, 1, 2] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            let c0 = cpu_seconds();
            let wall = pool.install(|| {
                mean_seconds(reps, || {
                    sys.factor(&x).unwrap();
                })
            });
            let cpu = (cpu_seconds() - c0) / f64::from(reps);
            eprintln!(
                "N={nn} threads={threads}: factor {:.1} µs wall, {:.1} µs CPU",
                wall * 1e6,
                cpu * 1e6
            );
        }
    }
}
