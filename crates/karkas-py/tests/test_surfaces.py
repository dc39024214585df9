"""Surfaces: bicubic vs SciPy's RectBivariateSpline, LL surfaces, grid/pointwise, out=."""

import numpy as np
import pytest
from scipy.interpolate import RectBivariateSpline

import karkas


def height_grid(nu=7, nv=9):
    x = np.linspace(0.0, 1.0, nu)
    y = np.linspace(0.0, 2.0, nv)
    X, Y = np.meshgrid(x, y, indexing="ij")
    return np.stack([X, Y, np.sin(3 * X) * np.cos(2 * Y)], axis=-1)


def test_bicubic_matches_rect_bivariate_spline_on_given_knots(rng):
    grid = height_grid()
    grid[..., 0] += 0.05 * rng.standard_normal(grid.shape[:2])
    ku = np.cumsum(rng.uniform(0.5, 1.5, grid.shape[0])) - 1.0
    kv = np.cumsum(rng.uniform(0.5, 1.5, grid.shape[1]))
    S = karkas.BicubicSurface.from_knots(grid, ku, kv)
    us = np.linspace(ku[0], ku[-1], 31)
    vs = np.linspace(kv[0], kv[-1], 23)
    got = S(us, vs)
    assert got.shape == (31, 23, 3)
    for c in range(3):
        ref = RectBivariateSpline(ku, kv, grid[..., c], kx=3, ky=3, s=0)
        np.testing.assert_allclose(got[..., c], ref(us, vs), rtol=0, atol=1e-11)
        for ku_, kv_ in [(1, 0), (0, 1), (1, 1), (2, 0)]:
            np.testing.assert_allclose(
                S(us, vs, du=ku_, dv=kv_)[..., c],
                ref(us, vs, dx=ku_, dy=kv_),
                rtol=1e-8,
                atol=1e-8,
            )


def test_bicubic_grid_false_matches_scipy_ev(rng):
    grid = height_grid()
    ku, kv = np.arange(7.0), np.arange(9.0)
    S = karkas.BicubicSurface.from_knots(grid, ku, kv)
    u = rng.uniform(0, 6, 50)
    v = rng.uniform(0, 8, 50)
    ref = RectBivariateSpline(ku, kv, grid[..., 2], s=0)
    np.testing.assert_allclose(S(u, v, grid=False)[:, 2], ref.ev(u, v), atol=1e-12)
    assert S(u.reshape(5, 10), v.reshape(5, 10), grid=False).shape == (5, 10, 3)
    assert S(1.5, 2.5).shape == (3,)


def test_bicubic_parameterizations():
    grid = height_grid()
    S = karkas.BicubicSurface(grid, parameterization="uniform")
    np.testing.assert_array_equal(S.knots_u, np.arange(7.0))
    np.testing.assert_allclose(S(S.knots_u, S.knots_v), grid, atol=1e-12)
    for name in ("chord", "averaged-chord", "centripetal"):
        S = karkas.BicubicSurface(grid, parameterization=name)
        np.testing.assert_allclose(S(S.knots_u, S.knots_v), grid, atol=1e-12)
    with pytest.raises(ValueError, match="parameterization"):
        karkas.BicubicSurface(grid, parameterization="arc")


def test_ll_surface_corners_and_interpolation():
    grid = height_grid()
    S = karkas.LLSurface(grid, order=4)
    (a, b), (c, d) = S.domain_u, S.domain_v
    np.testing.assert_allclose(S(a, c), grid[0, 0], atol=1e-14)
    np.testing.assert_allclose(S(b, d), grid[-1, -1], atol=1e-14)
    I = karkas.LLSurface.interpolate(grid, order=4)
    nu, nv = grid.shape[:2]
    us = np.arange(1, nu + 1) / (nu + 1)
    vs = np.arange(1, nv + 1) / (nv + 1)
    np.testing.assert_allclose(I(us, vs), grid, atol=1e-12)
    assert isinstance(I, karkas.LLSurface) and isinstance(I, karkas.Surface)


def test_ll_surface_grid_matches_pointwise_and_out():
    grid = height_grid()
    S = karkas.LLSurface(grid, order=5, closed_v=True)
    assert S.closed_v and not S.closed_u
    us = np.linspace(*S.domain_u, 40)
    vs = np.linspace(*S.domain_v, 30)
    G = S(us, vs)
    U, V = np.meshgrid(us, vs, indexing="ij")
    np.testing.assert_allclose(S(U, V, grid=False), G, atol=1e-14)
    out = np.empty((40, 30, 3))
    assert S(us, vs, out=out) is out
    np.testing.assert_array_equal(out, G)
    h = 1e-6
    fd = (S(us + h, vs) - S(us - h, vs)) / (2 * h)
    inner = slice(2, -2)
    np.testing.assert_allclose(S(us, vs, du=1)[inner], fd[inner], rtol=1e-5, atol=1e-5)
    assert S.sample(5, 6).shape == (5, 6, 3)


def test_surface_errors():
    with pytest.raises(ValueError, match="3-D float array"):
        karkas.LLSurface(np.zeros((4, 4)))
    with pytest.raises(ValueError, match="2 or 3 coordinates"):
        karkas.LLSurface(np.zeros((4, 4, 5)))
    with pytest.raises(ValueError, match="at least"):
        karkas.LLSurface(np.zeros((2, 4, 3)))
    S = karkas.LLSurface(height_grid())
    with pytest.raises(ValueError, match="one shape"):
        S(np.zeros(3), np.zeros(4), grid=False)
    with pytest.raises(ValueError, match="shape"):
        S(np.zeros(3), np.zeros(4), out=np.empty((4, 3, 3)))
    with pytest.raises(ValueError, match="knots"):
        karkas.BicubicSurface.from_knots(height_grid(), np.arange(3.0), np.arange(9.0))


def test_surface_reprs():
    r = repr(karkas.LLSurface(height_grid(), order=3))
    assert r.startswith("<karkas.LLSurface") and "7x9 grid in 3-D" in r and "order=3" in r
    r = repr(karkas.BicubicSurface(height_grid()))
    assert r.startswith("<karkas.BicubicSurface") and "chord" in r


def test_bicubic_origin_keyword():
    """origin=(i, j): the paper's origin node of the chord parameters; u along column j, v
    along row i (closed forms on a grid with rows at x = 0, 1, 4 and a tilt in z)."""
    grid = np.array([[[x, j, 0.5 * i * j] for j in range(4)] for i, x in enumerate([0.0, 1.0, 4.0])])
    u, v = karkas.grid_parameters(grid, "chord", origin=(1, 2))
    np.testing.assert_allclose(u, [-np.hypot(1.0, 1.0), 0.0, np.hypot(3.0, 1.0)], atol=1e-15)
    np.testing.assert_allclose(v, np.hypot(1.0, 0.5) * (np.arange(4) - 2.0), atol=1e-15)
    S = karkas.BicubicSurface(grid, origin=(1, 2))
    np.testing.assert_allclose(S.knots_u, u)
    np.testing.assert_allclose(S(u[2], v[3]), grid[2, 3], atol=1e-12)
    import pickle

    T = pickle.loads(pickle.dumps(S))
    np.testing.assert_array_equal(T.knots_u, S.knots_u)
    for bad in [dict(origin=(3, 0)), dict(origin=(0, 4)), dict(origin=(-1, 0)),
                dict(origin=(1, 1), parameterization="uniform")]:
        with pytest.raises(karkas.OptionError, match="origin"):
            karkas.BicubicSurface(grid, **bad)
