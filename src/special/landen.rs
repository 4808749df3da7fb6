//! sn, cn, dn near m = 1 by the ascending Landen (Gauss) transformation
//! down to the expansion about m = 1 (crate-private).

/// The largest v at which the first-order expansion about m = 1
/// ([`sncndn_hyperbolic`]) is exact to rounding for this m₁: its neglected
/// term is ~ (m₁ e^{2v}/16)², so it needs m₁ e^{2v} ≤ 2⁻²⁴, i.e.
/// v ≤ ½ ln(2⁻²⁴/m₁). Taken from the binary exponent e of m₁
/// (m₁ < 2^(e+1)) without a logarithm; subnormal m₁ take the log. Negative
/// for m₁ ≥ 2⁻²⁵.
#[inline(always)]
pub(crate) fn hyperbolic_reach(mc: f64) -> f64 {
    let e = ((mc.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    if e > -1023 {
        0.5 * core::f64::consts::LN_2 * f64::from(-25 - e)
    } else {
        0.5 * ((1.0 / (1u64 << 24) as f64) / mc).ln()
    }
}

/// (sn, cn, dn) for m₁ e^{2v} ≤ 2⁻²⁴ (DLMF 22.10.4–6):
///
/// ```text
/// sn = tanh v + ¼ m₁ (sinh v cosh v − v) sech² v
/// cn = sech v − ¼ m₁ (sinh v cosh v − v) tanh v sech v
/// dn = sech v + ¼ m₁ (sinh v cosh v + v) tanh v sech v
/// ```
#[inline(always)]
pub(crate) fn sncndn_hyperbolic(v: f64, mc: f64) -> (f64, f64, f64) {
    // One exp (and for v < ln 2 one expm1) instead of tanh, cosh and sinh:
    // t = e^{−2v} − 1, tanh v = −t/(2 + t), sech v = 2e^{−v}/(1 + e^{−2v}),
    // sinh v cosh v = −t (2 + t)/(4 e^{−2v}); no cancellation for any v ≥ 0.
    // For v ≥ ln 2, e^{−2v} = (e^{−v})² (≤ 1.5 ulp; a second exp call cost
    // ~2 ns per `jacobi` call on the bench's extreme set) and the
    // subtraction e^{−2v} − 1 is exact and passes at most
    // e^{−2v}/(1 − e^{−2v}) ≤ ⅓ of that error to t (≤ 0.5 ulp); e^{−2v}
    // alone enters only the m₁ term, ≤ 2⁻²⁴ of the result. libm's expm1
    // (old fdlibm code: replacing it took ~9 ns off the mean `jacobi` call
    // on the bench's extreme set) is needed only for smaller v.
    let ex = (-v).exp();
    let (t, e2) = if v >= core::f64::consts::LN_2 {
        let e2 = ex * ex;
        (e2 - 1.0, e2)
    } else {
        let t = (-2.0 * v).exp_m1();
        (t, ex * ex)
    };
    let th = -t / (2.0 + t);
    let sech = 2.0 * ex / (1.0 + e2);
    let sc = -t * (2.0 + t) / (4.0 * e2);
    let q = 0.25 * mc;
    let sn = th + q * (sc - v) * (sech * sech);
    let cn = sech - q * (sc - v) * th * sech;
    let dn = sech + q * (sc + v) * th * sech;
    (sn, cn, dn)
}

/// At most this many Landen steps: from m₁ ≤ [`LANDEN_MC`] four steps
/// reach m₁ < 1e-16, where the expansion about m = 1 covers v ≤ 9.
const MAX_STEPS: usize = 6;

/// Landen is used for m₁ up to this (and v ≥ [`LANDEN_MIN_V`]); above, the
/// doubling from the Maclaurin series is as accurate with fewer steps.
pub(crate) const LANDEN_MC: f64 = 0.1;
/// Below this v the doubling from the Maclaurin series takes at most four
/// steps and is the more accurate (cn, dn ≈ 1 carry no relative error there).
pub(crate) const LANDEN_MIN_V: f64 = 1.0;

/// The ascending Landen chain of a modulus: the complementary moduli
/// k′ᵢ₊₁ = (1 − kᵢ)/(1 + kᵢ) = m₁ᵢ/(1 + kᵢ)², whose m₁ᵢ₊₁ = k′ᵢ₊₁² ≈ m₁ᵢ²/16
/// falls quadratically, and the argument scale wᵢ₊₁ = wᵢ/(1 + k′ᵢ₊₁).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LandenChain {
    /// k′ of each step (first step first).
    pub kp: [f64; MAX_STEPS],
    /// 1/(1 − k′) and 1/(1 + k′) of each step.
    inv_minus: [f64; MAX_STEPS],
    inv_plus: [f64; MAX_STEPS],
    /// The number of steps taken.
    pub n: usize,
    /// m₁ after the last step.
    pub mc: f64,
    /// ∏ 1/(1 + k′ᵢ): w = v · scale.
    pub scale: f64,
}

impl LandenChain {
    /// The chain for m₁ and arguments up to `v_max`: steps until the
    /// expansion about m = 1 covers v_max·∏ 1/(1 + k′ᵢ).
    pub(crate) fn new(m: f64, mc: f64, v_max: f64) -> Self {
        let mut chain = Self {
            kp: [0.0; MAX_STEPS],
            inv_minus: [0.0; MAX_STEPS],
            inv_plus: [0.0; MAX_STEPS],
            n: 0,
            mc,
            scale: 1.0,
        };
        let mut k = m.sqrt();
        while chain.n < MAX_STEPS && v_max * chain.scale > hyperbolic_reach(chain.mc) {
            let kp = chain.mc / ((1.0 + k) * (1.0 + k));
            chain.kp[chain.n] = kp;
            chain.inv_minus[chain.n] = 1.0 / (1.0 - kp);
            chain.inv_plus[chain.n] = 1.0 / (1.0 + kp);
            chain.scale *= chain.inv_plus[chain.n];
            chain.n += 1;
            chain.mc = kp * kp;
            k = ((1.0 - kp) * (1.0 + kp)).sqrt();
        }
        chain
    }

    /// (sn, cn, dn) at v ≤ v_max (the chain's bound), v ≥ 0.
    ///
    /// With (s, c, d) at (w, kᵢ₊₁) and k′ = k′ᵢ₊₁ (DLMF 22.7.5–7, written with
    /// 1/kᵢ₊₁² = 1/((1 − k′)(1 + k′))):
    ///
    /// ```text
    /// sn(v, kᵢ) = (1 + k′) s c / d
    /// cn(v, kᵢ) = (d² − k′) / ((1 − k′) d)
    /// dn(v, kᵢ) = (d² + k′) / ((1 + k′) d)
    /// ```
    /// Once cn < 0.7, sn is taken as √((1 − cn)(1 + cn)) instead: that
    /// halves cn's small error where the product formula would sum three.
    #[inline(always)]
    pub(crate) fn eval(&self, v: f64) -> (f64, f64, f64) {
        let (mut s, mut c, mut d) = sncndn_hyperbolic(v * self.scale, self.mc);
        for i in (0..self.n).rev() {
            let kp = self.kp[i];
            let inv = 1.0 / d;
            let d2 = d * d;
            s = (1.0 + kp) * s * c * inv;
            c = (d2 - kp) * (inv * self.inv_minus[i]);
            d = (d2 + kp) * (inv * self.inv_plus[i]);
        }
        if c < 0.7 {
            s = ((1.0 - c) * (1.0 + c)).sqrt();
        }
        (s, c, d)
    }
}
