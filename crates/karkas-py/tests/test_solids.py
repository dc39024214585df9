"""Closed solids from Python: ``karkas.export(..., cap=True)`` caps a surface's open planar
boundary loops (the command line's ``--cap``), and ``crease_u``/``crease_v`` close a direction
of ``BicubicSurface`` and ``LLSurface`` with a C^0 seam (``--crease-u/--crease-v``). Open
CASCADE judges the STEP files (BRepCheck, one solid, GProp volume), trimesh the meshes
(skipped where cadquery-ocp or trimesh is not installed)."""

import math
import pickle

import numpy as np
import pytest

import karkas

pytest.importorskip("OCP.STEPControl")
trimesh = pytest.importorskip("trimesh")
from OCP.BRepCheck import BRepCheck_Analyzer  # noqa: E402
from OCP.BRepGProp import BRepGProp  # noqa: E402
from OCP.GProp import GProp_GProps  # noqa: E402
from OCP.IFSelect import IFSelect_RetDone  # noqa: E402
from OCP.STEPControl import STEPControl_Reader  # noqa: E402
from OCP.TopAbs import TopAbs_SOLID  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402


def occ_solid(path):
    """(valid, number of solids, volume) of a STEP file as Open CASCADE reads it."""
    reader = STEPControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    reader.TransferRoots()
    shape = reader.OneShape()
    solids, explorer = 0, TopExp_Explorer(shape, TopAbs_SOLID)
    while explorer.More():
        solids += 1
        explorer.Next()
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props, 1e-9)
    return BRepCheck_Analyzer(shape).IsValid(), solids, props.Mass()


def tube_rings(radius=1.0, heights=(0.0, 1.0, 2.0), n=24, offset=(0.0, 0.0, 0.0)):
    t = np.linspace(0, 2 * np.pi, n + 1)[:-1]
    return np.array([[[offset[0] + radius * math.cos(a), offset[1] + radius * math.sin(a),
                       offset[2] + z] for a in t] for z in heights])


def wing_sections(n=16, span=(0.0, 0.8, 1.6, 2.4), blunt=0.0):
    """Sharp-edged symmetric sections (NACA 0012-like), the trailing edge at t = 0."""
    t = np.linspace(0, 2 * np.pi, n + 1)[:-1]
    x = 0.5 + 0.5 * np.cos(t)
    half = 0.6 * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3
                  - 0.1036 * x**4)
    half[0] = 0.0
    y = np.sign(np.sin(t)) * half
    return np.array([[[xi, yi, z] for xi, yi in zip(x, y)] for z in span])


@pytest.mark.parametrize("radius,offset", [(1.0, (0, 0, 0)), (0.3, (50.0, -20.0, 7.0)),
                                           (4.0, (0, 0, -3.0))])
def test_a_capped_tube_is_a_valid_solid_of_the_cylinders_volume(tmp_path, radius, offset):
    tube = karkas.BicubicSurface(tube_rings(radius, offset=offset), closed_v=True)
    path = karkas.export(tube, tmp_path / "tube.step", cap=True)
    assert "MANIFOLD_SOLID_BREP" in path.read_text()
    valid, solids, volume = occ_solid(path)
    assert valid and solids == 1
    exact = math.pi * radius**2 * 2.0
    # 24 points a ring: the periodic cubic lies within 1e-5 of the circle's radius.
    assert abs(volume - exact) <= 1e-3 * exact, (volume, exact)
    mesh_path = karkas.export(tube, tmp_path / "tube.stl", cap=True, samples=(30, 240))
    mesh = trimesh.load(mesh_path)
    assert mesh.is_watertight and mesh.is_volume
    assert abs(mesh.volume - volume) <= 1e-3 * volume, (mesh.volume, volume)


@pytest.mark.parametrize("make", [
    lambda g: karkas.BicubicSurface(g, crease_v=True),
    lambda g: karkas.LLSurface(g, interpolate=True, crease_v=True),
], ids=["bicubic", "ll"])
def test_a_creased_capped_wing_is_a_solid_with_a_sharp_trailing_edge(tmp_path, make):
    sections = wing_sections()
    wing = make(sections)
    path = karkas.export(wing, tmp_path / "wing.step", cap=True)
    valid, solids, volume = occ_solid(path)
    assert valid and solids == 1
    # The section polygon's area (shoelace) times the span: the interpolating surface bulges
    # a little beyond the polygon of its points.
    x, y = sections[0, :, 0], sections[0, :, 1]
    polygon = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) * 2.4
    assert polygon < volume < 1.05 * polygon, (volume, polygon)
    mesh = trimesh.load(karkas.export(wing, tmp_path / "wing.stl", cap=True, samples=(40, 400)))
    assert mesh.is_watertight and mesh.is_volume
    assert abs(mesh.volume - volume) <= 1e-3 * volume, (mesh.volume, volume)
    # The trailing edge is the seam v = v0 = v1: the tangents along v on either side of it
    # point apart (the upper surface leaves it upward, the lower one arrives from below).
    (u0, u1), (v0, v1) = wing.domain_u, wing.domain_v
    u = 0.5 * (u0 + u1)
    start = np.asarray(wing(u, v0, dv=1)).ravel()
    end = np.asarray(wing(u, v1, dv=1)).ravel()
    cosine = np.dot(start, end) / (np.linalg.norm(start) * np.linalg.norm(end))
    assert np.degrees(np.arccos(np.clip(cosine, -1, 1))) > 5.0
    # The seam closes: both sides of it are the same points.
    assert np.allclose(wing(u, v0), wing(u, v1), atol=1e-12)


def test_a_creased_surface_pickles_to_the_same_surface():
    sections = wing_sections()
    for s in (karkas.BicubicSurface(sections, crease_v=True),
              karkas.LLSurface(sections, crease_v=True)):
        again = pickle.loads(pickle.dumps(s))
        u = np.linspace(*s.domain_u, 7)
        v = np.linspace(*s.domain_v, 9)
        assert np.array_equal(s(u, v), again(u, v))


def test_cap_and_crease_refuse_what_cannot_take_them(tmp_path):
    tube = karkas.BicubicSurface(tube_rings(), closed_v=True)
    curve = karkas.CubicSpline([[0, 0], [1, 2], [2, 1], [3, 3]])
    with pytest.raises(karkas.OptionError, match="cap"):
        karkas.export(curve, tmp_path / "c.step", cap=True)
    with pytest.raises(karkas.OptionError, match="cap.*not .csv"):
        karkas.export(tube, tmp_path / "t.csv", cap=True)
    with pytest.raises(karkas.OptionError, match="cap.*mesh_tolerance"):
        karkas.export(tube, tmp_path / "t.stl", cap=True, mesh_tolerance=1e-3)
    # A warped open sheet has no planar loop to cap.
    sheet = np.array([[[i, j, 0.3 * i * j] for j in range(4)] for i in range(4)], float)
    with pytest.raises(karkas.OptionError, match="cap"):
        karkas.export(karkas.BicubicSurface(sheet), tmp_path / "s.step", cap=True)
    assert not (tmp_path / "s.step").exists()
    with pytest.raises(karkas.OptionError, match="crease_v and closed_v"):
        karkas.BicubicSurface(tube_rings(), closed_v=True, crease_v=True)
    with pytest.raises(karkas.OptionError, match="crease_u and closed_u"):
        karkas.LLSurface(tube_rings(), closed_u=True, crease_u=True)
    # Two distinct columns cannot close.
    with pytest.raises(karkas.PointsError):
        karkas.BicubicSurface(tube_rings(n=2), crease_v=True)
