//! Products of many factors without intermediate overflow or underflow.

/// x = m · 2^e with m ∈ [1, 2) (x finite and non-zero), exactly.
fn split(x: f64) -> (f64, i32) {
    // subnormals: scale into the normal range first (exact)
    let (x, bias) = if x.abs() < f64::MIN_POSITIVE {
        (x * 2f64.powi(64), -64)
    } else {
        (x, 0)
    };
    let bits = x.to_bits();
    let e = ((bits >> 52) & 0x7ff) as i32 - 1023;
    let m = f64::from_bits((bits & !(0x7ff << 52)) | (1023 << 52));
    (m, e + bias)
}

/// x · 2^e, in steps that keep every intermediate exact until the last.
fn scale2(mut x: f64, mut e: i32) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
        if x.is_infinite() {
            return x;
        }
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
        if x == 0.0 {
            return x;
        }
    }
    x * 2f64.powi(e)
}

/// Π num / Π den with the exponents carried apart from the mantissas, so the
/// only rounding is that of the mantissa products (a few ulps) and the
/// result over- or underflows only if the true value does. Any zero factor
/// gives ±0; a NaN or infinite factor gives NaN or ±∞ (the callers turn
/// those into errors).
pub(super) fn ratio(num: &[f64], den: &[f64]) -> f64 {
    if num.iter().chain(den).any(|x| !x.is_finite() || *x == 0.0) {
        let plain: f64 = num.iter().product::<f64>() / den.iter().product::<f64>();
        return plain;
    }
    let (mut m, mut e) = (1.0_f64, 0_i32);
    for &x in num {
        let (mx, ex) = split(x);
        m *= mx;
        e += ex;
    }
    for &x in den {
        let (mx, ex) = split(x);
        m /= mx;
        e -= ex;
    }
    scale2(m, e)
}

#[cfg(test)]
mod tests {
    use super::ratio;

    #[test]
    fn exact_powers_of_two_and_extremes() {
        assert_eq!(ratio(&[1e300, 1e300], &[1e300, 1e300]), 1.0);
        assert_eq!(
            ratio(&[2f64.powi(-1074)], &[2f64.powi(-1000)]),
            2f64.powi(-74)
        );
        assert!((ratio(&[1e200, 1e200], &[1e300]) / 1e100 - 1.0).abs() < 4e-16);
        assert!(ratio(&[1e200, 1e200], &[1.0]).is_infinite());
        assert_eq!(ratio(&[1e-200, 1e-200], &[1.0]), 0.0);
        assert_eq!(ratio(&[-3.0, 5.0], &[2.0]), -7.5);
    }
}
