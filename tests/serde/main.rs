//! serde (feature `serde`): exact round trips, and inputs validated on the
//! way in exactly as their constructors validate them.
#![cfg(feature = "serde")]

use hockle::Stiffness;
use hockle::elastica::Elastica;
use hockle::special::Modulus;
use hockle::spring::{HelixModel, Model, Spring};

fn round_trip<T: serde::Serialize + serde::de::DeserializeOwned>(x: &T) -> T {
    serde_json::from_str(&serde_json::to_string(x).unwrap()).unwrap()
}

#[test]
fn modulus_round_trips_exactly_even_next_to_one() {
    // JSON carries f64 in shortest round-trip form and serde_json parses it
    // exactly (feature float_roundtrip): equality is exact.
    for md in [
        Modulus::from_k(0.3).unwrap(),
        Modulus::from_complement(1e-300).unwrap(),
        Modulus::from_m(1.0).unwrap(),
    ] {
        assert_eq!(round_trip(&md), md);
    }
}

#[test]
fn inconsistent_or_out_of_range_parts_are_rejected() {
    for bad in [
        r#"{"k":0.5,"m":0.25,"m1":0.5}"#,
        r#"{"k":1.5,"m":2.25,"m1":-1.25}"#,
        r#"{"k":0.5,"m":0.3,"m1":0.7}"#,
    ] {
        assert!(serde_json::from_str::<Modulus>(bad).is_err(), "{bad}");
    }
    assert!(serde_json::from_str::<Stiffness>(r#"{"a":10,"b":-1,"c":1}"#).is_err());
    let spring = serde_json::to_string(&Spring::paper()).unwrap();
    let zero_coils = spring.replacen("\"coils\":4", "\"coils\":0", 1);
    assert_ne!(spring, zero_coils);
    assert!(serde_json::from_str::<Spring>(&zero_coils).is_err());
    // a strip width is validated on the way in too
    let strip = serde_json::to_string(&Spring::paper().with_strip_width(1e-3).unwrap()).unwrap();
    let negative = strip.replacen("0.001", "-0.001", 1);
    assert_ne!(strip, negative);
    assert!(serde_json::from_str::<Spring>(&negative).is_err());
}

#[test]
fn results_round_trip() {
    let e = Elastica::symmetric(4, 0.7).unwrap();
    assert_eq!(round_trip(&e), e);
    let spring = Spring::paper();
    assert_eq!(round_trip(&spring), spring);
    let strip = spring.with_strip_width(1e-3).unwrap();
    assert_eq!(round_trip(&strip), strip);
    let labels = response_labels();
    assert_eq!(round_trip(&labels), labels);
    // A response's curve and folds serialize; its termination carries the
    // typed error of a failed run, which is not data.
    let response = HelixModel::default().pull(&spring, 0.5).unwrap();
    assert_eq!(round_trip(response.curve()), *response.curve());
    assert_eq!(round_trip(&response.folds().to_vec()), response.folds());
    let target = hockle::Target::Extension(0.5);
    assert_eq!(round_trip(&target), target);
}

fn response_labels() -> Vec<hockle::stability::Stability> {
    HelixModel::default()
        .pull(&Spring::paper(), 3.0)
        .unwrap()
        .stability(hockle::Control::Force)
}
