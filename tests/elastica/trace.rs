//! Branch tracing.
use crate::common::rel_err;
use hockle::elastica::{Arm, Branch, Elastica, Trace, bifurcation, secondary_fold};

/// Largest gap between consecutive points in the plot normalised by the
/// curve's ranges: with N points adaptively placed the gaps are ~1/N.
fn max_gap(c: &hockle::ForceExtension) -> f64 {
    let p = c.points();
    let (z0, z1) = p.iter().fold((f64::MAX, f64::MIN), |a, q| {
        (a.0.min(q.extension), a.1.max(q.extension))
    });
    let (f0, f1) = p.iter().fold((f64::MAX, f64::MIN), |a, q| {
        (a.0.min(q.force), a.1.max(q.force))
    });
    p.windows(2)
        .map(|w| {
            ((w[1].extension - w[0].extension) / (z1 - z0))
                .hypot((w[1].force - w[0].force) / (f1 - f0))
        })
        .fold(0.0, f64::max)
}

#[test]
fn primary_and_theta_branches_run_from_the_ring_to_the_limit() {
    for branch in [Branch::Upsilon, Branch::Alpha, Branch::Theta { j: 4 }] {
        let c = Trace::new()
            .points(300)
            .max_force_scaled(1.5)
            .run(4, branch)
            .unwrap();
        assert_eq!(c.len(), 300);
        let p = c.points();
        assert_eq!(p[0].force, 0.0);
        assert_eq!(p[0].extension, 0.0);
        // the end is at the limit (bisection to 2^-60 in q)
        assert!(rel_err(c.force_scaled(299).unwrap(), 1.5) < 1e-9);
        // monotone in k, force and extension
        assert!(
            p.windows(2)
                .all(|w| w[1].parameter > w[0].parameter && w[1].force > w[0].force)
        );
        // 300 points on a curve of normalised length ≤ ~2: gaps ≤ 2.5/150
        assert!(max_gap(&c) < 0.02, "{branch}: {}", max_gap(&c));
        // every point is the solution at its k
        for q in p.iter().step_by(37) {
            let s = Elastica::symmetric(4, q.parameter).unwrap();
            let e = match branch {
                Branch::Upsilon => s.upsilon,
                Branch::Alpha => s.alpha,
                _ => Elastica::nonsymmetric(4, 4, q.parameter).unwrap()[0],
            };
            // k is stored rounded from q: the force moves by F'(k)·ε·k
            assert!(rel_err(e.force(), q.force) < 1e-12);
        }
    }
}

#[test]
fn theta_j_starts_at_its_bifurcation_point() {
    let b = bifurcation(4, 2).unwrap();
    let c = Trace::new()
        .points(50)
        .scale_coils(4)
        .max_force_scaled(3.0)
        .run(4, Branch::Theta { j: 2 })
        .unwrap();
    let p0 = c.points()[0];
    assert!(rel_err(p0.force, b.force()) < 1e-12 && rel_err(p0.extension, b.extension()) < 1e-12);
}

#[test]
fn secondary_branch_is_traced_through_its_fold() {
    for j in [1, 2, 3, 5] {
        let c = Trace::new()
            .points(400)
            .scale_coils(4)
            .max_force_scaled(6.0)
            .secondary(4, j)
            .unwrap();
        let fold = secondary_fold(4, j).unwrap();
        let p = c.points();
        let kmin = p.iter().map(|q| q.parameter).fold(f64::MAX, f64::min);
        assert!(rel_err(kmin, fold.modulus()) < 1e-15, "j = {j}");
        // the bifurcation point lies on the curve: some segment passes within
        // the sampling resolution of it
        let b = bifurcation(4, j).unwrap();
        let s = c.force_scale();
        let near = p
            .iter()
            .map(|q| (q.extension - b.extension()).hypot((q.force - b.force()) / s))
            .fold(f64::MAX, f64::min);
        assert!(near < 0.02, "j = {j}: {near}");
        assert!(max_gap(&c) < 0.03, "j = {j}: {}", max_gap(&c));
        // a single arm starts at the fold
        let arm = Trace::new()
            .points(20)
            .scale_coils(4)
            .max_force_scaled(6.0)
            .run(4, Branch::Secondary { j, arm: Arm::Upper })
            .unwrap();
        assert!(rel_err(arm.points()[0].parameter, fold.modulus()) < 1e-15);
    }
}

#[test]
fn bad_options_are_errors() {
    assert!(Trace::new().points(1).run(4, Branch::Upsilon).is_err());
    assert!(
        Trace::new()
            .max_force_scaled(f64::NAN)
            .run(4, Branch::Upsilon)
            .is_err()
    );
    assert!(
        Trace::new()
            .max_force_scaled(0.0)
            .run(4, Branch::Upsilon)
            .is_err()
    );
    assert!(Trace::new().run(0, Branch::Upsilon).is_err());
    assert!(Trace::new().secondary(4, 4).is_err());
    assert!(Trace::new().scale_coils(0).run(4, Branch::Alpha).is_err());
    // a limit below where the branch starts
    assert!(
        Trace::new()
            .scale_coils(4)
            .max_force_scaled(0.01)
            .secondary(4, 6)
            .is_err()
    );
}
