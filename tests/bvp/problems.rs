//! The classical problems (from the library, shared with the example and
//! the benches) and a reference that does not share the code under test.

pub use hockle::bvp::classic::*;

/// K(k) by the arithmetic–geometric mean: K = π / (2 AGM(1, √(1 − k²)))
/// (DLMF 19.8.5), independent of the code under test.
pub fn ellip_k_agm(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    for _ in 0..40 {
        let (an, bn) = (0.5 * (a + b), (a * b).sqrt());
        a = an;
        b = bn;
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
    }
    std::f64::consts::PI / (2.0 * a)
}
