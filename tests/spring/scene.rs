//! The scene's contract, each item a bug of the first version: the force
//! scale includes B, targets are met exactly or refused, settings are
//! checked before any work, loop counts and pop-outs mean one thing for
//! every model, extension control is a first-class target, and the rod
//! takes any intrinsic strains.

use hockle::nalgebra::Vector3;
use hockle::spring::{Control, ElasticaModel, HelixModel, Model, RodModel, Spring, Target};
use hockle::{Error, Stiffness};

use crate::common::rel_err;

/// Scaling A, B, C and F together leaves every model's equations
/// unchanged, so curves in F/((2πn)²B) must not depend on the units of
/// stiffness. The helix and the elastica evaluate the same closed forms in
/// both units (a few roundings); the rod's continuation sees the same
/// scaled norm, and Newton converges to 1e-10 in both.
#[test]
fn every_model_answers_in_units_of_b() {
    let unit = Stiffness::new(10.0, 1.0, 1.7316).unwrap();
    let twice = Stiffness::new(20.0, 2.0, 3.4632).unwrap();
    let spring = |k| Spring::from_degrees(4, 89.8, k).unwrap();
    let models: [(&dyn Model, f64, f64); 3] = [
        (&HelixModel::default(), 1.0, 1e-13),
        (&ElasticaModel::default(), 1.0, 1e-13),
        (&RodModel::default(), 0.3, 1e-8),
    ];
    for (model, target, tol) in models {
        let a = model.pull(&spring(unit), target).unwrap();
        let b = model.pull(&spring(twice), target).unwrap();
        assert!(a.reached_target() && b.reached_target(), "{a} / {b}");
        let (pa, pb) = (a.curve().points(), b.curve().points());
        let (sa, sb) = (a.curve().scale(), b.curve().scale());
        // The closed forms sample the same points; the rod's steps depend on
        // Newton's unscaled corrections, so compare where both end: at the
        // target force, whose extension is a property of the spring.
        let pairs: Vec<_> = if model.name() == "rod" {
            vec![(pa.last().unwrap(), pb.last().unwrap())]
        } else {
            assert_eq!(pa.len(), pb.len(), "{}", model.name());
            pa.iter().zip(pb).collect()
        };
        for (p, q) in pairs {
            assert!(
                (p.force_scaled(sa) - q.force_scaled(sb)).abs() < tol,
                "{}",
                model.name()
            );
            assert!((p.extension - q.extension).abs() < tol, "{}", model.name());
        }
        // The pull ends at the target in the scene's own scale.
        let last = pb.last().unwrap();
        assert!(
            rel_err(last.force_scaled(sb), target) < 1e-8,
            "{}",
            model.name()
        );
    }
}

#[test]
fn small_targets_are_met_and_the_rest_state_is_refused() {
    let spring = Spring::paper();
    let pull = RodModel::default().pull(&spring, 5e-5).unwrap();
    assert!(pull.reached_target(), "{pull}");
    let last = pull.curve().points().last().unwrap();
    // Located to 1e-9 in arclength, where F/((2πn)²B) has weight 1.
    assert!((last.force_scaled(spring.scale()) - 5e-5).abs() < 1e-9);
    for model in [
        &HelixModel::default() as &dyn Model,
        &ElasticaModel::default(),
        &RodModel::default(),
    ] {
        for target in [
            Target::Force(0.0),
            Target::Extension(1.0),
            Target::Extension(spring.helix_angle().cos()),
        ] {
            assert!(
                matches!(
                    model.pull_to(&spring, target),
                    Err(Error::UnreachableTarget { .. })
                ),
                "{} accepted {target}",
                model.name()
            );
        }
    }
}

#[test]
fn invalid_settings_are_errors_not_empty_curves() {
    let spring = Spring::paper();
    assert!(RodModel::default().intervals(0).pull(&spring, 1.0).is_err());
    // (issue 10) a huge mesh is refused before any allocation, not aborted
    for n in [usize::MAX, u32::MAX as usize] {
        assert!(matches!(
            RodModel::default().intervals(n).pull(&spring, 1.0),
            Err(Error::InvalidCount { .. })
        ));
    }
    assert!(matches!(
        RodModel::default().points(8).pull(&spring, 1.0),
        Err(Error::InvalidCount { name: "points", .. })
    ));
    let ring = Spring::from_degrees(4, 90.0, spring.stiffness()).unwrap();
    assert!(matches!(
        RodModel::default().pull(&ring, 1.0),
        Err(Error::OutsideModel { model: "rod", .. })
    ));
    assert!(HelixModel::new(1).is_err() && ElasticaModel::new(usize::MAX).is_err());
}

#[test]
fn extension_control_is_a_target_of_every_model() {
    let spring = Spring::paper();
    for model in [
        &HelixModel::default() as &dyn Model,
        &ElasticaModel::default(),
    ] {
        let pull = model.pull_to(&spring, Target::Extension(0.6)).unwrap();
        assert!(pull.reached_target(), "{pull}");
        assert_eq!(pull.target().control(), Control::Extension);
        let last = pull.curve().points().last().unwrap();
        // The helix samples Δz = cos θ exactly; the elastica bisects k to
        // rounding, and Δz(k) has a bounded slope there.
        assert!((last.extension - 0.6).abs() < 1e-9, "{}", model.name());
    }
    // The rod under a hard device: the same three pop-outs (they are a
    // property of the curve) and jumps only where Δz folds (pop-outs 2 and
    // 3; the first one needs no jump under extension control).
    let pull = RodModel::default()
        .pull_to(&spring, Target::Extension(0.95))
        .unwrap();
    assert!(pull.reached_target(), "{pull}");
    assert_eq!(pull.pop_outs().len(), 3, "{pull}");
    let loops: Vec<Option<u32>> = pull.stretches().iter().map(|s| s.loops).collect();
    assert_eq!(loops, [Some(4), Some(3), Some(2), Some(1)]);
    let loading = pull
        .jumps(Control::Extension)
        .into_iter()
        .filter(|j| j.direction == hockle::spring::Direction::Loading)
        .count();
    assert_eq!(loading, 2, "{pull}");
}

#[test]
fn loop_counts_never_exceed_the_coils_and_pop_outs_lose_loops() {
    let spring = Spring::from_degrees(3, 89.8, Stiffness::nikolai(10.0, 0.05).unwrap()).unwrap();
    let pull = RodModel::default().pull(&spring, 3.0).unwrap();
    assert!(pull.reached_target(), "{pull}");
    assert!(pull.loops().iter().flatten().all(|&l| l <= 3), "{pull}");
    // The known counts of the stretches fall with every pop-out, from the
    // three coils at rest.
    let known: Vec<u32> = pull.stretches().iter().filter_map(|s| s.loops).collect();
    assert_eq!(known.first(), Some(&3), "{pull}");
    assert!(known.windows(2).all(|w| w[1] < w[0]), "{known:?}");
    assert!(!pull.pop_outs().is_empty(), "{pull}");
}

#[test]
fn the_rod_takes_custom_intrinsic_strains() {
    // A slight natural curvature about d1 as well (u10 = 1, against
    // κ0 = 25.1): the rest state relaxes to it and the pull proceeds; the
    // models that assume the helix refuse it.
    let spring = Spring::paper()
        .with_intrinsic_strains(Vector3::new(1.0, 8.0 * std::f64::consts::PI, 0.0))
        .unwrap();
    let pull = RodModel::default().pull(&spring, 0.3).unwrap();
    assert!(pull.reached_target(), "{pull}");
    assert!(
        HelixModel::default().pull(&spring, 0.3).is_err()
            && ElasticaModel::default().pull(&spring, 0.3).is_err()
    );
}
