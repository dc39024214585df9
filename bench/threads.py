#!/usr/bin/env python3
"""Multi-core speedup of the parallel karkas paths: the same calls with 1 thread and with all.

Each measurement runs in a fresh process with RAYON_NUM_THREADS set (rayon reads it once).

    python3 bench/threads.py
"""

import os
import statistics
import subprocess
import sys
import time

CASES = {
    "curve eval 1e7 (CubicSpline, out=)": """
pts = open_curve(1000); c = karkas.CubicSpline(pts); lo, hi = c.domain
ts = np.linspace(lo, hi, 10_000_000); out = np.empty((len(ts), 3))
run = lambda: c(ts, out=out)""",
    "curve eval + 1st derivative 1e7": """
pts = open_curve(1000); c = karkas.CubicSpline(pts); lo, hi = c.domain
ts = np.linspace(lo, hi, 10_000_000); out = np.empty((len(ts), 3)); d1 = np.empty_like(out)
run = lambda: (c(ts, out=out), c(ts, 1, out=d1))""",
    "bicubic construction 1000 x 1000": """
g = sheet(1000)
run = lambda: karkas.BicubicSurface(g, parameterization="chord")""",
    "bicubic evaluation 2000 x 2000": """
S = karkas.BicubicSurface(sheet(1000), parameterization="chord")
(a, b), (c0, d) = S.domain_u, S.domain_v
us, vs = np.linspace(a, b, 2000), np.linspace(c0, d, 2000); out = np.empty((2000, 2000, 3))
run = lambda: S(us, vs, grid=True, out=out)""",
    "smoothing fit 1e5 noisy 2-D points, 2012 knots": """
rng = np.random.default_rng(7)
pts = noisy_spiral(100_000, 2.9e-4, rng)
run = lambda: karkas.fit_curve(pts, knots=2012)""",
    "closed periodic cubic spline 1e5 (chord)": """
pts = closed_curve(100_000)
run = lambda: karkas.CubicSpline(pts, parameterization="chord", bc="periodic")""",
    "closed DPS interpolation 1e5": """
pts = closed_curve(100_000)
run = lambda: karkas.DiscreteSpline.interpolate(pts, order=3, n=10)""",
}

CHILD = """
import sys, time, statistics, numpy as np, karkas
sys.path.insert(0, {here!r})
from compare import open_curve, closed_curve, sheet, noisy_spiral
{setup}
run()
times = []
for _ in range(7):
    t0 = time.perf_counter(); run(); times.append(time.perf_counter() - t0)
print(statistics.median(times))
"""


def measure(setup, threads):
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    here = os.path.dirname(os.path.abspath(__file__))
    code = CHILD.format(here=here, setup=setup)
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(out.stderr)
    return float(out.stdout.split()[-1])


def main():
    cores = os.cpu_count()
    print(f"| case | 1 thread | {cores} threads | speedup |")
    print("|---|---|---|---|")
    for name, setup in CASES.items():
        one, all_ = measure(setup, 1), measure(setup, cores)
        print(f"| {name} | {one * 1e3:.1f} ms | {all_ * 1e3:.1f} ms | {one / all_:.2f} |", flush=True)


if __name__ == "__main__":
    main()
