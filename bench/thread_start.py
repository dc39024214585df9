#!/usr/bin/env python3
"""How promptly the parallel paths start: evaluations into `out=` of a cubic spline and of an
LL curve (L = 5) through the same 1000 3-D points, at batch sizes from the parallel threshold
(2^15 parameters) up, timed back to back and right after 4 ms of NumPy work (the pool's
threads have gone to sleep by then), with 1 thread and with 2.

Each thread count runs in a fresh process with RAYON_NUM_THREADS set before karkas is
imported. Each figure is the median of 41 calls; the NumPy work is a sum over an array sized
to take about 4 ms on this machine, done before each timed call and outside its timing.

    python3 bench/thread_start.py

Prints, per size: the medians with 1 and 2 threads in both settings, and the speedup of 2
threads over 1 (below 1: the second thread costs more than it brings).
"""

import json
import os
import subprocess
import sys
import time

SIZES = [2**15, 2**16, 10**5, 3 * 10**5, 10**6]
CALLS = 41


def child():
    import numpy as np

    import karkas

    rng = np.random.default_rng(3)
    pts = np.cumsum(rng.normal(size=(1000, 3)), axis=0)
    curves = {"CubicSpline": karkas.CubicSpline(pts), "LLCurve L=5": karkas.LLCurve(pts, order=5)}
    work = np.ones(1 << 19)
    # Size the NumPy work to about 4 ms.
    t0 = time.perf_counter()
    for _ in range(20):
        work.sum()
    per = (time.perf_counter() - t0) / 20
    repeats = max(1, round(4e-3 / per))
    result = {}
    for (name, c), n in ((kv, n) for kv in curves.items() for n in SIZES):
        lo, hi = c.domain
        t = np.linspace(lo, hi, n)
        out = np.empty((n, 3))
        c(t, out=out)
        for setting in ("back to back", "after NumPy work"):
            times = []
            for _ in range(CALLS):
                if setting != "back to back":
                    for _ in range(repeats):
                        work.sum()
                a = time.perf_counter()
                c(t, out=out)
                times.append(time.perf_counter() - a)
            times.sort()
            result[f"{name}|{n}|{setting}"] = times[CALLS // 2]
    print(json.dumps(result))


def main():
    if "--child" in sys.argv:
        child()
        return
    runs = {}
    for threads in (1, 2):
        env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
        out = subprocess.run(
            [sys.executable, __file__, "--child"], env=env, capture_output=True, text=True, check=True
        ).stdout
        runs[threads] = json.loads(out.strip().splitlines()[-1])
    print(f"load average (1 min): {os.getloadavg()[0]:.2f}; {os.cpu_count()} cores")
    print("| curve | parameters | setting | 1 thread | 2 threads | speedup |")
    print("|---|---|---|---|---|---|")
    for key, one in runs[1].items():
        name, n, setting = key.split("|")
        two = runs[2][key]
        print(f"| {name} | {int(n):,} | {setting} | {one * 1e3:.3f} ms | {two * 1e3:.3f} ms | {one / two:.2f} |")

if __name__ == "__main__":
    main()
