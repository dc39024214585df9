"""BicubicSurface.condition_measure: the condition measure (2.4) of the parameters
(Kuznetsov and Filatov) against closed forms, and the command line's --report."""

import pathlib
import subprocess

import numpy as np
import pytest

import karkas


def plane_grid(a, b, xs=(0.0, 0.7, 1.1, 2.0), ys=(0.0, 0.4, 1.3, 1.7, 2.9)):
    """origin + x_i a + y_j b in 3-D."""
    xs, ys = np.asarray(xs), np.asarray(ys)
    return np.array([0.3, -1.0, 2.0]) + xs[:, None, None] * a + ys[None, :, None] * b


A = np.array([2.0, 1.0, 2.0]) / 3.0
B = np.array([-1.0, 2.0, 0.0]) / np.sqrt(5.0)


def test_arc_lengths_along_orthogonal_lines_give_one():
    m = karkas.BicubicSurface(plane_grid(A, B)).condition_measure()
    assert m.shape == (4, 5) and m.dtype == np.float64
    np.testing.assert_allclose(m, 1.0, atol=1e-13)


@pytest.mark.parametrize("deg", [30.0, 60.0, 80.0])
def test_a_skewed_grid_gives_tan_of_half_the_angle(deg):
    t = np.radians(deg)
    m = karkas.BicubicSurface(plane_grid(A, np.cos(t) * A + np.sin(t) * B)).condition_measure()
    np.testing.assert_allclose(m, np.tan(t / 2), atol=1e-13)


def test_a_stretched_parameter_and_a_closed_seam():
    grid = plane_grid(A, B, xs=2.5 * np.arange(4), ys=0.8 * np.arange(5))
    m = karkas.BicubicSurface(grid, "uniform").condition_measure()
    np.testing.assert_allclose(m, 0.8 / 2.5, atol=1e-13)
    t = np.linspace(0, 2 * np.pi, 8, endpoint=False)
    ring = np.stack([np.cos(t)[None, :].repeat(3, 0), np.sin(t)[None, :].repeat(3, 0),
                     np.arange(3.0)[:, None].repeat(8, 1)], -1)
    m = karkas.BicubicSurface(ring, closed_v=True).condition_measure()
    assert m.shape == (3, 9)
    assert np.all((m > 0.9) & (m <= 1.0))


def papers_d(wu, wv):
    """|det [alpha; beta; n]| of (2.3)-(2.4) with the dual rows scaled to unit length, by NumPy."""
    n = np.cross(wu, wv)
    n /= np.linalg.norm(n)
    dual = np.linalg.inv(np.stack([wu, wv, n], 1))  # rows: alpha, beta, n
    alpha, beta = dual[0] / np.linalg.norm(dual[0]), dual[1] / np.linalg.norm(dual[1])
    return abs(np.linalg.det(np.stack([alpha, beta, n])))


def test_the_papers_measure_is_the_determinant_of_unit_rows():
    # A curved, skewed and stretched grid: node tangents from the surface's own derivatives.
    xs, ys = np.array([0.0, 0.6, 1.5, 2.0, 3.2]), np.array([0.0, 0.5, 1.4, 2.2])
    x, y = np.meshgrid(xs, ys, indexing="ij")
    grid = np.stack([x + 0.4 * y, 1.7 * y, 0.3 * x * x - 0.2 * x * y], -1)
    s = karkas.BicubicSurface(grid, "uniform")
    d = s.condition_measure(paper=True)
    ku, kv = s.knots_u, s.knots_v
    for i, u in enumerate(ku):
        for j, v in enumerate(kv):
            wu = s(u, v, du=1, grid=False)
            wv = s(u, v, dv=1, grid=False)
            assert abs(d[i, j] - papers_d(np.ravel(wu), np.ravel(wv))) < 1e-12
    # Not 1 (the lines are skewed) and not the extension (the parameters are stretched).
    assert d.min() < 0.99
    assert np.all(np.abs(d - s.condition_measure()) > 1e-3)


@pytest.mark.parametrize("scale", [1e-150, 1e150])
def test_the_papers_measure_does_not_depend_on_the_grid_scale(scale):
    # The sine of the angle between the grid lines (60 degrees) with uniform parameters,
    # where E G of tangents this small or large underflows or overflows.
    t = np.radians(60.0)
    grid = scale * plane_grid(A, np.cos(t) * A + np.sin(t) * B)
    d = karkas.BicubicSurface(grid, "uniform").condition_measure(paper=True)
    assert np.all(np.isfinite(d))
    np.testing.assert_allclose(d, np.sin(t), atol=1e-12)
