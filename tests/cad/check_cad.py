#!/usr/bin/env python3
"""CAD acceptance check: Open CASCADE reads karkas's STEP and IGES files exactly.

For each case of the test set (LL curve, fitted defect-2 cubic, LL surface, bicubic surface,
composite Coons surface), the karkas CLI writes the samples of the curve or surface as CSV
(with their parameters t or u,v) and its exact B-spline form as .step and .iges. Each CAD file
is imported with Open CASCADE (the cadquery-ocp package: STEPControl_Reader /
IGESControl_Reader); the B-spline curve of the (single) edge or the B-spline surface of the
(single) face is taken with BRep_Tool and evaluated at karkas's own parameters: OCC keeps the
knot values it reads, so no re-parameterization is involved. The largest distance between
OCC's point and karkas's sample, divided by the size of the samples' bounding box, must stay
below 1e-9. One line per file; exit status 1 on any failure.

Usage: python3 tests/cad/check_cad.py [--karkas target/release/karkas] [--keep DIR]
"""

import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

from OCP.BRep import BRep_Tool
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Reader
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

# The downcasts are static methods: `Edge_s` in older OCP releases, `Edge` in newer ones.
TO_EDGE = getattr(TopoDS, "Edge_s", None) or TopoDS.Edge
TO_FACE = getattr(TopoDS, "Face_s", None) or TopoDS.Face

TOLERANCE = 1e-9
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def network(folder):
    """A curve network sampled from a smooth surface; curves cross at equal point indices."""

    def s(u, v):
        return (3.0 * u, 2.0 * v + 0.3 * math.sin(3.0 * u), math.sin(2.0 * u) * (1.0 + v * v))

    m, n, per = 4, 3, 5  # v-curves at 4 values of u, u-curves at 3 values of v
    paths = {}
    for name, count, steps, point in (
        ("v", m, (n - 1) * per, lambda c, k, steps: s(c / (m - 1), k / steps)),
        ("u", n, (m - 1) * per, lambda c, k, steps: s(k / steps, c / (n - 1))),
    ):
        path = os.path.join(folder, f"net-{name}.csv")
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["curve", "x", "y", "z"])
            for c in range(count):
                for k in range(steps + 1):
                    w.writerow([c, *(repr(x) for x in point(c, k, steps))])
        paths[name] = path
    return paths["u"], paths["v"]


def cases(folder):
    data = os.path.join(ROOT, "data")
    u_net, v_net = network(folder)
    return [
        ("ll-curve", "curve", ["curve", "ll", "--order", "5", "--closed",
                               os.path.join(data, "contour-53.csv")]),
        ("spline-curve", "curve", ["curve", "spline", "--ends", "periodic", "--param",
                                   "centripetal", os.path.join(data, "contour-53.csv")]),
        ("fit-curve", "curve", ["curve", "fit", "--knots", "0,0.3,0.5,0.7,1",
                                os.path.join(data, "hydrofoil-profile.csv")]),
        ("ll-surface", "surface", ["surface", "ll", "--order", "3",
                                   os.path.join(data, "aircraft-15x31.csv")]),
        # Closed around the body: the STEP and IGES surfaces carry the closed flag in v.
        ("ll-surface-closed", "surface", ["surface", "ll", "--order", "3", "--closed-v",
                                          os.path.join(data, "aircraft-15x31.csv")]),
        ("bicubic-surface", "surface", ["surface", "bicubic", "--param", "chord",
                                        os.path.join(data, "aircraft-15x31.csv")]),
        ("composite-coons", "surface", ["surface", "coons", "--kind", "composite",
                                        "--u-curves", u_net, "--v-curves", v_net]),
    ]


def run(karkas, args, output):
    done = subprocess.run([karkas, *args, "-o", output], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"karkas {' '.join(args)} -o {output}: {done.stderr.strip()}")


def read_samples(path, kind):
    """Parameters and points of a karkas CSV (t,x,y[,z] or u,v,x,y,z)."""
    with open(path) as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    k = 1 if kind == "curve" else 2
    out = []
    for r in rows:
        values = [float(x) for x in r]
        point = values[k:] + [0.0] * (3 - len(values[k:]))
        out.append((values[:k], point))
    return header, out


def shape_of(path):
    reader = STEPControl_Reader() if path.endswith(".step") else IGESControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        raise RuntimeError("the reader refused the file")
    if reader.TransferRoots() < 1:
        raise RuntimeError("nothing was transferred")
    return reader.OneShape()


def geometry(path, kind):
    """The Geom curve of the one edge or the Geom surface of the one face."""
    shape = shape_of(path)
    found = []
    explorer = TopExp_Explorer(shape, TopAbs_EDGE if kind == "curve" else TopAbs_FACE)
    while explorer.More():
        found.append(explorer.Current())
        explorer.Next()
    if kind == "curve":
        if len(found) != 1:
            raise RuntimeError(f"{len(found)} edges, expected 1")
        curve = BRep_Tool.Curve_s(TO_EDGE(found[0]), 0.0, 1.0)
        return curve
    if len(found) != 1:
        raise RuntimeError(f"{len(found)} faces, expected 1")
    return BRep_Tool.Surface_s(TO_FACE(found[0]))


def basis_name(geom):
    name = geom.DynamicType().Name()
    if "Trimmed" in name or "RectangularTrimmed" in name:
        name += "(" + geom.BasisCurve().DynamicType().Name() + ")" if hasattr(geom, "BasisCurve") \
            else "(" + geom.BasisSurface().DynamicType().Name() + ")"
    return name


def check(path, kind, samples):
    geom = geometry(path, kind)
    name = basis_name(geom)
    if "BSpline" not in name:
        raise RuntimeError(f"OCC made a {name}, not a B-spline")
    lo = [min(p[c] for _, p in samples) for c in range(3)]
    hi = [max(p[c] for _, p in samples) for c in range(3)]
    size = math.sqrt(sum((h - l) ** 2 for l, h in zip(lo, hi))) or 1.0
    worst = 0.0
    for params, p in samples:
        q = geom.Value(*params)
        d = math.dist((q.X(), q.Y(), q.Z()), p)
        worst = max(worst, d / size)
    return name, worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default=os.path.join(ROOT, "target", "release", "karkas"))
    parser.add_argument("--keep", help="write the files into this folder and keep them")
    args = parser.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-cad-")
    os.makedirs(folder, exist_ok=True)
    failures = 0
    for name, kind, command in cases(folder):
        csv_path = os.path.join(folder, name + ".csv")
        try:
            run(args.karkas, command, csv_path)
            _, samples = read_samples(csv_path, kind)
        except Exception as e:  # noqa: BLE001 - report and go on
            print(f"FAIL {name}: {e}")
            failures += 1
            continue
        for ext in (".step", ".iges"):
            path = os.path.join(folder, name + ext)
            try:
                run(args.karkas, command, path)
                geom_name, worst = check(path, kind, samples)
                ok = worst <= TOLERANCE
                print(f"{'ok  ' if ok else 'FAIL'} {name}{ext}: {geom_name}, {len(samples)} "
                      f"points, max error {worst:.2e} (relative to the bounding box)")
                failures += 0 if ok else 1
            except Exception as e:  # noqa: BLE001
                print(f"FAIL {name}{ext}: {e}")
                failures += 1
    if failures:
        print(f"{failures} failure(s)")
        return 1
    print("all CAD files read back exactly")
    return 0


if __name__ == "__main__":
    sys.exit(main())
