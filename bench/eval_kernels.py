#!/usr/bin/env python3
"""Evaluation kernels and memory of the Python package, against NumPy and SciPy.

Speed (10^7 sorted parameters over the domain, 3-D, medians of ROUNDS rounds, the tools
interleaved within each round so that the machine's load hits them alike):

- ``CubicSpline`` through 1000 points: values and first derivatives into ``out=``, and values
  into a fresh array; SciPy's ``CubicSpline`` on the same knots and points (always a fresh
  array: SciPy has no ``out=``);
- ``LLCurve`` of order 5 through 1000 points into ``out=`` and into a fresh array;
- NumPy's fill of the same ``(10^7, 3)`` array (``out.fill``) and ``numpy.empty`` plus fill
  (the cost of a fresh array): the memory-bound floor of any kernel that writes it.

Each thread count runs in its own process with ``RAYON_NUM_THREADS`` set before karkas is
imported (the pool is fixed at its first use).

Memory: the peak resident memory added by building ``BicubicSurface`` from a 1000 x 1000 x 3
grid, and by SciPy's ``RectBivariateSpline`` on each of the three coordinates, each in a fresh
process: ``/proc/self/status`` ``VmHWM`` after the build minus ``VmRSS`` before it, with the
peak reset (``/proc/self/clear_refs``) once the grid exists (Rust allocations are invisible
to tracemalloc).

Run: ``python3 bench/eval_kernels.py [ROUNDS]`` (default 9) with karkas importable (e.g.
``PYTHONPATH`` pointing at an installed wheel). Prints one table per thread count and the
memory table.

Rust kernels before and after a change, on one thread:
``python3 bench/eval_kernels.py --criterion BEFORE_EXE AFTER_EXE PATTERN [ROUNDS]`` runs two
builds of the same Criterion bench target (``cargo bench -p karkas-bench --bench ll
--no-run`` prints the executable) alternately, ROUNDS times (default 5), and prints the
median time of each benchmark matching PATTERN (a regular expression) and the ratio.
"""

import os
import statistics
import subprocess
import sys
import time

N = 10_000_000


def polygon(np, k):
    s = np.arange(k) * 0.01
    return np.column_stack(
        [np.cos(s) * (1.0 + 0.3 * np.sin(7.0 * s)), np.sin(s), 0.2 * np.cos(3.0 * s)]
    )


def speed(rounds):
    """Times every tool, interleaved; prints medians (ms) and ratios."""
    import numpy as np
    import scipy.interpolate as si

    import karkas

    pts = polygon(np, 1000)
    spline = karkas.CubicSpline(pts)
    knots = np.asarray(spline.knots)
    reference = si.CubicSpline(knots, pts, bc_type="not-a-knot")
    ts_spline = np.linspace(knots[0], knots[-1], N)
    ll = karkas.LLCurve(pts, order=5)
    a, b = ll.domain
    ts_ll = np.linspace(a, b, N)
    out = np.empty((N, 3))
    out.fill(0.0)  # first touch of the reused buffer's pages

    def fresh_fill():
        fresh = np.empty((N, 3))
        fresh.fill(1.0)

    tools = {
        "numpy out.fill": lambda: out.fill(1.0),
        "numpy empty+fill": fresh_fill,
        "karkas CubicSpline out=": lambda: spline(ts_spline, out=out),
        "karkas CubicSpline nu=1 out=": lambda: spline(ts_spline, 1, out=out),
        "karkas CubicSpline fresh": lambda: spline(ts_spline),
        "scipy CubicSpline": lambda: reference(ts_spline),
        "scipy CubicSpline nu=1": lambda: reference(ts_spline, 1),
        "karkas LLCurve L=5 out=": lambda: ll(ts_ll, out=out),
        "karkas LLCurve L=5 fresh": lambda: ll(ts_ll),
    }
    # Same results before timing them.
    assert np.allclose(spline(ts_spline[::997]), reference(ts_spline[::997]), atol=1e-9)
    times = {name: [] for name in tools}
    for _ in range(rounds):
        for name, run in tools.items():
            start = time.perf_counter()
            run()
            times[name].append(time.perf_counter() - start)
    med = {name: statistics.median(v) * 1e3 for name, v in times.items()}
    fill = med["numpy out.fill"]
    print(f"{'tool':32} {'median ms':>10} {'M pts/s':>9} {'x fill':>7}")
    for name, m in med.items():
        print(f"{name:32} {m:10.2f} {N / m / 1e3:9.0f} {m / fill:7.2f}")
    ratios = [
        ("scipy / karkas, values", "scipy CubicSpline", "karkas CubicSpline out="),
        ("scipy / karkas, nu=1", "scipy CubicSpline nu=1", "karkas CubicSpline nu=1 out="),
        ("scipy / karkas fresh, values", "scipy CubicSpline", "karkas CubicSpline fresh"),
        ("LLCurve out= / numpy fill", "karkas LLCurve L=5 out=", "numpy out.fill"),
    ]
    for label, num, den in ratios:
        print(f"  {label}: {med[num] / med[den]:.2f}")
    print(f"  fresh - out=, CubicSpline: "
          f"{med['karkas CubicSpline fresh'] - med['karkas CubicSpline out=']:.1f} ms; LLCurve: "
          f"{med['karkas LLCurve L=5 fresh'] - med['karkas LLCurve L=5 out=']:.1f} ms; NumPy: "
          f"{med['numpy empty+fill'] - fill:.1f} ms")


def status_kb(field):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    raise KeyError(field)


def memory(tool):
    """Peak memory (MB) added by one build, in this (fresh) process."""
    import numpy as np

    n = 1000
    x = np.linspace(0.0, 1.0, n)
    y = np.linspace(0.0, 1.0, n)
    grid = np.empty((n, n, 3))
    grid[:, :, 0] = x[:, None]
    grid[:, :, 1] = y[None, :]
    grid[:, :, 2] = np.sin(6.0 * x)[:, None] * np.cos(4.0 * y)[None, :]
    if tool == "karkas":
        import karkas

        karkas.BicubicSurface(grid[:3, :3], "uniform")  # module set up before the reset
    else:
        import scipy.interpolate as si

        si.RectBivariateSpline(x[:4], y[:4], grid[:4, :4, 0])
    with open("/proc/self/clear_refs", "w") as f:
        f.write("5")
    before = status_kb("VmRSS")
    if tool == "karkas":
        keep = karkas.BicubicSurface(grid, "uniform")
    else:
        keep = [si.RectBivariateSpline(x, y, grid[:, :, c]) for c in range(3)]
    peak = status_kb("VmHWM")
    held = status_kb("VmRSS")
    del keep
    print(f"{tool} {(peak - before) / 1024:.1f} {(held - before) / 1024:.1f}")


def criterion_pair(before, after, pattern, rounds):
    """Runs two Criterion bench executables (the same benches built before and after a
    change) alternately, ROUNDS times each, and prints per benchmark the median over rounds
    of Criterion's point estimate and the after/before ratio of the medians."""
    import re

    found = {}
    for _ in range(rounds):
        for label, exe in (("before", before), ("after", after)):
            text = subprocess.run(
                [exe, "--bench", pattern, "--warm-up-time", "1", "--measurement-time", "2",
                 "--noplot"],
                capture_output=True, text=True, check=True,
                env=dict(os.environ, RAYON_NUM_THREADS="1"),
            ).stdout
            for name, mid, unit in re.findall(
                    r"^(\S+)\s*\n?\s+time:\s+\[\S+ \S+ (\S+) (\S+) \S+ \S+\]", text,
                    re.M):
                scale = {"ns": 1e-6, "µs": 1e-3, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]
                found.setdefault(name, {}).setdefault(label, []).append(float(mid) * scale)
    print(f"{'benchmark':52} {'before ms':>10} {'after ms':>10} {'after/before':>13}")
    for name, runs in found.items():
        b, a = statistics.median(runs["before"]), statistics.median(runs["after"])
        print(f"{name:52} {b:10.3f} {a:10.3f} {a / b:13.2f}")


def main():
    if len(sys.argv) > 4 and sys.argv[1] == "--criterion":
        rounds = int(sys.argv[5]) if len(sys.argv) > 5 else 5
        print(f"load average: {os.getloadavg()}")
        criterion_pair(sys.argv[2], sys.argv[3], sys.argv[4], rounds)
        print(f"load average: {os.getloadavg()}")
        return
    if len(sys.argv) > 2 and sys.argv[1] == "--speed":
        speed(int(sys.argv[2]))
        return
    if len(sys.argv) > 2 and sys.argv[1] == "--memory":
        memory(sys.argv[2])
        return
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 9
    print(f"load average: {os.getloadavg()}")
    for threads in (1, 2):
        env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
        print(f"\n## {threads} thread(s), {rounds} rounds, 10^7 parameters, 3-D")
        sys.stdout.flush()
        subprocess.run([sys.executable, __file__, "--speed", str(rounds)], env=env, check=True)
    print("\n## Peak memory added by a 1000 x 1000 x 3 grid interpolant (MB: peak, held after)")
    for tool in ("karkas", "scipy"):
        for _ in range(3):
            out = subprocess.run([sys.executable, __file__, "--memory", tool], check=True,
                                 capture_output=True, text=True).stdout
            print("  " + out.strip())
    print(f"load average: {os.getloadavg()}")


if __name__ == "__main__":
    main()
