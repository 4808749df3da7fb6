"""hockle and AUTO-07p side by side on the paper's spring (issue 11).

The paper's spring (n = 4, theta0 = 89.8 deg, A/B = 10, nu = 0.05, C by
Nikolai's equality) pulled from rest to F/((2 pi n)^2 B) = 3: six force
folds. Both codes solve the same equations (`rod.f90` is hockle's
`src/rod/problem.rs` written for AUTO, scaled for its arclength norm) and
are scored the same way: the fold error is the largest, over the six folds,
of max(|d dz|, |d F/((2 pi n)^2 B)|) against a converged reference, and the
cost is the user CPU time of the process (one thread: OMP_NUM_THREADS=1 for
AUTO, no `rayon` for hockle).

Needs an AUTO-07p built from its sources (./configure && make, serial; its
default -O: -O3 measured no faster) and AUTO_DIR pointing at it; AUTO
differentiates by finite differences (JAC = 0: FUNC is 3 % of its
instructions under callgrind, its condensation CONPAR 64 %, so an analytic
Jacobian would not change the comparison); hockle's side is `examples/tolerance_trade --folds`
(built by this script with cargo). Two steps:

    python3 benches/auto07p/side_by_side.py search [--out FILE]
        AUTO over a grid of NTST, NCOL, Newton tolerances (EPSL = EPSU),
        fold-location tolerance (EPSS) and largest step (DSMAX): one run of
        each, its time and fold error, as CSV (default
        target/hockle/auto07p_search.csv). About 15 minutes.

    python3 benches/auto07p/side_by_side.py race [--search FILE] [--repeat R]
        For each accuracy (1e-3, 1e-6, 1e-8): the cheapest AUTO setting of
        the search that reaches it and hockle's cheapest tolerance run, then
        each of these runs R times (default 5), the two codes alternating,
        and prints the medians and their ratio.

The reference is hockle on a fixed fine mesh (64 intervals, m = 7,
tolerance 1e-10), computed by `race`; AUTO at NTST = 160, NCOL = 7,
EPSL = EPSU = 1e-11 agrees with it on the four folds it reaches before its
Newton stalls at that tolerance to 1e-10, the last digit AUTO writes
(docs/PERFORMANCE.md).
"""

import csv
import itertools
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TIERS = [1e-3, 1e-6, 1e-8]
# hockle's candidates per tier: tolerance runs whose fold error is checked
# here, cheapest first (docs/PERFORMANCE.md "Tolerance sweep").
HOCKLE_CANDIDATES = ["1e-2", "1e-3", "1e-4", "1e-5", "5e-6", "1e-6", "3e-7", "1e-7", "1e-8"]
REFERENCE = "64,7,1e-10"


def user_seconds_of(cmd, cwd, stdin, env):
    """Run cmd, return (user CPU seconds of it, its completed process)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    with open(stdin) as inp:
        out = subprocess.run(
            cmd, cwd=cwd, stdin=inp, env=env, capture_output=True, text=True, check=False
        )
    after = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
    return after - before, out


def auto_folds(fort8):
    """The folds (type 2 or 5) of an AUTO run, (f, dz), from its fort.8."""
    lines = open(fort8).read().split("\n")
    i, out = 0, []
    while i < len(lines) and lines[i].strip():
        head = [int(v) for v in lines[i].split()]
        itp, nrow, npar = head[2], head[8], head[11]
        block = lines[i + 1 : i + 1 + nrow]
        rows = (npar + 6) // 7
        par = [float(v.replace("D", "E")) for l in block[-rows:] for v in l.split()]
        if abs(itp) % 10 in (2, 5):
            out.append((par[0], par[5]))
        i += 1 + nrow
    return out


class Auto:
    """rod.f90 compiled once against AUTO_DIR; runs in a scratch folder."""

    def __init__(self):
        self.auto_dir = os.environ.get("AUTO_DIR")
        if not self.auto_dir or not os.path.isdir(os.path.join(self.auto_dir, "lib")):
            sys.exit("AUTO_DIR must point at a built AUTO-07p (its lib/*.o)")
        self.dir = tempfile.mkdtemp(prefix="hockle-auto07p-")
        shutil.copy(os.path.join(HERE, "rod.f90"), self.dir)
        libs = sorted(
            os.path.join(self.auto_dir, "lib", f)
            for f in os.listdir(os.path.join(self.auto_dir, "lib"))
            if f.endswith(".o")
        )
        subprocess.run(["gfortran", "-O", "-c", "rod.f90"], cwd=self.dir, check=True)
        subprocess.run(
            ["gfortran", "-O", "-fopenmp", "rod.o", "-o", "rod.exe", *libs],
            cwd=self.dir,
            check=True,
        )
        self.template = open(os.path.join(HERE, "c.rod")).read()

    def run(self, ntst, ncol, eps, epss, dsmax):
        """One pull: (user seconds, steps, how it ended, folds)."""
        c = (
            self.template.replace("NTST=  48, NCOL=   4", f"NTST= {ntst}, NCOL= {ncol}")
            .replace("EPSL= 1e-07, EPSU = 1e-07, EPSS =1e-05", f"EPSL= {eps}, EPSU = {eps}, EPSS = {epss}")
            .replace("DSMAX=   0.02", f"DSMAX= {dsmax}")
        )
        with open(os.path.join(self.dir, "c.rod"), "w") as f:
            f.write(c)
        for old in ("fort.7", "fort.8", "fort.9"):
            p = os.path.join(self.dir, old)
            if os.path.exists(p):
                os.remove(p)
        env = dict(os.environ, OMP_NUM_THREADS="1")
        secs, out = user_seconds_of(["./rod.exe"], self.dir, os.path.join(self.dir, "c.rod"), env)
        steps, end = 0, "?"
        for line in out.stdout.splitlines():
            w = line.split()
            if len(w) > 3 and w[2] in ("UZ", "EP", "MX"):
                steps, end = int(w[1]), w[2]
        fort8 = os.path.join(self.dir, "fort.8")
        folds = auto_folds(fort8) if os.path.exists(fort8) else []
        return secs, steps, end, folds


def hockle_binary():
    subprocess.run(
        ["cargo", "build", "--release", "--quiet", "--example", "tolerance_trade"],
        cwd=ROOT,
        check=True,
    )
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    return os.path.join(target, "release", "examples", "tolerance_trade")


def hockle_run(binary, setting, repeat=1):
    """(median on-CPU seconds within the process, steps, folds)."""
    out = subprocess.run(
        [binary, "--folds", setting, "--repeat", str(repeat)],
        capture_output=True, text=True, check=True,
    ).stdout
    cpu, steps, folds = None, None, []
    for line in out.splitlines():
        w = line.split()
        if w[0] == "cpu":
            cpu = float(w[1])
        elif w[0] == "steps":
            steps = int(w[1])
        elif w[0] == "fold":
            folds.append((float(w[2]), float(w[3])))
    return cpu, steps, folds


def fold_error(folds, reference):
    if len(folds) != len(reference):
        return float("inf")
    return max(max(abs(a[0] - b[0]), abs(a[1] - b[1])) for a, b in zip(folds, reference))


def default_out(name):
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))
    os.makedirs(os.path.join(target, "hockle"), exist_ok=True)
    return os.path.join(target, "hockle", name)


def reference_folds(binary):
    _, _, folds = hockle_run(binary, REFERENCE)
    if len(folds) != 6:
        sys.exit(f"the reference has {len(folds)} folds, not 6")
    return folds


GRID = {
    "ntst": [8, 12, 16, 24, 32, 48],
    "ncol": [4, 5, 6, 7],
    "eps": ["1e-5", "1e-7", "1e-9"],
    "dsmax": [0.1, 0.2, 0.5],
}


def search(out):
    auto = Auto()
    reference = reference_folds(hockle_binary())
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["ntst", "ncol", "eps", "epss", "dsmax", "user_s", "steps", "end", "folds", "fold_error"])
        for ntst, ncol, eps, dsmax in itertools.product(*GRID.values()):
            epss = f"{float(eps) * 100:.0e}"
            secs, steps, end, folds = auto.run(ntst, ncol, eps, epss, dsmax)
            err = fold_error(folds, reference)
            w.writerow([ntst, ncol, eps, epss, dsmax, f"{secs:.3f}", steps, end, len(folds), f"{err:.3e}"])
            f.flush()
            print(f"NTST={ntst} NCOL={ncol} EPS={eps} DSMAX={dsmax}: {secs:.2f} s, {steps} steps ({end}), "
                  f"{len(folds)} folds, error {err:.2e}", flush=True)


def race(search_file, repeat):
    auto = Auto()
    binary = hockle_binary()
    reference = reference_folds(binary)
    rows = list(csv.DictReader(open(search_file)))
    print(f"load average before: {open('/proc/loadavg').read().strip()}")
    for tier in TIERS:
        ok = [r for r in rows if float(r["fold_error"]) <= tier and r["end"] == "UZ"]
        if not ok:
            print(f"{tier:.0e}: no AUTO setting of the search reaches it")
            continue
        best = min(ok, key=lambda r: float(r["user_s"]))
        setting = None
        for cand in HOCKLE_CANDIDATES:
            _, _, folds = hockle_run(binary, cand)
            if fold_error(folds, reference) <= tier:
                setting = cand
                break
        if setting is None:
            print(f"{tier:.0e}: no hockle candidate reaches it")
            continue
        a_times, h_times, a_err, h_err, a_steps, h_steps = [], [], 0.0, 0.0, 0, 0
        for _ in range(repeat):
            secs, a_steps, _, folds = auto.run(best["ntst"], best["ncol"], best["eps"], best["epss"], best["dsmax"])
            a_times.append(secs)
            a_err = fold_error(folds, reference)
            # hockle's process time includes start-up; its own on-CPU time of
            # the pull (median of 3 within the process) is what is reported.
            cpu, h_steps, folds = hockle_run(binary, setting, 3)
            h_times.append(cpu)
            h_err = fold_error(folds, reference)
        a, h = statistics.median(a_times), statistics.median(h_times)
        print(
            f"{tier:.0e}: AUTO NTST={best['ntst']} NCOL={best['ncol']} EPSL=EPSU={best['eps']} "
            f"EPSS={best['epss']} DSMAX={best['dsmax']}: {a:.3f} s ({a_steps} steps, fold error {a_err:.1e}); "
            f"hockle tol {setting}: {h:.3f} s ({h_steps} steps, fold error {h_err:.1e}); AUTO/hockle {a / h:.1f}",
            flush=True,
        )
    print(f"load average after: {open('/proc/loadavg').read().strip()}")


def main():
    args = sys.argv[1:]
    if not args or args[0] not in ("search", "race"):
        sys.exit(__doc__)
    opts = dict(zip(args[1::2], args[2::2]))
    if args[0] == "search":
        search(opts.get("--out", default_out("auto07p_search.csv")))
    else:
        race(opts.get("--search", default_out("auto07p_search.csv")), int(opts.get("--repeat", 5)))


if __name__ == "__main__":
    main()
