"""Reference values for the bvp/continuation suites (mpmath, 40 digits).

Run: python3 tests/data/bvp_references.py
Every number is from a closed form, solved to 40 digits:
- Bratu y'' + lam e^y = 0, y(0)=y(1)=0: y = -2 ln(cosh((s-1/2) th/2)/cosh(th/4)),
  lam = th^2 / (2 cosh^2(th/4)), y'(0) = th tanh(th/4), y(1/2) = 2 ln cosh(th/4).
  The fold is d lam/d th = 0  <=>  th tanh(th/4) = 4.
- Troesch y'' = mu sinh(mu y), y(0)=0, y(1)=1: with c = y'(0),
  y = (2/mu) asinh((c/2) sc(mu x | m)), m = 1 - c^2/4; solve y(1) = 1 for c.
- Euler buckling th'' + P sin th = 0, th'(0)=th'(1)=0, first mode: amplitude
  th0 = th(0), k = sin(th0/2), P = 4 K(k)^2.
"""
import mpmath as mp

mp.mp.dps = 40


def bratu_lam(th):
    return th**2 / (2 * mp.cosh(th / 4) ** 2)


def bratu():
    th_star = mp.findroot(lambda t: t * mp.tanh(t / 4) - 4, 4.8)
    print("bratu fold lambda*   =", mp.nstr(bratu_lam(th_star), 25))
    print("bratu fold y(1/2)    =", mp.nstr(2 * mp.log(mp.cosh(th_star / 4)), 25))
    for guess in (1.0, 10.0):
        th = mp.findroot(lambda t: bratu_lam(t) - 1, guess)
        print("bratu lam=1 y'(0)    =", mp.nstr(th * mp.tanh(th / 4), 25))


def troesch(mu, c0):
    def y1(c):
        m = 1 - c**2 / 4
        sc = mp.ellipfun("sn", mu, m=m) / mp.ellipfun("cn", mu, m=m)
        return 2 / mu * mp.asinh(c / 2 * sc) - 1

    # Bisection: y(1) increases with c until sc hits its pole (K(m) = mu),
    # which happens for smaller c; beyond the pole count y(1) as +inf.
    lo, hi = mp.mpf(c0) / 2, mp.mpf(c0) * 2

    def g(c):
        m = 1 - c**2 / 4
        if mp.ellipk(m) <= mu:
            return mp.inf
        return y1(c)

    for _ in range(200):
        mid = (lo + hi) / 2
        if g(mid) > 0:
            hi = mid
        else:
            lo = mid
    c = (lo + hi) / 2
    print(f"troesch mu={mu} y'(0) =", mp.nstr(c, 25))


def euler(theta0):
    k = mp.sin(mp.mpf(theta0) / 2)
    print(f"euler theta0={theta0} P =", mp.nstr(4 * mp.ellipk(k**2) ** 2, 25))


bratu()
troesch(5, 0.0457)
troesch(10, 0.000358)
for t in (0.5, 1.0, 2.0):
    euler(t)
