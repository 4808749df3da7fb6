#!/usr/bin/env python3
"""Reference tables for the `special` test suite, from mpmath (>= 40 digits).

Run from the repository root:  python3 tests/data/gen_special.py
Deterministic (fixed seed); rewrites tests/data/special_*.tsv.

`--seed S --out DIR/` writes the same kinds of tables from other random
points (the grids stay) into DIR, to check the code on points it was not
tuned on: copy them over tests/data/ and run `cargo test --release --test
special -- --nocapture` (docs/ACCURACY.md, "Fresh points").

Every input is a double written with repr() (it parses back exactly); the
modulus is given either as m ("m" rows) or as m1 = 1 - m ("c" rows), exactly
as the test builds it (Modulus::from_m / Modulus::from_complement), and the
reference is evaluated at that exact value with enough working precision
that m = 1 - m1 is exact (m1 down to 1e-300 needs ~340 digits).  Each
reference value v is stored as two doubles hi = fl(v), lo = fl(v - hi), so
that the test measures errors well below one ulp.

Besides the broad sets (2000 random moduli, |phi| <= 100, |u| <= 1e4), three
dense sets cover the corner near m = 1 (issue 9), appended to the same files
with their own seeds: m1 log-uniform in [1e-14, 1e-2] for K and E; m1 in
[1e-12, 1e-3] with phi up to 40 and any modulus with 10 pi <= |phi| <= 1e4
for F and E(phi); m1 in [1e-12, 1e-3] with u/K uniform in [1/2, 4] (and a
grid of u/K in steps of 1/8) for the Jacobi functions.

Independent checks run here, not in the code under test: F(am u) = u for
every Jacobi row (mpmath's ellipf is Carlson-based, its ellipfun is theta
based), dn^2 + m sn^2 = 1, and E(am u) against 2jE + E(r).
"""
import math
import random
import sys
from mpmath import mp, mpf, ellipk, ellipe, ellipf, ellipfun, atan2, pi, floor, nint

SEED = 20260122
N_RANDOM = 2000
GRID_M = [0.0, 1e-300, 1e-20, 1e-10, 0.5, 0.9, 0.99]
GRID_C = [1e-5, 1e-10, 1e-15, 2.0**-52, 1e-300]
OUT = "tests/data/"


def setprec(kind, x):
    """Working precision so that m and m1 are both exact and 40+ digits remain."""
    extra = 0
    if kind == "c" and x > 0:
        extra = int(-math.log10(x)) + 1
    mp.dps = 50 + extra


def mod(kind, x):
    x = mpf(x)
    if kind == "m":
        return x, 1 - x
    return 1 - x, x


def hl(v):
    """A reference value as (hi, lo) doubles, written with repr."""
    if v == mp.inf:
        return "inf\t0.0"
    hi = float(v)
    lo = float(v - mpf(hi))
    return f"{hi!r}\t{lo!r}"


def loguniform(rng, lo, hi):
    return 10.0 ** rng.uniform(math.log10(lo), math.log10(hi))


def moduli(rng):
    """Grid moduli, then N_RANDOM random ones: half log-uniform m, half m1."""
    out = [("m", x) for x in GRID_M] + [("c", x) for x in GRID_C]
    rand = []
    for i in range(N_RANDOM):
        if i % 2 == 0:
            rand.append(("m", loguniform(rng, 1e-20, 1.0)))
        else:
            rand.append(("c", loguniform(rng, 1e-300, 1.0)))
    return out, rand


def complete(rng):
    grid, rand = moduli(rng)
    rows = []
    for kind, x in grid + rand:
        setprec(kind, x)
        m, _ = mod(kind, x)
        rows.append(f"{kind}\t{x!r}\t{hl(ellipk(m))}\t{hl(ellipe(m))}")
    return rows


def incomplete(rng):
    grid, rand = moduli(rng)
    rows = []
    grid_phi = [1e-10, 0.3, 1.0, float(math.pi / 2), 1.5707963, 2.0, 3.5, 10.0, 100.0, -0.7]
    pts = [(k, x, p) for (k, x) in grid for p in grid_phi]
    for k, x in rand:
        p = loguniform(rng, 1e-3, 100.0) * rng.choice([-1.0, 1.0])
        pts.append((k, x, p))
    for kind, x, p in pts:
        setprec(kind, x)
        m, mc = mod(kind, x)
        if mc == 0:
            continue
        phi = mpf(p)
        rows.append(f"{kind}\t{x!r}\t{p!r}\t{hl(ellipf(phi, m))}\t{hl(ellipe(phi, m))}")
    return rows


def jacobi_row(kind, x, u):
    setprec(kind, x)
    m, mc = mod(kind, x)
    uu = mpf(u)
    sn = ellipfun("sn", uu, m=m)
    cn = ellipfun("cn", uu, m=m)
    dn = ellipfun("dn", uu, m=m)
    kk = ellipk(m)
    # am: atan2(sn, cn) on the branch next to the secular part pi u / 2K.
    a0 = atan2(sn, cn)
    am = a0 + 2 * pi * nint((pi * uu / (2 * kk) - a0) / (2 * pi))
    # Independent checks: F(am) = u (Carlson-based ellipf vs theta-based ellipfun).
    f = ellipf(am, m) if mc != 0 else uu  # m = 1: F diverges at the precision used; closed forms
    if abs(f - uu) > mpf(10) ** (-35) * max(1, abs(uu)):
        sys.exit(f"F(am u) != u at {kind} {x!r} u={u!r}: {f} vs {uu}")
    if abs(dn**2 + m * sn**2 - 1) > mpf(10) ** (-35):
        sys.exit(f"dn^2 + m sn^2 != 1 at {kind} {x!r} u={u!r}")
    eps = ellipe(am, m)
    j = nint(am / pi)
    eps2 = 2 * j * ellipe(m) + ellipe(am - j * pi, m)
    if abs(eps - eps2) > mpf(10) ** (-35) * max(1, abs(eps)):
        sys.exit(f"E(am) quasi-periodicity check failed at {kind} {x!r} u={u!r}")
    return f"{kind}\t{x!r}\t{u!r}\t{hl(sn)}\t{hl(cn)}\t{hl(dn)}\t{hl(am)}\t{hl(eps)}"


def jacobi(rng):
    grid, rand = moduli(rng)
    rows = []
    grid_u = [1e-300, 1e-10, 0.1, 0.5, 1.0, -2.5, 10.0, 100.0, 1000.0, 1e4, -9999.5]
    for kind, x in grid + [("c", 0.0)]:
        setprec(kind, x)
        m, mc = mod(kind, x)
        us = list(grid_u)
        if mc != 0:
            kk = ellipk(m)
            us += [float(kk / 2), float(kk), float(2 * kk), float(3 * kk), float(kk) * 101.0]
        for u in us:
            rows.append(jacobi_row(kind, x, u))
    for kind, x in rand:
        u = loguniform(rng, 1e-3, 1e4) * rng.choice([-1.0, 1.0])
        rows.append(jacobi_row(kind, x, u))
    return rows


DENSE_C = (1e-12, 1e-3)


def complete_dense(rng):
    """m1 log-uniform in [1e-14, 1e-2]: the log-term region of K and E."""
    rows = []
    for _ in range(1500):
        x = loguniform(rng, 1e-14, 1e-2)
        setprec("c", x)
        m, _ = mod("c", x)
        rows.append(f"c\t{x!r}\t{hl(ellipk(m))}\t{hl(ellipe(m))}")
    return rows


def incomplete_dense(rng):
    """m1 in [1e-12, 1e-3] with phi in (0, 40], and phi beyond 10 pi
    (10 pi <= |phi| <= 1e4, log-uniform) for moduli as in `moduli`."""
    pts = []
    for _ in range(1500):
        x = loguniform(rng, *DENSE_C)
        pts.append(("c", x, rng.uniform(0.0, 40.0) * rng.choice([-1.0, 1.0])))
    for i in range(1000):
        if i % 2 == 0:
            kind, x = "m", rng.uniform(0.0, 1.0)
        else:
            kind, x = "c", loguniform(rng, 1e-300, 1.0)
        p = loguniform(rng, 10 * math.pi, 1e4) * rng.choice([-1.0, 1.0])
        pts.append((kind, x, p))
    rows = []
    for kind, x, p in pts:
        setprec(kind, x)
        m, _ = mod(kind, x)
        phi = mpf(p)
        rows.append(f"{kind}\t{x!r}\t{p!r}\t{hl(ellipf(phi, m))}\t{hl(ellipe(phi, m))}")
    return rows


def jacobi_dense(rng):
    """m1 in [1e-12, 1e-3] (log-uniform) x u/K in [1/2, 4]: 2500 random
    points, then 19 moduli (every half decade) x u/K = 1/2, 5/8, ..., 4."""
    pts = []
    for _ in range(2500):
        x = loguniform(rng, *DENSE_C)
        pts.append((x, rng.uniform(0.5, 4.0) * rng.choice([-1.0, 1.0])))
    for i in range(19):
        x = 10.0 ** (-3.0 - 0.5 * i)
        for j in range(4, 33):
            pts.append((x, j / 8.0))
    rows = []
    for x, t in pts:
        setprec("c", x)
        m, _ = mod("c", x)
        u = float(t * ellipk(m))
        rows.append(jacobi_row("c", x, u))
    return rows


def write(name, header, rows):
    with open(OUT + name, "w") as f:
        f.write(header + "\n")
        for r in rows:
            f.write(r + "\n")


def main():
    write(
        "special_complete.tsv",
        "kind\tx\tK_hi\tK_lo\tE_hi\tE_lo",
        complete(random.Random(SEED)) + complete_dense(random.Random(SEED + 3)),
    )
    write(
        "special_incomplete.tsv",
        "kind\tx\tphi\tF_hi\tF_lo\tE_hi\tE_lo",
        incomplete(random.Random(SEED + 1)) + incomplete_dense(random.Random(SEED + 4)),
    )
    write(
        "special_jacobi.tsv",
        "kind\tx\tu\tsn_hi\tsn_lo\tcn_hi\tcn_lo\tdn_hi\tdn_lo\tam_hi\tam_lo\teps_hi\teps_lo",
        jacobi(random.Random(SEED + 2)) + jacobi_dense(random.Random(SEED + 5)),
    )


def options(argv):
    """--seed S and --out DIR/ (module docs); sets SEED and OUT."""
    global SEED, OUT
    args = iter(argv)
    for a in args:
        if a == "--seed":
            SEED = int(next(args))
        elif a == "--out":
            OUT = next(args).rstrip("/") + "/"
        else:
            sys.exit(f"unknown argument {a} (--seed S, --out DIR)")


if __name__ == "__main__":
    options(sys.argv[1:])
    main()
