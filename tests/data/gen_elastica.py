#!/usr/bin/env python3
"""Reference tables for hockle's `elastica` and `helix` layers (mpmath, 50 digits).

Regenerate (deterministic, about a minute):

    python3 tests/data/gen_elastica.py tests/data
    python3 tests/data/gen_elastica.py tests/data --only-helix   # helix.csv alone

Everything here is derived and solved independently of the Rust code:

* the unknown Omega of the symmetric branches is a root of the paper's eq7 in
  its printed form (Omega dn(Omega/2) = pi n for even m, Omega k' nd(Omega/2) =
  pi n for odd m), bracketed and bisected at 50 digits;
* the extension is eq5 evaluated with mpmath's own incomplete E(phi|m) and a
  subset is re-checked by adaptive quadrature of z' = gamma = 1 - 2 sn^2;
* the physical tension is checked against the energy derivative dU/d(Delta z)
  by central differences at 50 digits (the paper's printed F is twice it);
* bifurcation points solve K(k) = pi n/(2j) (j < n) and K(k) k' = pi n/(2j)
  (j > n), checked against eq81 and eq7 holding at once;
* helix forces are the derivative of the helical strain energy minimised over
  the twist rate (zero axial moment), by numerical differentiation, NOT the
  Appendix's closed form.

Moduli are given either as k (column kind = "k") or, near k = 1, as the
complementary parameter m1 = 1 - k^2 (kind = "m1"); both are exact doubles.
"""
import os
import sys

from mpmath import (mp, mpf, ellipk, ellipe, ellipf, ellipfun, findroot, pi, sqrt, quad,
                    atan2, floor, diff, sin, cos, radians, asin)

mp.dps = 50
OUT = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))

K_VALUES = ["0.001", "0.01", "0.05", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7",
            "0.8", "0.85", "0.9", "0.95", "0.99"]
M1_VALUES = ["1e-3", "1e-4", "1e-6", "1e-8", "1e-12", "1e-16", "1e-20"]


def moduli():
    """(kind, double text, m) for every tabulated modulus; m from the exact double."""
    out = []
    for t in K_VALUES:
        k = mpf(float(t))
        out.append(("k", t, k * k))
    for t in M1_VALUES:
        out.append(("m1", t, 1 - mpf(float(t))))
    return out


def fmt(x):
    return mp.nstr(x, 30, min_fixed=-5, max_fixed=5) if x != 0 else "0"


def dn(u, m):
    return ellipfun('dn', u, m=m)


def am(u, m):
    """Continuous amplitude: am(u + 2K) = am(u) + pi."""
    K = ellipk(m)
    q = floor((u + K) / (2 * K))
    r = u - 2 * K * q
    return atan2(ellipfun('sn', r, m=m), ellipfun('cn', r, m=m)) + pi * q


def eps(u, m):
    """Jacobi's epsilon: int_0^u dn^2 = E(am u | m)."""
    return ellipe(am(u, m), m)


def eq7(parity, n, m):
    """Left-hand side minus right-hand side of eq7 as a function of Omega."""
    if parity == 0:
        return lambda om: om * dn(om / 2, m) - pi * n
    return lambda om: om * sqrt(1 - m) / dn(om / 2, m) - pi * n


def bisect(f, a, b, iters=200):
    fa, fb = f(a), f(b)
    if fa == 0:
        return a
    if fb == 0:
        return b
    assert fa * fb < 0, (fa, fb)
    for _ in range(iters):
        c = (a + b) / 2
        fc = f(c)
        if fc == 0 or b - a < mpf(10) ** (-mp.dps + 3) * abs(c):
            return c
        if (fc < 0) == (fa < 0):
            a, fa = c, fc
        else:
            b = c
    return (a + b) / 2


def symmetric_state(n, m, parity, om):
    """Omega, Delta z (paper sign: positive in tension), tension k^2 Omega^2, energy."""
    K = ellipk(m)
    mid = parity * K
    u1, u2 = mid - om / 2, mid + om / 2
    de = eps(u2, m) - eps(u1, m)
    dz = 2 / m - 1 - 2 * de / (m * om)
    energy = 2 * om * de - 4 * pi * n * (am(u2, m) - am(u1, m)) + 2 * pi ** 2 * n ** 2
    return dz, m * om ** 2, energy


def dz_by_quadrature(n, m, parity, om):
    """Delta z = -int_{s1}^{s2} gamma ds with gamma = 1 - 2 sn^2(Omega s) (eq4), by quadrature."""
    K = ellipk(m)
    mid = parity * K
    u1, u2 = mid - om / 2, mid + om / 2
    pts = [u1]
    x = (floor(u1 / K) + 1) * K
    while x < u2:
        pts.append(x)
        x += K
    pts.append(u2)
    g = lambda u: 1 - 2 * ellipfun('sn', u, m=m) ** 2
    return -quad(g, pts) / om


# ---------------------------------------------------------------- primary

def primary_omega(n, m, shape):
    """Root of eq7 on the branch through Omega = pi n at k = 0.

    upsilon: parity of m = parity of n, Omega in [2(n-1)K, 2nK];
    alpha:   parity of m = parity of n+1, Omega in [2nK, 2(n+1)K].
    """
    K = ellipk(m)
    if shape == "upsilon":
        parity, lo, hi = n % 2, 2 * (n - 1) * K, 2 * n * K
    else:
        parity, lo, hi = (n + 1) % 2, 2 * n * K, 2 * (n + 1) * K
    f = eq7(parity, n, m)
    om = bisect(f, lo, hi)
    return parity, om


def gen_primary():
    rows = []
    for n in range(1, 9):
        for shape in ("upsilon", "alpha"):
            for kind, text, m in moduli():
                parity, om = primary_omega(n, m, shape)
                dz, force, energy = symmetric_state(n, m, parity, om)
                rows.append([str(n), shape, kind, text, fmt(om), fmt(force), fmt(dz), fmt(energy)])
    return ["n,shape,kind,value,omega,force,extension,energy"] + [",".join(r) for r in rows]


def check_primary():
    """Independent checks: quadrature of eq4 and F = dU/d(Delta z)."""
    for n in (1, 4):
        for shape in ("upsilon", "alpha"):
            for k in (mpf("0.3"), mpf("0.9"), mpf("0.999")):
                m = k * k
                parity, om = primary_omega(n, m, shape)
                dz, force, _ = symmetric_state(n, m, parity, om)
                dzq = dz_by_quadrature(n, m, parity, om)
                assert abs(dz - dzq) < mpf(10) ** -30, (n, shape, k, dz, dzq)
                h = mpf(10) ** -12

                def state(kk):
                    p, o = primary_omega(n, kk * kk, shape)
                    return symmetric_state(n, kk * kk, p, o)
                dzp, _, up = state(k + h)
                dzm, _, um = state(k - h)
                fd = (up - um) / (dzp - dzm)
                assert abs(fd / force - 1) < mpf(10) ** -18, (n, shape, k, fd, force)


# ---------------------------------------------------------------- theta

def gen_theta():
    rows = []
    for j in range(1, 8):
        for kind, text, m in moduli():
            K, E = ellipk(m), ellipe(m)
            om = 2 * K * j
            dz = 2 / m * (1 - E / K) - 1
            rows.append([str(j), kind, text, fmt(om), fmt(m * om ** 2), fmt(dz)])
    return ["j,kind,value,omega,force,extension"] + [",".join(r) for r in rows]


def theta_roots(n, j, m):
    """Every root s1 in [0, 1/j) of eq81: pi n = 2 K j dn(2 K j s1)."""
    K = ellipk(m)
    c = pi * n / (2 * K * j)
    kp = sqrt(1 - m)
    if c > 1 or c < kp:
        return []
    phi = asin(sqrt((1 - c * c) / m))
    u0 = ellipf(phi, m)
    return [u0 / (2 * K * j), (2 * K - u0) / (2 * K * j)]


def gen_theta_roots():
    rows = []
    for n in (3, 4):
        for j in range(1, 8):
            for text in ("0.5", "0.9", "0.99", "0.999"):
                k = mpf(float(text))
                for r, s1 in enumerate(theta_roots(n, j, k * k)):
                    # check eq81 at the root
                    K = ellipk(k * k)
                    assert abs(2 * K * j * dn(2 * K * j * s1, k * k) - pi * n) < mpf(10) ** -35
                    rows.append([str(n), str(j), text, str(r), fmt(s1)])
    return ["n,j,k,root,s1"] + [",".join(r) for r in rows]


# ---------------------------------------------------------------- bifurcations, folds, secondary arms

def bifurcation_m(n, j):
    """m at which secondary branch j meets theta_j: K = pi n/(2j) (j<n), K k' = pi n/(2j) (j>n)."""
    target = pi * n / (2 * j)
    if j < n:
        f = lambda m1: ellipk(1 - m1) - target
    else:
        f = lambda m1: ellipk(1 - m1) * sqrt(m1) - target
    # bisect in m1 = 1 - m so that m near 1 keeps its relative precision
    return 1 - bisect(f, mpf(10) ** -40, mpf(1))


def secondary_setup(n, j, m):
    """(parity, h(Omega), bifurcation Omega-side data): eq7 parity m = j (j<n) or j+1 (j>n)."""
    parity = j % 2 if j < n else (j + 1) % 2
    return parity, eq7(parity, n, m)


def extremum(h, j, n, K):
    """Omega of the local extremum of h that makes the fold of secondary branch j.

    j < n: the maximum of h to the right of Omega = 2jK; j > n: the minimum to its left.
    h' is positive at both ends of the scanned interval, so scan for the sign change.
    """
    dh = lambda om: diff(h, om)
    if j < n:
        a, b, want = 2 * j * K, 2 * (j + 1) * K, -1
    else:
        a, b, want = 2 * (j - 1) * K, 2 * j * K, 1
    N = 256
    prev = dh(a)
    for i in range(1, N + 1):
        x = a + (b - a) * i / N
        cur = dh(x)
        if (want < 0 and prev > 0 and cur <= 0) or (want > 0 and prev < 0 and cur >= 0):
            return bisect(dh, a + (b - a) * (i - 1) / N, x)
        prev = cur
    return None


def secondary_fold(n, j):
    """The fold (minimum k) of secondary branch j: h = pi n and dh/dOmega = 0."""
    parity = j % 2 if j < n else (j + 1) % 2

    def crit(m):
        K = ellipk(m)
        h = eq7(parity, n, m)
        om = extremum(h, j, n, K)
        if om is None:
            # h is monotone there: no roots yet, which is the side "before the fold"
            return None, mpf(-1) if j < n else mpf(1)
        return om, h(om)

    mb = bifurcation_m(n, j)
    # at the bifurcation the extremum value is beyond pi n; at small m it is not
    g = lambda m: crit(m)[1]
    lo = mb / 4
    while (g(lo) > 0) == (g(mb) > 0):
        lo /= 4
    mf = bisect(g, lo, mb, iters=170)
    return mf, crit(mf)[0]


def secondary_omega(n, j, m, arm, om_fold):
    """Root of eq7 on one arm: 'lower' (Omega below the fold's) or 'upper'."""
    K = ellipk(m)
    parity, h = secondary_setup(n, j, m)
    # the extremum of h for this m
    omc = extremum(h, j, n, K)
    lo, hi = 2 * (j - 1) * K, 2 * (j + 1) * K
    if arm == "lower":
        return parity, bisect(h, lo, omc)
    return parity, bisect(h, omc, hi)


def gen_bifurcations():
    rows = []
    for n in range(1, 11):
        for j in range(1, 8):
            if j == n:
                continue
            m = bifurcation_m(n, j)
            K, E = ellipk(m), ellipe(m)
            om = 2 * K * j
            force = m * om ** 2
            dz = 2 / m * (1 - E / K) - 1
            # the bifurcation point also solves eq7 with the secondary parity, and its
            # extension from eq8 equals the theta one
            parity, h = secondary_setup(n, j, m)
            assert abs(h(om)) < mpf(10) ** -30, (n, j, h(om))
            dz8, f8, _ = symmetric_state(n, m, parity, om)
            assert abs(dz8 - dz) < mpf(10) ** -30, (n, j, dz8, dz)
            rows.append([str(n), str(j), fmt(sqrt(m)), fmt(1 - m), fmt(force), fmt(dz)])
    return ["n,j,k,m1,force,extension"] + [",".join(r) for r in rows]


def gen_folds_and_arms():
    n = 4
    folds = ["n,j,k,m1,omega,force,extension"]
    arms = ["n,j,arm,kind,value,omega,force,extension,energy"]
    for j in (1, 2, 3, 5, 6, 7):
        mf, omf = secondary_fold(n, j)
        parity = j % 2 if j < n else (j + 1) % 2
        dz, force, _ = symmetric_state(n, mf, parity, omf)
        folds.append(",".join([str(n), str(j), fmt(sqrt(mf)), fmt(1 - mf), fmt(omf), fmt(force), fmt(dz)]))
        kf = sqrt(mf)
        mb = bifurcation_m(n, j)
        samples = []
        for text in ("0.3", "0.5", "0.7", "0.8", "0.9", "0.95", "0.99"):
            if mpf(float(text)) > kf * (1 + mpf(10) ** -6):
                samples.append(("k", text, mpf(float(text)) ** 2))
        for text in ("1e-4", "1e-8", "1e-12", "1e-16"):
            if 1 - mpf(float(text)) > mf * (1 + mpf(10) ** -6):
                samples.append(("m1", text, 1 - mpf(float(text))))
        for arm in ("lower", "upper"):
            for kind, text, m in samples:
                parity, om = secondary_omega(n, j, m, arm, omf)
                dz, force, energy = symmetric_state(n, m, parity, om)
                arms.append(",".join([str(n), str(j), arm, kind, text, fmt(om), fmt(force), fmt(dz), fmt(energy)]))
    return folds, arms


# ---------------------------------------------------------------- helix

def helix_rows():
    """Helix under an axial force with zero axial moment (Appendix), from the energy.

    U(rho, theta) = 1/2 [B (rho sin t - kappa0)^2 + C (rho cos t - tau0)^2], rho the
    twist rate of the frame about the axis (free: zero axial moment), Delta z = cos t;
    F = dU*/d(Delta z) with U* = min over rho.
    """
    rows = ["n,theta0_deg,theta0,a_over_b,nu,theta,force,extension,radius"]
    n = 4
    nu = mpf(float("0.05"))
    for th0d in ("89.8", "89.5", "89", "88", "60"):
        # theta0 and theta are exact doubles (printed with 17 digits) so that the
        # Rust side evaluates at the very same arguments
        th0 = mpf(float(radians(mpf(float(th0d)))))
        for ab in ("10", "1", "0.1"):
            A, B = mpf(float(ab)), mpf(1)
            C = 2 * A * B / ((1 + nu) * (A + B))
            rho0 = 2 * pi * n
            k0, t0 = rho0 * sin(th0), rho0 * cos(th0)

            def ustar(t):
                dU = lambda r: B * (r * sin(t) - k0) * sin(t) + C * (r * cos(t) - t0) * cos(t)
                r = findroot(dU, rho0)
                return (B * (r * sin(t) - k0) ** 2 + C * (r * cos(t) - t0) ** 2) / 2, r

            for frac in ("1", "0.999", "0.99", "0.9", "0.7", "0.5", "0.3", "0.1", "1.001"):
                t = mpf(float(th0 * mpf(float(frac))))
                if t >= pi / 2 + mpf(10) ** -30 and frac == "1.001":
                    continue
                dudt = diff(lambda x: ustar(x)[0], t)
                force = -dudt / sin(t)
                r = ustar(t)[1]
                rows.append(",".join([str(n), th0d, repr(float(th0)), ab, "0.05", repr(float(t)), fmt(force), fmt(cos(t)), fmt(sin(t) / r)]))
    return rows


def series_report():
    """Small-k coefficients fitted at 50 digits (documentation of the misprints)."""
    from mpmath import matrix, lu_solve
    lines = ["quantity,n,power_of_k,fitted"]
    deg, h = 9, mpf(10) ** -6
    ms = [h * (i + 1) for i in range(deg + 1)]
    A = matrix(deg + 1, deg + 1)
    for i, mm in enumerate(ms):
        for c in range(deg + 1):
            A[i, c] = mm ** c
    old = mp.dps
    mp.dps = 90
    for shape in ("upsilon", "alpha"):
        for n in (1, 2, 3):
            b_om, b_dz = matrix(deg + 1, 1), matrix(deg + 1, 1)
            for i, mm in enumerate(ms):
                parity, om = primary_omega(n, mm, shape)
                b_om[i] = om / (pi * n)
                b_dz[i] = symmetric_state(n, mm, parity, om)[0]
            c_om, c_dz = lu_solve(A, b_om), lu_solve(A, b_dz)
            for p in (1, 2, 3):
                lines.append(f"{shape}_omega_over_pi_n,{n},{2 * p},{mp.nstr(c_om[p], 20)}")
                lines.append(f"{shape}_extension,{n},{2 * p},{mp.nstr(c_dz[p], 20)}")
    mp.dps = old
    return lines


def write(name, lines):
    with open(os.path.join(OUT, name), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[2] == "--only-helix":
        write("helix.csv", helix_rows())
        sys.exit(0)
    check_primary()
    write("elastica_primary.csv", gen_primary())
    write("elastica_theta.csv", gen_theta())
    write("elastica_theta_roots.csv", gen_theta_roots())
    write("elastica_bifurcations.csv", gen_bifurcations())
    folds, arms = gen_folds_and_arms()
    write("elastica_folds.csv", folds)
    write("elastica_secondary.csv", arms)
    write("helix.csv", helix_rows())
    write("elastica_series_fit.csv", series_report())
