#!/usr/bin/env python3
"""The command line against the library on the same jobs (BENCHMARKS.md, "The command line
against the library").

Generates the inputs in a temporary directory: 10^5 points of a smooth open 3-D curve (CSV
x,y,z) and a 1000 x 1000 grid of a smooth surface (CSV i,j,x,y,z, the format `surface ll`
reads), both with every number in shortest round-trip form. Then runs, interleaved, each job
REPEATS times:

  curve ll    `karkas curve ll POINTS --samples 10000000 -o OUT.csv` (and OUT.npy, and
              `-o -` into /dev/null: the CSV without the file and its fsync)
  surface ll  `karkas surface ll GRID --samples 2000,2000 -o OUT.csv` (and OUT.npy)

measuring the wall time and the peak resident memory of the process (`/usr/bin/time -v`),
and the library's side of the same job: `target/release/library_job` (bench/src/bin), the
Rust library building the same LL curve or surface (order 3, open) and sampling the same
number of points into memory, timed inside the process from the build to the samples (the
input is read before the clock starts). The library writes no file; the command line's time
includes reading the input, writing the output and starting the process, so the ratio is
the whole cost of the command line over the library's computation.

Both binaries are built with the `release` profile:

  cargo build --release -p karkas-cli -p karkas-bench --bin karkas --bin library_job
  python3 bench/cli.py [--repeats 3] [--formats csv,npy] [--json OUT.json]

Prints one line per job with the medians and the ratio, and the load average.
"""

import argparse
import json
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
KARKAS = os.path.join(ROOT, "target", "release", "karkas")
LIBRARY = os.path.join(ROOT, "target", "release", "library_job")

CURVE_POINTS = 100_000
CURVE_SAMPLES = 10_000_000
GRID = 1000
SURFACE_SAMPLES = 2000


def write_curve(path, n):
    """n points of an open 3-D curve with uneven spacing (bench/benches/jobs.rs, open_curve)."""
    with open(path, "w") as f:
        f.write("x,y,z\n")
        for i in range(n):
            s = 20.0 * i / n
            s = s + 0.3 * math.sin(0.7 * s)
            x = math.cos(s) * (1.0 + 0.3 * math.sin(7.0 * s))
            f.write(f"{x!r},{math.sin(s)!r},{0.2 * s!r}\n")


def write_grid(path, n):
    """An n x n grid of the surface z = 0.3 sin(3x) cos(2y) over [0, 2] x [0, 1.5]."""
    with open(path, "w") as f:
        f.write("i,j,x,y,z\n")
        for i in range(n):
            x = 2.0 * i / (n - 1)
            rows = []
            for j in range(n):
                y = 1.5 * j / (n - 1)
                z = 0.3 * math.sin(3.0 * x) * math.cos(2.0 * y)
                rows.append(f"{i},{j},{x!r},{y!r},{z!r}\n")
            f.write("".join(rows))


def timed(command):
    """Wall time (s) and peak resident memory (MB) of `command` under /usr/bin/time -v; its
    standard output goes to /dev/null."""
    start = time.perf_counter()
    done = subprocess.run(["/usr/bin/time", "-v"] + command, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"failed: {' '.join(command)}\n{done.stderr}")
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", done.stderr).group(1))
    return wall, rss / 1024.0


def library(args):
    """The library's times (s) of the job `args`, one per repeat inside the process."""
    done = subprocess.run([LIBRARY] + args, capture_output=True, text=True, check=True)
    return json.loads(done.stdout)["seconds"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--formats", default="csv,npy")
    parser.add_argument("--json", help="also write the figures to this file")
    parser.add_argument("--karkas", default=KARKAS, help="the karkas binary to measure")
    opts = parser.parse_args()
    karkas = opts.karkas
    formats = opts.formats.split(",")
    for exe in (karkas, LIBRARY):
        if not os.path.exists(exe):
            sys.exit(f"{exe} missing: cargo build --release -p karkas-cli -p karkas-bench")

    with tempfile.TemporaryDirectory(prefix="karkas-cli-bench-") as tmp:
        points = os.path.join(tmp, "points.csv")
        grid = os.path.join(tmp, "grid.csv")
        write_curve(points, CURVE_POINTS)
        write_grid(grid, GRID)
        sizes = {p: os.path.getsize(p) for p in (points, grid)}
        jobs = {}
        for fmt in formats:
            out = os.path.join(tmp, f"curve.{fmt}")
            jobs[f"curve ll -> {fmt}"] = (
                [karkas, "curve", "ll", points, "--samples", str(CURVE_SAMPLES), "-o", out],
                out,
                ["curve", points, str(CURVE_SAMPLES)],
            )
            out = os.path.join(tmp, f"surface.{fmt}")
            n = SURFACE_SAMPLES
            jobs[f"surface ll -> {fmt}"] = (
                [karkas, "surface", "ll", grid, "--samples", f"{n},{n}", "-o", out],
                out,
                ["surface", grid, str(n), str(n)],
            )
        # The CSV to standard output (/dev/null): the same work without the file and its
        # fsync, which the atomic write does before the rename.
        jobs["curve ll -> csv on stdout"] = (
            [karkas, "curve", "ll", points, "--samples", str(CURVE_SAMPLES), "-o", "-"],
            None,
            ["curve", points, str(CURVE_SAMPLES)],
        )
        results = {name: {"wall": [], "rss": [], "library": [], "bytes": 0} for name in jobs}
        loads = []
        for _ in range(opts.repeats):
            for name, (command, out, lib) in jobs.items():
                loads.append(os.getloadavg()[0])
                wall, rss = timed(command)
                results[name]["wall"].append(wall)
                results[name]["rss"].append(rss)
                if out is not None:
                    results[name]["bytes"] = os.path.getsize(out)
                    os.remove(out)
                results[name]["library"].extend(library(lib + ["1"]))

    summary = {}
    print(f"inputs: {CURVE_POINTS} points ({sizes[points] / 1e6:.1f} MB), "
          f"{GRID} x {GRID} grid ({sizes[grid] / 1e6:.1f} MB); repeats {opts.repeats}")
    for name, r in results.items():
        wall = statistics.median(r["wall"])
        lib = statistics.median(r["library"])
        rss = statistics.median(r["rss"])
        summary[name] = {
            "cli_s": wall,
            "cli_peak_mb": rss,
            "library_s": lib,
            "ratio": wall / lib,
            "output_mb": r["bytes"] / 1e6,
            "runs": r,
        }
        print(f"{name:22s} cli {wall:6.2f} s  peak {rss:6.0f} MB  output {r['bytes'] / 1e6:6.0f} MB"
              f"  library {lib:6.3f} s  ratio {wall / lib:5.1f}")
    load = f"{min(loads):.2f}-{max(loads):.2f}"
    print(f"load average (1 min) during the runs: {load}; {os.cpu_count()} cores")
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump({"load": load, "jobs": summary}, f, indent=1)


if __name__ == "__main__":
    main()
