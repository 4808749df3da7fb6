#!/usr/bin/env python3
"""special at the extremes: m1 = 1 - m down to 5e-324, |u|, |phi| up to 1e6.

Regenerate (deterministic, a few seconds):

    python3 tests/data/gen_special_extremes.py > tests/data/special_extremes.csv

mpmath at 60 + |log10 m1| digits, so that m = 1 - m1 is exact; sn, cn, dn from
mpmath's theta-function ellipfun, F and E(phi) from its Carlson-based ellipf,
ellipe. Every argument is an exact double. Read by `examples/extremes.rs`
(the extremes table of docs/ACCURACY.md).
"""
from mpmath import mp, mpf, ellipk, ellipe, ellipf, ellipfun, log10, nstr

M1 = ["0.5", "1e-16", "1e-300", "1e-310", "1e-320", "5e-324"]
U = ["0.5", "-3", "10", "1000", "-1000000", "1000000"]
PHI = ["0.5", "1.5", "10", "1000", "-1000000", "1000000"]


def s(v):
    return nstr(v, 25, strip_zeros=False)


if __name__ == "__main__":
    print("function,m1,x,value")
    for m1s in M1:
        m1 = mpf(float(m1s))
        mp.dps = 60 + int(-log10(m1))
        m = 1 - m1
        print(f"K,{m1s},,{s(ellipk(m))}")
        print(f"E,{m1s},,{s(ellipe(m))}")
        for us in U:
            u = mpf(float(us))
            for f in ("sn", "cn", "dn"):
                print(f"{f},{m1s},{us},{s(ellipfun(f, u, m=m))}")
        for ps in PHI:
            phi = mpf(float(ps))
            print(f"F,{m1s},{ps},{s(ellipf(phi, m))}")
            print(f"Ephi,{m1s},{ps},{s(ellipe(phi, m))}")
