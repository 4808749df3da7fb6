#!/usr/bin/env python3
"""Reference planar elastica for the rod tests (independent of hockle).

Planar, inextensible rod of length 1, B = 1, intrinsic curvature k0 = 2*pi*n,
zero end moments, pulled by the physical tension F along z. With theta the
angle between tangent and force and kappa = theta':

    theta'' = F sin(theta)        (moment balance, M = kappa - k0)
    kappa(0) = kappa(1) = k0      (zero end moments)
    kappa^2/2 + F cos(theta) = const   (first integral)

Symmetric solutions have theta(1/2) = tm in {0, pi} (a curvature extremum).
For a j-loop upsilon-shape the ends lie near curvature maxima:
theta(1) = tm + pi*j + delta with tm = pi (j even) or 0 (j odd), delta small.
Given delta, kappa_mid^2 = k0^2 + 2F(cos(theta1) - cos(tm)) by the first
integral, and the length condition  int_tm^theta1 dtheta/kappa(theta) = 1/2
fixes delta; the extension is  dz = 2 int_tm^theta1 cos(theta)/kappa dtheta.

Run:  python3 tests/data/rod_planar_elastica.py > tests/data/rod_planar_elastica.csv
Columns: n, j, force (physical), force_scaled = F/(2 pi n)^2, extension, delta.
"""
import mpmath as mp

mp.mp.dps = 30


def branch_point(n, j, F, delta0):
    k0 = 2 * mp.pi * n
    tm = mp.pi if j % 2 == 0 else mp.mpf(0)

    def pieces(delta):
        t1 = tm + mp.pi * j + delta
        km2 = k0**2 + 2 * F * (mp.cos(t1) - mp.cos(tm))
        kap = lambda t: mp.sqrt(km2 + 2 * F * (mp.cos(tm) - mp.cos(t)))
        inner = [tm + mp.pi * i for i in range(1, j + 2) if tm + mp.pi * i < t1]
        return t1, kap, [tm] + inner + [t1]

    def length(delta):
        t1, kap, pts = pieces(delta)
        return mp.quad(lambda t: 1 / kap(t), pts) - mp.mpf(1) / 2

    delta = mp.findroot(length, delta0, tol=mp.mpf(10) ** -25)
    t1, kap, pts = pieces(delta)
    dz = 2 * mp.quad(lambda t: mp.cos(t) / kap(t), pts)
    return delta, dz


def main():
    print("n,j,force,force_scaled,extension,delta")
    n = 4
    scale = (2 * mp.pi * n) ** 2
    # The primary upsilon branch j = n (the secondary branches are checked
    # against hockle::elastica, an independent closed-form model).
    cases = {4: [0.02, 0.05, 0.1, 0.2, 0.3, 0.4]}
    for j, fs_list in cases.items():
        hist = []
        for fs in fs_list:
            F = mp.mpf(fs) * scale
            guess = hist[-1] if hist else mp.mpf(-0.2)
            if len(hist) >= 2:
                guess = 2 * hist[-1] - hist[-2]
            delta, dz = branch_point(n, j, F, guess)
            hist.append(delta)
            print(f"{n},{j},{mp.nstr(F, 20)},{fs},{mp.nstr(dz, 20)},{mp.nstr(delta, 20)}")


if __name__ == "__main__":
    main()
