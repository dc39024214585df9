#!/usr/bin/env python3
"""Medians of the `jobs` criterion benchmarks and the fitted cost exponents (time ~ size^p).

Run after `cargo bench -p karkas-bench --bench jobs`; reads target/criterion/<job>/<size>/new/
estimates.json (needs only the standard library).

    python3 bench/exponents.py [--criterion target/criterion]
"""

import argparse
import json
import math
import os

JOBS = [
    "curve_eval_value",
    "curve_eval_value_d1",
    "curve_interp_not_a_knot",
    "closed_interp_periodic_cubic",
    "closed_interp_dps",
    "smoothing_fit_adaptive",
    "bicubic_construct",
    "bicubic_eval_grid",
]


def slope(xs, ys):
    """Least-squares slope of log(y) against log(x)."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    num = sum((a - mx) * (b - my) for a, b in zip(lx, ly))
    den = sum((a - mx) ** 2 for a in lx)
    return num / den


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--criterion", default=os.path.join("target", "criterion"))
    args = ap.parse_args()
    print("| job | sizes | medians | exponent p |")
    print("|---|---|---|---|")
    for job in JOBS:
        folder = os.path.join(args.criterion, job)
        if not os.path.isdir(folder):
            continue
        rows = []
        for size in os.listdir(folder):
            path = os.path.join(folder, size, "new", "estimates.json")
            if size.isdigit() and os.path.exists(path):
                with open(path) as f:
                    rows.append((int(size), json.load(f)["median"]["point_estimate"] * 1e-9))
        rows.sort()
        if len(rows) < 2:
            continue
        sizes = ", ".join(f"{n:.0e}".replace("e+0", "e") for n, _ in rows)
        times = ", ".join(fmt(t) for _, t in rows)
        p = slope([n for n, _ in rows], [t for _, t in rows])
        print(f"| {job} | {sizes} | {times} | {p:.2f} |")


def fmt(seconds):
    return f"{seconds * 1e3:.3g} ms" if seconds < 1 else f"{seconds:.3g} s"


if __name__ == "__main__":
    main()
