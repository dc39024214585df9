"""The command line and Python build the same objects: for every method command, the CLI's CSV
output (which carries its parameters: t,x,y / u,v,x,y,z / j,x,y / ...) equals the Python
object's evaluation at those parameters (to 1e-12 relative), on the same input file, with the
same options and with the defaults of both (which must therefore agree).

The binary is $KARKAS_BIN, else target/release/karkas of this repository (build it with
`cargo build --release -p karkas-cli`); without it these tests are skipped."""

import math
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

import karkas

REPO = Path(__file__).resolve().parents[3]
BIN = Path(os.environ.get("KARKAS_BIN", REPO / "target" / "release" / "karkas"))

pytestmark = pytest.mark.skipif(not BIN.is_file(), reason=f"no karkas binary at {BIN}")

RTOL = 1e-12


def cli(*args):
    """Runs the CLI, failing with its message when it fails; returns standard output."""
    done = subprocess.run([str(BIN), *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def read_csv(path):
    """The header names and the rows as a float array."""
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def close(actual, expected):
    """1e-12 relative to the size of the values (absolute near zero coordinates)."""
    actual, expected = np.asarray(actual), np.asarray(expected)
    assert actual.shape == expected.shape
    scale = max(1.0, float(np.max(np.abs(expected))))
    np.testing.assert_allclose(actual, expected, rtol=RTOL, atol=RTOL * scale)


def cli_default(*command, option):
    """The default of an option as the CLI's help prints it."""
    text = cli(*command, "--help")
    found = re.search(rf"--{option}\b.*?\[default: ([^\]]+)\]", text, re.S)
    assert found, f"no default for --{option} in the help of {command}"
    return found.group(1)


def write_curve(path, pts):
    cols = "x,y,z"[: 2 * pts.shape[1] - 1]
    np.savetxt(path, pts, delimiter=",", header=cols, comments="", fmt="%.17g")
    return path


def write_grid(path, grid):
    nu, nv, _ = grid.shape
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    rows = np.column_stack([i.ravel(), j.ravel(), grid.reshape(-1, 3)])
    np.savetxt(path, rows, delimiter=",", header="i,j,x,y,z", comments="", fmt="%.17g")
    return path


def write_family(path, curves, header=("curve", "x", "y", "z")):
    rows = np.vstack([np.column_stack([np.full(len(c), k), c]) for k, c in enumerate(curves)])
    np.savetxt(path, rows, delimiter=",", header=",".join(header), comments="", fmt="%.17g")
    return path


@pytest.fixture
def wavy_file(tmp_path):
    s = np.linspace(0.0, 3.0, 25)
    pts = np.column_stack([np.cos(s) * (1 + 0.3 * np.sin(7 * s)), np.sin(s), 0.2 * np.cos(3 * s)])
    return write_curve(tmp_path / "wavy.csv", pts)


@pytest.fixture
def grid_file(tmp_path):
    u, v = np.meshgrid(np.linspace(0, 1, 7), np.linspace(0, 2, 9), indexing="ij")
    grid = np.stack([u + 0.1 * v**2, v, np.sin(2 * u) * np.cos(v)], -1)
    return write_grid(tmp_path / "grid.csv", grid)


# ---------------------------------------------------------------- defaults


@pytest.mark.parametrize(
    "command, option, python, keyword",
    [
        (("curve", "ll"), "order", karkas.LLCurve, "order"),
        (("surface", "ll"), "order", karkas.LLSurface, "order"),
        (("section",), "order", karkas.LLSurface, "order"),
        (("surface", "dps-tube"), "r1", karkas.TubeSurface, "r1"),
        (("surface", "dps-tube"), "r2", karkas.TubeSurface, "r2"),
        (("surface", "bicubic"), "param", karkas.BicubicSurface, "parameterization"),
        (("curve", "fit"), "fairness", karkas.fit_curve, "fairness"),
        (("curve", "fit"), "starts", karkas.fit_curve, "starts"),
    ],
)
def test_defaults_are_the_same(command, option, python, keyword):
    import inspect

    default = inspect.signature(python).parameters[keyword].default
    shown = cli_default(*command, option=option)
    if isinstance(default, str):
        assert shown == default
    else:
        assert float(shown) == default



def test_the_smoothing_default_is_per_mode(tmp_path):
    """--smoothing has no single default: 0.1 on given knots, 0.3 with --tolerance, as the
    help says; fit_curve's smoothing=None is the same, and so is the command without it."""
    import inspect

    assert inspect.signature(karkas.fit_curve).parameters["smoothing"].default is None
    text = " ".join(cli("curve", "fit", "--help").split())
    assert "Default 0.1 on given knots (--knots), 0.3 with --tolerance" in text
    rng = np.random.default_rng(5)
    t = np.linspace(0.0, 2.0 * np.pi, 400)
    pts = np.column_stack([np.cos(t), 0.3 * np.sin(t)]) + rng.normal(0.0, 1e-3, (400, 2))
    path = write_curve(tmp_path / "noisy.csv", pts)
    for mode, value, other in (({"knots": 12}, 0.1, 0.3), ({"tolerance": 5e-3}, 0.3, 0.1)):
        default = karkas.fit_curve(pts, **mode).distances
        np.testing.assert_array_equal(default, karkas.fit_curve(pts, smoothing=value, **mode).distances)
        assert not np.array_equal(default, karkas.fit_curve(pts, smoothing=other, **mode).distances)
        option = f"--{next(iter(mode))}"
        report = tmp_path / "dev.csv"
        cli("curve", "fit", path, option, list(mode.values())[0], "-o", tmp_path / "c.csv", "--report", report)
        close(read_csv(report)[1][:, 2], default)


# ---------------------------------------------------------------- curves


@pytest.mark.parametrize(
    "options, kwargs",
    [
        ([], {}),
        (["--order", 5, "--closed"], dict(order=5, closed=True)),
        (["--order", 2, "--interpolate"], dict(order=2, interpolate=True)),
        (["--order", 4, "--within", 0.004], dict(order=4, within=0.004)),
    ],
)
def test_curve_ll(tmp_path, wavy_file, options, kwargs):
    out = tmp_path / "out.csv"
    cli("curve", "ll", wavy_file, "-o", out, "--samples", 77, *options)
    header, rows = read_csv(out)
    assert header == ["t", "x", "y", "z"]
    c = karkas.LLCurve(karkas.read_curve(wavy_file), **kwargs)
    close(rows[:, 1:], c(rows[:, 0]))
    assert rows[0, 0] == c.domain[0] and rows[-1, 0] == c.domain[1]


@pytest.mark.parametrize(
    "options, kwargs",
    [
        (["--knots", 7], dict(knots=7)),
        (["--knots", 7, "--free-ends"], dict(knots=7, free_ends=True)),
        (["--knots", "0,0.3,0.45,0.7,1", "--eps", 0.05, "--pin-ends"], dict(knots=[0, 0.3, 0.45, 0.7, 1], eps=0.05, pin_ends=True)),
        (["--knots", 6, "--corner", 0.4, "--fairness", 0], dict(knots=6, corners=[0.4], fairness=0.0)),
        (["--tolerance", 2e-3], dict(tolerance=2e-3)),
        (["--knots", "0,0.3,0.45,0.7,1", "--eps", 0.05, "--penalty", "paper"], dict(knots=[0, 0.3, 0.45, 0.7, 1], eps=0.05, penalty="paper")),
        (["--knots", 6, "--starts", 5], dict(knots=6, starts=5)),
    ],
)
def test_curve_fit(tmp_path, wavy_file, options, kwargs):
    out, report = tmp_path / "out.csv", tmp_path / "dev.csv"
    cli("curve", "fit", wavy_file, "-o", out, "--samples", 61, "--report", report, *options)
    header, rows = read_csv(out)
    assert header == ["t", "x", "y", "z"]
    f = karkas.fit_curve(karkas.read_curve(wavy_file), **kwargs)
    close(rows[:, 1:], f(rows[:, 0]))
    dev_header, dev = read_csv(report)
    assert dev_header == ["point", "t", "distance"]
    close(dev[:, 1], f.parameters)
    close(dev[:, 2], f.distances)


@pytest.mark.parametrize("options, kwargs", [(["--knots", 13], dict(knots=13)), (["--tolerance", 1e-4], dict(tolerance=1e-4))])
@pytest.mark.parametrize("scale, offset", [(1.0, (0.0, 0.0)), (40.0, (-300.0, 125.0))])
def test_closed_curve_fit(tmp_path, options, kwargs, scale, offset):
    """fit_curve(..., closed=True) is the command's `curve fit --closed`: a periodic fit of
    an ellipse, closed and C^1 at the seam (to round-off), equal to the CLI's samples and
    deviations to 1e-12, and close to the ellipse."""
    u = np.linspace(0.0, 2.0 * np.pi, 48, endpoint=False)
    pts = scale * np.column_stack([3.0 * np.cos(u), np.sin(u + 0.2 * np.sin(u))]) + offset
    path = write_curve(tmp_path / "ellipse.csv", pts)
    out, report = tmp_path / "out.csv", tmp_path / "dev.csv"
    cli("curve", "fit", path, "--closed", "-o", out, "--samples", 97, "--report", report, *options)
    header, rows = read_csv(out)
    assert header == ["t", "x", "y"]
    f = karkas.fit_curve(pts, closed=True, **kwargs)
    close(rows[:, 1:], f(rows[:, 0]))
    dev_header, dev = read_csv(report)
    close(dev[:, 1], f.parameters)
    close(dev[:, 2], f.distances)
    size = 6.0 * scale
    np.testing.assert_allclose(f(0.0), f(1.0), rtol=0, atol=1e-12 * size)
    np.testing.assert_allclose(f(0.0, nu=1), f(1.0, nu=1), rtol=0, atol=1e-9 * size)
    assert f.max_distance < 1e-2 * size
    assert np.linalg.norm(f(0.0, nu=1)) > 1.0 * scale  # a real tangent, not a stalled seam
    # The open fit of the same points does not close: the option is what closes the curve.
    g = karkas.fit_curve(pts, **kwargs)
    assert np.linalg.norm(g(0.0) - g(1.0)) > 1e-3 * size
    with pytest.raises(karkas.OptionError, match="closed"):
        karkas.fit_curve(pts, closed=True, pin_ends=True, **kwargs)


@pytest.mark.parametrize("points", [[[1.0, 2.0]] * 3, [[1.0, 2.0], [3.0, 4.0], [1.0, 2.0]]])
def test_closed_fit_says_the_repeated_last_point_was_dropped(tmp_path, points):
    """A closed fit of three points whose last repeats the first has two points left: Python
    and the CLI both say that the repeated point was dropped (not just "got 2")."""
    pts = np.array(points)
    expected = (
        "a closed fit (after dropping its last point, which repeats the first) needs at least 3 points, got 2"
    )
    with pytest.raises(karkas.PointsError) as raised:
        karkas.fit_curve(pts, knots=5, closed=True)
    assert expected in str(raised.value)
    path = write_curve(tmp_path / "three.csv", pts)
    done = subprocess.run(
        [str(BIN), "curve", "fit", str(path), "--closed", "--knots", "5", "-o", str(tmp_path / "out.csv")],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 2, done.stderr
    assert expected in done.stderr
    # Three distinct points are enough: nothing is dropped and the fit is made.
    f = karkas.fit_curve(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), knots=3, closed=True)
    assert f.parameters.shape == (3,)


@pytest.mark.parametrize("poles", [False, True])
def test_curve_dps(tmp_path, wavy_file, poles):
    out = tmp_path / "out.csv"
    cli("curve", "dps", wavy_file, "-o", out, "--order", 3, "--n", 4, *(["--poles"] if poles else []))
    header, rows = read_csv(out)
    assert header == ["j", "x", "y", "z"]
    pts = karkas.read_curve(wavy_file)
    s = karkas.DiscreteSpline(pts, order=3, n=4) if poles else karkas.DiscreteSpline.interpolate(pts, order=3, n=4)
    np.testing.assert_array_equal(rows[:, 0], np.arange(s.period))
    close(rows[:, 1:], s.values())


# ---------------------------------------------------------------- surfaces


def check_grid_surface(out, surface, params=("u", "v")):
    header, rows = read_csv(out)
    assert header == [*params, "x", "y", "z"]
    close(rows[:, 2:], surface(rows[:, 0], rows[:, 1], grid=False))


@pytest.mark.parametrize(
    "options, kwargs",
    [
        ([], {}),
        (["--order", 4, "--closed-v"], dict(order=4, closed_v=True)),
        (["--order", 2, "--interpolate", "--closed-u"], dict(order=2, closed_u=True, interpolate=True)),
        (["--order", 3, "--within", 0.01, "--closed-v"], dict(order=3, closed_v=True, within=0.01)),
    ],
)
def test_surface_ll(tmp_path, grid_file, options, kwargs):
    out = tmp_path / "out.csv"
    cli("surface", "ll", grid_file, "-o", out, "--samples", "13,17", *options)
    check_grid_surface(out, karkas.LLSurface(karkas.read_grid(grid_file), **kwargs))


@pytest.mark.parametrize("param", [None, "uniform", "chord", "averaged", "averaged-chord", "centripetal"])
@pytest.mark.parametrize("closed", [[], ["--closed-v"]])
def test_surface_bicubic(tmp_path, grid_file, param, closed):
    out = tmp_path / "out.csv"
    options = [] if param is None else ["--param", param]
    cli("surface", "bicubic", grid_file, "-o", out, "--samples", "11,15", *options, *closed)
    kwargs = {} if param is None else dict(parameterization=param)
    S = karkas.BicubicSurface(karkas.read_grid(grid_file), closed_v=bool(closed), **kwargs)
    check_grid_surface(out, S)


def test_surface_bicubic_origin(tmp_path, grid_file):
    out = tmp_path / "out.csv"
    cli("surface", "bicubic", grid_file, "-o", out, "--samples", "11,15", "--origin", "3,5")
    S = karkas.BicubicSurface(karkas.read_grid(grid_file), origin=(3, 5))
    check_grid_surface(out, S)
    u, v = karkas.grid_parameters(karkas.read_grid(grid_file), origin=(3, 5))
    close(S.knots_u, u)
    close(S.knots_v, v)
    assert u[3] == 0.0 and v[5] == 0.0
    # Not the default origin's surface.
    assert not np.allclose(S.knots_u, karkas.BicubicSurface(karkas.read_grid(grid_file)).knots_u)


def network_files(tmp_path, step=4):
    """z = x^2 + y^3/2 + x y: u-curves at y = const, v-curves at x = const (crossing at
    every step-th point), and the cross-derivatives per unit of the network parameters (the
    crossings sit at u, v = (x + 1)/2, (y + 1)/2)."""
    s = np.linspace(-1.0, 1.0, 13)
    xs = s[::step]
    v = [np.column_stack([np.full_like(s, x), s, x**2 + 0.5 * s**3 + x * s]) for x in xs]
    u = [np.column_stack([s, np.full_like(s, y), s**2 + 0.5 * y**3 + s * y]) for y in xs]
    du = [np.column_stack([np.zeros_like(s), np.full_like(s, 2.0), 2 * (1.5 * y**2 + s)]) for y in xs]
    dv = [np.column_stack([np.full_like(s, 2.0), np.zeros_like(s), 2 * (2 * x + s)]) for x in xs]
    names = ("u", "v", "du", "dv")
    return [write_family(tmp_path / f"{n}.csv", c) for n, c in zip(names, (u, v, du, dv))]


@pytest.mark.parametrize("kind", ["bilinear", "bicubic", "gordon", "gordon-spline", "composite"])
def test_surface_coons(tmp_path, kind):
    u, v, du, dv = network_files(tmp_path, 12 if kind in ("bilinear", "bicubic") else 4)
    out = tmp_path / "out.csv"
    cli("surface", "coons", "--kind", kind, "--u-curves", u, "--v-curves", v, "-o", out, "--samples", "9,12")
    S = karkas.CoonsSurface(u_curves=karkas.read_network(u), v_curves=karkas.read_network(v), kind=kind)
    check_grid_surface(out, S)


def test_surface_coons_with_cross_derivatives(tmp_path):
    u, v, du, dv = network_files(tmp_path)
    out = tmp_path / "out.csv"
    cli("surface", "coons", "--kind", "composite", "--u-curves", u, "--v-curves", v,
        "--u-derivs", du, "--v-derivs", dv, "-o", out, "--samples", "9,12")
    read = karkas.read_network
    S = karkas.CoonsSurface(u_curves=read(u), v_curves=read(v), kind="composite", u_derivs=read(du), v_derivs=read(dv))
    check_grid_surface(out, S)


@pytest.mark.parametrize("orders", [[], ["--r1", 3, "--r2", 1]])
def test_surface_dps_tube(tmp_path, orders):
    m1, m2, n1, n2, R, r = 4, 5, 3, 4, 3.0, 1.0
    N1, N2 = m1 * n1, m2 * n2

    def torus(p, q):
        a, b = np.broadcast_arrays(2 * np.pi * np.asarray(p) / N1, 2 * np.pi * np.asarray(q) / N2)
        return np.stack([(R + r * np.cos(a)) * np.cos(b), (R + r * np.cos(a)) * np.sin(b), r * np.sin(a)], -1)

    along = [torus(i * n1, np.arange(N2)) for i in range(m1)]
    across = [torus(np.arange(N1), j * n2) for j in range(m2)]
    fa = tmp_path / "along.csv"
    fb = tmp_path / "across.csv"
    rows_a = np.vstack([np.column_stack([np.full(N2, i), np.arange(N2), c]) for i, c in enumerate(along)])
    rows_b = np.vstack([np.column_stack([np.full(N1, j), np.arange(N1), c]) for j, c in enumerate(across)])
    np.savetxt(fa, rows_a, delimiter=",", header="i,q,x,y,z", comments="", fmt="%.17g")
    np.savetxt(fb, rows_b, delimiter=",", header="j,p,x,y,z", comments="", fmt="%.17g")
    out = tmp_path / "out.csv"
    cli("surface", "dps-tube", "--along", fa, "--across", fb, "--n1", n1, "--n2", n2, "-o", out, *orders)
    header, rows = read_csv(out)
    assert header == ["p", "q", "x", "y", "z"]
    # The same files, read as Python reads CSV: the coordinates in file order.
    a = np.loadtxt(fa, delimiter=",", skiprows=1)[:, 2:].reshape(m1, N2, 3)
    b = np.loadtxt(fb, delimiter=",", skiprows=1)[:, 2:].reshape(m2, N1, 3)
    kwargs = dict(zip(("r1", "r2"), orders[1::2]))
    t = karkas.TubeSurface(a, b, n1, n2, **kwargs)
    values = t.values()
    p, q = rows[:, 0].astype(int), rows[:, 1].astype(int)
    close(rows[:, 2:], values[p, q])
    assert len(rows) == N1 * N2


@pytest.mark.parametrize("turn", [0.0, 20.0])
def test_surface_implicit(tmp_path, turn):
    out = tmp_path / "out.csv"
    expr = "x^2/4 + y^2 + z^2/2 - 1"
    cli("surface", "implicit", "--expr", expr, "--start", "1.2,0.7,0.3", "--nodes", "5,6",
        "--step", "0.1,0.15", "--turn", turn, "-o", out)
    header, rows = read_csv(out)
    assert header == ["i", "j", "x", "y", "z"]
    directions = "principal" if turn == 0 else "turned"
    surface = karkas.ImplicitSurface(expr)
    grid = surface.trace_net([1.2, 0.7, 0.3], (5, 6), (0.1, 0.15), directions=directions, angle=math.radians(turn))
    i, j = rows[:, 0].astype(int), rows[:, 1].astype(int)
    close(rows[:, 2:], grid[i, j])
    # The command line's names.
    same = surface.trace_net([1.2, 0.7, 0.3], (5, 6), step=(0.1, 0.15), turn=turn)
    close(rows[:, 2:], same[i, j])


@pytest.mark.parametrize("option, directions", [("--turn-u", "turned-u"), ("--turn-v", "turned-v")])
def test_surface_implicit_one_family_turned(tmp_path, option, directions):
    out = tmp_path / "out.csv"
    expr = "x^2/4 + y^2 + z^2/2 - 1"
    cli("surface", "implicit", "--expr", expr, "--start", "1.2,0.7,0.3", "--nodes", "5,6",
        "--step", "0.1,0.15", option, 25, "-o", out)
    header, rows = read_csv(out)
    grid = karkas.ImplicitSurface(expr).trace_net(
        [1.2, 0.7, 0.3], (5, 6), (0.1, 0.15), directions=directions, angle=math.radians(25))
    i, j = rows[:, 0].astype(int), rows[:, 1].astype(int)
    close(rows[:, 2:], grid[i, j])
    # Not the net with both families turned.
    both = karkas.ImplicitSurface(expr).trace_net(
        [1.2, 0.7, 0.3], (5, 6), (0.1, 0.15), directions="turned", angle=math.radians(25))
    assert np.abs(rows[:, 2:] - both[i, j]).max() > 1e-3


def test_surface_implicit_closed_v_and_one_step(tmp_path):
    out = tmp_path / "out.csv"
    expr = "x^2 + y^2 - 1 + 0*z"
    cli("surface", "implicit", "--expr", expr, "--start", "1,0,0", "--nodes", "4,9", "--step", "0.2",
        "--closed-v", "-o", out)
    header, rows = read_csv(out)
    grid = karkas.ImplicitSurface(expr).trace_net([1.0, 0, 0], (4, 9), step=0.2, closed_v=True)
    close(rows[:, 2:], grid[rows[:, 0].astype(int), rows[:, 1].astype(int)])


# ---------------------------------------------------------------- section, hausdorff, vary


@pytest.mark.parametrize("options, tolerance, cells", [([], None, None), (["--tolerance", 1e-5, "--cells", "20,30"], 1e-5, (20, 30))])
def test_section(tmp_path, grid_file, options, tolerance, cells):
    out = tmp_path / "out.csv"
    cli("section", grid_file, "--method", "ll", "--z", "0.2,-0.3", "--plane", "1,1,0,1.2", "-o", out, *options)
    header, rows = read_csv(out)
    assert header == ["section", "t", "x", "y", "z"]
    S = karkas.LLSurface(karkas.read_grid(grid_file))
    pieces = []
    for normal, offset in [([1.0, 1.0, 0.0], 1.2), ([0, 0, 1.0], 0.2), ([0, 0, 1.0], -0.3)]:
        pieces += S.section(normal, offset, tolerance=tolerance, cells=cells)
    assert len(pieces) == int(rows[:, 0].max()) + 1 and len(pieces) >= 3
    for k, piece in enumerate(pieces):
        block = rows[rows[:, 0] == k]
        pts = piece.points
        if piece.closed:
            pts = np.vstack([pts, pts[:1]])
        close(block[:, 2:], pts)
        t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(pts, axis=0), axis=1))])
        close(block[:, 1], t)
        assert math.isclose(block[-1, 1], piece.length, rel_tol=1e-12)


def test_hausdorff_to_an_implicit_surface(tmp_path, wavy_file):
    expr = "x^2 + y^2 + z^2/4 - 1"
    lines = cli("hausdorff", wavy_file, "--expr", expr).splitlines()
    h = karkas.hausdorff(karkas.read_curve(wavy_file), expr=expr)
    assert float(lines[0].split()[1]) == h["distance"]
    for line, side in zip(lines[1:], ("forward", "backward")):
        assert float(line.split()[3]) == h[side]["distance"], line


def test_hausdorff(tmp_path, wavy_file, grid_file):
    text = cli("hausdorff", wavy_file, grid_file)
    lines = text.splitlines()
    a = karkas.read_curve(wavy_file)
    b = karkas.read_grid(grid_file).reshape(-1, 3)
    h = karkas.hausdorff(a, b)
    assert float(lines[0].split()[1]) == h["distance"]
    for line, side in zip(lines[1:], ("forward", "backward")):
        found = re.match(r".* -> .* (\S+) at (\S+) nearest (\S+)", line)
        assert found, line
        d, p, q = found.groups()
        assert float(d) == h[side]["distance"]
        close([float(x) for x in p.split(",")], h[side]["from"])
        close([float(x) for x in q.split(",")], h[side]["to"])


@pytest.mark.parametrize("penalty, with_total, scale", [(None, False, False), (50.0, False, False), (None, True, True)])
def test_vary(tmp_path, grid_file, penalty, with_total, scale):
    grid = karkas.read_grid(grid_file)
    z = grid[..., 2]
    n, m = z.shape
    rows_sum = z.sum(axis=1) + np.linspace(0.1, 0.4, n)
    total = rows_sum.sum()
    cols_sum = z.sum(axis=0) + (total - z.sum()) / m
    mask = tmp_path / "mask.csv"
    mask.write_text("i,j\n0,0\n3,4\n")
    fixed = np.zeros((n, m), bool)
    fixed[0, 0] = fixed[3, 4] = True
    out = tmp_path / "out.csv"
    extra = [] if penalty is None else ["--penalty", penalty]
    numbers = lambda xs: ",".join("%.17g" % x for x in xs)  # noqa: E731
    kwargs = {}
    if with_total:  # the last row and column sums left to the total
        rows_sum, cols_sum = rows_sum[:-1], cols_sum[:-1]
        extra += ["--total", "%.17g" % total, "--scale-with-total"]
        kwargs = dict(total=float("%.17g" % total), scale_with_total=scale)
    cli("vary", grid_file, "--coord", "z", "--rows", numbers(rows_sum),
        "--cols", numbers(cols_sum), "--fixed", mask, "-o", out, *extra)
    header, rows = read_csv(out)
    assert header == ["i", "j", "x", "y", "z"]
    varied = karkas.vary(z, rows_sum, cols_sum, fixed=fixed, penalty=penalty, **kwargs)
    i, j = rows[:, 0].astype(int), rows[:, 1].astype(int)
    close(rows[:, 4], varied[i, j])
    close(rows[:, 2:4], grid[i, j, :2])
