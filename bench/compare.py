#!/usr/bin/env python3
"""karkas side by side with SciPy, geomdl and Open CASCADE on the same jobs, timed interleaved.

For every job and size, each tool runs on the same data. First every tool runs once
untimed and the results are checked equal: karkas's result against each peer's values at
common parameters where both compute the same object (tolerance per job), otherwise each
tool's own error measure against the data or a reference (tolerance per job or tool); a
failed check prints a DISAGREE line and the script exits non-zero at the end. Then the tools
are timed in rounds (at least 9; `--rounds`), each round running every tool once in turn,
the order rotating from round to round, and the median per tool is kept. The input arrays
(NumPy arrays, Open CASCADE's TColgp arrays) are built before the timing for every tool.

The job set runs once per thread count (`--threads 1,2`), each in a fresh process with
RAYON_NUM_THREADS set before karkas is imported. Writes bench/results.json (per thread count:
medians, errors, checks, exponents, ratios; the run on the most threads also at the top
level, as before) and one log-log plot per job into bench/plots/ (most threads), and prints
one final table: job, size (the largest and the one 10x smaller), threads, karkas median,
fastest peer and its median, ratio, and whether karkas is 3x faster.

Needs: the karkas Python package (`pip install ./crates/karkas-py`), numpy, scipy,
matplotlib; optional: geomdl (`pip install geomdl`), Open CASCADE (`pip install cadquery-ocp`).

    python3 bench/compare.py            # full sizes, 1 and 2 threads (several minutes)
    python3 bench/compare.py --quick    # small sizes, 3 rounds: a smoke run (about a minute)
    python3 bench/compare.py --threads 2 --jobs closed_interp   # one job, one thread count
    python3 bench/compare.py --overhead # only the call overhead on one point (seconds)
    python3 bench/compare.py --python-vs-rust [--run-rust]  # only 10^7 points, Python vs Rust

Besides the jobs, two checks of the Python binding itself (both in every full run, on the
most threads):

- the call overhead on ONE point: a karkas CubicSpline, SciPy's BSpline (make_interp_spline)
  and SciPy's CubicSpline on the same data, their values checked equal first, timed
  interleaved in rounds (each round calls each tool in turn, the order rotating), medians per
  call; the goal is karkas within 2x of BSpline;
- 10^7 points of an LL curve from Python (`c(t, out=)`) against the same job in Rust, the
  Criterion benchmark ll_curve_eval_L5_3d_1e7/sorted/1000 of bench/benches/ll.rs (its median,
  read from target/criterion; --run-rust runs it first); the goal is Python within 1.1x.
"""

import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time

import numpy as np

import karkas
import scipy
from scipy.interpolate import (
    BSpline,
    CubicSpline,
    RectBivariateSpline,
    make_interp_spline,
    splev,
    splprep,
)
from scipy.spatial import cKDTree

try:
    from geomdl import fitting as geomdl_fitting
except ImportError:  # optional peer
    geomdl_fitting = None

try:
    from OCP.Approx import Approx_ParametrizationType
    from OCP.GeomAbs import GeomAbs_Shape
    from OCP.GeomAPI import (
        GeomAPI_Interpolate,
        GeomAPI_PointsToBSpline,
        GeomAPI_PointsToBSplineSurface,
        GeomAPI_ProjectPointOnCurve,
        GeomAPI_ProjectPointOnSurf,
    )
    from OCP.gp import gp_Pnt

    try:  # OCP >= 7.8
        from OCP.collections import Array1_gp_Pnt as TColgp_Array1OfPnt
        from OCP.collections import Array2_gp_Pnt as TColgp_Array2OfPnt
        from OCP.collections import HArray1_gp_Pnt
    except ImportError:
        from OCP.TColgp import TColgp_Array1OfPnt, TColgp_Array2OfPnt
        from OCP.TColgp import TColgp_HArray1OfPnt as HArray1_gp_Pnt
except ImportError:  # optional peer
    GeomAPI_PointsToBSpline = GeomAPI_Interpolate = None

# Open CASCADE's approximation tolerance (3-D distance) for its interpolation-like fits.
OCC_TOLERANCE = 1e-6
# GeomAPI_Interpolate's tolerance: points closer than this count as one (an error).
OCC_POINT_TOLERANCE = 1e-9

HERE = os.path.dirname(os.path.abspath(__file__))

# Each tool gets at most this many seconds per size (one run); slower tools stop growing.
BUDGET = 20.0


def timed(fn, repeats):
    """Median wall time of `repeats` calls of fn() and the last result."""
    times = []
    result = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), result


def chord_parameters(points):
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    return np.concatenate(([0.0], np.cumsum(steps)))


def open_curve(n):
    s = 20.0 * np.arange(n) / n
    s = s + 0.3 * np.sin(0.7 * s)
    return np.column_stack(
        (np.cos(s) * (1.0 + 0.3 * np.sin(7.0 * s)), np.sin(s), 0.2 * s)
    )


def closed_curve(n):
    s = 2.0 * np.pi * np.arange(n) / n
    return np.column_stack(
        (np.cos(s) * (1.0 + 0.3 * np.sin(7.0 * s)), np.sin(s), 0.2 * np.cos(3.0 * s))
    )


def spiral(s):
    a = 3.0 * s
    return np.column_stack(((1.0 + s) * np.cos(a), (1.0 + s) * np.sin(a)))


def noisy_spiral(n, sigma, rng):
    s = np.linspace(0.0, 1.0, n)
    return spiral(s) + rng.normal(0.0, sigma, (n, 2))


def sheet(n):
    x = np.arange(n) / n
    y = np.arange(n) / n
    x = x + 0.2 * x * x
    X, Y = np.meshgrid(x, y, indexing="ij")
    return np.stack((X, Y + 0.05 * np.sin(3.0 * X), np.sin(6.0 * X) * np.cos(4.0 * Y)), axis=-1)


def grid_chord_parameters(grid):
    """The karkas default grid rule: chords along column 0 (u) and row 0 (v) from node (0, 0)."""
    return chord_parameters(grid[:, 0]), chord_parameters(grid[0, :])


class Run:
    """One tool at one size, ready to time: `go()` is the timed call (its input already built);
    `error(result)` is the job's accuracy measure; `values(result)`, when the tool computes the
    same object as karkas, gives its values at the job's common parameters for that size."""

    def __init__(self, go, error, values=None):
        self.go, self.error, self.values = go, error, values


class Job:
    """One job: sizes, tools (name -> setup(size) -> Run) and the results.

    At every size each tool first runs once untimed: its result gives the error measure and
    the agreement check (karkas against every peer, see `check`); then `rounds` rounds time
    every tool once each, the order rotating from round to round, and the median per tool is
    kept. A tool stops growing after a size whose call took more than BUDGET seconds.
    """

    def __init__(self, name, title, unit, sizes, agree_tol, error_tol, table_sizes=None):
        self.name, self.title, self.unit, self.sizes = name, title, unit, sizes
        # Largest |karkas - peer| at the common parameters allowed for tools computing the
        # same object; largest error measure allowed for the others (and for karkas itself).
        self.agree_tol, self.error_tol = agree_tol, error_tol
        largest = sizes[-1]
        medium = min(sizes, key=lambda n: abs(np.log(n / (largest / 10))))
        self.table_sizes = table_sizes or sorted({largest, medium}, reverse=True)
        self.tools = {}
        self.agree_tols = {}
        self.results = {}
        self.checks = []

    def tool(self, name, setup, max_size=None, error_tol=None, agree_tol=None):
        """`error_tol` replaces the job's for this tool's error measure; `agree_tol` the
        job's for its values against karkas's."""
        self.tools[name] = (setup, max_size, error_tol)
        self.agree_tols[name] = agree_tol or self.agree_tol

    def check(self, n, runs, outcome):
        """karkas against each peer at size n: values at common parameters where both give
        them, else each tool's own error measure against its tolerance."""
        mine = [k for k in runs if k.startswith("karkas")]
        peers = [k for k in runs if not k.startswith(("karkas", "store"))]
        for name in mine + peers:
            run, result = runs[name], outcome[name]
            tol = self.tools[name][2] or self.error_tol
            if name in peers and run.values is not None and any(
                runs[k].values is not None for k in mine
            ):
                continue  # compared with karkas below
            err = run.error(result)
            self.record(n, name, None, "error measure", err, tol)
        for k in mine:
            if runs[k].values is None:
                continue
            ours = runs[k].values(outcome[k])
            for p in peers:
                if runs[p].values is None:
                    continue
                theirs = runs[p].values(outcome[p])
                diff = float(np.max(np.abs(np.asarray(ours) - np.asarray(theirs))))
                self.record(
                    n, k, p, "max |karkas - peer| at common parameters", diff, self.agree_tols[p]
                )

    def record(self, n, name, peer, measure, value, tol):
        ok = bool(value <= tol)  # NaN fails
        self.checks.append(
            {"size": n, "tool": name, "peer": peer, "measure": measure, "value": value,
             "tolerance": tol, "ok": ok}
        )
        what = f"{name} vs {peer}" if peer else name
        if not ok:
            print(f"   DISAGREE {self.name} n={n}: {what}: {measure} {value:.3e} > {tol:.1e}",
                  flush=True)
        else:
            print(f"   agree    n={n:>9}: {what}: {measure} {value:.2e} <= {tol:.0e}", flush=True)

    @property
    def disagreements(self):
        return [c for c in self.checks if not c["ok"]]

    def run(self, rounds):
        print(f"\n== {self.title} ({rounds} rounds, interleaved)", flush=True)
        stopped = set()
        rows = {name: [] for name in self.tools}
        for n in self.sizes:
            runs = {}
            for name, (setup, max_size, _) in self.tools.items():
                if name in stopped or (max_size is not None and n > max_size):
                    continue
                try:
                    runs[name] = setup(n)
                except Exception as e:  # a peer that fails is reported, not fatal
                    print(f"   {name:34s} n={n:>9}: failed to set up: {e}", flush=True)
                    stopped.add(name)
            outcome, first = {}, {}
            for name in list(runs):
                try:
                    t0 = time.perf_counter()
                    outcome[name] = runs[name].go()
                    first[name] = time.perf_counter() - t0
                except Exception as e:
                    print(f"   {name:34s} n={n:>9}: failed: {e}", flush=True)
                    stopped.add(name)
                    del runs[name]
            self.check(n, runs, outcome)
            errors = {name: runs[name].error(outcome[name]) for name in runs}
            del outcome
            names = list(runs)
            samples = {name: [] for name in names}
            for r in range(rounds):
                shift = r % len(names) if names else 0
                for name in names[shift:] + names[:shift]:
                    t0 = time.perf_counter()
                    runs[name].go()
                    samples[name].append(time.perf_counter() - t0)
            for name in names:
                t = statistics.median(samples[name])
                rows[name].append((n, t, errors[name]))
                print(
                    f"   {name:34s} n={n:>9}: {t * 1e3:10.3f} ms   error {errors[name]:.2e}",
                    flush=True,
                )
                if first[name] > BUDGET:
                    stopped.add(name)
        for name, r in rows.items():
            if r:
                sizes, times, errors = zip(*r)
                self.results[name] = {
                    "sizes": list(sizes),
                    "median_s": list(times),
                    "max_error": list(errors),
                    "exponent": exponent(sizes, times),
                }

    def summary(self):
        karkas_tools = [k for k in self.results if k.startswith("karkas")]
        peers = [k for k in self.results if not k.startswith(("karkas", "store"))]
        out = {
            "title": self.title,
            "unit": self.unit,
            "tools": self.results,
            "ratios": {},
            "agree_tol": self.agree_tol,
            "error_tol": self.error_tol,
            "checks": self.checks,
            "table": self.table(),
        }
        store = self.results.get("store limit (NumPy fill)")
        if store:
            for k in karkas_tools:
                mine = self.results[k]
                n = mine["sizes"][-1]
                if n in store["sizes"]:
                    out[f"times the store limit: {k}"] = {
                        "size": n,
                        "ratio": mine["median_s"][-1] / store["median_s"][store["sizes"].index(n)],
                    }
        for k in karkas_tools:
            mine = self.results[k]
            for p in peers:
                theirs = self.results[p]
                common = sorted(set(mine["sizes"]) & set(theirs["sizes"]))
                if not common:
                    continue
                n = common[-1]
                ratio = theirs["median_s"][theirs["sizes"].index(n)] / mine["median_s"][
                    mine["sizes"].index(n)
                ]
                out["ratios"][f"{p} / {k}"] = {"size": n, "ratio": ratio}
        return out

    def table(self):
        """Rows of the final table: the first karkas tool against the fastest peer at the
        table sizes."""
        mine = next((k for k in self.results if k.startswith("karkas")), None)
        peers = [k for k in self.results if not k.startswith(("karkas", "store"))]
        rows = []
        if mine is None:
            return rows

        def at(name, n):
            r = self.results[name]
            return r["median_s"][r["sizes"].index(n)] if n in r["sizes"] else None

        for n in self.table_sizes:
            t = at(mine, n)
            if t is None:
                continue
            timed_peers = [(at(p, n), p) for p in peers if at(p, n) is not None]
            best = min(timed_peers) if timed_peers else (None, None)
            rows.append(
                {"size": n, "karkas": mine, "karkas_s": t, "peer": best[1], "peer_s": best[0],
                 "ratio": None if best[0] is None else best[0] / t}
            )
        return rows


def exponent(sizes, times):
    """The slope p of log(time) against log(size) (least squares); None below 3 sizes."""
    if len(sizes) < 3:
        return None
    return float(np.polyfit(np.log(sizes), np.log(times), 1)[0])


# ---------------------------------------------------------------------------------------------
# The jobs


class SizeCache:
    """The data of the current size, shared by the tools (one size held at a time)."""

    def __init__(self, make):
        self.make, self.n, self.value = make, None, None

    def __call__(self, n):
        if n != self.n:
            self.value = None
            self.n, self.value = n, self.make(n)
        return self.value


def occ_points(pts, handle=False):
    """The points as Open CASCADE's array (1-based), built outside any timing."""
    arr = HArray1_gp_Pnt(1, len(pts)) if handle else TColgp_Array1OfPnt(1, len(pts))
    for i, (x, y, z) in enumerate(np.asarray(pts).tolist()):
        arr.SetValue(i + 1, gp_Pnt(x, y, z))
    return arr


def occ_values(curve, params):
    out = np.empty((len(params), 3))
    for i, u in enumerate(params):
        p = curve.Value(float(u))
        out[i] = (p.X(), p.Y(), p.Z())
    return out


def midpoints(knots, count):
    """About `count` parameters halfway between consecutive knots (the common parameters of
    two interpolants: at the knots they agree by construction)."""
    step = max(1, (len(knots) - 1) // count)
    k = np.asarray(knots)
    return 0.5 * (k[:-1:step] + k[1::step])


def curve_eval_job(sizes, knots_n, with_derivative, max_size=None):
    pts = open_curve(knots_n)
    t = chord_parameters(pts)
    mine = karkas.CubicSpline(pts, parameterization="chord", bc="not-a-knot")
    cs = CubicSpline(t, pts, bc_type="not-a-knot", axis=0)
    bs = make_interp_spline(t, pts, k=3)
    tck = (bs.t, [bs.c[:, k] for k in range(3)], 3)
    lo, hi = mine.domain
    params = SizeCache(lambda m: np.linspace(lo, hi, m))

    suffix = " + 1st derivative" if with_derivative else ""
    job = Job(
        "curve_eval_d1" if with_derivative else "curve_eval",
        f"evaluate a 3-D cubic spline (1000 points) at m sorted parameters{suffix}",
        "parameters",
        sizes,
        agree_tol=1e-10,
        error_tol=1e-10,
    )

    def sampled(ts):
        return max(1, len(ts) // 100_000)

    def error(ts, value, d1):
        step = sampled(ts)
        ref = cs(ts[::step])
        e = np.max(np.abs(value[::step] - ref))
        if with_derivative:
            ref_d1 = cs(ts[::step], 1)
            e = max(e, np.max(np.abs(d1[::step] - ref_d1)) / np.max(np.abs(ref_d1)))
        return float(e)

    def values(ts, value, d1):
        step = sampled(ts)
        parts = [value[::step]] + ([d1[::step]] if with_derivative else [])
        return np.concatenate(parts, axis=1)

    def runner(m, go):
        ts = params(m)
        return Run(lambda: go(ts), lambda r: error(ts, *r), lambda r: values(ts, *r))

    def setup_karkas(m):
        out = np.empty((m, 3))
        d1 = np.empty((m, 3)) if with_derivative else None

        def go(ts):
            mine(ts, out=out)
            if with_derivative:
                mine(ts, 1, out=d1)
            return out, d1

        return runner(m, go)

    def setup_cs(m):
        return runner(m, lambda ts: (cs(ts), cs(ts, 1) if with_derivative else None))

    def setup_bspline(m):
        return runner(m, lambda ts: (bs(ts), bs(ts, 1) if with_derivative else None))

    def setup_splev(m):
        def go(ts):
            v = np.column_stack(splev(ts, tck))
            d = np.column_stack(splev(ts, tck, der=1)) if with_derivative else None
            return v, d

        return runner(m, go)

    def setup_store(m):
        arr = np.empty((m * (2 if with_derivative else 1), 3))
        arr.fill(0.0)
        return Run(lambda: arr.fill(1.0), lambda r: 0.0)

    job.tool("karkas CubicSpline (out=)", setup_karkas)
    job.tool("SciPy CubicSpline", setup_cs)
    job.tool("SciPy BSpline.__call__", setup_bspline)
    job.tool("SciPy splev", setup_splev, max_size)
    job.tool("store limit (NumPy fill)", setup_store)
    return job


def curve_interp_job(sizes, geomdl_max, occ_max):
    data = SizeCache(open_curve)
    job = Job(
        "curve_interp",
        "interpolate n 3-D points (chord length, not-a-knot)",
        "points",
        sizes,
        agree_tol=1e-9,
        error_tol=1e-9,
    )

    def data_error(evaluate, pts):
        step = max(1, len(pts) // 20_000)
        return float(np.max(np.abs(evaluate(step) - pts[::step])))

    def at_midpoints(n):
        return midpoints(chord_parameters(data(n)), 2000)

    def setup_karkas(n):
        pts = data(n)
        mid = at_midpoints(n)

        def error(c):
            knots = c.breakpoints
            return data_error(lambda s: c(knots[::s]), pts)

        return Run(
            lambda: karkas.CubicSpline(pts, parameterization="chord", bc="not-a-knot"),
            error,
            lambda c: c(mid),
        )

    def setup_ll(n):
        pts = data(n)

        def error(c):
            lo, hi = c.domain  # the nodes sit at equal steps from end to end
            nodes = np.linspace(lo, hi, n)
            return data_error(lambda s: c(nodes[::s]), pts)

        return Run(lambda: karkas.LLCurve.interpolate(pts, order=5), error)

    def setup_scipy(make):
        def setup(n):
            pts = data(n)
            mid = at_midpoints(n)

            def go():
                t = chord_parameters(pts)
                return t, make(t, pts)

            def error(r):
                knots, c = r
                return data_error(lambda s: c(knots[::s]), pts)

            return Run(go, error, lambda r: r[1](mid))

        return setup

    def setup_geomdl(n):
        pts = data(n).tolist()

        def error(c):
            u = chord_parameters(np.array(pts))
            u = u / u[-1]
            step = max(1, n // 200)
            ev = np.array(c.evaluate_list(list(u[::step])))
            return float(np.max(np.abs(ev - np.array(pts)[::step])))

        return Run(lambda: geomdl_fitting.interpolate_curve(pts, 3), error)

    def setup_occ(n):
        pts = data(n)
        arr = occ_points(pts)

        def go():
            return GeomAPI_PointsToBSpline(
                arr,
                Approx_ParametrizationType.Approx_ChordLength,
                3,
                3,
                GeomAbs_Shape.GeomAbs_C2,
                OCC_TOLERANCE,
            ).Curve()

        def error(c):
            step = max(1, n // 200)
            err = 0.0
            for p in pts[::step]:
                err = max(err, GeomAPI_ProjectPointOnCurve(gp_Pnt(*p), c).LowerDistance())
            return err

        return Run(go, error)

    def setup_occ_interpolate(n):
        pts = data(n)
        arr = occ_points(pts, handle=True)
        knots = chord_parameters(pts)

        def go():
            interpolation = GeomAPI_Interpolate(arr, False, OCC_POINT_TOLERANCE)
            interpolation.Perform()
            return interpolation.Curve()

        def error(c):
            step = max(1, n // 2000)
            return float(np.max(np.abs(occ_values(c, knots[::step]) - pts[::step])))

        return Run(go, error)

    job.tool("karkas CubicSpline", setup_karkas)
    job.tool("karkas LLCurve.interpolate (L=5)", setup_ll)
    job.tool(
        "SciPy CubicSpline",
        setup_scipy(lambda t, p: CubicSpline(t, p, bc_type="not-a-knot", axis=0)),
    )
    job.tool("SciPy make_interp_spline", setup_scipy(lambda t, p: make_interp_spline(t, p, k=3)))
    if geomdl_fitting is not None:
        job.tool("geomdl interpolate_curve", setup_geomdl, geomdl_max)
    if GeomAPI_PointsToBSpline is not None:
        # An approximation to its tolerance (1e-6), not an interpolant: its distance from the
        # points is checked, within 10x its tolerance.
        job.tool("OCC GeomAPI_PointsToBSpline", setup_occ, occ_max, error_tol=10 * OCC_TOLERANCE)
    if GeomAPI_Interpolate is not None:
        # The C^2 cubic through the points at the same chord-length parameters, but with a
        # knot at every point and other end conditions than not-a-knot (it departs from
        # karkas's curve near the ends only): checked by its error at the points.
        job.tool("OCC GeomAPI_Interpolate", setup_occ_interpolate)
    return job


def closed_interp_job(sizes, table_sizes=None):
    data = SizeCache(closed_curve)
    job = Job(
        "closed_interp",
        "interpolate n points of a closed 3-D curve",
        "points",
        sizes,
        agree_tol=1e-9,
        error_tol=1e-9,
        table_sizes=table_sizes,
    )

    def closed_knots(pts):
        return chord_parameters(np.vstack((pts, pts[:1])))

    def setup_karkas(n):
        pts = data(n)
        mid = midpoints(closed_knots(pts), 2000)

        def error(c):
            return float(np.max(np.abs(c(c.breakpoints[:-1]) - pts)))

        return Run(
            lambda: karkas.CubicSpline(pts, parameterization="chord", bc="periodic"),
            error,
            lambda c: c(mid),
        )

    def setup_dps(n):
        pts = data(n)
        return Run(
            lambda: karkas.DiscreteSpline.interpolate(pts, order=3, n=10),
            lambda s: float(np.max(np.abs(s.values()[::10] - pts))),
        )

    def setup_cs(n):
        pts = data(n)
        mid = midpoints(closed_knots(pts), 2000)

        def go():
            closed = np.vstack((pts, pts[:1]))
            t = chord_parameters(closed)
            return t, CubicSpline(t, closed, bc_type="periodic", axis=0)

        def error(r):
            knots, c = r
            return float(np.max(np.abs(c(knots[:-1]) - pts)))

        return Run(go, error, lambda r: r[1](mid))

    def setup_occ(n):
        # The periodic C^2 cubic through the points with chord-length parameters from 0: the
        # same curve as the periodic CubicSpline.
        pts = data(n)
        arr = occ_points(pts, handle=True)
        knots = closed_knots(pts)
        mid = midpoints(knots, 2000)

        def go():
            interpolation = GeomAPI_Interpolate(arr, True, OCC_POINT_TOLERANCE)
            interpolation.Perform()
            return interpolation.Curve()

        def error(c):
            step = max(1, n // 2000)
            return float(np.max(np.abs(occ_values(c, knots[:-1:step]) - pts[::step])))

        return Run(go, error, lambda c: occ_values(c, mid))

    job.tool("karkas CubicSpline periodic", setup_karkas)
    job.tool("karkas DiscreteSpline (r=3, n=10)", setup_dps)
    job.tool("SciPy CubicSpline periodic", setup_cs)
    if GeomAPI_Interpolate is not None:
        # Its periodic curve has a double knot at the seam (C^1 there, C^2 elsewhere): near
        # the seam it departs from the C^2 spline by O(h^4) (2e-8 at 1000 points, 2e-12 at
        # 10^4), elsewhere they agree to rounding.
        job.tool("OCC GeomAPI_Interpolate periodic", setup_occ, agree_tol=1e-6)
    return job


def smoothing_fit_job(sizes, sigma):
    truth = cKDTree(spiral(np.linspace(0.0, 1.0, 2_000_001)))
    # Seeded by the size: every tool gets the same points for a size.
    data = SizeCache(lambda n: noisy_spiral(n, sigma, np.random.default_rng([7, n])))

    def deviation(curve_points):
        """The largest distance of a dense sample of the fit from the true spiral."""
        d, _ = truth.query(curve_points)
        return float(np.max(d))

    # Different fits of the same points: each must lie within 10 sigma of the true curve.
    job = Job(
        "smoothing_fit",
        f"smoothing fit of n noisy 2-D points (sigma {sigma:g}); error = max distance from the truth",
        "points",
        sizes,
        agree_tol=None,
        error_tol=10 * sigma,
    )

    knot_count = {}

    def fitpack_knots(n):
        """The number of inner knots FITPACK chooses for s = 2 n sigma^2 (n points, 2-D)."""
        if n not in knot_count:
            tck, _ = splprep(data(n).T, s=n * 2 * sigma**2)
            knot_count[n] = len(tck[0]) - 6
        return knot_count[n]

    def setup_karkas(n):
        pts = data(n)
        k = fitpack_knots(n)

        def error(f):
            lo, hi = f.domain
            return deviation(f(np.linspace(lo, hi, 20_000)))

        return Run(lambda: karkas.fit_curve(pts, knots=k), error)

    def setup_splprep(n):
        pts = data(n)
        s = n * 2 * sigma**2  # FITPACK's smoothing: s = sum of squared residuals, 2 coordinates

        def error(r):
            tck, _ = r
            return deviation(np.column_stack(splev(np.linspace(0, 1, 20_000), tck)))

        return Run(lambda: splprep(pts.T, s=s), error)

    job.tool("karkas fit_curve (uniform knots, as many as FITPACK)", setup_karkas)
    job.tool("SciPy splprep (s = 2 n sigma^2)", setup_splprep)
    return job


def bicubic_job(sizes, occ_max):
    data = SizeCache(lambda nn: sheet(int(round(nn**0.5))))

    job = Job(
        "bicubic_interp",
        "interpolate an n x n grid of 3-D points (chord parameters)",
        "nodes",
        sizes,
        agree_tol=1e-9,
        error_tol=1e-9,
    )

    def node_error(evaluate, grid):
        step = max(1, grid.shape[0] // 100)
        return float(np.max(np.abs(evaluate(step) - grid[::step, ::step])))

    def common(grid):
        u, v = grid_chord_parameters(grid)
        return midpoints(u, 100), midpoints(v, 100)

    def setup_karkas(nn):
        grid = data(nn)
        u, v = grid_chord_parameters(grid)
        mu, mv = common(grid)
        return Run(
            lambda: karkas.BicubicSurface(grid, parameterization="chord"),
            lambda S: node_error(lambda s: S(u[::s], v[::s]), grid),
            lambda S: S(mu, mv),
        )

    def setup_rbs(nn):
        grid = data(nn)
        mu, mv = common(grid)

        def go():
            u, v = grid_chord_parameters(grid)
            return u, v, [RectBivariateSpline(u, v, grid[:, :, k], s=0) for k in range(3)]

        def error(r):
            u, v, fs = r
            return node_error(
                lambda s: np.stack([f(u[::s], v[::s]) for f in fs], axis=-1), grid
            )

        return Run(go, error, lambda r: np.stack([f(mu, mv) for f in r[2]], axis=-1))

    def setup_occ(nn):
        grid = data(nn)
        n = grid.shape[0]
        arr = TColgp_Array2OfPnt(1, n, 1, n)
        for i in range(n):
            for j in range(n):
                arr.SetValue(i + 1, j + 1, gp_Pnt(*grid[i, j]))

        def go():
            return GeomAPI_PointsToBSplineSurface(
                arr, 3, 3, GeomAbs_Shape.GeomAbs_C2, OCC_TOLERANCE
            ).Surface()

        def error(S):
            step = max(1, n // 20)
            err = 0.0
            for i in range(0, n, step):
                for j in range(0, n, step):
                    err = max(
                        err, GeomAPI_ProjectPointOnSurf(gp_Pnt(*grid[i, j]), S).LowerDistance()
                    )
            return err

        return Run(go, error)

    job.tool("karkas BicubicSurface", setup_karkas)
    job.tool("SciPy RectBivariateSpline (x, y, z)", setup_rbs)
    if GeomAPI_PointsToBSpline is not None:
        # An approximation to its tolerance (1e-6): its distance from the nodes is checked.
        job.tool("OCC GeomAPI_PointsToBSplineSurface", setup_occ, occ_max, error_tol=10 * OCC_TOLERANCE)
    return job


def bicubic_eval_job(sizes, grid_n):
    grid = sheet(grid_n)
    u, v = grid_chord_parameters(grid)
    S = karkas.BicubicSurface(grid, parameterization="chord")
    fs = [RectBivariateSpline(u, v, grid[:, :, k], s=0) for k in range(3)]
    job = Job(
        "bicubic_eval",
        f"evaluate the {grid_n} x {grid_n} bicubic surface on an m x m grid",
        "values",
        sizes,
        agree_tol=1e-9,
        error_tol=1e-9,
    )

    def axes(mm):
        m = int(round(mm**0.5))
        return np.linspace(u[0], u[-1], m), np.linspace(v[0], v[-1], m)

    def sampled(r, us):
        s = max(1, len(us) // 200)
        return r[::s, ::s]

    def setup_karkas(mm):
        us, vs = axes(mm)
        out = np.empty((len(us), len(vs), 3))

        def error(r):
            s = max(1, len(us) // 200)
            ref = np.stack([f(us[::s], vs[::s]) for f in fs], axis=-1)
            return float(np.max(np.abs(r[::s, ::s] - ref)))

        def go():
            S(us, vs, grid=True, out=out)
            return out

        return Run(go, error, lambda r: sampled(r, us))

    def setup_rbs(mm):
        us, vs = axes(mm)
        return Run(
            lambda: [f(us, vs) for f in fs],
            lambda r: 0.0,
            lambda r: sampled(np.stack(r, axis=-1), us),
        )

    def setup_store(mm):
        arr = np.empty((mm, 3))
        arr.fill(0.0)
        return Run(lambda: arr.fill(1.0), lambda r: 0.0)

    job.tool("karkas BicubicSurface (out=)", setup_karkas)
    job.tool("SciPy RectBivariateSpline (x, y, z)", setup_rbs)
    job.tool("store limit (NumPy fill)", setup_store)
    return job


# ---------------------------------------------------------------------------------------------
# The binding's own costs


def one_point_overhead(rounds, calls):
    """Median seconds per call of evaluating ONE point, karkas against SciPy, interleaved.

    The same 1000-point 3-D interpolant three ways: karkas CubicSpline (chord parameters,
    not-a-knot), SciPy BSpline from make_interp_spline (the same cubic: not-a-knot is its default
    for k=3) and SciPy CubicSpline. Their values at the point are checked equal (1e-12) before
    any timing. Each round times `calls` calls of each tool in turn, the order rotating from
    round to round, so that drift of the machine hits every tool alike.
    """
    pts = open_curve(1000)
    t = chord_parameters(pts)
    x = float(0.37 * t[-1])
    tools = {
        "karkas CubicSpline c(x)": karkas.CubicSpline(pts, t=t, bc="not-a-knot"),
        "SciPy BSpline bs(x)": make_interp_spline(t, pts, k=3),
        "SciPy CubicSpline cs(x)": CubicSpline(t, pts, bc_type="not-a-knot", axis=0),
    }
    reference = tools["SciPy CubicSpline cs(x)"](x)
    for name, f in tools.items():
        value = f(x)
        if value.shape != reference.shape or not np.allclose(value, reference, rtol=0, atol=1e-12):
            raise AssertionError(f"{name} gives {value}, SciPy CubicSpline {reference}")
    names = list(tools)
    samples = {name: [] for name in names}
    for r in range(rounds):
        for name in names[r % len(names):] + names[: r % len(names)]:
            f = tools[name]
            t0 = time.perf_counter()
            for _ in range(calls):
                f(x)
            samples[name].append((time.perf_counter() - t0) / calls)
    medians = {name: statistics.median(v) for name, v in samples.items()}
    print(f"\n== call overhead on one point ({rounds} rounds x {calls} calls, interleaved)")
    for name, m in medians.items():
        print(f"   {name:34s} {m * 1e9:9.0f} ns per call")
    ratio = medians["karkas CubicSpline c(x)"] / medians["SciPy BSpline bs(x)"]
    print(f"   karkas / BSpline: {ratio:.2f} (goal: at most 2)")
    return {"rounds": rounds, "calls": calls, "median_s": medians, "karkas_over_bspline": ratio}


RUST_1E7 = "ll_curve_eval_L5_3d_1e7/sorted/1000"


def ll_polygon(k):
    """The wavy 3-D polygon of bench/benches/ll.rs (point i at s = 0.01 i)."""
    s = np.arange(k) * 0.01
    return np.column_stack(
        [np.cos(s) * (1.0 + 0.3 * np.sin(7.0 * s)), np.sin(s), 0.2 * np.cos(3.0 * s)]
    )


def python_vs_rust(runs, run_rust):
    """10^7 points of an LL curve (order 5, 1000 points, 3-D) from Python with out= against
    the Rust benchmark of the same job (its Criterion median)."""
    root = os.path.dirname(HERE)
    if run_rust:
        subprocess.run(
            ["cargo", "bench", "-p", "karkas-bench", "--bench", "ll", "--", "ll_curve_eval_L5_3d_1e7"],
            cwd=root,
            check=True,
        )
    n = 10_000_000
    curve = karkas.LLCurve(ll_polygon(1000), order=5)
    a, b = curve.domain
    ts = np.linspace(a, b, n)
    out = np.empty((n, 3))
    curve(ts, out=out)  # first touch of the buffer's pages
    py, _ = timed(lambda: curve(ts, out=out), runs)
    print("\n== 10^7 points of an LL curve (L=5, 1000 points, 3-D), out=")
    print(f"   Python c(t, out=)                  {py * 1e3:9.2f} ms (median of {runs})")
    result = {"python_s": py, "rust_s": None, "python_over_rust": None}
    estimates = os.path.join(root, "target", "criterion", *RUST_1E7.split("/"), "new", "estimates.json")
    if os.path.exists(estimates):
        with open(estimates) as f:
            rust = json.load(f)["median"]["point_estimate"] * 1e-9
        result.update(rust_s=rust, python_over_rust=py / rust)
        print(f"   Rust eval_into (Criterion median)  {rust * 1e3:9.2f} ms")
        print(f"   Python / Rust: {py / rust:.3f} (goal: at most 1.1)")
    else:
        print(f"   no Rust figure: run with --run-rust, or `cargo bench -p karkas-bench --bench ll "
              f"-- ll_curve_eval_L5_3d_1e7` first")
    return result


# ---------------------------------------------------------------------------------------------


def plot(job, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, r in job.results.items():
        p = r["exponent"]
        label = name if p is None else f"{name} (p = {p:.2f})"
        style = "o-" if name.startswith("karkas") else ("k:" if name.startswith("store") else "s--")
        ax.loglog(r["sizes"], r["median_s"], style, label=label)
    ax.set_xlabel(job.unit)
    ax.set_ylabel("median time [s]")
    ax.set_title(job.title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def job_set(quick):
    """The jobs at full sizes (the largest and the one 10x smaller go into the final table)
    or at small sizes (--quick)."""
    if quick:
        return [
            curve_eval_job([10_000, 30_000, 100_000], 1000, False),
            curve_eval_job([10_000, 30_000, 100_000], 1000, True),
            curve_interp_job([100, 1_000, 10_000], 100, 1_000),
            closed_interp_job([1_000, 3_000, 10_000]),
            smoothing_fit_job([1_000, 3_000, 10_000], 2.9e-4),
            bicubic_job([50**2, 100**2, 200**2], 50**2),
            bicubic_eval_job([100**2, 200**2, 400**2], 200),
        ]
    return [
        curve_eval_job([100_000, 1_000_000, 3_000_000, 10_000_000], 1000, False, 3_000_000),
        curve_eval_job([100_000, 1_000_000, 3_000_000, 10_000_000], 1000, True, 3_000_000),
        curve_interp_job([100, 300, 1_000, 10_000, 100_000, 300_000, 1_000_000], 300, 1_000),
        # 10^5 is the size of the closed-curve job: in the table too.
        closed_interp_job(
            [1_000, 10_000, 30_000, 100_000, 300_000], table_sizes=[300_000, 100_000, 30_000]
        ),
        smoothing_fit_job([3_000, 10_000, 30_000, 100_000], 2.9e-4),
        bicubic_job([125**2, 250**2, 316**2, 500**2, 1000**2], 125**2),
        bicubic_eval_job([250**2, 500**2, 632**2, 1000**2, 2000**2], 1000),
    ]


def machine():
    return {
        "platform": platform.platform(),
        "processor": platform.processor() or platform.machine(),
        "cpus": os.cpu_count(),
        "python": sys.version.split()[0],
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "karkas": karkas.__version__,
        "geomdl": geomdl_fitting is not None,
        "occ": GeomAPI_PointsToBSpline is not None,
        "rayon_num_threads": os.environ.get("RAYON_NUM_THREADS"),
        "load_average": os.getloadavg(),
    }


def run_jobs(args, rounds):
    """The jobs in this process (RAYON_NUM_THREADS as this process was started with)."""
    quick = args.quick
    jobs = job_set(quick)
    if args.jobs:
        wanted = set(args.jobs.split(","))
        jobs = [j for j in jobs if j.name in wanted]
    t0 = time.perf_counter()
    for job in jobs:
        job.run(rounds)
    binding = None
    if not args.jobs and not args.no_binding:
        binding = {
            "one_point_overhead": one_point_overhead(args.overhead_rounds, args.calls),
            "python_vs_rust_1e7": python_vs_rust(3 if quick else 15, args.run_rust),
        }
    results = {
        "machine": machine(),
        "quick": quick,
        "rounds": rounds,
        "timing": TIMING,
        "jobs": {},
        "binding": binding,
    }
    if args.plots:
        os.makedirs(args.plots, exist_ok=True)
    print("\n== ratios peer / karkas at the largest common size (> 1: karkas faster)")
    for job in jobs:
        s = job.summary()
        results["jobs"][job.name] = s
        if args.plots:
            plot(job, os.path.join(args.plots, f"{job.name}.png"))
        for key, r in s["ratios"].items():
            print(f"   {job.name:15s} {key:70s} n={r['size']:>9}: {r['ratio']:7.2f}")
    print("\n== fitted exponents p (time ~ size^p)")
    for job in jobs:
        for name, r in job.results.items():
            if r["exponent"] is not None:
                print(f"   {job.name:15s} {name:40s} {r['exponent']:5.2f}")
    disagree = [(job.name, c) for job in jobs for c in job.disagreements]
    results["disagreements"] = len(disagree)
    print(f"\nran the jobs in {time.perf_counter() - t0:.0f} s")
    return results


TIMING = (
    "the input arrays (NumPy arrays; Open CASCADE's TColgp arrays of gp_Pnt) are built before "
    "the timing for every tool; everything from them to the finished result is timed "
    "(SciPy's chord-length parameters included, as karkas computes its own)"
)


def final_table(by_threads):
    """One table: job, size, threads, karkas median, fastest peer and its median, ratio."""
    rows = []
    for threads, results in sorted(by_threads.items()):
        for name, job in results["jobs"].items():
            for r in job["table"]:
                rows.append((name, r["size"], threads, r))
    rows.sort(key=lambda x: (list(by_threads[x[2]]["jobs"]).index(x[0]), -x[1], x[2]))
    lines = [
        "| job | size | threads | karkas | median | fastest peer | median | ratio | >= 3x |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for name, n, threads, r in rows:
        if r["peer"] is None:
            peer, pt, ratio, ok = "(none timed)", "—", "—", "—"
        else:
            peer, pt = r["peer"], f"{r['peer_s'] * 1e3:.3g} ms"
            ratio, ok = f"{r['ratio']:.2f}", ("yes" if r["ratio"] >= 3 else "NO")
        lines.append(
            f"| {name} | {n:,} | {threads} | {r['karkas']} | {r['karkas_s'] * 1e3:.3g} ms | "
            f"{peer} | {pt} | {ratio} | {ok} |"
        )
    return "\n".join(lines)


def child_run(args, threads, path):
    """This script again in a fresh process with RAYON_NUM_THREADS set before karkas is
    imported (rayon reads it once); its results go to `path`."""
    argv = [sys.executable, os.path.abspath(__file__), "--child", "--out", path]
    if args.quick:
        argv.append("--quick")
    if args.jobs:
        argv += ["--jobs", args.jobs]
    if args.rounds is not None:
        argv += ["--rounds", str(args.rounds)]
    argv += ["--overhead-rounds", str(args.overhead_rounds), "--calls", str(args.calls)]
    if args.run_rust:
        argv.append("--run-rust")
    # The binding checks once, on the most threads; plots likewise.
    if threads != max(args.threads) or args.no_binding:
        argv.append("--no-binding")
    if threads == max(args.threads) and args.plots:
        argv += ["--plots", args.plots]
    else:
        argv += ["--plots", ""]
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    print(f"\n######## {threads} thread(s): RAYON_NUM_THREADS={threads}", flush=True)
    return subprocess.run(argv, env=env).returncode


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes: a smoke run")
    ap.add_argument(
        "--rounds",
        type=int,
        default=None,
        help="interleaved timing rounds per job and size (default 9, --quick 3); with "
        "--overhead alone: the rounds of the one-point overhead",
    )
    ap.add_argument("--repeats", type=int, default=None, help="the same as --rounds (older name)")
    ap.add_argument(
        "--threads",
        default=None,
        help="comma-separated RAYON_NUM_THREADS values, each run in its own process "
        "(default 1,2; the machine's cores in place of 2 if it has more)",
    )
    ap.add_argument("--jobs", default=None, help="comma-separated job names to run")
    ap.add_argument("--overhead", action="store_true", help="only the one-point call overhead")
    ap.add_argument("--overhead-rounds", type=int, default=15, help="rounds of the overhead")
    ap.add_argument("--calls", type=int, default=20_000, help="calls per tool and round")
    ap.add_argument(
        "--python-vs-rust", action="store_true", help="only 10^7 points from Python against Rust"
    )
    ap.add_argument(
        "--run-rust", action="store_true", help="run the Rust benchmark first (cargo bench)"
    )
    ap.add_argument("--no-binding", action="store_true", help="skip the two binding checks")
    ap.add_argument("--out", default=os.path.join(HERE, "results.json"))
    ap.add_argument("--plots", default=os.path.join(HERE, "plots"))
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.rounds is None:
        args.rounds = args.repeats
    if args.overhead or args.python_vs_rust:
        if args.overhead:
            one_point_overhead(args.rounds or args.overhead_rounds, args.calls)
        if args.python_vs_rust:
            python_vs_rust(args.repeats or 15, args.run_rust)
        return
    rounds = args.rounds or (3 if args.quick else 9)
    if not args.quick and rounds < 9:
        print(f"full runs take at least 9 rounds (fewer only with --quick): 9, not {rounds}")
        rounds = args.rounds = 9

    if args.child:
        results = run_jobs(args, rounds)
        with open(args.out, "w") as f:
            json.dump(results, f, indent=1)
        sys.exit(1 if results["disagreements"] else 0)

    cores = os.cpu_count() or 2
    args.threads = sorted(
        {int(x) for x in (args.threads or f"1,{max(2, cores)}").split(",")}
    )
    t0 = time.perf_counter()
    by_threads, failed = {}, []
    for threads in args.threads:
        path = f"{args.out}.{threads}threads.tmp"
        code = child_run(args, threads, path)
        if code not in (0, 1) or not os.path.exists(path):
            failed.append(threads)
            continue
        with open(path) as f:
            by_threads[threads] = json.load(f)
        os.remove(path)
        if code == 1:
            failed.append(threads)
    results = {
        "machine": machine(),
        "quick": args.quick,
        "rounds": rounds,
        "timing": TIMING,
        "threads": {str(k): v for k, v in by_threads.items()},
    }
    if by_threads:  # the layout of earlier files: the run on the most threads
        most = by_threads[max(by_threads)]
        results["jobs"], results["binding"] = most["jobs"], most["binding"]
    table = final_table(by_threads)
    results["table"] = table
    with open(args.out, "w") as f:
        json.dump(results, f, indent=1)
    print(f"\n== karkas against the fastest peer ({rounds} interleaved rounds, medians; {TIMING})")
    print(table)
    disagreements = [
        (t, name, c)
        for t, r in by_threads.items()
        for name, job in r["jobs"].items()
        for c in job["checks"]
        if not c["ok"]
    ]
    for t, name, c in disagreements:
        what = f"{c['tool']} vs {c['peer']}" if c["peer"] else c["tool"]
        print(f"DISAGREE ({t} thread(s)) {name} n={c['size']}: {what}: {c['measure']} "
              f"{c['value']:.3e} > {c['tolerance']:.1e}")
    print(f"\nwrote {args.out} in {time.perf_counter() - t0:.0f} s")
    if failed or disagreements:
        sys.exit(1)


if __name__ == "__main__":
    main()
