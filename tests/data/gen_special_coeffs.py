#!/usr/bin/env python3
"""Polynomial coefficients for K(m) and E(m), written to src/special/coeffs.rs.

Run from the repository root:  python3 tests/data/gen_special_coeffs.py
(mpmath, 60 digits; deterministic).  The two generated files are exempt from
rustfmt (`#[rustfmt::skip]` on their `mod` lines in src/special/mod.rs), so
the output is committed as written: one polynomial per line.  Every coefficient is an exact Taylor
coefficient, not a fit:

* 0 <= m < 0.95: Taylor polynomials in t = m - c about the centre c of each
  interval, from the closed-form derivatives of the Gauss series
      K(m) = (pi/2) 2F1(1/2, 1/2; 1; m),  E(m) = (pi/2) 2F1(-1/2, 1/2; 1; m)
      d^j/dm^j 2F1(a, b; c; m) = (a)_j (b)_j / (c)_j  2F1(a+j, b+j; c+j; m).
* 0.95 <= m <= 1 (m1 = 1 - m <= 0.05): DLMF 19.12.1 and 19.12.2,
      K = PK(m1) + L QK(m1),  E = PE(m1) + L QE(m1),  L = -ln m1, with
      QK = 1/2 sum a_n m1^n,  PK = sum a_n d_n m1^n,
      QE = 1/4 sum b_n m1^(n+1),
      PE = 1 + 1/2 sum b_n m1^(n+1) (d_n - 1/((2n+1)(2n+2))),
      written as E = 1 + m1 (SE(m1) + L RE(m1)), SE = (PE - 1)/m1, RE = QE/m1,
      a_n = ((1/2)_n / n!)^2,  b_n = (1/2)_n (3/2)_n / ((2)_n n!),
      d_n = psi(1+n) - psi(1/2+n);
  each series (all terms positive) is re-expanded about m1 = 0.025.

The degree of each polynomial is the smallest whose neglected tail is below
2^-60 of the value over the interval.  The constant term is split into
hi + lo doubles so that it carries no rounding error.
"""
from mpmath import mp, mpf, hyp2f1, rf, factorial, pi, psi, log, ellipk, ellipe, binomial

mp.dps = 60
TOL = mpf(2) ** -60
NSER = 400  # terms of the m1 series (0.1^400: far beyond any need)


def intervals():
    """[lo, hi) pieces of [0, 0.95): width 1/80, 1/160, 1/320, 1/640, 1/1280
    on [0, .5), [.5, .7), [.7, .875), [.875, .925), [.925, .95).  (Issue 9,
    fourth pass: narrower than before, so that no K piece needs more than
    degree 8 nor E more than 7 -- fewer instructions per call.)"""
    out = []
    for lo, hi, n in [("0", "0.5", 80), ("0.5", "0.7", 160), ("0.7", "0.875", 320),
                      ("0.875", "0.925", 640), ("0.925", "0.95", 1280)]:
        a, b = mpf(lo), mpf(hi)
        for i in range(int((b - a) * n + mpf("0.5"))):
            out.append((a + mpf(i) / n, a + mpf(i + 1) / n))
    return out


def taylor_hyp(a, b, c, centre, n):
    return [pi / 2 * rf(a, j) * rf(b, j) / (rf(c, j) * factorial(j)) * hyp2f1(a + j, b + j, c + j, centre)
            for j in range(n)]


def truncate(coefs, h, value):
    """Smallest degree whose tail sum |c_j| h^j is below TOL * value."""
    for deg in range(len(coefs)):
        tail = sum(abs(coefs[j]) * h**j for j in range(deg + 1, len(coefs)))
        if tail < TOL * value:
            return coefs[: deg + 1]
    raise SystemExit("series too short")


def shift(series, c, n):
    """Taylor coefficients about c of sum series[k] x^k (first n)."""
    return [sum(series[k] * binomial(k, j) * c ** (k - j) for k in range(j, len(series))) for j in range(n)]


def fmt(x):
    return repr(float(x))


def poly_rust(centre, coefs, n):
    """A `Poly<n>`: coefficients padded with zeros to the fixed length n."""
    hi = float(coefs[0])
    lo = float(coefs[0] - mpf(hi))
    body = ", ".join(fmt(c) for c in [hi] + coefs[1:] + [0] * (n - len(coefs)))
    return f"    Poly {{ centre: {fmt(centre)}, omc: {fmt(1 - centre)}, lo: {lo!r}, a: [{body}] }},"


def main():
    out = []
    out.append("//! GENERATED FILE, do not edit: `python3 tests/data/gen_special_coeffs.py`")
    out.append("//! (mpmath, 60 digits). Exact Taylor coefficients for K(m) and E(m), see the")
    out.append("//! script's docstring. Exempt from rustfmt (`#[rustfmt::skip]` in `mod.rs`).")
    out.append("#![allow(clippy::unreadable_literal, clippy::excessive_precision)]")
    out.append("")
    out.append("use super::poly::Poly;")
    out.append("")
    ks, es = [], []
    for lo, hi in intervals():
        # The centre on the 2^-20 grid: a double with 1 - c exact, about which
        # the Taylor coefficients are exact (t = m - c then carries no
        # rounding of c; the reduction modulo 2K relies on it).
        c = mpf(round(float((lo + hi) / 2) * 2**20)) / 2**20
        h = max(c - lo, hi - c)
        kc = truncate(taylor_hyp(mpf(1) / 2, mpf(1) / 2, 1, c, 60), h, ellipk(hi))
        ec = truncate(taylor_hyp(-mpf(1) / 2, mpf(1) / 2, 1, c, 60), h, ellipe(hi))
        ks.append((c, kc))
        es.append((c, ec))
    nk = max(len(k) for _, k in ks)
    ne = max(len(e) for _, e in es)
    out.append(f"/// Fixed length of the K pieces (highest degree + 1).")
    out.append(f"pub(super) const NK: usize = {nk};")
    out.append(f"/// Fixed length of the E pieces.")
    out.append(f"pub(super) const NE: usize = {ne};")
    out.append(f"/// K on the pieces of [0, 0.95) (see `complete.rs` for the index).")
    out.append(f"pub(super) static K_PIECES: [Poly<NK>; {len(ks)}] = [")
    out += [poly_rust(c, k, nk) for c, k in ks]
    out.append("];")
    out.append(f"/// E on the same pieces.")
    out.append(f"pub(super) static E_PIECES: [Poly<NE>; {len(es)}] = [")
    out += [poly_rust(c, e, ne) for c, e in es]
    out.append("];")
    # Piece index from floor(1280 m): the pieces above, padded with the last
    # piece to 2048 entries so that the index is masked, not bounds-checked.
    lut = []
    for k, (lo, hi) in enumerate(intervals()):
        lut += [k] * int((hi - lo) * 1280 + mpf("0.5"))
    assert len(lut) == 1216 and len(intervals()) < 256
    lut += [lut[-1]] * (2048 - len(lut))
    out.append("/// Piece index of m ∈ [0, 0.95) from ⌊1280 m⌋ (padded to 2048 entries).")
    out.append(f"pub(super) static PIECE_OF: [u8; {len(lut)}] = {lut};")
    # m1 series.
    half = mpf(1) / 2
    a = [(rf(half, n) / factorial(n)) ** 2 for n in range(NSER)]
    b = [rf(half, n) * rf(3 * half, n) / (rf(2, n) * factorial(n)) for n in range(NSER)]
    d = [psi(0, 1 + n) - psi(0, half + n) for n in range(NSER)]
    qk = [a[n] / 2 for n in range(NSER)]
    pk = [a[n] * d[n] for n in range(NSER)]
    qe = [mpf(0)] + [b[n] / 4 for n in range(NSER - 1)]
    pe = [mpf(1)] + [b[n] / 2 * (d[n] - mpf(1) / ((2 * n + 1) * (2 * n + 2))) for n in range(NSER - 1)]
    # Check the series against mpmath at a few m1.
    for x in [mpf("0.1"), mpf("0.01"), mpf("1e-9")]:
        ev = lambda s: sum(s[k] * x**k for k in range(NSER))
        L = -log(x)
        assert abs(ev(pk) + L * ev(qk) - ellipk(1 - x)) < mpf(10) ** -50
        assert abs(ev(pe) + L * ev(qe) - ellipe(1 - x)) < mpf(10) ** -50
    c, h = mpf("0.025"), mpf("0.025")
    # E = 1 + m1 (SE + L RE): factor m1 out of PE - 1 and QE so that E - 1
    # keeps its relative accuracy as m1 -> 0 (QE(0) = 0 exactly).
    se = pe[2:] and [pe[k + 1] for k in range(NSER - 1)]
    re = [qe[k + 1] for k in range(NSER - 1)]
    names = {"PK": pk, "QK": qk, "SE": se, "RE": re}
    for name, s in names.items():
        coefs = truncate(shift(s, c, 60), h, mpf(1))  # PK, QK >= 1/2; E >= 1 absorbs m1 SE, m1 RE
        out.append(f"/// {name}(m1) about m1 = 0.025 (DLMF 19.12.1–2).")
        out.append(f"pub(super) static {name}: Poly<{len(coefs)}> =")
        out.append(poly_rust(c, coefs, len(coefs)).strip().rstrip(",") + ";")
    with open("src/special/coeffs.rs", "w") as f:
        f.write("\n".join(out) + "\n")




# ---------------------------------------------------------------------------
# Taylor series of Carlson's R_F and R_D about the mean (src/special/carlson_series.rs).
#
# With A the (weighted) mean and X_i = 1 - x_i/A (sum of the weights times X_i = 0),
#   prod_i (t + x_i) = (t + A)^n (1 + e2 w^2 - e3 w^3 + e4 w^4 - e5 w^5),  w = A/(t + A),
# where e_j are the elementary symmetric polynomials of the X_i (R_F: X, Y, Z;
# R_D: X, Y, Z, Z, Z).  Expanding (1 + xi)^(-1/2) and integrating term by term,
#   int_0^inf (t + A)^(-n/2 - 1) w^p dt = A^(-n/2) / (p + n/2),
# gives
#   R_F = A^(-1/2) sum C(-1/2, a+b) C(a+b, a) (-1)^b E2^a E3^b / (4a + 6b + 1)
#   R_D = A^(-3/2) sum C(-1/2, j) multinomial(j; a) (-1)^(a3+a5) 3/(2p + 3) E2^a2 E3^a3 E4^a4 E5^a5
# (j = a2+a3+a4+a5, p = 2a2+3a3+4a4+5a5), which reproduce DLMF 19.36.1-2 at low
# order.  Orders and tolerances: the truncation error was measured against
# mpmath's elliprf/elliprd over random X with max|X| <= TOL (R_F order 15,
# TOL 0.1: 1.2e-18; R_D order 10, TOL 0.035: 4.2e-18).
from fractions import Fraction
from math import comb, factorial

RF_ORDER, RD_ORDER = 15, 10


def binom_half(j):
    r = Fraction(1)
    for i in range(j):
        r *= (Fraction(-1, 2) - i) / (i + 1)
    return r


def rf_terms(order=None):
    order = RF_ORDER if order is None else order
    out = {}
    for b in range(order // 3 + 1):
        for a in range((order - 3 * b) // 2 + 1):
            if a or b:
                out[(a, b)] = binom_half(a + b) * comb(a + b, a) * (-1) ** b / Fraction(4 * a + 6 * b + 1)
    return out


def rd_terms():
    out = {}
    n = RD_ORDER
    for a5 in range(n // 5 + 1):
        for a4 in range((n - 5 * a5) // 4 + 1):
            for a3 in range((n - 5 * a5 - 4 * a4) // 3 + 1):
                for a2 in range((n - 5 * a5 - 4 * a4 - 3 * a3) // 2 + 1):
                    j = a2 + a3 + a4 + a5
                    if j == 0:
                        continue
                    p = 2 * a2 + 3 * a3 + 4 * a4 + 5 * a5
                    mult = factorial(j) // (factorial(a2) * factorial(a3) * factorial(a4) * factorial(a5))
                    out[(a2, a3, a4, a5)] = binom_half(j) * mult * (-1) ** (a3 + a5) * Fraction(3, 2 * p + 3)
    return out


def estrin(var, coefs):
    """Rust expression for sum coefs[i] var^i by Estrin's scheme (pairs
    c_i + c_{i+1} var, then powers var^2, var^4 named `{var}_2`, `{var}_4`),
    which shortens the dependency chain from len(coefs) to ~log2(len)."""
    coefs = list(coefs)
    if len(coefs) == 1:
        return repr(float(coefs[0]))
    if len(coefs) == 2:
        return f"({float(coefs[0])!r} + {var} * {float(coefs[1])!r})"
    h = 1
    while 2 * h < len(coefs):
        h *= 2
    power = var if h == 1 else f"{var}_{h}"
    return f"({estrin(var, coefs[:h])} + {power} * {estrin(var, coefs[h:])})"


def bare(expr):
    """expr without redundant outer parentheses (rustc warns on them)."""
    while expr.startswith("("):
        depth = 0
        for i, ch in enumerate(expr):
            depth += {"(": 1, ")": -1}.get(ch, 0)
            if depth == 0:
                break
        if i != len(expr) - 1:
            break
        expr = expr[1:-1]
    return expr


def tree_sum(terms):
    """Pairwise sum, so that the additions run in parallel."""
    while len(terms) > 1:
        terms = [f"({terms[i]} + {terms[i + 1]})" if i + 1 < len(terms) else terms[i] for i in range(0, len(terms), 2)]
    return terms[0]


def estrin_names(var, names):
    """Estrin's scheme over named coefficients (Rust identifiers)."""
    if len(names) == 1:
        return names[0]
    if len(names) == 2:
        return f"({names[0]} + {var} * {names[1]})"
    h = 1
    while 2 * h < len(names):
        h *= 2
    power = var if h == 1 else f"{var}_{h}"
    return f"({estrin_names(var, names[:h])} + {power} * {estrin_names(var, names[h:])})"


def carlson_rust():
    # R_F's series (rf_terms, order 15) is no longer emitted: F is computed by
    # the half-argument transformation (src/special/half_argument.rs) since
    # issue 9's fourth pass; only R_D (for ε and the derivatives) is left.
    out = [
        "//! GENERATED FILE, do not edit: `python3 tests/data/gen_special_coeffs.py`.",
        "//! Exempt from rustfmt (`#[rustfmt::skip]` in `mod.rs`).",
        f"//! Taylor series of R_D (order {RD_ORDER}) about the mean.",
        "#![allow(clippy::unreadable_literal, clippy::excessive_precision)]",
    ]
    rd = rd_terms()
    out += [
        "",
        "/// R_D(x, y, z) A^{3/2} − 1 in E2 … E5 of (X, Y, Z, Z, Z).",
        "#[inline(always)]",
        "pub(super) fn rd_series(e2: f64, e3: f64, e4: f64, e5: f64) -> f64 {",
        "    let e2_2 = e2 * e2;",
        "    let e2_4 = e2_2 * e2_2;",
    ]
    groups = sorted({k[1:] for k in rd})
    terms = []
    for g in groups:
        amax = max(k[0] for k in rd if k[1:] == g)
        coefs = [rd.get((a,) + g, Fraction(0)) for a in range(amax + 1)]
        mon = " * ".join([f"e{i + 3}" for i, p in enumerate(g) for _ in range(p)])
        poly = estrin("e2", coefs)
        terms.append(f"{mon} * {poly}" if mon else poly)
    out.append(f"    {bare(tree_sum(terms))}")
    out.append("}")
    with open("src/special/carlson_series.rs", "w") as f:
        f.write("\n".join(out) + "\n")



# ---------------------------------------------------------------------------
# Maclaurin coefficients of sn, 1 - cn, 1 - dn as exact polynomials in m
# (src/special/maclaurin_coeffs.rs), from sn' = cn dn, cn' = -sn dn,
# dn' = -m sn cn term by term (DLMF 22.13.1-3; low orders are DLMF 22.10.1-3).
# To u^21 for sn and u^22 for 1 - cn, 1 - dn: at |u| <= 1/4 the first
# neglected terms are <= 2.3e-18 relative for every m in [0, 1] (the largest
# coefficients are at m = 1, tanh and sech).
MAC_ORDER = 22


def maclaurin_polys():
    def padd(a, b):
        n = max(len(a), len(b))
        return [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)]

    def pmul(a, b):
        if not a or not b:
            return []
        r = [Fraction(0)] * (len(a) + len(b) - 1)
        for i, x in enumerate(a):
            for j, y in enumerate(b):
                r[i + j] += x * y
        return r

    def prod(A, B, k):
        r = []
        for i in range(k + 1):
            r = padd(r, pmul(A[i], B[k - i]))
        return r

    n = MAC_ORDER + 2
    S = [[] for _ in range(n + 1)]
    C = [[] for _ in range(n + 1)]
    D = [[] for _ in range(n + 1)]
    C[0], D[0] = [Fraction(1)], [Fraction(1)]
    for k in range(n):
        S[k + 1] = [x * Fraction(1, k + 1) for x in prod(C, D, k)]
        C[k + 1] = [x * Fraction(-1, k + 1) for x in prod(S, D, k)]
        D[k + 1] = [x * Fraction(-1, k + 1) for x in pmul([Fraction(0), Fraction(1)], prod(S, C, k))]
    # Checks against DLMF 22.10.1-3.
    assert S[3] == [Fraction(-1, 6), Fraction(-1, 6)]
    assert S[5] == [Fraction(1, 120), Fraction(14, 120), Fraction(1, 120)]
    assert C[4] == [Fraction(1, 24), Fraction(4, 24)]
    assert D[4] == [Fraction(0), Fraction(4, 24), Fraction(1, 24)]
    s = [S[k] for k in range(3, MAC_ORDER, 2)]
    y = [[-x for x in C[k]] for k in range(2, MAC_ORDER + 1, 2)]
    z = [[-x for x in D[k]] for k in range(2, MAC_ORDER + 1, 2)]
    return s, y, z


def maclaurin_rust():
    s, y, z = maclaurin_polys()
    out = [
        "//! GENERATED FILE, do not edit: `python3 tests/data/gen_special_coeffs.py`.",
        "//! Exempt from rustfmt (`#[rustfmt::skip]` in `mod.rs`).",
        "//! Maclaurin coefficients of sn (u^3 .. u^21), 1 - cn and 1 - dn (u^2 .. u^22) as exact",
        "//! polynomials in m (coefficient of m^0 first), from sn' = cn dn, cn' = -sn dn, dn' = -m sn cn.",
        "#![allow(clippy::unreadable_literal, clippy::excessive_precision)]",
        "",
    ]
    for name, polys in (("SN", s), ("Y", y), ("Z", z)):
        out.append(f"pub(super) static {name}: [&[f64]; {len(polys)}] = [")
        for p in polys:
            body = ", ".join(repr(float(c)) for c in p) if p else "0.0"
            out.append(f"    &[{body}],")
        out.append("];")
    with open("src/special/maclaurin_coeffs.rs", "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
    carlson_rust()
    maclaurin_rust()
