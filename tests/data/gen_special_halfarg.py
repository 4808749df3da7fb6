#!/usr/bin/env python3
"""Series coefficients for E(phi|m) by the half-argument transformation,
written to src/special/h_series.rs.

Run from the repository root:  python3 tests/data/gen_special_halfarg.py
(exact rationals, then mpmath at 40 digits for the truncation check;
deterministic).  The generated file is exempt from rustfmt.

E(phi|m) = sin(phi) + m1 H,  H = int_0^phi sin^2/(cos + Delta) d theta
         = (1/m1) int_0^s (sqrt(1 - m t^2)/sqrt(1 - t^2) - 1) dt,  s = sin(phi).
With sqrt(1 - m y)/sqrt(1 - y) = sum_k Q_k(m) y^k,
Q_k = sum_j a_(k-j) b_j m^j,  a_n = (1/2)_n/n!,  b_n = (-1/2)_n/n!,
and Q_k(1) = 0, so Q_k = (1 - m) R_k with R_k a polynomial of degree k-1
(partial sums of Q_k's coefficients; all positive), and
    H = s^3 sum_{k>=1} h_k(m) y^(k-1),  h_k = R_k/(2k+1),  y = s^2.
H is a `const` (not a `static`), so that a crate inlining `ellip_e_inc`
sees the coefficients and unrolls the loops over them (as a `static`
E(phi) took 55 ns in the bench instead of 42).
The series is used for y <= DELTA = 0.04 with NH = 12 terms; the first
neglected terms (the next 12, the rest being smaller by 0.04^12) are
checked below 2^-58 (1/64 ulp) of H, whose share of E = s + m1 H is <= 1, for m = 0, 0.01, ..., 1.
"""
from fractions import Fraction as Fr
import math
from math import comb

from mpmath import mp, mpf

DELTA = Fr(1, 25)
NH = 12


def coefficients(n):
    a = [Fr(comb(2 * i, i), 4**i) for i in range(n + 2)]
    b = [Fr(1)]
    for j in range(1, n + 2):
        b.append(b[-1] * (Fr(-1, 2) + j - 1) / j)
    out = []
    for k in range(1, n + 1):
        q = [a[k - j] * b[j] for j in range(k + 1)]
        assert sum(q) == 0
        r = [sum(q[: i + 1]) / (2 * k + 1) for i in range(k)]
        assert all(x > 0 for x in r)
        out.append(r)
    return out


def check_truncation():
    mp.dps = 40
    h = coefficients(NH + 12)
    y = mpf(DELTA.numerator) / DELTA.denominator
    worst = mpf(0)
    for i in range(101):
        m = mpf(i) / 100
        hk = [sum(mpf(c.numerator) / c.denominator * m**j for j, c in enumerate(p)) for p in h]
        total = sum(hk[k] * y**k for k in range(NH))
        tail = sum(hk[k] * y**k for k in range(NH, NH + 12))
        worst = max(worst, tail / total)
    assert worst < mpf(2) ** -58, worst
    return worst


def reach_table():
    """REACH[i], i = 0..63: the largest y (grid 1/2000, in [DELTA, 1/2]) at
    which the 12-term series may start for m1 in [2^e, 2^(e+1)), e = -(i+1)
    (i = 63 also for every smaller m1).  E = s + m1 H, so a relative error
    tau of H moves E by tau m1 H/E <= tau B, with
    B = min(1, 1.25 m1 ln(16/m1)) at the bucket's largest m1 (H <= H(pi/2)
    = (E - 1)/m1 < ln(16/m1)/4, and s > 0.2 wherever the series is not
    used at once); the truncation tau (terms 13..60 over terms 1..12, at
    the bucket's largest m and at m = 1) must keep tau B <= 2^-57."""
    h = [[float(c) for c in p] for p in coefficients(60)]

    def hk(m):
        return [sum(c * m**j for j, c in enumerate(p)) for p in h]

    out = []
    for i in range(64):
        e = -(i + 1)
        m1_hi = 2.0 ** (e + 1)
        b = min(1.0, 1.25 * m1_hi * math.log(16 / m1_hi))
        cs = [hk(1 - 2.0**e), hk(1.0)]
        best = float(DELTA)
        for n in range(80, 1001):
            y = n / 2000
            ok = True
            for c in cs:
                head = sum(c[k] * y**k for k in range(NH))
                tail = sum(c[k] * y**k for k in range(NH, 60))
                if tail / head * b > 2.0**-57:
                    ok = False
            if not ok:
                break
            best = y
        out.append(best)
    return out


def main():
    worst = check_truncation()
    reach = reach_table()
    rows = []
    for r in coefficients(NH):
        rows.append("    &[" + ", ".join(repr(float(x)) for x in r) + "],")
    text = (
        "//! GENERATED FILE, do not edit: `python3 tests/data/gen_special_halfarg.py`.\n"
        "//! Exempt from rustfmt (`#[rustfmt::skip]` in `mod.rs`).\n"
        "//! h_k(m), k = 1..=12: H = (E(phi|m) - sin phi)/m1 = s^3 sum h_k(m) y^(k-1), y = s^2\n"
        "//! (coefficient of m^0 first; exact rationals rounded once). Neglected\n"
        f"//! terms at y = {float(DELTA)}: <= {float(worst):.2e} of H for m in [0, 1].\n"
        "#![allow(clippy::unreadable_literal, clippy::excessive_precision)]\n\n"
        f"pub(super) const H: [&[f64]; {NH}] = [\n" + "\n".join(rows) + "\n];\n"
        "\n/// The largest sin\u00b2 at which the series may start, by the binary\n"
        "/// exponent e of m1 (index -e - 1, clamped to 0..=63): the smaller m1,\n"
        "/// the less H weighs in E = s + m1 H and the fewer terms it needs.\n"
        "pub(super) const REACH: [f64; 64] = [\n"
        + "\n".join("    " + ", ".join(repr(v) for v in reach[i:i + 8]) + "," for i in range(0, 64, 8))
        + "\n];\n"
    )
    with open("src/special/h_series.rs", "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
