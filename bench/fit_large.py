#!/usr/bin/env python3
"""`karkas curve fit` at large n: time, memory and distance from the true curve.

The points: n noisy points on a known open curve (``ellipse``: the upper half of the ellipse
x = 0.5 cos(theta), y = 0.2 sin(theta), theta from 0 to pi, the points uniform in theta; or
``naca``: the NACA 2412 contour with a closed trailing edge, cosine spacing), Gaussian noise
of sigma = 1e-4 of the size (the chord) per coordinate, seeded. Written once per n as CSV
(x,y, 12 significant digits) under --work.

Each run: ``karkas curve fit POINTS --knots K --json --samples 200001 -o FIT.csv`` under
``/usr/bin/time``; wall time, CPU time (user + system, both threads) and peak resident memory
of the karkas process are recorded, and the fit's own seconds (the JSON summary, which
leaves out reading and writing). The distance from the truth is computed here, independently
of karkas: every sample of the fitted curve to the true curve (a polyline of 2 x 10^6 + 1
samples of the closed form, each query to the two segments at its nearest vertex) gives the
largest and the RMS distance; every vertex of the true polyline to the fitted polyline (the
same way) adds the largest distance the other way round (an end the fit falls short of).

The exponent of time in n is the least-squares slope of log(median time) against log(n) (wall,
CPU, and the fit's own seconds; on a loaded machine the CPU time is the steadier); the
memory is reported as a multiple of the points' size, n x 2 x 8 bytes.

Usage:
    python3 bench/fit_large.py [--sizes 1e5,3e5,1e6,2e6] [--knots 30,200] [--rounds 1]
                               [--shape ellipse|naca] [--karkas target/release/karkas]
Needs numpy and scipy. The machine is shared: run it when it is quiet, and give --rounds 3
for medians.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fit_vs_scipy import naca2412  # noqa: E402  (the one closed form of the truth)

SIGMA = 1e-4
SAMPLES = 200_001
DENSE = 2_000_001


def ellipse(theta):
    """The true curve at parameters `theta` in [0, pi] (chord 1)."""
    return np.stack([0.5 * np.cos(theta), 0.2 * np.sin(theta)], axis=1)


SHAPES = {
    "ellipse": (ellipse, math.pi),
    "naca": (naca2412, 2 * math.pi),
}


def points_file(shape, n, work):
    """The CSV of n noisy points of `shape` (written once)."""
    path = os.path.join(work, f"{shape}-{n}.csv")
    if not os.path.exists(path):
        curve, end = SHAPES[shape]
        rng = np.random.default_rng(n)
        pts = curve(np.linspace(0.0, end, n)) + rng.normal(0.0, SIGMA, (n, 2))
        tmp = path + ".tmp"
        np.savetxt(tmp, pts, fmt="%.12g", delimiter=",", header="x,y", comments="")
        os.replace(tmp, path)
    return path


class Polyline:
    """Distances to a polyline: each query to the two segments at its nearest vertex."""

    def __init__(self, vertices):
        self.v = vertices
        self.tree = cKDTree(vertices)

    def distance(self, queries):
        _, j = self.tree.query(queries)
        best = np.full(len(queries), np.inf)
        last = len(self.v) - 1
        for a_idx, b_idx in ((np.maximum(j - 1, 0), j), (j, np.minimum(j + 1, last))):
            a, b = self.v[a_idx], self.v[b_idx]
            ab = b - a
            den = np.einsum("ij,ij->i", ab, ab)
            s = np.where(den > 0, np.einsum("ij,ij->i", queries - a, ab) / np.where(den > 0, den, 1), 0.0)
            s = np.clip(s, 0.0, 1.0)
            foot = a + s[:, None] * ab
            best = np.minimum(best, np.linalg.norm(queries - foot, axis=1))
        return best


_TRUTH = {}


def truth(shape):
    if shape not in _TRUTH:
        curve, end = SHAPES[shape]
        _TRUTH[shape] = Polyline(curve(np.linspace(0.0, end, DENSE)))
    return _TRUTH[shape]


def run_measured(karkas, points, knots, out):
    """One fit as a child of /usr/bin/time: (wall, cpu, peak RSS bytes, summary).

    The resource usage is the one /usr/bin/time reads for its own child: a child forked from
    this process would count this process's pages (the true curve and its k-d tree) in its
    peak, since the peak survives exec.
    """
    cmd = ["/usr/bin/time", "-f", "TIME %e %U %S %M", karkas, "curve", "fit", points,
           "--knots", str(knots), "--json", "--samples", str(SAMPLES), "-o", out]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"karkas failed ({done.returncode}): {' '.join(cmd)}\n{done.stderr}")
    line = [l for l in done.stderr.splitlines() if l.startswith("TIME ")][-1]
    wall, user, system, rss_kb = (float(v) for v in line.split()[1:])
    summary = json.loads(done.stdout.strip().splitlines()[-1])
    return wall, user + system, rss_kb * 1024, summary


def distances(shape, fit_csv):
    """Largest (both ways) and RMS (fit samples to truth) distance of the fit from the truth."""
    samples = np.loadtxt(fit_csv, delimiter=",", skiprows=1)[:, 1:3]
    to_truth = truth(shape).distance(samples)
    back = Polyline(samples).distance(truth(shape).v[::10])
    return max(to_truth.max(), back.max()), math.sqrt(float(np.mean(to_truth**2)))


def slope(xs, ys):
    lx, ly = np.log(xs), np.log(ys)
    return float(np.polyfit(lx, ly, 1)[0])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="1e5,3e5,1e6,2e6")
    ap.add_argument("--knots", default="30,200")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--shape", default="ellipse", choices=sorted(SHAPES))
    ap.add_argument("--karkas", default=os.path.join("target", "release", "karkas"))
    ap.add_argument("--work", default="/tmp/karkas-fit-large")
    ap.add_argument("--json", help="write the rows here")
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    sizes = [int(float(s)) for s in args.sizes.split(",")]
    rows = []
    print("| knots | n | wall s | cpu s | fit s | peak RSS MB | RSS / points | max dist | RMS dist |")
    print("|---|---|---|---|---|---|---|---|---|")
    for knots in [int(k) for k in args.knots.split(",")]:
        for n in sizes:
            points = points_file(args.shape, n, args.work)
            out = os.path.join(args.work, f"fit-{args.shape}-{n}-{knots}.csv")
            runs = [run_measured(args.karkas, points, knots, out) for _ in range(args.rounds)]
            wall = statistics.median(r[0] for r in runs)
            cpu = statistics.median(r[1] for r in runs)
            rss = max(r[2] for r in runs)
            fit_s = statistics.median(r[3]["seconds"] for r in runs)
            largest, rms = distances(args.shape, out)
            row = dict(knots=knots, n=n, wall=wall, cpu=cpu, fit=fit_s, rss=rss,
                       rss_ratio=rss / (n * 2 * 8), max_dist=largest, rms_dist=rms)
            rows.append(row)
            print(f"| {knots} | {n:.0e} | {wall:.2f} | {cpu:.2f} | {fit_s:.2f} | {rss / 1e6:.0f} | "
                  f"{row['rss_ratio']:.2f} | {largest:.2e} | {rms:.2e} |", flush=True)
        mine = [r for r in rows if r["knots"] == knots]
        if len(mine) >= 2:
            ns = [r["n"] for r in mine]
            print(f"knots {knots}: exponent in n of wall {slope(ns, [r['wall'] for r in mine]):.2f}, "
                  f"of CPU {slope(ns, [r['cpu'] for r in mine]):.2f}, "
                  f"of the fit's seconds {slope(ns, [r['fit'] for r in mine]):.2f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
