#!/usr/bin/env python3
"""Airfoil-like files for batch runs: NACA 4-digit sections (closed trailing edge, cosine
spacing) with Gaussian noise, in Selig .dat form, plus damaged files of six kinds.

Usage: bench/make_airfoil_batch.py OUT_DIR [--count N] [--damaged K] [--points P]
                                          [--noise SIGMA] [--seed S]

Writes OUT_DIR/foil-00000.dat ... (the good ones) and OUT_DIR/damaged-000.dat ... (empty,
text, a NaN, one point, binary bytes, a cut line). Standard library only, deterministic for a
seed. The same sections as the batch test of the command line (crates/karkas-cli/tests).
"""

import argparse
import math
import os
import random


def naca4(m, p, t, points):
    """Upper surface from the trailing edge to the nose, then the lower one back."""
    xs = [0.5 * (1 - math.cos(math.pi * i / (points - 1))) for i in range(points)]
    upper, lower = [], []
    for x in xs:
        yt = 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x * x
                      + 0.2843 * x ** 3 - 0.1036 * x ** 4)
        if m > 0 and x < p:
            yc, dy = m / p ** 2 * (2 * p * x - x * x), 2 * m / p ** 2 * (p - x)
        elif m > 0:
            yc = m / (1 - p) ** 2 * ((1 - 2 * p) + 2 * p * x - x * x)
            dy = 2 * m / (1 - p) ** 2 * (p - x)
        else:
            yc, dy = 0.0, 0.0
        th = math.atan(dy)
        upper.append((x - yt * math.sin(th), yc + yt * math.cos(th)))
        lower.append((x + yt * math.sin(th), yc - yt * math.cos(th)))
    return upper[::-1] + lower[1:]


DAMAGED = [
    b"",
    b"not an airfoil\nat all, just words\n",
    b"NACA broken\n1.0 0.0\n0.5 nan\n0.0 0.0\n0.5 -0.05\n1.0 0.0\n",
    b"NACA one point\n0.5 0.01\n",
    bytes(range(256)) * 4,
    b"NACA cut\n1.0 0.0\n0.5 0.06\n0.0 0.0\n0.5",
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--damaged", type=int, default=6)
    ap.add_argument("--points", type=int, default=81, help="points per side")
    ap.add_argument("--noise", type=float, default=2e-5, help="sigma, in chords")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    os.makedirs(args.out, exist_ok=True)
    for k in range(args.count):
        m = rng.choice([0, 1, 2, 3, 4, 5, 6]) / 100
        p = rng.choice([2, 3, 4, 5, 6]) / 10
        t = rng.uniform(0.06, 0.21)
        pts = naca4(m, p, t, args.points)
        with open(os.path.join(args.out, f"foil-{k:05d}.dat"), "w") as f:
            f.write(f"NACA {round(m * 100)}{round(p * 10)}{round(t * 100):02d} noisy {k}\n")
            for x, y in pts:
                f.write(f" {x + rng.gauss(0, args.noise):.7f} {y + rng.gauss(0, args.noise):.7f}\n")
    for k in range(args.damaged):
        with open(os.path.join(args.out, f"damaged-{k:03d}.dat"), "wb") as f:
            f.write(DAMAGED[k % len(DAMAGED)])


if __name__ == "__main__":
    main()
