"""Discrete periodic splines and tubes."""

import numpy as np
import pytest

import karkas


def test_discrete_spline_interpolates_its_nodes(rng):
    nodes = rng.standard_normal((7, 2))
    s = karkas.DiscreteSpline.interpolate(nodes, order=3, n=10)
    v = s.values()
    assert v.shape == (70, 2) and s.period == 70
    np.testing.assert_allclose(v[::10], nodes, atol=1e-12)
    out = np.empty((70, 2))
    assert s.values(out=out) is out
    np.testing.assert_array_equal(out, v)


def test_discrete_spline_of_order_one_is_the_closed_polygon():
    # Order 1 (first differences): the discrete B-spline is the hat function, so the values
    # between two poles lie on the segment joining them (shifted by the spline's centring).
    poles = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    v = karkas.DiscreteSpline(poles, order=1, n=4).values()
    # Every value is a convex combination of two consecutive poles: on the square's boundary.
    on_edge = np.isclose(v, 0.0) | np.isclose(v, 1.0)
    assert np.all(on_edge.any(axis=1))
    assert np.all((v >= -1e-12) & (v <= 1 + 1e-12))


def test_discrete_spline_errors_and_repr():
    with pytest.raises(ValueError):
        karkas.DiscreteSpline(np.zeros((1, 2)))
    with pytest.raises(ValueError):
        karkas.DiscreteSpline(np.eye(3), n=1)
    with pytest.raises(ValueError, match="order"):
        karkas.DiscreteSpline(np.eye(3), order=-1)
    r = repr(karkas.DiscreteSpline(np.eye(3), order=2, n=5))
    assert r.startswith("<karkas.DiscreteSpline") and "period=15" in r


def torus_skeleton(m1=4, m2=6, n1=8, n2=8, R=3.0, r=1.0):
    """along[i]: m1 rings around the tube axis, N2 = m2 n2 samples; across[j]: m2 meridians."""
    N1, N2 = m1 * n1, m2 * n2

    def torus(p, q):
        a, b = np.broadcast_arrays(2 * np.pi * np.asarray(p) / N1, 2 * np.pi * np.asarray(q) / N2)
        return np.stack([(R + r * np.cos(a)) * np.cos(b), (R + r * np.cos(a)) * np.sin(b), r * np.sin(a)], -1)

    along = np.stack([torus(i * n1, np.arange(N2)) for i in range(m1)])
    across = np.stack([torus(np.arange(N1), j * n2) for j in range(m2)])
    return along, across


def test_tube_passes_through_its_skeleton():
    along, across = torus_skeleton()
    t = karkas.TubeSurface(along, across, 8, 8, 3, 3)
    v = t.values()
    assert v.shape == (32, 48, 3)
    np.testing.assert_allclose(v[::8, :], along, atol=1e-10)
    np.testing.assert_allclose(v[:, ::8].transpose(1, 0, 2), across, atol=1e-10)
    c = t.closed_grid()
    assert c.shape == (33, 49, 3)
    np.testing.assert_array_equal(c[-1, :-1], v[0])
    assert "TubeSurface" in repr(t)


def test_tube_rejects_an_incompatible_skeleton():
    along, across = torus_skeleton()
    across = across.copy()
    across[1, 0] += 0.1
    with pytest.raises(ValueError):
        karkas.TubeSurface(along, across, 8, 8)
