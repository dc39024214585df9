#!/usr/bin/env python3
"""Where the defect-2 fit puts the open ends of noisy points, against SciPy's splprep.

The points are those of the smoothing-fit job of bench/compare.py: n points of the spiral
((1 + s) cos 3s, (1 + s) sin 3s), s uniform in [0, 1], with Gaussian noise sigma = 2.9e-4
per coordinate, one noise set per seed. Both fits get FITPACK's knot count
(``splprep(s = 2 n sigma^2)``; karkas on as many uniform knots). For each size the table
gives, over the seeds:

  * the largest distance of each fit from the true spiral (20 000 samples), median over the
    seeds, in units of sigma: karkas with its ends held (the default), with free ends
    (``free_ends=True``), and splprep;
  * in how many seeds karkas is farther from the truth than splprep;
  * the RMS distance of karkas's two ends from the true ends, held and free.

``--smoothing S`` passes ``smoothing=S`` to karkas (its default otherwise).

Usage: python3 bench/fit_ends.py [--seeds 8] [--sizes 1000,3000,10000,30000] [--smoothing S]
Needs: the karkas Python package, numpy, scipy.
"""

import argparse

import numpy as np
from scipy.interpolate import splev, splprep
from scipy.spatial import cKDTree

import karkas

SIGMA = 2.9e-4


def spiral(s):
    return np.column_stack(((1.0 + s) * np.cos(3.0 * s), (1.0 + s) * np.sin(3.0 * s)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--sizes", default="1000,3000,10000,30000")
    ap.add_argument("--smoothing", type=float, default=None)
    args = ap.parse_args()
    tree = cKDTree(spiral(np.linspace(0.0, 1.0, 2_000_001)))
    ends_true = spiral(np.array([0.0, 1.0]))
    print("| points | knots | max from truth / sigma: held | free | splprep "
          "| seeds over splprep: held | free | ends from truth / sigma (RMS): held | free |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n in (int(v) for v in args.sizes.split(",")):
        worst = {"held": [], "free": [], "splprep": []}
        ends = {"held": [], "free": []}
        knots = []
        for seed in range(args.seeds):
            rng = np.random.default_rng([seed + 100, n])
            points = spiral(np.linspace(0.0, 1.0, n)) + rng.normal(0.0, SIGMA, (n, 2))
            tck, _ = splprep(points.T, s=2 * n * SIGMA**2)
            count = len(tck[0]) - 6
            knots.append(count)
            for mode in ("held", "free"):
                fit = karkas.fit_curve(points, knots=count, free_ends=mode == "free", smoothing=args.smoothing)
                lo, hi = fit.domain
                worst[mode].append(tree.query(fit(np.linspace(lo, hi, 20_000)))[0].max())
                ends[mode].extend(np.sum((fit(np.array([lo, hi])) - ends_true) ** 2, axis=1))
            samples = np.column_stack(splev(np.linspace(0.0, 1.0, 20_000), tck))
            worst["splprep"].append(tree.query(samples)[0].max())
        w = {k: np.array(v) / SIGMA for k, v in worst.items()}
        e = {k: np.sqrt(np.mean(v)) / SIGMA for k, v in ends.items()}
        over = {k: int(np.sum(w[k] > w["splprep"])) for k in ("held", "free")}
        print(f"| {n} | {min(knots)}-{max(knots)} | {np.median(w['held']):.2f} | {np.median(w['free']):.2f} "
              f"| {np.median(w['splprep']):.2f} | {over['held']} | {over['free']} | {e['held']:.2f} | {e['free']:.2f} |",
              flush=True)


if __name__ == "__main__":
    main()
