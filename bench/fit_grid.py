#!/usr/bin/env python3
"""The smoothing fit against SciPy's splprep over a grid of sizes, noise levels and knot counts.

The grid (issue 53): n in {10^3, 10^4, 10^5, 10^6} points; noise sigma in {1e-5, 1e-4, 1e-3,
3e-3, 1e-2} of the size; knots from FITPACK's rule, half and double it; four curves, 2-D and
3-D, open and closed. Each cell gives karkas's time against splprep's, on one thread and on two,
and the largest and the RMS distance of both fits from the true curve.

The curves (closed forms, parameter u):

  * 2-D open: the spiral (1 + s) (cos 3s, sin 3s), s in [0, 1] (bench/compare.py's);
  * 3-D open: the same spiral rising, z = 0.8 s^2;
  * 2-D closed: r (cos u, 0.6 sin u) with r = 1 + 0.15 cos 3u, u in [0, 2 pi);
  * 3-D closed: the same with z = 0.3 sin 2u.

The points: n points at uniform u (closed: u = 2 pi i / n, and the first point repeated at the
end, as splprep's per=1 reads a closed curve and karkas drops), plus Gaussian noise of
standard deviation sigma L / sqrt(d) per coordinate (L the diagonal of the true curve's bounding
box, d the dimension), so that sigma L is the RMS length of the noise vector, seeded per cell.

FITPACK's rule for the knot count: K = the number of interior knots splprep picks for
s = n (sigma L)^2 (the expected sum of the squared noise vectors; its condition is that the
sum of squared residuals be at most s), ``splprep(points, s=s, k=3, per=closed)``, K =
len(t) - 8. The three cells of a (curve, n, sigma) take K, max(1, round(K / 2)) and 2K
interior knots (at least 1):

  * karkas: ``karkas.fit_curve(points, knots=count + 2, closed=closed)`` (uniform knots, ends
    included, its defaults otherwise);
  * splprep: in the K cell the smoothing spline itself (``s`` as above: it chooses its knots
    and its smoothing); in the half and double cells the least-squares spline on the same
    number of uniform interior knots in its chord-length parameters (``task=-1``), the job
    karkas is given.

Distances from the truth, both ends included: 10,001 samples of each fit (uniform in its
parameter, ends included) projected onto the true curve, and 10,001 samples of the true curve
(uniform in arc length, ends included) projected onto the fit; each projection starts at the
nearest of 50,001 samples of the curve projected onto and takes up to 6 Newton steps (kept
only where they bring it closer). Largest: over both ways; RMS: the truth's samples. The point
of the truth nearest karkas's largest distance is reported as a share of the arc length ("end"
when within 1% of an open end).

Times: wall and CPU time (the process's, user + system: the steadier figure on a loaded
machine; on two threads it adds both threads') of each fit, timed in turn in one process
(karkas, then splprep, repeated; medians):
7 rounds at 10^3 points, 5 at 10^4, 3 at 10^5, 1 at 10^6. The first round is the call whose
result is measured (splprep's in the K cell: the call that gave K). The whole grid runs once per thread
count, each in a fresh process with RAYON_NUM_THREADS set before karkas is imported (splprep is
serial). Before timing, every fit is checked: karkas's and splprep's largest distance from the
truth within 20 sigma L (a cell failing it is marked "CHECK"); the run on more threads checks
that karkas's fit equals the first run's at 101 parameters to 1e-12 of the size.

A cell passes when karkas is at least 3x as fast as splprep on every thread count and its
largest distance is at most splprep's.

Usage:
    python3 bench/fit_grid.py --quick                 # a few cells, about a minute
    nice -n 10 python3 bench/fit_grid.py --json grid.json   # the whole grid (an hour or more)
    python3 bench/fit_grid.py --sizes 1e4 --noise 1e-3 --curves open2 --threads 1
Needs the karkas Python package, numpy and scipy.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
import warnings

import numpy as np
from scipy.interpolate import splev, splprep
from scipy.spatial import cKDTree

SIZES = (1_000, 10_000, 100_000, 1_000_000)
NOISE = (1e-5, 1e-4, 1e-3, 3e-3, 1e-2)
FACTORS = (0.5, 1.0, 2.0)
FIT_SAMPLES = 10_001
TRUTH_SAMPLES = 10_001
SEED_SAMPLES = 50_001
CHECK_SIGMAS = 20.0


def spiral(s, lift):
    a = 3.0 * s
    cols = [(1.0 + s) * np.cos(a), (1.0 + s) * np.sin(a)]
    if lift:
        cols.append(0.8 * s * s)
    return np.column_stack(cols)


def blob(u, lift):
    r = 1.0 + 0.15 * np.cos(3.0 * u)
    cols = [r * np.cos(u), 0.6 * r * np.sin(u)]
    if lift:
        cols.append(0.3 * np.sin(2.0 * u))
    return np.column_stack(cols)


# name: (closed form of u, u's range, closed, dimension)
CURVES = {
    "open2": (lambda u: spiral(u, False), 1.0, False, 2),
    "closed2": (lambda u: blob(u, False), 2 * math.pi, True, 2),
    "open3": (lambda u: spiral(u, True), 1.0, False, 3),
    "closed3": (lambda u: blob(u, True), 2 * math.pi, True, 3),
}


class Parametric:
    """A curve given by value(t, nu) on [lo, hi] (periodic or clamped), projected onto by a
    k-d tree seed and Newton steps."""

    def __init__(self, value, lo, hi, periodic):
        self.value, self.lo, self.hi, self.periodic = value, lo, hi, periodic
        self.seed_t = np.linspace(lo, hi, SEED_SAMPLES)
        self.seeds = value(self.seed_t, 0)
        self.tree = cKDTree(self.seeds)

    def fold(self, t):
        if self.periodic:
            return self.lo + np.mod(t - self.lo, self.hi - self.lo)
        return np.clip(t, self.lo, self.hi)

    def distance(self, queries):
        """The distance of every query to the curve (foot point by Newton from the nearest
        seed sample, each step kept only if it brings the point closer)."""
        best, j = self.tree.query(queries)
        t = self.seed_t[j]
        limit = 4.0 * (self.hi - self.lo) / (SEED_SAMPLES - 1)
        for _ in range(6):
            c, d1, d2 = (self.value(t, nu) for nu in (0, 1, 2))
            r = c - queries
            g = np.einsum("ij,ij->i", r, d1)
            h = np.einsum("ij,ij->i", d1, d1) + np.einsum("ij,ij->i", r, d2)
            h = np.where(h > 0, h, np.einsum("ij,ij->i", d1, d1) + 1e-300)
            t_new = self.fold(t - np.clip(g / h, -limit, limit))
            d_new = np.linalg.norm(self.value(t_new, 0) - queries, axis=1)
            better = d_new < best
            best = np.where(better, d_new, best)
            t = np.where(better, t_new, t)
            if not better.any():
                break
        return best


def truth_curve(name):
    """The true curve as a Parametric, its samples even in arc length and their arc-length
    shares, and the diagonal of its bounding box."""
    form, span, closed, _ = CURVES[name]
    h = 1e-4 * span

    def value(u, nu):
        if nu == 0:
            return form(u)
        if nu == 1:
            return (form(u + h) - form(u - h)) / (2 * h)
        return (form(u + h) - 2 * form(u) + form(u - h)) / (h * h)

    curve = Parametric(value, 0.0, span, closed)
    dense = form(np.linspace(0.0, span, 2_000_001))
    acc = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(dense, axis=0), axis=1))])
    share = np.linspace(0.0, 1.0, TRUTH_SAMPLES)
    u = np.interp(share * acc[-1], acc, np.linspace(0.0, span, len(dense)))
    size = float(np.linalg.norm(dense.max(0) - dense.min(0)))
    return curve, form(u), share, size


def noisy_points(name, n, sigma, size):
    form, span, closed, dim = CURVES[name]
    seed = [53, list(CURVES).index(name), n, int(round(-100 * math.log10(sigma)))]
    rng = np.random.default_rng(seed)
    u = np.arange(n) * span / n if closed else np.linspace(0.0, span, n)
    pts = form(u) + rng.normal(0.0, sigma * size / math.sqrt(dim), (n, dim))
    if closed:
        pts = np.vstack([pts, pts[:1]])
    return pts


def splprep_curve(tck, closed):
    lo, hi = (tck[0][3], tck[0][-4])
    return Parametric(lambda t, nu: np.column_stack(splev(t, tck, der=nu)), lo, hi, closed)


def karkas_curve(fit, closed):
    lo, hi = fit.domain

    def value(t, nu):
        if closed:
            t = lo + np.mod(t - lo, hi - lo)
        return fit(t, nu=nu) if nu else fit(t)

    return Parametric(value, lo, hi, closed)


def distances(truth, samples, share, fit, closed):
    """(largest, RMS, arc-length share of the truth point nearest the largest) of a fit."""
    away = truth.distance(fit.value(np.linspace(fit.lo, fit.hi, FIT_SAMPLES), 0))
    back = fit.distance(samples)
    if away.max() > back.max():
        _, j = cKDTree(samples).query(fit.value(np.array([np.linspace(fit.lo, fit.hi, FIT_SAMPLES)[away.argmax()]]), 0))
        where = float(share[j[0]])
    else:
        where = float(share[back.argmax()])
    return float(max(away.max(), back.max())), float(np.sqrt(np.mean(back**2))), where


def rounds_for(n):
    return {1_000: 7, 10_000: 5, 100_000: 3}.get(n, 1)


def uniform_t(count, closed):
    inner = np.arange(1, count + 1) / (count + 1)
    if closed:
        return np.arange(-3, count + 5) / (count + 1)
    return np.r_[[0.0] * 4, inner, [1.0] * 4]


def run_cells(args, karkas):
    """The grid in this process: a list of cell records."""
    measure = args.measure
    reference = {}
    if args.reference:
        with open(args.reference) as f:
            reference = {c["key"]: c for c in json.load(f)["cells"]}
    cells = []
    for name in args.curves:
        truth, samples, share, size = truth_curve(name)
        closed = CURVES[name][2]
        for n in args.sizes:
            for sigma in args.noise:
                pts = noisy_points(name, n, sigma, size)
                s = n * (sigma * size) ** 2
                smooth = lambda: splprep(pts.T, s=s, k=3, per=int(closed))[0]
                rule_start, rule_cpu = time.perf_counter(), time.process_time()
                rule_tck = smooth()
                rule_s, rule_cpu = time.perf_counter() - rule_start, time.process_time() - rule_cpu
                rule = max(1, len(rule_tck[0]) - 8)
                for factor in args.factors:
                    count = max(1, round(rule * factor))
                    if factor == 1.0:
                        peer = smooth
                    else:
                        t = uniform_t(count, closed)
                        peer = lambda t=t: splprep(pts.T, task=-1, t=t, k=3, per=int(closed))[0]
                    ours = lambda: karkas.fit_curve(pts, knots=count + 2, closed=closed)
                    key = f"{name}/{n}/{sigma:g}/{factor:g}"
                    cell = dict(key=key, curve=name, n=n, sigma=sigma, factor=factor,
                                rule=rule, knots=count, threads=os.environ.get("RAYON_NUM_THREADS"))
                    start, cpu = time.perf_counter(), time.process_time()
                    fit = ours()
                    ours_t, ours_c = [time.perf_counter() - start], [time.process_time() - cpu]
                    if factor == 1.0:
                        tck, peer_t, peer_c = rule_tck, [rule_s], [rule_cpu]
                    else:
                        start, cpu = time.perf_counter(), time.process_time()
                        tck = peer()
                        peer_t, peer_c = [time.perf_counter() - start], [time.process_time() - cpu]
                    probe = fit(np.linspace(0.0, 1.0, 101))
                    cell["probe"] = probe.tolist()
                    cell["warnings"] = len(fit.warnings)
                    if measure:
                        k = distances(truth, samples, share, karkas_curve(fit, closed), closed)
                        p = distances(truth, samples, share, splprep_curve(tck, closed), closed)
                        cell.update(karkas_max=k[0], karkas_rms=k[1], karkas_where=k[2],
                                    splprep_max=p[0], splprep_rms=p[1], splprep_where=p[2])
                        bound = CHECK_SIGMAS * sigma * size
                        cell["checked"] = bool(k[0] <= bound and p[0] <= bound)
                    elif key in reference:
                        gap = np.abs(probe - np.array(reference[key]["probe"])).max()
                        cell["checked"] = bool(gap <= 1e-12 * size)
                    del fit, tck
                    for _ in range((args.rounds or rounds_for(n)) - 1):
                        start, cpu = time.perf_counter(), time.process_time()
                        ours()
                        ours_t.append(time.perf_counter() - start)
                        ours_c.append(time.process_time() - cpu)
                        start, cpu = time.perf_counter(), time.process_time()
                        peer()
                        peer_t.append(time.perf_counter() - start)
                        peer_c.append(time.process_time() - cpu)
                    cell.update(karkas_s=statistics.median(ours_t), splprep_s=statistics.median(peer_t),
                                karkas_cpu=statistics.median(ours_c), splprep_cpu=statistics.median(peer_c),
                                load=os.getloadavg()[0])
                    cells.append(cell)
                    with open(args.out, "w") as f:
                        json.dump(dict(threads=os.environ.get("RAYON_NUM_THREADS"), cells=cells), f)
                    print(f"  {key} knots {count}: karkas {cell['karkas_s'] * 1e3:.1f} ms, "
                          f"splprep {cell['splprep_s'] * 1e3:.1f} ms"
                          + (f", max {cell['karkas_max']:.2e} vs {cell['splprep_max']:.2e}" if measure else ""),
                          file=sys.stderr, flush=True)
    return cells


def child(args):
    warnings.simplefilter("ignore")
    import karkas

    run_cells(args, karkas)


def table(runs, out):
    """The markdown table of every cell and the list of failing cells."""
    first, *more = runs
    others = {r["threads"]: {c["key"]: c for c in r["cells"]} for r in more}
    heads = ["curve", "n", "sigma", "knots", "karkas ms (1 thr)", "splprep ms"]
    heads += [f"ratio {r['threads']} thr" for r in runs] + ["CPU ratio 1 thr"]
    heads += ["max karkas", "max splprep", "RMS karkas", "RMS splprep", "worst at", "pass"]
    lines = ["| " + " | ".join(heads) + " |", "|" + "---|" * len(heads)]
    failing = []
    for c in first["cells"]:
        ratios = [c["splprep_s"] / c["karkas_s"]]
        ratios += [o[c["key"]]["splprep_s"] / o[c["key"]]["karkas_s"] if c["key"] in o else None
                   for o in others.values()]
        checked = c["checked"] and all(o[c["key"]].get("checked", False) for o in others.values() if c["key"] in o)
        fast = all(r >= 3.0 for r in ratios if r is not None)
        close = c["karkas_max"] <= c["splprep_max"]
        where = c["karkas_where"]
        at = "end" if not CURVES[c["curve"]][2] and min(where, 1 - where) < 0.01 else f"{where:.2f}"
        verdict = "yes" if fast and close and checked and None not in ratios else ", ".join(
            w for w, bad in (("time", not fast), ("max", not close), ("CHECK", not checked),
                         ("a thread count not run", None in ratios)) if bad)
        if verdict != "yes":
            failing.append(c["key"])
        knots = f"{c['knots']} ({'K' if c['factor'] == 1 else str(c['factor']) + 'K'})"
        row = [c["curve"], f"{c['n']:.0e}", f"{c['sigma']:g}", knots, f"{c['karkas_s'] * 1e3:.3g}",
               f"{c['splprep_s'] * 1e3:.3g}"] + ["not run" if r is None else f"{r:.2f}" for r in ratios]
        row += [f"{c['splprep_cpu'] / max(c['karkas_cpu'], 1e-9):.2f}"]
        row += [f"{c['karkas_max']:.2e}", f"{c['splprep_max']:.2e}", f"{c['karkas_rms']:.2e}",
                f"{c['splprep_rms']:.2e}", at, verdict]
        lines.append("| " + " | ".join(row) + " |")
    loads = [c["load"] for r in runs for c in r["cells"]]
    lines.append("")
    lines.append(f"cells {len(first['cells'])}, passing {len(first['cells']) - len(failing)}; "
                 f"load average {min(loads):.1f}-{max(loads):.1f}")
    print("\n".join(lines), file=out)
    return failing


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="four cells: 10^3 points, noise 1e-4 and "
                    "1e-2, FITPACK's count, the open 2-D and closed 3-D curves")
    ap.add_argument("--sizes", default=",".join(str(n) for n in SIZES))
    ap.add_argument("--noise", default=",".join(f"{s:g}" for s in NOISE))
    ap.add_argument("--factors", default=",".join(f"{f:g}" for f in FACTORS))
    ap.add_argument("--curves", default=",".join(CURVES))
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--rounds", type=int, default=0, help="timing rounds (default by size)")
    ap.add_argument("--json", help="write every cell of every run here")
    ap.add_argument("--work", help="keep each run's cells here (run-THREADS.json, written cell by cell)")
    ap.add_argument("--table-from", help="print the table of the run files given (comma-separated), "
                    "the first the measured run, as far as they got")
    # Internal: one run of the grid in this process.
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--measure", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--reference", help=argparse.SUPPRESS)
    ap.add_argument("--out", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.quick:
        args.sizes, args.noise, args.factors, args.curves = "1000", "1e-4,1e-2", "1", "open2,closed3"
    args.sizes = [int(float(v)) for v in args.sizes.split(",")]
    args.noise = [float(v) for v in args.noise.split(",")]
    args.factors = [float(v) for v in args.factors.split(",")]
    args.curves = args.curves.split(",")
    if args.child:
        child(args)
        return
    if args.table_from:
        runs = []
        for path in args.table_from.split(","):
            with open(path) as f:
                runs.append(json.load(f))
        failing = table(runs, sys.stdout)
        print("failing: " + (", ".join(failing) if failing else "none"))
        return
    bad = [c for c in args.curves if c not in CURVES]
    if bad:
        sys.exit(f"--curves: unknown curve {bad[0]!r} (known: {', '.join(CURVES)})")
    runs = []
    with tempfile.TemporaryDirectory() as scratch:
        tmp = args.work or scratch
        for i, threads in enumerate(args.threads.split(",")):
            out = os.path.join(tmp, f"run-{threads}.json")
            cmd = [sys.executable, os.path.abspath(__file__), "--child", "--out", out]
            cmd += ["--sizes", ",".join(map(str, args.sizes)), "--noise", ",".join(f"{s:g}" for s in args.noise),
                    "--factors", ",".join(f"{f:g}" for f in args.factors), "--curves", ",".join(args.curves),
                    "--rounds", str(args.rounds)]
            cmd += ["--measure"] if i == 0 else ["--reference", os.path.join(tmp, f"run-{runs[0]['threads']}.json")]
            print(f"threads {threads}:", file=sys.stderr, flush=True)
            subprocess.run(cmd, env=dict(os.environ, RAYON_NUM_THREADS=threads), check=True)
            with open(out) as f:
                runs.append(json.load(f))
    if args.json:
        for r in runs:
            for c in r["cells"]:
                c.pop("probe", None)
        with open(args.json, "w") as f:
            json.dump(runs, f, indent=1)
    failing = table(runs, sys.stdout)
    print("failing: " + (", ".join(failing) if failing else "none"))
    sys.exit(1 if failing else 0)


if __name__ == "__main__":
    main()
