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
