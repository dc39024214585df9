#!/usr/bin/env python3
"""karkas side by side with SciPy, geomdl and Open CASCADE on the same jobs, in one process.

For every job and size, each tool runs on the same data; the median of several runs is kept,
with the accuracy of the result (the largest error against the data or a reference). Writes
bench/results.json and one log-log plot per job into bench/plots/, prints a table with the
ratios peer/karkas at the largest size and the fitted cost exponents (time ~ size^p).

Needs: the karkas Python package (`pip install ./crates/karkas-py`), numpy, scipy,
matplotlib; optional: geomdl (`pip install geomdl`), Open CASCADE (`pip install cadquery-ocp`).

    python3 bench/compare.py            # full sizes (several minutes)
    python3 bench/compare.py --quick    # small sizes, a smoke run (well under a minute)
    python3 bench/compare.py --overhead # only the call overhead on one point (seconds)
    python3 bench/compare.py --python-vs-rust [--run-rust]  # only 10^7 points, Python vs Rust

Besides the jobs, two checks of the Python binding itself (both in every full run):

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
        GeomAPI_PointsToBSpline,
        GeomAPI_PointsToBSplineSurface,
        GeomAPI_ProjectPointOnCurve,
        GeomAPI_ProjectPointOnSurf,
    )
    from OCP.gp import gp_Pnt

    try:  # OCP >= 7.8
        from OCP.collections import Array1_gp_Pnt as TColgp_Array1OfPnt
        from OCP.collections import Array2_gp_Pnt as TColgp_Array2OfPnt
    except ImportError:
        from OCP.TColgp import TColgp_Array1OfPnt, TColgp_Array2OfPnt
except ImportError:  # optional peer
    GeomAPI_PointsToBSpline = None

# Open CASCADE's approximation tolerance (3-D distance) for its interpolation-like fits.
OCC_TOLERANCE = 1e-6

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


def store_limit(m, repeats):
    """Seconds to fill an (m, 3) float64 array with NumPy: the streaming-store limit."""
    arr = np.empty((m, 3))
    arr.fill(0.0)
    t, _ = timed(lambda: arr.fill(1.0), repeats)
    return t


class Job:
    """One job: sizes, tools (name -> callable(size) -> (time, error)) and the results."""

    def __init__(self, name, title, unit, sizes):
        self.name, self.title, self.unit, self.sizes = name, title, unit, sizes
        self.tools = {}
        self.results = {}

    def tool(self, name, run, max_size=None):
        self.tools[name] = (run, max_size)

    def run(self, repeats):
        print(f"\n== {self.title}", flush=True)
        for name, (run, max_size) in self.tools.items():
            rows = []
            for n in self.sizes:
                if max_size is not None and n > max_size:
                    continue
                try:
                    t, err = run(n, repeats)
                except Exception as e:  # a peer that fails is reported, not fatal
                    print(f"   {name:34s} n={n:>9}: failed: {e}", flush=True)
                    break
                rows.append((n, t, err))
                print(
                    f"   {name:34s} n={n:>9}: {t * 1e3:10.3f} ms   error {err:.2e}",
                    flush=True,
                )
                if t > BUDGET:
                    break
            if rows:
                sizes, times, errors = zip(*rows)
                self.results[name] = {
                    "sizes": list(sizes),
                    "median_s": list(times),
                    "max_error": list(errors),
                    "exponent": exponent(sizes, times),
                }

    def summary(self):
        karkas_tools = [k for k in self.results if k.startswith("karkas")]
        peers = [k for k in self.results if not k.startswith(("karkas", "store"))]
        out = {"title": self.title, "unit": self.unit, "tools": self.results, "ratios": {}}
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


def exponent(sizes, times):
    """The slope p of log(time) against log(size) (least squares); None below 3 sizes."""
    if len(sizes) < 3:
        return None
    return float(np.polyfit(np.log(sizes), np.log(times), 1)[0])


# ---------------------------------------------------------------------------------------------
# The jobs


def curve_eval_job(sizes, knots_n, with_derivative, max_size=None):
    pts = open_curve(knots_n)
    t = chord_parameters(pts)
    mine = karkas.CubicSpline(pts, parameterization="chord", bc="not-a-knot")
    cs = CubicSpline(t, pts, bc_type="not-a-knot", axis=0)
    bs = make_interp_spline(t, pts, k=3)
    tck = (bs.t, [bs.c[:, k] for k in range(3)], 3)
    lo, hi = mine.domain
    cache = {}

    def params(m):
        if m not in cache:
            cache.clear()
            cache[m] = np.linspace(lo, hi, m)
        return cache[m]

    suffix = " + 1st derivative" if with_derivative else ""
    job = Job(
        "curve_eval_d1" if with_derivative else "curve_eval",
        f"evaluate a 3-D cubic spline (1000 points) at m sorted parameters{suffix}",
        "parameters",
        sizes,
    )

    def reference(ts):
        return cs(ts), (cs(ts, 1) if with_derivative else None)

    def error(ts, value, d1):
        ref, ref_d1 = reference(ts[:: max(1, len(ts) // 100_000)])
        step = max(1, len(ts) // 100_000)
        e = np.max(np.abs(value[::step] - ref))
        if with_derivative:
            e = max(e, np.max(np.abs(d1[::step] - ref_d1)) / np.max(np.abs(ref_d1)))
        return float(e)

    def run_karkas(m, repeats):
        ts = params(m)
        out = np.empty((m, 3))
        d1 = np.empty((m, 3)) if with_derivative else None

        def go():
            mine(ts, out=out)
            if with_derivative:
                mine(ts, 1, out=d1)

        t, _ = timed(go, repeats)
        return t, error(ts, out, d1)

    def run_cs(m, repeats):
        ts = params(m)
        t, r = timed(lambda: (cs(ts), cs(ts, 1) if with_derivative else None), repeats)
        return t, error(ts, *r)

    def run_bspline(m, repeats):
        ts = params(m)
        t, r = timed(lambda: (bs(ts), bs(ts, 1) if with_derivative else None), repeats)
        return t, error(ts, *r)

    def run_splev(m, repeats):
        ts = params(m)

        def go():
            v = np.column_stack(splev(ts, tck))
            d = np.column_stack(splev(ts, tck, der=1)) if with_derivative else None
            return v, d

        t, r = timed(go, repeats)
        return t, error(ts, *r)

    def run_store(m, repeats):
        return store_limit(m * (2 if with_derivative else 1), repeats), 0.0

    job.tool("karkas CubicSpline (out=)", run_karkas)
    job.tool("SciPy CubicSpline", run_cs)
    job.tool("SciPy BSpline.__call__", run_bspline)
    job.tool("SciPy splev", run_splev, max_size)
    job.tool("store limit (NumPy fill)", run_store)
    return job


def curve_interp_job(sizes, geomdl_max, occ_max):
    cache = {}

    def data(n):
        if n not in cache:
            cache.clear()
            cache[n] = open_curve(n)
        return cache[n]

    job = Job(
        "curve_interp",
        "interpolate n 3-D points (chord length, not-a-knot)",
        "points",
        sizes,
    )

    def data_error(evaluate, pts):
        step = max(1, len(pts) // 20_000)
        return float(np.max(np.abs(evaluate(step) - pts[::step])))

    def run_karkas(n, repeats):
        pts = data(n)
        t, c = timed(
            lambda: karkas.CubicSpline(pts, parameterization="chord", bc="not-a-knot"), repeats
        )
        knots = c.breakpoints
        return t, data_error(lambda s: c(knots[::s]), pts)

    def run_ll(n, repeats):
        pts = data(n)
        t, c = timed(lambda: karkas.LLCurve.interpolate(pts, order=5), repeats)
        lo, hi = c.domain  # the nodes sit at equal steps from end to end
        nodes = np.linspace(lo, hi, n)
        return t, data_error(lambda s: c(nodes[::s]), pts)

    def run_cs(n, repeats):
        pts = data(n)

        def go():
            t = chord_parameters(pts)
            return t, CubicSpline(t, pts, bc_type="not-a-knot", axis=0)

        t, (knots, c) = timed(go, repeats)
        return t, data_error(lambda s: c(knots[::s]), pts)

    def run_mis(n, repeats):
        pts = data(n)

        def go():
            t = chord_parameters(pts)
            return t, make_interp_spline(t, pts, k=3)

        t, (knots, c) = timed(go, repeats)
        return t, data_error(lambda s: c(knots[::s]), pts)

    def run_geomdl(n, repeats):
        pts = data(n).tolist()
        t, c = timed(lambda: geomdl_fitting.interpolate_curve(pts, 3), 1)
        u = chord_parameters(np.array(pts))
        u = u / u[-1]
        step = max(1, n // 200)
        ev = np.array(c.evaluate_list(list(u[::step])))
        return t, float(np.max(np.abs(ev - np.array(pts)[::step])))

    def run_occ(n, repeats):
        pts = data(n)

        def go():
            arr = TColgp_Array1OfPnt(1, n)
            for i, p in enumerate(pts):
                arr.SetValue(i + 1, gp_Pnt(*p))
            return GeomAPI_PointsToBSpline(
                arr,
                Approx_ParametrizationType.Approx_ChordLength,
                3,
                3,
                GeomAbs_Shape.GeomAbs_C2,
                OCC_TOLERANCE,
            ).Curve()

        t, c = timed(go, min(repeats, 3))
        step = max(1, n // 200)
        err = 0.0
        for p in pts[::step]:
            err = max(err, GeomAPI_ProjectPointOnCurve(gp_Pnt(*p), c).LowerDistance())
        return t, err

    job.tool("karkas CubicSpline", run_karkas)
    job.tool("karkas LLCurve.interpolate (L=5)", run_ll)
    job.tool("SciPy CubicSpline", run_cs)
    job.tool("SciPy make_interp_spline", run_mis)
    if geomdl_fitting is not None:
        job.tool("geomdl interpolate_curve", run_geomdl, geomdl_max)
    if GeomAPI_PointsToBSpline is not None:
        job.tool("OCC GeomAPI_PointsToBSpline", run_occ, occ_max)
    return job


def closed_interp_job(sizes):
    cache = {}

    def data(n):
        if n not in cache:
            cache.clear()
            cache[n] = closed_curve(n)
        return cache[n]

    job = Job("closed_interp", "interpolate n points of a closed 3-D curve", "points", sizes)

    def run_karkas(n, repeats):
        pts = data(n)
        t, c = timed(lambda: karkas.CubicSpline(pts, parameterization="chord", bc="periodic"), repeats)
        knots = c.breakpoints[:-1]
        return t, float(np.max(np.abs(c(knots) - pts)))

    def run_dps(n, repeats):
        pts = data(n)
        t, s = timed(lambda: karkas.DiscreteSpline.interpolate(pts, order=3, n=10), repeats)
        return t, float(np.max(np.abs(s.values()[::10] - pts)))

    def run_cs(n, repeats):
        pts = data(n)

        def go():
            closed = np.vstack((pts, pts[:1]))
            t = chord_parameters(closed)
            return t, CubicSpline(t, closed, bc_type="periodic", axis=0)

        t, (knots, c) = timed(go, repeats)
        return t, float(np.max(np.abs(c(knots[:-1]) - pts)))

    job.tool("karkas CubicSpline periodic", run_karkas)
    job.tool("karkas DiscreteSpline (r=3, n=10)", run_dps)
    job.tool("SciPy CubicSpline periodic", run_cs)
    return job


def smoothing_fit_job(sizes, sigma):
    truth = cKDTree(spiral(np.linspace(0.0, 1.0, 2_000_001)))
    cache = {}

    def data(n):
        if n not in cache:
            cache.clear()
            # Seeded by the size: every tool gets the same points for a size.
            cache[n] = noisy_spiral(n, sigma, np.random.default_rng([7, n]))
        return cache[n]

    def deviation(curve_points):
        """The largest distance of a dense sample of the fit from the true spiral."""
        d, _ = truth.query(curve_points)
        return float(np.max(d))

    job = Job(
        "smoothing_fit",
        f"smoothing fit of n noisy 2-D points (sigma {sigma:g}); error = max distance from the truth",
        "points",
        sizes,
    )

    knot_count = {}

    def fitpack_knots(n):
        """The number of inner knots FITPACK chooses for s = 2 n sigma^2 (n points, 2-D)."""
        if n not in knot_count:
            tck, _ = splprep(data(n).T, s=n * 2 * sigma**2)
            knot_count[n] = len(tck[0]) - 6
        return knot_count[n]

    def run_karkas(n, repeats):
        pts = data(n)
        k = fitpack_knots(n)
        t, f = timed(lambda: karkas.fit_curve(pts, knots=k), repeats)
        lo, hi = f.domain
        return t, deviation(f(np.linspace(lo, hi, 20_000)))

    def run_splprep(n, repeats):
        pts = data(n)
        s = n * 2 * sigma**2  # FITPACK's smoothing: s = sum of squared residuals, 2 coordinates

        t, (tck, _) = timed(lambda: splprep(pts.T, s=s), repeats)
        return t, deviation(np.column_stack(splev(np.linspace(0, 1, 20_000), tck)))

    job.tool("karkas fit_curve (uniform knots, as many as FITPACK)", run_karkas)
    job.tool("SciPy splprep (s = 2 n sigma^2)", run_splprep)
    return job


def bicubic_job(sizes, occ_max):
    cache = {}

    def data(n):
        if n not in cache:
            cache.clear()
            cache[n] = sheet(n)
        return cache[n]

    job = Job("bicubic_interp", "interpolate an n x n grid of 3-D points (chord parameters)", "nodes", sizes)

    def node_error(evaluate, grid):
        step = max(1, grid.shape[0] // 100)
        return float(np.max(np.abs(evaluate(step) - grid[::step, ::step])))

    def run_karkas(nn, repeats):
        grid = data(int(round(nn**0.5)))
        t, S = timed(lambda: karkas.BicubicSurface(grid, parameterization="chord"), repeats)
        u, v = grid_chord_parameters(grid)
        return t, node_error(lambda s: S(u[::s], v[::s]), grid)

    def run_rbs(nn, repeats):
        grid = data(int(round(nn**0.5)))

        def go():
            u, v = grid_chord_parameters(grid)
            return u, v, [RectBivariateSpline(u, v, grid[:, :, k], s=0) for k in range(3)]

        t, (u, v, fs) = timed(go, repeats)
        return t, node_error(
            lambda s: np.stack([f(u[::s], v[::s]) for f in fs], axis=-1), grid
        )

    def run_occ(nn, repeats):
        grid = data(int(round(nn**0.5)))
        n = grid.shape[0]

        def go():
            arr = TColgp_Array2OfPnt(1, n, 1, n)
            for i in range(n):
                for j in range(n):
                    arr.SetValue(i + 1, j + 1, gp_Pnt(*grid[i, j]))
            return GeomAPI_PointsToBSplineSurface(
                arr, 3, 3, GeomAbs_Shape.GeomAbs_C2, OCC_TOLERANCE
            ).Surface()

        t, S = timed(go, min(repeats, 3))
        step = max(1, n // 20)
        err = 0.0
        for i in range(0, n, step):
            for j in range(0, n, step):
                err = max(err, GeomAPI_ProjectPointOnSurf(gp_Pnt(*grid[i, j]), S).LowerDistance())
        return t, err

    job.tool("karkas BicubicSurface", run_karkas)
    job.tool("SciPy RectBivariateSpline (x, y, z)", run_rbs)
    if GeomAPI_PointsToBSpline is not None:
        job.tool("OCC GeomAPI_PointsToBSplineSurface", run_occ, occ_max)
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
    )

    def axes(mm):
        m = int(round(mm**0.5))
        return np.linspace(u[0], u[-1], m), np.linspace(v[0], v[-1], m)

    def run_karkas(mm, repeats):
        us, vs = axes(mm)
        out = np.empty((len(us), len(vs), 3))
        t, _ = timed(lambda: S(us, vs, grid=True, out=out), repeats)
        s = max(1, len(us) // 200)
        ref = np.stack([f(us[::s], vs[::s]) for f in fs], axis=-1)
        return t, float(np.max(np.abs(out[::s, ::s] - ref)))

    def run_rbs(mm, repeats):
        us, vs = axes(mm)
        t, r = timed(lambda: [f(us, vs) for f in fs], repeats)
        return t, 0.0

    def run_store(mm, repeats):
        return store_limit(mm, repeats), 0.0

    job.tool("karkas BicubicSurface (out=)", run_karkas)
    job.tool("SciPy RectBivariateSpline (x, y, z)", run_rbs)
    job.tool("store limit (NumPy fill)", run_store)
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes: a smoke run")
    ap.add_argument("--repeats", type=int, default=None, help="runs per measurement (median)")
    ap.add_argument("--jobs", default=None, help="comma-separated job names to run")
    ap.add_argument("--overhead", action="store_true", help="only the one-point call overhead")
    ap.add_argument("--rounds", type=int, default=15, help="rounds of the one-point overhead")
    ap.add_argument("--calls", type=int, default=20_000, help="calls per tool and round")
    ap.add_argument(
        "--python-vs-rust", action="store_true", help="only 10^7 points from Python against Rust"
    )
    ap.add_argument(
        "--run-rust", action="store_true", help="run the Rust benchmark first (cargo bench)"
    )
    ap.add_argument("--out", default=os.path.join(HERE, "results.json"))
    ap.add_argument("--plots", default=os.path.join(HERE, "plots"))
    args = ap.parse_args()
    quick = args.quick
    repeats = args.repeats or (3 if quick else 5)
    if args.overhead or args.python_vs_rust:
        if args.overhead:
            one_point_overhead(args.rounds, args.calls)
        if args.python_vs_rust:
            python_vs_rust(args.repeats or 15, args.run_rust)
        return

    if quick:
        jobs = [
            curve_eval_job([10_000, 30_000, 100_000], 1000, False),
            curve_eval_job([10_000, 30_000, 100_000], 1000, True),
            curve_interp_job([100, 1_000, 10_000], 100, 1_000),
            closed_interp_job([1_000, 3_000, 10_000]),
            smoothing_fit_job([1_000, 3_000, 10_000], 2.9e-4),
            bicubic_job([50**2, 100**2, 200**2], 50**2),
            bicubic_eval_job([100**2, 200**2, 400**2], 200),
        ]
    else:
        jobs = [
            curve_eval_job([100_000, 1_000_000, 3_000_000, 10_000_000], 1000, False, 3_000_000),
            curve_eval_job([100_000, 1_000_000, 3_000_000, 10_000_000], 1000, True, 3_000_000),
            curve_interp_job([100, 300, 1_000, 10_000, 100_000, 300_000, 1_000_000], 300, 1_000),
            closed_interp_job([1_000, 10_000, 30_000, 100_000, 300_000]),
            smoothing_fit_job([3_000, 10_000, 30_000, 100_000], 2.9e-4),
            bicubic_job([125**2, 250**2, 500**2, 1000**2], 125**2),
            bicubic_eval_job([250**2, 500**2, 1000**2, 2000**2], 1000),
        ]
    if args.jobs:
        wanted = set(args.jobs.split(","))
        jobs = [j for j in jobs if j.name in wanted]

    t0 = time.perf_counter()
    for job in jobs:
        job.run(repeats)
    binding = None
    if not args.jobs:
        binding = {
            "one_point_overhead": one_point_overhead(args.rounds, args.calls),
            "python_vs_rust_1e7": python_vs_rust(repeats if quick else 15, args.run_rust),
        }

    os.makedirs(args.plots, exist_ok=True)
    results = {
        "machine": {
            "platform": platform.platform(),
            "processor": platform.processor() or platform.machine(),
            "cpus": os.cpu_count(),
            "python": sys.version.split()[0],
            "numpy": np.__version__,
            "scipy": scipy.__version__,
            "karkas": karkas.__version__,
            "geomdl": geomdl_fitting is not None,
            "occ": GeomAPI_PointsToBSpline is not None,
        },
        "quick": quick,
        "repeats": repeats,
        "jobs": {},
        "binding": binding,
    }
    print("\n== ratios peer / karkas at the largest common size (> 1: karkas faster)")
    for job in jobs:
        s = job.summary()
        results["jobs"][job.name] = s
        plot(job, os.path.join(args.plots, f"{job.name}.png"))
        for key, r in s["ratios"].items():
            print(f"   {job.name:15s} {key:70s} n={r['size']:>9}: {r['ratio']:7.2f}")
    print("\n== fitted exponents p (time ~ size^p)")
    for job in jobs:
        for name, r in job.results.items():
            if r["exponent"] is not None:
                print(f"   {job.name:15s} {name:40s} {r['exponent']:5.2f}")
    with open(args.out, "w") as f:
        json.dump(results, f, indent=1)
    print(f"\nwrote {args.out} and {args.plots}/*.png in {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
