"""karkas.fair_curve: the bound on dense samples (measured here with SciPy's BSpline of the
result), kept ends and tangents, a curve as input, pickling, and bad input."""

import pickle

import numpy as np
import pytest
from scipy.interpolate import BSpline
from scipy.spatial import cKDTree

import karkas


def noisy_arc(n=80, sigma=1e-4, seed=3):
    rng = np.random.default_rng(seed)
    a = np.linspace(0.0, 2.5, n)
    return np.column_stack([np.cos(a), 0.6 * np.sin(a)]) + rng.normal(0.0, sigma, (n, 2))


def largest_distance(curve, points):
    t, c, k = curve.to_bspline()
    dense = BSpline(t, c, k)(np.linspace(t[0], t[-1], 400001))
    return cKDTree(dense).query(points)[0].max()


def test_bound_holds_and_energy_falls():
    pts = noisy_arc()
    f = karkas.fair_curve(pts, 4e-4)
    assert isinstance(f, karkas.Curve)
    # 400001 samples of a curve of length about 2.5: gaps below 1e-5 add at most 1e-10.
    assert largest_distance(f, pts) <= 4e-4 + 1e-9
    assert f.max_distance <= 4e-4
    report = f.report()
    assert report["after"]["fairness_energy"] < 0.1 * report["before"]["fairness_energy"]
    assert report["after"]["curvature_extrema"] < report["before"]["curvature_extrema"]
    assert f.points.shape == pts.shape and f.parameters.shape == (80,) and f.distances.shape == (80,)


def test_kept_ends_tangents_and_a_curve_as_input():
    pts = noisy_arc()
    f = karkas.fair_curve(pts, 4e-4, keep_tangents=True)
    np.testing.assert_allclose(f(np.array([0.0, 1.0])), pts[[0, -1]], atol=1e-14)
    d0 = f(0.0, 1)
    chord = pts[1] - pts[0]
    assert abs(d0[0] * chord[1] - d0[1] * chord[0]) < 1e-12 * np.linalg.norm(d0) * np.linalg.norm(chord)
    wavy = karkas.CubicSpline(pts)
    g = karkas.fair_curve(wavy, 4e-4)
    assert g.points.shape == (max(200, 20 * (len(wavy.breakpoints) - 1)), 2)
    assert g.report()["before"] == wavy.fairness(g.points)


def test_pickle_round_trip():
    f = karkas.fair_curve(noisy_arc(), 4e-4, closed=False)
    g = pickle.loads(pickle.dumps(f))
    t = np.linspace(0, 1, 101)
    assert np.array_equal(f(t), g(t))
    assert g.tolerance == f.tolerance and np.array_equal(g.distances, f.distances)


@pytest.mark.parametrize(
    "kwargs, error, needle",
    [
        ({"tolerance": 0.0}, karkas.KarkasError, "tolerance"),
        ({"tolerance": -1.0}, karkas.KarkasError, "tolerance"),
        ({"tolerance": 1e-30}, karkas.KarkasError, "resolve"),
        ({"tolerance": 1e-3, "corners": [0]}, karkas.KarkasError, "corner"),
    ],
)
def test_bad_options(kwargs, error, needle):
    with pytest.raises(error, match=needle):
        karkas.fair_curve(noisy_arc(), **kwargs)


def test_bad_points():
    pts = noisy_arc(40)
    with pytest.raises(karkas.KarkasError, match="points not in order"):
        karkas.fair_curve(pts[(np.arange(40) * 17) % 40], 1e-3)
    with pytest.raises(karkas.KarkasError, match="at least 4"):
        karkas.fair_curve(pts[:3], 1e-3)
    bad = pts.copy()
    bad[5, 0] = np.nan
    with pytest.raises(karkas.KarkasError):
        karkas.fair_curve(bad, 1e-3)
