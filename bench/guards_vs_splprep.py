#!/usr/bin/env python3
"""Excess turning of karkas's tolerance-mode fit and of SciPy's splprep, by one measure, on
the real airfoil files of the corpus.

The shape guard of `karkas curve fit` (docs/methods.md §4, "shape guards") warns when the
fitted curve turns more than the polygon through its points by over 5% + 0.1 rad. This script
asks whether a peer does better on the same files: for every .dat file of the corpus (the
multi-element 30P30N left out) at the tolerance TOL it fits

- karkas: `karkas.fit_curve(points, tolerance=TOL)` (the Python package: the CLI's fit);
- splprep: cubic, chord-length parameters, open, with the LARGEST smoothing s whose fit has
  every point within TOL (bisection on log s between 1e-12 n TOL^2 and 10 n TOL^2, 30 steps,
  plus s = 0): the smoothest curve that meets the tolerance, so the least prone to wiggle;

samples each curve at 40 points per data interval (at least 20000), and compares its total
absolute turning (the sum of the absolute angles between consecutive sample chords) with the
polygon's (the sum of the absolute exterior angles at its vertices): a curve turns too much
when it exceeds 1.05 x polygon + 0.1 rad. (The guard itself counts the polygon's end angles
and gaps a little differently; this measure is the same for both fits.) Files splprep cannot
fit within TOL are counted apart.

    python3 bench/guards_vs_splprep.py [--corpus DIR] [--every K] [--tol 1e-4]
"""

import argparse
import math
import os
import sys
import warnings
from pathlib import Path

import numpy as np
from scipy.interpolate import splev, splprep

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fit_tolerance import polyline_distance  # noqa: E402

import karkas  # noqa: E402

RELATIVE, MARGIN = 0.05, 0.1


def turning(polyline):
    """The sum of the absolute angles between consecutive chords of `polyline`."""
    chords = np.diff(polyline, axis=0)
    chords = chords[np.linalg.norm(chords, axis=1) > 0]
    angles = np.arctan2(chords[:, 1], chords[:, 0])
    return float(np.abs(np.angle(np.exp(1j * np.diff(angles)))).sum())


def splprep_smoothest(points, tol, samples):
    """Samples of the splprep fit with the largest s meeting `tol`, or None."""
    n = len(points)

    def attempt(s):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                tck, _ = splprep(points.T, s=s, k=3, nest=n + 8)
        except Exception:
            return None
        curve = np.column_stack(splev(samples, tck))
        return curve if polyline_distance(curve, points).max() <= tol else None

    best = attempt(0.0)
    lo, hi = math.log(1e-12 * n * tol * tol), math.log(10.0 * n * tol * tol)
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        curve = attempt(math.exp(mid))
        if curve is not None:
            best, lo = curve, mid
        else:
            hi = mid
    return best


def read(path):
    try:
        return np.asarray(karkas.read_airfoil(str(path))[1], dtype=float)[:, :2]
    except Exception:
        try:
            return np.loadtxt(path, ndmin=2)[:, :2]
        except Exception:
            return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    default = Path(os.environ.get("KARKAS_CORPUS_DIR", Path.home() / ".cache/karkas-corpus")) / "files"
    ap.add_argument("--corpus", default=str(default))
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--tol", type=float, default=1e-4)
    args = ap.parse_args()
    files = sorted(p for p in Path(args.corpus).rglob("*") if p.suffix.lower() == ".dat")
    files = [f for f in files if "30P30N" not in f.name][:: args.every]
    counts = {"files": 0, "karkas over": 0, "splprep over": 0, "both over": 0, "splprep missed": 0}
    for f in files:
        points = read(f)
        if points is None or len(points) < 5:
            continue
        keep = np.ones(len(points), bool)
        keep[1:] = np.any(np.diff(points, axis=0) != 0.0, axis=1)
        points = points[keep]
        samples = np.linspace(0.0, 1.0, max(20000, 40 * len(points)))
        allowed = (1 + RELATIVE) * turning(points) + MARGIN
        try:
            ours = turning(karkas.fit_curve(points, tolerance=args.tol)(samples)) > allowed
        except Exception:
            continue
        counts["files"] += 1
        theirs = splprep_smoothest(points, args.tol, samples)
        if theirs is None:
            counts["splprep missed"] += 1
            counts["karkas over"] += ours
            continue
        theirs = turning(theirs) > allowed
        counts["karkas over"] += ours
        counts["splprep over"] += theirs
        counts["both over"] += ours and theirs
        if ours or theirs:
            print(f"{f.relative_to(args.corpus)}: karkas {'over' if ours else 'ok'}, "
                  f"splprep {'over' if theirs else 'ok'}", flush=True)
    print("; ".join(f"{k} {v}" for k, v in counts.items()))


if __name__ == "__main__":
    main()
