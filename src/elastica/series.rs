//! Small-k expansions of the branches through the ring (eq9–eq12) and the
//! linear responses, with the coefficients derived again (k is the modulus,
//! forces are physical tensions, half the paper's F).
//!
//! Each function is the truncated series; the error is O(k⁸) for all of
//! them (the first omitted power), and the expansion parameter is really πnk,
//! so use them for k ≲ 0.1/n. `tests/elastica` checks every one by a
//! property test over n ∈ 1..=10: the residual against the exact branch
//! divided by k⁸ stays bounded as k → 0 (a wrong coefficient of k⁶ makes it
//! grow like 1/k²).
//!
//! # Derivation and the paper's misprints
//!
//! With t the end's distance from the curvature extremum (Ω = 2(nK ∓ t)),
//! eq7 and eq8 were expanded in m = k² at 90 digits with mpmath
//! (`tests/data/gen_elastica.py`, table `elastica_series_fit.csv`: a
//! degree-9 fit in m on m ∈ [1e-6, 1e-5]), for n = 1, 2, 3, and the
//! coefficients identified as a + b π²n²:
//!
//! | quantity | printed | derived |
//! |---|---|---|
//! | υ: Ω | πn + π³n³k⁶/128 | same ✓ |
//! | υ: F | (2)π²n²k² + O(k⁸) | same ✓ (physical π²n²k²) |
//! | υ: Δz, k⁶ (eq9) | 1225/8192 − π²n²/96 | **175/1024** − π²n²/96 (fit: 0.1708984375 + 0.102808379·(1 − n²)) |
//! | α: Ω | πn(1 + k²/2 + 3k⁴/8 + (40 − π²n²)k⁶/128) | same ✓ |
//! | α: F | (2)π²n²k²(1 + k² + k⁴) | same ✓ |
//! | α: Δz, k⁶ (eq10) | 457/8192 − π²n²/96 | **79/1024** − π²n²/96 (fit: 0.0771484375 at n = 1 after adding π²/96) |
//! | ϑ_n: Δz (eq11) | k²(1/8 + k²/16 + 41k⁴/1024) | same ✓ (next: 59/2048 k⁸) |
//! | ϑ_n: F (eq12) | π²n²k²(2 + k² + 11k⁴/16) | same ✓ in the paper's F; physical is half |
//! | linear | F = 16π²n²Δz/3 and 16π²n²Δz | same in the paper's F; physical 8π²n²/3 and 8π²n² |
//!
//! So the two k⁶ coefficients of the extension (eq9, eq10) are misprinted;
//! everything else agrees once the paper's F is read as twice the tension.
//! The ratio 3 between the non-symmetric and the symmetric linear response
//! holds as the paper states.

use core::f64::consts::PI;

fn pn(n: u32) -> f64 {
    PI * f64::from(n)
}

/// Ω on the primary υ-branch: πn + π³n³k⁶/128 + O(k⁸).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let k = 0.02;
/// let exact = Elastica::symmetric(1, k)?.upsilon.omega();
/// assert!((series::upsilon_omega(1, k) - exact).abs() < 1e-13);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn upsilon_omega(n: u32, k: f64) -> f64 {
    pn(n) + upsilon_omega_excess(n, k)
}

/// Ω − πn on the primary υ-branch, π³n³k⁶/128 + O(k⁸) (compare with
/// [`Elastica::omega_excess`](super::Elastica::omega_excess), not with Ω − πn
/// formed by subtraction).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let (n, k) = (3, 0.01);
/// let e = Elastica::symmetric(n, k)?.upsilon;
/// // relative error O(k²)·(πn)²/… of a tiny quantity: 1e-3 here
/// assert!((series::upsilon_omega_excess(n, k) / e.omega_excess() - 1.0).abs() < 1e-3);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn upsilon_omega_excess(n: u32, k: f64) -> f64 {
    let p = pn(n);
    p * p * p * k.powi(6) / 128.0
}

/// Physical tension on the primary υ-branch: π²n²k² + O(k⁸) (the k⁴ and k⁶
/// terms vanish; the paper's F is twice this).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::symmetric(2, 0.01)?.upsilon;
/// assert!((series::upsilon_force(2, 0.01) / e.force() - 1.0).abs() < 1e-12);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn upsilon_force(n: u32, k: f64) -> f64 {
    let p = pn(n);
    p * p * k * k
}

/// Extension on the primary υ-branch (eq9 corrected):
///
/// ```text
/// Δz = 3k²/8 + 15k⁴/64 + (175/1024 − π²n²/96) k⁶ + O(k⁸)
/// ```
///
/// The paper prints 1225/8192 for 175/1024 = 1400/8192.
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::symmetric(2, 0.02)?.upsilon;
/// // error O(k⁸) relative to Δz = O(k²): ~1e-10 here
/// assert!((series::upsilon_extension(2, 0.02) / e.extension() - 1.0).abs() < 1e-9);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn upsilon_extension(n: u32, k: f64) -> f64 {
    let p = pn(n);
    let m = k * k;
    m * (3.0 / 8.0 + m * (15.0 / 64.0 + m * (175.0 / 1024.0 - p * p / 96.0)))
}

/// Ω on the primary α-branch: πn(1 + k²/2 + 3k⁴/8 + (40 − π²n²)k⁶/128) + O(k⁸).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::symmetric(2, 0.02)?.alpha;
/// assert!((series::alpha_omega(2, 0.02) - e.omega()).abs() < 1e-12);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn alpha_omega(n: u32, k: f64) -> f64 {
    pn(n) + alpha_omega_excess(n, k)
}

/// Ω − πn on the primary α-branch: πn(k²/2 + 3k⁴/8 + (40 − π²n²)k⁶/128) + O(k⁸).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::symmetric(2, 0.02)?.alpha;
/// assert!((series::alpha_omega_excess(2, 0.02) / e.omega_excess() - 1.0).abs() < 1e-9);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn alpha_omega_excess(n: u32, k: f64) -> f64 {
    let p = pn(n);
    let m = k * k;
    p * m * (0.5 + m * (3.0 / 8.0 + m * (40.0 - p * p) / 128.0))
}

/// Physical tension on the primary α-branch: π²n²k²(1 + k² + k⁴) + O(k⁸).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::symmetric(2, 0.02)?.alpha;
/// assert!((series::alpha_force(2, 0.02) / e.force() - 1.0).abs() < 1e-9);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn alpha_force(n: u32, k: f64) -> f64 {
    let p = pn(n);
    let m = k * k;
    p * p * m * (1.0 + m * (1.0 + m))
}

/// Extension on the primary α-branch (eq10 corrected):
///
/// ```text
/// Δz = 3k²/8 + 9k⁴/64 + (79/1024 − π²n²/96) k⁶ + O(k⁸)
/// ```
///
/// The paper prints 457/8192 for 79/1024 = 632/8192.
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::symmetric(2, 0.02)?.alpha;
/// assert!((series::alpha_extension(2, 0.02) / e.extension() - 1.0).abs() < 1e-9);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn alpha_extension(n: u32, k: f64) -> f64 {
    let p = pn(n);
    let m = k * k;
    m * (3.0 / 8.0 + m * (9.0 / 64.0 + m * (79.0 / 1024.0 - p * p / 96.0)))
}

/// Extension of the ϑ-branches (eq11; independent of n and j):
/// Δz = k²(1/8 + k²/16 + 41k⁴/1024) + O(k⁸).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::nonsymmetric(5, 5, 0.05)?[0];
/// // relative error ≈ 0.23 k⁶ ≈ 4e-9
/// assert!((series::theta_extension(0.05) / e.extension() - 1.0).abs() < 1e-7);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn theta_extension(k: f64) -> f64 {
    let m = k * k;
    m * (1.0 / 8.0 + m * (1.0 / 16.0 + m * 41.0 / 1024.0))
}

/// Physical tension on ϑ_n (j = n, eq12 halved):
/// F = π²n²k²(1 + k²/2 + 11k⁴/32) + O(k⁸).
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::nonsymmetric(5, 5, 0.05)?[0];
/// assert!((series::theta_force(5, 0.05) / e.force() - 1.0).abs() < 1e-7);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn theta_force(n: u32, k: f64) -> f64 {
    let p = pn(n);
    let m = k * k;
    p * p * m * (1.0 + m * (0.5 + m * 11.0 / 32.0))
}

/// Linear response dF/dΔz at the ring of both primary symmetric branches:
/// 8π²n²/3 (physical; the paper's 16π²n²/3 is in its doubled F).
///
/// ```
/// use hockle::elastica::series;
/// assert_eq!(series::nonsymmetric_stiffness(2), 3.0 * series::symmetric_stiffness(2));
/// ```
#[must_use]
pub fn symmetric_stiffness(n: u32) -> f64 {
    let p = pn(n);
    8.0 * p * p / 3.0
}

/// Linear response dF/dΔz at the ring of ϑ_n: 8π²n², three times
/// [`symmetric_stiffness`].
///
/// ```
/// use hockle::elastica::{Elastica, series};
/// let e = Elastica::nonsymmetric(1, 1, 1e-4)?[0];
/// assert!((e.force() / e.extension() / series::nonsymmetric_stiffness(1) - 1.0).abs() < 1e-7);
/// # Ok::<(), hockle::Error>(())
/// ```
#[must_use]
pub fn nonsymmetric_stiffness(n: u32) -> f64 {
    let p = pn(n);
    8.0 * p * p
}
