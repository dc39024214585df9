#!/usr/bin/env python3
"""CAD reading acceptance: karkas reads the STEP and IGES files Open CASCADE writes and
evaluates their geometry as Open CASCADE does.

Open CASCADE (the cadquery-ocp package) builds and writes, one file each: B-spline curves
and surfaces, a rational circle and ellipse, rational cylinders, spheres and tori (as NURBS,
GeomConvert), the same as their analytic STEP types (solids of BRepPrimAPI: cylinder, cone,
sphere, torus), a surface of revolution and one of linear extrusion, a lofted wing shell
(ThruSections through NACA sections) and a trimmed face (a B-spline face with a hole cut by a
cylinder); the B-spline and trimmed cases as IGES too (faces: entities 128, 144, 142).
Both read every file (karkas through `karkas.read_cad`, Open CASCADE through its readers);
each karkas face and curve is paired with the Open CASCADE face or edge it lies on, and

- B-spline geometry (OCC's Geom_BSplineCurve / Geom_BSplineSurface): both evaluate at 10^4
  parameters (a 100 x 100 grid on a face, 10^4 along a curve) of the same domain; points agree
  to 1e-12 of the model's size, first and second derivatives to 1e-9 of their largest
  magnitude;
- analytic geometry (karkas converts it to NURBS, whose parameter is the angle at every
  knot but not between them): every one of the 10^4 karkas points lies on OCC's surface or
  curve to 1e-12 of the model's size (OCC's own projection), and karkas's unit normal
  (surfaces) or unit tangent (curves) equals OCC's there to 1e-9; the domains are equal;
- the trimmed face: karkas's `contains(u, v)` equals OCC's BRepClass_FaceClassifier on a
  100 x 100 grid (points within 1e-6 of the trim left out).

One line per file, with the largest figures; exit status 1 on any failure.

Usage: python3 tests/cad/check_cad_read.py [--keep DIR]
"""

import argparse
import math
import os
import sys
import tempfile
import time

import numpy as np

import karkas
from OCP.BRep import BRep_Tool
from OCP.BRepAlgoAPI import BRepAlgoAPI_Cut
from OCP.BRepBuilderAPI import (BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace,
                                BRepBuilderAPI_MakeWire)
from OCP.BRepClass import BRepClass_FaceClassifier
from OCP.BRepOffsetAPI import BRepOffsetAPI_ThruSections
from OCP.BRepPrimAPI import (BRepPrimAPI_MakeCone, BRepPrimAPI_MakeCylinder,
                             BRepPrimAPI_MakePrism, BRepPrimAPI_MakeRevol,
                             BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeTorus)
from OCP.GeomAbs import GeomAbs_C2
from OCP.GeomAPI import (GeomAPI_PointsToBSpline, GeomAPI_PointsToBSplineSurface,
                         GeomAPI_ProjectPointOnCurve, GeomAPI_ProjectPointOnSurf)
from OCP.Geom import (Geom_Circle, Geom_CylindricalSurface, Geom_Ellipse,
                      Geom_RectangularTrimmedSurface, Geom_SphericalSurface,
                      Geom_ToroidalSurface, Geom_TrimmedCurve)
from OCP.GeomConvert import GeomConvert
from OCP.gp import gp_Ax1, gp_Ax2, gp_Ax3, gp_Dir, gp_Pnt, gp_Pnt2d, gp_Vec
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Reader
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_IN, TopAbs_OUT
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

from occ_shapes import write_iges, write_step

try:  # OCP 7.7
    from OCP.TColgp import TColgp_Array1OfPnt as Array1OfPnt, TColgp_Array2OfPnt as Array2OfPnt
except ImportError:  # OCP 8: NCollection arrays
    from OCP.collections import Array1_gp_Pnt as Array1OfPnt, Array2_gp_Pnt as Array2OfPnt


def static(cls, name):
    """A static method: `Name_s` in OCP 7.7, `Name` in later releases."""
    return getattr(cls, name + "_s", None) or getattr(cls, name)


TO_EDGE = static(TopoDS, "Edge")
TO_FACE = static(TopoDS, "Face")
SURFACE_OF = static(BRep_Tool, "Surface")
RANGE_OF = static(BRep_Tool, "Range")


def CURVE_OF(edge):
    """The 3-D curve of an edge (location applied) and the edge's range on it."""
    first, last = RANGE_OF(edge)
    return static(BRep_Tool, "Curve")(edge, first, last), first, last

TO_BSPLINE_CURVE = static(GeomConvert, "CurveToBSplineCurve")
TO_BSPLINE_SURFACE = static(GeomConvert, "SurfaceToBSplineSurface")

POINT_TOLERANCE = 1e-12
DERIVATIVE_TOLERANCE = 1e-9
GRID = 100


# -- Open CASCADE's files -----------------------------------------------------------------


def bspline_curve():
    pts = Array1OfPnt(1, 9)
    for i in range(9):
        t = i / 8.0
        pts.SetValue(i + 1, gp_Pnt(10.0 * t, 2.0 * math.sin(3.0 * t), 0.5 * t * t - 0.3))
    return GeomAPI_PointsToBSpline(pts, 3, 5, GeomAbs_C2, 1e-9).Curve()


def bspline_surface(nu=7, nv=6):
    pts = Array2OfPnt(1, nu, 1, nv)
    for i in range(nu):
        for j in range(nv):
            u, v = i / (nu - 1), j / (nv - 1)
            pts.SetValue(i + 1, j + 1, gp_Pnt(20.0 * u, 12.0 * v, 3.0 * math.sin(2.0 * u) * math.cos(1.5 * v)))
    return GeomAPI_PointsToBSplineSurface(pts, 3, 5, GeomAbs_C2, 1e-9).Surface()


def naca_wire(thickness, chord, z, twist):
    """A closed NACA 4-digit section (symmetric, the closed trailing-edge coefficient -0.1036)
    as one B-spline edge through its points."""
    n = 31
    pts = []
    for k in range(2 * n - 1):
        s = k / (n - 1) - 1.0  # -1 .. 1: lower surface back to front, then upper
        x = abs(s) ** 2
        y = 5 * thickness * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 - 0.1036 * x ** 4)
        y = -y if s < 0 else y
        c, sn = math.cos(twist), math.sin(twist)
        X, Y = chord * (x * c - y * sn), chord * (x * sn + y * c)
        pts.append(gp_Pnt(X, Y, z))
    arr = Array1OfPnt(1, len(pts))
    for i, p in enumerate(pts):
        arr.SetValue(i + 1, p)
    curve = GeomAPI_PointsToBSpline(arr, 3, 3, GeomAbs_C2, 1e-7).Curve()
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve).Edge()).Wire()


def cases():
    """(name, shape, formats) of every file Open CASCADE writes."""
    ax2 = gp_Ax2(gp_Pnt(1.0, -2.0, 0.5), gp_Dir(0.2, 0.3, 1.0), gp_Dir(1.0, 0.0, -0.2))
    ax3 = gp_Ax3(ax2)
    out = []
    out.append(("bspline-curve", BRepBuilderAPI_MakeEdge(bspline_curve()).Edge(), ("step", "igs")))
    circle = TO_BSPLINE_CURVE(Geom_TrimmedCurve(Geom_Circle(ax2, 3.0), 0.2, 5.9))
    out.append(("rational-circle", BRepBuilderAPI_MakeEdge(circle).Edge(), ("step", "igs")))
    ellipse = TO_BSPLINE_CURVE(Geom_TrimmedCurve(Geom_Ellipse(ax2, 4.0, 1.5), 0.0, 2.0 * math.pi))
    out.append(("rational-ellipse", BRepBuilderAPI_MakeEdge(ellipse).Edge(), ("step",)))
    out.append(("bspline-surface", BRepBuilderAPI_MakeFace(bspline_surface(), 1e-7).Face(), ("step", "igs")))
    for name, surface, (u1, u2, v1, v2) in (
        ("rational-cylinder", Geom_CylindricalSurface(ax3, 2.0), (0.0, 2.0 * math.pi, -1.0, 4.0)),
        ("rational-sphere", Geom_SphericalSurface(ax3, 2.5), (0.3, 5.0, -1.2, 1.4)),
        ("rational-torus", Geom_ToroidalSurface(ax3, 5.0, 1.2), (0.0, 2.0 * math.pi, 0.0, 2.0 * math.pi)),
    ):
        nurbs = TO_BSPLINE_SURFACE(Geom_RectangularTrimmedSurface(surface, u1, u2, v1, v2))
        out.append((name, BRepBuilderAPI_MakeFace(nurbs, 1e-7).Face(), ("step", "igs")))
    out.append(("analytic-cylinder", BRepPrimAPI_MakeCylinder(ax2, 2.0, 5.0).Shape(), ("step",)))
    out.append(("analytic-cone", BRepPrimAPI_MakeCone(ax2, 2.0, 0.5, 4.0).Shape(), ("step",)))
    out.append(("analytic-sphere", BRepPrimAPI_MakeSphere(ax2, 2.5).Shape(), ("step",)))
    out.append(("analytic-torus", BRepPrimAPI_MakeTorus(ax2, 5.0, 1.2).Shape(), ("step",)))
    profile = BRepBuilderAPI_MakeEdge(bspline_curve()).Edge()
    axis = gp_Ax1(gp_Pnt(0.0, -5.0, 0.0), gp_Dir(1.0, 0.0, 0.0))
    out.append(("revolution", BRepPrimAPI_MakeRevol(profile, axis, 2.0).Shape(), ("step",)))
    out.append(("extrusion", BRepPrimAPI_MakePrism(profile, gp_Vec(0.3, 0.2, 5.0)).Shape(), ("step",)))
    loft = BRepOffsetAPI_ThruSections(False, False, 1e-6)
    for k in range(5):
        z = 4.0 * k
        loft.AddWire(naca_wire(0.12 - 0.01 * k, 3.0 - 0.4 * k, z, 0.05 * k))
    loft.Build()
    out.append(("lofted-wing", loft.Shape(), ("step", "igs")))
    face = BRepBuilderAPI_MakeFace(bspline_surface(), 1e-7).Face()
    tool = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(9.0, 6.0, -5.0), gp_Dir(0.0, 0.0, 1.0)), 2.5, 10.0).Shape()
    out.append(("trimmed-face", BRepAlgoAPI_Cut(face, tool).Shape(), ("step", "igs")))
    return out


# -- Reading back with Open CASCADE ---------------------------------------------------------


def occ_shape(path):
    reader = STEPControl_Reader() if path.endswith(".step") else IGESControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        raise RuntimeError("OCC could not read its own file")
    reader.TransferRoots()
    return reader.OneShape()


def explore(shape, kind):
    found = []
    e = TopExp_Explorer(shape, kind)
    while e.More():
        found.append(TO_FACE(e.Current()) if kind == TopAbs_FACE else TO_EDGE(e.Current()))
        e.Next()
    return found


def model_size(points):
    p = np.asarray(points).reshape(-1, 3)
    return float(np.linalg.norm(p.max(0) - p.min(0))) or 1.0


def pnt(p):
    return gp_Pnt(float(p[0]), float(p[1]), float(p[2]))


def xyz(p):
    return np.array([p.X(), p.Y(), p.Z()])


def surface_d2(surface, u, v):
    p, d1u, d1v, d2u, d2v, d2uv = gp_Pnt(), gp_Vec(), gp_Vec(), gp_Vec(), gp_Vec(), gp_Vec()
    surface.D2(u, v, p, d1u, d1v, d2u, d2v, d2uv)
    return xyz(p), xyz(d1u), xyz(d1v), xyz(d2u), xyz(d2uv), xyz(d2v)


def curve_d2(curve, t):
    p, d1, d2 = gp_Pnt(), gp_Vec(), gp_Vec()
    curve.D2(t, p, d1, d2)
    return xyz(p), xyz(d1), xyz(d2)


def basis_name(geom):
    name = geom.DynamicType().Name()
    if "Trimmed" in name:
        inner = geom.BasisSurface() if hasattr(geom, "BasisSurface") else geom.BasisCurve()
        return inner.DynamicType().Name(), inner
    return name, geom


def unit(v):
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n > 0, n, 1.0)


# -- Comparisons ---------------------------------------------------------------------------


def cells(a, b, n=GRID):
    """The centres of n equal cells of [a, b]: 10^4 parameters in all, none at an end or (but
    by chance) at a knot, where a derivative may jump and each side's value is right."""
    return a + (np.arange(n) + 0.5) * (b - a) / n


def compare_surface(face, occ_faces, size, report):
    S = face.surface
    (a, b), (c, d) = S.domain_u, S.domain_v
    us, vs = cells(a, b), cells(c, d)
    mid = S((a + b) / 2, (c + d) / 2)
    occ = min(occ_faces, key=lambda f: GeomAPI_ProjectPointOnSurf(pnt(mid), SURFACE_OF(f)).LowerDistance()
              if GeomAPI_ProjectPointOnSurf(pnt(mid), SURFACE_OF(f)).NbPoints() else 1e300)
    name, geom = basis_name(SURFACE_OF(occ))
    points = S(us, vs)
    su, sv = S(us, vs, 1, 0), S(us, vs, 0, 1)
    if name == "Geom_BSplineSurface":
        u1, u2, v1, v2 = geom.Bounds()
        span = max(abs(b - a), abs(d - c))
        if max(abs(u1 - a), abs(u2 - b), abs(v1 - c), abs(v2 - d)) > 1e-12 * span:
            raise RuntimeError(f"domains differ: karkas {(a, b, c, d)}, OCC {(u1, u2, v1, v2)}")
        derivs = [su, sv, S(us, vs, 2, 0), S(us, vs, 1, 1), S(us, vs, 0, 2)]
        want = np.array([[surface_d2(geom, u, v) for v in vs] for u in us])
        worst = np.max(np.linalg.norm(points - want[:, :, 0], axis=-1)) / size
        # Each derivative against the largest of its order (S_uv of a cylinder is 0).
        scale = [np.max(np.linalg.norm(want[:, :, 1:3], axis=-1))] * 2 + [np.max(np.linalg.norm(want[:, :, 3:], axis=-1))] * 3
        dworst = max(
            np.max(np.linalg.norm(k - want[:, :, m + 1], axis=-1)) / max(scale[m], 1e-300)
            for m, k in enumerate(derivs)
        )
        report(f"B-spline surface {S.control_points.shape[0]}x{S.control_points.shape[1]}", worst, dworst)
        return
    # Analytic: karkas's points on OCC's surface, normals and tangent directions equal.
    worst = dworst = 0.0
    nk = unit(np.cross(su, sv))
    for i in range(GRID):
        for j in range(GRID):
            proj = GeomAPI_ProjectPointOnSurf(pnt(points[i, j]), geom)
            worst = max(worst, proj.LowerDistance() / size)
            pu, pv = proj.LowerDistanceParameters()
            _, d1u, d1v, *_ = surface_d2(geom, pu, pv)
            n = np.cross(d1u, d1v)
            if np.linalg.norm(n) < 1e-9 * np.linalg.norm(d1u) * np.linalg.norm(d1v) or np.linalg.norm(su[i, j]) < 1e-9 * size:
                continue  # a pole: no normal
            dworst = max(dworst, np.linalg.norm(nk[i, j] - unit(n)))
            dworst = max(dworst, np.linalg.norm(unit(su[i, j]) - unit(d1u)), np.linalg.norm(unit(sv[i, j]) - unit(d1v)))
    report(f"{name} as NURBS", worst, dworst)


def occ_pieces(curve, occ_edges, size):
    """The OCC edges on B-spline curves that carry `curve` with its own parameter (OCC's IGES
    reader splits a curve at its C1 knots): (first, last, geom, reversed) covering its domain,
    or None. A loop's curve runs along the loop (karkas reverses it where OCC's edge runs the
    other way): C(t) = E(a + b - t)."""
    a, b = curve.domain
    pieces = []
    for e in occ_edges:
        g, first, last = CURVE_OF(e)
        name, geom = basis_name(g)
        if name != "Geom_BSplineCurve":
            continue
        for reverse in (False, True):
            lo, hi = (a + b - last, a + b - first) if reverse else (first, last)
            if lo < a - 1e-12 * (b - a) or hi > b + 1e-12 * (b - a):
                continue
            if any(lo < h and hi > l for l, h, _, _ in pieces):
                break  # the same edge met again (a seam is in its loop twice)
            probes = [lo + f * (hi - lo) for f in (0.3, 0.7)]
            if all(np.linalg.norm(curve(t) - curve_d2(geom, a + b - t if reverse else t)[0]) <= 1e-9 * size for t in probes):
                pieces.append((lo, hi, geom, reverse))
                break
    pieces.sort(key=lambda p: p[0])
    covered = sum(hi - lo for lo, hi, _, _ in pieces)
    return pieces if pieces and abs(covered - (b - a)) <= 1e-9 * (b - a) else None


def compare_curve(curve, occ_edges, size, report):
    a, b = curve.domain
    ts = cells(a, b, GRID * GRID)
    points, d1, d2 = curve(ts), curve(ts, 1), curve(ts, 2)
    pieces = occ_pieces(curve, occ_edges, size)
    if pieces is not None:
        want = []
        for t in ts:
            lo, hi, geom, reverse = next((p for p in pieces if p[0] <= t <= p[1]), pieces[-1])
            p, e1, e2 = curve_d2(geom, a + b - t if reverse else t)
            want.append((p, -e1 if reverse else e1, e2))
        worst = max(np.linalg.norm(points[k] - want[k][0]) for k in range(len(ts))) / size
        dworst = 0.0
        for m, mine in ((1, d1), (2, d2)):
            theirs = np.array([w[m] for w in want])
            dworst = max(dworst, np.max(np.linalg.norm(mine - theirs, axis=-1)) / max(np.max(np.linalg.norm(theirs, axis=-1)), 1e-300))
        report(f"B-spline curve, {len(curve.control_points)} poles ({len(pieces)} OCC edges)", worst, dworst)
        return
    mid = curve((a + b) / 2)
    occ = min(occ_edges, key=lambda e: GeomAPI_ProjectPointOnCurve(pnt(mid), CURVE_OF(e)[0]).LowerDistance()
              if GeomAPI_ProjectPointOnCurve(pnt(mid), CURVE_OF(e)[0]).NbPoints() else 1e300)
    name, geom = basis_name(CURVE_OF(occ)[0])
    if name == "Geom_BSplineCurve":
        raise RuntimeError("a B-spline edge of OCC's with another parameter than karkas's curve")
    worst = dworst = 0.0
    for k, t in enumerate(ts):
        proj = GeomAPI_ProjectPointOnCurve(pnt(points[k]), geom)
        worst = max(worst, proj.LowerDistance() / size)
        _, t1, _ = curve_d2(geom, proj.LowerDistanceParameter())
        dworst = max(dworst, min(np.linalg.norm(unit(d1[k]) - unit(t1)), np.linalg.norm(unit(d1[k]) + unit(t1))))
    report(f"{name} as NURBS", worst, dworst)


def compare_trims(face, occ_faces, report):
    """karkas's contains(u, v) against OCC's classifier of the face the surface carries."""
    S = face.surface
    (a, b), (c, d) = S.domain_u, S.domain_v
    mid = S((a + b) / 2, (c + d) / 2)
    occ = min(occ_faces, key=lambda f: GeomAPI_ProjectPointOnSurf(pnt(mid), SURFACE_OF(f)).LowerDistance())
    us, vs = np.linspace(a, b, GRID), np.linspace(c, d, GRID)
    eps = 1e-6 * max(b - a, d - c)
    tested = disagree = 0
    for u in us:
        for v in vs:
            states = set()
            for du, dv in ((0, 0), (eps, 0), (-eps, 0), (0, eps), (0, -eps)):
                s = BRepClass_FaceClassifier(occ, gp_Pnt2d(u + du, v + dv), 1e-9).State()
                states.add(s)
            if len(states) != 1 or states.pop() not in (TopAbs_IN, TopAbs_OUT):
                continue  # near the trim
            inside = BRepClass_FaceClassifier(occ, gp_Pnt2d(u, v), 1e-9).State() == TopAbs_IN
            tested += 1
            disagree += inside != face.contains(u, v)
    report(f"trims: {tested} points classified", float(disagree), 0.0, exact=True)
    return tested


def check_file(path):
    shape = occ_shape(path)
    occ_faces = explore(shape, TopAbs_FACE)
    occ_edges = explore(shape, TopAbs_EDGE)
    model = karkas.read_cad(path)
    if model.warning:
        raise RuntimeError(f"karkas did not read everything: {model.warning}")
    pts = [f.surface.sample(5, 5).reshape(-1, 3) for f in model.faces] + [c.sample(9) for c in model.curves]
    size = model_size(np.concatenate(pts))
    results = []

    def report(what, worst, dworst, exact=False):
        ok = worst == 0.0 if exact else (worst <= POINT_TOLERANCE and dworst <= DERIVATIVE_TOLERANCE)
        text = f"{what}: {int(worst)} disagree" if exact else f"{what}: points {worst:.1e}, derivatives {dworst:.1e}"
        results.append((ok, text, 0.0 if exact else worst, dworst))

    if len(model.faces) != len(occ_faces):
        raise RuntimeError(f"{len(model.faces)} faces read, OCC has {len(occ_faces)}")
    for face in model.faces:
        compare_surface(face, occ_faces, size, report)
        for loop in face.loops:
            for edge in loop:
                compare_curve(edge, occ_edges, size, report)
    for curve in model.curves:
        compare_curve(curve, occ_edges, size, report)
    if "trimmed" in os.path.basename(path):
        for face in model.faces:
            if compare_trims(face, occ_faces, report) < 1000:
                raise RuntimeError("too few points away from the trims")
    return results


def quiet_occ():
    """Open CASCADE's readers and writers report to standard output: silenced."""
    try:
        from OCP.Message import Message
        messenger = static(Message, "DefaultMessenger")()
        printers = messenger.Printers()
        for _ in range(printers.Size()):
            messenger.RemovePrinter(printers.First())
    except Exception:  # noqa: BLE001 - the messages are only noise
        pass


def main():
    quiet_occ()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--keep", help="write the files into this folder and keep them")
    args = parser.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-cad-read-")
    os.makedirs(folder, exist_ok=True)
    failures = 0
    start = time.time()
    count = 0
    for name, shape, formats in cases():
        for ext in formats:
            path = os.path.join(folder, f"{name}.{ext}")
            (write_step if ext == "step" else write_iges)(shape, path)
            try:
                results = check_file(path)
            except Exception as e:  # noqa: BLE001 - one line per failing file
                print(f"FAIL {name}.{ext}: {e}")
                failures += 1
                continue
            bad = [text for ok, text, _, _ in results if not ok]
            count += len(results)
            worst = max((r[2] for r in results), default=0.0)
            dworst = max((r[3] for r in results), default=0.0)
            kinds = sorted({text.split(":")[0] for _, text, _, _ in results})
            status = "FAIL" if bad or not results else "ok  "
            failures += bool(bad) or not results
            summary = bad[0] if bad else f"points {worst:.1e}, derivatives {dworst:.1e}"
            print(f"{status} {name}.{ext}: {len(results)} entities ({'; '.join(kinds)}); {summary}")
    print(f"cad read: {count} entities compared with Open CASCADE in {time.time() - start:.0f}s, "
          f"{failures} files failing")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
