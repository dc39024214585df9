#!/usr/bin/env python3
"""Open the mesh files karkas wrote with meshio and trimesh and check their counts.

Usage: check_meshes.py --grid NU,NV FILE...

Every FILE is the mesh of one NU x NV sample grid (the surface commands and `karkas convert`
from a grid write these), so it must have NU*NV vertices and 2(NU-1)(NV-1) triangles; a
structured VTK grid has (NU-1)(NV-1) quadrilaterals instead, and an STL file has no shared
vertices, so only its triangles are counted (and meshio's merged vertices must be NU*NV).
Formats: .ply .obj .stl (meshio and trimesh), .vtk (meshio; trimesh for triangle meshes),
.glb (trimesh; meshio has no glTF reader), .vts (parsed as XML: extents and array lengths,
as neither library reads VTK XML structured grids). Exit 1 with one line per mismatch.
"""
import argparse
import pathlib
import sys
import xml.etree.ElementTree as ET

import meshio
import trimesh


def check(path, nu, nv, problems):
    n, tri, quad = nu * nv, 2 * (nu - 1) * (nv - 1), (nu - 1) * (nv - 1)
    ext = path.suffix.lower()

    def expect(what, got, want):
        if got != want:
            problems.append(f"{path}: {what}: {got}, expected {want}")

    if ext == ".vts":
        root = ET.parse(path).getroot()
        piece = root.find("StructuredGrid/Piece")
        extent = [int(v) for v in piece.get("Extent").split()]
        expect("extent", extent, [0, nv - 1, 0, nu - 1, 0, 0])
        for array in root.iter("DataArray"):
            values = array.text.split()
            expect(f"values of {array.get('Name')}", len(values), 3 * n)
        return
    if ext in (".ply", ".obj", ".stl", ".vtk"):
        m = meshio.read(path)
        cells = {c.type: len(c.data) for c in m.cells}
        expect("meshio vertices", len(m.points), n)
        if ext == ".vtk" and "quad" in cells:
            expect("meshio quads", cells, {"quad": quad})
        else:
            expect("meshio triangles", cells, {"triangle": tri})
    if ext in (".ply", ".obj", ".stl", ".glb") or (ext == ".vtk" and "quad" not in cells):
        t = trimesh.load(path, force="mesh", process=False)
        expect("trimesh triangles", len(t.faces), tri)
        expect("trimesh vertices", len(t.vertices), 3 * tri if ext == ".stl" else n)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grid", required=True, help="NU,NV")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    nu, nv = (int(v) for v in args.grid.split(","))
    problems = []
    for name in args.files:
        try:
            check(pathlib.Path(name), nu, nv, problems)
        except Exception as e:  # a reader that fails is a finding, not a crash
            problems.append(f"{name}: cannot be read: {type(e).__name__}: {e}")
    for line in problems:
        print(f"check_meshes: {line}")
    if not problems:
        print(f"check_meshes: {len(args.files)} files ok ({nu} x {nv} grid)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
