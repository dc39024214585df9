"""karkas.export against the command line: for each format, the file Python writes equals the
file `karkas` writes for the same command and input, byte for byte (no randomness; the one
clock reading, the time stamp of a STEP or IGES header, is fixed by SOURCE_DATE_EPOCH for every
test here, else the two writes can fall in different seconds); STEP and IGES read back in Open
CASCADE; the readers read the files back; _repr_html_ shows a curve as SVG and a surface in the
viewer."""

import pathlib
import subprocess

import numpy as np
import pytest

import karkas


from cli_binary import CLI, needs_cli


@pytest.fixture(autouse=True)
def fixed_time_stamp(monkeypatch):
    """The same STEP and IGES time stamp for the command line (inherited) and this process."""
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1000000000")


def run_cli(*args):
    subprocess.run([CLI, *map(str, args)], check=True, capture_output=True)


def same_bytes(a, b):
    da, db = pathlib.Path(a).read_bytes(), pathlib.Path(b).read_bytes()
    assert da == db, f"{a} and {b} differ ({len(da)} and {len(db)} bytes)"


# A wavy open polygon in the plane, and one in space.
POINTS2 = np.array([[np.cos(t) * (1 + 0.2 * t), np.sin(2 * t) + 0.1 * t] for t in np.linspace(0, 3, 9)])
POINTS3 = np.column_stack([POINTS2, np.linspace(0.0, 1.0, len(POINTS2)) ** 2])
GRID = np.array(
    [[[i, j, np.sin(0.7 * i) * np.cos(0.5 * j) + 0.1 * i * j] for j in range(6)] for i in range(5)],
    dtype=float,
)


def write_points(path, points):
    header = "x,y" if points.shape[1] == 2 else "x,y,z"
    np.savetxt(path, points, delimiter=",", header=header, comments="", fmt="%.17g")


def write_grid(path, grid):
    with open(path, "w") as f:
        f.write("i,j,x,y,z\n")
        for i in range(grid.shape[0]):
            for j in range(grid.shape[1]):
                x, y, z = map(float, grid[i, j])
                f.write(f"{i},{j},{x!r},{y!r},{z!r}\n")


CURVE_EXTS = ["csv", "svg", "png", "html"]
SURFACE_EXTS = ["csv", "obj", "stl", "ply", "vtk", "vts", "glb", "svg", "png", "html"]


@needs_cli
@pytest.mark.parametrize("points", [POINTS2, POINTS3], ids=["2d", "3d"])
@pytest.mark.parametrize("ext", CURVE_EXTS)
@pytest.mark.parametrize("comb", [False, True], ids=["plain", "comb"])
def test_ll_curve_matches_cli(tmp_path, points, ext, comb):
    if comb and ext in ("csv", "html"):
        pytest.skip("the comb is drawn in pictures only")
    src = tmp_path / "points.csv"
    write_points(src, points)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("curve", "ll", src, "-o", cli_out, *(["--comb"] if comb else []))
    c = karkas.LLCurve(points, order=3)
    title = f"LL curve, L = 3, {len(points)} points"
    written = karkas.export(c, py_out, title=title, points=points, comb=comb)
    assert pathlib.Path(written) == py_out
    same_bytes(cli_out, py_out)


@needs_cli
@pytest.mark.parametrize("ext", CURVE_EXTS)
def test_samples_option_matches_cli(tmp_path, ext):
    src = tmp_path / "points.csv"
    write_points(src, POINTS2)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("curve", "ll", src, "-o", cli_out, "--samples", 37, "--interpolate", "--closed")
    c = karkas.LLCurve.interpolate(POINTS2, order=3, closed=True)
    title = f"interpolating LL curve, L = 3, {len(POINTS2)} points"
    karkas.export(c, py_out, samples=37, title=title, points=POINTS2, closed_points=True)
    same_bytes(cli_out, py_out)


@needs_cli
@pytest.mark.parametrize("ext", SURFACE_EXTS)
def test_ll_surface_matches_cli(tmp_path, ext):
    src = tmp_path / "grid.csv"
    write_grid(src, GRID)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("surface", "ll", src, "-o", cli_out)
    S = karkas.LLSurface(GRID, order=3)
    title = f"LL surface, L = 3, {GRID.shape[0]} x {GRID.shape[1]} grid"
    # Meshes default to a tolerance in Python; the command line's default samples asked for.
    samples = (max(50, 4 * GRID.shape[0]), max(50, 4 * GRID.shape[1]))
    karkas.export(S, py_out, title=title, net=GRID, samples=samples)
    same_bytes(cli_out, py_out)


@needs_cli
@pytest.mark.parametrize("ext", ["obj", "stl", "ply", "glb"])
def test_meshes_to_a_tolerance_match_cli(tmp_path, ext):
    src = tmp_path / "grid.csv"
    write_grid(src, GRID)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("surface", "bicubic", src, "--mesh-tolerance", "1e-3", "-o", cli_out)
    karkas.export(karkas.BicubicSurface(GRID), py_out, mesh_tolerance=1e-3)
    same_bytes(cli_out, py_out)


@needs_cli
@pytest.mark.parametrize("ext", ["stl", "ply"])
@pytest.mark.parametrize("flip", [False, True], ids=["up", "flipped"])
def test_mesh_options_match_cli(tmp_path, ext, flip):
    src = tmp_path / "grid.csv"
    write_grid(src, GRID)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("surface", "bicubic", src, "-o", cli_out, "--samples", "20,30", *(["--flip-normals"] if flip else []))
    S = karkas.BicubicSurface(GRID)
    karkas.export(S, py_out, samples=(20, 30), flip_normals=flip)
    same_bytes(cli_out, py_out)
    # OBJ's flipped rows take another path in the writer.
    run_cli("surface", "bicubic", src, "-o", tmp_path / "cli.obj", *(["--flip-normals"] if flip else []))
    samples = (max(50, 4 * GRID.shape[0]), max(50, 4 * GRID.shape[1]))
    karkas.export(S, tmp_path / "py.obj", net=GRID, flip_normals=flip, samples=samples)
    same_bytes(tmp_path / "cli.obj", tmp_path / "py.obj")


@needs_cli
@pytest.mark.parametrize("ext", ["csv", "svg", "png", "html"])
def test_discrete_spline_matches_cli(tmp_path, ext):
    src = tmp_path / "points.csv"
    write_points(src, POINTS2)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("curve", "dps", src, "--order", 3, "--n", 6, "-o", cli_out)
    s = karkas.DiscreteSpline.interpolate(POINTS2, order=3, n=6)
    m, period = len(POINTS2), len(POINTS2) * 6
    if ext == "html":
        title = f"discrete periodic spline, order 3, n = 6 ({period} values)"
    else:
        title = f"discrete periodic spline, order 3, {m} nodes, n = 6 ({period} values)"
    karkas.export(s, py_out, title=title, points=POINTS2)
    same_bytes(cli_out, py_out)


@needs_cli
def test_discrete_spline_refuses_step_as_the_cli(tmp_path):
    src = tmp_path / "points.csv"
    write_points(src, POINTS2)
    r = subprocess.run([CLI, "curve", "dps", str(src), "--order", "3", "--n", "6", "-o", str(tmp_path / "c.step")], capture_output=True, text=True)
    assert r.returncode != 0 and "no exact STEP/IGES/DXF form" in r.stderr
    s = karkas.DiscreteSpline.interpolate(POINTS2, order=3, n=6)
    with pytest.raises(karkas.OptionError, match="no exact STEP/IGES/DXF form"):
        karkas.export(s, tmp_path / "c.step")
    assert not (tmp_path / "c.step").exists()


@needs_cli
@pytest.mark.parametrize("ext", SURFACE_EXTS)
def test_grid_array_matches_cli_convert(tmp_path, ext):
    src = tmp_path / "grid.csv"
    write_grid(src, GRID)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("convert", src, cli_out)
    karkas.export(GRID, py_out, title="grid.csv")
    same_bytes(cli_out, py_out)


@needs_cli
@pytest.mark.parametrize("points", [POINTS2, POINTS3], ids=["2d", "3d"])
@pytest.mark.parametrize("ext", ["svg", "png", "html"])
def test_points_array_matches_cli_convert(tmp_path, points, ext):
    src = tmp_path / "points.csv"
    write_points(src, points)
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("convert", src, cli_out)
    karkas.export(points, py_out, title="points.csv")
    same_bytes(cli_out, py_out)


@needs_cli
@pytest.mark.parametrize("ext", ["obj", "stl", "vtk", "glb", "html"])
def test_mesh_tuple_matches_cli_convert(tmp_path, ext):
    # An OBJ without normals: what read_mesh returns is the whole mesh.
    karkas.export(GRID, tmp_path / "grid.stl")
    v, f = karkas.read_mesh(tmp_path / "grid.stl")
    with open(tmp_path / "mesh.obj", "w") as out:
        for p in v:
            out.write("v {!r} {!r} {!r}\n".format(*map(float, p)))
        for t in f:
            out.write("f {} {} {}\n".format(*(t + 1)))
    cli_out, py_out = tmp_path / f"cli.{ext}", tmp_path / f"py.{ext}"
    run_cli("convert", tmp_path / "mesh.obj", cli_out)
    karkas.export(karkas.read_mesh(tmp_path / "mesh.obj"), py_out, title="mesh.obj")
    same_bytes(cli_out, py_out)


def test_format_option_wins_over_the_extension(tmp_path):
    c = karkas.LLCurve(POINTS2, order=3)
    karkas.export(c, tmp_path / "a.txt", format="csv", samples=11)
    karkas.export(c, tmp_path / "b.csv", samples=11)
    same_bytes(tmp_path / "a.txt", tmp_path / "b.csv")
    lines = (tmp_path / "a.txt").read_text().splitlines()
    assert lines[0] == "t,x,y" and len(lines) == 12
    t, x, y = np.loadtxt(tmp_path / "a.txt", delimiter=",", skiprows=1).T
    np.testing.assert_allclose(np.column_stack([x, y]), c(t), rtol=0, atol=1e-12)


def test_unknown_extension_and_kind_are_refused(tmp_path):
    c = karkas.LLCurve(POINTS2, order=3)
    with pytest.raises(karkas.OptionError, match="unknown output extension"):
        karkas.export(c, tmp_path / "c.xyz")
    with pytest.raises(karkas.OptionError):
        karkas.export(c, tmp_path / "c.obj")  # a curve is not a mesh
    with pytest.raises(karkas.OptionError, match="flip_normals"):
        karkas.export(karkas.LLSurface(GRID), tmp_path / "s.svg", flip_normals=True)
    with pytest.raises(karkas.OptionError, match="unknown"):
        karkas.export(c, tmp_path / "c.csv", format="docx")
    with pytest.raises(TypeError):
        karkas.export(object(), tmp_path / "c.csv")
    assert list(tmp_path.iterdir()) == []


def test_a_failed_write_keeps_the_existing_file(tmp_path):
    target = tmp_path / "keep.csv"
    target.write_text("precious\n")
    c = karkas.LLCurve(POINTS2, order=3)
    with pytest.raises(karkas.OptionError):
        karkas.export(c, target, format="obj")
    assert target.read_text() == "precious\n"
    missing = tmp_path / "no" / "such" / "dir" / "c.csv"
    with pytest.raises(OSError):
        karkas.export(c, missing)


def test_surface_csv_is_the_surface(tmp_path):
    S = karkas.LLSurface(GRID, order=3)
    karkas.export(S, tmp_path / "s.csv", samples=(7, 9))
    data = np.loadtxt(tmp_path / "s.csv", delimiter=",", skiprows=1)
    assert data.shape == (63, 5)
    u, v = data[:, 0], data[:, 1]
    np.testing.assert_allclose(data[:, 2:], S(u, v, grid=False), rtol=0, atol=1e-12)


def test_mesh_read_back(tmp_path):
    S = karkas.BicubicSurface(GRID)
    for ext in ["obj", "stl", "ply"]:
        karkas.export(S, tmp_path / f"s.{ext}", samples=(8, 10), ascii=(ext == "ply"))
        v, f = karkas.read_mesh(tmp_path / f"s.{ext}")
        assert f.shape[1] == 3 and f.max() < len(v)
        # Every vertex lies on the sampled grid of the surface.
        u = np.linspace(*S.domain_u, 8)
        w = np.linspace(*S.domain_v, 10)
        grid = S(u, w).reshape(-1, 3)
        d = np.min(np.linalg.norm(v[:, None, :] - grid[None, :, :], axis=2), axis=1)
        assert d.max() < 1e-5  # STL keeps single precision


def test_readers_read_back(tmp_path):
    write_grid(tmp_path / "grid.csv", GRID)
    np.testing.assert_array_equal(karkas.read_grid(tmp_path / "grid.csv"), GRID)
    write_points(tmp_path / "p.csv", POINTS3)
    np.testing.assert_array_equal(karkas.read_curve(tmp_path / "p.csv"), POINTS3)
    karkas.export(GRID, tmp_path / "g.csv")
    np.testing.assert_array_equal(karkas.read_grid(tmp_path / "g.csv"), GRID)


def test_repr_html_of_a_curve_is_an_svg_with_its_comb():
    c = karkas.LLCurve(POINTS2, order=3)
    html = c._repr_html_()
    assert "<svg" in html and "</svg>" in html
    assert len(html) < 2_000_000


def test_repr_html_of_a_surface_embeds_the_viewer():
    S = karkas.LLSurface(GRID, order=3)
    html = S._repr_html_()
    assert html.startswith("<iframe") and "srcdoc=" in html
    assert "three" in html and "<script" in html.replace("&lt;script", "<script")
    assert len(html) < 5_000_000


# --- STEP and IGES: read back in Open CASCADE -------------------------------------------------

def _occ_shape(path):
    OCP = pytest.importorskip("OCP")  # noqa: F841
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.IGESControl import IGESControl_Reader
    from OCP.STEPControl import STEPControl_Reader

    reader = STEPControl_Reader() if str(path).endswith(".step") else IGESControl_Reader()
    assert reader.ReadFile(str(path)) == IFSelect_RetDone
    reader.TransferRoots()
    return reader.OneShape()


def _occ_items(shape, kind):
    from OCP.TopExp import TopExp_Explorer

    explorer, items = TopExp_Explorer(shape, kind), []
    while explorer.More():
        items.append(explorer.Current())
        explorer.Next()
    return items


def occ_curve(path):
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_EDGE
    from OCP.TopoDS import TopoDS

    (edge,) = _occ_items(_occ_shape(path), TopAbs_EDGE)
    curve = BRep_Tool.Curve_s(TopoDS.Edge(edge), 0.0, 1.0)
    return lambda ts: np.array([[(p := curve.Value(t)).X(), p.Y(), p.Z()] for t in ts])


def occ_surface(path):
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopoDS import TopoDS

    (face,) = _occ_items(_occ_shape(path), TopAbs_FACE)
    surface = BRep_Tool.Surface_s(TopoDS.Face(face))
    return lambda u, v: np.array([[(p := surface.Value(a, b)).X(), p.Y(), p.Z()] for a, b in zip(u, v)])


@pytest.mark.parametrize("ext", ["step", "iges"])
@pytest.mark.parametrize("dim", [2, 3])
def test_scipy_bspline_curve_reads_back_in_open_cascade(tmp_path, ext, dim):
    si = pytest.importorskip("scipy.interpolate")
    pts = POINTS3[:, :dim]
    b = si.make_interp_spline(np.linspace(0.0, 1.0, len(pts)), pts, k=3)
    karkas.export(b, tmp_path / f"b.{ext}")
    ts = np.linspace(0.0, 1.0, 41)
    expected = np.column_stack([b(ts), np.zeros((len(ts), 3 - dim))])
    np.testing.assert_allclose(occ_curve(tmp_path / f"b.{ext}")(ts), expected, rtol=0, atol=1e-9)


@pytest.mark.parametrize("ext", ["step", "iges"])
def test_scipy_bspline_surface_reads_back_in_open_cascade(tmp_path, ext):
    si = pytest.importorskip("scipy.interpolate")
    if not hasattr(si, "NdBSpline"):
        pytest.skip("SciPy without NdBSpline")
    tu = np.r_[[0.0] * 4, 0.5, [1.0] * 4]
    tv = np.r_[[0.0] * 3, 0.3, 0.6, [1.0] * 3]
    rng = np.random.default_rng(1)
    c = rng.random((5, 5, 3))
    s = si.NdBSpline((tu, tv), c, (3, 2))
    karkas.export(s, tmp_path / f"s.{ext}")
    u, v = rng.random(30), rng.random(30)
    np.testing.assert_allclose(occ_surface(tmp_path / f"s.{ext}")(u, v), s(np.column_stack([u, v])), rtol=0, atol=1e-9)


def test_scipy_bspline_only_as_cad(tmp_path):
    si = pytest.importorskip("scipy.interpolate")
    b = si.make_interp_spline(np.linspace(0.0, 1.0, len(POINTS2)), POINTS2, k=3)
    with pytest.raises(karkas.OptionError):
        karkas.export(b, tmp_path / "b.csv")


needs_exact_form = pytest.mark.skipif(
    not hasattr(karkas.Curve, "to_bspline"), reason="curves without to_bspline() in this build"
)


@needs_cli
@needs_exact_form
@pytest.mark.parametrize("ext", ["step", "iges"])
def test_ll_curve_cad_matches_cli_and_open_cascade(tmp_path, ext):
    src = tmp_path / "points.csv"
    write_points(src, POINTS3)
    run_cli("curve", "ll", src, "-o", tmp_path / f"cli.{ext}")
    c = karkas.LLCurve(POINTS3, order=3)
    karkas.export(c, tmp_path / f"py.{ext}")
    # The product is named after the file: write the same name to compare.
    (tmp_path / "py").mkdir()
    karkas.export(c, tmp_path / "py" / f"cli.{ext}")
    same_bytes(tmp_path / f"cli.{ext}", tmp_path / "py" / f"cli.{ext}")
    a, b = c.domain
    ts = np.linspace(a, b, 41)
    np.testing.assert_allclose(occ_curve(tmp_path / f"py.{ext}")(ts), c(ts), rtol=0, atol=1e-9)


@needs_cli
@needs_exact_form
@pytest.mark.parametrize("ext", ["step", "iges"])
def test_ll_surface_cad_matches_cli(tmp_path, ext):
    src = tmp_path / "grid.csv"
    write_grid(src, GRID)
    run_cli("surface", "ll", src, "-o", tmp_path / f"cli.{ext}")
    (tmp_path / "py").mkdir()
    karkas.export(karkas.LLSurface(GRID, order=3), tmp_path / "py" / f"cli.{ext}")
    same_bytes(tmp_path / f"cli.{ext}", tmp_path / "py" / f"cli.{ext}")


def test_curve_without_exact_form_is_refused(tmp_path):
    if hasattr(karkas.Curve, "to_bspline"):
        pytest.skip("every curve class has an exact form in this build")
    with pytest.raises(karkas.OptionError, match="STEP/IGES"):
        karkas.export(karkas.LLCurve(POINTS2), tmp_path / "c.step")
    assert not (tmp_path / "c.step").exists()


# --- readers ------------------------------------------------------------------------------------

def test_read_surface_samples_reads_what_export_writes(tmp_path):
    S = karkas.LLSurface(GRID, order=3)
    karkas.export(S, tmp_path / "s.csv", samples=(6, 7))
    g = karkas.read_surface_samples(tmp_path / "s.csv")
    u = np.linspace(*S.domain_u, 6)
    v = np.linspace(*S.domain_v, 7)
    np.testing.assert_allclose(g, S(u, v), rtol=0, atol=1e-12)


def test_read_point_set_of_obj_and_csv(tmp_path):
    karkas.export(GRID, tmp_path / "g.obj")
    pts = karkas.read_point_set(tmp_path / "g.obj")
    np.testing.assert_allclose(pts, GRID.reshape(-1, 3), rtol=0, atol=1e-12)
    write_grid(tmp_path / "g.csv", GRID)
    np.testing.assert_array_equal(karkas.read_point_set(tmp_path / "g.csv"), GRID.reshape(-1, 3))


def test_read_skeleton_and_tube_export(tmp_path):
    # Two circles along a torus-like tube and their crossings, sampled 4 x 3.
    m1, m2, n1, n2 = 3, 4, 4, 3
    N1, N2 = m1 * n1, m2 * n2
    R, r = 3.0, 1.0

    def point(p, q):
        a, b = 2 * np.pi * p / N1, 2 * np.pi * q / N2
        return [(R + r * np.cos(b)) * np.cos(a), (R + r * np.cos(b)) * np.sin(a), r * np.sin(b)]

    with open(tmp_path / "along.csv", "w") as f:
        f.write("i,q,x,y,z\n")
        for i in range(m1):
            for q in range(N2):
                f.write("{},{},{!r},{!r},{!r}\n".format(i, q, *map(float, point(i * n1, q))))
    with open(tmp_path / "across.csv", "w") as f:
        f.write("j,p,x,y,z\n")
        for j in range(m2):
            for p in range(N1):
                f.write("{},{},{!r},{!r},{!r}\n".format(j, p, *map(float, point(p, j * n2))))
    along = karkas.read_skeleton(tmp_path / "along.csv")
    across = karkas.read_skeleton(tmp_path / "across.csv", across=True)
    assert along.shape == (m1, N2, 3) and across.shape == (m2, N1, 3)
    np.testing.assert_allclose(along[1, 5], point(n1, 5), rtol=0, atol=1e-15)
    tube = karkas.TubeSurface(along, across, n1, n2, 2, 2)
    for ext in ["csv", "obj", "html"]:
        out = tmp_path / f"cli.{ext}"
        if CLI is not None:
            run_cli("surface", "dps-tube", "--along", tmp_path / "along.csv", "--across", tmp_path / "across.csv",
                    "--n1", n1, "--n2", n2, "--r1", 2, "--r2", 2, "-o", out)
            title = f"discrete periodic tube, {N1} x {N2} values, orders 2 and 2"
            karkas.export(tube, tmp_path / f"py.{ext}", title=title)
            same_bytes(out, tmp_path / f"py.{ext}")
    with pytest.raises(karkas.OptionError, match="no exact STEP/IGES/DXF form"):
        karkas.export(tube, tmp_path / "t.iges")


def test_read_mask(tmp_path):
    (tmp_path / "m.csv").write_text("i,j\n0,2\n1,1\n")
    m = karkas.read_mask(tmp_path / "m.csv", 2, 3)
    assert m.dtype == bool and m.tolist() == [[False, False, True], [False, True, False]]
    with pytest.raises(karkas.FileFormatError):
        karkas.read_mask(tmp_path / "m.csv", 1, 1)


# --- the examples of the docstrings run -------------------------------------------------------

@pytest.mark.parametrize(
    "name",
    ["export", "read_skeleton", "read_point_set", "read_surface_samples", "read_mask"],
)
def test_docstring_examples(name):
    import doctest

    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner()
    for test in finder.find(getattr(karkas, name), name, globs={}):
        runner.run(test)
    assert runner.failures == 0


def test_repr_html_docstring_examples():
    import doctest

    runner = doctest.DocTestRunner()
    for cls in (karkas.Curve, karkas.Surface):
        for test in doctest.DocTestFinder().find(cls._repr_html_, "_repr_html_", globs={}):
            runner.run(test)
    assert runner.failures == 0


def test_mesh_tuple_with_bad_faces_is_refused(tmp_path):
    v = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    with pytest.raises(karkas.OptionError, match="faces"):
        karkas.export((v, np.array([[0, 1, 3]])), tmp_path / "m.obj")
    with pytest.raises(TypeError):
        karkas.export((v, np.array([[0, 1]])), tmp_path / "m.obj")
    karkas.export((v, np.array([[0, 1, 2]])), tmp_path / "m.obj")
    v2, f2 = karkas.read_mesh(tmp_path / "m.obj")
    np.testing.assert_array_equal(v2, v)
    assert f2.tolist() == [[0, 1, 2]]


def test_sample_counts_are_checked(tmp_path):
    c = karkas.LLCurve(POINTS2, order=3)
    S = karkas.LLSurface(GRID, order=3)
    with pytest.raises(karkas.OptionError, match="at least 2"):
        karkas.export(c, tmp_path / "c.csv", samples=1)
    with pytest.raises(karkas.OptionError, match="at most"):
        karkas.export(S, tmp_path / "s.csv", samples=(100_000, 100_000))
    with pytest.raises(karkas.OptionError):
        karkas.export(c, tmp_path / "c.csv", samples="many")
    assert list(tmp_path.iterdir()) == []
