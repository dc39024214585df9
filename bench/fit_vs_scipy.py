#!/usr/bin/env python3
"""karkas curve fit side by side with SciPy's splprep/splev smoothing (issue 12).

The same noisy points with known truth go through

  * SciPy: ``splprep([x, y], s=n * 2 * sigma**2, k=3)`` (FITPACK's smoothing spline: C^2 cubic,
    chord-length parameters held, knots chosen by FITPACK until the residual meets ``s``);
  * karkas: ``karkas curve fit --knots <SciPy's knots>`` (release binary), the C^1 cubic
    Hermite fit with foot-point distances, on exactly the same knots; once unconstrained (the
    default) and once with a tight jump bound (nearly C^2).

For every fit: the largest distance between the fitted curve and the true curve (both ways,
point to polyline on dense samples), the same away from the ends (the middle 98 % of the arc
length: orthogonal distances let noisy points beyond an open end pull it outwards), the RMS
distance from the true curve (sampled evenly in arc length) to the fit, and the time: SciPy's ``splprep`` call, the fit alone inside karkas
(as the command reports it), and the whole karkas process (reading the CSV, fitting, writing
the default samples); best of a few runs.

Usage: python3 bench/fit_vs_scipy.py [--karkas target/release/karkas]
Needs: pip install numpy scipy; a release build (cargo build --release -p karkas-cli).
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.interpolate import splev, splprep
from scipy.spatial import cKDTree

DENSE = 200_000  # samples of every fit for the deviation measures


def spiral(s):
    """The benchmark's open spiral (1 + s) (cos 3s, sin 3s), s in [0, 1]."""
    return np.stack([(1 + s) * np.cos(3 * s), (1 + s) * np.sin(3 * s)], axis=1)


def naca2412(beta):
    """NACA 2412, closed trailing edge; beta in [0, 2 pi]: x = (1 + cos beta) / 2, upper
    surface first (the formulas of crates/karkas/tests/karkas/fit_reference.rs)."""
    m, p, t = 0.02, 0.4, 0.12
    x = 0.5 * (1 + np.cos(beta))
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    fore = x < p
    yc = np.where(fore, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x**2))
    slope = np.where(fore, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    theta = np.arctan(slope)
    side = np.where(beta <= np.pi, 1.0, -1.0)
    return np.stack([x - side * yt * np.sin(theta), yc + side * yt * np.cos(theta)], axis=1)


def even_in_length(polyline, count):
    """`count` points spread evenly in arc length along a dense polyline."""
    seg = np.linalg.norm(np.diff(polyline, axis=0), axis=1)
    acc = np.concatenate([[0.0], np.cumsum(seg)])
    at = np.linspace(0, acc[-1], count)
    return np.stack([np.interp(at, acc, polyline[:, c]) for c in range(2)], axis=1)


def to_polyline(points, line, tree, nearest=None):
    """Distance from every point to the polyline `line` (nearest vertex, then its two
    segments); the nearest vertex of every point goes into `nearest` when given."""
    _, j = tree.query(points)
    if nearest is not None:
        nearest.append(j)
    best = np.full(len(points), np.inf)
    for a, b in ((j - 1, j), (j, j + 1)):
        ok = (a >= 0) & (b < len(line))
        a, b = np.clip(a, 0, len(line) - 1), np.clip(b, 0, len(line) - 1)
        ab = line[b] - line[a]
        ap = points - line[a]
        den = np.maximum((ab * ab).sum(1), 1e-300)
        u = np.clip((ap * ab).sum(1) / den, 0, 1)
        d = np.linalg.norm(ap - u[:, None] * ab, axis=1)
        best = np.where(ok, np.minimum(best, d), best)
    return best


def deviations(fit, truth_dense):
    """(max two-sided distance, the same away from the ends, RMS distance of the evenly
    spread truth to the fit). Away from the ends: the points of either curve whose nearest
    point on the other lies in the middle 98 % of the true curve's arc length."""
    fit_tree, truth_tree = cKDTree(fit), cKDTree(truth_dense)
    seg = np.linalg.norm(np.diff(truth_dense, axis=0), axis=1)
    share = np.concatenate([[0.0], np.cumsum(seg)]) / seg.sum()
    nearest = []
    fit_to_truth = to_polyline(fit, truth_dense, truth_tree, nearest)
    inner = (share[nearest[0]] > 0.01) & (share[nearest[0]] < 0.99)
    coarse = truth_dense[::10]
    truth_to_fit_all = to_polyline(coarse, fit, fit_tree)
    coarse_inner = (share[::10] > 0.01) & (share[::10] < 0.99)
    worst = max(fit_to_truth.max(), truth_to_fit_all.max())
    worst_inner = max(fit_to_truth[inner].max(), truth_to_fit_all[coarse_inner].max())
    even = even_in_length(truth_dense, 20_000)
    truth_to_fit = to_polyline(even, fit, fit_tree)
    return worst, worst_inner, float(np.sqrt(np.mean(truth_to_fit**2)))


def run_karkas(binary, csv, knots, extra, samples=None):
    """Runs karkas curve fit; returns (samples as an array, wall seconds of the process,
    seconds of the fit alone as the command reports it)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "fit.csv")
        cmd = [binary, "curve", "fit", csv, "--knots", ",".join(repr(float(k)) for k in knots), "-o", out]
        cmd += extra
        if samples:
            cmd += ["--samples", str(samples)]
        start = time.perf_counter()
        done = subprocess.run(cmd, capture_output=True, text=True)
        elapsed = time.perf_counter() - start
        if done.returncode != 0:
            sys.exit(f"karkas failed: {done.stderr.strip()}")
        fit_ms = float(done.stderr.rsplit("fitted in ", 1)[1].split(" ms")[0])
        data = np.loadtxt(out, delimiter=",", skiprows=1)
    return data[:, 1:3], elapsed, fit_ms / 1e3


def case(name, points, truth_dense, sigma, binary, extra, repeats, knots=None):
    """One comparison. Without `knots`, FITPACK chooses them for the smoothing condition
    `s = n * 2 * sigma^2` (the expected sum of squared residuals); with `knots` (inner and
    ends, from 0 to 1) both fit on those, SciPy by least squares (`task=-1`)."""
    n = len(points)
    xy = [points[:, 0], points[:, 1]]
    if knots is None:
        fit = lambda: splprep(xy, s=n * 2 * sigma**2, k=3)[0]
        how = "SciPy's choice for s = 2 n sigma^2"
    else:
        full = np.concatenate([[0.0] * 3, knots, [1.0] * 3])
        fit = lambda: splprep(xy, task=-1, t=full, k=3)[0]
        how = "uniform, given to both"
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        tck = fit()
        best = min(best, time.perf_counter() - start)
    knots = tck[0][3:-3]
    scipy_fit = np.stack(splev(np.linspace(0, 1, DENSE), tck), axis=1)
    rows = [("SciPy splprep (C^2)", *deviations(scipy_fit, truth_dense), best, best)]
    with tempfile.TemporaryDirectory() as tmp:
        csv = os.path.join(tmp, "points.csv")
        np.savetxt(csv, points, delimiter=",", header="x,y", comments="", fmt="%.17g")
        for label, more in (("karkas, no bound", []), ("karkas, --eps 1e-6", ["--eps", "1e-6"])):
            runs = [run_karkas(binary, csv, knots, extra + more) for _ in range(repeats)]
            wall = min(r[1] for r in runs)
            alone = min(r[2] for r in runs)
            dense = run_karkas(binary, csv, knots, extra + more, samples=DENSE)[0]
            rows.append((label, *deviations(dense, truth_dense), alone, wall))
    print(f"\n{name}: {n} points, noise sigma {sigma:.1e} per coordinate, {len(knots)} knots ({how})")
    print(f"  {'fit':<22} {'max dev':>10} {'max inner':>10} {'RMS dev':>10} {'fit time':>11} {'process':>11}")
    for label, worst, inner, rms, alone, wall in rows:
        process = "" if label.startswith("SciPy") else f"{wall * 1e3:8.1f} ms"
        print(f"  {label:<22} {worst:10.3e} {inner:10.3e} {rms:10.3e} {alone * 1e3:8.1f} ms {process:>11}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default=os.path.join("target", "release", "karkas"))
    args = parser.parse_args()
    if not os.path.exists(args.karkas):
        sys.exit(f"{args.karkas} not found: cargo build --release -p karkas-cli")
    rng = np.random.default_rng(12)

    # The criterion benchmark's data: 1e5 points, uniform noise in [-5e-4, 5e-4].
    n = 100_000
    s = np.linspace(0, 1, n)
    half = 5e-4
    pts = spiral(s) + rng.uniform(-half, half, (n, 2))
    truth = spiral(np.linspace(0, 1, 2_000_000))
    case("spiral", pts, truth, half / np.sqrt(3), args.karkas, [], repeats=3)
    case("spiral", pts, truth, half / np.sqrt(3), args.karkas, [], 3, np.linspace(0, 1, 200))

    # NACA 2412 sections, cosine spacing, Gaussian noise on the inner points; the trailing
    # edge is known exactly, and karkas pins the ends there.
    beta_truth = np.linspace(0, 2 * np.pi, 2_000_001)
    truth = naca2412(beta_truth)
    for n, sigma in ((200, 5e-4), (2000, 1e-4)):
        pts = naca2412(np.linspace(0, 2 * np.pi, n))
        pts[1:-1] += rng.normal(0, sigma, (n - 2, 2))
        case("NACA 2412", pts, truth, sigma, args.karkas, ["--pin-ends"], repeats=5)


if __name__ == "__main__":
    main()
