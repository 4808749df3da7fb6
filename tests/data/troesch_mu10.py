"""Troesch's problem at mu = 10 in closed form (mpmath, 40 digits): the
reference of tests/continuation/tolerance.rs (Collocation::tolerance).

Run: python3 tests/data/troesch_mu10.py > tests/data/troesch_mu10.csv

y'' = mu sinh(mu y), y(0) = 0, y(1) = 1. With c = y'(0) and m = 1 - c^2/4,
y = (2/mu) asinh((c/2) sc(mu x | m)) (as in bvp_references.py; c solves
y(1) = 1 by bisection to 200 halvings), and from the first integral
y'^2 = c^2 + 4 sinh^2(mu y / 2), with y' > 0. The layer sits at x = 1, so
the table is denser there. (scipy is not installed here: no solve_bvp
comparison.)
"""
import mpmath as mp

mp.mp.dps = 40
MU = mp.mpf(10)


def y_of(c, x):
    m = 1 - c**2 / 4
    u = MU * x
    sc = mp.ellipfun("sn", u, m=m) / mp.ellipfun("cn", u, m=m)
    return 2 / MU * mp.asinh(c / 2 * sc)


def solve_c(c0):
    lo, hi = mp.mpf(c0) / 2, mp.mpf(c0) * 2

    def g(c):
        if mp.ellipk(1 - c**2 / 4) <= MU:
            return mp.inf
        return y_of(c, 1) - 1

    for _ in range(200):
        mid = (lo + hi) / 2
        if g(mid) > 0:
            hi = mid
        else:
            lo = mid
    return (lo + hi) / 2


c = solve_c(0.000358)
xs = [mp.mpf(k) / 10 for k in range(0, 9)]
xs += [mp.mpf(k) / 100 for k in range(90, 101)]
print("x,y,dy")
for x in xs:
    y = mp.mpf(0) if x == 0 else (y_of(c, x) if x < 1 else mp.mpf(1))
    dy = mp.sqrt(c**2 + 4 * mp.sinh(MU * y / 2) ** 2)
    print(f"{mp.nstr(x, 3)},{mp.nstr(y, 20)},{mp.nstr(dy, 20)}")
