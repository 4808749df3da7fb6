use super::*;

struct Bratu(bool);
impl Problem for Bratu {
    fn dim(&self) -> usize {
        2
    }
    fn parameter_count(&self) -> usize {
        2
    }
    fn boundary_count(&self) -> usize {
        2
    }
    fn integral_count(&self) -> usize {
        usize::from(self.0)
    }
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1] + 0.3 * s * y[0];
        f[1] = -p[0] * y[0].exp() + p[1] * s;
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        g[0] = y0[0] + 0.1 * y1[1];
        g[1] = y1[0] - 0.2 * p[0];
    }
    fn integrand(&self, s: f64, y: &[f64], _r: &[f64], p: &[f64], h: &mut [f64]) {
        h[0] = y[0] * y[0] + s * y[1] - p[0];
    }
}

/// The residual's equations in one vector: stage, continuity, boundary,
/// dense rows.
fn flat(r: &Residual) -> Vec<f64> {
    r.stage
        .iter()
        .chain(&r.cont)
        .chain(&r.bc)
        .chain(&r.dense)
        .copied()
        .collect()
}

/// The Jacobian of the residual at `x` in (Y, K, the first `free`
/// parameters) by central differences of step 1e-6 (entries to ~1e-10 for
/// smooth problems of unit scale), column-major, with its size.
fn difference_jacobian<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &State,
    free: usize,
) -> (Vec<f64>, usize) {
    let (ny, nk) = (x.y.len(), x.k.len());
    let size = ny + nk + free;
    let mut jm = vec![0.0; size * size];
    let d = 1e-6;
    for c in 0..size {
        let (mut xp, mut xm) = (x.clone(), x.clone());
        let (p, q) = if c < ny {
            (&mut xp.y[c], &mut xm.y[c])
        } else if c < ny + nk {
            (&mut xp.k[c - ny], &mut xm.k[c - ny])
        } else {
            (&mut xp.p[c - ny - nk], &mut xm.p[c - ny - nk])
        };
        *p += d;
        *q -= d;
        let (mut rp, mut rm) = (sys.zero_residual(), sys.zero_residual());
        sys.residual(&xp, &mut rp).unwrap();
        sys.residual(&xm, &mut rm).unwrap();
        for (i, (u, v)) in flat(&rp).iter().zip(flat(&rm)).enumerate() {
            jm[c * size + i] = (u - v) / (2.0 * d);
        }
    }
    (jm, size)
}

/// The residual at `x` and the Newton corrections for it by the condensed
/// solve (with the factorisation's determinant) and by the sparse LU (the
/// system is left on the sparse LU).
fn condensed_and_sparse<P: Problem + ?Sized>(
    sys: &mut System<'_, P>,
    x: &State,
) -> (Residual, (State, Det), State) {
    let mut r = sys.zero_residual();
    sys.residual(x, &mut r).unwrap();
    let det = sys.factor(x).unwrap();
    let mut a = sys.zero_state();
    sys.solve(&r, &mut a).unwrap();
    sys.linear = LinearSolver::SparseLu;
    sys.factor(x).unwrap();
    let mut b = sys.zero_state();
    sys.solve(&r, &mut b).unwrap();
    (r, (a, det), b)
}

/// The condensed solve and faer's sparse LU on the full system give the
/// same Newton correction at an arbitrary (non-solution) state, with a
/// free parameter, an integral row and a border row.
#[test]
fn condensed_matches_sparse() {
    for (nn, full) in [(1usize, false), (1, true), (2, true), (5, true)] {
        let tab = Tableau::new(3);
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let prob = Bratu(full);
        let mut sys = System::new(
            &prob,
            t.clone(),
            tab.clone(),
            if full { vec![0, 1] } else { vec![] },
            usize::from(full),
        )
        .unwrap();
        let mut x = sys.zero_state();
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.1 * (i as f64).sin();
        }
        for (i, v) in x.k.iter_mut().enumerate() {
            *v = 0.2 * (i as f64 * 0.7).cos();
        }
        x.p[0] = 1.3;
        x.p[1] = -0.4;
        for (i, v) in sys.border.coef_y.iter_mut().enumerate() {
            *v = 0.01 * (i as f64 + 1.0);
        }
        if full {
            sys.border.coef_q[0] = 0.5;
            sys.border.coef_q[1] = -0.25;
            sys.border.target[0] = 0.3;
        }
        let (r, (a, _), b) = condensed_and_sparse(&mut sys, &x);
        // Third reference: dense FD Jacobian of the residual.
        let (mut jm, size) = difference_jacobian(&mut sys, &x, if full { 2 } else { 0 });
        let mut rhs: Vec<f64> = flat(&r).iter().map(|v| -v).collect();
        let mut piv = vec![0; size];
        crate::linalg::lu_panel(&mut jm, size, size, size, &mut piv).unwrap();
        crate::linalg::apply_lower(&jm, size, size, &piv, &mut rhs);
        crate::linalg::solve_upper(&jm, size, size, &mut rhs);
        let c: Vec<f64> = rhs;
        let av: Vec<f64> = a.y.iter().chain(&a.k).chain(&a.p).copied().collect();
        let bv: Vec<f64> = b.y.iter().chain(&b.k).chain(&b.p).copied().collect();
        for i in 0..size {
            assert!(
                (c[i] - av[i]).abs() < 1e-6 * (1.0 + c[i].abs()),
                "condensed N={nn} i={i}: {} vs {}",
                av[i],
                c[i]
            );
            assert!(
                (c[i] - bv[i]).abs() < 1e-6 * (1.0 + c[i].abs()),
                "sparse N={nn} i={i}: {} vs {}",
                bv[i],
                c[i]
            );
        }
        for (u, v) in
            a.y.iter()
                .chain(&a.k)
                .chain(&a.p)
                .zip(b.y.iter().chain(&b.k).chain(&b.p))
        {
            assert!((u - v).abs() < 1e-9 * (1.0 + v.abs()), "N={nn}: {u} vs {v}");
        }
    }
}

/// The sparse path analyses its pattern once per system: new Jacobians and
/// new border rows cost numeric factorisations only, and each correction
/// still agrees with the condensed one at the same state.
#[test]
fn sparse_pattern_is_analysed_once() {
    let nn = 6;
    let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
    let prob = Bratu(true);
    let new = || System::new(&prob, t.clone(), Tableau::new(3), vec![0, 1], 1).unwrap();
    let (mut sparse, mut dense) = (new(), new());
    sparse.linear = LinearSolver::SparseLu;
    let mut x = sparse.zero_state();
    let mut r = sparse.zero_residual();
    let (mut a, mut b) = (sparse.zero_state(), sparse.zero_state());
    for step in 0..4 {
        let s = step as f64;
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.1 * (i as f64 + s).sin();
        }
        for (i, v) in x.k.iter_mut().enumerate() {
            *v = 0.2 * (i as f64 * 0.7 - s).cos();
        }
        x.p[0] = 1.3 + 0.1 * s;
        x.p[1] = -0.4;
        for sys in [&mut sparse, &mut dense] {
            for (i, v) in sys.border.coef_y.iter_mut().enumerate() {
                *v = 0.01 * (i as f64 + 1.0 + s);
            }
            sys.border.coef_q[0] = 0.5;
            sys.border.coef_q[1] = -0.25 + 0.1 * s;
            sys.factor(&x).unwrap();
            // A border change after the factorisation (as continuation does).
            sys.border.coef_q[0] = 0.5 + 0.05 * s;
            sys.factor_border().unwrap();
        }
        sparse.residual(&x, &mut r).unwrap();
        sparse.solve(&r, &mut a).unwrap();
        dense.solve(&r, &mut b).unwrap();
        for (u, v) in a.y.iter().chain(&a.k).zip(b.y.iter().chain(&b.k)) {
            // Two LU orderings of the same well-conditioned system
            // (condition ~1e3): agreement to rounding times the condition.
            assert!(
                (u - v).abs() < 1e-11 * (1.0 + v.abs()),
                "step {step}: {u} vs {v}"
            );
        }
    }
    assert_eq!(sparse.sparse.analyses, 1);
}

/// Everything a factorisation and a correction produce, as bits.
#[cfg(feature = "rayon")]
fn factor_and_solve_bits<P: Problem + ?Sized>(sys: &mut System<'_, P>, x: &State) -> Vec<u64> {
    let det = sys.factor(x).unwrap();
    let mut r = sys.zero_residual();
    sys.residual(x, &mut r).unwrap();
    let mut d = sys.zero_state();
    sys.solve(&r, &mut d).unwrap();
    [det.sign, det.log_abs]
        .iter()
        .chain(&sys.wa)
        .chain(&sys.gam)
        .chain(&sys.pim)
        .chain(&sys.dint)
        .chain(&sys.dint_p)
        .chain(&sys.fin)
        .chain(&d.y)
        .chain(&d.k)
        .chain(&d.p)
        .map(|v| v.to_bits())
        .chain(sys.wpiv.iter().map(|&i| i as u64))
        .collect()
}

/// With the `rayon` feature the intervals are condensed on every thread of
/// the pool; the factorisation, the correction and a whole solve are the
/// same bit for bit on 1, 2 and 3 threads (1 is the serial code path, 3
/// splits the intervals unevenly).
#[cfg(feature = "rayon")]
#[test]
fn parallel_condensation_is_bit_identical() {
    use crate::bvp::Collocation;
    use crate::bvp::classic::Coupled13;
    let on = |threads: usize, f: &(dyn Fn() -> Vec<u64> + Sync)| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(f)
    };
    // The 13-dimensional system with its analytic Jacobian, N = 50, a free
    // parameter and a border row.
    let coupled = || {
        let nn = 50;
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let big = Coupled13::new();
        let mut sys = System::new(&big, t, Tableau::new(4), vec![0], 1).unwrap();
        assert_eq!(
            super::condense::groups(nn, 52 * 52 * 52),
            rayon::current_num_threads()
        );
        let mut x = sys.zero_state();
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.01 * (i as f64).sin();
        }
        x.p[0] = 0.3;
        for (i, v) in sys.border.coef_y.iter_mut().enumerate() {
            *v = 1e-3 * (i as f64 * 0.1).cos();
        }
        sys.border.coef_q[0] = 1.0;
        factor_and_solve_bits(&mut sys, &x)
    };
    // Bratu with finite-difference Jacobians, an integral condition, two
    // free parameters and a border row, on enough intervals to go parallel.
    let bratu = || {
        let nn = 5000;
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let prob = Bratu(true);
        let mut sys = System::new(&prob, t, Tableau::new(3), vec![0, 1], 1).unwrap();
        assert_eq!(
            super::condense::groups(nn, 6 * 6 * 6),
            rayon::current_num_threads()
        );
        let mut x = sys.zero_state();
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.1 * (i as f64 * 1e-3).sin();
        }
        x.p[0] = 1.3;
        x.p[1] = -0.4;
        for (i, v) in sys.border.coef_y.iter_mut().enumerate() {
            *v = 1e-4 * (i as f64 * 1e-2).cos();
        }
        sys.border.coef_q[0] = 0.5;
        factor_and_solve_bits(&mut sys, &x)
    };
    // A whole Newton solve.
    let solve = || {
        let sol = Collocation::new()
            .intervals(50)
            .solve(&Coupled13::new(), |_s: f64| [0.0; 13], &[0.3])
            .unwrap();
        (0..=50)
            .flat_map(|j| {
                sol.at_mesh(j)
                    .iter()
                    .map(|v| v.to_bits())
                    .collect::<Vec<_>>()
            })
            .collect()
    };
    for case in [&coupled as &(dyn Fn() -> Vec<u64> + Sync), &bratu, &solve] {
        let serial = on(1, case);
        for threads in [2, 3] {
            assert!(serial == on(threads, case), "{threads} threads differ");
        }
    }
}

/// Four core components, two components with zero rows of f_y (one
/// constant, one linear in the parameter) and two quadratures (zero
/// columns), all Jacobians by central differences.
struct Passive;
impl Problem for Passive {
    fn dim(&self) -> usize {
        8
    }
    fn parameter_count(&self) -> usize {
        1
    }
    fn boundary_count(&self) -> usize {
        8
    }
    fn rhs(&self, s: f64, y: &[f64], p: &[f64], f: &mut [f64]) {
        f[0] = y[1] + y[4] * y[0];
        f[1] = -p[0] * y[0].exp() + y[5] * s;
        f[2] = y[3] + y[0] * y[1];
        f[3] = -y[2] + y[1].sin() * y[4];
        f[4] = 0.0;
        f[5] = 0.1 * p[0];
        f[6] = y[0] * y[0] + y[3];
        f[7] = y[2] * y[5] + p[0];
    }
    fn boundary(&self, y0: &[f64], y1: &[f64], p: &[f64], g: &mut [f64]) {
        g[0] = y0[0] - 0.1 * y1[1];
        g[1] = y0[1] + y1[0] - 0.2 * p[0];
        g[2] = y0[2] - 0.3;
        g[3] = y1[3] + 0.1 * y1[2];
        g[4] = y0[4] - 0.5 - 0.1 * p[0];
        g[5] = y1[5] + 0.2;
        g[6] = y0[6];
        g[7] = y0[7] + 0.3 * y1[6];
    }
}

/// With constants and quadratures the block's core alone is factored
/// (`stage_split`): the Newton correction agrees with the sparse LU of the
/// whole system and the determinant with a dense LU of its
/// difference-quotient Jacobian, on the plain-loop (m = 3: a 12 × 12 core)
/// and faer (m = 7: 28 × 28) paths.
#[test]
fn split_block_matches_sparse_and_dense() {
    for (nn, m) in [(1usize, 3usize), (4, 3), (3, 7)] {
        let t: Vec<f64> = (0..=nn).map(|j| j as f64 / nn as f64).collect();
        let prob = Passive;
        let mut sys = System::new(&prob, t, Tableau::new(m), vec![0], 1).unwrap();
        let mut x = sys.zero_state();
        for (i, v) in x.y.iter_mut().enumerate() {
            *v = 0.1 * (i as f64).sin();
        }
        for (i, v) in x.k.iter_mut().enumerate() {
            *v = 0.2 * (i as f64 * 0.7).cos();
        }
        x.p[0] = 1.3;
        for (i, v) in sys.border.coef_y.iter_mut().enumerate() {
            *v = 0.01 * (i as f64 + 1.0);
        }
        sys.border.coef_q[0] = 0.5;
        let (_, (a, det), b) = condensed_and_sparse(&mut sys, &x);
        assert!(sys.split.iter().all(|s| *s == [4, 2]), "{:?}", sys.split);
        for (u, v) in
            a.y.iter()
                .chain(&a.k)
                .chain(&a.p)
                .zip(b.y.iter().chain(&b.k).chain(&b.p))
        {
            // two LU orderings of one system (condition ≲ 1e4 here)
            assert!(
                (u - v).abs() < 1e-9 * (1.0 + v.abs()),
                "N={nn} m={m}: {u} vs {v}"
            );
        }
        // the difference-quotient Jacobian of the residual, densely
        let (mut jm, size) = difference_jacobian(&mut sys, &x, 1);
        let mut piv = vec![0; size];
        let dense = crate::linalg::lu_panel(&mut jm, size, size, size, &mut piv).unwrap();
        // entries to ~1e-10 (central differences of smooth functions at
        // step 1e-6), each moving log|det| by at most that times the
        // condition
        assert!(
            (dense.log_abs - det.log_abs).abs() < 1e-6,
            "N={nn} m={m}: log|det| {} vs {}",
            det.log_abs,
            dense.log_abs
        );
    }
}
