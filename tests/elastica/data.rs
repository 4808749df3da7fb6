//! Reading the reference tables.
use hockle::special::Modulus;

/// A table row as strings.
pub fn rows(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect()
}

/// The modulus of a row given as (`kind`, `value`): "k" or "m1".
pub fn modulus(kind: &str, value: &str) -> Modulus {
    let v: f64 = value.parse().unwrap();
    match kind {
        "k" => Modulus::from_k(v).unwrap(),
        "m1" => Modulus::from_complement(v).unwrap(),
        _ => panic!("unknown modulus kind {kind}"),
    }
}

/// Parses a number.
pub fn num(s: &str) -> f64 {
    s.parse().unwrap()
}
