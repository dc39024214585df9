"""karkas.loft against aerosandbox (the same table builds the same wing), SciPy's PCHIP (the
monotone rule's leading edge) and Open CASCADE (the STEP surface)."""

import pickle

import numpy as np
import pytest

import karkas

asb = pytest.importorskip("aerosandbox")

# Real airfoils from aerosandbox's copy of the UIUC database, root to tip; leading edge
# (x, y, z), chord, twist: taper, twist, sweep and dihedral, and a kink in the dihedral.
FOILS = ["e387", "sd7037", "clarky", "e387"]
PLACES = [
    ((0.0, 0.0, 0.0), 1.8, 3.0),
    ((0.25, 1.5, 0.08), 1.5, 2.0),
    ((0.6, 3.2, 0.25), 1.1, 0.0),
    ((1.1, 5.0, 0.7), 0.55, -2.5),
]


def asb_wing():
    return asb.Wing(
        xsecs=[
            asb.WingXSec(xyz_le=np.array(le), chord=c, twist=t, airfoil=asb.Airfoil(name))
            for name, (le, c, t) in zip(FOILS, PLACES)
        ]
    )


def karkas_wing(span="monotone", tolerance=1e-5):
    profiles = [asb.Airfoil(name).coordinates for name in FOILS]
    return karkas.loft(
        profiles,
        [p[0] for p in PLACES],
        [p[1] for p in PLACES],
        [p[2] for p in PLACES],
        span=span,
        tolerance=tolerance,
    )


def distance_to_section(S, station, points, n=20001):
    """Distance of every point to the surface's section at `station`: dense samples, then
    the nearest sample's neighbourhood refined on the B-spline."""
    line = S.section_at(station, n)
    v = np.linspace(0.0, 1.0, n)
    d = np.linalg.norm(points[:, None, :] - line[None, :, :], axis=2)
    best = d.argmin(axis=1)
    out = np.empty(len(points))
    for i, j in enumerate(best):
        lo, hi = v[max(j - 1, 0)], v[min(j + 1, n - 1)]
        vv = np.linspace(lo, hi, 401)
        pts = S(np.full_like(vv, station), vv, grid=False)
        out[i] = np.linalg.norm(pts - points[i], axis=1).min()
    return out


@pytest.mark.parametrize("span", ["monotone", "linear", "spline"])
def test_the_same_table_builds_the_same_wing_as_aerosandbox(span):
    wing = asb_wing()
    S = karkas_wing(span)
    assert S.tolerance_met
    for i, name in enumerate(FOILS):
        foil = asb.Airfoil(name).coordinates
        placed = np.asarray(wing._compute_xyz_of_WingXSec(i, x_nondim=foil[:, :1], z_nondim=foil[:, 1:]))
        chord = PLACES[i][1]
        d = distance_to_section(S, S.stations[i], placed)
        assert d.max() <= 1e-5 * chord * (1 + 1e-6), (name, d.max() / chord)
        # The leading edge (the point of smallest x) and the trailing edges exactly.
        le = placed[np.argmin(foil[:, 0])]
        assert np.linalg.norm(S(S.stations[i], 0.5) - le) < 1e-12 * chord
        assert np.linalg.norm(S(S.stations[i], 0.0) - placed[0]) < 1e-12 * chord
        assert np.linalg.norm(S(S.stations[i], 1.0) - placed[-1]) < 1e-12 * chord
    # The stations: the length of the leading edges' polyline projected onto y-z.
    les = np.array([p[0] for p in PLACES])
    steps = np.hypot(np.diff(les[:, 1]), np.diff(les[:, 2]))
    assert np.allclose(S.stations, np.concatenate([[0.0], np.cumsum(steps)]), rtol=1e-14)


def test_the_monotone_leading_edge_is_scipys_pchip_of_the_placed_leading_edges():
    from scipy.interpolate import PchipInterpolator

    S = karkas_wing("monotone")
    les = S(S.stations, 0.5)
    reference = PchipInterpolator(S.stations, les, axis=0)
    u = np.linspace(S.stations[0], S.stations[-1], 1000)
    assert np.abs(S(u, 0.5) - reference(u)).max() < 1e-12


def test_monotone_placement_stays_between_neighbours_on_1000_lines():
    S = karkas_wing("monotone")
    st = np.asarray(S.stations)

    def figures(u):
        le, upper, lower = S(u, 0.5), S(u, 0.0), S(u, 1.0)
        e = 0.5 * (upper + lower) - le
        chord = np.linalg.norm(e, axis=-1)
        twist = np.degrees(np.arctan2(-np.sign(e[..., 2]) * np.hypot(e[..., 1], e[..., 2]), e[..., 0]))
        return le, chord, twist, upper - lower

    u = st[0] + (st[-1] - st[0]) * (np.arange(1000) + 0.5) / 1000
    le, chord, twist, gap = figures(u)
    a_le, a_chord, a_twist, a_gap = figures(st)
    k = np.searchsorted(st, u) - 1
    violations = 0
    # The leading edge exactly; the chord (a share of the longer neighbouring chord) and the
    # twist (radians) to the loft's tolerance, 1e-5 (docs/methods.md 7.3).
    longer = np.maximum(a_chord[k], a_chord[k + 1])
    for values, at, slack in ((le, a_le, 1e-12), (chord, a_chord, 1e-5 * longer), (twist, a_twist, np.degrees(1e-5))):
        slack = slack[:, None] if np.ndim(slack) and np.ndim(values) > 1 else slack
        lo = np.minimum(at[k], at[k + 1]) - slack
        hi = np.maximum(at[k], at[k + 1]) + slack
        violations += int(np.sum((values < lo) | (values > hi)))
    # The trailing-edge branches never cross: the upper end stays above the lower one.
    violations += int(np.sum(gap[:, 2] < -1e-12))
    assert violations == 0


def test_step_is_a_valid_face_in_open_cascade_and_agrees_with_the_surface(tmp_path):
    OCP = pytest.importorskip("OCP")
    from OCP.BRep import BRep_Tool
    from OCP.BRepCheck import BRepCheck_Analyzer
    from OCP.STEPControl import STEPControl_Reader
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS

    # Blunt trailing edges: the face's four corners are four vertices. (A sharp trailing edge
    # makes two corners one point, which the open-face STEP writer still writes as two
    # vertices: Open CASCADE's analyzer refuses that face; closing it is the caps and solids
    # writer's work.)
    blunt = ["clarky", "naca2412", "naca4415", "clarky"]
    profiles = [asb.Airfoil(name).coordinates for name in blunt]
    S = karkas.loft(profiles, [p[0] for p in PLACES], [p[1] for p in PLACES], [p[2] for p in PLACES])
    path = tmp_path / "wing.step"
    karkas.export(S, str(path))
    reader = STEPControl_Reader()
    assert reader.ReadFile(str(path)) == 1
    reader.TransferRoots()
    shape = reader.OneShape()
    assert BRepCheck_Analyzer(shape).IsValid()
    explorer = TopExp_Explorer(shape, TopAbs_FACE)
    face = TopoDS.Face(explorer.Current())
    surface = BRep_Tool.Surface_s(face)
    for u in np.linspace(S.stations[0], S.stations[-1], 7):
        for v in np.linspace(0, 1, 9):
            p = surface.Value(u, v)
            assert np.linalg.norm(np.array([p.X(), p.Y(), p.Z()]) - S(u, v)) < 1e-12


def test_bad_sections_raise_points_errors_naming_the_section():
    profiles = [asb.Airfoil(name).coordinates for name in FOILS]
    les, chords, twists = [p[0] for p in PLACES], [p[1] for p in PLACES], [p[2] for p in PLACES]
    bad = list(profiles)
    bad[2] = bad[2] * 100
    with pytest.raises(karkas.PointsError, match="section 2: the profile is not in unit chord"):
        karkas.loft(bad, les, chords, twists)
    same = list(les)
    same[3] = same[2]
    with pytest.raises(karkas.PointsError, match="section 3"):
        karkas.loft(profiles, same, chords, twists)
    with pytest.raises(karkas.OptionError, match="span rule"):
        karkas.loft(profiles, les, chords, twists, span="cubic")
    with pytest.raises(karkas.OptionError, match="chords"):
        karkas.loft(profiles, les, chords[:2], twists)


def test_pickles_and_exports(tmp_path):
    S = karkas_wing("spline", 1e-4)
    T = pickle.loads(pickle.dumps(S))
    u, v = np.linspace(0, 5, 7), np.linspace(0, 1, 11)
    assert np.array_equal(S(u, v), T(u, v))
    assert T.span == "spline" and T.tolerance == 1e-4
    knots, coefs, degrees = S.to_bspline()
    assert coefs.shape[:2] == S.control_points
    karkas.export(S, str(tmp_path / "w.stl"))
    assert (tmp_path / "w.stl").stat().st_size > 0


# karkas.loft_windio: a small prebent blade written here, its airfoils placed by the test as
# windIO describes (numpy and SciPy's PCHIP, not karkas), and the reference IEA-15-240-RWT
# blade when the windIO package is installed.


def foil_yaml(t, n=41):
    beta = np.linspace(0.0, 2.0 * np.pi, n)
    x = 0.5 * (1.0 + np.cos(beta))
    y = 5 * t * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    y = np.where(beta <= np.pi, y, -y)
    return "{x: [%s], y: [%s]}" % (", ".join(map(repr, x.tolist())), ", ".join(map(repr, y.tolist())))


def blade_yaml(positions=(0.0, 0.4, 1.0)):
    return (
        "windIO_version: '2.0'\nname: test blade\ncomponents:\n  blade:\n    reference_axis:\n"
        "      x: {grid: &g [0.0, 0.5, 1.0], values: [0.0, -0.2, -1.0]}\n"
        "      y: {grid: [0.0, 1.0], values: [0.0, 0.0]}\n"
        "      z: {grid: *g, values: [0.0, 10.0, 20.0]}\n"
        "    outer_shape:\n"
        "      chord: {grid: *g, values: [2.0, 2.4, 0.8]}\n"
        "      twist: {grid: *g, values: [12.0, 4.0, -1.0]}\n"
        "      section_offset_y: {grid: *g, values: [1.0, 0.7, 0.2]}\n"
        "      airfoils:\n"
        f"        - {{name: thick, spanwise_position: {positions[0]}}}\n"
        f"        - {{name: thin, spanwise_position: {positions[1]}}}\n"
        f"        - {{name: thin, spanwise_position: {positions[2]}}}\n"
        f"airfoils:\n  - {{name: thick, coordinates: {foil_yaml(0.21)}}}\n"
        f"  - {{name: thin, coordinates: {foil_yaml(0.12)}}}\n"
    )


def windio_place(blade, s, xa, ya):
    """Unit-chord points placed at the nondimensional position s as windIO 2 places them:
    P = r(s) + My(b) Mx(a) Rz(-(twist + rz)) (c y + ox, c x - oy, 0), the axis's PCHIP tangent
    the section's normal (as tests/cad/check_windio_blade.py places the IEA blades)."""
    from scipy.interpolate import PchipInterpolator

    def pchip(d):
        return PchipInterpolator(np.asarray(d["grid"], float), np.asarray(d["values"], float))

    axis = [pchip(blade["reference_axis"][k]) for k in "xyz"]
    shape = blade["outer_shape"]
    chord, twist, oy = (float(pchip(shape[k])(s)) for k in ("chord", "twist", "section_offset_y"))
    ox = float(pchip(shape["section_offset_x"])(s)) if "section_offset_x" in shape else 0.0
    r = np.array([float(a(s)) for a in axis])
    t = np.array([float(a.derivative()(s)) for a in axis])
    t /= np.linalg.norm(t)
    a, b = np.arcsin(-t[1]), np.arctan2(t[0], t[2])
    mx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
    my = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
    mxy = my @ mx
    rz = np.radians(twist) + np.arctan2(mxy[0, 1], mxy[0, 0])
    rot = np.array([[np.cos(rz), np.sin(rz), 0], [-np.sin(rz), np.cos(rz), 0], [0, 0, 1]])
    local = np.c_[chord * ya + ox, chord * xa - oy, np.zeros_like(xa)]
    return r + local @ (mxy @ rot).T, chord


def axis_length(blade, n=200001):
    from scipy.interpolate import PchipInterpolator

    s = np.linspace(0.0, 1.0, n)
    xyz = np.column_stack(
        [PchipInterpolator(blade["reference_axis"][k]["grid"], blade["reference_axis"][k]["values"])(s) for k in "xyz"]
    )
    return float(np.linalg.norm(np.diff(xyz, axis=0), axis=1).sum())


def check_blade_through_its_airfoils(S, turbine, tolerance=1e-5):
    blade = turbine["components"]["blade"]
    coords = {a["name"]: a["coordinates"] for a in turbine["airfoils"]}
    entries = blade["outer_shape"]["airfoils"]
    length = axis_length(blade)
    assert len(S.airfoil_stations) == len(entries)
    worst = 0.0
    for station, entry in zip(S.airfoil_stations, entries):
        s = float(entry["spanwise_position"])
        # The station: the position times the axis length (the length by SciPy's PCHIP).
        assert abs(station - s * length) < 1e-6 * length, (station, s * length)
        c = coords[entry["name"]]
        points, chord = windio_place(blade, s, np.asarray(c["x"], float), np.asarray(c["y"], float))
        worst = max(worst, distance_to_section(S, station, points, n=4001).max() / chord)
    assert worst <= tolerance * (1 + 1e-6), worst
    return worst


def test_loft_windio_passes_through_the_airfoils_as_windio_places_them(tmp_path):
    import yaml

    path = tmp_path / "blade.yaml"
    path.write_text(blade_yaml())
    S = karkas.loft_windio(path)
    assert isinstance(S, karkas.LoftSurface)
    assert S.tolerance_met and S.span == "monotone" and S.tolerance == 1e-5
    # The three airfoils and the grid position 0.5 between the second and the third.
    assert len(S.stations) == 4
    check_blade_through_its_airfoils(S, yaml.safe_load(path.read_text()))
    # The options of `karkas loft --windio`, and a str path.
    T = karkas.loft_windio(str(path), span="linear", tolerance=1e-4)
    assert (T.span, T.tolerance, T.tolerance_met) == ("linear", 1e-4, True)
    assert T.control_points[1] <= S.control_points[1]
    # Pickled as the file's path, read again.
    U = pickle.loads(pickle.dumps(S))
    assert U.control_points == S.control_points
    uv = np.linspace(0.0, 1.0, 7)
    assert np.array_equal(U(S.stations[-1] * uv, uv), S(S.stations[-1] * uv, uv))


def test_loft_windio_lofts_the_iea_15_blade_as_the_command_line():
    windIO = pytest.importorskip("windIO")
    from pathlib import Path

    path = Path(windIO.__file__).parent / "examples" / "turbine" / "IEA-15-240-RWT.yaml"
    S = karkas.loft_windio(path)
    assert S.tolerance_met
    # The figures `karkas loft --windio` reports for this file.
    assert S.control_points == (122, 232) and len(S.stations) == 61
    check_blade_through_its_airfoils(S, windIO.load_yaml(str(path)))


def test_loft_windio_errors_name_the_file(tmp_path):
    missing = tmp_path / "missing.yaml"
    with pytest.raises(FileNotFoundError):
        karkas.loft_windio(missing)
    cases = [
        (blade_yaml().replace("name: thick, spanwise", "name: gone, spanwise"), karkas.FileFormatError, ["gone"]),
        (blade_yaml().replace("chord: {grid: *g, values: [2.0, 2.4, 0.8]}", "chord: [2.0]"), karkas.FileFormatError, []),
        ("components: [1\n", karkas.FileFormatError, ["line"]),
        (blade_yaml((0.0, 0.4, 0.4)), karkas.PointsError, ["airfoil 3 ('thin' at spanwise_position 0.4)"]),
        (blade_yaml((0.0, 0.6, 0.4)), karkas.PointsError, ["airfoil 3", "not after"]),
    ]
    for k, (text, error, words) in enumerate(cases):
        path = tmp_path / f"bad{k}.yaml"
        path.write_text(text)
        with pytest.raises(error) as info:
            karkas.loft_windio(path)
        assert isinstance(info.value, karkas.KarkasError)
        message = str(info.value)
        assert f"bad{k}.yaml" in message, message
        for w in words:
            assert w in message, message
    with pytest.raises(karkas.OptionError):
        karkas.loft_windio(tmp_path / "bad0.yaml", span="cubic")
