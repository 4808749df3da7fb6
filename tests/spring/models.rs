//! The cheap models against their own layers' closed forms.

use hockle::FoldKind;
use hockle::Stiffness;
use hockle::elastica::Elastica;
use hockle::helix::Helix;
use hockle::spring::{ElasticaModel, HelixModel, Model, Spring};

use crate::common::rel_err;

#[test]
fn helix_model_is_the_appendix_helix_from_rest_to_the_target() {
    let spring = Spring::paper();
    let target = 0.8;
    let pull = HelixModel::default().pull(&spring, target).unwrap();
    let helix = Helix::new(4, spring.helix_angle(), spring.stiffness()).unwrap();
    let pts = pull.curve().points();
    // The first point is the unstressed helix: F(θ0) = 0 exactly (sin 0).
    assert_eq!(pts[0].force, 0.0);
    assert_eq!(pts[0].extension, spring.helix_angle().cos());
    for p in pts {
        // Each point is the helix at its own θ, evaluated by the same
        // closed form: equal to rounding.
        assert!(rel_err(p.force, helix.force(p.parameter).unwrap()) < 1e-14);
    }
    // The last point is the bisected θ: the force meets the target to a few
    // ulps of θ times dF/dθ/F (≈ 1e3 here), far inside 1e-9.
    let last = pts.last().unwrap();
    assert!(rel_err(last.force / spring.force_scale(), target) < 1e-9);
    assert!(pull.reached_target());
}

#[test]
fn helix_model_folds_are_the_turning_points_of_the_appendix_force() {
    // At θ0 = 89.8°, A/B = 10 the helix force is not monotone: it peaks
    // (F/(2πn)² ≈ 0.66) and dips again before rising without bound.
    let spring = Spring::paper();
    let pull = HelixModel::new(2000).unwrap().pull(&spring, 3.0).unwrap();
    let helix = Helix::new(4, spring.helix_angle(), spring.stiffness()).unwrap();
    let last = pull.curve().points().last().unwrap();
    assert!(rel_err(last.force / spring.force_scale(), 3.0) < 1e-9);
    // The helix keeps its n loops: its force folds are no pop-out.
    assert!(pull.pop_outs().is_empty());
    assert!(pull.loops().iter().all(|&l| l == Some(4)));
    let folds: Vec<_> = pull
        .folds()
        .iter()
        .filter(|f| matches!(f.kind, FoldKind::MaxForce | FoldKind::MinForce))
        .collect();
    assert_eq!(folds.len(), 2, "{pull}");
    for fold in folds {
        // dF/dθ at the located fold, by a central difference with
        // h = 1e-5: zero up to the parabola's location error O(Δθ²)
        // (Δθ ≈ 1e-3 between samples), i.e. |dF/dθ| ≲ F″·1e-6 relative
        // to the slope scale F/θ ≈ 1e3 away from the folds.
        let (t, h) = (fold.point.parameter, 1e-5);
        let slope = (helix.force(t + h).unwrap() - helix.force(t - h).unwrap()) / (2.0 * h);
        assert!(slope.abs() < 1.0, "{fold}: dF/dθ = {slope}");
    }
}

#[test]
fn elastica_model_is_the_primary_upsilon_branch_scaled_by_b() {
    let b = 2.5;
    let spring =
        Spring::from_degrees(3, 90.0, Stiffness::new(10.0 * b, b, 1.5 * b).unwrap()).unwrap();
    let pull = ElasticaModel::default().pull(&spring, 1.0).unwrap();
    for p in pull.curve().points().iter().skip(1).step_by(37) {
        let e = Elastica::symmetric(3, p.parameter).unwrap().upsilon;
        // Same closed form on both sides, forces multiplied by B (one
        // rounding): agreement to a few ulps.
        assert!(rel_err(p.force, b * e.force()) < 1e-14, "{p:?}");
        assert!(rel_err(p.extension, e.extension()) < 1e-14, "{p:?}");
    }
    assert!(pull.loops().iter().all(|&l| l == Some(3)));
    assert!(pull.pop_outs().is_empty());
}

#[test]
fn scaffold_holds_the_primary_and_the_secondary_upsilon_branches() {
    let spring = Spring::paper();
    let scaffold = ElasticaModel::default().scaffold(&spring, 3.0).unwrap();
    let labels: Vec<&str> = scaffold.iter().map(|b| b.label()).collect();
    assert_eq!(labels.len(), 4, "{labels:?}");
    assert!(
        labels[1].contains("j = 3") && labels[3].contains("j = 1"),
        "{labels:?}"
    );
}
