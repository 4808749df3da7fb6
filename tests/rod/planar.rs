//! θ0 = 90° exactly: the planar 3D solutions are the planar elastica.
//!
//! Reference: tests/data/rod_planar_elastica.csv, computed by
//! tests/data/rod_planar_elastica.py (mpmath, 30 digits) from the first
//! integral of θ″ = F sin θ by quadrature: an independent model of the same
//! physics (2D, no quaternions, no collocation).

use core::f64::consts::PI;

use hockle::Control;
use hockle::bvp::Collocation;
use hockle::continuation::{Continuation, PointKind};
use hockle::elastica::Elastica;
use hockle::rod::{Equilibrium, Rod};

/// Collocation with m = 4 on 100 uniform intervals: the error at mesh
/// points is O(h⁸) ≈ (κ_max h)⁸ with κ_max ≲ 40 → (0.4)⁸ · C ≈ 1e-4·C …
/// measured 7e-12 relative at F_s = 0.3; 1e-8 relative is the brief's bar
/// and leaves three orders of margin.
const PLANAR_FORCE_REL: f64 = 1e-8;

struct Row {
    force: f64,
    extension: f64,
    delta: f64,
}

fn table() -> Vec<Row> {
    include_str!("../data/rod_planar_elastica.csv")
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            Row {
                force: v[2],
                extension: v[4],
                delta: v[5],
            }
        })
        .collect()
}

/// A starting guess only (the answer is checked against the mpmath force):
/// the planar shape integrated by RK4 from the midpoint, θ(½) = π,
/// κ(½)² = κ0² + 2F(1 − cos δ), lifted to 3D in the x–z plane with d2 = j.
fn planar_guess(f: f64, delta: f64) -> impl Fn(f64) -> [f64; 13] {
    let k0 = 8.0 * PI;
    let kmid = (k0 * k0 + 2.0 * f * (1.0 - delta.cos())).sqrt();
    let half = 4000;
    let h = 0.5 / f64::from(half);
    let rk = |st: (f64, f64), h: f64| {
        let d = |s: (f64, f64)| (s.1, f * s.0.sin());
        let k1 = d(st);
        let k2 = d((st.0 + 0.5 * h * k1.0, st.1 + 0.5 * h * k1.1));
        let k3 = d((st.0 + 0.5 * h * k2.0, st.1 + 0.5 * h * k2.1));
        let k4 = d((st.0 + h * k3.0, st.1 + h * k3.1));
        (
            st.0 + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0),
            st.1 + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1),
        )
    };
    let (mut fwd, mut bwd) = (vec![(PI, kmid)], vec![(PI, kmid)]);
    for _ in 0..half {
        let a = *fwd.last().unwrap();
        fwd.push(rk(a, h));
        let b = *bwd.last().unwrap();
        bwd.push(rk(b, -h));
    }
    let mut th: Vec<(f64, f64)> = bwd.into_iter().rev().collect();
    th.extend_from_slice(&fwd[1..]);
    let n = th.len();
    let (mut xs, mut zs) = (vec![0.0; n], vec![0.0; n]);
    for i in 1..n {
        xs[i] = xs[i - 1] + 0.5 * h * (th[i].0.sin() + th[i - 1].0.sin());
        zs[i] = zs[i - 1] + 0.5 * h * (th[i].0.cos() + th[i - 1].0.cos());
    }
    move |s: f64| {
        let i = ((s / h).round() as usize).min(n - 1);
        let (t, k) = th[i];
        let mut y = [0.0; 13];
        y[0] = xs[i];
        y[2] = zs[i];
        y[3] = (t / 2.0).cos();
        y[5] = (t / 2.0).sin();
        y[9] = f;
        y[11] = k - k0;
        y
    }
}

#[test]
fn planar_solutions_are_the_elastica_to_1e_8_in_force() {
    let rod = Rod::new(4, PI / 2.0, hockle::Stiffness::nikolai(10.0, 0.05).unwrap())
        .unwrap()
        .with_control(Control::Extension);
    let solver = Collocation::new().intervals(100);
    for row in table() {
        let p = [0.0, row.extension, PI / 2.0];
        let sol = solver
            .solve(&rod, planar_guess(row.force, row.delta), &p)
            .unwrap();
        let e = Equilibrium::new(rod, sol).unwrap();
        let err = ((e.force() - row.force) / row.force).abs();
        assert!(
            err < PLANAR_FORCE_REL,
            "F_s = {}: rod {} vs elastica {}, rel {err:e}",
            row.force / (8.0 * PI).powi(2),
            e.force(),
            row.force
        );
        // Planar to rounding, one loop count of 4, |q| conserved.
        assert!(e.planarity() < 1e-12, "planarity {:e}", e.planarity());
        assert_eq!(e.loops(), Some(4));
        assert!(e.quaternion_drift() < 1e-12);
    }
}

/// The υ-branch force of `hockle::elastica` at extension `dz` (secant on k;
/// the extension is increasing in k on the primary υ-branch).
fn elastica_force_at(dz: f64) -> f64 {
    let ext = |k: f64| Elastica::symmetric(4, k).unwrap().upsilon.extension() - dz;
    let (mut a, mut b) = (0.05, 1.0 - 1e-12);
    let (mut fa, mut fb) = (ext(a), ext(b));
    assert!(fa < 0.0 && fb > 0.0);
    for _ in 0..200 {
        // Illinois-free bisection/secant hybrid: safe and plenty fast here.
        let c = if (b - a) > 1e-3 {
            0.5 * (a + b)
        } else {
            b - fb * (b - a) / (fb - fa)
        };
        let fc = ext(c);
        if fc.abs() < 1e-15 || (b - a).abs() < 1e-15 {
            return Elastica::symmetric(4, c).unwrap().upsilon.force();
        }
        if fc < 0.0 {
            (a, fa) = (c, fc);
        } else {
            (b, fb) = (c, fc);
        }
    }
    Elastica::symmetric(4, 0.5 * (a + b))
        .unwrap()
        .upsilon
        .force()
}

#[test]
fn planar_branch_is_the_elastica_and_has_its_out_of_plane_branch_point() {
    // Start on the planar primary υ-branch at F/(2πn)² = 0.1 (mpmath row),
    // then continue in the force with hockle::continuation, detecting
    // branch points (sign changes of the bordered Jacobian's determinant).
    let scale = (8.0 * PI).powi(2);
    let row = table().into_iter().nth(2).unwrap();
    let rod = Rod::new(4, PI / 2.0, hockle::Stiffness::nikolai(10.0, 0.05).unwrap()).unwrap();
    // 128 intervals: the O(h⁸) error at the mesh points is 2e-8 relative
    // with 64 intervals at F/(2πn)² ≈ 1.1 (tight hockles), 256× less here.
    let solver = Collocation::new().intervals(128);
    let start = solver
        .solve(
            &rod,
            planar_guess(row.force, row.delta),
            &[row.force, row.extension, PI / 2.0],
        )
        .unwrap();
    let w = rod.norm_weights();
    let branch = Continuation::new(Rod::FORCE)
        .solver(solver)
        .weights(&w)
        .parameter_weight(1.0 / (scale * scale))
        .step(0.01)
        .step_bounds(1e-9, 0.05)
        .max_steps(500)
        .stop_at(1.2 * scale)
        .run(&rod, &start, ())
        .unwrap();
    // Every point is planar and on hockle::elastica's υ-branch (two
    // independent models: quaternion collocation vs Jacobi functions).
    for p in branch.points().iter().step_by(6) {
        let e = Equilibrium::new(rod, p.solution().clone()).unwrap();
        assert!(e.planarity() < 1e-10);
        let f = elastica_force_at(e.extension());
        let err = ((e.force() - f) / f).abs();
        assert!(
            err < PLANAR_FORCE_REL,
            "Δz = {}: rod {} vs elastica {f}: {err:e}",
            e.extension(),
            e.force()
        );
    }
    // One out-of-plane branch point (the paper's diamond) on the primary
    // branch below F/(2πn)² = 1.2, measured at F/(2πn)² = 0.70456; the
    // imperfect spring (θ0 = 89.8°) pops out below it, at 0.6026.
    let bps: Vec<_> = branch
        .points()
        .iter()
        .filter(|p| p.kind() == PointKind::BranchPoint)
        .collect();
    assert_eq!(bps.len(), 1, "{:?}", branch.termination());
    let e = Equilibrium::new(rod, bps[0].solution().clone()).unwrap();
    assert!(e.planarity() < 1e-10);
    assert!(
        e.force_scaled() > 0.6026 && e.force_scaled() < 0.8,
        "{}",
        e.force_scaled()
    );
}

/// The secondary planar branches at θ0 = 90°, reached from the n = 4 pull
/// at θ0 = 89.8° (the most planar point of the j-loop stretch, re-solved at
/// θ0 = 90°), traced in the force towards their fold: their branch points
/// include the in-plane bifurcation with the non-symmetric ϑ_j branch, at
/// the closed-form point of `hockle::elastica::bifurcation(4, j)`, and
/// out-of-plane ones (the paper's diamonds).
#[test]
fn secondary_branches_branch_where_the_elastica_says() {
    use hockle::Target;
    use hockle::bvp::Solution;
    use hockle::continuation::Point;
    use hockle::rod::Pull;
    use std::ops::ControlFlow;

    let scale = (8.0 * PI).powi(2);
    let rod = Rod::new(
        4,
        89.8_f64.to_radians(),
        hockle::Stiffness::nikolai(10.0, 0.05).unwrap(),
    )
    .unwrap();
    let mut best: Vec<Option<(f64, Solution)>> = vec![None; 5];
    // (steps of at most 0.03 in arclength: the most planar point of a
    // stretch is read off the run's points, and the tolerance alone would
    // step over the stretches in a few long steps)
    Pull::new(rod, Target::Force(1.3))
        .intervals(64)
        .step(1e-3, 1e-7, 0.03)
        .run(|p: &Point| {
            let e = Equilibrium::new(rod, p.solution().clone()).unwrap();
            let planarity = e.planarity();
            if let Some(l) = e.loops().map(|l| l as usize)
                && (2..=3).contains(&l)
                && e.force_scaled() > 0.1
                && best[l].as_ref().is_none_or(|b| planarity < b.0)
            {
                best[l] = Some((planarity, e.solution().clone()));
            }
            ControlFlow::Continue(())
        })
        .unwrap();
    let rod90 = Rod::new(4, PI / 2.0, hockle::Stiffness::nikolai(10.0, 0.05).unwrap()).unwrap();
    let w = rod90.norm_weights();
    for j in [3_u32, 2] {
        let (_, sol) = best[j as usize].as_ref().expect("a near-planar stretch");
        let mut p = sol.parameters().to_vec();
        // to θ0 = 90° in a few Newton solves: one jump from 89.8° converged
        // in 17 iterations or not at all, depending on the rounding of the
        // run that chose the start
        let mut start = sol.clone();
        for theta0 in [89.9, 89.97, 90.0] {
            p[Rod::THETA0] = f64::to_radians(theta0);
            start = Collocation::new().solve(&rod90, &start, &p).unwrap();
        }
        let e = Equilibrium::new(rod90, start.clone()).unwrap();
        assert!(e.planarity() < 1e-12 && e.loops() == Some(j));
        let branch = Continuation::new(Rod::FORCE)
            .weights(&w)
            .parameter_weight(1.0 / (scale * scale))
            .step(-0.01)
            .step_bounds(1e-9, 0.05)
            .max_steps(400)
            .stop_at(0.05 * scale)
            .stop_at(2.5 * scale)
            .run(&rod90, &start, ())
            .unwrap();
        let bif = hockle::elastica::bifurcation(4, j).unwrap();
        let bps: Vec<Equilibrium> = branch
            .points()
            .iter()
            .filter(|p| p.kind() == PointKind::BranchPoint)
            .map(|p| Equilibrium::new(rod90, p.solution().clone()).unwrap())
            .collect();
        // Located to 1e-10 in arclength on a 64-interval mesh (O(h⁸)):
        // measured agreement with the closed form ~1e-9; 1e-6 is safe.
        let in_plane = bps.iter().find(|e| {
            ((e.force() - bif.force()) / bif.force()).abs() < 1e-6
                && (e.extension() - bif.extension()).abs() < 1e-6
        });
        assert!(
            in_plane.is_some(),
            "j = {j}: no branch point at the elastica bifurcation (F = {}, Δz = {}); found {:?}",
            bif.force(),
            bif.extension(),
            bps.iter()
                .map(|e| (e.force(), e.extension()))
                .collect::<Vec<_>>()
        );
        // Out-of-plane branch points too, and the branch stays planar.
        assert!(bps.len() >= 2, "j = {j}: {} branch points", bps.len());
        assert!(bps.iter().all(|e| e.planarity() < 1e-10));
    }
}
