"""karkas.loft against Open CASCADE's BRepOffsetAPI_ThruSections on the same placed sections.

Sections: NACA 4-digit airfoils of 200 points each (thickness 18% to 9%, camber 4% to 1% along
the span), placed with taper (chord 2 to 0.8), twist (3 to -2 degrees), sweep and dihedral, as
aerosandbox's WingXSec places them (karkas's placement; Open CASCADE gets the placed points).
Open CASCADE needs curves: each section's placed points are approximated by
GeomAPI_PointsToBSpline (cubic, C^2, 3-D tolerance 1e-5 of the chord), then lofted by
ThruSections (smooth, not ruled). Both are timed from the points, interleaved in one process,
one thread each (karkas's loft runs on one thread; RAYON_NUM_THREADS=1 all the same).

Accuracy is measured the same way for both: every input point of every section projected onto
the surface read back from STEP (karkas) or built (Open CASCADE) with GeomAPI_ProjectPointOnSurf,
as a share of its section's chord.

    RAYON_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 python3 bench/loft_peers.py [--quick]
        [--sizes 11,101] [--rounds 3]

--quick: 11, 101 and 1,000 sections, 3 interleaved rounds (else 11, 101, 301, 1,000 and 7);
--sizes and --rounds choose them (Open CASCADE runs up to 101 sections).
"""

import argparse
import os
import statistics
import sys
import tempfile
import time

os.environ.setdefault("RAYON_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # no idle BLAS threads spinning beside the timings

import numpy as np

import karkas


def naca(m, p, t, n=100):
    """200 points: the upper side from the trailing edge to the leading edge (n), the lower
    side after it (n)."""
    beta = np.linspace(0.0, np.pi, n)
    x = 0.5 * (1 + np.cos(beta))  # 1 .. 0
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    yc = np.where(x < p, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x**2))
    dy = np.where(x < p, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    th = np.arctan(dy)
    upper = np.column_stack([x - yt * np.sin(th), yc + yt * np.cos(th)])
    lower = np.column_stack([0.5 * (1 - np.cos(np.linspace(0, np.pi, n + 1)[1:])), np.zeros(n)])
    xl = lower[:, 0]
    ytl = 5 * t * (0.2969 * np.sqrt(xl) - 0.126 * xl - 0.3516 * xl**2 + 0.2843 * xl**3 - 0.1015 * xl**4)
    ycl = np.where(xl < p, m / p**2 * (2 * p * xl - xl**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * xl - xl**2))
    dyl = np.where(xl < p, 2 * m / p**2 * (p - xl), 2 * m / (1 - p) ** 2 * (p - xl))
    thl = np.arctan(dyl)
    lower = np.column_stack([xl + ytl * np.sin(thl), ycl - ytl * np.cos(thl)])
    return np.vstack([upper, lower])


def wing(sections):
    s = np.linspace(0.0, 1.0, sections)
    profiles = [naca(0.04 - 0.03 * f, 0.4, 0.18 - 0.09 * f) for f in s]
    y = 8.0 * s
    les = np.column_stack([0.3 * y, y, 0.05 * y + 0.01 * y**2])
    chords = 2.0 - 1.2 * s
    twists = 3.0 - 5.0 * s
    return profiles, les, chords, twists


def placed_points(S, profiles, les, chords, twists):
    """The placed points of every section, placed by aerosandbox (karkas places them the same
    way: crates/karkas-py/tests/test_loft.py)."""
    import aerosandbox as asb

    w = asb.Wing(
        xsecs=[
            asb.WingXSec(xyz_le=le, chord=c, twist=t, airfoil=asb.Airfoil(coordinates=p))
            for p, le, c, t in zip(profiles, les, chords, twists)
        ]
    )
    return [
        np.asarray(w._compute_xyz_of_WingXSec(i, x_nondim=p[:, :1], z_nondim=p[:, 1:]))
        for i, p in enumerate(profiles)
    ]


def occ_loft(points, chords):
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeWire
    from OCP.BRepOffsetAPI import BRepOffsetAPI_ThruSections
    from OCP.GeomAbs import GeomAbs_C2
    from OCP.GeomAPI import GeomAPI_PointsToBSpline
    try:
        from OCP.TColgp import TColgp_Array1OfPnt
    except ImportError:  # newer OCP
        from OCP.collections import Array1_gp_Pnt as TColgp_Array1OfPnt
    from OCP.gp import gp_Pnt

    loft = BRepOffsetAPI_ThruSections(False, False, 1e-6)
    for pts, c in zip(points, chords):
        arr = TColgp_Array1OfPnt(1, len(pts))
        for i, p in enumerate(pts):
            arr.SetValue(i + 1, gp_Pnt(*p))
        curve = GeomAPI_PointsToBSpline(arr, 3, 3, GeomAbs_C2, 1e-5 * c).Curve()
        edge = BRepBuilderAPI_MakeEdge(curve).Edge()
        loft.AddWire(BRepBuilderAPI_MakeWire(edge).Wire())
    loft.Build()
    return loft.Shape()


def face_surface(shape):
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    faces = []
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        faces.append(BRep_Tool.Surface_s(TopoDS.Face(ex.Current())))
        ex.Next()
    return faces


def poles(surface):
    from OCP.Geom import Geom_BSplineSurface

    b = Geom_BSplineSurface.DownCast(surface) if hasattr(Geom_BSplineSurface, "DownCast") else surface
    try:
        return b.NbUPoles() * b.NbVPoles(), (b.NbUPoles(), b.NbVPoles())
    except AttributeError:
        return None, None


def worst_distance(surfaces, points, chords):
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.gp import gp_Pnt

    worst = 0.0
    for pts, c in zip(points, chords):
        for p in pts:
            d = min(GeomAPI_ProjectPointOnSurf(gp_Pnt(*p), s).LowerDistance() for s in surfaces)
            worst = max(worst, d / c)
    return worst


def step_surface(S):
    from OCP.STEPControl import STEPControl_Reader

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "w.step")
        karkas.export(S, path)
        r = STEPControl_Reader()
        r.ReadFile(path)
        r.TransferRoots()
        return face_surface(r.OneShape())


def timed(f):
    """Wall and process CPU seconds of one call (the CPU time is the cost on one core when
    the machine is shared: the wall time then includes the waits for a core)."""
    w, c = time.perf_counter(), time.process_time()
    f()
    return time.perf_counter() - w, time.process_time() - c


def median_time(f, repeat):
    times = [timed(f) for _ in range(repeat)]
    return statistics.median(t[0] for t in times), statistics.median(t[1] for t in times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--sizes", help="section counts, e.g. 11,101")
    parser.add_argument("--rounds", type=int, help="interleaved rounds")
    args = parser.parse_args()
    quick = args.quick
    repeat = args.rounds or (3 if quick else 7)
    sizes = [11, 101, 1000] if quick else [11, 101, 301, 1000]
    if args.sizes:
        sizes = [int(n) for n in args.sizes.split(",")]
    print("# karkas.loft (monotone, tolerance 1e-5 of the chord) and ThruSections, 200 points a section")
    print("# times: median wall ms / median process CPU ms; OCC/karkas is the CPU-time ratio")
    print(
        "sections | karkas ms wall/CPU | karkas CPU ms/section | karkas poles | karkas worst/chord"
        " | OCC ms wall/CPU | OCC poles | OCC worst/chord | OCC/karkas"
    )
    for n in sizes:
        profiles, les, chords, twists = wing(n)
        run_karkas = lambda: karkas.loft(profiles, les, chords, twists)
        S = run_karkas()
        k_poles = S.control_points[0] * S.control_points[1]
        if n <= 101:
            pts = placed_points(S, profiles, les, chords, twists)
            accuracy_points = pts if n <= 11 else pts[::10]
            accuracy_chords = chords if n <= 11 else chords[::10]
            k_worst = worst_distance(step_surface(S), accuracy_points, accuracy_chords)
            shape = occ_loft(pts, chords)
            k_times, o_times = [], []
            for _ in range(repeat):  # interleaved
                k_times.append(timed(run_karkas))
                o_times.append(timed(lambda: occ_loft(pts, chords)))
            t_k = [statistics.median(t[i] for t in k_times) for i in (0, 1)]
            t_o = [statistics.median(t[i] for t in o_times) for i in (0, 1)]
            surfaces = face_surface(shape)
            o_poles = sum(poles(s)[0] or 0 for s in surfaces)
            o_worst = worst_distance(surfaces, accuracy_points, accuracy_chords)
            print(
                f"{n} | {1e3 * t_k[0]:.1f} / {1e3 * t_k[1]:.1f} | {1e3 * t_k[1] / n:.3f} | {k_poles} | {k_worst:.2e}"
                f" | {1e3 * t_o[0]:.1f} / {1e3 * t_o[1]:.1f} | {o_poles} | {o_worst:.2e} | {t_o[1] / t_k[1]:.1f}"
            )
        else:
            t_k = median_time(run_karkas, repeat)
            print(
                f"{n} | {1e3 * t_k[0]:.1f} / {1e3 * t_k[1]:.1f} | {1e3 * t_k[1] / n:.3f} | {k_poles}"
                f" | {S.deviations.max() / chords.min():.2e} (own) | - | - | - | -"
            )
        sys.stdout.flush()


if __name__ == "__main__":
    main()
