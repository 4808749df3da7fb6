//! Jacobi elliptic functions and elliptic integrals.
//!
//! Everything takes a [`Modulus`], which holds the modulus k, the parameter
//! m = k² and the complementary parameter m₁ = 1 − m exactly: the functions
//! read m₁ from it and never form 1 − m, so k → 1 (m₁ down to 1e-300 and
//! below) loses nothing. **k or m:** DLMF writes K(k), sn(u, k); SciPy,
//! Boost's `*_m` and the `ellip` crate take m = k². Build the `Modulus` with
//! the constructor that matches your formula.
//!
//! | function | math | DLMF |
//! |---|---|---|
//! | [`ellip_k`], [`ellip_e`] | complete integrals K(k), E(k) | 19.2.8 |
//! | [`ellip_f`], [`ellip_e_inc`] | incomplete F(φ, k), E(φ, k), any real φ | 19.2.4, 19.2.5 |
//! | [`jacobi`] | sn, cn, dn and the amplitude am (continuous), plus the quotients | 22.2, 22.16.1 |
//! | [`jacobi_epsilon`] | ε(u) = ∫0^u dn² = E(am u, k), the paper's E(u, k) in eq5 | 22.16.14 |
//! | [`jacobi_zeta`] | Z(u) = ε(u) − uE/K | 22.16.32 |
//! | [`FixedModulus`] | sn, cn, dn, am, ε (and their m-derivatives) at many u, one modulus | – |
//! | [`ellip_k_dm`], [`ellip_e_dm`] | dK/dm, dE/dm | 19.4.1 |
//! | [`ellip_f_dm`], [`ellip_e_inc_dm`] | ∂F(φ\|m)/∂m, ∂E(φ\|m)/∂m | 19.4.2 |
//! | [`jacobi_dm`] | ∂sn/∂m, ∂cn/∂m, ∂dn/∂m, ∂am/∂m at fixed u | 19.4.2, 22.16.1 |
//!
//! K′ = K(k′) is `ellip_k(modulus.complementary())`.
//!
//! # Methods, and why
//! - **K, E**: exact Taylor polynomials (degree ≤ 8 for K, ≤ 7 for E)
//!   about the centres (doubles with 1 − centre exact) of 192 pieces of
//!   [0, 0.95) (widths 1/80 down to 1/1280 as m nears 1; found from
//!   ⌊1280 m⌋ through a table), with the constant term in double-double,
//!   the offset t = (1 − centre) − m₁ (for m < ½ the K and E that reduce
//!   u modulo 2K, 2E take t = m − centre, exact for a modulus given by
//!   m), and for m ≥ 0.95 the logarithmic
//!   expansion K = PK(m₁) − ln m₁ · QK(m₁),
//!   E = 1 + m₁ (SE(m₁) − ln m₁ · RE(m₁)) (DLMF 19.12.1–2), every term
//!   positive. Coefficients come from the Gauss series by exact
//!   differentiation (`tests/data/gen_special_coeffs.py`, mpmath). This is
//!   Fukushima's (2009) scheme; it beats Carlson's R_F(0, m₁, 1) (measured
//!   2.2 ulp, ~45 ns) on both accuracy and speed (~7 ns), and for m ≥ ½ the
//!   offset is formed from m₁, so a modulus given by its complement is exact.
//!   Near m = 1, −ln m₁ is formed in double-double (m₁ = f·2^e,
//!   −e ln 2 exact, ln f ≤ 0.7 from libm), which took K from 1.2 to
//!   ≤ 0.74 ulp; the K that reduces u modulo 2K also carries L·QK exactly
//!   (Dekker), so 2K is right to ~1e-32.
//! - **F**: φ = jπ + r (π in three Cody–Waite parts), 1 − m sin²r formed
//!   as cos²r + m₁ sin²r, and within the last stretch before π/2
//!   (cos²r < m₁ sin²r/4) the complementary amplitude ψ (tan ψ = cot r/k′):
//!   F = K − F(ψ), E = E − E(ψ) + m sin r sin ψ. F(r) itself by the
//!   half-argument transformation (after Fukushima 2010): F(u) = u, so
//!   u is halved through sn²(u/2) = (1 − cn)/(1 + dn) (DLMF 22.6.19–21,
//!   one division and two square roots a step) until sin² ≤ 0.07, and
//!   F = 2ⁿ F(u/2ⁿ) from a 15-term series in sin² whose coefficients
//!   P_k(m)/(2k + 1) follow a three-term recurrence. It replaced Carlson's
//!   R_F (three square roots a duplication step; 40 → 30 ns uniform, 55 →
//!   45 ns extreme), at a small cost in accuracy (1.07 → 1.08 ulp norm. on
//!   the table, 0.93 → 1.34 on 20 000 random points: every halving rounds
//!   sin², and F inherits all of it). Near m = 1, where ε = m₁ tan²r ≤
//!   1/64 and tan r ≥ 2 (φ nearer π/2 than 1.1 but not within ~k′ of it),
//!   F and E(φ) come instead from the binomial series of
//!   (1 + m₁ tan²θ)^{∓1/2} integrated term by term: one logarithm,
//!   asinh tan r = ln((1 + sin r)/cos r), plus O(m₁) corrections in ε and
//!   m₁ (`tests/data/gen_special_near_one.py`), in place of four to six
//!   halvings (extreme set: F 47 → 36 ns, E(φ) 50 → 37 ns; issue 9, fifth
//!   pass). sin r, cos r come from fdlibm's
//!   polynomial kernels inline (≤ 0.81 ulp) rather than two libm calls,
//!   which alone took ~15 of ~40 ns in `ellip_f`.
//! - **E(φ)**: the same reduction and fold, then E(r) = sin r + m₁ H(r),
//!   H = ∫0^r sin²θ/(cos θ + Δ) dθ ≥ 0, by the half-argument
//!   transformation (after Fukushima 2011): u = F(r) is halved through
//!   sn²(u/2) = (1 − cn)/(1 + dn) (DLMF 22.6.19) until sin² ≤ 0.04, H
//!   taken there from its 12-term series in sin² (coefficients exact;
//!   the threshold rises to ½ as m₁ shrinks, since H weighs ≤ 1.25 m₁
//!   ln(16/m₁) in E;
//!   `tests/data/gen_special_halfarg.py`) and doubled back by
//!   H(2u) = 2H(u) + (a sum of positive terms, from DLMF 22.16.27), so no
//!   step cancels. It replaced Carlson's R_F + R_D (1.38 → 1.14 ulp norm.,
//!   58 → 41 ns uniform, 75 → 53 ns extreme).
//! - **sn, cn, dn, am**: u = 2jK + r with 2K as a double-double and exact
//!   products (|r| ≤ K); |r| > K/2 is folded by the quarter-period shift
//!   (DLMF 22.4.3) to K − |r| ∈ [0, K/2] (K − |r| formed from K's
//!   double-double), with sn = √(1 − m₁ sd²) there. On [0, K/2]:
//!   - for m₁ ≤ 0.1 and v ≥ 1, the ascending Landen (Gauss) transformation
//!     (DLMF 22.7.4–7): k′ → (1 − k)/(1 + k) = m₁/(1 + k)², so m₁ falls as
//!     ~m₁²/16 per step, until the first-order expansion about m = 1
//!     (DLMF 22.10.4–6, from e^{−v} and e^{−2v} − 1 = (e^{−v})² − 1: one
//!     `exp`, and `expm1` for v < ln 2) is exact to rounding at
//!     the scaled argument (m₁ e^{2w} ≤ 2⁻²⁴); then back up with
//!     sn = (1 + k′) s c/d, cn = (d² − k′)/((1 − k′) d),
//!     dn = (d² + k′)/((1 + k′) d) (one division per step; at most four
//!     steps), and sn = √((1 − cn)(1 + cn)) once cn < 0.7. No doubling:
//!     the doubling it replaces accumulated ~1.5 ulp per step, each
//!     doubled by the later ones, and reached 8 ulp normalised in cn and
//!     dn near m₁ ~ 1e-8 and v ~ K/2 (issue 9).
//!   - otherwise the argument is halved to ≤ 1/8, expanded in Maclaurin
//!     series (to u¹⁵; [`FixedModulus`] to u²² from ≤ 1/4, its 32
//!     m-polynomials formed once) and doubled back (at most four steps),
//!     carrying 1 − cn and 1 − dn (Fukushima's conditional duplication;
//!     on [0, K/2] they stay ≤ 0.51), every step adding positive terms,
//!     and homogeneously: sn, 1 − cn, 1 − dn are numerators over one
//!     denominator Q, so the steps need no division until the end; the
//!     number of halvings comes from the exponent of v, not a loop. For
//!     m₁ < 2⁻³⁰ (v < 1) the expansion about m = 1 replaces the series
//!     outright.
//!
//!   am = jπ + am(r), continuous, with am(r) from the quarter-period
//!   values by a branch-free atan of a ratio in [0, 1]: 2 atan(sn/(1 + cn))
//!   on [0, K/2], π/2 − atan(k′ sn s/cn s) at K − s (q = 64 n/d by one
//!   division, the node i = round q, and atan's Taylor polynomial of
//!   degree 8 about i/64 in q − i from a generated 65-node table,
//!   `tests/data/gen_special_atan.py`; 4–5 ns less than the nine nodes
//!   found by eight comparisons before), so am waits neither for the
//!   shift's division and square root nor for a branch. Descending Landen
//!   (AGM) was not used: its cn = cos φ₀ loses all digits near K/2 as
//!   m → 1. [`FixedModulus`] holds K, E, the reduction constants, the
//!   series coefficients and the Landen chain for [0, K/2], so that many u
//!   at one modulus pay for them once.
//! - **m-derivatives**: dK/dm = R_D(0, 1, m₁)/6 and dE/dm = −R_D(0, m₁, 1)/6
//!   (DLMF 19.25.1; the closed forms (E − m₁K)/(2 m m₁), (E − K)/(2m) where
//!   R_D would need many steps and they cancel little);
//!   ∂F/∂m = (sin³φ/6) R_D(cos²φ, 1, Δ²), ∂E(φ)/∂m = −(sin³φ/6)
//!   R_D(cos²φ, Δ², 1) (DLMF 19.4.2 rewritten with 19.25.9–10: no
//!   cancellation), plus 2j dK/dm or 2j dE/dm per period; at fixed u,
//!   ∂am/∂m = −dn ∂F/∂m at φ = am u (u = F(am u | m) held fixed), and
//!   ∂sn/∂m = cn ∂am/∂m, ∂cn/∂m = −sn ∂am/∂m,
//!   ∂dn/∂m = −sn (sn + 2m cn ∂am/∂m)/(2 dn).
//! - **ε**: on [0, K/2], ε = m₁u + (m m₁/3) sn³ R_D(cn², 1, dn²) + m sn cd
//!   (DLMF 19.25.9 at φ = am u, since F(am u) = u); beyond K/2,
//!   ε(K − s) = E − ε(s) + m sn s cd s (addition formula, DLMF 22.16.27),
//!   which never evaluates R_D at the underflowing cn(u)², dn(u)²; then
//!   ε(u + 2jK) = ε(u) + 2jE.
//!
//! # Accuracy
//! Measured against mpmath (50 + |log₁₀ m₁| digits) on 3512 moduli (a grid
//! of extremes: m = 0, 1e-300, 1e-20, 1e-10, 0.5, 0.9, 0.99 and
//! m₁ = 1e-5, 1e-10, 1e-15, 2⁻⁵², 1e-300, 2000 random moduli log-uniform
//! in m ∈ [1e-20, 1] or m₁ ∈ [1e-300, 1], 1500 with m₁ ∈ [1e-14, 1e-2]),
//! 4620 (φ, m) points with |φ| ≤ 1e4 (incl. fl(π/2), 1500 with
//! m₁ ∈ [1e-12, 1e-3], 1000 beyond 10π) and 5254 (u, m) points with
//! |u| ≤ 1e4 (incl. fl(K), fl(2K), 101·fl(K), and 3051 with
//! m₁ ∈ [1e-12, 1e-3], K/2 ≤ |u| ≤ 4K). Errors in ulps of the true value;
//! "norm." is the error divided by 1 + the relative condition number
//! |x f′(x)/f(x)| in φ or u, since rounding the input alone moves f by that
//! many half-ulps.
//!
//! | function | median | p99 | max | median (norm.) | p99 (norm.) | max (norm.) |
//! |---|---|---|---|---|---|---|
//! | K | 0.18 | 0.59 | 0.74 | – | – | – |
//! | E | 0.14 | 0.49 | 0.50 | – | – | – |
//! | F(φ) | 0.28 | 1.31 | 3.85 | 0.17 | 0.81 | 1.08 |
//! | E(φ) | 0.21 | 0.90 | 1.53 | 0.11 | 0.58 | 1.14 |
//! | sn | 0.17 | 88 | 1.5e16 | 0.08 | 0.50 | 1.02 |
//! | cn | 0.66 | 4.6e13 | 2.4e16 | 0.05 | 0.46 | 1.16 |
//! | dn | 0.39 | 32 | 125 | 0.05 | 0.47 | 0.89 |
//! | am | 0.20 | 1.03 | 2.01 | 0.14 | 0.59 | 1.00 |
//! | ε | 0.19 | 1.05 | 1.58 | 0.12 | 0.96 | 1.58 |
//!
//! [`FixedModulus`] measures sn 0.83, cn 1.16, am 1.11. The m-derivatives (tables by
//! `python3 tests/data/gen_special_dm.py`, normalised by their condition
//! numbers in m and in φ or u): dK/dm ≤ 1.84, dE/dm ≤ 1.71 ulp;
//! ∂F/∂m ≤ 1.40, ∂E(φ)/∂m ≤ 1.35, ∂sn/∂m ≤ 1.57, ∂cn/∂m ≤ 1.68,
//! ∂dn/∂m ≤ 1.02, ∂am/∂m ≤ 1.57 ulp norm.
//!
//! The huge raw errors are at zeros of sn and cn for large u (u = 2jK
//! rounded to a double is not a zero) and are what the condition number
//! predicts; no NaN occurs. Reproduce with
//! `cargo test --release --test special -- --nocapture accuracy`
//! (tables: `python3 tests/data/gen_special.py`). `docs/ACCURACY.md` has
//! the full tables and what changed.
//!
//! # Performance
//! ns per call on the project's shared 2-core machine (x86-64 baseline, no
//! FMA), interleaved minimum over 1024 inputs, with `ellip` 1.2.3 in the
//! same passes (medians of three runs at load average 5–6, issue 9's fifth
//! pass); "extreme" is m₁ = 10^−U(0,15), φ = π/2 − 10^−U(0,8),
//! u ∈ [0, 100]:
//!
//! | function | uniform | ellip | extreme | ellip |
//! |---|---|---|---|---|
//! | K | 5.0 | 10.9 | 11.6 | 19.5 |
//! | E | 4.8 | 12.6 | 8.9 | 33.8 |
//! | F(φ) | 30.0 | 68.1 | 35.8 | 94.2 |
//! | E(φ) | 39.9 | 103.8 | 37.0 | 129.5 |
//! | jacobi | 55.4 | – | 69.2 | – |
//! | [`FixedModulus::jacobi`] (128 u per modulus) | 20.2 | – | 22.6 | – |
//!
//! Reproduce with `cargo bench --bench special -- zzzz` (the interleaved
//! and replayed minima only) or `-- --warm-up-time 1 --measurement-time 2`
//! (criterion as well); criterion's means and the history are in
//! `docs/PERFORMANCE.md`.
//!
//! # Errors
//! Only [`Modulus`] construction can fail ([`crate::Error::InvalidModulus`]);
//! the functions are total: a NaN or infinite φ or u gives NaN, K(1) = +∞.
//!
//! # References
//! - NIST DLMF, chapters 19 and 22.
//! - B. C. Carlson, *Numerical computation of real or complex elliptic
//!   integrals*, Numer. Algorithms 10 (1995) 13–26.
//! - T. Fukushima, *Fast computation of complete elliptic integrals and
//!   Jacobian elliptic functions*, Celest. Mech. Dyn. Astr. 105 (2009) 305–328;
//!   *Precise and fast computation of Jacobian elliptic functions by
//!   conditional duplication*, Numer. Math. 123 (2013) 585–605;
//!   *Precise and fast computation of a general incomplete elliptic
//!   integral of second kind by half and double argument transformations*,
//!   Math. Comp. 80 (2011) 1725–1743;
//!   *Fast computation of incomplete elliptic integral of first kind by
//!   half argument transformation*, Numer. Math. 116 (2010) 687–719.

mod amplitude;
mod carlson;
#[rustfmt::skip]
mod carlson_series;
#[rustfmt::skip]
mod atan_table;
#[rustfmt::skip]
mod coeffs;

mod complete;
mod derivatives;
mod duplication;
mod epsilon;
mod fixed;
mod half_argument;
#[rustfmt::skip]
mod h_series;
mod incomplete;
mod jacobi;
mod landen;
#[rustfmt::skip]
mod near_one_coeffs;
#[rustfmt::skip]
mod maclaurin_coeffs;
mod modulus;
mod period;
mod poly;

pub use complete::{ellip_e, ellip_k};
pub use derivatives::{JacobiDm, ellip_e_dm, ellip_e_inc_dm, ellip_f_dm, ellip_k_dm, jacobi_dm};
pub use epsilon::{jacobi_epsilon, jacobi_zeta};
pub use fixed::FixedModulus;
pub use incomplete::{ellip_e_inc, ellip_f};
pub use jacobi::{Jacobi, jacobi};
pub use modulus::Modulus;
