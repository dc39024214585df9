"""DXF output read back with ezdxf: the files that `karkas curve ll`, `karkas curve fit` and
`karkas.export` write open in ezdxf without audit errors, hold one SPLINE on layer CURVE and
the input points as POINT entities on layer POINTS, and ezdxf's own B-spline evaluation of
the SPLINE (its control points, knots and order) gives the curve that karkas evaluates (the
command's CSV samples, or `curve(t)` in Python) at the same parameters to 1e-12 of the
curve's size."""

import os
import subprocess

import numpy as np
import pytest

import karkas

if os.environ.get("CI"):
    import ezdxf  # CI installs it: a missing ezdxf must fail there, not skip
else:
    ezdxf = pytest.importorskip("ezdxf")
from ezdxf.math import BSpline  # noqa: E402


from cli_binary import CLI, needs_cli  # noqa: E402

CLOSED, PERIODIC, RATIONAL, PLANAR = 1, 2, 4, 8


def run_cli(*args):
    subprocess.run([CLI, *map(str, args)], check=True, capture_output=True)


def wave(n=25):
    s = np.linspace(0.0, 4.0, n)
    return np.column_stack([s, 0.3 * np.sin(2.1 * s) + 0.05 * s * s])


def ring3d(n=16):
    a = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    return np.column_stack([3 * np.cos(a), 2 * np.sin(a), 0.4 * np.sin(2 * a)])


def write_points(path, pts):
    header = "x,y" if pts.shape[1] == 2 else "x,y,z"
    np.savetxt(path, pts, delimiter=",", header=header, comments="", fmt="%.17g")


def read_dxf(path):
    """The document (audited: no errors), its one SPLINE and its POINT entities."""
    doc = ezdxf.readfile(str(path))
    assert doc.dxfversion >= "AC1015"
    auditor = doc.audit()
    assert not auditor.has_errors, [e.message for e in auditor.errors]
    names = {layer.dxf.name for layer in doc.layers}
    assert {"CURVE", "POINTS"} <= names, names
    msp = doc.modelspace()
    splines = msp.query("SPLINE")
    assert len(splines) == 1
    spline = splines[0]
    assert spline.dxf.layer == "CURVE"
    points = list(msp.query("POINT"))
    assert all(p.dxf.layer == "POINTS" for p in points)
    assert len(msp) == 1 + len(points)
    return doc, spline, points


def ezdxf_curves(spline):
    """ezdxf's B-spline of the entity, built twice: from its control points, knots and order,
    and by the entity's own construction tool."""
    assert spline.dxf.flags & (PERIODIC | RATIONAL) == 0
    control = np.array(spline.control_points)
    knots = list(spline.knots)
    order = spline.dxf.degree + 1
    assert len(knots) == len(control) + order
    assert spline.fit_point_count() == 0 and len(spline.weights) == 0
    return [BSpline(control, order=order, knots=knots), spline.construction_tool()], control


def assert_same_curve(spline, ts, expected):
    """ezdxf's evaluation of `spline` at `ts` is `expected` (n, 3) to 1e-12 of the size.

    The entity holds karkas's own knots (the domain is that of `ts`); ezdxf's BSpline
    normalizes a knot vector to [0, 1], so it is evaluated at (t - t0) / (t1 - t0)."""
    curves, control = ezdxf_curves(spline)
    knots = np.array(spline.knots)
    p = spline.dxf.degree
    t0, t1 = knots[0], knots[-1]
    assert (knots[p], knots[-p - 1]) == (t0, t1) == (ts[0], ts[-1])
    u = np.clip((np.asarray(ts) - t0) / (t1 - t0), 0.0, 1.0)
    size = np.max(np.abs(control))
    for curve in curves:
        assert curve.max_t == 1.0
        got = np.array(list(curve.points(u)))
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12 * size)
    # The test can fail: a parameter shifted by 1e-6 is far outside the tolerance.
    shifted = np.array(list(curves[0].points(np.clip(u + 1e-6, 0.0, 1.0))))
    assert np.max(np.abs(shifted - expected)) > 1e-9 * size


def in_space(pts):
    return pts if pts.shape[1] == 3 else np.column_stack([pts, np.zeros(len(pts))])


def assert_points(points, pts):
    got = np.array([tuple(p.dxf.location) for p in points])
    np.testing.assert_array_equal(got, in_space(pts))


def csv_samples(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, 0], in_space(data[:, 1:])


@needs_cli
def test_cli_ll_dxf_opens_in_ezdxf_with_the_same_curve(tmp_path):
    pts = wave()
    src = tmp_path / "wave.csv"
    write_points(src, pts)
    run_cli("curve", "ll", "--order", "3", src, "-o", tmp_path / "wave.dxf")
    run_cli("curve", "ll", "--order", "3", "--samples", "301", src, "-o", tmp_path / "samples.csv")
    _, spline, points = read_dxf(tmp_path / "wave.dxf")
    assert spline.dxf.flags == PLANAR and spline.dxf.degree == 6
    assert tuple(spline.dxf.extrusion) == (0.0, 0.0, 1.0)
    assert_points(points, pts)
    ts, expected = csv_samples(tmp_path / "samples.csv")
    assert_same_curve(spline, ts, expected)


@needs_cli
def test_cli_fit_dxf_opens_in_ezdxf_with_the_same_curve(tmp_path):
    rng = np.random.default_rng(7)
    pts = wave(60) + rng.normal(scale=1e-3, size=(60, 2))
    src = tmp_path / "noisy.csv"
    write_points(src, pts)
    run_cli("curve", "fit", "--knots", "9", src, "-o", tmp_path / "fit.dxf")
    run_cli("curve", "fit", "--knots", "9", "--samples", "257", src, "-o", tmp_path / "fit.csv")
    _, spline, points = read_dxf(tmp_path / "fit.dxf")
    assert spline.dxf.degree == 3 and spline.dxf.flags == PLANAR
    assert_points(points, pts)
    ts, expected = csv_samples(tmp_path / "fit.csv")
    assert_same_curve(spline, ts, expected)


@needs_cli
def test_cli_closed_space_curve_keeps_z_and_is_flagged_closed(tmp_path):
    pts = ring3d()
    src = tmp_path / "ring.csv"
    write_points(src, pts)
    run_cli("curve", "ll", "--closed", "--interpolate", src, "-o", tmp_path / "ring.dxf")
    run_cli("curve", "ll", "--closed", "--interpolate", src, "-o", tmp_path / "ring.csv.csv")
    _, spline, points = read_dxf(tmp_path / "ring.dxf")
    assert spline.dxf.flags == CLOSED and spline.closed
    control = np.array(spline.control_points)
    np.testing.assert_allclose(control[0], control[-1], rtol=0, atol=1e-12 * 3)
    assert np.ptp(control[:, 2]) > 0.5
    assert_points(points, pts)
    ts, expected = csv_samples(tmp_path / "ring.csv.csv")
    assert_same_curve(spline, ts, expected)


def test_python_export_dxf_matches_curve_evaluation(tmp_path):
    pts = wave()
    curve = karkas.LLCurve(pts, order=2)
    path = karkas.export(curve, tmp_path / "ll.dxf", points=pts)
    _, spline, points = read_dxf(path)
    assert_points(points, pts)
    t, c, k = curve.to_bspline()
    assert spline.dxf.degree == k
    np.testing.assert_array_equal(np.array(spline.knots), t)
    np.testing.assert_array_equal(np.array(spline.control_points), in_space(np.asarray(c)))
    ts = np.linspace(t[0], t[-1], 211)
    assert_same_curve(spline, ts, in_space(curve(ts)))

    fit = karkas.fit_curve(pts, knots=6)
    karkas.export(fit, tmp_path / "fit.dxf", points=pts)
    _, spline, points = read_dxf(tmp_path / "fit.dxf")
    t, _, _ = fit.to_bspline()
    ts = np.linspace(t[0], t[-1], 199)
    assert_same_curve(spline, ts, in_space(fit(ts)))
    assert_points(points, pts)


def test_python_export_dxf_of_a_space_curve_without_points(tmp_path):
    curve = karkas.LLCurve(ring3d(), closed=True)
    karkas.export(curve, tmp_path / "ring.dxf")
    _, spline, points = read_dxf(tmp_path / "ring.dxf")
    assert points == []
    assert spline.dxf.flags == CLOSED
    t, _, _ = curve.to_bspline()
    ts = np.linspace(t[0], t[-1], 157)
    assert_same_curve(spline, ts, curve(ts))


@needs_cli
def test_python_and_cli_write_the_same_dxf(tmp_path):
    pts = wave()
    src = tmp_path / "wave.csv"
    write_points(src, pts)
    run_cli("curve", "ll", src, "-o", tmp_path / "cli.dxf")
    karkas.export(karkas.LLCurve(pts), tmp_path / "py.dxf", points=pts)
    assert (tmp_path / "cli.dxf").read_bytes() == (tmp_path / "py.dxf").read_bytes()


def test_dxf_is_refused_where_there_is_no_exact_curve(tmp_path, circle2d):
    dps = karkas.DiscreteSpline.interpolate(circle2d, order=2) if hasattr(karkas, "DiscreteSpline") else None
    if dps is not None:
        with pytest.raises(karkas.OptionError, match="no exact STEP/IGES/DXF form"):
            karkas.export(dps, tmp_path / "d.dxf")
    grid = np.array([[[i, j, 0.1 * i * j] for j in range(4)] for i in range(4)], dtype=float)
    surface = karkas.LLSurface(grid)
    with pytest.raises(karkas.OptionError, match="DXF is written for curves only"):
        karkas.export(surface, tmp_path / "s.dxf")
    with pytest.raises(karkas.OptionError, match="points have 3 coordinates"):
        karkas.export(karkas.LLCurve(wave()), tmp_path / "c.dxf", points=ring3d())
    assert not any(tmp_path.iterdir())
