#!/usr/bin/env python3
"""`karkas convert MODEL.step OUT.stl --tolerance T` against Open CASCADE and trimesh: the mesh of
a CAD model's faces is watertight and a volume where the model is a solid, its volume and area
agree with Open CASCADE's exact ones (GProp) to within what the tolerance allows, and it lies
within T of the model's faces.

Open CASCADE (cadquery-ocp) builds and writes the models: a box, a cylinder, a sphere, a torus
(analytic STEP types), the plate with blind holes of check_inspect.py (trimmed planes and
cylinders) and the same plate with every face converted to NURBS, away from the origin; a box
with every edge filleted (three blends meet on a sphere's pole at each corner), the same as
NURBS and 10^4 away from the origin (meshed to OBJ there: STL's single precision is 1e-3 at
10^4), and a box with five edges filleted (two fillets meet in a mitre); the filleted box and
the plate also as Open CASCADE's IGES (planes, entity 108, bounded in model space; faces that do
not say their outside). For each model and
two tolerances (1e-2 and 1e-3 of the model's size):
- trimesh: `is_watertight` and `is_volume`; its volume within `T A` of Open CASCADE's (A the
  model's area: a mesh within T of every face encloses at most that much more or less) and its
  area within `3 T A / V` of A (relative; V the volume);
- the mesh's vertices lie on the model (Open CASCADE's distance to the shape at most 1e-6 of
  the size) and the midpoints of its triangles' sides within 1.05 T of it
  (BRepExtrema_DistShapeShape, on a sample of 400 a model);
- a smaller tolerance gives no fewer triangles and a volume no farther from the exact one;
- a second run writes the same file, byte for byte.
One line per case; exit status 1 on any failure.

Usage: python3 tests/cad/check_convert.py --karkas target/release/karkas [--keep DIR]
"""

import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
import trimesh

from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeVertex, BRepBuilderAPI_NurbsConvert
from OCP.BRepExtrema import BRepExtrema_DistShapeShape
from OCP.BRepFilletAPI import BRepFilletAPI_MakeFillet
from OCP.BRepGProp import BRepGProp
from OCP.BRepPrimAPI import (BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeSphere,
                             BRepPrimAPI_MakeTorus)
from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib
from OCP.GProp import GProp_GProps
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.gp import gp_Ax2, gp_Dir, gp_Pnt

from occ_shapes import faces_of, write_iges, write_step


def bbox_size(shape):
    box = Bnd_Box()
    BRepBndLib.Add_s(shape, box)
    lo, hi = np.array(box.CornerMin().Coord()), np.array(box.CornerMax().Coord())
    return float(np.linalg.norm(hi - lo))


def volume_and_area(shape):
    v, a = GProp_GProps(), GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, v)
    BRepGProp.SurfaceProperties_s(shape, a)
    return v.Mass(), a.Mass()


def holed_plate(origin=(100.0, -50.0, 20.0)):
    x0, y0, z0 = origin
    plate = BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), 30.0, 24.0, 4.0).Shape()
    for i in range(3):
        for j in range(3):
            axis = gp_Ax2(gp_Pnt(x0 + 5.0 + 10.0 * i, y0 + 4.0 + 8.0 * j, z0 + 1.5), gp_Dir(0, 0, 1))
            plate = BRepAlgoAPI_Cut(plate, BRepPrimAPI_MakeCylinder(axis, 2.0 + 0.3 * j, 3.0).Shape()).Shape()
    return plate


def as_edge(shape):
    cast = getattr(TopoDS, "Edge_s", None) or TopoDS.Edge  # OCP 7.7 / OCP 8
    return cast(shape)


def filleted_box(corner=(-20.0, 5.0, 7.0), sizes=(12.0, 8.0, 5.0), radius=1.5, edges=None):
    """A box with the edges numbered in `edges` (every edge when None) filleted to `radius`."""
    box = BRepPrimAPI_MakeBox(gp_Pnt(*corner), *sizes).Shape()
    fillet = BRepFilletAPI_MakeFillet(box)
    explorer = TopExp_Explorer(box, TopAbs_EDGE)
    k = 0
    while explorer.More():
        if edges is None or k in edges:
            fillet.Add(radius, as_edge(explorer.Current()))
        k += 1
        explorer.Next()
    return fillet.Shape()


def cases():
    axis = gp_Ax2(gp_Pnt(3.0, -2.0, 5.0), gp_Dir(0.2, 0.3, 1.0))
    plate = holed_plate()
    filleted = filleted_box()
    return [
        ("filleted box", filleted, "step"),
        ("filleted box, NURBS", BRepBuilderAPI_NurbsConvert(filleted, True).Shape(), "step"),
        ("filleted box, far", filleted_box(corner=(1e4, 5.0, 7.0)), "step"),
        ("filleted box, IGES", filleted, "iges"),
        ("box, five edges filleted", filleted_box((1.0, 2.0, 3.0), (3.0, 4.0, 5.0), 0.7, {0, 1, 2, 5, 8}), "step"),
        ("box", BRepPrimAPI_MakeBox(gp_Pnt(10.0, 20.0, 30.0), 4.0, 5.0, 6.0).Shape(), "step"),
        ("cylinder", BRepPrimAPI_MakeCylinder(axis, 2.0, 7.0).Shape(), "step"),
        ("sphere", BRepPrimAPI_MakeSphere(gp_Pnt(1.0, 2.0, -3.0), 3.0).Shape(), "step"),
        ("torus", BRepPrimAPI_MakeTorus(axis, 5.0, 1.5).Shape(), "step"),
        ("holed plate", plate, "step"),
        ("holed plate, NURBS", BRepBuilderAPI_NurbsConvert(plate, True).Shape(), "step"),
        ("holed plate, IGES", plate, "iges"),
    ]


def distances(shape, points):
    shape = faces_of(shape)
    out = []
    for p in points:
        v = BRepBuilderAPI_MakeVertex(gp_Pnt(*map(float, p))).Vertex()
        d = BRepExtrema_DistShapeShape(shape, v)
        out.append(d.Value() if d.IsDone() else float("inf"))
    return np.array(out)


def check(karkas, name, shape, kind, share, folder, rng):
    size = bbox_size(shape)
    tol = share * size
    model = os.path.join(folder, f"{name.replace(' ', '_').replace(',', '')}.{kind}")
    if not os.path.exists(model):
        (write_step if kind == "step" else write_iges)(shape, model)
    mesh_format = "obj" if name.endswith("far") else "stl"
    out = os.path.join(folder, f"{os.path.basename(model)}-{share:g}.{mesh_format}")
    run = subprocess.run([karkas, "convert", model, out, "--tolerance", repr(tol)], capture_output=True, text=True)
    if run.returncode != 0:
        return None, [f"karkas exit {run.returncode}: {run.stderr.strip()}"]
    mesh = trimesh.load(out, force="mesh", process=True)
    volume, area = volume_and_area(shape)
    faults = []
    again_out = f"{out}.again.{mesh_format}"
    again = subprocess.run([karkas, "convert", model, again_out, "--tolerance", repr(tol)],
                           capture_output=True, text=True)
    with open(out, "rb") as a, open(again_out, "rb") as b:
        if again.returncode != 0 or a.read() != b.read():
            faults.append("a second run writes a different file")
    if not mesh.is_watertight:
        faults.append("not watertight")
    if not mesh.is_volume:
        faults.append("not a volume")
    dv = abs(abs(mesh.volume) - volume)
    if dv > tol * area:
        faults.append(f"volume {abs(mesh.volume):.6g} vs {volume:.6g}")
    da = abs(mesh.area - area) / area
    if da > 3.0 * tol * area / volume:
        faults.append(f"area {mesh.area:.6g} vs {area:.6g}")
    pick = rng.choice(len(mesh.vertices), size=min(200, len(mesh.vertices)), replace=False)
    on = distances(shape, mesh.vertices[pick]).max()
    if on > 1e-6 * size:
        faults.append(f"a vertex {on:.3g} off the model")
    edges = mesh.edges_unique
    pick = rng.choice(len(edges), size=min(200, len(edges)), replace=False)
    mids = 0.5 * (mesh.vertices[edges[pick, 0]] + mesh.vertices[edges[pick, 1]])
    chord = distances(shape, mids).max()
    if chord > 1.05 * tol:
        faults.append(f"a side's midpoint {chord / tol:.3g} T from the model")
    figures = (len(mesh.faces), dv / volume, da, on / size, chord / tol)
    return figures, faults


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--karkas", required=True)
    ap.add_argument("--keep", help="keep the models and meshes in this folder")
    args = ap.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-convert-")
    os.makedirs(folder, exist_ok=True)
    rng = np.random.default_rng(7)
    failed = 0
    models = cases()
    for name, shape, kind in models:
        previous = None
        for share in (1e-2, 1e-3):
            figures, faults = check(args.karkas, name, shape, kind, share, folder, rng)
            if figures is not None and previous is not None:
                if figures[0] < previous[0]:
                    faults.append("fewer triangles at the smaller tolerance")
                if figures[1] > previous[1] + 1e-9:
                    faults.append("volume farther from the exact one at the smaller tolerance")
            status = "ok" if not faults else "FAIL: " + "; ".join(faults)
            failed += bool(faults)
            if figures is not None:
                n, rv, ra, on, chord = figures
                print(f"{name:20s} T={share:g} size: {n:7d} triangles, volume {rv:.2e}, area {ra:.2e}, "
                      f"vertices {on:.1e}, sides {chord:.2f} T: {status}")
            else:
                print(f"{name:20s} T={share:g} size: {status}")
            previous = figures if figures is not None else previous
    print(f"check_convert: {failed} failing cases")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
