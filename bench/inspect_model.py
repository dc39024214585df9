"""`karkas inspect`: 10^6 points against a model of about 100 faces, one thread and two.

The model, built and written to STEP by Open CASCADE (cadquery-ocp): a 70 x 56 x 4 plate with
7 x 7 blind cylindrical holes of varied radii from its top: 104 faces (6 planes of the plate,
the top one trimmed by 49 circles; 49 cylinders; 49 hole bottoms). The points: 10^6, three in
four within 2% of the model's size from its faces (Open CASCADE's feet of random points, moved
along random directions), one in four over its bounding box grown by a fifth.

Each round runs `karkas inspect MODEL --points SCAN.csv` (the summary alone) and the same with
`-o REPORT.csv` (a row of 13 numbers per point, about 190 MB), with RAYON_NUM_THREADS=1 and =2
interleaved, and reads the times karkas prints (faces prepared, points projected: the
projection alone, without reading the 10^6-line CSV or writing the report) and the process's
wall and CPU time (end to end: reading, projecting, writing the summary or the report). The load average is
printed beside the figures (the wall times mean little on a loaded machine).
Before timing, the distances of the first 2,000 points are checked equal to Open CASCADE's
BRepExtrema_DistShapeShape to 1e-9.

    python3 bench/inspect_model.py --karkas target/release/karkas [--rounds 3] [--points 1000000]
        [--keep DIR]

`--keep DIR` writes the model and the points to DIR once and reuses them on later runs (the
Open CASCADE feet of the points take minutes).
"""

import argparse
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "cad"))
from check_inspect import holed_plate, occ_distances, run_karkas, write_step  # noqa: E402

from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeVertex  # noqa: E402
from OCP.BRepExtrema import BRepExtrema_DistShapeShape  # noqa: E402
from OCP.gp import gp_Pnt  # noqa: E402
from OCP.TopAbs import TopAbs_FACE  # noqa: E402
from OCP.TopExp import TopExp_Explorer  # noqa: E402


def faces(shape):
    e, n = TopExp_Explorer(shape, TopAbs_FACE), 0
    while e.More():
        n += 1
        e.Next()
    return n


def points(shape, count, rng):
    lo = np.array([100.0, -50.0, 20.0])
    hi = lo + np.array([70.0, 56.0, 4.0])
    size = float(np.linalg.norm(hi - lo))
    grow = 0.2 * (hi - lo)
    spread = rng.uniform(lo - grow, hi + grow, size=(count // 4, 3))
    # Feet of 5,000 random points, each reused with many small random moves.
    feet = []
    for p in rng.uniform(lo, hi, size=(5000, 3)):
        d = BRepExtrema_DistShapeShape(shape, BRepBuilderAPI_MakeVertex(gp_Pnt(*p)).Vertex())
        feet.append(d.PointOnShape1(1).Coord())
    feet = np.array(feet)
    near = feet[rng.integers(0, len(feet), size=count - len(spread))]
    near = near + rng.normal(scale=0.02 * size / np.sqrt(3), size=near.shape)
    out = np.vstack([near, spread])
    rng.shuffle(out)
    return out


def run(karkas, model, scan, threads, report):
    """One `karkas inspect` of the scan: the summary alone, or with the per-point CSV report
    (about 190 bytes a point) when `report`."""
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    command = [karkas, "inspect", model, "--points", scan, "--worst", "1"]
    if report:
        command += ["-o", os.path.join(os.path.dirname(scan), f"report-{threads}.csv")]
    done = subprocess.run(command, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(done.stderr)
    m = re.search(r"prepared in ([0-9.]+) s, points projected in ([0-9.]+) s", done.stderr)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return float(m.group(1)), float(m.group(2)), wall, cpu


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default="target/release/karkas")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--keep", help="a folder to keep the model and points in, and reuse")
    args = parser.parse_args()
    folder = args.keep or tempfile.mkdtemp(prefix="karkas-inspect-bench-")
    os.makedirs(folder, exist_ok=True)
    shape = holed_plate(holes=7)
    model = os.path.join(folder, "plate-49-holes.step")
    write_step(shape, model)
    scan = os.path.join(folder, f"scan-{args.points}.csv")
    if os.path.exists(scan):
        pts = np.loadtxt(scan, delimiter=",", skiprows=1, max_rows=2000)
    else:
        rng = np.random.default_rng(7)
        pts = points(shape, args.points, rng)
        np.savetxt(scan, pts, delimiter=",", header="x,y,z", comments="", fmt="%.17g")
    # Equal before timed.
    check = pts[:2000]
    check_folder = os.path.join(folder, "check")
    os.makedirs(check_folder, exist_ok=True)
    distance, *_ = run_karkas(args.karkas, model, check, check_folder)
    error = float(np.max(np.abs(distance - occ_distances(shape, check))))
    print(f"model: {faces(shape)} faces; {args.points} points; first 2,000 equal to OCC's to {error:.1e}")
    if error > 1e-9:
        sys.exit("distances differ from Open CASCADE's")
    jobs = [(threads, report) for threads in (1, 2) for report in (False, True)]
    figures = {job: [] for job in jobs}
    loads = []
    for _ in range(args.rounds):
        for threads, report in jobs:
            loads.append(os.getloadavg()[0])
            figures[threads, report].append(run(args.karkas, model, scan, threads, report))
    print(f"load average (1 min) during the runs: {min(loads):.1f} to {max(loads):.1f}")
    print("| threads | report | prepare s | project s | command wall s | command CPU s |")
    print("|---|---|---|---|---|---|")
    for (threads, report), runs in figures.items():
        med = [statistics.median(r[k] for r in runs) for k in range(4)]
        print(f"| {threads} | {'-o' if report else 'summary'} | {med[0]:.3f} | {med[1]:.3f} | {med[2]:.2f} | {med[3]:.2f} |")


if __name__ == "__main__":
    main()
