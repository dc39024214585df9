#!/usr/bin/env python3
"""`karkas section MODEL --plane NX,NY,NZ,C --x X --y Y --z Z -o OUT.csv` against Open CASCADE:
the plane sections of a CAD model's faces agree with BRepAlgoAPI_Section of the model (as Open
CASCADE reads it back from the same file) by a gp_Pln, judged by Open CASCADE.

Open CASCADE (cadquery-ocp) builds and writes the models, away from the origin: the plate with
blind holes of check_inspect.py (trimmed planes and cylinders, STEP), the same plate with every
face converted to NURBS (STEP, and IGES: 144 faces on 128 surfaces), a sphere, a whole torus and
a cylinder (analytic STEP) and a wing lofted through three periodic B-spline airfoils
(BRepOffsetAPI_ThruSections: a solid with planar caps, STEP). Each is cut by one oblique --plane
and one --x, --y and --z plane through its holes or curved faces (none holds a face or runs along
an edge), in one run at karkas's default tolerance T (1e-4 of its size: the diagonal of its
faces' control points' box, which must hold Open CASCADE's tight box and be at most 1.5 times its
diagonal) and one at --tolerance T/10. Open CASCADE's section edges are sampled within T/100:
lines and conics (exact) with GCPnts_QuasiUniformDeflection; approximated B-spline edges (the
wing's lie up to 1.5e-5 of its size off the exact section) have their samples moved onto the exact
section (from their pcurve, Newton on their face's surface to the plane) and their chords cut in
three until the exact points at the thirds lie within T/100. For each model, tolerance and plane:
- the pieces come in plane order (--plane, then --x, --y, --z), each on its plane (1e-9 of the
  size), t is the length along each (1e-9 size), the summary line counts the CSV's pieces, and a
  plane has pieces exactly when Open CASCADE's section is not empty;
- two-sided distance: karkas's points and the quarter points of its chords lie within
  1.05 T + 1e-9 size of Open CASCADE's sampled edges, and those samples, with points at most T
  apart along their chords, within 1.05 T of karkas's polylines (distances to chords: the nearest
  of 4 chords found by cKDTree, then every chord that may be nearer where that exceeds the limit);
- the pieces' total length within 1e-3 (relative) of Open CASCADE's (BRepGProp linear properties
  of the section), and not longer than the larger of that and the exact samples' length by more
  than 1e-9 of it plus 2e-9 size per chord (inscribed polylines are shorter: rounding only);
- every model here is closed: every karkas piece is closed (its last row repeats its first point
  exactly), and their count equals the count of closed wires Open CASCADE's section edges form
  (edge ends within 1e-6 size joined; a wire is closed when each vertex ends two edges), with no
  open wire.
One line per case (model, tolerance, plane); exit status 1 on any failure.

Usage: python3 tests/cad/check_section.py --karkas target/release/karkas [--keep DIR]
"""

import argparse
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

from OCP.BRepAdaptor import BRepAdaptor_Curve, BRepAdaptor_Curve2d, BRepAdaptor_Surface
from OCP.BRepAlgoAPI import BRepAlgoAPI_Section
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeWire, BRepBuilderAPI_NurbsConvert
from OCP.BRepGProp import BRepGProp
from OCP.BRepOffsetAPI import BRepOffsetAPI_ThruSections
from OCP.BRepPrimAPI import BRepPrimAPI_MakeCylinder, BRepPrimAPI_MakeSphere, BRepPrimAPI_MakeTorus
from OCP.Bnd import Bnd_Box
from OCP.GCPnts import GCPnts_QuasiUniformDeflection
from OCP.GeomAbs import GeomAbs_Circle, GeomAbs_Ellipse, GeomAbs_Hyperbola, GeomAbs_Line, GeomAbs_Parabola
from OCP.GeomAPI import GeomAPI_Interpolate
from OCP.GProp import GProp_GProps
from OCP.IGESControl import IGESControl_Reader
from OCP.Message import Message
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS, TopoDS_Shape
from OCP.gp import gp_Ax2, gp_Dir, gp_Pln, gp_Pnt, gp_Vec

try:  # OCP 7.7
    from OCP.TColgp import TColgp_HArray1OfPnt as HArray1OfPnt
except ImportError:  # OCP 8
    from OCP.collections import HArray1_gp_Pnt as HArray1OfPnt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_inspect import holed_plate, static, write_iges, write_step  # noqa: E402

EXACT = (GeomAbs_Line, GeomAbs_Circle, GeomAbs_Ellipse, GeomAbs_Hyperbola, GeomAbs_Parabola)
SLACK = 1.05  # karkas's chord tolerance, with room for rounding and the samples' T/100


def wing(origin=(40.0, -15.0, 8.0)):
    """A solid lofted through three periodic B-spline airfoils (round nose, thin rounded tail,
    cambered: an inflection on the lower side) at spans 0, 9, 20, tapered and swept."""
    x0, y0, z0 = origin
    loft = BRepOffsetAPI_ThruSections(True, False, 1e-6)
    for span, chord, sweep in ((0.0, 8.0, 0.0), (9.0, 6.0, 1.5), (20.0, 3.5, 4.0)):
        pts = HArray1OfPnt(1, 28)
        for k, a in enumerate(np.linspace(0.0, 2.0 * math.pi, 28, endpoint=False)):
            y = chord * (0.07 * math.sin(a) * (1.0 - 0.5 * math.cos(a)) + 0.03 * math.sin(a) ** 2)
            pts.SetValue(k + 1, gp_Pnt(x0 + sweep + 0.5 * chord * (1.0 + math.cos(a)), y0 + y, z0 + span))
        curve = GeomAPI_Interpolate(pts, True, 1e-9)
        curve.Perform()
        loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve.Curve()).Edge()).Wire())
    loft.Build()
    return loft.Shape()


def cases():
    """(name, shape, formats, planes): a plane is ('plane', (nx, ny, nz, c)) or (axis, value),
    in karkas's order (--plane, --x, --y, --z)."""
    plate = holed_plate()
    plate_planes = [("plane", (0.1, 0.05, 1.0, 32.1)), ("x", 105.7), ("y", -38.4), ("z", 23.0)]
    tilt = gp_Ax2(gp_Pnt(3.0, -2.0, 5.0), gp_Dir(0.2, 0.3, 1.0))
    torus = gp_Ax2(gp_Pnt(1.0, 2.0, 3.0), gp_Dir(0.3, -0.2, 1.0))
    return [
        ("plate", plate, ("step",), plate_planes),
        ("plate-nurbs", BRepBuilderAPI_NurbsConvert(plate, True).Shape(), ("step", "igs"), plate_planes),
        ("sphere", BRepPrimAPI_MakeSphere(gp_Pnt(1.0, 2.0, -3.0), 3.0).Shape(), ("step",),
         [("plane", (1.0, 1.0, 1.0, 0.5)), ("x", 2.1), ("y", 0.3), ("z", -2.2)]),
        ("torus", BRepPrimAPI_MakeTorus(torus, 5.0, 1.5).Shape(), ("step",),
         [("plane", (0.35, -0.1, 1.0, 3.9)), ("x", 1.4), ("y", 5.5), ("z", 3.3)]),
        ("cylinder", BRepPrimAPI_MakeCylinder(tilt, 2.0, 7.0).Shape(), ("step",),
         [("plane", (1.0, -0.5, 0.3, 6.6)), ("x", 3.4), ("y", -1.0), ("z", 8.0)]),
        ("wing", wing(), ("step",), [("plane", (0.2, 0.0, 1.0, 28.0)), ("x", 43.3), ("y", -14.9), ("z", 14.2)]),
    ]


def plane_of(spec):
    """A plane spec's unit normal n and c, the plane n . p = c."""
    kind, value = spec
    n, c = (value[:3], value[3]) if kind == "plane" else (np.eye(3)["xyz".index(kind)], value)
    return np.array(n) / np.linalg.norm(n), c / np.linalg.norm(n)


def read_back(path):
    """The model as Open CASCADE reads its file, and its size (the diagonal of its tight box)."""
    reader = STEPControl_Reader() if path.endswith(".step") else IGESControl_Reader()
    reader.ReadFile(path)
    reader.TransferRoots()
    box = Bnd_Box()
    static(BRepBndLib, "AddOptimal")(reader.OneShape(), box, False, False)
    return reader.OneShape(), float(np.linalg.norm(np.subtract(box.CornerMax().Coord(), box.CornerMin().Coord())))


def edges_of(shape):
    edges = TopExp_Explorer(shape, TopAbs_EDGE)
    while edges.More():
        yield static(TopoDS, "Edge")(edges.Current())
        edges.Next()


def occ_section(shape, normal, c, size):
    """Open CASCADE's section (with pcurves on the model's faces), its length, and the closed
    and open wires its edges form (ends within 1e-6 size joined; closed: every vertex ends two)."""
    section = BRepAlgoAPI_Section(shape, gp_Pln(*normal, -c), False)
    section.Approximation(True)
    section.ComputePCurveOn1(True)
    section.Build()
    props = GProp_GProps()
    static(BRepGProp, "LinearProperties")(section.Shape(), props)
    curves = [BRepAdaptor_Curve(e) for e in edges_of(section.Shape())]
    if not curves:
        return section, 0.0, 0, 0
    ends = np.array([q.Value(t).Coord() for q in curves for t in (q.FirstParameter(), q.LastParameter())])
    near = cKDTree(ends).query_pairs(1e-6 * size, output_type="ndarray").reshape(-1, 2)
    _, vertex = connected_components(coo_matrix((np.ones(len(near)), near.T), (len(ends),) * 2))
    links = vertex.reshape(-1, 2).T  # each edge's two vertices
    count, wire = connected_components(coo_matrix((np.ones(len(curves)), links), (vertex.max() + 1,) * 2))
    closed = sum(bool(np.all(np.bincount(vertex)[wire == w] == 2)) for w in range(count))
    return section, props.Mass(), closed, count - closed


def onto_section(surface, u, v, normal, c):
    """The point of the plane on `surface` nearest S(u, v) (Newton, the shortest steps in space;
    plain floats: it runs for every sample) and the section's tangent there."""
    P, Du, Dv = gp_Pnt(), gp_Vec(), gp_Vec()
    n0, n1, n2 = normal
    for _ in range(12):
        surface.D1(u, v, P, Du, Dv)
        (x, y, z), (a0, a1, a2), (b0, b1, b2) = P.Coord(), Du.Coord(), Dv.Coord()
        f, ga, gb = n0 * x + n1 * y + n2 * z - c, n0 * a0 + n1 * a1 + n2 * a2, n0 * b0 + n1 * b1 + n2 * b2
        if abs(f) < 1e-13 * (1.0 + abs(c)):  # the tangent: normal x (Su x Sv)
            m0, m1, m2 = a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0
            return (x, y, z), (n1 * m2 - n2 * m1, n2 * m0 - n0 * m2, n0 * m1 - n1 * m0)
        e, f_, g = a0 * a0 + a1 * a1 + a2 * a2, a0 * b0 + a1 * b1 + a2 * b2, b0 * b0 + b1 * b1 + b2 * b2
        h0, h1 = g * ga - f_ * gb, e * gb - f_ * ga  # the first fundamental form's inverse on (ga, gb), x det
        step = f / (ga * h0 + gb * h1)
        u, v = u - step * h0, v - step * h1
    raise RuntimeError(f"no point of the plane on a face near {P.Coord()}")


def occ_polylines(section, normal, c, deflection):
    """The section's edges as polylines within `deflection` of the exact section (see the module
    docs), and how far across the section OCC's B-spline edges lie from the exact points."""
    out, moved = [], 0.0
    for edge in edges_of(section.Shape()):
        curve, face = BRepAdaptor_Curve(edge), TopoDS_Shape()
        sample = GCPnts_QuasiUniformDeflection(curve, deflection, curve.FirstParameter(), curve.LastParameter())
        ts = np.array([sample.Parameter(i + 1) for i in range(sample.NbPoints())])
        if curve.GetType() in EXACT or not section.HasAncestorFaceOn1(edge, face):
            out.append(np.array([curve.Value(t).Coord() for t in ts]))
            continue
        face = static(TopoDS, "Face")(face)
        pcurve, surface = BRepAdaptor_Curve2d(edge, face), BRepAdaptor_Surface(face)

        def exact(params):
            got = [onto_section(surface, *pcurve.Value(t).Coord(), normal, c) for t in params]
            return np.array([g[0] for g in got]), np.array([g[1] for g in got])

        points, tangents = exact(ts)
        pending, span = np.arange(len(ts) - 1), ts[-1] - ts[0]
        while len(pending):  # thirds, not halves: an inflection may hide at a chord's midpoint
            t0, t1, p0, p1 = ts[pending], ts[pending + 1], points[pending], points[pending + 1]
            new = np.concatenate([t0 + (t1 - t0) / 3.0, t0 + 2.0 * (t1 - t0) / 3.0])
            new_points, new_tangents = exact(new)
            bad = np.tile(np.maximum(to_chords(new_points[:len(pending)], p0, p1),
                                     to_chords(new_points[len(pending):], p0, p1)) > deflection, 2)
            order = np.argsort(np.concatenate([ts, new]), kind="stable")
            ts, points = np.concatenate([ts, new])[order], np.concatenate([points, new_points])[order]
            tangents = np.concatenate([tangents, new_tangents])[order]
            where = np.flatnonzero(np.concatenate([np.zeros(len(order) - len(new), bool), bad])[order])
            pending = np.unique(np.concatenate([where - 1, where]))
            pending = pending[ts[pending + 1] - ts[pending] > 1e-9 * span]  # a kink: stop there
        d = np.array([curve.Value(t).Coord() for t in ts]) - points
        tangents /= np.linalg.norm(tangents, axis=1)[:, None]
        moved = max(moved, np.linalg.norm(d - np.einsum("ij,ij->i", d, tangents)[:, None] * tangents, axis=1).max())
        out.append(points)
    return out, moved


def chords(polylines, longest):
    """The chords of polylines as ends a, b, the long ones split into pieces at most `longest`."""
    a, b = np.concatenate([p[:-1] for p in polylines]), np.concatenate([p[1:] for p in polylines])
    parts = np.maximum(1, np.ceil(np.linalg.norm(b - a, axis=1) / longest)).astype(int)
    step = np.repeat(1.0 / parts, parts)[:, None]
    f = (np.arange(parts.sum()) - np.repeat(np.cumsum(parts) - parts, parts))[:, None] * step
    a, b = np.repeat(a, parts, 0), np.repeat(b, parts, 0)
    return a + f * (b - a), a + (f + step) * (b - a)


def to_chords(q, a, b):
    """Distances from points q to chords a, b (broadcast)."""
    ab = b - a
    t = np.clip(np.einsum("...i,...i", q - a, ab) / np.maximum(np.einsum("...i,...i", ab, ab), 1e-300), 0.0, 1.0)
    return np.linalg.norm(q - a - t[..., None] * ab, axis=-1)


def distances(q, polylines, limit, longest):
    """Each point's distance to the polylines: to the nearest of the 4 chords whose midpoints are
    nearest (an upper bound); where that exceeds `limit`, to every chord whose midpoint lies
    within it plus half a chord (exact)."""
    a, b = chords(polylines, longest)
    tree, k, out = cKDTree(0.5 * (a + b)), min(4, len(a)), np.empty(len(q))
    for s in range(0, len(q), 50000):
        idx = tree.query(q[s:s + 50000], k=k, workers=2)[1].reshape(-1, k)
        out[s:s + 50000] = to_chords(q[s:s + 50000, None, :], a[idx], b[idx]).min(axis=1)
    half, over = 0.5 * np.linalg.norm(b - a, axis=1).max(), np.flatnonzero(out > limit)
    for s in range(0, len(over), 1000):
        o = over[s:s + 1000]
        near = tree.query_ball_point(q[o], out[o] * (1.0 + 1e-9) + half)
        counts = np.array([len(n) for n in near])
        if counts.sum() < 5e6:  # else keep the upper bound
            idx = np.concatenate(near).astype(int)
            d = to_chords(np.repeat(q[o], counts, 0), a[idx], b[idx])
            out[o] = np.minimum.reduceat(d, np.cumsum(counts) - counts)
    return out


def run_karkas(karkas, model, planes, tol, out):
    """karkas's pieces (rows t, x, y, z) and its tolerance, checked against its summary line."""
    cmd = [karkas, "section", model, "-o", out] + (["--tolerance", repr(tol)] if tol else [])
    for kind, value in planes:
        cmd += ["--" + kind, ",".join(map(repr, value)) if kind == "plane" else repr(value)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"karkas exit {done.returncode}: {done.stderr.strip()}")
    told = re.search(r"wrote .* \((\d+) section pieces of .* from (\d+) planes, tolerance (\S+)\)", done.stderr)
    rows = np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)
    pieces = [rows[rows[:, 0] == s, 1:5] for s in np.unique(rows[:, 0])] if len(rows) else []
    if not told or int(told[1]) != len(pieces) or int(told[2]) != len(planes):
        raise RuntimeError(f"karkas's summary disagrees with its {len(pieces)} pieces: {done.stderr.strip()}")
    return pieces, float(told[3])


def check(karkas, name, path, planes, sections, tol, size, folder):
    """One run of karkas (`tol` None: its default), one line per plane; returns the count of
    failing planes and the tolerance karkas used."""
    share = "1e-4" if tol is None else "1e-5"
    pieces, tol = run_karkas(karkas, path, planes, tol, os.path.join(folder, f"{os.path.basename(path)}-{share}.csv"))
    common = []
    if share == "1e-4" and not size * (1.0 - 1e-6) <= 1e4 * tol <= 1.5 * size:
        common.append(f"karkas's size {1e4 * tol:.6g}, OCC's box {size:.6g}")
    normals = [plane_of(p) for p in planes]
    along = [np.abs(p[1:, 0] - np.cumsum(np.linalg.norm(np.diff(p[:, 1:], axis=0), axis=1))).max(initial=abs(p[0, 0]))
             for p in pieces]
    if pieces and max(along) > 1e-9 * size:
        common.append("t is not the length along the piece")
    pieces = [p[:, 1:] for p in pieces]
    owner = [int(np.argmin([np.abs(p @ n - c).max() for n, c in normals])) for p in pieces]
    if owner != sorted(owner):
        common.append(f"pieces out of plane order: {owner}")
    failed = 0
    for k, (spec, (normal, c), (section, length, closed, opened)) in enumerate(zip(planes, normals, sections)):
        mine, faults = [p for p, o in zip(pieces, owner) if o == k], list(common)
        label = "plane " + ",".join(f"{v:g}" for v in spec[1]) if spec[0] == "plane" else f"{spec[0]} = {spec[1]:g}"
        head = f"{name} T={share} size ({tol:.3g}) {label}"
        if length == 0.0 or not mine:
            faults += [f"{len(mine)} karkas pieces, OCC's section {length:.6g} long"] if length or mine else []
            print(f"{'FAIL' if faults else 'ok  '} {head}: no section" + "".join("; " + f for f in faults))
            failed += bool(faults)
            continue
        off = max(np.abs(p @ normal - c).max() for p in mine)
        if off > 1e-9 * size:
            faults.append(f"a point {off:.2g} off its plane")
        limit = SLACK * tol + 1e-9 * size
        occ, moved = occ_polylines(section, normal, c, tol / 100.0)
        vertex = distances(np.concatenate(mine), occ, limit, size / 500.0)
        quarter = np.concatenate([p[:-1] + f * (p[1:] - p[:-1]) for p in mine for f in (0.25, 0.5, 0.75)])
        ko = max(vertex.max(), distances(quarter, occ, limit, size / 500.0).max())
        dense = np.concatenate([chords(occ, tol)[0]] + [p[-1:] for p in occ])  # at most T apart
        ok_ = distances(dense, mine, limit, size / 500.0).max()
        for what, d in (("a karkas point", ko), ("a point of OCC's section", ok_)):
            if d > limit:
                faults.append(f"{what} {d / tol:.3g} T from the other's")
        ours, theirs = (sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in lines) for lines in (mine, occ))
        count = sum(len(p) - 1 for p in mine)
        if abs(ours / length - 1.0) > 1e-3:
            faults.append(f"length {ours:.9g}, OCC {length:.9g}")
        if ours > max(length, theirs) * (1.0 + 1e-9) + 2e-9 * size * count:
            faults.append(f"length {ours:.12g} longer than OCC's {max(length, theirs):.12g}")
        shut = sum(bool(np.all(p[0] == p[-1])) for p in mine)
        if shut != len(mine) or opened or shut != closed:
            faults.append(f"{shut} of {len(mine)} pieces closed, OCC {closed} closed wires and {opened} open")
        failed += bool(faults)
        print(f"{'FAIL' if faults else 'ok  '} {head}: {len(mine)} pieces, {shut} closed (OCC {closed}, "
              f"{opened} open), {count} chords, length {ours / length - 1.0:+.1e}, karkas->OCC {ko / tol:.3f} T "
              f"(points {vertex.max() / size:.0e} size), OCC->karkas {ok_ / tol:.3f} T"
              + (f" (OCC's B-splines off by {moved / tol:.2g} T)" if moved else "") + "".join("; " + f for f in faults))
    return failed, tol


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default="target/release/karkas", help="the karkas binary")
    parser.add_argument("--keep", help="write the models and sections into this folder and keep them")
    args = parser.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-section-")
    os.makedirs(folder, exist_ok=True)
    static(Message, "DefaultMessenger")().ChangePrinters().Clear()  # no transfer statistics on stdout
    failed = 0
    for name, built, formats, planes in cases():
        for ext in formats:
            path = os.path.join(folder, f"{name}.{ext}")
            (write_step if ext == "step" else write_iges)(built, path)
            shape, size = read_back(path)
            sections = [occ_section(shape, *plane_of(p), size) for p in planes]
            tol = None
            for share in ("1e-4", "1e-5"):
                try:
                    bad, tol = check(args.karkas, f"{name}.{ext}", path, planes, sections,
                                     tol and tol / 10.0, size, folder)
                    failed += bad
                except Exception as e:  # noqa: BLE001 - one line per failing case
                    print(f"FAIL {name}.{ext} T={share} size: {e}")
                    failed, tol = failed + 1, tol or 1e-4 * size
    print(f"check_section: {failed} failing cases")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
