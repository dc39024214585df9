#!/usr/bin/env python3
"""Curve projection and arc length: karkas against SciPy baselines on the same curve, in one
process, results checked equal before timing, interleaved rounds, medians.

The curve: the periodic cubic spline (chord parameters) through 1000 points of the rose
r = 1 + 0.3 cos 5θ, built by karkas.CubicSpline and by scipy.interpolate.CubicSpline (the two
agree to round-off, checked). The same jobs in Rust: `cargo bench -p karkas-bench --bench geometry`.

- projection of 10^6 points lying within 0.05 of the curve (3% of its size), both sides:
  karkas `Curve.project` against a cKDTree of a few samples per piece (query with `workers` =
  the thread count) refined by vectorised Newton steps on (P(t) - q) . P'(t) = 0. Several
  (samples per piece, steps) settings are tried; those whose distances equal karkas's to 1e-12
  at every point are timed, and the ratio is taken against the fastest of them;
- arc length from the start to 10^6 parameters: karkas `Curve.arc_length(t0, t1s, tol=1e-10)`
  against the piece lengths and the partial piece by a vectorised 16-point Gauss-Legendre rule
  on SciPy's derivative.

Open CASCADE, when its wrapper (cadquery-ocp) is installed: the same curve as a
Geom_BSplineCurve (karkas's exact B-spline form, checked equal), each point projected by
GeomAPI_ProjectPointOnCurve (it has no batch call: a Python loop over `--occ-points` of the
points, one thread), distances checked against karkas's, the time per point scaled to 10^6.

    RAYON_NUM_THREADS=1 python3 bench/geometry_vs_scipy.py --threads 1
    RAYON_NUM_THREADS=2 python3 bench/geometry_vs_scipy.py --threads 2
"""

import argparse
import statistics
import time

import numpy as np
from scipy.interpolate import CubicSpline
from scipy.spatial import cKDTree

import karkas


def rose(n):
    th = np.linspace(0.0, 2.0 * np.pi, n + 1)
    r = 1.0 + 0.3 * np.cos(5.0 * th)
    pts = np.column_stack((r * np.cos(th), r * np.sin(th)))
    pts[-1] = pts[0]
    return pts


def project_scipy(s, period, q, workers, per_piece=8, steps=6):
    ts = np.linspace(0.0, period, per_piece * (len(s.x) - 1), endpoint=False)
    _, i = cKDTree(s(ts)).query(q, workers=workers)
    t = ts[i]
    for _ in range(steps):
        r = s(t) - q
        d1, d2 = s(t, 1), s(t, 2)
        g = np.einsum("ij,ij->i", r, d1)
        h = np.einsum("ij,ij->i", d1, d1) + np.einsum("ij,ij->i", r, d2)
        t = t - g / np.where(h > 0.0, h, 1.0)
    t = np.mod(t, period)
    return t, np.linalg.norm(s(t) - q, axis=1)


def occ_curve(t, c, k):
    """The clamped B-spline (t, c, k) as an Open CASCADE Geom_BSplineCurve in the plane z = 0;
    None when cadquery-ocp is not installed."""
    try:
        from OCP.Geom import Geom_BSplineCurve
        from OCP.gp import gp_Pnt
    except ImportError:
        return None
    try:  # OCP >= 7.8
        from OCP.collections import Array1_double, Array1_gp_Pnt, Array1_int
    except ImportError:
        from OCP.TColgp import TColgp_Array1OfPnt as Array1_gp_Pnt
        from OCP.TColStd import TColStd_Array1OfInteger as Array1_int
        from OCP.TColStd import TColStd_Array1OfReal as Array1_double
    knots, mults = np.unique(np.asarray(t), return_counts=True)
    c = np.asarray(c)
    poles = Array1_gp_Pnt(1, len(c))
    for i, p in enumerate(c):
        poles.SetValue(i + 1, gp_Pnt(float(p[0]), float(p[1]), 0.0))
    kn, mu = Array1_double(1, len(knots)), Array1_int(1, len(knots))
    for i, (x, m) in enumerate(zip(knots, mults)):
        kn.SetValue(i + 1, float(x))
        mu.SetValue(i + 1, int(m))
    return Geom_BSplineCurve(poles, kn, mu, k)


def project_occ(curve, q):
    """GeomAPI_ProjectPointOnCurve at every point of q: (parameters, distances)."""
    from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
    from OCP.gp import gp_Pnt

    t, d = np.empty(len(q)), np.empty(len(q))
    for i, (x, y) in enumerate(q):
        proj = GeomAPI_ProjectPointOnCurve(gp_Pnt(float(x), float(y), 0.0), curve)
        t[i], d[i] = proj.LowerDistanceParameter(), proj.LowerDistance()
    return t, d


GL_X, GL_W = np.polynomial.legendre.leggauss(16)


def lengths_scipy(s, t1s):
    knots = s.x

    def gauss(a, b):
        mid, half = 0.5 * (a + b), 0.5 * (b - a)
        t = mid[:, None] + half[:, None] * GL_X[None, :]
        speed = np.linalg.norm(s(t.ravel(), 1), axis=1).reshape(t.shape)
        return half * (speed @ GL_W)

    cumulative = np.concatenate(([0.0], np.cumsum(gauss(knots[:-1], knots[1:]))))
    k = np.clip(np.searchsorted(knots, t1s, side="right") - 1, 0, len(knots) - 2)
    return cumulative[k] + gauss(knots[k], t1s)


def timed(run, rounds):
    """Median seconds of each callable in `run`, interleaved (the order rotating)."""
    times = {name: [] for name in run}
    names = list(run)
    for r in range(rounds):
        for name in names[r % len(names):] + names[: r % len(names)]:
            t0 = time.perf_counter()
            run[name]()
            times[name].append(time.perf_counter() - t0)
    return {name: statistics.median(v) for name, v in times.items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--threads", type=int, default=2, help="cKDTree workers (set RAYON_NUM_THREADS too)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--occ-points", type=int, default=20_000,
                    help="points projected by Open CASCADE (a Python loop; 0 skips it)")
    args = ap.parse_args()

    pts = rose(1000)
    curve = karkas.CubicSpline(pts, bc="periodic")
    knots = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))))
    s = CubicSpline(knots, pts, bc_type="periodic")
    period = knots[-1]
    check = np.linspace(0.0, period, 10_007)
    assert np.abs(curve(check) - s(check)).max() < 1e-12, "the two splines differ"

    rng = np.random.default_rng(2026)
    n = args.points
    u = rng.uniform(0.0, period, n)
    d = s(u, 1)
    normal = np.column_stack((-d[:, 1], d[:, 0])) / np.linalg.norm(d, axis=1)[:, None]
    q = s(u) + normal * rng.uniform(-0.05, 0.05, n)[:, None]

    tk, dk, _ = curve.project(q)
    baselines = {}
    for per_piece, steps in [(2, 2), (2, 3), (4, 2), (4, 3), (8, 3), (8, 6)]:
        tb, db = project_scipy(s, period, q, args.threads, per_piece, steps)
        diff = np.abs(dk - db).max()
        equal = diff < 1e-12
        print(f"cKDTree {per_piece}/piece + {steps} Newton: max |distance difference| {diff:.1e}; "
              f"karkas farther in {int(np.sum(dk > db + 1e-12))}, SciPy farther in "
              f"{int(np.sum(db > dk + 1e-12))} of {n}{'' if equal else ' (not timed)'}")
        assert not np.any(dk > db + 1e-9), "karkas missed a nearer point"
        if equal:
            baselines[f"scipy {per_piece}/piece+{steps} Newton"] = (
                lambda per_piece=per_piece, steps=steps:
                project_scipy(s, period, q, args.threads, per_piece, steps))
    assert baselines, "no baseline reached karkas's accuracy"

    occ = occ_curve(*curve.to_bspline()) if args.occ_points > 0 else None
    if occ is not None:
        gp = np.array([[occ.Value(float(x)).X(), occ.Value(float(x)).Y()] for x in check])
        assert np.abs(gp - curve(check)).max() < 1e-12, "the Open CASCADE curve differs"
        occ_m = min(args.occ_points, n)
        _, do = project_occ(occ, q[:occ_m])
        diff = np.abs(dk[:occ_m] - do).max()
        print(f"Open CASCADE on {occ_m} points: max |distance difference| {diff:.1e}; karkas farther "
              f"in {int(np.sum(dk[:occ_m] > do + 1e-12))}, OCC farther in {int(np.sum(do > dk[:occ_m] + 1e-12))}")
        assert not np.any(dk[:occ_m] > do + 1e-9), "karkas missed a point Open CASCADE found nearer"

    t1s = rng.uniform(0.0, period, n)
    lk = curve.arc_length(0.0, t1s, tol=1e-10)
    lb = lengths_scipy(s, t1s)
    ldiff = np.abs(lk - lb).max()
    print(f"arc length: max |difference| {ldiff:.1e} (whole length {lk.max():.6f})")
    assert ldiff < 1e-9

    medians = timed(
        {
            "karkas project": lambda: curve.project(q),
            **baselines,
            "karkas arc_length": lambda: curve.arc_length(0.0, t1s, tol=1e-10),
            "numpy Gauss-Legendre": lambda: lengths_scipy(s, t1s),
        },
        args.rounds,
    )
    for name, m in medians.items():
        print(f"{name:28s} {m * 1e3:9.1f} ms")
    if occ is not None:
        per_point = timed({"occ": lambda: project_occ(occ, q[:occ_m])}, 3)["occ"] / occ_m
        print(f"{'Open CASCADE project':28s} {per_point * n * 1e3:9.1f} ms (per point x {n}, "
              f"from {occ_m} points, one thread) = {per_point * n / medians['karkas project']:.1f}x karkas")
    fastest = min(baselines, key=lambda name: medians[name])
    print(f"projection: fastest equal-accuracy baseline ({fastest}) / karkas = "
          f"{medians[fastest] / medians['karkas project']:.2f}x ({args.threads} thread(s))")
    print(f"arc length: numpy/karkas = {medians['numpy Gauss-Legendre'] / medians['karkas arc_length']:.2f}x")


if __name__ == "__main__":
    main()
