#!/usr/bin/env python3
"""Coefficients of F(phi|m) and E(phi|m) near m = 1 for small
eps = m1 tan^2 phi, written to src/special/near_one_coeffs.rs.

Run from the repository root:  python3 tests/data/gen_special_near_one.py
(exact rationals; the check uses mpmath, 40 digits; deterministic).

With T = tan phi, 1 - m sin^2 = cos^2 (1 + m1 T^2), so for eps = m1 T^2 < 1
    F = int_0^phi sec(t) (1 + m1 tan^2 t)^(-1/2) dt = sum_j b_j m1^j I_j,
    b_j = binom(-1/2, j),  I_j = int_0^phi sec tan^(2j),
    I_0 = asinh T = ln((1 + sin phi)/cos phi),
    I_j = (sec phi T^(2j-1) - (2j - 1) I_(j-1)) / (2j).
Unrolling the recurrence (m1^j sec T^(2j-1) = eps^j / sin phi):
    F = A(m1) I_0 + (1/sin phi) sum_{i>=1} eps^i Q_i(m1),
    A(m1) = sum_j ((1/2)_j / j!)^2 m1^j   (= 2K(m1)/pi),
    Q_i(m1) = sum_{k>=0} b_{i+k} g_{i+k,i} m1^k,
    g_{j,i} = 1/(2i) prod_{l=i+1..j} (-(2l-1)/(2l)).
Used for eps <= 1/64 and T >= 2 (so m1 = eps/T^2 <= 1/256): A to m1^8, Q_i
to m1^(8-i), i = 1..8.  The script checks the truncated sum against mpmath's
ellipf at the corners of that region and inside it: relative error below
2^-56 (the double coefficients add their own rounding, ~1e-17 of the
corrections, which are themselves <= 1/64 of F).

E the same way: 1 - m sin^2 = cos^2 (1 + m1 T^2), so
    E = int_0^phi cos t (1 + m1 tan^2 t)^(1/2) dt = sum_j c_j m1^j L_j,
    c_j = binom(1/2, j),  L_j = int_0^phi cos tan^(2j),
    L_0 = sin phi,  L_j = I_(j-1) - L_(j-1)   (cos tan^2j = tan^(2j-2)(sec - cos)).
Collected over the basis {I_0, sin phi, eps^i / sin phi} (exact rationals):
    E = alpha(m1) I_0 + beta(m1) sin phi + (m1 / sin phi) sum_{i>=1} eps^i R_i(m1),
truncated at total order 8 in (m1, eps) and checked against mpmath's ellipe
like F.
"""
from fractions import Fraction as Fr

from mpmath import mp, mpf, ellipf, ellipe, sin, cos, atan, log

mp.dps = 40
NI = 8


def b(j):
    r = Fr(1)
    for l in range(1, j + 1):
        r *= Fr(-(2 * l - 1), 2 * l)
    return r


def g(j, i):
    r = Fr(1, 2 * i)
    for l in range(i + 1, j + 1):
        r *= Fr(-(2 * l - 1), 2 * l)
    return r


A = [b(j) * b(j) for j in range(NI + 1)]
Q = [[b(i + k) * g(i + k, i) for k in range(NI + 1 - i)] for i in range(1, NI + 1)]


def mp_of(x):
    return mpf(x.numerator) / x.denominator


def f_series(phi, mc):
    s, c = sin(phi), cos(phi)
    eps = mc * (s / c) ** 2
    a = sum(mp_of(x) * mc ** j for j, x in enumerate(A))
    corr = sum(eps ** (i + 1) * sum(mp_of(x) * mc ** k for k, x in enumerate(row))
               for i, row in enumerate(Q))
    return a * log((1 + s) / c) + corr / s


def check(series, reference):
    """The worst relative truncation of `series` against mpmath's
    `reference` over tan phi in [2, 1e8] and eps = m1 tan^2 phi in
    [1e-10, 1/64]."""
    worst = mpf(0)
    for t in [mpf(2), mpf(3), mpf(10), mpf(100), mpf(10) ** 4, mpf(10) ** 8]:
        phi = atan(t)
        for eps in [mpf(1) / 64, mpf(1) / 200, mpf(10) ** -4, mpf(10) ** -10]:
            mc = eps / t ** 2
            ref = reference(phi, 1 - mc)
            worst = max(worst, abs(series(phi, mc) / ref - 1))
    assert worst < mpf(2) ** -56, worst
    return worst


def e_forms(order=8, nj=10):
    """(alpha, beta, [R_1, R_2, ...]) as coefficient lists in m1."""
    def add(a, b, scale=Fr(1), shift=0):
        out = {k: dict(v) for k, v in a.items()}
        for k, p in b.items():
            q = out.setdefault(k, {})
            for pw, cf in p.items():
                q[pw + shift] = q.get(pw + shift, Fr(0)) + scale * cf
        return out

    def c(j):
        r = Fr(1)
        for l in range(j):
            r *= (Fr(1, 2) - l) / (l + 1)
        return r
    n = [{"I0": {0: Fr(1)}}]
    m = [{"S": {0: Fr(1)}}]
    for j in range(1, nj + 1):
        # m1^j I_j = (eps^j/s - (2j - 1) m1 m1^(j-1) I_(j-1)) / (2j)
        n.append(add({j: {0: Fr(1, 2 * j)}}, n[j - 1], scale=Fr(-(2 * j - 1), 2 * j), shift=1))
        # m1^j L_j = m1 (m1^(j-1) I_(j-1)) - m1 (m1^(j-1) L_(j-1))
        m.append(add(add({}, n[j - 1], shift=1), m[j - 1], scale=Fr(-1), shift=1))
    e = {}
    for j in range(nj + 1):
        e = add(e, m[j], scale=c(j))

    def dense(poly, cap):
        return [poly.get(p, Fr(0)) for p in range(cap + 1)]
    alpha = dense(e["I0"], order)
    beta = dense(e["S"], order)
    rs = []
    for i in range(1, order):
        # eps^i m1^p with p + i <= order, p >= 1: R_i = sum_p coef m1^(p-1)
        rs.append(dense({p - 1: v for p, v in e[i].items() if p >= 1}, order - i - 1))
        assert e[i].get(0, 0) == 0
    return alpha, beta, rs


ALPHA, BETA, R = e_forms()


def e_series(phi, mc):
    s, c = sin(phi), cos(phi)
    eps = mc * (s / c) ** 2
    ev = lambda row: sum(mp_of(x) * mc ** k for k, x in enumerate(row))
    corr = sum(eps ** (i + 1) * ev(row) for i, row in enumerate(R))
    return ev(ALPHA) * log((1 + s) / c) + ev(BETA) * s + mc * corr / s


def lit(x):
    return repr(float(x))


def main():
    worst = check(f_series, ellipf)
    worst_e = check(e_series, ellipe)
    out = ["// Generated by tests/data/gen_special_near_one.py -- do not edit.\n",
           "//! F(phi|m) and E(phi|m) for small m1 tan^2 phi: the coefficients of\n",
           "//! A(m1), Q_i(m1) (F) and alpha(m1), beta(m1), R_i(m1) (E), coefficient of\n",
           "//! m1^0 first (crate-private; derivation in the generator).\n",
           "//! Truncation checked against mpmath: relative %.1e (F), %.1e (E).\n\n"
           % (float(worst), float(worst_e)),
           "/// A(m1) = sum ((1/2)_j / j!)^2 m1^j, coefficient of m1^0 first.\n",
           "pub(crate) const A: [f64; %d] = [%s];\n\n" % (len(A), ", ".join(lit(x) for x in A)),
           "/// Q_1 .. Q_%d (coefficient of m1^0 first).\n" % NI]
    for i, row in enumerate(Q):
        out.append("pub(crate) const Q%d: [f64; %d] = [%s];\n" % (i + 1, len(row), ", ".join(lit(x) for x in row)))
    out.append("\n/// E: alpha(m1), the coefficient of asinh(tan phi).\n")
    out.append("pub(crate) const ALPHA: [f64; %d] = [%s];\n" % (len(ALPHA), ", ".join(lit(x) for x in ALPHA)))
    out.append("/// E: beta(m1), the coefficient of sin phi.\n")
    out.append("pub(crate) const BETA: [f64; %d] = [%s];\n" % (len(BETA), ", ".join(lit(x) for x in BETA)))
    out.append("/// E: R_1 .. R_%d.\n" % len(R))
    for i, row in enumerate(R):
        out.append("pub(crate) const R%d: [f64; %d] = [%s];\n" % (i + 1, len(row), ", ".join(lit(x) for x in row)))
    with open("src/special/near_one_coeffs.rs", "w") as f:
        f.write("".join(out))


if __name__ == "__main__":
    main()
