"""Times 10^7 points of an LL curve evaluated from Python into a reused buffer.

The same job as the Rust benchmark `ll_curve_eval_L5_3d_1e7/sorted/1000` in bench/benches/ll.rs
(the same 1000-point wavy 3-D polygon, order 5, 10^7 sorted parameters over the domain). Prints
the median of several runs. Run: python3 crates/karkas-py/tests/bench_eval.py [runs]
"""

import statistics
import sys
import time

import numpy as np

import karkas


def polygon(k):
    s = np.arange(k) * 0.01
    return np.column_stack(
        [np.cos(s) * (1.0 + 0.3 * np.sin(7.0 * s)), np.sin(s), 0.2 * np.cos(3.0 * s)]
    )


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 15
    n = 10_000_000
    curve = karkas.LLCurve(polygon(1000), order=5)
    a, b = curve.domain
    t = np.linspace(a, b, n)
    out = np.empty((n, 3))
    curve(t, out=out)  # first touch of the buffer's pages
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        curve(t, out=out)
        times.append(time.perf_counter() - start)
    median = statistics.median(times)
    print(f"LLCurve(order=5, 1000 points, 3-D): 10^7 points with out=: "
          f"median {median * 1e3:.1f} ms over {runs} runs (min {min(times) * 1e3:.1f} ms)")
    fresh = []
    for _ in range(max(3, runs // 3)):
        start = time.perf_counter()
        curve(t)
        fresh.append(time.perf_counter() - start)
    print(f"  without out= (a new array each call): median {statistics.median(fresh) * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
