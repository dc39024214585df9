"""B-splines out to Open CASCADE: ``c.to_bspline()`` handed to OCP's ``Geom_BSplineCurve`` and
``S.to_bspline()`` to ``Geom_BSplineSurface`` evaluate to the karkas object (skipped where
cadquery-ocp is not installed)."""

import numpy as np
import pytest

import karkas

ocp = pytest.importorskip("OCP.collections")
from OCP.collections import Array1_double, Array1_gp_Pnt, Array1_int, Array2_gp_Pnt  # noqa: E402
from OCP.Geom import Geom_BSplineCurve, Geom_BSplineSurface  # noqa: E402
from OCP.gp import gp_Pnt  # noqa: E402


def knots_and_multiplicities(t):
    knots, mults = np.unique(t, return_counts=True)
    kn, mu = Array1_double(1, len(knots)), Array1_int(1, len(knots))
    for i, (x, m) in enumerate(zip(knots, mults), 1):
        kn.SetValue(i, float(x))
        mu.SetValue(i, int(m))
    return kn, mu


def occ_curve(c):
    t, coefs, k = c.to_bspline()
    poles = Array1_gp_Pnt(1, len(coefs))
    for i, p in enumerate(coefs, 1):
        poles.SetValue(i, gp_Pnt(*p))
    return Geom_BSplineCurve(poles, *knots_and_multiplicities(t), k)


def helix(n=30):
    s = np.linspace(0.0, 1.0, n)
    return np.column_stack([np.cos(5 * s), np.sin(5 * s), s])


CURVES = {
    "ll": lambda: karkas.LLCurve(helix(), order=3),
    "ll-interpolating": lambda: karkas.LLCurve.interpolate(helix(), order=2),
    "ll-closed": lambda: karkas.LLCurve(helix()[:-1], order=2, closed=True),
    "cubic": lambda: karkas.CubicSpline(helix()),
    "cubic-periodic": lambda: karkas.CubicSpline(
        np.vstack([helix()[:-1] * [1, 1, 0], [[1.0, 0.0, 0.0]]]), bc="periodic"
    ),
    "fit": lambda: karkas.fit_curve(helix(200), knots=12),
}


@pytest.mark.parametrize("name", sorted(CURVES))
def test_open_cascade_evaluates_the_exported_curve(name):
    c = CURVES[name]()
    g = occ_curve(c)
    ts = np.linspace(*c.domain, 201)[:-1]
    q = np.array([[g.Value(float(x)).X(), g.Value(float(x)).Y(), g.Value(float(x)).Z()] for x in ts])
    scale = np.abs(c(ts)).max()
    assert np.abs(q - c(ts)).max() <= 1e-12 * scale


def test_open_cascade_evaluates_the_exported_surface():
    u, v = np.meshgrid(np.linspace(0, 1, 7), np.linspace(0, 2, 9), indexing="ij")
    grid = np.stack([u, v, np.sin(3 * u) * np.cos(2 * v)], axis=-1)
    for S in (karkas.BicubicSurface(grid), karkas.LLSurface(grid, order=2)):
        (tu, tv), coefs, (ku, kv) = S.to_bspline()
        poles = Array2_gp_Pnt(1, coefs.shape[0], 1, coefs.shape[1])
        for i in range(coefs.shape[0]):
            for j in range(coefs.shape[1]):
                poles.SetValue(i + 1, j + 1, gp_Pnt(*coefs[i, j]))
        (uk, um), (vk, vm) = knots_and_multiplicities(tu), knots_and_multiplicities(tv)
        g = Geom_BSplineSurface(poles, uk, vk, um, vm, ku, kv)
        us, vs = np.linspace(*S.domain_u, 13), np.linspace(*S.domain_v, 17)
        want = S(us, vs)
        for i, a in enumerate(us):
            for j, b in enumerate(vs):
                p = g.Value(float(a), float(b))
                error = np.abs([p.X(), p.Y(), p.Z()] - want[i, j]).max()
                assert error <= 1e-12 * np.abs(want).max()
