//! Bad input gives typed errors that name the value.

use hockle::Error;
use hockle::Stiffness;
use hockle::nalgebra::Vector3;
use hockle::spring::{ElasticaModel, HelixModel, Model, RodModel, Spring};

#[test]
fn springs_reject_zero_coils_and_bad_angles() {
    let k = Stiffness::nikolai(10.0, 0.05).unwrap();
    assert!(matches!(
        Spring::new(0, 1.0, k),
        Err(Error::InvalidCount { name: "coils", .. })
    ));
    for angle in [0.0, -0.1, 1.6, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Spring::new(4, angle, k),
            Err(Error::InvalidArgument {
                name: "helix_angle",
                ..
            })
        ));
    }
    assert!(
        Spring::paper()
            .with_intrinsic_strains(Vector3::new(0.0, f64::NAN, 0.0))
            .is_err()
    );
}

#[test]
fn every_model_rejects_a_bad_target() {
    let spring = Spring::paper();
    let models: [&dyn Model; 3] = [
        &HelixModel::default(),
        &ElasticaModel::default(),
        &RodModel::default(),
    ];
    for model in models {
        for target in [0.0, f64::NAN, f64::INFINITY] {
            assert!(
                matches!(
                    model.pull(&spring, target),
                    Err(Error::UnreachableTarget { .. })
                ),
                "{} accepted {target}",
                model.name()
            );
        }
    }
}

#[test]
fn models_that_assume_helical_strains_refuse_others() {
    let spring = Spring::paper()
        .with_intrinsic_strains(Vector3::new(1.0, 25.0, 0.0))
        .unwrap();
    for model in [
        &HelixModel::default() as &dyn Model,
        &ElasticaModel::default(),
    ] {
        assert!(matches!(
            model.pull(&spring, 1.0),
            Err(Error::OutsideModel { .. })
        ));
        // Pushing is outside what they model too.
        assert!(matches!(
            model.pull(&Spring::paper(), -1.0),
            Err(Error::OutsideModel { .. })
        ));
    }
}

#[test]
fn strip_widths_must_be_finite_and_positive() {
    for w in [0.0, -1e-3, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Spring::paper().with_strip_width(w),
            Err(Error::InvalidArgument {
                name: "strip width",
                ..
            })
        ));
    }
    assert_eq!(
        Spring::paper()
            .with_strip_width(1e-3)
            .unwrap()
            .strip_width(),
        Some(1e-3)
    );
    // A response takes one closest approach per point and a valid width.
    let pull = HelixModel::default().pull(&Spring::paper(), 0.5).unwrap();
    let n = pull.curve().len();
    assert!(matches!(
        pull.clone().with_closest_approach(vec![None; n + 1], None),
        Err(Error::LengthMismatch { .. })
    ));
    assert!(matches!(
        pull.clone()
            .with_closest_approach(vec![Some(1.0); n], Some(-1.0)),
        Err(Error::InvalidArgument { .. })
    ));
    let flagged = pull
        .with_closest_approach(vec![Some(1.0); n], Some(2.0))
        .unwrap();
    assert_eq!(flagged.first_contact(), Some(0));
}
