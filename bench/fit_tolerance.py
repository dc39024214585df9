#!/usr/bin/env python3
"""The tolerance mode of `karkas curve fit` (knots placed until every point is within TOL).

Three measurements, each printed as a table:

(a) time against n: NACA 2412 points (cosine spacing, closed trailing edge) with Gaussian
    noise of 1e-3 chord per coordinate, n = 1e2, 1e3, 1e4, 1e5, at the tolerance 3 sigma;
    the time is the CPU time (user + system) of the whole CLI run, the best of --repeat runs
    (the machine may be shared: wall time would count other processes' turns; the CLI's own
    "fitted in" wall figure is printed beside it), and the exponent is the least-squares
    slope of log(CPU time) against log(n);
(b) 1000 such points at the unreachable tolerance 2e-4: the time and the warning;
(c) real airfoils (the .dat files of the corpus, see tests/corpus/run_corpus.py): karkas
    --tolerance 1e-4 against SciPy's splprep (cubic, chord-length parameters, open) in
    coefficients per coordinate: karkas 2 N for N knots (a value and a derivative per knot),
    splprep len(t) - 4. splprep's smoothing s is searched: bisection on log s between
    1e-12 n TOL^2 and 10 n TOL^2 (40 steps, plus s = 0), keeping the fewest coefficients
    among the s whose fit has every point within TOL (the foot-point distance to the curve,
    measured on a polyline of 40 samples per data interval, at least 20000). A file counts
    where splprep reaches the tolerance; karkas wins there when it reaches it too with no
    more coefficients. The points are read with karkas.read_airfoil (the Python package),
    the same reader as the CLI's; splprep gets them with consecutive duplicates removed.

Usage:
    python3 bench/fit_tolerance.py --karkas target/release/karkas [--only a,b,c]
        [--corpus DIR] [--every K] [--limit M]
"""

import argparse
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

LINE = re.compile(
    r"(\d+) knots, max deviation ([0-9.eE+-]+), rms ([0-9.eE+-]+).*fitted in ([0-9.]+) ms"
)


def naca2412(n, sigma, seed):
    """n points of NACA 2412, cosine spacing from the trailing edge round the nose and back,
    the inner ones with Gaussian noise of sigma per coordinate."""
    m, p, t = 0.02, 0.4, 0.12
    beta = np.linspace(0.0, 2.0 * np.pi, n)
    x = 0.5 * (1.0 + np.cos(beta))
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    yc = np.where(x < p, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * ((1 - 2 * p) + 2 * p * x - x**2))
    dyc = np.where(x < p, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    th = np.arctan(dyc)
    side = np.where(beta <= np.pi, 1.0, -1.0)
    pts = np.column_stack([x - side * yt * np.sin(th), yc + side * yt * np.cos(th)])
    rng = np.random.default_rng(seed)
    pts[1:-1] += sigma * rng.standard_normal((n - 2, 2))
    return pts


def karkas_fit(karkas, source, tol, work):
    """Runs `karkas curve fit --tolerance tol`; returns (knots, max deviation, fit ms, CPU s of
    the whole run, warning or None)."""
    out = Path(work) / "fit.csv"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    run = subprocess.run(
        [karkas, "curve", "fit", "--tolerance", repr(tol), str(source), "-o", str(out)],
        capture_output=True,
        text=True,
    )
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if run.returncode != 0:
        return None
    found = LINE.search(run.stderr)
    if not found:
        return None
    warning = next(
        (l for l in run.stderr.splitlines() if l.startswith("karkas: warning: tolerance")), None
    )
    knots, dev, _, ms = found.groups()
    return int(knots), float(dev), float(ms), cpu, warning


def part_a(karkas, work, repeat):
    sigma = 1e-3
    print("(a) time against n: noisy NACA 2412, sigma 1e-3 chord, tolerance 3 sigma")
    print(f"{'n':>8} {'knots':>6} {'max dev':>10} {'fit wall ms':>12} {'CPU s':>8}  met")
    ns, times = [], []
    for n in (100, 1000, 10000, 100000):
        src = Path(work) / f"naca{n}.csv"
        np.savetxt(src, naca2412(n, sigma, seed=n), delimiter=",")
        best = None
        for _ in range(repeat):
            r = karkas_fit(karkas, src, 3 * sigma, work)
            if r is None:
                print(f"{n:>8} karkas failed")
                break
            if best is None or r[3] < best[3]:
                best = r
        if best is None:
            continue
        knots, dev, ms, cpu, warning = best
        print(f"{n:>8} {knots:>6} {dev:>10.3e} {ms:>12.1f} {cpu:>8.3f}  {'no' if warning else 'yes'}")
        ns.append(n)
        times.append(cpu)
    if len(ns) >= 2:
        slope = np.polyfit(np.log(ns), np.log(times), 1)[0]
        print(f"log-log exponent of the CPU time: {slope:.2f}")


def part_b(karkas, work):
    print("(b) 1000 noisy NACA points (sigma 1e-3), unreachable tolerance 2e-4")
    src = Path(work) / "naca1000.csv"
    np.savetxt(src, naca2412(1000, 1e-3, seed=7), delimiter=",")
    r = karkas_fit(karkas, src, 2e-4, work)
    if r is None:
        print("karkas failed")
        return
    knots, dev, ms, cpu, warning = r
    print(f"knots {knots}, max deviation {dev:.3e}, fit {ms:.1f} ms wall, {cpu:.3f} s CPU (whole run)")
    print(warning or "(no warning)")


def polyline_distance(curve, pts):
    """Distance of every point to the polyline `curve` (nearest vertex, then its segments)."""
    from scipy.spatial import cKDTree

    _, idx = cKDTree(curve).query(pts)
    best = np.full(len(pts), np.inf)
    for shift in (-1, 0):
        i = np.clip(idx + shift, 0, len(curve) - 2)
        a, b = curve[i], curve[i + 1]
        ab = b - a
        u = np.einsum("ij,ij->i", pts - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300)
        u = np.clip(u, 0.0, 1.0)
        d = np.linalg.norm(a + u[:, None] * ab - pts, axis=1)
        best = np.minimum(best, d)
    return best


def splprep_best(pts, tol):
    """The fewest splprep coefficients per coordinate with every point within tol, or None."""
    from scipy.interpolate import splev, splprep

    keep = np.ones(len(pts), bool)
    keep[1:] = np.any(np.diff(pts, axis=0) != 0.0, axis=1)
    pts = pts[keep]
    n = len(pts)
    if n < 4:
        return None
    samples = np.linspace(0.0, 1.0, max(20000, 40 * n))

    def attempt(s):
        try:
            import warnings

            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                (t, c, k), _ = splprep(pts.T, s=s, k=3, nest=n + 8)
        except Exception:
            return None
        curve = np.column_stack(splev(samples, (t, c, k)))
        dev = polyline_distance(curve, pts).max()
        return len(t) - 4, dev

    fewest = None
    r = attempt(0.0)
    if r and r[1] <= tol:
        fewest = r[0]
    lo, hi = math.log(1e-12 * n * tol * tol), math.log(10.0 * n * tol * tol)
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        r = attempt(math.exp(mid))
        if r is not None and r[1] <= tol:
            fewest = r[0] if fewest is None else min(fewest, r[0])
            lo = mid
        else:
            hi = mid
    return fewest


def part_c(karkas, work, corpus, every, limit, tol):
    import karkas as kk

    files = sorted(p for p in Path(corpus).rglob("*") if p.suffix.lower() == ".dat")
    files = files[::every][:limit] if limit else files[::every]
    print(f"(c) real airfoils: {len(files)} files (every {every}th of the corpus), tolerance {tol}")
    counted = wins = unread = karkas_failed = splprep_missed = 0
    ratios, losses = [], []
    started = time.perf_counter()
    for f in files:
        try:
            pts = np.asarray(kk.read_airfoil(str(f))[1], dtype=float)
        except Exception:
            try:  # plain columns without a name line (the CLI reads these too)
                pts = np.loadtxt(f, ndmin=2)
            except Exception:
                unread += 1
                continue
        if pts.ndim != 2 or len(pts) < 5:
            unread += 1
            continue
        sp = splprep_best(pts[:, :2], tol)
        if sp is None:
            splprep_missed += 1
            continue
        r = karkas_fit(karkas, f, tol, work)
        counted += 1
        if r is None:
            karkas_failed += 1
            losses.append((f, "karkas failed", sp))
            continue
        knots, dev, ms, wall, warning = r
        ours = 2 * knots
        ratios.append(ours / sp)
        if warning is None and ours <= sp:
            wins += 1
        else:
            losses.append((f, f"karkas {ours} coeffs, dev {dev:.2e}, {'met' if warning is None else 'not met'}", sp))
    took = time.perf_counter() - started
    print(f"unread {unread}, splprep did not reach the tolerance {splprep_missed}, compared {counted}")
    if counted:
        print(f"karkas met the tolerance with no more coefficients: {wins}/{counted} = {wins / counted:.1%}")
        print(f"coefficients karkas/splprep: median {np.median(ratios):.2f}, "
              f"mean {np.mean(ratios):.2f}, max {np.max(ratios):.2f}")
    for f, what, sp in losses[:20]:
        print(f"  loss: {f.relative_to(corpus)}: {what}; splprep {sp}")
    print(f"(c) took {took:.0f} s")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--karkas", default="target/release/karkas")
    ap.add_argument("--only", default="a,b,c")
    default_corpus = os.environ.get("KARKAS_CORPUS_DIR", str(Path.home() / ".cache/karkas-corpus"))
    ap.add_argument("--corpus", default=str(Path(default_corpus) / "files"))
    ap.add_argument("--every", type=int, default=1, help="take every K-th airfoil file")
    ap.add_argument("--limit", type=int, default=0, help="at most M airfoil files")
    ap.add_argument("--tolerance", type=float, default=1e-4, help="tolerance of part (c)")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    parts = set(args.only.split(","))
    with tempfile.TemporaryDirectory() as work:
        if "a" in parts:
            part_a(args.karkas, work, args.repeat)
        if "b" in parts:
            part_b(args.karkas, work)
        if "c" in parts:
            part_c(args.karkas, work, args.corpus, args.every, args.limit, args.tolerance)
    return 0


if __name__ == "__main__":
    sys.exit(main())
