#!/usr/bin/env python3
"""Open the mesh files karkas wrote with meshio and trimesh and check their counts.

Usage: check_meshes.py --grid NU,NV FILE...
       check_meshes.py --closed KARKAS FOLDER

Every FILE is the mesh of one NU x NV sample grid (the surface commands and `karkas convert`
from a grid write these), so it must have NU*NV vertices and 2(NU-1)(NV-1) triangles; a
structured VTK grid has (NU-1)(NV-1) quadrilaterals instead, and an STL file has no shared
vertices, so only its triangles are counted (and meshio's merged vertices must be NU*NV).
Formats: .ply .obj .stl (meshio and trimesh), .vtk (meshio; trimesh for triangle meshes),
.glb (trimesh; meshio has no glTF reader), .vts (parsed as XML: extents and array lengths,
as neither library reads VTK XML structured grids). The legacy VTK normals are
`NORMALS Normals float`, which meshio 5 does not know: it reads a copy with that line as
`VECTORS` (the same layout), after checking the line is there.

With --closed, the binary KARKAS writes closed surfaces into FOLDER (a torus by `surface ll
--closed-u --closed-v` from a grid of nodes, and by `surface dps-tube` from a skeleton) as
OBJ, PLY and GLB, each also with --flip-normals: trimesh must find every one watertight
with consistent winding (the seams are welded), and the flipped file enclosing the same
volume with the opposite sign. Exit 1 with one line per mismatch.
"""
import argparse
import math
import pathlib
import subprocess
import sys
import tempfile
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
        m = read_with(meshio.read, path, problems)
        cells = {c.type: len(c.data) for c in m.cells}
        expect("meshio vertices", len(m.points), n)
        if ext == ".vtk" and "quad" in cells:
            expect("meshio quads", cells, {"quad": quad})
        else:
            expect("meshio triangles", cells, {"triangle": tri})
    if ext in (".ply", ".obj", ".stl", ".glb") or (ext == ".vtk" and "quad" not in cells):
        t = read_with(lambda p: trimesh.load(p, force="mesh", process=False), path, problems)
        expect("trimesh triangles", len(t.faces), tri)
        expect("trimesh vertices", len(t.vertices), 3 * tri if ext == ".stl" else n)


def read_with(reader, path, problems):
    """reader(path); a legacy VTK file is read from a copy with its NORMALS line as VECTORS
    (meshio, which trimesh also uses for VTK, does not know NORMALS)."""
    if path.suffix.lower() != ".vtk":
        return reader(path)
    text = path.read_text()
    if "\nNORMALS Normals float\n" not in text:
        problems.append(f"{path}: no 'NORMALS Normals float' point data")
    with tempfile.TemporaryDirectory() as folder:
        copy = pathlib.Path(folder) / path.name
        copy.write_text(text.replace("\nNORMALS Normals float\n", "\nVECTORS Normals float\n"))
        return reader(copy)


def torus_grid(path, rows, cols):
    """A grid of nodes on a torus (i around the axis, j around the tube), no node repeated."""
    lines = ["i,j,x,y,z"]
    for i in range(rows):
        for j in range(cols):
            u, v = 2 * math.pi * i / rows, 2 * math.pi * j / cols
            r = 3 + math.cos(v)
            lines.append(f"{i},{j},{r * math.cos(u)},{r * math.sin(u)},{math.sin(v)}")
    path.write_text("\n".join(lines) + "\n")


def torus_skeleton(folder, m1, n1, m2, n2):
    """The skeleton files of a torus for `surface dps-tube`: m1 curves along, m2 rings."""
    def at(p, q):
        u, v = 2 * math.pi * p / (m1 * n1), 2 * math.pi * q / (m2 * n2)
        r = 3 + math.cos(u)
        return f"{r * math.cos(v)},{r * math.sin(v)},{math.sin(u)}"
    along = ["i,q,x,y,z"] + [f"{i},{q},{at(i * n1, q)}" for i in range(m1) for q in range(m2 * n2)]
    across = ["j,p,x,y,z"] + [f"{j},{p},{at(p, j * n2)}" for j in range(m2) for p in range(m1 * n1)]
    (folder / "along.csv").write_text("\n".join(along) + "\n")
    (folder / "across.csv").write_text("\n".join(across) + "\n")


def check_closed(karkas, folder, problems):
    """Writes closed surfaces with KARKAS into FOLDER and checks them in trimesh (--closed)."""
    folder = pathlib.Path(folder)
    torus_grid(folder / "torus-grid.csv", 12, 16)
    torus_skeleton(folder, 3, 4, 4, 5)
    commands = {
        "ll-torus": ["surface", "ll", "--closed-u", "--closed-v", "--samples", "25,33",
                     str(folder / "torus-grid.csv")],
        "dps-tube": ["surface", "dps-tube", "--along", str(folder / "along.csv"),
                     "--across", str(folder / "across.csv"), "--n1", "4", "--n2", "5"],
    }
    count = 0
    for name, command in commands.items():
        for ext in ("obj", "ply", "glb"):
            volumes = []
            for flip in ([], ["--flip-normals"]):
                out = folder / f"{name}{'-flipped' if flip else ''}.{ext}"
                run = subprocess.run([karkas, *command, "-o", str(out), *flip],
                                     capture_output=True, text=True)
                if run.returncode != 0:
                    problems.append(f"{out}: karkas failed: {run.stderr.strip()}")
                    continue
                t = trimesh.load(out, force="mesh", process=False)
                if not t.is_watertight:
                    problems.append(f"{out}: not watertight in trimesh")
                if not t.is_winding_consistent:
                    problems.append(f"{out}: winding not consistent in trimesh")
                volumes.append(t.volume)
                count += 1
            if len(volumes) == 2 and not (
                volumes[0] * volumes[1] < 0
                and abs(volumes[0] + volumes[1]) <= 1e-6 * abs(volumes[0])
            ):
                problems.append(f"{name}.{ext}: --flip-normals volumes {volumes}, expected opposite")
    return count


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grid", help="NU,NV")
    parser.add_argument("--closed", nargs=2, metavar=("KARKAS", "FOLDER"),
                        help="write closed surfaces with KARKAS into FOLDER and check them")
    parser.add_argument("files", nargs="*")
    args = parser.parse_args()
    problems = []
    if args.closed:
        try:
            count = check_closed(*args.closed, problems)
        except Exception as e:  # a reader that fails is a finding, not a crash
            problems.append(f"closed surfaces: {type(e).__name__}: {e}")
            count = 0
        for line in problems:
            print(f"check_meshes: {line}")
        if not problems:
            print(f"check_meshes: {count} closed meshes watertight, winding consistent, flipped")
        return 1 if problems else 0
    if not args.grid or not args.files:
        parser.error("--grid NU,NV and files, or --closed KARKAS FOLDER")
    nu, nv = (int(v) for v in args.grid.split(","))
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
