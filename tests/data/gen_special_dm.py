#!/usr/bin/env python3
"""Reference tables for the derivatives in the parameter m (hockle::special::*_dm).

Run from the repository root:  python3 tests/data/gen_special_dm.py
Deterministic (fixed seed); rewrites tests/data/special_dm_*.tsv.
`--seed S --out DIR/` as in gen_special.py (fresh points into DIR).

Inputs as in gen_special.py: "m" rows give m, "c" rows give m1 = 1 - m, each
a double written with repr(); references are evaluated at that exact value
with 50 + |log10 m1| + |log10 m| digits and stored as hi, lo doubles.

The references are the classical closed forms evaluated by mpmath (whose
ellipk/ellipe/ellipf are Carlson- or AGM-based and whose ellipfun is
theta-based, independent of hockle's code):
  dK/dm    = (E - m1 K) / (2 m m1)                          DLMF 19.4.1
  dE/dm    = (E - K) / (2 m)                                DLMF 19.4.1
  dF/dm    = (E(phi) - m1 F(phi)) / (2 m m1) - sin cos / (2 m1 Delta)   DLMF 19.4.2
  dE(phi)/dm = (E(phi) - F(phi)) / (2 m)                    DLMF 19.4.2
  d am/dm  = -dn * dF/dm at phi = am u (u = F(am u | m) held fixed)
  d sn/dm  = cn d am/dm,  d cn/dm = -sn d am/dm,  d dn/dm = -(sn^2 + 2 m sn cn d am/dm) / (2 dn)
and every row is checked against mpmath's numerical differentiation
(mp.diff) of K, E, F, E(phi), sn, cn, dn, am themselves, to 1e-25 relative.

Each row also stores the condition numbers of the derivative g(x, m) in m
and in x (phi or u), |m dg/dm / g| + |x dg/dx / g|, from mp.diff of the
closed form, so that the test can normalise errors as docs/ACCURACY.md does.
"""
import math
import random
import sys
from mpmath import mp, mpf, ellipk, ellipe, ellipf, ellipfun, atan2, pi, nint, sin, cos, sqrt, diff

from gen_special import hl, loguniform, write  # same directory

SEED = 20261123


def setprec(kind, x):
    extra = 0
    if kind == "c" and x > 0:
        extra = int(-math.log10(x)) + 1
    if kind == "m" and x > 0:
        extra = int(-math.log10(x)) + 1
    mp.dps = 50 + extra


def mod(kind, x):
    x = mpf(x)
    return (x, 1 - x) if kind == "m" else (1 - x, x)


def moduli(rng, n):
    out = [("m", 1e-12), ("m", 1e-4), ("m", 0.1), ("m", 0.5), ("m", 0.9), ("c", 1e-3), ("c", 1e-8), ("c", 1e-15), ("c", 1e-100)]
    for i in range(n):
        if i % 2 == 0:
            out.append(("m", loguniform(rng, 1e-8, 1.0)))
        else:
            out.append(("c", loguniform(rng, 1e-100, 1.0)))
    return out


def d_in_m(f, m, m1):
    """df/dm by mp.diff with a step well inside (0, 1): in m1 when m1 < m."""
    if m1 < m:
        return -diff(lambda t: f(1 - t), m1, h=m1 * mpf(10) ** (-mp.dps // 3))
    return diff(f, m, h=m * mpf(10) ** (-mp.dps // 3))


def cond(g, m, m1, x=None, gx=None):
    """|m g_m / g| (+ |x g_x / g|) for the closed form g(m) (and g_x)."""
    v = g(m)
    if v == 0:
        return mpf(0)
    c = abs(m * d_in_m(g, m, m1) / v)
    if x is not None:
        c += abs(x * gx / v)
    return c


def check(name, a, b, where):
    if abs(a - b) > mpf(10) ** (-25) * max(abs(a), mpf(10) ** (-300)):
        sys.exit(f"{name}: closed form {a} vs mp.diff {b} at {where}")


def kdm(m):
    m1 = 1 - m
    return (ellipe(m) - m1 * ellipk(m)) / (2 * m * m1)


def edm(m):
    return (ellipe(m) - ellipk(m)) / (2 * m)


def complete(rng):
    rows = []
    for kind, x in moduli(rng, 300):
        setprec(kind, x)
        m, m1 = mod(kind, x)
        k, e = kdm(m), edm(m)
        check("dK/dm", k, d_in_m(ellipk, m, m1), (kind, x))
        check("dE/dm", e, d_in_m(ellipe, m, m1), (kind, x))
        ck, ce = cond(kdm, m, m1), cond(edm, m, m1)
        rows.append(f"{kind}\t{x!r}\t{hl(k)}\t{hl(e)}\t{float(ck)!r}\t{float(ce)!r}")
    return rows


def fdm(phi, m):
    m1 = 1 - m
    s, c = sin(phi), cos(phi)
    d = sqrt(c * c + m1 * s * s)
    return (ellipe(phi, m) - m1 * ellipf(phi, m)) / (2 * m * m1) - s * c / (2 * m1 * d)


def einc_dm(phi, m):
    return (ellipe(phi, m) - ellipf(phi, m)) / (2 * m)


def incomplete(rng):
    rows = []
    for kind, x in moduli(rng, 400):
        p = loguniform(rng, 1e-3, 100.0) * rng.choice([-1.0, 1.0])
        setprec(kind, x)
        m, m1 = mod(kind, x)
        phi = mpf(p)
        f, e = fdm(phi, m), einc_dm(phi, m)
        check("dF/dm", f, d_in_m(lambda t: ellipf(phi, t), m, m1), (kind, x, p))
        check("dE(phi)/dm", e, d_in_m(lambda t: ellipe(phi, t), m, m1), (kind, x, p))
        # d/dphi of the derivatives: d/dm of F' = 1/Delta and E' = Delta.
        dl = lambda t: sqrt(1 - t * sin(phi) ** 2)
        fx = d_in_m(lambda t: 1 / dl(t), m, m1)
        ex = d_in_m(dl, m, m1)
        cf = cond(lambda t: fdm(phi, t), m, m1, phi, fx)
        ce = cond(lambda t: einc_dm(phi, t), m, m1, phi, ex)
        rows.append(f"{kind}\t{x!r}\t{p!r}\t{hl(f)}\t{hl(e)}\t{float(cf)!r}\t{float(ce)!r}")
    return rows


def jac(u, m):
    sn, cn, dn = (ellipfun(f, u, m=m) for f in ("sn", "cn", "dn"))
    kk = ellipk(m)
    a0 = atan2(sn, cn)
    am = a0 + 2 * pi * nint((pi * u / (2 * kk) - a0) / (2 * pi))
    return sn, cn, dn, am


def jac_dm(u, m):
    sn, cn, dn, am = jac(u, m)
    amm = -dn * fdm(am, m)
    return (cn * amm, -sn * amm, -(sn * sn + 2 * m * sn * cn * amm) / (2 * dn), amm), (sn, cn, dn, am)


def jacobi(rng):
    pts = []
    for kind, x in moduli(rng, 500):
        pts.append((kind, x, loguniform(rng, 1e-3, 100.0) * rng.choice([-1.0, 1.0])))
    for _ in range(300):
        x = loguniform(rng, 1e-12, 1e-3)
        setprec("c", x)
        pts.append(("c", x, float(rng.uniform(0.5, 4.0) * ellipk(1 - mpf(x)))))
    rows = []
    for kind, x, u in pts:
        setprec(kind, x)
        m, m1 = mod(kind, x)
        uu = mpf(u)
        (snm, cnm, dnm, amm), (sn, cn, dn, am) = jac_dm(uu, m)
        for i, (name, v) in enumerate([("sn", snm), ("cn", cnm), ("dn", dnm)]):
            check(f"d{name}/dm", v, d_in_m(lambda t: ellipfun(name, uu, m=t), m, m1), (kind, x, u))
        check("dam/dm", amm, d_in_m(lambda t: jac(uu, t)[3], m, m1), (kind, x, u))
        # d/du of the derivatives = d/dm of (cn dn, -sn dn, -m sn cn, dn).
        ux = [
            d_in_m(lambda t: ellipfun("cn", uu, m=t) * ellipfun("dn", uu, m=t), m, m1),
            d_in_m(lambda t: -ellipfun("sn", uu, m=t) * ellipfun("dn", uu, m=t), m, m1),
            d_in_m(lambda t: -t * ellipfun("sn", uu, m=t) * ellipfun("cn", uu, m=t), m, m1),
            d_in_m(lambda t: ellipfun("dn", uu, m=t), m, m1),
        ]
        conds = [cond(lambda t, i=i: jac_dm(uu, t)[0][i], m, m1, uu, ux[i]) for i in range(4)]
        vals = "\t".join(hl(v) for v in (snm, cnm, dnm, amm))
        cs = "\t".join(repr(float(c)) for c in conds)
        rows.append(f"{kind}\t{x!r}\t{u!r}\t{vals}\t{cs}")
    return rows


def main():
    write("special_dm_complete.tsv", "kind\tx\tKm_hi\tKm_lo\tEm_hi\tEm_lo\tcond_Km\tcond_Em",
          complete(random.Random(SEED)))
    write("special_dm_incomplete.tsv", "kind\tx\tphi\tFm_hi\tFm_lo\tEm_hi\tEm_lo\tcond_Fm\tcond_Em",
          incomplete(random.Random(SEED + 1)))
    write("special_dm_jacobi.tsv",
          "kind\tx\tu\tsnm_hi\tsnm_lo\tcnm_hi\tcnm_lo\tdnm_hi\tdnm_lo\tamm_hi\tamm_lo\tcond_sn\tcond_cn\tcond_dn\tcond_am",
          jacobi(random.Random(SEED + 2)))


def options(argv):
    """--seed S and --out DIR/, as gen_special.py (whose `write` takes OUT)."""
    global SEED
    import gen_special
    gen_special.options(argv)
    if "--seed" in argv:
        SEED = gen_special.SEED


if __name__ == "__main__":
    options(sys.argv[1:])
    main()
