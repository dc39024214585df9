"""karkas.relay_grid: a turned cylinder grid re-laid along the lines of curvature of its
interpolant comes back to circles z = const and axial lines (Kuznetsov and Filatov,
Theorem 2.1); umbilic regions and bad shapes are refused."""

import numpy as np
import pytest

import karkas


def turned_cylinder(rows=9, cols=13, turn=np.radians(30.0)):
    """Nodes on x^2 + y^2 = 1 along helices turned by `turn` (both families): node (i, j) at
    arc lengths s = 0.15 i, t = 0.15 j along the two orthogonal turned directions."""
    s = 0.15 * (np.arange(rows) - (rows - 1) / 2)[:, None]
    t = 0.15 * (np.arange(cols) - (cols - 1) / 2)[None, :]
    c, d = np.cos(turn), np.sin(turn)
    z = c * s - d * t
    angle = d * s + c * t
    return np.stack(np.broadcast_arrays(np.cos(angle), np.sin(angle), z), axis=-1)


def test_turned_cylinder_comes_back_to_circles_and_axial_lines():
    grid = turned_cylinder()
    z_spread_before = np.ptp(grid[..., 2], axis=1).max()
    relaid = karkas.relay_grid(grid, size=(5, 7))
    assert relaid.shape == (5, 7, 3)
    assert np.allclose(np.hypot(relaid[..., 0], relaid[..., 1]), 1.0, atol=1e-3)
    # Rows or columns are circles (constant z); the others are axial lines (constant angle).
    z_rows = np.ptp(relaid[..., 2], axis=1).max()
    z_cols = np.ptp(relaid[..., 2], axis=0).max()
    circles = relaid if z_rows <= z_cols else relaid.transpose(1, 0, 2)
    assert np.ptp(circles[..., 2], axis=1).max() < 1e-3 < z_spread_before
    angles = np.unwrap(np.arctan2(circles[..., 1], circles[..., 0]), axis=0)
    assert np.ptp(angles, axis=0).max() < 1e-3


def test_start_moves_the_centre_of_the_new_grid():
    grid = turned_cylinder()
    relaid = karkas.relay_grid(grid, start=(2, 3))
    assert relaid.shape == grid.shape
    # The start node keeps its place (same size: same index) and its point.
    assert np.allclose(relaid[2, 3], grid[2, 3], atol=1e-9)
    centred = karkas.relay_grid(grid)
    assert not np.allclose(relaid[2, 3], centred[2, 3], atol=1e-3)


def test_a_plane_is_an_umbilic_region():
    u, v = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 2, 6), indexing="ij")
    plane = np.stack([u, v, 0.5 * u + 0.25 * v], axis=-1)
    with pytest.raises(karkas.PointsError, match="umbilic"):
        karkas.relay_grid(plane)


def test_bad_input_is_refused():
    with pytest.raises(karkas.PointsError):
        karkas.relay_grid(np.zeros((4, 4, 2)))
    with pytest.raises(karkas.PointsError):
        karkas.relay_grid(turned_cylinder(), size=(1, 5))
    with pytest.raises(karkas.PointsError):
        karkas.relay_grid(turned_cylinder(), start=(20, 0))
