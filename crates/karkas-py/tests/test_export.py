"""Exports: OBJ, STL, CSV files of sampled curves and surfaces."""

import numpy as np
import pytest

import karkas


def test_export_obj_and_stl(tmp_path):
    x = np.linspace(0, 1, 4)
    X, Y = np.meshgrid(x, x[:3], indexing="ij")
    grid = np.stack([X, Y, X * Y], axis=-1)
    karkas.export_obj(tmp_path / "s.obj", grid)
    lines = (tmp_path / "s.obj").read_text().splitlines()
    vertices = [l for l in lines if l.startswith("v ")]
    faces = [l for l in lines if l.startswith("f ")]
    assert len(vertices) == 12
    np.testing.assert_allclose([float(t) for t in vertices[5].split()[1:]], grid[1, 2])
    assert len(faces) in (6, 12)  # 3 x 2 quads, or twice as many triangles
    karkas.export_stl(tmp_path / "s.stl", grid)
    data = (tmp_path / "s.stl").read_bytes()
    triangles = int.from_bytes(data[80:84], "little")
    assert triangles == 12 and len(data) == 84 + 50 * 12


def test_export_csv(tmp_path):
    c = karkas.LLCurve(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), order=3)
    t = np.linspace(*c.domain, 5)
    karkas.export_curve_csv(tmp_path / "c.csv", t, c(t))
    rows = (tmp_path / "c.csv").read_text().splitlines()
    assert rows[0] == "t,x,y" and len(rows) == 6
    np.testing.assert_allclose([float(v) for v in rows[3].split(",")], [t[2], *c(t[2])])
    S = karkas.LLSurface(np.random.default_rng(1).random((4, 5, 3)))
    u, v = np.linspace(*S.domain_u, 3), np.linspace(*S.domain_v, 2)
    karkas.export_surface_csv(tmp_path / "s.csv", u, v, S(u, v))
    rows = (tmp_path / "s.csv").read_text().splitlines()
    assert rows[0] == "u,v,x,y,z" and len(rows) == 7


def test_export_errors(tmp_path):
    with pytest.raises(ValueError, match="3 coordinates"):
        karkas.export_obj(tmp_path / "s.obj", np.zeros((3, 3, 2)))
    with pytest.raises(OSError):
        karkas.export_obj(tmp_path / "missing" / "s.obj", np.zeros((3, 3, 3)))
    # Parameters and points of different counts: a data error (a ValueError), not OSError.
    with pytest.raises(karkas.IncompatibleDataError, match="3 parameters for 4 points"):
        karkas.export_curve_csv(tmp_path / "c.csv", np.zeros(3), np.zeros((4, 2)))
    assert issubclass(karkas.IncompatibleDataError, ValueError)
    assert not (tmp_path / "c.csv").exists()
