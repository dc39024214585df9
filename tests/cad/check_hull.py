#!/usr/bin/env python3
"""CAD acceptance check of `karkas loft --offsets --mirror`: the whole Wigley hull.

The Wigley hull (length 1, beam 0.1, draught 0.0625: half-breadth
y = 0.05 (1 - 4 x^2) (1 - (z / 0.0625)^2)) is written as a table of offsets of 21 stations and
11 waterlines, midship at x = 250 (off the origin), and lofted as the whole hull. Open CASCADE
(cadquery-ocp) reads the STEP file: BRepCheck_Analyzer must find it valid and it must hold one
face; the points of the analytic hull between the offsets (the midpoints of the stations and
of the waterlines), on both sides, projected onto the face (GeomAPI_ProjectPointOnSurf), must
lie within 2e-3 of the beam of it (the table's spacing; the keel is a V that a single smooth
section would round by 1.7e-2 of the beam); the area (GProp) of the face Open CASCADE makes of
the file's B-spline surface over its whole domain must be within 1e-3 of the analytic wetted
area (SciPy's dblquad of both sides), and so must the area of the face as the file bounds
it (within 1e-6 of the whole domain's: the face is the whole patch). The end stations of a
Wigley hull are vertical lines (half-breadth 0), so the whole hull's end sections run down
the line and back up it; a reader finding the boundary's parameter curves by projection
folds them there (Open CASCADE then gets an area 4.3e-3 short), so the file carries each
edge's line in the parameter plane (PCURVE), which the check counts.
Exit 1 on any failure.

Usage: python3 tests/cad/check_hull.py [--karkas target/release/karkas] [--keep DIR]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeFace
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRep import BRep_Tool
from OCP.BRepGProp import BRepGProp
from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
from OCP.GProp import GProp_GProps
from OCP.gp import gp_Pnt
from OCP.IFSelect import IFSelect_RetDone
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from scipy.integrate import dblquad

L, B, T, X0 = 1.0, 0.1, 0.0625, 250.0
STATIONS, WATERLINES = 21, 11


def half_breadth(x, z):
    return 0.5 * B * (1 - (2 * x / L) ** 2) * (1 - (z / T) ** 2)


def analytic_area():
    def density(z, x):
        yx = 0.5 * B * (-8 * x / L**2) * (1 - (z / T) ** 2)
        yz = 0.5 * B * (1 - (2 * x / L) ** 2) * (-2 * z / T**2)
        return np.sqrt(1 + yx**2 + yz**2)

    one_side, _ = dblquad(density, -L / 2, L / 2, -T, 0.0, epsabs=1e-12, epsrel=1e-10)
    return 2 * one_side


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default="target/release/karkas")
    parser.add_argument("--keep", help="keep the table and the STEP file in this folder")
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(args.keep or tmp)
        work.mkdir(parents=True, exist_ok=True)
        table = work / "wigley.csv"
        xs = np.linspace(-L / 2, L / 2, STATIONS)
        zs = np.linspace(-T, 0.0, WATERLINES)
        with open(table, "w") as f:
            f.write("station,waterline,half_breadth\n")
            for x in xs:
                for z in zs:
                    f.write(f"{float(X0 + x)!r},{float(z)!r},{float(half_breadth(x, z))!r}\n")
        step = work / "hull.step"
        run = subprocess.run(
            [os.path.abspath(args.karkas), "loft", "--offsets", str(table), "--mirror", "-o", str(step), "--json"],
            capture_output=True,
            text=True,
        )
        if run.returncode != 0:
            print("FAIL karkas:", run.stderr)
            sys.exit(1)
        summary = json.loads(run.stdout)
        reader = STEPControl_Reader()
        if reader.ReadFile(str(step)) != IFSelect_RetDone:
            print("FAIL Open CASCADE cannot read", step)
            sys.exit(1)
        reader.TransferRoots()
        shape = reader.OneShape()
        faces = []
        explorer = TopExp_Explorer(shape, TopAbs_FACE)
        while explorer.More():
            faces.append(TopoDS.Face(explorer.Current()))
            explorer.Next()
        valid = BRepCheck_Analyzer(shape).IsValid()
        if not valid:
            failures.append("BRepCheck_Analyzer finds the shape invalid")
        if len(faces) != 1:
            failures.append(f"{len(faces)} faces, expected 1")
        surface = BRep_Tool.Surface_s(faces[0])
        u0, u1, v0, v1 = surface.Bounds()
        projector = GeomAPI_ProjectPointOnSurf()
        projector.Init(surface, u0, u1, v0, v1)
        worst = 0.0
        mid_x, mid_z = 0.5 * (xs[1:] + xs[:-1]), 0.5 * (zs[1:] + zs[:-1])
        for x in mid_x:
            for z in np.r_[mid_z, -T]:
                for side in (-1.0, 1.0):
                    projector.Perform(gp_Pnt(X0 + x, side * half_breadth(x, z), z))
                    d = projector.LowerDistance() if projector.NbPoints() > 0 else np.inf
                    worst = max(worst, d)
        if not worst <= 2e-3 * B:
            failures.append(f"analytic points {worst:.3e} from the face, above 2e-3 of the beam")
        def area_of(s):
            props = GProp_GProps()
            BRepGProp.SurfaceProperties_s(s, props, 1e-9)
            return props.Mass()

        area = area_of(BRepBuilderAPI_MakeFace(surface, 1e-7).Face())
        bounded, exact = area_of(shape), analytic_area()
        if not abs(area - exact) <= 1e-3 * exact:
            failures.append(f"area {area:.9g} vs analytic {exact:.9g}")
        if not abs(bounded - exact) <= 1e-3 * exact:
            failures.append(f"the face as the file bounds it: area {bounded:.9g} vs analytic {exact:.9g}")
        if not abs(bounded - area) <= 1e-6 * area:
            failures.append(f"the face as the file bounds it: area {bounded:.9g} vs its whole surface's {area:.9g}")
        pcurves = step.read_text().count("PCURVE(")
        if pcurves != 4:
            failures.append(f"{pcurves} PCURVEs in the file, expected 4 (one per side of the face)")
        print(
            f"wigley --mirror: valid {valid}, {len(faces)} face, control points {summary['control_points']}, "
            f"analytic points within {worst:.3e} ({worst / B:.2e} of the beam), "
            f"area {area:.9g} vs {exact:.9g} (relative {abs(area - exact) / exact:.2e}); "
            f"the face as the file bounds it {bounded:.9g} (relative {abs(bounded - exact) / exact:.2e})"
        )
    for f in failures:
        print("FAIL", f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
