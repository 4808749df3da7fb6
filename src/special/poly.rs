//! Fixed-length polynomials with a double-double constant term
//! (crate-private).

/// p(x) = (a₀ + lo) + a₁ t + a₂ t² + … + a_{N−1} t^{N−1}, t = x − centre.
/// The constant term is split hi + lo so that it is exact to ~1e-32;
/// `a[0]` is the hi part. `omc` = 1 − centre exactly, so that t can be
/// formed from m₁ as omc − m₁.
pub(crate) struct Poly<const N: usize> {
    pub centre: f64,
    pub omc: f64,
    pub lo: f64,
    pub a: [f64; N],
}

impl<const N: usize> Poly<N> {
    /// p at the offset t, as (hi, lo): hi = fl(p) and lo the rounding
    /// error of the final addition (the rest of p − hi is O(ε |t p′|), a
    /// few 1e-18 of p on our intervals).
    #[inline(always)]
    pub fn eval_t(&self, t: f64) -> (f64, f64) {
        let a = &self.a;
        // S(t) = a₁ + a₂ t + … + a_{N−1} t^{N−2} by Estrin's scheme: Horner
        // in t² over the pairs (a_{2k+1} + a_{2k+2} t), which halves the
        // dependency chain; q = lo + t S(t).
        let t2 = t * t;
        let nb = N - 1;
        let mut p = if nb % 2 == 1 { a[N - 1] } else { 0.0 };
        let mut k = nb / 2;
        while k > 0 {
            k -= 1;
            p = p * t2 + (a[2 * k + 1] + a[2 * k + 2] * t);
        }
        let q = self.lo + t * p;
        let hi = a[0] + q;
        let lo = q - (hi - a[0]);
        (hi, lo)
    }

    /// p at the offset t, rounded once at the end: `eval_t(t).0`.
    #[inline(always)]
    pub fn eval(&self, t: f64) -> f64 {
        self.eval_t(t).0
    }
}
