#!/usr/bin/env python3
"""Throughput of `karkas batch` on a corpus of airfoil-like files: one thread against two, and
the Dask LocalCluster run of examples/dask_batch.py against the command line on the same
machine.

Usage: bench/batch_throughput.py [--karkas target/dist/karkas] [--count 2000] [--rounds 5]
                                 [--dask] [--keep DIR]

The corpus is bench/make_airfoil_batch.py's (noisy NACA 4-digit sections, 81 points a side,
noise 2e-5 chord, plus 6 damaged files), fitted with `curve fit --tolerance 1e-4`. Before any
timing, the one- and two-thread runs are checked to give the same records (figures) and the
same output bytes. Runs alternate (1 thread, 2 threads, Dask) within each round; every figure
is the median over the rounds of the whole process's wall time (start-up, reading, fitting,
writing and the records), with files/s = inputs / time. Dask needs the karkas wheel, dask and
distributed in this interpreter; its time includes starting the LocalCluster (2 worker
processes, one thread each).
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]


def run(cmd):
    """Wall time of `cmd`; it must exit 1 (the damaged files fail) and no worse."""
    start = time.perf_counter()
    done = subprocess.run(cmd, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 1:
        sys.exit(f"{' '.join(map(str, cmd))}: exit {done.returncode}\n{done.stderr[-2000:]}")
    return seconds


def records(out):
    with open(out / "results.jsonl") as f:
        return {r["input"]: r for r in map(json.loads, f)}


def figures(record):
    return {k: v for k, v in record["summary"].items() if k not in ("seconds", "messages")}


def same(a_out, b_out, count):
    """The two runs' records agree in status and figures, and their outputs byte for byte."""
    a, b = records(a_out), records(b_out)
    assert a.keys() == b.keys(), "different inputs"
    ok = 0
    for name, ra in a.items():
        rb = b[name]
        assert ra["status"] == rb["status"] and ra["error"] == rb["error"], name
        assert figures(ra) == figures(rb), name
        for pa, pb in zip(ra["outputs"], rb["outputs"]):
            assert Path(pa).read_bytes() == Path(pb).read_bytes(), pa
        ok += ra["status"] == "ok"
    assert ok == count, f"{ok} of {count} fitted"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--karkas", default=str(REPO / "target" / "dist" / "karkas"))
    ap.add_argument("--count", type=int, default=2000)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--dask", action="store_true")
    ap.add_argument("--keep", help="the folder for the corpus and outputs (default: a temporary one)")
    args = ap.parse_args()
    work = Path(args.keep or tempfile.mkdtemp(prefix="karkas-batch-bench-"))
    corpus = work / "corpus"
    if not corpus.is_dir():
        subprocess.run([sys.executable, str(REPO / "bench" / "make_airfoil_batch.py"), str(corpus),
                        "--count", str(args.count)], check=True)
    job = ["curve", "fit", "--tolerance", "1e-4"]

    def cli(threads, out):
        shutil.rmtree(out, ignore_errors=True)
        return run([args.karkas, "batch", *job, "--inputs", str(corpus), "--out", str(out),
                    "--jobs", str(threads)])

    def dask(out):
        shutil.rmtree(out, ignore_errors=True)
        return run([sys.executable, str(REPO / "examples" / "dask_batch.py"), *job, "--inputs",
                    str(corpus), "--out", str(out), "--workers", "2"])

    cli(1, work / "check-1")
    cli(2, work / "check-2")
    same(work / "check-1", work / "check-2", args.count)
    if args.dask:
        dask(work / "check-dask")
        same(work / "check-2", work / "check-dask", args.count)
    print("results equal before timing", file=sys.stderr)
    times = {"1 thread": [], "2 threads": [], "dask": []}
    for r in range(args.rounds):
        times["1 thread"].append(cli(1, work / "out"))
        times["2 threads"].append(cli(2, work / "out"))
        if args.dask:
            times["dask"].append(dask(work / "out"))
        print(f"round {r + 1}: " + ", ".join(f"{k} {v[-1]:.2f} s" for k, v in times.items() if v),
              file=sys.stderr)
    inputs = args.count + 6
    med = {k: statistics.median(v) for k, v in times.items() if v}
    print(f"| run | median time (s) | files/s |\n|---|---|---|")
    for k, t in med.items():
        print(f"| {k} | {t:.2f} | {inputs / t:.0f} |")
    print(f"\ntwo threads against one: {med['1 thread'] / med['2 threads']:.2f}x "
          f"(rounds: {args.rounds}, inputs: {inputs}, load: {os.getloadavg()[0]:.2f})")
    if "dask" in med:
        print(f"Dask LocalCluster (2 workers) against the command line on 2 threads: "
              f"{med['dask'] / med['2 threads']:.2f}x the time")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
