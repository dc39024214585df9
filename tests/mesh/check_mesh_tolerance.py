#!/usr/bin/env python3
"""Meshes to a chordal tolerance, measured by trimesh: a wing-like surface written with
`--mesh-tolerance T` lies within T of its mesh, with fewer triangles than any uniform grid of
that accuracy.

The wing: NACA 0012 sections (closed at a blunt trailing edge, 41 points, cosine spacing, so
that the leading edge is sharply curved) on 9 stations over a span of 4 chords, tapered 2:1,
twisted 6 degrees and swept; its bicubic interpolant (`surface bicubic --closed-v`). karkas
writes the mesh (`--mesh-tolerance T`, STL) and, in the same run, dense exact samples of the
surface (`--samples 161,1201`, CSV); trimesh measures the distance from every sample to the
mesh (closest points on the triangles), and the largest must be at most T. Then uniform grids
(`--samples NU,NV`, the default's way) are measured the same way: the fewest samples along v
(chordwise) that reach T with the mesh's spanwise samples doubled, and the fewest along u
(spanwise) with that chordwise count doubled; a uniform grid of that accuracy needs at least
both, and the adaptive mesh must have fewer triangles than that grid. The figures are
printed; exit status 1 on failure.

Usage: python3 tests/mesh/check_mesh_tolerance.py [--karkas target/release/karkas] [--tolerance T]
"""

import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

import numpy as np
import trimesh

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DENSE = (161, 1201)


def wing_grid(path):
    """The grid CSV of the wing (rows i spanwise, columns j around the section)."""
    n = 41
    beta = np.linspace(0.0, np.pi, (n + 1) // 2)
    x = (1 - np.cos(beta)) / 2
    t = 0.6 * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    upper = np.column_stack([x[::-1], t[::-1]])
    lower = np.column_stack([x[1:], -t[1:]])
    section = np.vstack([upper, lower])  # trailing edge, upper, nose, lower, trailing edge
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["i", "j", "x", "y", "z"])
        for i in range(9):
            s = i / 8
            chord = 1.0 - 0.5 * s
            twist = math.radians(6.0 * s)
            for j, (px, py) in enumerate(section):
                qx, qy = (px - 0.25) * chord, py * chord
                rx = qx * math.cos(twist) + qy * math.sin(twist)
                ry = -qx * math.sin(twist) + qy * math.cos(twist)
                w.writerow([i, j, repr(float(rx + 0.25 + 0.3 * s)), repr(float(ry)), repr(4.0 * s)])


def karkas(binary, *args):
    done = subprocess.run([binary, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"karkas {' '.join(args)}: {done.stderr.strip()}")
    return done.stderr


def dense_points(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, 2:]


def distance_to(mesh_path, points):
    """The largest distance from `points` to the triangles of the mesh, and the triangles."""
    mesh = trimesh.load(mesh_path, force="mesh", process=False)
    worst = 0.0
    # In chunks: trimesh gathers candidate triangles per point, whose memory grows with both.
    for chunk in np.array_split(points, max(1, len(points) // 2000)):
        _, distance, _ = trimesh.proximity.closest_point(mesh, chunk)
        worst = max(worst, float(distance.max()))
    return worst, len(mesh.faces)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--karkas", default=os.path.join(ROOT, "target", "release", "karkas"))
    parser.add_argument("--tolerance", type=float, default=2e-4)
    args = parser.parse_args()
    t = args.tolerance
    folder = tempfile.mkdtemp(prefix="karkas-mesh-tolerance-")
    grid = os.path.join(folder, "wing.csv")
    wing_grid(grid)
    build = ["surface", "bicubic", grid, "--closed-v"]
    mesh, dense = os.path.join(folder, "wing.stl"), os.path.join(folder, "dense.csv")
    report = karkas(args.karkas, *build, "--mesh-tolerance", repr(t), "-o", mesh,
                    "--samples", f"{DENSE[0]},{DENSE[1]}", "-o", dense)
    found = re.search(r"wing\.stl \((\d+) x (\d+) samples, (\d+) triangles", report)
    nu, nv, triangles = (int(g) for g in found.groups())
    points = dense_points(dense)
    # A random sample of the dense points keeps trimesh's queries to a few seconds.
    rng = np.random.default_rng(20240607)
    probe = points[rng.choice(len(points), size=min(len(points), 20000), replace=False)]
    worst, faces = distance_to(mesh, probe)
    assert faces == triangles, (faces, triangles)
    ok = worst <= t
    print(f"{'ok  ' if ok else 'FAIL'} mesh to {t:g}: {nu} x {nv} samples, {triangles} triangles, "
          f"largest surface-to-mesh distance {worst:.3e} (trimesh, {len(probe)} surface points)")
    failures = 0 if ok else 1

    def uniform_error(cu, cv):
        path = os.path.join(folder, f"u-{cu}-{cv}.stl")
        karkas(args.karkas, *build, "--samples", f"{cu},{cv}", "-o", path)
        return distance_to(path, probe)[0]

    def fewest(lo, hi, error):
        """The fewest samples in [lo, hi] whose error is within t (errors fall with samples)."""
        while error(hi) > t:
            lo, hi = hi, hi * 2
            if hi > 20000:
                raise RuntimeError("no uniform grid of this accuracy below 20000 samples")
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if error(mid) <= t:
                hi = mid
            else:
                lo = mid
        return hi

    cv = fewest(8, 2 * nv, lambda c: uniform_error(2 * nu, c))
    cu = fewest(2, 2 * nu, lambda c: uniform_error(c, 2 * cv))
    uniform = 2 * (cu - 1) * (cv - 1)
    error = uniform_error(cu, cv)
    ok = triangles < uniform
    print(f"{'ok  ' if ok else 'FAIL'} a uniform grid needs at least {cu} x {cv} samples for {t:g} "
          f"({uniform} triangles, measured {error:.3e}); the mesh to the tolerance has {triangles}, "
          f"{uniform / triangles:.1f}x fewer")
    failures += 0 if ok else 1
    # The default uniform grid (4 samples per grid line): what the issue measured.
    default = uniform_error(50, 164)
    print(f"     the default 50 x 164 uniform grid: largest distance {default:.3e}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
