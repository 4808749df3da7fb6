//! Analytic Jacobians against central finite differences.

use hockle::Control;
use hockle::bvp::Problem;
use hockle::nalgebra::DMatrix;
use hockle::rod::Rod;

/// Central differences with step h have truncation error h²|f‴|/6 and
/// rounding ε|f|/h. The rhs is a polynomial of degree ≤ 4 in y (R quadratic
/// in q, times M) with entries of size ≤ ~100 here, so h = 1e-5 gives
/// ~1e-10·100 + 1e-11·100 ≈ 1e-8 absolute on entries of size up to 100:
/// a relative tolerance of 1e-8 of the largest entry is safe.
const FD_REL: f64 = 1e-8;
const H: f64 = 1e-5;

fn pseudo_random(seed: u64, n: usize) -> Vec<f64> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((x >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        })
        .collect()
}

fn states(rod: &Rod) -> Vec<([f64; 13], [f64; 13], Vec<f64>)> {
    let mut out = Vec::new();
    for seed in 1..6 {
        let v = pseudo_random(seed, 29);
        let mut y = [0.0; 13];
        let mut yr = [0.0; 13];
        for k in 0..13 {
            // Forces and moments of the size met along the paper's curve.
            let scale = if k >= 7 { 30.0 } else { 1.0 };
            y[k] = scale * v[k];
            yr[k] = v[13 + k];
        }
        let p = vec![v[26] * 100.0, v[27], rod.theta0() + 0.1 * v[28]];
        out.push((y, yr, p));
    }
    out
}

fn max_abs(m: &DMatrix<f64>) -> f64 {
    m.iter().fold(0.0_f64, |a, v| a.max(v.abs()))
}

fn check(name: &str, analytic: &DMatrix<f64>, fd: &DMatrix<f64>) {
    let scale = max_abs(fd).max(1.0);
    let err = max_abs(&(analytic - fd));
    assert!(
        err <= FD_REL * scale,
        "{name}: |J − J_fd| = {err:e} (scale {scale:e})\n{analytic}\n{fd}"
    );
}

fn rods() -> Vec<Rod> {
    let r = Rod::new(
        4,
        89.8_f64.to_radians(),
        hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    vec![
        r,
        r.with_control(Control::Extension),
        Rod::new(2, 1.0, hockle::Stiffness::new(0.3, 1.7, 2.2).unwrap()).unwrap(),
    ]
}

/// [`rods`] and the same rods solved on their halves (`Rod::symmetric`:
/// ½ the right-hand side, the midpoint's conditions).
fn all_rods() -> Vec<Rod> {
    let whole = rods();
    let halves: Vec<Rod> = whole.iter().map(|r| r.symmetric().unwrap()).collect();
    whole.into_iter().chain(halves).collect()
}

#[test]
fn rhs_jacobian_matches_central_differences() {
    for rod in all_rods() {
        let (n, np) = (rod.dim(), rod.parameter_count());
        for (y, _, p) in states(&rod) {
            let mut jy = DMatrix::zeros(n, n);
            let mut jp = DMatrix::zeros(n, np);
            assert!(rod.rhs_jacobian(0.3, &y, &p, jy.as_view_mut(), jp.as_view_mut()));
            let mut fdy = DMatrix::zeros(n, n);
            let (mut fp, mut fm) = ([0.0; 13], [0.0; 13]);
            for k in 0..n {
                let (mut yp, mut ym) = (y, y);
                yp[k] += H;
                ym[k] -= H;
                rod.rhs(0.3, &yp, &p, &mut fp);
                rod.rhs(0.3, &ym, &p, &mut fm);
                for i in 0..n {
                    fdy[(i, k)] = (fp[i] - fm[i]) / (2.0 * H);
                }
            }
            let mut fdp = DMatrix::zeros(n, np);
            for k in 0..np {
                let (mut pp, mut pm) = (p.clone(), p.clone());
                pp[k] += H;
                pm[k] -= H;
                rod.rhs(0.3, &y, &pp, &mut fp);
                rod.rhs(0.3, &y, &pm, &mut fm);
                for i in 0..n {
                    fdp[(i, k)] = (fp[i] - fm[i]) / (2.0 * H);
                }
            }
            check("df/dy", &jy, &fdy);
            check("df/dp", &jp, &fdp);
        }
    }
}

#[test]
fn boundary_jacobian_matches_central_differences() {
    for rod in all_rods() {
        let (n, np, nb) = (rod.dim(), rod.parameter_count(), rod.boundary_count());
        for (y0, y1, p) in states(&rod) {
            let mut j0 = DMatrix::zeros(nb, n);
            let mut j1 = DMatrix::zeros(nb, n);
            let mut jp = DMatrix::zeros(nb, np);
            assert!(rod.boundary_jacobian(
                &y0,
                &y1,
                &p,
                j0.as_view_mut(),
                j1.as_view_mut(),
                jp.as_view_mut()
            ));
            let (mut gp, mut gm) = (vec![0.0; nb], vec![0.0; nb]);
            let mut fd0 = DMatrix::zeros(nb, n);
            let mut fd1 = DMatrix::zeros(nb, n);
            let mut fdp = DMatrix::zeros(nb, np);
            for k in 0..n {
                let (mut a, mut b) = (y0, y0);
                a[k] += H;
                b[k] -= H;
                rod.boundary(&a, &y1, &p, &mut gp);
                rod.boundary(&b, &y1, &p, &mut gm);
                for i in 0..nb {
                    fd0[(i, k)] = (gp[i] - gm[i]) / (2.0 * H);
                }
                let (mut a, mut b) = (y1, y1);
                a[k] += H;
                b[k] -= H;
                rod.boundary(&y0, &a, &p, &mut gp);
                rod.boundary(&y0, &b, &p, &mut gm);
                for i in 0..nb {
                    fd1[(i, k)] = (gp[i] - gm[i]) / (2.0 * H);
                }
            }
            for k in 0..np {
                let (mut a, mut b) = (p.clone(), p.clone());
                a[k] += H;
                b[k] -= H;
                rod.boundary(&y0, &y1, &a, &mut gp);
                rod.boundary(&y0, &y1, &b, &mut gm);
                for i in 0..nb {
                    fdp[(i, k)] = (gp[i] - gm[i]) / (2.0 * H);
                }
            }
            check("dg/dy0", &j0, &fd0);
            check("dg/dy1", &j1, &fd1);
            check("dg/dp", &jp, &fdp);
        }
    }
}

#[test]
fn integrand_jacobian_matches_central_differences() {
    for rod in rods() {
        let (n, np) = (rod.dim(), rod.parameter_count());
        for (y, yr, p) in states(&rod) {
            let mut jy = DMatrix::zeros(1, n);
            let mut jp = DMatrix::zeros(1, np);
            assert!(rod.integrand_jacobian(0.5, &y, &yr, &p, jy.as_view_mut(), jp.as_view_mut()));
            let mut fd = DMatrix::zeros(1, n);
            let (mut hp, mut hm) = ([0.0], [0.0]);
            for k in 0..n {
                let (mut a, mut b) = (y, y);
                a[k] += H;
                b[k] -= H;
                rod.integrand(0.5, &a, &yr, &p, &mut hp);
                rod.integrand(0.5, &b, &yr, &p, &mut hm);
                fd[(0, k)] = (hp[0] - hm[0]) / (2.0 * H);
            }
            check("dh/dy", &jy, &fd);
            assert_eq!(max_abs(&jp), 0.0);
        }
    }
}
