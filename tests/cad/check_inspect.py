#!/usr/bin/env python3
"""`karkas inspect` against Open CASCADE: each point's distance to a model's faces equals
BRepExtrema_DistShapeShape's to 1e-9 (model units), and its sign agrees with Open CASCADE's
solid classifier.

Open CASCADE (cadquery-ocp) builds and writes the models: a plate with a grid of blind
cylindrical holes (a solid of trimmed planes and cylinders, offset from the origin; STEP and
NURBS IGES), an analytic sphere (STEP), a whole torus (STEP, and NURBS IGES), two faces swept from a
hyperbola's and a parabola's arcs (an open shell, STEP) and a B-spline surface face (an open
shell: distances unsigned; STEP and IGES). For each, 600 points spread over the model's bounding box
grown by a fifth, and 600 near its faces (within 2% of its size), go through
`karkas inspect MODEL --points P.csv -o REPORT.csv`; Open CASCADE measures each point's
distance to the shape (BRepExtrema_DistShapeShape with a vertex) and, for solids, classifies it
(BRepClass3d_SolidClassifier, STEP solids: a point inside must have a negative signed
distance, a point outside a positive one; points within 1e-7 of the boundary are not
classified; IGES faces bound no solid and must be unsigned). One line per
model; exit status 1 on any failure. Where karkas's distance is smaller than Open CASCADE's,
karkas's foot point must lie on Open CASCADE's shape (Open CASCADE's own distance to it within
the tolerance): then the smaller distance is attained on the shape and is counted as a minimum
Open CASCADE missed.

Usage: python3 tests/cad/check_inspect.py --karkas target/release/karkas [--keep DIR]
"""

import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from OCP.BRep import BRep_Builder
from OCP.Bnd import Bnd_Box
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepBuilderAPI import (BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace, BRepBuilderAPI_MakeVertex,
                                BRepBuilderAPI_MakeWire,
                                BRepBuilderAPI_NurbsConvert)
from OCP.BRepClass3d import BRepClass3d_SolidClassifier
from OCP.BRepExtrema import BRepExtrema_DistShapeShape
from OCP.BRepPrimAPI import (BRepPrimAPI_MakeBox, BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakePrism,
                             BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeTorus)
from OCP.GeomAbs import GeomAbs_C2
from OCP.GeomAPI import GeomAPI_PointsToBSplineSurface
from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Hypr, gp_Parab, gp_Pnt, gp_Vec
from OCP.TopAbs import TopAbs_IN, TopAbs_OUT
from OCP.TopoDS import TopoDS_Compound

from occ_shapes import faces_of, write_iges, write_step

try:  # OCP 7.7
    from OCP.TColgp import TColgp_Array1OfPnt as Array1OfPnt, TColgp_Array2OfPnt as Array2OfPnt
except ImportError:  # OCP 8: NCollection arrays
    from OCP.collections import Array1_gp_Pnt as Array1OfPnt, Array2_gp_Pnt as Array2OfPnt

TOLERANCE = 1e-9  # model units; for IGES files 1e-9 of the model's size (see check)
POINTS = 600


def static(cls, name):
    """A static method: `Name_s` in OCP 7.7, `Name` in later releases."""
    return getattr(cls, name + "_s", None) or getattr(cls, name)


def holed_plate(holes=3, origin=(100.0, -50.0, 20.0)):
    """A plate with holes x holes blind cylindrical holes from its top: a solid."""
    x0, y0, z0 = origin
    plate = BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), 10.0 * holes, 8.0 * holes, 4.0).Shape()
    for i in range(holes):
        for j in range(holes):
            axis = gp_Ax2(gp_Pnt(x0 + 10.0 * i + 5.0, y0 + 8.0 * j + 4.0, z0 + 1.5), gp_Dir(0, 0, 1))
            plate = BRepAlgoAPI_Cut(plate, BRepPrimAPI_MakeCylinder(axis, 2.0 + 0.3 * j, 3.0).Shape()).Shape()
    return plate


def bspline_face():
    nu, nv = 7, 6
    pts = Array2OfPnt(1, nu, 1, nv)
    for i in range(nu):
        for j in range(nv):
            u, v = i / (nu - 1), j / (nv - 1)
            pts.SetValue(i + 1, j + 1, gp_Pnt(20.0 * u, 12.0 * v, 3.0 * math.sin(2.0 * u) * math.cos(1.5 * v)))
    surface = GeomAPI_PointsToBSplineSurface(pts, 3, 5, GeomAbs_C2, 1e-9).Surface()
    return BRepBuilderAPI_MakeFace(surface, 1e-9).Face()


def conic_extrusions():
    """Two faces swept from a hyperbola's and a parabola's arcs (STEP HYPERBOLA, PARABOLA in
    SURFACE_OF_LINEAR_EXTRUSION): an open shell."""
    ax2 = gp_Ax2(gp_Pnt(3.0, -1.0, 2.0), gp_Dir(0.2, 0.3, 1.0), gp_Dir(1.0, 0.0, -0.2))
    compound = TopoDS_Compound()
    builder = BRep_Builder()
    builder.MakeCompound(compound)
    for edge in (BRepBuilderAPI_MakeEdge(gp_Hypr(ax2, 2.0, 1.0), -1.0, 1.5).Edge(),
                 BRepBuilderAPI_MakeEdge(gp_Parab(ax2, 0.7), -2.0, 3.0).Edge()):
        builder.Add(compound, BRepPrimAPI_MakePrism(edge, gp_Vec(0.3, 0.2, 5.0)).Shape())
    return compound


def tilted_disc():
    """A disc bounded by one full circle on one vertex, its axis a rounding away from -z as in
    a FreeCAD library file (SOT404.stp): the vertex's angle is -6e-16, just below a turn."""
    axis = gp_Ax2(gp_Pnt(-4.423929967573, 2.553033135614, 2.24866721196),
                  gp_Dir(-1.898746e-16, 3.798993e-17, -1.0), gp_Dir(-1.0, 6.106227e-16, 1.898746e-16))
    edge = BRepBuilderAPI_MakeEdge(gp_Circ(axis, 0.5)).Edge()
    return BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(edge).Wire()).Face()


def vase(skew=False):
    """A B-spline profile turned 250 degrees about a tilted axis off the origin: one face on a
    surface of revolution (IGES entity 120 with a B-spline generatrix, 126). The profile lies
    in a half-plane through the axis, as a revolved sketch does; `skew` moves it off that
    plane (a space curve turned about the axis)."""
    from OCP.BRepPrimAPI import BRepPrimAPI_MakeRevol
    from OCP.GeomAPI import GeomAPI_PointsToBSpline
    from OCP.gp import gp_Ax1
    origin = np.array([1.0, -2.0, 0.5])
    a = np.array([0.1, 0.05, 1.0]) / np.linalg.norm([0.1, 0.05, 1.0])
    x = np.cross([0.0, 1.0, 0.0], a)
    x /= np.linalg.norm(x)
    y = np.cross(a, x)
    profile = [(2.0, 0.0, 0.0), (3.0, 0.3, 1.0), (2.2, 0.1, 2.5), (2.8, -0.2, 4.0)]
    array = Array1OfPnt(1, len(profile))
    for k, (r, off, h) in enumerate(profile):
        q = origin + r * x + (off if skew else 0.0) * y + h * a
        array.SetValue(k + 1, gp_Pnt(*q))
    curve = GeomAPI_PointsToBSpline(array).Curve()
    edge = BRepBuilderAPI_MakeEdge(curve).Edge()
    axis = gp_Ax1(gp_Pnt(*origin), gp_Dir(*a))
    return BRepPrimAPI_MakeRevol(edge, axis, math.radians(250.0)).Shape()


def cases():
    """(name, shape, is_solid, formats). IGES gets the plate with its analytic planes (entity
    108, bounded in model space) and as NURBS faces (entity 128). The NURBS plate's STEP holds its hole
    walls as periodic B-splines (unclamped knots), which karkas solves as cylinders. The torus and the vase reach IGES as
    surfaces of revolution (entity 120) of an arc and of a B-spline. IGES
    faces (entity 144) bound no solid: their distances are unsigned. The torus is one face
    bounded by its two seam circles, each used twice, with a tilted axis off the origin."""
    plate = holed_plate()
    torus = BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(1.0, 2.0, 3.0), gp_Dir(0.3, -0.2, 1.0)), 5.0, 1.5).Shape()
    return [
        ("plate-holes", plate, True, ("step", "igs")),
        ("plate-holes-nurbs", BRepBuilderAPI_NurbsConvert(plate, True).Shape(), True, ("step", "igs")),
        ("sphere", BRepPrimAPI_MakeSphere(gp_Pnt(1.0, 2.0, -3.0), 3.0).Shape(), True, ("step", "igs")),
        ("bspline-face", bspline_face(), False, ("step", "igs")),
        ("torus", torus, True, ("step", "igs")),
        ("vase", vase(), False, ("step", "igs")),
        ("skew-vase", vase(skew=True), False, ("step", "igs")),
        ("torus-nurbs", BRepBuilderAPI_NurbsConvert(torus, True).Shape(), True, ("igs",)),
        ("conic-extrusions", conic_extrusions(), False, ("step",)),
        ("tilted-disc", tilted_disc(), False, ("step",)),
    ]


def probe_points(shape, rng):
    """Points over the bounding box grown by a fifth, and points near the faces."""
    box = Bnd_Box()
    static(BRepBndLib, "Add")(shape, box)
    lo = np.array(box.CornerMin().Coord())
    hi = np.array(box.CornerMax().Coord())
    size = float(np.linalg.norm(hi - lo))
    grow = 0.2 * (hi - lo)
    spread = rng.uniform(lo - grow, hi + grow, size=(POINTS, 3))
    # Near the faces: random points pulled onto the shape by OCC, then moved a little.
    near = []
    for p in rng.uniform(lo, hi, size=(POINTS, 3)):
        d = BRepExtrema_DistShapeShape(shape, BRepBuilderAPI_MakeVertex(gp_Pnt(*p)).Vertex())
        foot = np.array(d.PointOnShape1(1).Coord())
        near.append(foot + rng.normal(scale=0.02 * size / math.sqrt(3), size=3))
    return np.vstack([spread, np.array(near)]), size


def occ_distances(shape, points):
    out = np.empty(len(points))
    shape = faces_of(shape)
    for k, p in enumerate(points):
        d = BRepExtrema_DistShapeShape(shape, BRepBuilderAPI_MakeVertex(gp_Pnt(*p)).Vertex())
        if not d.IsDone():
            raise RuntimeError(f"OCC found no distance for point {k}")
        out[k] = d.Value()
    return out


def run_karkas(karkas, model, points, folder):
    scan = os.path.join(folder, "scan.csv")
    np.savetxt(scan, points, delimiter=",", header="x,y,z", comments="", fmt="%.17g")
    report = os.path.join(folder, "report.csv")
    done = subprocess.run([karkas, "inspect", model, "--points", scan, "-o", report],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"karkas inspect failed: {done.stderr.strip()}")
    with open(report, newline="") as f:
        rows = list(csv.DictReader(f))
    distance = np.array([float(r["distance"]) for r in rows])
    signed = np.array([float(r["signed_distance"]) if r["signed_distance"] else np.nan for r in rows])
    feet = np.array([[float(r[k]) for k in ("foot_x", "foot_y", "foot_z")] for r in rows])
    return distance, signed, feet


def check(karkas, name, shape, solid, path, rng, folder):
    points, size = probe_points(shape, rng)
    start = time.time()
    distance, signed, feet = run_karkas(karkas, path, points, folder)
    karkas_time = time.time() - start
    start = time.time()
    reference = occ_distances(shape, points)
    occ_time = time.time() - start
    # Open CASCADE's IGES carries 10 significant digits: a surface of revolution's axis and
    # angles (entity 120) move by about 1e-10 of the model's size in the file.
    tolerance = TOLERANCE * max(1.0, size) if path.endswith(".igs") else TOLERANCE
    # Where karkas is nearer than Open CASCADE, karkas's foot must lie on Open CASCADE's shape:
    # then karkas's distance is attained on the shape and Open CASCADE's extrema missed it
    # (BRepExtrema misses an interior minimum on a B-spline edge of the skew vase).
    nearer = np.flatnonzero(distance < reference - tolerance)
    on_shape = occ_distances(shape, feet[nearer]) <= tolerance if len(nearer) else np.array([], bool)
    missed = int(on_shape.sum())
    reference[nearer[on_shape]] = distance[nearer[on_shape]]
    error = np.abs(distance - reference)
    worst = int(np.argmax(error))
    problems = []
    if error[worst] > tolerance:
        problems.append(f"point {worst} {points[worst].tolist()}: karkas {distance[worst]!r}, "
                        f"OCC {reference[worst]!r}")
    wrong_side = 0
    classified = 0
    solid = solid and not path.endswith(".igs")
    if solid:
        if np.isnan(signed).any():
            problems.append(f"{int(np.isnan(signed).sum())} points unsigned on a solid")
        for k, p in enumerate(points):
            if reference[k] < 1e-7:
                continue
            state = BRepClass3d_SolidClassifier(shape, gp_Pnt(*p), 1e-9).State()
            if state not in (TopAbs_IN, TopAbs_OUT):
                continue
            classified += 1
            if (state == TopAbs_IN) != (signed[k] < 0):
                wrong_side += 1
        if wrong_side:
            problems.append(f"{wrong_side} of {classified} points on the wrong side")
    elif not np.isnan(signed).all():
        problems.append("signed distances on an open shell or IGES faces")
    status = "FAIL" if problems else "ok  "
    sides = f", sign agrees on {classified - wrong_side}/{classified}" if solid else ""
    print(f"{status} {os.path.basename(path)}: {len(points)} points, size {size:.3g}, "
          f"largest difference {error[worst]:.1e}{sides}"
          + (f", {missed} nearer feet on OCC's shape that OCC missed" if missed else "")
          + f"; karkas {karkas_time:.2f}s, "
          f"OCC {occ_time:.2f}s" + (f"; {problems[0]}" if problems else ""))
    return not problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default="target/release/karkas", help="the karkas binary")
    parser.add_argument("--keep", help="write the files into this folder and keep them")
    args = parser.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-inspect-")
    os.makedirs(folder, exist_ok=True)
    rng = np.random.default_rng(55)
    start = time.time()
    failures = 0
    for name, shape, solid, formats in cases():
        for ext in formats:
            path = os.path.join(folder, f"{name}.{ext}")
            (write_step if ext == "step" else write_iges)(shape, path)
            try:
                failures += not check(args.karkas, name, shape, solid, path, rng, folder)
            except Exception as e:  # noqa: BLE001 - one line per failing model
                print(f"FAIL {name}.{ext}: {e}")
                failures += 1
    print(f"inspect: {failures} models failing, {time.time() - start:.0f}s")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
