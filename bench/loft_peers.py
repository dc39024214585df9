"""karkas.loft against Open CASCADE's BRepOffsetAPI_ThruSections on the same placed sections.

Sections: NACA 4-digit airfoils of 200 points each (thickness 18% to 9%, camber 4% to 1% along
the span), placed with taper (chord 2 to 0.8), twist (3 to -2 degrees), sweep and dihedral, as
aerosandbox's WingXSec places them (karkas's placement; Open CASCADE gets the placed points).
Open CASCADE needs curves: each section's placed points are approximated by
GeomAPI_PointsToBSpline (cubic, C^2, to a share of the chord), then lofted by ThruSections
(smoothing off) with the settings of OCC_VARIANTS: approximated through the sections with the
section curves at 1e-5 and at 1e-6 of the chord, and ruled at 1e-6. Both are timed from the
points, interleaved in one process, one thread each (ThruSections has no threads;
RAYON_NUM_THREADS sets karkas's: run once with 1 and once with 2).

Accuracy is measured the same way for both, before any timing: every input point of every
section, its distance from the surface read back from STEP (karkas) or built (Open CASCADE)
as a share of its section's chord (marched_distances: the section placed on the surface once,
then a local search from point to point; --check-projection checks it point by point against
GeomAPI_ProjectPointOnSurf's global search, which takes minutes at 101 sections). For each
Open CASCADE setting karkas runs at the loosest tolerance of KARKAS_TOLERANCES at which its
worst distance is at most Open CASCADE's, and the two are timed at that pairing.

    RAYON_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 python3 bench/loft_peers.py [--quick]
        [--sizes 11,101] [--rounds 3] [--occ-rounds 1] [--check-projection]
    RAYON_NUM_THREADS=1 python3 bench/loft_peers.py --karkas-only [--sizes 101,301,1000,3000]

--quick: 11, 101 and 1,000 sections, 3 interleaved rounds (else 11, 101, 301, 1,000 and 7);
Open CASCADE runs up to 101 sections, --occ-rounds times above 11 (default 1: a ThruSections
of 101 sections takes over a minute of CPU). --karkas-only: karkas.loft alone at each size,
its median CPU time and the cost exponent p of time ~ sections^p.
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


def occ_loft(points, chords, fit=1e-5, ruled=False, max_degree=None):
    """ThruSections through the sections, each approximated by GeomAPI_PointsToBSpline to
    `fit` of its chord; `ruled` or approximated (smoothing off, its default; `max_degree` its
    SetMaxDegree, default 8)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeWire
    from OCP.BRepOffsetAPI import BRepOffsetAPI_ThruSections
    from OCP.GeomAbs import GeomAbs_C2
    from OCP.GeomAPI import GeomAPI_PointsToBSpline
    try:
        from OCP.TColgp import TColgp_Array1OfPnt
    except ImportError:  # newer OCP
        from OCP.collections import Array1_gp_Pnt as TColgp_Array1OfPnt
    from OCP.gp import gp_Pnt

    loft = BRepOffsetAPI_ThruSections(False, ruled, 1e-6)
    loft.SetSmoothing(False)
    if max_degree is not None:
        loft.SetMaxDegree(max_degree)
    for pts, c in zip(points, chords):
        arr = TColgp_Array1OfPnt(1, len(pts))
        for i, p in enumerate(pts):
            arr.SetValue(i + 1, gp_Pnt(*p))
        curve = GeomAPI_PointsToBSpline(arr, 3, 3, GeomAbs_C2, fit * c).Curve()
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


def distances(surfaces, points):
    """The distance of every point of every section from the nearest surface, each found by
    GeomAPI_ProjectPointOnSurf (a global search: minutes for the 2,211 points at 101 sections)."""
    from OCP.GeomAPI import GeomAPI_ProjectPointOnSurf
    from OCP.gp import gp_Pnt

    return [
        np.array([min(GeomAPI_ProjectPointOnSurf(gp_Pnt(*p), s).LowerDistance() for s in surfaces) for p in pts])
        for pts in points
    ]


def marched_distances(surfaces, points):
    """distances' figures, found cheaply: a section's first point lies on the boundary
    iso-curve where every section starts (u or v at its low end, whichever is nearer), so its
    projection onto that curve (GeomAPI_ProjectPointOnCurve) places the section on the
    surface; each next point of the section is then found by a local search from the one
    before (Extrema_GenLocateExtPS, Newton on the normal-projection condition). Checked equal
    to distances point by point (--check-projection)."""
    from OCP.Extrema import Extrema_GenLocateExtPS
    from OCP.GeomAdaptor import GeomAdaptor_Surface
    from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
    from OCP.gp import gp_Pnt

    searches = []
    for s in surfaces:
        adaptor = GeomAdaptor_Surface(s)  # kept alive beside the search that refers to it
        searches.append((s, adaptor, Extrema_GenLocateExtPS(adaptor, 1e-12, 1e-12)))
    out = []
    for pts in points:
        first = gp_Pnt(*pts[0])
        start = None  # (distance, search, u, v)
        for s, _, search in searches:
            u0, _, v0, _ = s.Bounds()
            for iso, at_u in ((s.UIso(u0), True), (s.VIso(v0), False)):
                proj = GeomAPI_ProjectPointOnCurve(first, iso)
                if proj.NbPoints() == 0:
                    continue
                t = proj.LowerDistanceParameter()
                if start is None or proj.LowerDistance() < start[0]:
                    start = (proj.LowerDistance(), search, *((u0, t) if at_u else (t, v0)))
        _, search, u, v = start
        found = []
        for p in pts:
            search.Perform(gp_Pnt(*p), u, v, False)
            if not search.IsDone():
                raise RuntimeError("the local search found no foot point")
            u, v = search.Point().Parameter()
            found.append(np.sqrt(search.SquareDistance()))
        out.append(np.array(found))
    return out


def worst_share(dists, chords):
    """The largest distance as a share of its section's chord."""
    return max(float(d.max()) / c for d, c in zip(dists, chords))


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


def timed_result(f):
    """f's result and the (wall, CPU) seconds of the call."""
    out = []
    times = timed(lambda: out.append(f()))
    return out[0], times


def median_time(f, repeat):
    times = [timed(f) for _ in range(repeat)]
    return statistics.median(t[0] for t in times), statistics.median(t[1] for t in times)


# Open CASCADE's settings tried: (label, PointsToBSpline tolerance / chord, ruled, max degree).
OCC_VARIANTS = [
    ("approx", 1e-5, False, None),
    ("approx, sections 1e-6", 1e-6, False, None),
    ("ruled, sections 1e-6", 1e-6, True, None),
]
# karkas's tolerances tried for "equal or better accuracy", loosest first.
KARKAS_TOLERANCES = [1e-5, 5e-6, 2e-6, 1e-6, 5e-7, 2e-7, 1e-7]


def karkas_worst(S, points, chords):
    return worst_share(marched_distances(step_surface(S), points), chords)


def check_projection(surfaces, points, label):
    """The cheap distances equal the global projection's, point by point, to 1e-3 of the
    worst distance (measured at 11 sections: 1.8e-9, 1e-4 of it, about the global search's
    own tolerance): the worst figures reported are the same to three digits."""
    cheap, full = marched_distances(surfaces, points), distances(surfaces, points)
    above = max(float((a - b).max()) for a, b in zip(cheap, full))
    below = max(float((b - a).max()) for a, b in zip(cheap, full))
    worst = max(float(b.max()) for b in full)
    print(
        f"# projection check, {label}: {sum(len(p) for p in points)} points; marched above global by at most"
        f" {above:.2e}, below by at most {below:.2e}; worst {worst:.4e} global, {max(float(a.max()) for a in cheap):.4e} marched"
    )
    if not max(above, below) <= 1e-3 * worst:
        sys.exit(f"the marched distances differ from the global projection ({label})")


def compare(n, repeat, occ_repeat, check):
    profiles, les, chords, twists = wing(n)
    pts = placed_points(None, profiles, les, chords, twists)
    loft = lambda tol: (lambda: karkas.loft(profiles, les, chords, twists, tolerance=tol))
    S = loft(1e-5)()
    k_default = karkas_worst(S, pts, chords)
    occ = []
    for label, fit, ruled, degree in OCC_VARIANTS:
        run = lambda fit=fit, ruled=ruled, degree=degree: occ_loft(pts, chords, fit, ruled, degree)
        shape, first_time = timed_result(run)  # the first of the timed runs
        surfaces = face_surface(shape)
        if check:
            check_projection(surfaces, pts, f"OCC {label}")
            check_projection(step_surface(S), pts, "karkas 1e-5")
            check = False
        worst = worst_share(marched_distances(surfaces, pts), chords)
        occ.append((label, run, worst, sum(poles(s)[0] or 0 for s in surfaces), len(surfaces), first_time))
        print(f"# {n} sections, OCC {label}: worst {worst:.3e} of the chord, {occ[-1][3]} poles on {len(surfaces)} faces")
        sys.stdout.flush()
    rows = []
    for label, run, o_worst, o_poles, _, first_time in occ:
        # karkas's loosest tolerance at which it is at least as accurate as this OCC loft.
        for tol in KARKAS_TOLERANCES:
            k_surface = loft(tol)()
            k_worst = k_default if tol == 1e-5 else karkas_worst(k_surface, pts, chords)
            if k_worst <= o_worst:
                break
        k_poles = k_surface.control_points[0] * k_surface.control_points[1]
        k_times, o_times = [timed(loft(tol))], [first_time]
        for r in range(1, max(repeat, occ_repeat)):  # interleaved
            k_times.append(timed(loft(tol)))
            if r < occ_repeat:
                o_times.append(timed(run))
        t_k = [statistics.median(t[i] for t in k_times) for i in (0, 1)]
        t_o = [statistics.median(t[i] for t in o_times) for i in (0, 1)]
        rows.append(
            f"{n} | {label} | {tol:.0e} | {k_worst:.3e}{'' if k_worst <= o_worst else ' (less accurate)'} | {o_worst:.3e} | {1e3 * t_k[0]:.1f} / {1e3 * t_k[1]:.1f}"
            f" | {1e3 * t_o[0]:.1f} / {1e3 * t_o[1]:.1f} | {k_poles} | {o_poles} | {t_o[1] / t_k[1]:.1f}"
        )
        print(rows[-1])
        sys.stdout.flush()
    return k_default


def karkas_alone(sizes, repeat):
    """karkas.loft's median CPU time at each size (interleaved rounds) and the exponent p of
    time ~ sections^p (least squares in log-log)."""
    wings = {n: wing(n) for n in sizes}
    runs = {n: (lambda w=wings[n]: karkas.loft(*w)) for n in sizes}
    for n in sizes:  # results checked before timing: every section within the tolerance
        S = runs[n]()
        share = np.asarray(S.deviations) / wings[n][2]
        if not (S.tolerance_met and share.max() <= 1e-5):
            sys.exit(f"{n} sections: a section {share.max():.3e} of its chord from the surface")
    times = {n: [] for n in sizes}
    for _ in range(repeat):
        for n in sizes:
            times[n].append(timed(runs[n]))
    print(f"# karkas.loft alone, RAYON_NUM_THREADS={os.environ['RAYON_NUM_THREADS']}, {repeat} interleaved rounds")
    print("sections | median wall ms | median CPU ms | min-max CPU ms | CPU ms a section")
    med = {}
    for n in sizes:
        cpu = [t[1] for t in times[n]]
        med[n] = statistics.median(cpu)
        print(f"{n} | {1e3 * statistics.median(t[0] for t in times[n]):.1f} | {1e3 * med[n]:.1f}"
              f" | {1e3 * min(cpu):.1f}-{1e3 * max(cpu):.1f} | {1e3 * med[n] / n:.3f}")
    lx = np.log(np.array(sizes, float))
    ly = np.log(np.array([med[n] for n in sizes]))
    print(f"# cost exponent (CPU ~ sections^p, least squares over {sizes}): p = {np.polyfit(lx, ly, 1)[0]:.3f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--sizes", help="section counts, e.g. 11,101")
    parser.add_argument("--rounds", type=int, help="interleaved rounds")
    parser.add_argument("--occ-rounds", type=int, help="ThruSections runs at more than 11 sections (default 1)")
    parser.add_argument("--karkas-only", action="store_true",
                        help="time karkas.loft alone at the sizes (default 101,301,1000,3000) and fit the cost exponent")
    parser.add_argument("--check-projection", action="store_true",
                        help="at the first size, check the cheap distances against the global projection")
    args = parser.parse_args()
    quick = args.quick
    repeat = args.rounds or (3 if quick else 7)
    sizes = [11, 101, 1000] if quick else [11, 101, 301, 1000]
    if args.sizes:
        sizes = [int(n) for n in args.sizes.split(",")]
    if args.karkas_only:
        karkas_alone([int(n) for n in (args.sizes or "101,301,1000,3000").split(",")], repeat)
        return
    print(f"# karkas.loft (monotone) and ThruSections, 200 points a section, RAYON_NUM_THREADS={os.environ['RAYON_NUM_THREADS']}")
    print("# worst: largest distance of an input point from the surface / its chord, every point of every section")
    print("# times: median wall ms / median process CPU ms; OCC/karkas is the CPU-time ratio")
    print("sections | OCC settings | karkas tolerance | karkas worst | OCC worst | karkas ms wall/CPU | OCC ms wall/CPU"
          " | karkas poles | OCC poles | OCC/karkas")
    check = args.check_projection
    for n in sizes:
        if n <= 101:
            occ_repeat = repeat if n <= 11 else (args.occ_rounds or 1)
            compare(n, repeat, occ_repeat, check)
            check = False
        else:
            profiles, les, chords, twists = wing(n)
            S = karkas.loft(profiles, les, chords, twists)
            t_k = median_time(lambda: karkas.loft(profiles, les, chords, twists), repeat)
            k_poles = S.control_points[0] * S.control_points[1]
            print(
                f"{n} | - | 1e-05 | {S.deviations.max() / chords.min():.2e} (own) | - | {1e3 * t_k[0]:.1f} / {1e3 * t_k[1]:.1f}"
                f" | - | {k_poles} | - | -"
            )
        sys.stdout.flush()


if __name__ == "__main__":
    main()
