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

/// The rod model solved on the rod's half (`RodModel::symmetric`) answers
/// the paper's spring as the whole rod does, a second model of the same
/// equilibria (the half's image against the whole rod with its phase
/// condition): the same pop-outs, their folds within the sum of the two
/// estimates (each bounds its own fold errors, tests/rod/tolerance.rs), the
/// same loops lost, as many jumps under either control, leaving and landing
/// within that sum of the other curve, and the same first contact of the
/// paper's strip (none).
#[test]
fn the_rod_on_its_half_answers_as_the_whole_rod() {
    use hockle::Control;
    use hockle::spring::{RodModel, Target};
    let spring = Spring::paper().with_strip_width(1e-4).unwrap();
    let model = RodModel::default().tolerance(1e-5);
    let whole = model.pull(&spring, 3.0).unwrap();
    let half = model
        .symmetric(true)
        .pull_with_contact(&spring, Target::Force(3.0), ())
        .unwrap();
    assert!(whole.reached_target() && half.reached_target(), "{half}");
    let bound = whole.estimated_error().unwrap() + half.estimated_error().unwrap();
    let scale = whole.curve().scale();
    let near = |a: &hockle::ForcePoint, b: &hockle::ForcePoint| {
        (a.extension - b.extension)
            .abs()
            .max((a.force_scaled(scale) - b.force_scaled(scale)).abs())
    };
    let (pw, ph) = (whole.pop_outs(), half.pop_outs());
    assert_eq!(pw.len(), 3);
    assert_eq!(pw.len(), ph.len());
    for (a, b) in pw.iter().zip(&ph) {
        assert!(near(&a.max.point, &b.max.point) <= bound, "{a:?} {b:?}");
        assert!(near(&a.min.point, &b.min.point) <= bound, "{a:?} {b:?}");
    }
    assert_eq!(whole.loops_lost(), half.loops_lost());
    for control in [Control::Force, Control::Extension] {
        let (jw, jh) = (whole.jumps(control), half.jumps(control));
        assert_eq!(jw.len(), jh.len(), "under {control}");
        for (a, b) in jw.iter().zip(&jh) {
            // under force control a jump leaves at a located maximum-force
            // fold: the two runs' within the bound
            if control == Control::Force {
                assert!(near(&a.from, &b.from) <= bound, "{a:?} {b:?}");
            }
            // where it lands (on the run's dense output at the controlled
            // value, on another branch) lies on the whole rod's curve: at
            // that value the curve passes within the bound of it. (Where a
            // jump leaves under extension control is the last stable point
            // before a turning point of Δz, a curve point of a
            // force-controlled pull, not compared: near the turning point
            // the force at a given Δz is ill-conditioned.)
            let p = b.to;
            let off = match control {
                Control::Force => whole
                    .curve()
                    .extension_at(p.force)
                    .iter()
                    .map(|z| (z - p.extension).abs())
                    .fold(f64::INFINITY, f64::min),
                Control::Extension => whole
                    .curve()
                    .force_at(p.extension)
                    .iter()
                    .map(|f| (f - p.force).abs() / scale.value())
                    .fold(f64::INFINITY, f64::min),
            };
            assert!(off <= bound, "{a:?} {b:?}: {off:e}");
        }
    }
    assert_eq!(half.first_contact(), None);
    assert!(half.closest_approach().iter().all(Option::is_some));
}
