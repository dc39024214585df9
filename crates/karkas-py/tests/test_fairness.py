"""Curve.fairness against closed forms (SciPy quadrature of an ellipse's curvature) and against
the command line (`karkas curve analyze --json` on the same points builds the same curves).

The CLI tests need $KARKAS_BIN or target/release/karkas (skipped without it)."""

import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

import karkas

REPO = Path(__file__).resolve().parents[3]
BIN = Path(os.environ.get("KARKAS_BIN", REPO / "target" / "release" / "karkas"))

KEYS = {
    "length",
    "curvature_min",
    "curvature_max",
    "curvature_extrema",
    "inflections",
    "max_distance_to_polygon",
    "fairness_energy",
}


def ellipse_spline(a, b, n):
    s = np.linspace(0.0, 2.0 * np.pi, n + 1)
    return karkas.CubicSpline(np.c_[a * np.cos(s), b * np.sin(s)], t=s, bc="periodic")


def test_ellipse_matches_its_closed_form():
    a, b = 3.0, 1.0
    f = ellipse_spline(a, b, 400).fairness()
    assert KEYS <= set(f)
    # The exact ellipse has 4; the spline's dk/ds jumps at its knots, which near the flat
    # sides (where the true dk/ds passes through 0) may add pairs of tiny extrema.
    assert f["curvature_extrema"] >= 4 and f["curvature_extrema"] % 2 == 0
    assert f["inflections"] == 0
    assert f["max_distance_to_polygon"] is None
    assert f["curvature_min"] == pytest.approx(b / a**2, rel=1e-4)
    assert f["curvature_max"] == pytest.approx(a / b**2, rel=1e-4)

    def d(th):
        return a * a * math.sin(th) ** 2 + b * b * math.cos(th) ** 2

    perimeter = quad(lambda th: math.sqrt(d(th)), 0, 2 * math.pi, epsabs=1e-13)[0]
    assert f["length"] == pytest.approx(perimeter, rel=1e-9)

    def density(th):
        dd = 2.0 * (a * a - b * b) * math.sin(th) * math.cos(th)
        dk = -1.5 * a * b * d(th) ** -2.5 * dd
        return dk * dk / math.sqrt(d(th))

    energy = quad(density, 0, 2 * math.pi, limit=200, epsabs=1e-12)[0]
    assert f["fairness_energy"] == pytest.approx(energy, rel=2e-3)


def test_a_circle_through_its_points_is_fair_and_the_polygon_distance_is_the_sagitta():
    n, r = 64, 2.0
    s = np.linspace(0.0, 2.0 * np.pi, n + 1)
    pts = np.c_[r * np.cos(s), r * np.sin(s)]
    f = karkas.CubicSpline(pts, t=s, bc="periodic").fairness(pts[:-1])
    assert f["inflections"] == 0
    assert f["curvature_min"] == pytest.approx(1 / r, rel=1e-3)
    assert f["curvature_max"] == pytest.approx(1 / r, rel=1e-3)
    sagitta = r * (1 - math.cos(math.pi / n))
    assert f["max_distance_to_polygon"] == pytest.approx(sagitta, rel=1e-3)


def test_points_of_another_dimension_are_refused():
    c = ellipse_spline(2.0, 1.0, 20)
    with pytest.raises(karkas.PointsError):
        c.fairness(np.zeros((4, 3)))


def test_every_curve_class_and_derivatives_have_it():
    # An S: the sine over one period turns left, then right (one inflection near pi).
    pts = np.c_[np.linspace(0, 6, 25), np.sin(np.linspace(0, 6, 25))]
    ll = karkas.LLCurve(pts)
    f = ll.fairness(pts)
    assert f["pieces"] == len(ll.breakpoints) - 1
    assert f["inflections"] >= 1
    assert f["max_distance_to_polygon"] < 0.1
    g = ll.derivative().fairness()
    assert KEYS <= set(g)


@pytest.mark.skipif(not BIN.is_file(), reason=f"no karkas binary at {BIN}")
def test_the_command_line_reports_the_same_figures(tmp_path):
    x = 0.5 * (1 - np.cos(np.linspace(0, np.pi, 30)))
    y = 0.6 * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    pts = np.r_[np.c_[x[::-1], y[::-1]], np.c_[x[1:], -y[1:]]]
    path = tmp_path / "naca.csv"
    np.savetxt(path, pts, delimiter=",", header="x,y", comments="", fmt="%.17g")
    done = subprocess.run(
        [str(BIN), "curve", "analyze", str(path), "--compare", "ll,spline", "--json"],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    cli = json.loads(done.stdout)
    read = np.loadtxt(path, delimiter=",", skiprows=1)
    for method, curve in [("ll", karkas.LLCurve(read)), ("spline", karkas.CubicSpline(read))]:
        f = curve.fairness(read)
        for key in KEYS:
            assert f[key] == pytest.approx(cli[method][key], rel=1e-12, abs=1e-300), (method, key)
