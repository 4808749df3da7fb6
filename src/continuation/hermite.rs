//! The interpolant of a step in the diagram's plane: the quintic Hermite
//! polynomial through the two ends' points P, slopes P' and curvatures P''
//! (d/ds, s the arclength), its error estimate, and the guards read off it.
//!
//! In τ = s/h over a step of length h, with v = h P', a = h² P'' at the
//! ends 0 and 1 and Δ = P₁ − P₀, the quintic is Σ c_k τ^k with
//!
//! ```text
//!   c₀ = P₀,  c₁ = v₀,  c₂ = a₀/2,
//!   c₃ = 10Δ − 6v₀ − 4v₁ − (3a₀ − a₁)/2,
//!   c₄ = −15Δ + 8v₀ + 7v₁ + (3a₀ − 2a₁)/2,
//!   c₅ = 6Δ − 3v₀ − 3v₁ − (a₀ − a₁)/2,
//! ```
//!
//! its fifth derivative is the constant P⁽⁵⁾ = 120 c₅ / h⁵, and its
//! interpolation error is at most h⁶ ‖P⁽⁶⁾‖ max τ³(1 − τ)³ / 6! =
//! h⁶ ‖P⁽⁶⁾‖ / 46080 (the remainder of Hermite interpolation with triple
//! nodes). The sixth derivative is estimated by the change of P⁽⁵⁾ between
//! successive steps, divided by the mean of their lengths: an estimate of
//! the same order as the error it bounds. A cubic through the points and
//! slopes alone has the error h⁴ ‖P''''‖ / 384, so that its steps shrink as
//! tol^¼ instead of tol^⅙: at a tolerance of 1e-6 the quintic takes about
//! half the steps.
//!
//! At loose tolerances ([`CUBIC_FROM`]) the steps are set by the angle
//! between tangents, not by the interpolation error, and the curvatures
//! (x'' of the branch, one refined bordered solve per point) would buy
//! nothing: there the interpolant is the cubic ([`Degree::Cubic`]: c₂, c₃
//! of the cubic Hermite basis, c₄ = c₅ = 0), its P''' = 6 c₃ / h³ stands
//! for P⁽⁵⁾ and its error is 3 h⁴ ‖ΔP'''‖∞ / (384 h̄), the estimate of the
//! cubic engine that came before the quintic.

/// The loosest tolerance at which a run interpolates by the quintic; from
/// this tolerance up, by the cubic without curvatures. (Measured on the
/// paper's spring before the quintic existed: the cubic took 134 and 139
/// steps at 1e-2 and 1e-3, as the quintic does, all set by the angle
/// between tangents, but 162 against 141 at 1e-4; docs/PERFORMANCE.md.)
pub(super) const CUBIC_FROM: f64 = 1e-3;

/// The degree of a run's step interpolant (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Degree {
    /// Through points and slopes: error ∝ h⁴.
    Cubic,
    /// Through points, slopes and curvatures: error ∝ h⁶.
    Quintic,
}

impl Degree {
    /// The degree for a run with tolerance `tol`.
    pub(super) fn for_tolerance(tol: f64) -> Self {
        if tol >= CUBIC_FROM {
            Degree::Cubic
        } else {
            Degree::Quintic
        }
    }
}

/// A point of the branch in the diagram's plane with its first two
/// derivatives along the arclength.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Jet {
    pub(super) point: [f64; 2],
    pub(super) slope: [f64; 2],
    pub(super) curvature: [f64; 2],
    /// ⟨x'', x''⟩ in the continuation's norm: the branch's squared
    /// curvature in state space (for [`length`]).
    pub(super) bend: f64,
}

/// The arclength h of a step between two points of the branch a chord
/// c = ‖x₁ − x₀‖ apart: c = h − κ² h³ / 24 + O(h⁵) with κ² = ⟨x'', x''⟩,
/// so h = c (1 + κ̄² c² / 24) to a relative O(h⁴), κ̄² the mean of the
/// ends' (their `bend`). The corrector's Δs is the projection of the chord
/// on the old tangent, short of h by a relative O(θ²) for a turn θ, which
/// would put an error of O(θ² h) into the slopes h P' of the step's
/// interpolant: more than the quintic's own error at every tolerance
/// below about 1e-5. Without curvatures (cubic jets, `bend` NaN) κ̄ c is
/// the angle `turn` between the ends' unit tangents in the continuation's
/// norm (the same to leading order: a circular arc of angle θ has
/// c = h sin(θ/2)/(θ/2) = h (1 − θ²/24 + …)).
pub(super) fn length(chord: f64, a: &Jet, b: &Jet, turn: f64) -> f64 {
    let bend = 0.5 * (a.bend + b.bend);
    let h = if bend.is_finite() {
        chord * (1.0 + bend * chord * chord / 24.0)
    } else {
        chord * (1.0 + turn * turn / 24.0)
    };
    if h.is_finite() { h } else { chord }
}

/// The coefficients c₀ … c₅ (module docs) of one axis of the step from
/// `a` to `b` of length `h`.
fn coefficients(a: &Jet, b: &Jet, h: f64, axis: usize, degree: Degree) -> [f64; 6] {
    let d = b.point[axis] - a.point[axis];
    let (v0, v1) = (h * a.slope[axis], h * b.slope[axis]);
    if degree == Degree::Cubic {
        return [
            a.point[axis],
            v0,
            3.0 * d - 2.0 * v0 - v1,
            -2.0 * d + v0 + v1,
            0.0,
            0.0,
        ];
    }
    let (a0, a1) = (h * h * a.curvature[axis], h * h * b.curvature[axis]);
    [
        a.point[axis],
        v0,
        0.5 * a0,
        10.0 * d - 6.0 * v0 - 4.0 * v1 - 0.5 * (3.0 * a0 - a1),
        -15.0 * d + 8.0 * v0 + 7.0 * v1 + 0.5 * (3.0 * a0 - 2.0 * a1),
        6.0 * d - 3.0 * v0 - 3.0 * v1 - 0.5 * (a0 - a1),
    ]
}

/// The highest derivative of the step's interpolant, per axis: P⁽⁵⁾ =
/// 120 c₅ / h⁵ of the quintic, P''' = 6 c₃ / h³ of the cubic.
pub(super) fn fifth(a: &Jet, b: &Jet, h: f64, degree: Degree) -> [f64; 2] {
    let at = |axis| match degree {
        Degree::Quintic => 120.0 * coefficients(a, b, h, axis, degree)[5] / h.powi(5),
        Degree::Cubic => 6.0 * coefficients(a, b, h, axis, degree)[3] / h.powi(3),
    };
    [at(0), at(1)]
}

/// The interpolation error estimate 3 h⁶ ‖ΔP⁽⁵⁾‖∞ / (46080 h̄) of a step
/// of length `h` whose P⁽⁵⁾ is `fifth`, next to a step of length `h_prev`
/// whose P⁽⁵⁾ was `fifth_prev` (h̄ the mean length): three times the bound
/// with the difference quotient for P⁽⁶⁾, which lags the step by half a
/// step (the factor is the cubic's, measured in `tests/rod/tolerance.rs`,
/// and checked there again for the quintic). For the cubic (`fifth` its
/// P'''): 3 h⁴ ‖ΔP'''‖∞ / (384 h̄).
pub(super) fn error(
    fifth: [f64; 2],
    fifth_prev: [f64; 2],
    h: f64,
    h_prev: f64,
    degree: Degree,
) -> f64 {
    let jump = (fifth[0] - fifth_prev[0])
        .abs()
        .max((fifth[1] - fifth_prev[1]).abs());
    let mean = 0.5 * (h + h_prev);
    match degree {
        Degree::Quintic => 3.0 * h.powi(6) * jump / (46080.0 * mean),
        Degree::Cubic => 3.0 * h.powi(4) * jump / (384.0 * mean),
    }
}

/// The step factor that brings an interpolation error `error` to `goal`
/// (error ∝ h⁶ for the quintic, h⁴ for the cubic).
pub(super) fn step_factor(error: f64, goal: f64, degree: Degree) -> f64 {
    let order = match degree {
        Degree::Quintic => 6.0,
        Degree::Cubic => 4.0,
    };
    if error > 0.0 {
        (goal / error).powf(1.0 / order)
    } else {
        f64::INFINITY
    }
}

/// The step's interpolant at τ ∈ [0, 1].
pub(super) fn at(a: &Jet, b: &Jet, h: f64, tau: f64, degree: Degree) -> [f64; 2] {
    let eval = |axis| {
        coefficients(a, b, h, axis, degree)
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * tau + c)
    };
    [eval(0), eval(1)]
}

/// The distance from the point `p` of the branch, whose slope is `t`, to
/// the interpolant's point `q`, across the branch (along `t` it is a
/// shift of the parametrisation): |(q − p) × t̂|, or the max-norm when
/// `t` vanishes.
pub(super) fn across(p: [f64; 2], t: [f64; 2], q: [f64; 2]) -> f64 {
    let d = [q[0] - p[0], q[1] - p[1]];
    let len = t[0].hypot(t[1]);
    if len > 0.0 && len.is_finite() {
        (d[0] * t[1] - d[1] * t[0]).abs() / len
    } else {
        d[0].abs().max(d[1].abs())
    }
}

/// Whether the cubic Hermite interpolant of one axis over a step, from
/// (p0, slope d0) to (p1, d1) over the length h, turns back twice inside
/// the step by more than `amplitude`: the trace of a pair of folds that
/// one step passed over (with end slopes of one sign, a cubic whose secant
/// is much flatter than its ends must wiggle).
pub(super) fn turns_back_twice(p0: f64, d0: f64, p1: f64, d1: f64, h: f64, amplitude: f64) -> bool {
    let (a, b) = (h * d0, h * d1);
    if a * b <= 0.0 {
        return false;
    }
    let c2 = 3.0 * (p1 - p0) - 2.0 * a - b;
    let c3 = 2.0 * (p0 - p1) + a + b;
    // q(τ) = a + 2 c2 τ + 3 c3 τ²: two roots in (0, 1)?
    let (qa, qb, qc) = (3.0 * c3, 2.0 * c2, a);
    if qa == 0.0 {
        return false;
    }
    let disc = qb * qb - 4.0 * qa * qc;
    if disc <= 0.0 {
        return false;
    }
    let r = disc.sqrt();
    let q = -0.5 * (qb + qb.signum() * r);
    if q == 0.0 {
        return false;
    }
    let (t1, t2) = (q / qa, qc / q);
    let inside = |t: f64| t > 0.0 && t < 1.0;
    if !(inside(t1) && inside(t2)) {
        return false;
    }
    let at = |t: f64| p0 + t * (a + t * (c2 + t * c3));
    (at(t1) - at(t2)).abs() > amplitude
}

#[cfg(test)]
mod tests {
    use super::*;

    fn jet(p: [f64; 2], slope: [f64; 2], curvature: [f64; 2]) -> Jet {
        Jet {
            point: p,
            slope,
            curvature,
            bend: 0.0,
        }
    }

    /// A quintic is reproduced exactly: P⁽⁵⁾ is its own fifth derivative,
    /// the interpolant meets it inside the step, and the error estimate
    /// between two steps on it vanishes.
    #[test]
    fn quintic_is_exact() {
        let p = |s: f64| [s.powi(5) - 2.0 * s * s, 0.5 * s * s];
        let dp = |s: f64| [5.0 * s.powi(4) - 4.0 * s, s];
        let ddp = |s: f64| [20.0 * s.powi(3) - 4.0, 1.0];
        let j = |s: f64| jet(p(s), dp(s), ddp(s));
        let f = fifth(&j(0.2), &j(0.7), 0.5, Degree::Quintic);
        // (P⁽⁵⁾ = 120 c₅/h⁵: the rounding of the c's, ~1e-15, over
        // h⁵ = 0.03, times 120, is ~1e-11; 1e-8 leaves room and still
        // tells 120 from any other fifth derivative; the interpolant
        // itself is exact to the rounding of its six terms, 1e-14)
        assert!((f[0] - 120.0).abs() < 1e-8 && f[1].abs() < 1e-8, "{f:?}");
        let mid = at(&j(0.2), &j(0.7), 0.5, 0.3, Degree::Quintic);
        let exact = p(0.35);
        assert!((mid[0] - exact[0]).abs() < 1e-14 && (mid[1] - exact[1]).abs() < 1e-14);
        let prev = fifth(&j(-0.1), &j(0.2), 0.3, Degree::Quintic);
        assert!(error(f, prev, 0.5, 0.3, Degree::Quintic) < 1e-12);
    }

    /// On sin, the estimate is above the true maximum interpolation error
    /// h⁶/46080 · max|sin⁽⁶⁾| and within a factor 6 of it.
    #[test]
    fn error_of_sine() {
        let h: f64 = 0.4;
        let j = |s: f64| jet([s.sin(), 0.0], [s.cos(), 0.0], [-s.sin(), 0.0]);
        let truth = h.powi(6) / 46080.0 * (1.0 + 1.5 * h).sin();
        check_on_sine(j, h, Degree::Quintic, truth);
    }

    /// The estimate over the second of two steps of length `h` along
    /// (sin s, 0) from s = 1 is above `truth` and within a factor 6 of it,
    /// and above the interpolant's own error, sampled.
    fn check_on_sine(j: impl Fn(f64) -> Jet, h: f64, d: Degree, truth: f64) {
        let e = error(
            fifth(&j(1.0 + h), &j(1.0 + 2.0 * h), h, d),
            fifth(&j(1.0), &j(1.0 + h), h, d),
            h,
            h,
            d,
        );
        let worst = (1..100)
            .map(|i| {
                let tau = f64::from(i) / 100.0;
                (at(&j(1.0 + h), &j(1.0 + 2.0 * h), h, tau, d)[0] - (1.0 + h * (1.0 + tau)).sin())
                    .abs()
            })
            .fold(0.0, f64::max);
        assert!(e > truth && e < 6.0 * truth, "{e} vs {truth}");
        assert!(worst < e, "{worst} vs {e}");
    }

    /// The cubic reproduces a cubic (its P''' is the cubic's own, the
    /// curvatures are not read: NaN), and the error estimate between two
    /// steps on it vanishes.
    #[test]
    fn cubic_is_exact() {
        let p = |s: f64| [s.powi(3) - 2.0 * s, 0.5 * s * s];
        let dp = |s: f64| [3.0 * s * s - 2.0, s];
        let j = |s: f64| jet(p(s), dp(s), [f64::NAN; 2]);
        let c = Degree::Cubic;
        let f = fifth(&j(0.2), &j(0.7), 0.5, c);
        // (P''' = 6 c₃/h³: the rounding of c₃, ~1e-16, over h³ = 0.125,
        // times 6, is ~1e-14; 1e-10 leaves room and tells 6 from 0)
        assert!((f[0] - 6.0).abs() < 1e-10 && f[1].abs() < 1e-10, "{f:?}");
        let mid = at(&j(0.2), &j(0.7), 0.5, 0.3, c);
        let exact = p(0.35);
        assert!((mid[0] - exact[0]).abs() < 1e-14 && (mid[1] - exact[1]).abs() < 1e-14);
        let prev = fifth(&j(-0.1), &j(0.2), 0.3, c);
        assert!(error(f, prev, 0.5, 0.3, c) < 1e-12);
    }

    /// On sin, the cubic's estimate is above the true maximum
    /// interpolation error h⁴/384 · max|sin''''| and within a factor 6 of
    /// it, and above the interpolant's sampled error.
    #[test]
    fn cubic_error_of_sine() {
        let h: f64 = 0.2;
        let j = |s: f64| jet([s.sin(), 0.0], [s.cos(), 0.0], [f64::NAN; 2]);
        let truth = h.powi(4) / 384.0 * (1.0 + 1.5 * h).sin();
        check_on_sine(j, h, Degree::Cubic, truth);
    }

    /// The step's length from the turn of the tangents where the jets
    /// carry no bend: a circular arc of radius 1 over the angle θ has the
    /// chord 2 sin(θ/2), and the length from it is θ to within 7θ⁵/5760,
    /// far below the chord's own shortfall θ³/24.
    #[test]
    fn length_from_turn() {
        let j = Jet {
            bend: f64::NAN,
            ..jet([0.0; 2], [1.0, 0.0], [f64::NAN; 2])
        };
        for theta in [0.05_f64, 0.2, 0.4] {
            let chord = 2.0 * (0.5 * theta).sin();
            let h = length(chord, &j, &j, theta);
            // (θ/(2 sin(θ/2)) − (1 + θ²/24) = 7θ⁴/5760 + O(θ⁶) relative;
            // 2e-3 θ⁵ bounds it with room for the rounding, ~1e-16)
            assert!((h - theta).abs() < 2e-3 * theta.powi(5), "{h} vs {theta}");
            assert!((chord - theta).abs() > 0.03 * theta.powi(3));
        }
    }

    /// A step over a hairpin (λ = s³ − s sampled at its ends only) is
    /// recognised; a monotone step is not.
    #[test]
    fn fold_pair_trace() {
        // λ(s) = s³ − s on [−1.2, 1.2]: slopes 3.32 at both ends, folds at ±0.577
        let (p0, p1, d) = (
            -1.2_f64.powi(3) + 1.2,
            1.2_f64.powi(3) - 1.2,
            3.0 * 1.44 - 1.0,
        );
        assert!(turns_back_twice(p0, d, p1, d, 2.4, 1e-3));
        // λ(s) = s³ + s: monotone
        assert!(!turns_back_twice(
            -1.2_f64.powi(3) - 1.2,
            5.32,
            1.2_f64.powi(3) + 1.2,
            5.32,
            2.4,
            1e-3
        ));
    }
}
