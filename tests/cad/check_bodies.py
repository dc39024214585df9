#!/usr/bin/env python3
"""CAD acceptance check for bodies: poles, seams, caps and solids as Open CASCADE reads them.

karkas writes closed bodies as STEP and IGES: an ellipsoid whose first and last grid rows
are single points (poles), closed around by `--closed-v`, through `surface ll --interpolate`
and `surface bicubic` (default parameters: a pole row needs no option), and as a curve
network whose first and last rings are single points through `surface coons --kind
gordon-spline`; a fuselage-like body with poles through `surface bicubic`; a tube (`surface
bicubic`) and the demo's aircraft grid (`data/aircraft-15x31.csv`, closed across its plane of
symmetry by `--closed-v`, `surface ll`) capped at both ends by `--cap`; a tapered wing of
sharp-trailing-edge sections closed around by `--crease-v` (`surface bicubic`; a
C^0 seam at the edge: the tangents on its two sides must differ by more than 5 degrees on
the finely sampled surface) and capped at root and tip; the same wing as a curve network
(closed sections whose points crowd at the nose only, spanwise lines) through `surface coons
--kind gordon-spline --crease-v --cap`. Each file is read by Open
CASCADE (cadquery-ocp): BRepCheck_Analyzer must find the shape valid; the STEP file must hold
one solid; the face area (GProp) must be within 1e-3 of the area of the same surface finely
sampled by karkas (a 400 x 400 CSV, triangulated here, caps added as the areas the command
reports) and, for the ellipsoid, of the analytic area; the volume (GProp at 1e-7) within
1e-3 of the analytic one (ellipsoid) and of the finely sampled surface closed by fans at its
ends (capped bodies), and within 1e-6 of the volume the command reports.
IGES holds the faces: sewn (BRepBuilderAPI_Sewing), several faces must close into one shell
with the same volume. The same command writing an STL mesh (`--samples 200,400`, `--cap` as
for the solid): trimesh must find it watertight and a volume (`is_watertight`, `is_volume`:
poles closed by fans, seams welded, caps, normals outwards), with no triangle of zero area and
its volume within 1e-3 of Open CASCADE's volume of the STEP solid. One line per file with the
counts; exit 1 on any failure. One case per kind of body and method of the acceptance (ll,
bicubic and coons on the ellipsoid, a fuselage, a capped tube, the capped aircraft, the
creased capped wing, a wing lofted through two sharp-edged NACA sections by `karkas loft
--cap`), small enough to run in well under two minutes.

Usage: python3 tests/cad/check_bodies.py [--karkas target/release/karkas] [--keep DIR]
"""

import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np
import trimesh
from OCP.BRepBuilderAPI import BRepBuilderAPI_Sewing
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Reader
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_FACE, TopAbs_SHELL, TopAbs_SOLID
from OCP.TopExp import TopExp_Explorer
from scipy.integrate import dblquad

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
AREA_TOLERANCE = 1e-3
VOLUME_TOLERANCE = 1e-3


def write_grid(path, rows, cols, point):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["i", "j", "x", "y", "z"])
        for i in range(rows):
            for j in range(cols):
                w.writerow([i, j, *(repr(float(x)) for x in point(i, j))])


ELLIPSOID = (2.0, 1.0, 0.7)


def ellipsoid(i, j, rows=49, cols=96):
    a, b, c = ELLIPSOID
    theta, phi = math.pi * i / (rows - 1), 2 * math.pi * j / cols
    r = 0.0 if i in (0, rows - 1) else math.sin(theta)
    return a * math.cos(theta), b * r * math.cos(phi), c * r * math.sin(phi)


def ellipsoid_area():
    a, b, c = ELLIPSOID

    def density(phi, theta):
        st, ct, sp, cp = math.sin(theta), math.cos(theta), math.sin(phi), math.cos(phi)
        # |S_theta x S_phi| of (a cos t, b sin t cos p, c sin t sin p).
        n = np.array([b * c * st * ct, a * c * st * st * cp, a * b * st * st * sp])
        return float(np.linalg.norm(n))

    return dblquad(density, 0.0, math.pi, 0.0, 2 * math.pi, epsabs=1e-11, epsrel=1e-11)[0]


def fuselage(i, j, rows=31, cols=40):
    """A body of revolution-like fuselage: an elliptic nose and a tapered tail, both poles."""
    x = 10.0 * i / (rows - 1)
    r = 0.0 if i in (0, rows - 1) else 0.8 * math.sin(math.pi * (x / 10.0) ** 0.7)
    phi = 2 * math.pi * j / cols
    return x, r * math.cos(phi), 0.8 * r * math.sin(phi) + 0.05 * x


def tube(i, j, rows=13, cols=24):
    phi = 2 * math.pi * j / cols
    r = 1.0 + 0.2 * math.sin(i / 3.0)
    return 0.3 * i, r * math.cos(phi), 0.6 * r * math.sin(phi)


def ellipsoid_network(folder, rings=13, meridians=16, per=4):
    """The ellipsoid as a curve network: v-curves are closed rings x = const (the first and
    last one point each, the poles), u-curves meridians from pole to pole."""
    a, b, c = ELLIPSOID

    def point(theta, phi, pole):
        r = 0.0 if pole else math.sin(theta)
        return a * math.cos(theta), b * r * math.cos(phi), c * r * math.sin(phi)

    paths = []
    for name, count, steps, at in (
        ("v", rings, meridians * per,
         lambda i, k: point(math.pi * i / (rings - 1), 2 * math.pi * k / (meridians * per),
                            i in (0, rings - 1))),
        ("u", meridians, (rings - 1) * per,
         lambda j, k: point(math.pi * k / ((rings - 1) * per), 2 * math.pi * j / meridians,
                            k in (0, (rings - 1) * per))),
    ):
        path = os.path.join(folder, f"ellipsoid-{name}.csv")
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["curve", "x", "y", "z"])
            for curve in range(count):
                for k in range(steps + 1):
                    w.writerow([curve, *(repr(x) for x in at(curve, k))])
        paths.append(path)
    return paths


def wing(i, j, rows=9, cols=61, crowd_te=True):
    """A tapered wing: NACA 0012-like sections with a sharp trailing edge at (chord, 0), each
    in Selig order (the trailing edge first and last), at spans z = 0..4; points crowded at
    the nose and the trailing edge (cosine spacing), or at the nose only."""
    span = 4.0 * i / (rows - 1)
    chord = 2.0 - 0.25 * span
    half = (cols - 1) // 2
    k = abs(j - half)  # 0 at the nose, half at the trailing edge
    if crowd_te:
        x = 0.5 * (1.0 - math.cos(math.pi * k / half))
    else:
        x = 1.0 - math.cos(0.5 * math.pi * k / half)
    t = 0.6 * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x ** 3
               - 0.1036 * x ** 4)
    if k == half:
        t = 0.0
    y = t if j < half else -t
    return 0.3 * span + chord * x, chord * y, span


def wing_network(folder, rows=9, cols=61):
    """The wing of `wing` as a curve network: v-curves are its closed sections (Selig order,
    the sharp trailing edge first and last), u-curves the spanwise lines through each
    section point (the trailing edge's first). The points crowd at the nose only: the
    network's curves take their parameter from the point index, and points crowding at a
    creased trailing edge make a hook there (see docs/reference/contract.md)."""
    paths = []
    for name, count, steps, at in (
        ("v", rows, cols, lambda i, j: wing(i, j, rows, cols, crowd_te=False)),
        ("u", cols - 1, rows, lambda j, i: wing(i, j, rows, cols, crowd_te=False)),
    ):
        path = os.path.join(folder, f"wing-{name}.csv")
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["curve", "x", "y", "z"])
            for curve in range(count):
                for k in range(steps):
                    w.writerow([curve, *(repr(x) for x in at(curve, k))])
        paths.append(path)
    return paths


def loft_table(folder):
    """A two-section wing table for `karkas loft`: NACA 2412 root and 0009 tip in unit chord,
    their trailing edges closed to a point (first point = last), swept, tapered and twisted."""
    def naca(m, p, t, n=61):
        points = []
        for k in range(2 * n - 1):
            b = math.pi * abs(k - (n - 1)) / (n - 1)
            x = (1 - math.cos(b)) / 2
            yt = 5 * t * (0.2969 * math.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3
                          - 0.1036 * x**4)
            if p == 0:
                yc = 0.0
            elif x < p:
                yc = m / p**2 * (2 * p * x - x * x)
            else:
                yc = m / (1 - p) ** 2 * ((1 - 2 * p) + 2 * p * x - x * x)
            points.append((x, yc + yt if k < n - 1 else yc - yt))
        points[-1] = points[0]
        return points
    for name, (m, p, t) in {"root.dat": (0.02, 0.4, 0.12), "tip.dat": (0.0, 0.0, 0.09)}.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(name + "\n" + "".join(f"{x:.10f} {y:.10f}\n" for x, y in naca(m, p, t)))
    table = os.path.join(folder, "loft.csv")
    with open(table, "w") as f:
        f.write("file,x,y,z,chord,twist\nroot.dat,0,0,0,1.5,2\ntip.dat,0.4,4,0.2,0.8,-1\n")
    return table


def closed_mesh_volume(csv_path):
    """The volume of the sampled surface (u,v,x,y,z, u outer) closed by fans at its first and
    last rows (the caps), by the divergence theorem on its triangles. The first column is
    repeated after the last: the strip between them closes a blunt trailing edge (and has no
    area where the two coincide)."""
    data = np.loadtxt(csv_path, delimiter=",", skiprows=1)
    nu = len(np.unique(data[:, 0]))
    p = data[:, 2:].reshape(nu, -1, 3)
    p = np.concatenate([p, p[:, :1]], axis=1)
    a, b, c, d = p[:-1, :-1], p[1:, :-1], p[1:, 1:], p[:-1, 1:]
    six = (np.einsum("...i,...i", a, np.cross(b, c)) + np.einsum("...i,...i", a, np.cross(c, d)))
    total = float(six.sum())
    for row, sign in ((p[0], 1.0), (p[-1], -1.0)):
        centre = row[:-1].mean(axis=0)
        total += sign * float(np.einsum("...i,...i", np.broadcast_to(centre, row[:-1].shape),
                                        np.cross(row[:-1], row[1:])).sum())
    return abs(total) / 6.0


def sharp_seam(csv_path):
    """The angle (degrees) between the tangents on the two sides of the v-seam, at the
    middle row of the samples."""
    data = np.loadtxt(csv_path, delimiter=",", skiprows=1)
    nu = len(np.unique(data[:, 0]))
    row = data[:, 2:].reshape(nu, -1, 3)[nu // 2]
    start, end = row[1] - row[0], row[-1] - row[-2]
    cosine = np.dot(start, end) / np.linalg.norm(start) / np.linalg.norm(end)
    return math.degrees(math.acos(max(-1.0, min(1.0, cosine))))


def run(karkas, args):
    done = subprocess.run([karkas, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"karkas {' '.join(args)}: {done.stderr.strip()}")
    return done.stderr


def read_shape(path):
    reader = STEPControl_Reader() if path.endswith(".step") else IGESControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone:
        raise RuntimeError("the reader refused the file")
    reader.TransferRoots()
    return reader.OneShape()


def count(shape, kind):
    explorer, n = TopExp_Explorer(shape, kind), 0
    while explorer.More():
        n += 1
        explorer.Next()
    return n


def area_of(shape):
    props = GProp_GProps()
    BRepGProp.SurfaceProperties_s(shape, props, 1e-7)
    return props.Mass()


def volume_of(shape):
    props = GProp_GProps()
    BRepGProp.VolumeProperties_s(shape, props, 1e-7)
    return props.Mass()


def sampled_area(csv_path):
    """The area of the triangulated u,v,x,y,z samples (u outer)."""
    data = np.loadtxt(csv_path, delimiter=",", skiprows=1)
    nu = len(np.unique(data[:, 0]))
    p = data[:, 2:].reshape(nu, -1, 3)
    a, b, c, d = p[:-1, :-1], p[1:, :-1], p[1:, 1:], p[:-1, 1:]
    t1 = np.linalg.norm(np.cross(b - a, c - a), axis=-1)
    t2 = np.linalg.norm(np.cross(c - a, d - a), axis=-1)
    return 0.5 * float(t1.sum() + t2.sum())


def relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default=os.path.join(ROOT, "target", "release", "karkas"))
    parser.add_argument("--keep", help="write the files into this folder and keep them")
    args = parser.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-bodies-")
    os.makedirs(folder, exist_ok=True)
    grids = {
        "ellipsoid": (49, 96, ellipsoid),
        "fuselage": (31, 40, fuselage),
        "tube": (13, 24, tube),
        "wing": (9, 61, wing),
    }
    for name, (rows, cols, point) in grids.items():
        write_grid(os.path.join(folder, name + ".csv"), rows, cols,
                   lambda i, j, p=point, r=rows, c=cols: p(i, j, r, c))
    a, b, c = ELLIPSOID
    exact = {"ellipsoid": (ellipsoid_area(), 4.0 / 3.0 * math.pi * a * b * c)}
    aircraft = os.path.join(ROOT, "data", "aircraft-15x31.csv")
    cases = []
    wing_csv = os.path.join(folder, "wing.csv")
    # One case per body and method of the acceptance (the CLI tests cover the other pairs).
    cases.append(("wing-bicubic-crease-capped", "wing",
                  ["surface", "bicubic", "--crease-v", "--cap", wing_csv]))
    wing_v, wing_u = wing_network(folder)
    cases.append(("wing-coons-crease-capped", "wing",
                  ["surface", "coons", "--kind", "gordon-spline", "--crease-v", "--cap",
                   "--u-curves", wing_u, "--v-curves", wing_v]))
    ellipsoid_csv = os.path.join(folder, "ellipsoid.csv")
    cases.append(("ellipsoid-ll", "ellipsoid",
                  ["surface", "ll", "--interpolate", "--closed-v", ellipsoid_csv]))
    cases.append(("ellipsoid-bicubic", "ellipsoid",
                  ["surface", "bicubic", "--closed-v", ellipsoid_csv]))
    v_net, u_net = ellipsoid_network(folder)
    cases.append(("ellipsoid-coons-gordon-spline", "ellipsoid",
                  ["surface", "coons", "--kind", "gordon-spline", "--u-curves", u_net,
                   "--v-curves", v_net]))
    cases.append(("fuselage-bicubic", "fuselage",
                  ["surface", "bicubic", "--closed-v", os.path.join(folder, "fuselage.csv")]))
    cases.append(("tube-bicubic-capped", "tube",
                  ["surface", "bicubic", "--closed-v", "--cap", os.path.join(folder, "tube.csv")]))
    cases.append(("aircraft-ll-capped", "aircraft",
                  ["surface", "ll", "--closed-v", "--cap", aircraft]))
    cases.append(("wing-loft-capped", "loft", ["loft", "--cap", loft_table(folder)]))
    # The shipped wing: three NACA files with blunt trailing edges, tapered, twisted, swept
    # and with dihedral; --cap adds the flat trailing-edge face and closes root and tip.
    cases.append(("wing-loft-blunt-capped", "loft",
                  ["loft", "--cap", os.path.join(ROOT, "data", "loft-wing", "wing.csv")]))
    failures = 0
    for name, grid, command in cases:
        started = time.monotonic()
        try:
            fine = os.path.join(folder, name + "-fine.csv")
            plain = [x for x in command if x != "--cap"]
            run(args.karkas, [*plain, "--samples", "400,400", "-o", fine])
            mesh_area = sampled_area(fine)
            for ext in (".step", ".iges"):
                path = os.path.join(folder, name + ext)
                note = run(args.karkas, [*command, "-o", path])
                reported = float(re.search(r"enclosed volume ([0-9.eE+-]+)", note).group(1))
                caps = 0.0
                shape = read_shape(path)
                problems = []
                valid = BRepCheck_Analyzer(shape).IsValid()
                if not valid:
                    problems.append("BRepCheck: not valid")
                if ext == ".step":
                    solids = count(shape, TopAbs_SOLID)
                    if solids != 1:
                        problems.append(f"{solids} solids, expected 1")
                    body = shape
                else:
                    sewing = BRepBuilderAPI_Sewing(1e-6)
                    sewing.Add(shape)
                    sewing.Perform()
                    body = sewing.SewedShape()
                    # One face closed by its poles and seam is its own shell; several (caps)
                    # must sew into one.
                    if count(shape, TopAbs_FACE) > 1 and count(body, TopAbs_SHELL) != 1:
                        problems.append("the IGES faces do not sew into one shell")
                faces = count(shape, TopAbs_FACE)
                area = area_of(shape)
                # The caps' area: the shell's area less the B-spline face's.
                side = area if faces == 1 else area_of(first_face(shape))
                caps = area - side
                volume = abs(volume_of(body))
                if relative(side, mesh_area) > AREA_TOLERANCE:
                    problems.append(f"face area {side:.9g}, finely meshed {mesh_area:.9g}")
                if relative(volume, reported) > 1e-6:
                    problems.append(f"volume {volume:.9g}, the command reported {reported:.9g}")
                if "--cap" in command:
                    meshed_volume = closed_mesh_volume(fine)
                    if relative(volume, meshed_volume) > VOLUME_TOLERANCE:
                        problems.append(f"volume {volume:.9g}, finely meshed {meshed_volume:.9g}")
                if grid == "wing":
                    angle = sharp_seam(fine)
                    if angle < 5.0:
                        problems.append(f"the trailing edge is not sharp: tangents {angle:.2f} deg apart")
                if grid in exact:
                    exact_area, exact_volume = exact[grid]
                    if relative(side, exact_area) > AREA_TOLERANCE:
                        problems.append(f"area {side:.9g}, analytic {exact_area:.9g}")
                    if relative(volume, exact_volume) > VOLUME_TOLERANCE:
                        problems.append(f"volume {volume:.9g}, analytic {exact_volume:.9g}")
                status = "FAIL" if problems else "ok  "
                print(f"{status} {name}{ext}: valid {valid}, {faces} faces, face area {side:.6f}"
                      f" (meshed {mesh_area:.6f}), caps {caps:.6f}, volume {volume:.6f}"
                      f" (reported {reported:.6f}){'; ' + '; '.join(problems) if problems else ''}")
                failures += bool(problems)
                if ext == ".step":
                    solid_volume = volume
            failures += check_mesh(args.karkas, folder, name, command, solid_volume)
            print(f"     {name}: {time.monotonic() - started:.1f} s")
        except Exception as e:  # noqa: BLE001 - report and go on
            print(f"FAIL {name}: {e}")
            failures += 1
    if failures:
        print(f"{failures} failure(s)")
        return 1
    print(f"all {len(cases) * 2} body files valid in Open CASCADE, all {len(cases)} meshes"
          " watertight volumes")
    return 0


def check_mesh(karkas, folder, name, command, solid_volume):
    """Writes the body as an STL mesh and checks it in trimesh against the solid's volume;
    prints one line, returns 1 on a failure."""
    path = os.path.join(folder, name + ".stl")
    run(karkas, [*command, "--samples", "200,400", "-o", path])
    mesh = trimesh.load(path, force="mesh")
    problems = []
    if not mesh.is_watertight:
        problems.append("not watertight")
    if not mesh.is_volume:
        problems.append("not a volume")
    smallest = float(mesh.area_faces.min())
    if smallest <= 1e-14 * mesh.area:  # zero up to round-off (a pole triangle)
        problems.append(f"a triangle of area {smallest:.3g}")
    if relative(float(mesh.volume), solid_volume) > VOLUME_TOLERANCE:
        problems.append(f"volume {mesh.volume:.9g}, the STEP solid {solid_volume:.9g}")
    status = "FAIL" if problems else "ok  "
    print(f"{status} {name}.stl: {len(mesh.faces)} triangles, watertight {mesh.is_watertight},"
          f" volume {mesh.volume:.6f} (solid {solid_volume:.6f})"
          f"{'; ' + '; '.join(problems) if problems else ''}")
    return int(bool(problems))


def first_face(shape):
    explorer = TopExp_Explorer(shape, TopAbs_FACE)
    best, best_area = None, -1.0
    while explorer.More():
        face = explorer.Current()
        a = area_of(face)
        props_face = face
        if a > best_area:
            best, best_area = props_face, a
        explorer.Next()
    return best


if __name__ == "__main__":
    sys.exit(main())
