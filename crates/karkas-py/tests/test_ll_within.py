"""LLCurve(..., within=D) and LLSurface(..., within=D): every node within D of its point,
the plain approximation when D allows it, the interpolating variant in the limit, and the
refusals. Node values are compared with the plain and interpolating constructors and with
the closed form of the node deviation, d_L (r_{i-1} - 2 r_i + r_{i+1}) (formula (5))."""

from math import comb

import numpy as np
import pytest

import karkas


def d_l(order):
    return comb(2 * order, order) / 2 ** (2 * order + 2)


@pytest.fixture
def noisy():
    rng = np.random.default_rng(5)
    x = np.linspace(0.0, 6.0, 30)
    return np.column_stack([x, np.sin(x)]) + 0.05 * rng.standard_normal((30, 2))


def nodes_of(curve, k):
    return curve(np.arange(1, k + 1) / (k + 1))


@pytest.mark.parametrize("order", [1, 3, 6])
def test_curve_within_every_node(noisy, order):
    k = len(noisy)
    # The plain deviation from formula (5) (open ends pass through their points).
    second = noisy[:-2] - 2 * noisy[1:-1] + noisy[2:]
    plain = np.concatenate([[0.0], d_l(order) * np.linalg.norm(second, axis=1), [0.0]])
    np.testing.assert_allclose(
        np.linalg.norm(nodes_of(karkas.LLCurve(noisy, order=order), k) - noisy, axis=1), plain, atol=1e-12
    )
    for f in (0.9, 0.3, 0.05):
        d = f * plain.max()
        c = karkas.LLCurve(noisy, order=order, within=d)
        dev = np.linalg.norm(nodes_of(c, k) - noisy, axis=1)
        assert np.all(dev <= d + 1e-12)
        # Nodes the plain curve passes farther than d end at distance d; the others keep it.
        np.testing.assert_allclose(dev, np.minimum(plain, d), atol=1e-12)
        assert c.within == d and abs(c.largest_deviation - d) < 1e-12
        assert c.order == order and not c.interpolating
        # C^L with pieces of degree 2L, as every LL curve.
        t, coef, degree = c.to_bspline()
        assert degree == 2 * order


def test_curve_within_limits(noisy):
    plain = karkas.LLCurve(noisy, order=3)
    big = karkas.LLCurve(noisy, order=3, within=10.0)
    np.testing.assert_array_equal(big.control_points, plain.control_points)
    assert big.largest_deviation < 10.0
    tiny = karkas.LLCurve(noisy, order=3, within=1e-10)
    interp = karkas.LLCurve.interpolate(noisy, order=3)
    np.testing.assert_allclose(tiny.control_points, interp.control_points, atol=3e-10)
    assert plain.within is None and plain.largest_deviation is None


def test_surface_within_every_node():
    rng = np.random.default_rng(9)
    u, v = np.meshgrid(np.linspace(0, 2, 8), np.linspace(0, 3, 9), indexing="ij")
    grid = np.stack([u, v, np.sin(u) * np.cos(v)], -1) + 0.03 * rng.standard_normal((8, 9, 3))
    nu, nv = np.arange(1, 9) / 9, np.arange(1, 10) / 10
    plain = np.linalg.norm(karkas.LLSurface(grid, order=2)(nu, nv) - grid, axis=-1)
    for f in (0.8, 0.2, 0.02):
        d = f * plain.max()
        S = karkas.LLSurface(grid, order=2, within=d)
        dev = np.linalg.norm(S(nu, nv) - grid, axis=-1)
        np.testing.assert_allclose(dev, np.minimum(plain, d), atol=1e-12)
        assert abs(S.largest_deviation - d) < 1e-12
    tiny = karkas.LLSurface(grid, order=2, within=1e-10)
    np.testing.assert_allclose(tiny(nu, nv), grid, atol=1e-9)


@pytest.mark.parametrize("d", [0.0, -1.0, float("nan"), float("inf")])
def test_within_refused(noisy, d):
    with pytest.raises(karkas.OptionError, match="distance"):
        karkas.LLCurve(noisy, within=d)
    with pytest.raises(karkas.OptionError, match="distance"):
        karkas.LLSurface(np.zeros((4, 4, 3)) + np.arange(4)[:, None, None], within=d)


def test_within_not_with_interpolate(noisy):
    with pytest.raises(karkas.OptionError, match="within and interpolate"):
        karkas.LLCurve(noisy, within=0.1, interpolate=True)
    with pytest.raises(karkas.OptionError, match="within and interpolate"):
        karkas.LLSurface(np.zeros((4, 4, 3)), within=0.1, interpolate=True)
