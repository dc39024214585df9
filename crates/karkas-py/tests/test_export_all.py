"""karkas.export against the command line: for each format, the file Python writes equals the
file `karkas` writes for the same command and input, byte for byte (every format here is
deterministic: no clock, no randomness); STEP and IGES read back in Open CASCADE; the readers
read the files back; _repr_html_ shows a curve as SVG and a surface in the viewer."""

import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import karkas

ROOT = pathlib.Path(__file__).resolve().parents[3]


def _cli():
    candidates = [os.environ.get("KARKAS_BIN")]
    for target in (os.environ.get("CARGO_TARGET_DIR"), str(ROOT / "target")):
        if target:
            candidates += [os.path.join(target, "release", "karkas"), os.path.join(target, "debug", "karkas")]
    candidates.append(shutil.which("karkas"))
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    return None


CLI = _cli()
needs_cli = pytest.mark.skipif(CLI is None, reason="the karkas binary is not built (cargo build --release -p karkas-cli)")


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
    karkas.export(S, py_out, title=title, net=GRID)
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
    karkas.export(S, tmp_path / "py.obj", net=GRID, flip_normals=flip)
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
    assert r.returncode != 0 and "no exact STEP/IGES form" in r.stderr
    s = karkas.DiscreteSpline.interpolate(POINTS2, order=3, n=6)
    with pytest.raises(karkas.OptionError, match="no exact STEP/IGES form"):
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
