#!/usr/bin/env python3
"""Helix force and spring constant at extreme stiffnesses (mpmath, 700 digits).

Regenerate (deterministic, a few seconds):

    python3 tests/data/gen_helix_extremes.py > tests/data/helix_extremes.csv

mpmath's exponent range is unbounded, so nothing over- or underflows here. The
force is the energy derivative F = -dU*/dtheta / sin(theta), with U* the strain
energy minimised over the twist rate (zero axial moment; the minimiser is the
root of dU/drho, linear in rho, from two evaluations, not the closed form), as in gen_elastica.py's
helix table. The spring constant is dF/d(Delta z) at rest from the Appendix's
closed form (2 pi n)^2 B C / (sin^2 t0 (B sin^2 t0 + C cos^2 t0)), evaluated in
mpmath: the closed form itself is checked against the energy by helix.csv and
tests/helix; this table checks hockle's evaluation of it at extreme values.
Values "overflow" mark results beyond the largest double (1.8e308).
"""
from mpmath import mp, mpf, pi, sin, cos, diff

# B/C up to 1e600: rho sin t - kappa0 is O(C/B), so U needs > 600 digits
mp.dps = 700
DMAX = mpf("1.7976931348623157e308")


def force(n, t0, B, C, t):
    rho0 = 2 * pi * n
    k0, tau0 = rho0 * sin(t0), rho0 * cos(t0)

    def ustar(x):
        du = lambda r: B * (r * sin(x) - k0) * sin(x) + C * (r * cos(x) - tau0) * cos(x)
        # du is linear in r: its root from two evaluations is exact
        r = -du(0) / (du(1) - du(0))
        return (B * (r * sin(x) - k0) ** 2 + C * (r * cos(x) - tau0) ** 2) / 2

    return -diff(ustar, t, h=t * mpf(10) ** -25) / sin(t)


def spring_constant(n, t0, B, C):
    rho0 = 2 * pi * n
    s0, c0 = sin(t0), cos(t0)
    return rho0**2 * B * C / (s0**2 * (B * s0**2 + C * c0**2))


def fmt(v):
    return "overflow" if abs(v) > DMAX else mp.nstr(v, 25)


# (n, theta0, A, B, C, [theta...]); every number is an exact double
CASES = [
    (4, "1.0", "10", "1", "1e200", ["0.5", "0.9", "1.2"]),
    (4, "1.0", "10", "1e-200", "1e-200", ["0.9", "0.5", "0.1415394733244273"]),
    (4, "1.0", "10", "1", "1e300", ["0.9", "0.5", "0.1415394733244273"]),
    (4, "1.0", "10", "1e300", "1", ["0.9", "0.5"]),
    (4, "1.0", "1", "1e-300", "1e300", ["0.9", "0.5"]),
    (4, "1.0", "1", "1e300", "1e-300", ["0.9", "0.5"]),
    (4, "1.0", "1", "5e-324", "5e-324", ["0.5"]),
    (4, "1.0", "1", "1.7976931348623157e308", "1.7976931348623157e308", ["0.9"]),
    (4, "1.0", "1", "1e300", "1e300", ["1e-10"]),
    (1000000, "0.001", "1", "1", "1e-300", ["0.0005"]),
]
SPRING = [
    (4, "1e-300", "1", "1e-300", "1"),
    (4, "1.0", "1", "1e200", "1e200"),
    (4, "1e-100", "1", "1e-100", "1e100"),
    (4, "1e-100", "1", "1e100", "1e100"),
    (1, "1.5707963267948966", "1", "1e-300", "1e-300"),
]

if __name__ == "__main__":
    print("kind,n,theta0,a,b,c,theta,value")
    for n, t0, a, b, c, thetas in CASES:
        for t in thetas:
            v = force(n, mpf(float(t0)), mpf(float(b)), mpf(float(c)), mpf(float(t)))
            print(f"force,{n},{t0},{a},{b},{c},{t},{fmt(v)}")
    for n, t0, a, b, c in SPRING:
        v = spring_constant(n, mpf(float(t0)), mpf(float(b)), mpf(float(c)))
        print(f"spring_constant,{n},{t0},{a},{b},{c},,{fmt(v)}")
