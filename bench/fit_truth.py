#!/usr/bin/env python3
"""The defect-2 fit against SciPy on noisy NACA sections with known truth.

The truth table: NACA 0012, 2412 and 4415 (closed trailing edge, from their closed-form
equations), n = 200, 1000 and 5000 points in cosine spacing from the trailing edge over the
upper surface and back, Gaussian noise sigma = 1e-4 and 1e-3 of the chord per coordinate
(seeded), and two knot choices given to both sides:

  * uniform: 32 knots uniform in [0, 1]; SciPy ``make_lsq_spline`` (C^2 cubic least squares)
    on the normalized chord-length parameters of the points;
  * fitpack: SciPy ``splprep(s = 2 n sigma^2)`` (FITPACK's smoothing spline, its own knots);
    karkas gets FITPACK's knots.

karkas: ``karkas.fit_curve(points, knots=...)`` with its defaults. The figure is the largest
distance between the fitted curve and the TRUE contour, both ways (every sample of the fit to
the dense true contour, every point of the contour to the dense fit), ends included. Both
fits are sampled at 200001 parameters, about 1e-5 of the chord apart, so that the gaps
between samples add at most about 5e-6 to the second way.

The speed case: 10^5 noisy points of NACA 2412 (sigma 1e-4), karkas on 200 uniform knots
against ``splprep`` (s = 2 n sigma^2), rounds interleaved in one process, both results checked
within 5 sigma of the truth before timing, medians of the rounds. Run it once as is and once
with ``RAYON_NUM_THREADS=1`` for one thread (SciPy's FITPACK is serial).

Usage: python3 bench/fit_truth.py [--rounds 9] [--table-only | --speed-only]
Needs: the karkas Python package (maturin develop --release -m crates/karkas-py/Cargo.toml),
numpy, scipy.
"""

import argparse
import os
import statistics
import time

import numpy as np
from scipy.interpolate import make_lsq_spline, splev, splprep
from scipy.spatial import cKDTree

import karkas

SECTIONS = ("0012", "2412", "4415")
SIZES = (200, 1000, 5000)
NOISE = (1e-4, 1e-3)
UNIFORM_KNOTS = 32
DENSE = 200_001


def naca(code, beta):
    """NACA 4-digit section `code`, closed trailing edge; beta in [0, 2 pi] gives
    x = (1 + cos beta) / 2, upper surface first."""
    m, p, t = int(code[0]) / 100, int(code[1]) / 10, int(code[2:]) / 100
    x = 0.5 * (1 + np.cos(beta))
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    if m == 0:
        yc = np.zeros_like(x)
        slope = np.zeros_like(x)
    else:
        fore = x < p
        yc = np.where(fore, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x**2))
        slope = np.where(fore, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    theta = np.arctan(slope)
    side = np.where(beta <= np.pi, 1.0, -1.0)
    return np.stack([x - side * yt * np.sin(theta), yc + side * yt * np.cos(theta)], axis=1)


_TRUTH = {}


def truth(code):
    """The dense true contour and its k-d tree."""
    if code not in _TRUTH:
        contour = naca(code, np.linspace(0, 2 * np.pi, 400_001))
        _TRUTH[code] = (contour, cKDTree(contour))
    return _TRUTH[code]


def distance_to_truth(code, samples):
    """The largest distance between the fit's samples and the true contour, both ways."""
    contour, tree = truth(code)
    one = tree.query(samples)[0].max()
    other = cKDTree(samples).query(contour[::4])[0].max()
    return max(one, other)


def chord(points):
    """Normalized chord-length parameters."""
    d = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))])
    return d / d[-1]


# Added to every seed of the table (--seed-offset): the same cases with other noise.
SEED_OFFSET = 0


def noisy(code, n, sigma):
    rng = np.random.default_rng(n + int(sigma * 1e6) + int(code) + SEED_OFFSET)
    return naca(code, np.linspace(0, 2 * np.pi, n)) + rng.normal(0, sigma, (n, 2))


def one_case(code, n, sigma, kind):
    points = noisy(code, n, sigma)
    u = chord(points)
    dense = np.linspace(0, 1, DENSE)
    if kind == "uniform":
        knots = np.linspace(0, 1, UNIFORM_KNOTS)
        spline = make_lsq_spline(u, points, np.r_[[0.0] * 3, knots, [1.0] * 3], k=3)
        scipy_samples = spline(dense)
    else:
        tck, _ = splprep(points.T, u=u, s=2 * n * sigma**2, k=3)
        knots = np.unique(tck[0])
        scipy_samples = np.array(splev(dense, tck)).T
    fit = karkas.fit_curve(points, knots=knots)
    return (
        len(knots),
        distance_to_truth(code, scipy_samples),
        distance_to_truth(code, fit(dense)),
        fit.noise,
    )


def table():
    print("| section | points | noise | knots | SciPy | karkas | karkas / SciPy | noise estimate |")
    print("|---|---|---|---|---|---|---|---|")
    ratios = []
    for code in SECTIONS:
        for n in SIZES:
            for sigma in NOISE:
                for kind in ("uniform", "fitpack"):
                    count, theirs, ours, estimate = one_case(code, n, sigma, kind)
                    ratio = ours / theirs
                    ratios.append(ratio)
                    peer = "make_lsq_spline" if kind == "uniform" else "splprep"
                    print(
                        f"| NACA {code} | {n} | {sigma:.0e} | {count} {kind} | {theirs:.2e} ({peer}) "
                        f"| {ours:.2e} | {ratio:.2f}{' **over**' if ratio > 1 else ''} | {estimate:.2e} |",
                        flush=True,
                    )
    over = sum(r > 1 for r in ratios)
    print(f"\ncases: {len(ratios)}; karkas at most SciPy's in {len(ratios) - over}; "
          f"worst ratio {max(ratios):.2f}; median ratio {statistics.median(ratios):.2f}")


def speed(rounds):
    n, sigma = 100_000, 1e-4
    points = noisy("2412", n, sigma)
    u = chord(points)
    dense = np.linspace(0, 1, DENSE)
    knots = np.linspace(0, 1, 200)
    fit = karkas.fit_curve(points, knots=knots)
    tck, _ = splprep(points.T, u=u, s=2 * n * sigma**2, k=3)
    for name, samples in (("karkas", fit(dense)), ("splprep", np.array(splev(dense, tck)).T)):
        d = distance_to_truth("2412", samples)
        print(f"{name}: {d:.2e} from the true contour")
        assert d < 5 * sigma, f"{name} is {d:.2e} from the truth"
    ours, theirs = [], []
    for _ in range(rounds):
        t = time.perf_counter()
        karkas.fit_curve(points, knots=knots)
        ours.append(time.perf_counter() - t)
        t = time.perf_counter()
        splprep(points.T, u=u, s=2 * n * sigma**2, k=3)
        theirs.append(time.perf_counter() - t)
    a, b = statistics.median(ours), statistics.median(theirs)
    threads = os.environ.get("RAYON_NUM_THREADS", "all")
    print(f"10^5 points, 200 knots, threads {threads}: karkas {a * 1e3:.1f} ms, "
          f"splprep {b * 1e3:.1f} ms ({len(tck[0])} knots), splprep / karkas {b / a:.2f} "
          f"(medians of {rounds} interleaved rounds; load {os.getloadavg()[0]:.1f})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument("--table-only", action="store_true")
    parser.add_argument("--speed-only", action="store_true")
    parser.add_argument("--seed-offset", type=int, default=0,
                        help="added to the noise seed of every case of the table")
    args = parser.parse_args()
    global SEED_OFFSET
    SEED_OFFSET = args.seed_offset
    if not args.speed_only:
        table()
    if not args.table_only:
        speed(args.rounds)


if __name__ == "__main__":
    main()
