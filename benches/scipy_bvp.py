"""SciPy side of the bvp benches: scipy.integrate.solve_bvp on Bratu (lambda = 1,
lower branch) and Troesch (mu = 5), timing and accuracy; and Troesch at mu = 10
with SciPy's own adaptive mesh from its mu = 5 solution, against
`cargo run --release --example troesch` (hockle's Collocation::tolerance):
the error at the 20 points of tests/data/troesch_mu10.csv, max |dy|, |dy'|.

Run: pip install scipy && python3 benches/scipy_bvp.py
Compare with: cargo bench --bench bvp -- scipy_match
(the Rust bench prints its own accuracy on the same problems first).
References: tests/data/bvp_references.py (closed forms).
"""
import time

import numpy as np
from scipy.integrate import solve_bvp

BRATU_THETA = None


def bratu_theta():
    # lambda = theta^2 / (2 cosh^2(theta/4)) = 1 on the lower branch, by bisection.
    lo, hi = 0.0, 4.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid**2 / (2 * np.cosh(mid / 4) ** 2) < 1.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def bratu(tol):
    th = bratu_theta()
    exact = lambda s: -2 * np.log(np.cosh((s - 0.5) * th / 2) / np.cosh(th / 4))
    f = lambda s, y: np.vstack([y[1], -np.exp(y[0])])
    bc = lambda a, b: np.array([a[0], b[0]])
    x = np.linspace(0, 1, 5)
    y0 = np.zeros((2, x.size))
    best = float("inf")
    for _ in range(20):
        t = time.perf_counter()
        sol = solve_bvp(f, bc, x, y0, tol=tol)
        best = min(best, time.perf_counter() - t)
    err = np.max(np.abs(sol.y[0] - exact(sol.x)))
    return best, err, sol.x.size - 1, sol.status


def troesch(tol):
    mu = 5.0
    f = lambda s, y: np.vstack([y[1], mu * np.sinh(mu * y[0])])
    bc = lambda a, b: np.array([a[0], b[0] - 1])
    x = np.linspace(0, 1, 5)
    y0 = np.vstack([x, np.ones_like(x)])
    best = float("inf")
    for _ in range(20):
        t = time.perf_counter()
        sol = solve_bvp(f, bc, x, y0, tol=tol, max_nodes=100000)
        best = min(best, time.perf_counter() - t)
    err = abs(sol.y[1, 0] - 0.045750461406318739)
    return best, err, sol.x.size - 1, sol.status


for tol in (1e-6, 1e-8):
    t, e, n, st = bratu(tol)
    print(f"scipy bratu  tol={tol:.0e}: {t*1e3:8.3f} ms  max mesh error {e:.2e}  intervals {n}  status {st}")
    t, e, n, st = troesch(tol)
    print(f"scipy troesch tol={tol:.0e}: {t*1e3:8.3f} ms  |y'(0) error| {e:.2e}  intervals {n}  status {st}")


def troesch10(tol, jacobian):
    """mu = 10 from SciPy's mu = 5 solution (not timed): best of 10."""
    import os
    here = os.path.dirname(os.path.abspath(__file__))
    table = np.loadtxt(os.path.join(here, "..", "tests", "data", "troesch_mu10.csv"), delimiter=",", skiprows=1)
    rhs = lambda mu: (lambda s, y: np.vstack([y[1], mu * np.sinh(mu * y[0])]))

    def jac(s, y):
        j = np.zeros((2, 2, y.shape[1]))
        j[0, 1] = 1.0
        j[1, 0] = 100.0 * np.cosh(10.0 * y[0])
        return j

    bc = lambda a, b: np.array([a[0], b[0] - 1])
    x = np.linspace(0, 1, 5)
    start = solve_bvp(rhs(5.0), bc, x, np.vstack([x, np.ones_like(x)]), tol=1e-6, max_nodes=100000)
    best = float("inf")
    for _ in range(10):
        t = time.perf_counter()
        sol = solve_bvp(rhs(10.0), bc, start.x, start.y, fun_jac=jac if jacobian else None,
                        tol=tol, max_nodes=1000000)
        best = min(best, time.perf_counter() - t)
    v = sol.sol(table[:, 0])
    err = max(np.max(np.abs(v[0] - table[:, 1])), np.max(np.abs(v[1] - table[:, 2])))
    return best, err, sol.x.size - 1, sol.status


print("troesch mu = 10, adaptive (scipy tol, time, error at the table's points, intervals):")
for tol in (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9):
    for jacobian in (False, True):
        t, e, n, st = troesch10(tol, jacobian)
        print(f"scipy troesch10 tol={tol:.0e} jac={jacobian}: {t*1e3:8.2f} ms  error {e:.1e}  intervals {n}  status {st}")
