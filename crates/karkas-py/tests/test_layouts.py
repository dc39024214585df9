"""Input arrays in any memory layout give the same result as their C-ordered copy: a
Fortran-ordered array (the everyday ``np.array([x, y]).T``), a strided view and a reversed
view are read in their logical (row-major) order, never as raw memory; a Fortran-ordered
``out=`` array is refused rather than filled in the wrong order."""

import numpy as np
import pytest

import karkas


def layouts(a):
    """The array `a` in C order, Fortran order, as a strided view and as a reversed view."""
    c = np.ascontiguousarray(a)
    f = np.asfortranarray(a)
    wide = np.zeros(a.shape[:-1] + (2 * a.shape[-1],))
    wide[..., ::2] = a
    strided = wide[..., ::2]
    reversed_view = np.ascontiguousarray(a[::-1])[::-1]
    for v in (f, strided, reversed_view):
        np.testing.assert_array_equal(v, c)
    assert f.flags.f_contiguous and not f.flags.c_contiguous
    return c, [f, strided, reversed_view]


def curve_points(n=40):
    s = np.linspace(0.0, 1.0, n)
    return np.array([np.cos(3 * s) * (1 + s), np.sin(3 * s) * (1 + s)]).T


def surface_grid(nu=7, nv=9):
    u, v = np.meshgrid(np.linspace(0, 1, nu), np.linspace(0, 2, nv), indexing="ij")
    return np.stack([u, v, np.sin(3 * u) * np.cos(2 * v)], axis=-1)


def test_the_everyday_transpose_is_fortran_ordered():
    p = curve_points()
    assert p.flags.f_contiguous and not p.flags.c_contiguous


@pytest.mark.parametrize(
    "build",
    [
        lambda p: karkas.LLCurve(p, order=3),
        lambda p: karkas.LLCurve.interpolate(p, order=3),
        lambda p: karkas.CubicSpline(p),
        lambda p: karkas.fit_curve(p, knots=6),
    ],
    ids=["LLCurve", "LLCurve.interpolate", "CubicSpline", "fit_curve"],
)
def test_curves_read_every_layout_as_its_values(build):
    c, others = layouts(curve_points())
    reference = build(c)
    t = np.linspace(*reference.domain, 57)
    expected = reference(t)
    for a in others:
        np.testing.assert_array_equal(build(a)(t), expected)


def test_discrete_splines_and_hausdorff_read_every_layout():
    c, others = layouts(curve_points(12))
    expected = karkas.DiscreteSpline(c, order=2, n=4).values()
    for a in others:
        np.testing.assert_array_equal(karkas.DiscreteSpline(a, order=2, n=4).values(), expected)
    p = curve_points(12)
    c, others = layouts(np.column_stack([p, p[:, 0] * p[:, 1]]))
    b = np.ascontiguousarray(c[:, ::-1] * 0.9)
    h = karkas.hausdorff(c, b)["distance"]
    assert h > 0
    for a in others:
        assert karkas.hausdorff(a, b)["distance"] == h


@pytest.mark.parametrize(
    "build",
    [lambda g: karkas.LLSurface(g, order=3), lambda g: karkas.BicubicSurface(g)],
    ids=["LLSurface", "BicubicSurface"],
)
def test_surfaces_read_every_layout_as_its_values(build):
    c, others = layouts(surface_grid())
    u, v = np.linspace(0.3, 0.6, 5), np.linspace(0.3, 0.6, 6)
    reference = build(c)
    expected = reference(u, v)
    for a in others:
        np.testing.assert_array_equal(build(a)(u, v), expected)


def test_surface_csv_export_reads_every_layout(tmp_path):
    c, others = layouts(surface_grid(3, 4))
    u, v = np.arange(3.0), np.arange(4.0)
    karkas.export_surface_csv(tmp_path / "c.csv", u, v, c)
    for k, a in enumerate(others):
        karkas.export_surface_csv(tmp_path / f"{k}.csv", u, v, a)
        assert (tmp_path / f"{k}.csv").read_text() == (tmp_path / "c.csv").read_text()


def test_a_fortran_ordered_out_is_refused():
    curve = karkas.LLCurve(curve_points(), order=3)
    t = np.linspace(*curve.domain, 10)
    out = np.asfortranarray(np.zeros((10, 2)))
    with pytest.raises(karkas.KarkasError, match="C-contiguous"):
        curve(t, out=out)
