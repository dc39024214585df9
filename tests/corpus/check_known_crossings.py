#!/usr/bin/env python3
"""Each crossing listed in tests/corpus/known_crossings.txt is the method's own, rebuilt
independently of karkas.

    python3 tests/corpus/check_known_crossings.py --karkas target/release/karkas --dir CORPUS/files

For every FILE METHOD BOUND line of known_crossings.txt the file's points are read by
aerosandbox's `get_file_coordinates` (not by karkas), their first and last points replaced by
their midpoint (the shared-end rule, docs/reference/contract.md), and the method is rebuilt:

- `ll` (`curve ll --interpolate`, order 3): Aulchenko, Latypov and Nikulichev's interpolating
  LL curve in NumPy (docs/methods.md §1.2): system (6) for the control points r* (first and
  last rows identity), the end extensions r_0 = 2 r_1 - r_2, r_{K+1} = 2 r_K - r_{K-1}, and
  P_i(xi) = c_-(xi) r_{i-1} + c_0(xi) r_i + c_+(xi) r_{i+1} with the kernel h of §1.1 at
  evenly spaced nodes t_i = i/(K+1);
- `spline` (`curve spline`): SciPy's `CubicSpline` on cumulative chord-length parameters with
  natural ends (the ends `curve spline` takes at a shared end).

Checks, each of which can fail: karkas's branches cross (upper minus lower thickness over the
last 20% of the chord, as tests/corpus/closed_profiles_corpus.py measures it) by the reference's
depth within 2% of it, and by no more than the listed bound; for `ll` the reference's control
polygon r* crosses too (the cause: system (6) on evenly spaced nodes moves the control point
next to the edge across the other branch where the last chord is several times shorter than
the one before it; the curve keeps to its control points' hull); for `spline` the reference
with end slopes clamped to the last chords (the points' own end directions) still crosses
(no end rule removes it: the overshoot is inside the last piece, at the points' kink). The
polygon through the points must not cross (else the data cross, not the method). The last
line reads 'known crossings: N of N confirmed by the rebuild'; exit 1 on any failure.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
from math import comb
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

sys.path.insert(0, str(Path(__file__).resolve().parent))
from closed_profiles_corpus import KNOWN, crossing  # noqa: E402

AGREE = 0.02
SAMPLES = 200_000


def read_points(path: Path) -> np.ndarray:
    from aerosandbox.geometry.airfoil.airfoil_families import get_file_coordinates
    p = np.asarray(get_file_coordinates(str(path)), dtype=float)
    p[0] = p[-1] = 0.5 * (p[0] + p[-1])
    return p


def kernel(xi, order):
    eps = [comb(order + k, k) / (order + k) for k in range(order + 1)]
    return xi ** (order + 1) * sum(eps[k] * (order - k) * (1 - xi) ** k for k in range(order + 1))


def ll_controls(p, order=3):
    """The control points r* of system (6): the curve passes through p at its nodes."""
    n, d = len(p), comb(2 * order, order) / 2 ** (2 * order + 2)
    a = np.zeros((n, n))
    a[0, 0] = a[-1, -1] = 1.0
    for i in range(1, n - 1):
        a[i, i - 1:i + 2] = (d, 1 - 2 * d, d)
    return np.linalg.solve(a, p)


def ll_curve(r, order=3, per_segment=2000):
    """Dense samples of the open LL curve over its control points r (nodes 1..K)."""
    ext = np.vstack([2 * r[0] - r[1], r, 2 * r[-1] - r[-2]])
    n, out = len(r), []
    for i in range(1, n + 1):
        lo, hi = (0.5, 1.0) if i == 1 else (0.0, 0.5) if i == n else (0.0, 1.0)
        xi = np.linspace(lo, hi, per_segment, endpoint=i == n)[:, None]
        h = kernel(xi, order)
        out.append((1 - 2 * xi + h) / 2 * ext[i - 1] + (1 + 2 * xi - 2 * h) / 2 * ext[i]
                   + h / 2 * ext[i + 1])
    return np.vstack(out)


def chord_spline(p, ends):
    t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
    spline = CubicSpline(t, p, bc_type=ends)
    return spline(np.linspace(t[0], t[-1], SAMPLES))


def chord_ends(p):
    """SciPy's clamped ends along the first and last chords (unit speed: chord parameters)."""
    first, last = p[1] - p[0], p[-1] - p[-2]
    return ((1, first / np.linalg.norm(first)), (1, last / np.linalg.norm(last)))


def karkas_samples(binary, path, method, folder):
    out = Path(folder) / f"{path.stem}-{method}.csv"
    command = ["curve", "ll", "--interpolate"] if method == "ll" else ["curve", "spline"]
    subprocess.run([binary, *command, str(path), "--samples", str(SAMPLES), "-o", str(out)],
                   check=True, capture_output=True, timeout=120)
    return np.loadtxt(out, delimiter=",", skiprows=1)[:, 1:3]


def check(binary, path, method, bound, folder):
    """The failures of one listed file and method, and a line of figures."""
    p = read_points(path)
    depth = -crossing(karkas_samples(binary, path, method, folder))
    failures = []
    if method == "ll":
        r = ll_controls(p)
        reference, cause = -crossing(ll_curve(r)), -crossing(r)
        cause_text = f"control polygon r* crosses by {cause:.2e}"
    else:
        reference = -crossing(chord_spline(p, "natural"))
        cause = -crossing(chord_spline(p, chord_ends(p)))
        cause_text = f"with end slopes along the last chords still {cause:.2e}"
    line = (f"{path.name} {method}: karkas {depth:.3e}, rebuild {reference:.3e} "
            f"(bound {bound:.2e}); {cause_text}; points' polygon {abs(crossing(p)):.1e}")
    if depth <= 0 or abs(depth - reference) > AGREE * reference:
        failures.append("karkas's depth is not the rebuild's")
    if depth > bound:
        failures.append("deeper than the listed bound")
    if cause <= 0:
        failures.append("the stated cause does not hold")
    if crossing(p) < 0:
        failures.append("the points themselves cross")
    return failures, line


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default="target/release/karkas")
    parser.add_argument("--dir", required=True, type=Path)
    args = parser.parse_args()
    found = {p.name: p for p in sorted(args.dir.rglob("*.dat"))}
    folder, failed = tempfile.mkdtemp(prefix="karkas-known-"), 0
    for (name, method), bound in sorted(KNOWN.items()):
        if name not in found:
            print(f"FAIL {name} {method}: not in the corpus")
            failed += 1
            continue
        failures, line = check(args.karkas, found[name], method, bound, folder)
        print(("FAIL " if failures else "") + line + "".join(f"; {f}" for f in failures))
        failed += bool(failures)
    print(f"known crossings: {len(KNOWN) - failed} of {len(KNOWN)} confirmed by the rebuild")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
