#!/usr/bin/env python3
"""Curvature extrema of LL, cubic-spline and fitted curves on real airfoil files.

    python3 tests/corpus/analyze_corpus.py --karkas target/release/karkas --dir CORPUS/files

Runs `karkas curve analyze FILE --compare ll,spline,fit --knots K --json` on an even sample of
the corpus's airfoil files (--limit, default 100, every k-th file; 0 for all) and on every RAE 2822 file
in it, and counts the files where the extrema counts keep the order the methods promise: the
LL curve ripples (about two extrema per piece), the interpolating spline is fair, the fit with
few knots is fairest (fit <= spline < ll). Prints the counts per file for RAE 2822, the medians
over the sample, and a last line 'analyze corpus: N files, N in order (fit <= spline < ll), ...'.

Exit status 1 when a run fails (exit status other than 0 or 2: 2 is a refusal, listed in
tests/corpus/expected_refusals.txt or counted), when the JSON lacks a key, or when fewer than
--min-order (default 0.95) of the analyzed files keep the order.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from fit_guards_corpus import HERE, airfoil_files, refused

KEYS = ("length", "curvature_min", "curvature_max", "curvature_extrema", "inflections",
        "max_distance_to_polygon", "fairness_energy")
METHODS = ("ll", "spline", "fit")


def analyze(karkas: str, path: Path, knots: int, timeout: float):
    cmd = [karkas, "curve", "analyze", str(path), "--compare", ",".join(METHODS),
           "--knots", str(knots), "--json"]
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", None
    if run.returncode == 2:
        return "refused", run.stderr.strip().splitlines()[-1:]
    if run.returncode != 0:
        return "failed", run.stderr.strip()[-500:]
    data = json.loads(run.stdout)
    for m in METHODS:
        missing = [k for k in KEYS if k not in data.get(m, {})]
        if missing:
            return "failed", f"{m}: keys {missing} missing"
    return "ok", data


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--karkas", required=True)
    ap.add_argument("--dir", required=True, type=Path)
    ap.add_argument("--limit", type=int, default=100)
    ap.add_argument("--knots", type=int, default=8)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--min-order", type=float, default=0.95)
    args = ap.parse_args()

    skip = refused(HERE / "expected_refusals.txt")
    files = [f for f in airfoil_files(args.dir) if f not in skip]
    if not files:
        print(f"analyze corpus: no airfoil files under {args.dir}", file=sys.stderr)
        return 1
    step = max(1, len(files) // args.limit) if args.limit > 0 else 1
    chosen = sorted(set(files[::step]) | {f for f in files if "rae2822" in f.lower()})
    with ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(
            lambda f: (f, *analyze(args.karkas, args.dir / f, args.knots, args.timeout)), chosen))

    failed = [(f, why) for f, status, why in results if status in ("failed", "timeout")]
    refusals = [f for f, status, _ in results if status == "refused"]
    done = [(f, data) for f, status, data in results if status == "ok"]
    ordered = [f for f, d in done
               if d["fit"]["curvature_extrema"] <= d["spline"]["curvature_extrema"]
               < d["ll"]["curvature_extrema"]]
    for f, d in done:
        if "rae2822" in f.lower():
            counts = ", ".join(f"{m} {d[m]['curvature_extrema']}" for m in METHODS)
            print(f"{f}: curvature extrema {counts}")
    for m in METHODS:
        counts = [d[m]["curvature_extrema"] for _, d in done]
        if counts:
            print(f"{m}: median {statistics.median(counts)} curvature extrema, "
                  f"range {min(counts)}..{max(counts)}")
    for f, why in failed:
        print(f"FAILED {f}: {why}")
    for f, d in done:
        if f not in ordered:
            counts = ", ".join(f"{m} {d[m]['curvature_extrema']}" for m in METHODS)
            print(f"out of order: {f}: {counts}")
    share = len(ordered) / len(done) if done else 0.0
    print(f"analyze corpus: {len(done)} files, {len(ordered)} in order (fit <= spline < ll), "
          f"{len(refusals)} refused, {len(failed)} failed ({100 * share:.1f}% in order)")
    return 1 if failed or share < args.min_order else 0


if __name__ == "__main__":
    sys.exit(main())
