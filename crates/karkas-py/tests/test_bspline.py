"""B-splines out: to_bspline of every piecewise polynomial curve and surface, checked against
SciPy's BSpline / NdBSpline and geomdl built from the same knots and coefficients."""

import numpy as np
import pytest
from scipy.interpolate import BSpline, NdBSpline

import karkas

geomdl = pytest.importorskip("geomdl")
from geomdl import BSpline as GeomdlBSpline  # noqa: E402


def wavy(n, d, seed=3):
    s = np.linspace(0.0, 3.0, n)
    pts = np.column_stack([np.cos(s) * (1 + 0.3 * np.sin(5 * s)), np.sin(s), 0.2 * np.cos(3 * s)])
    return pts[:, :d]


def ring(n, d, repeat_first=False):
    a = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    pts = np.column_stack([np.cos(a), np.sin(a) * (1 + 0.2 * np.cos(3 * a)), 0.3 * np.sin(2 * a)])
    pts = pts[:, :d]
    return np.vstack([pts, pts[:1]]) if repeat_first else pts


def curves(d):
    """Every piecewise polynomial curve class, open and closed, in d dimensions."""
    rng = np.random.default_rng(7)
    noisy = wavy(60, d) + 0.01 * rng.normal(size=(60, d))
    return {
        "LLCurve": karkas.LLCurve(wavy(15, d), order=3),
        "LLCurve-order5": karkas.LLCurve(wavy(15, d), order=5),
        "LLCurve.interpolate": karkas.LLCurve.interpolate(wavy(15, d), order=3),
        "LLCurve-closed": karkas.LLCurve(ring(12, d), order=3, closed=True),
        "LLCurve.interpolate-closed": karkas.LLCurve.interpolate(ring(12, d), order=2, closed=True),
        "CubicSpline-not-a-knot": karkas.CubicSpline(wavy(11, d)),
        "CubicSpline-natural": karkas.CubicSpline(wavy(11, d), bc="natural"),
        "CubicSpline-clamped": karkas.CubicSpline(
            wavy(11, d), bc=("clamped", np.ones(d), -np.ones(d))
        ),
        "CubicSpline-periodic": karkas.CubicSpline(ring(10, d, repeat_first=True), bc="periodic"),
        "HermiteSpline": karkas.fit_curve(noisy, knots=7),
    }


CASES = [(d, name) for d in (2, 3) for name in curves(2)]


def inner_params(c, n=301):
    """Parameters over the domain; [a, b) for a closed curve (at b it wraps to a, where a
    derivative beyond the continuity comes from the first piece, the B-spline's from the last)."""
    a, b = c.domain
    return np.linspace(a, b, n, endpoint=not c.closed)


def scale(values):
    return max(1.0, float(np.abs(values).max()))


@pytest.mark.parametrize("d,name", CASES)
def test_to_bspline_equals_the_curve_in_scipy(d, name):
    c = curves(d)[name]
    t, coefs, k = c.to_bspline()
    assert coefs.shape == (len(t) - k - 1, d)
    assert t[0] == c.domain[0] and t[-1] == pytest.approx(c.domain[1], rel=1e-15)
    ref = BSpline(t, coefs, k)
    ts = inner_params(c)
    for nu in range(4):
        want = ref(ts, nu)
        np.testing.assert_allclose(c(ts, nu), want, rtol=0, atol=1e-12 * scale(want))


@pytest.mark.parametrize("d,name", CASES)
def test_to_bspline_equals_the_curve_in_geomdl(d, name):
    c = curves(d)[name]
    t, coefs, k = c.to_bspline()
    a, b = t[0], t[-1]
    g = GeomdlBSpline.Curve()
    g.degree = k
    g.ctrlpts = coefs.tolist()
    g.knotvector = ((t - a) / (b - a)).tolist()  # geomdl works on [0, 1]
    ts = inner_params(c, 41)
    s = (ts - a) / (b - a)
    got = np.array([g.evaluate_single(x) for x in s])
    np.testing.assert_allclose(c(ts), got, rtol=0, atol=1e-12 * scale(got))
    d1 = np.array([g.derivatives(x, 1)[1] for x in s]) / (b - a)
    np.testing.assert_allclose(c(ts, 1), d1, rtol=0, atol=1e-11 * scale(d1))


@pytest.mark.parametrize("d,name", CASES)
def test_derivative_curves_have_the_derivative_bspline(d, name):
    c = curves(d)[name]
    ts = inner_params(c)
    for nu in (1, 2, 3):
        dc = c.derivative(nu)
        t, coefs, k = dc.to_bspline()
        assert k == max(c.to_bspline()[2] - nu, 0)
        want = c(ts, nu)
        np.testing.assert_allclose(BSpline(t, coefs, k)(ts), want, rtol=0, atol=1e-11 * scale(want))
        if nu > c.continuity + 1:
            continue  # SciPy refuses to differentiate across knots repeated more than k - nu
        # SciPy's own differentiation of the B-spline agrees.
        sci = BSpline(*c.to_bspline()).derivative(nu)(ts)
        np.testing.assert_allclose(BSpline(t, coefs, k)(ts), sci, rtol=0, atol=1e-11 * scale(sci))


def test_closed_curves_export_one_period_whose_ends_meet():
    c = karkas.LLCurve(ring(12, 3), order=3, closed=True)
    t, coefs, k = c.to_bspline()
    np.testing.assert_allclose(coefs[0], coefs[-1], atol=1e-13)
    a, b = c.domain
    np.testing.assert_allclose(BSpline(t, coefs, k)(b), c(a), atol=1e-12)


# ---------------------------------------------------------------- surfaces


def height_grid(nu=7, nv=6, d=3):
    u = np.linspace(0.0, 1.0, nu)
    v = np.linspace(0.0, 1.3, nv)
    U, V = np.meshgrid(u, v, indexing="ij")
    g = np.stack([U + 0.1 * V, V, np.sin(2 * U) * np.cos(3 * V)], axis=-1)
    return g[..., :d]


def tube_grid(nu=6, nv=8):
    u = np.linspace(0.0, 1.0, nu)
    a = np.linspace(0.0, 2 * np.pi, nv)  # the last column repeats the first: closed in v
    U, A = np.meshgrid(u, a, indexing="ij")
    r = 1 + 0.2 * np.sin(3 * U)
    return np.stack([r * np.cos(A), r * np.sin(A), U], axis=-1)


def surfaces():
    return {
        "LLSurface": karkas.LLSurface(height_grid(), order=2),
        "LLSurface.interpolate-2d": karkas.LLSurface.interpolate(height_grid(d=2), order=2),
        "LLSurface-closed_v": karkas.LLSurface(tube_grid()[:, :-1], order=2, closed_v=True),
        "BicubicSurface": karkas.BicubicSurface(height_grid()),
        "BicubicSurface-closed_v": karkas.BicubicSurface(tube_grid(), closed_v=True),
        "CoonsSurface": karkas.CoonsSurface(**dict(zip(("v_curves", "u_curves"), network(4, 5))), kind="gordon-spline"),
    }


def network(n, m):
    u = np.linspace(0.0, 1.0, n)
    v = np.linspace(0.0, 1.0, m)
    f = lambda a, b: np.stack([a, b, np.sin(2 * a) * np.cos(3 * b)], -1)  # noqa: E731
    return [f(np.full(m, x), v) for x in u], [f(u, np.full(n, y)) for y in v]


def surface_params(S, n=13):
    (a, b), (c, e) = S.domain_u, S.domain_v
    us = np.linspace(a, b, n, endpoint=not S.closed_u)
    vs = np.linspace(c, e, n + 2, endpoint=not S.closed_v)
    return us, vs


@pytest.mark.parametrize("name", list(surfaces()))
def test_surface_to_bspline_equals_the_surface_in_ndbspline(name):
    S = surfaces()[name]
    (tu, tv), coefs, (ku, kv) = S.to_bspline()
    assert coefs.shape == (len(tu) - ku - 1, len(tv) - kv - 1, S.dim)
    ref = NdBSpline((tu, tv), coefs, (ku, kv))
    us, vs = surface_params(S)
    U, V = np.meshgrid(us, vs, indexing="ij")
    xi = np.stack([U, V], axis=-1)
    for du, dv in [(0, 0), (1, 0), (0, 1), (1, 1), (2, 1)]:
        want = ref(xi, nu=(du, dv))
        # Rounding grows by about a factor 10 per order of differentiation beyond the first.
        atol = 1e-11 * scale(want) * 10.0 ** max(du + dv - 1, 0)
        np.testing.assert_allclose(S(us, vs, du, dv), want, rtol=0, atol=atol)
        got = S.derivative(du, dv)(us, vs)
        np.testing.assert_allclose(got, want, rtol=0, atol=atol)


def test_surface_to_bspline_equals_the_surface_in_geomdl():
    S = karkas.LLSurface(height_grid(), order=2)
    (tu, tv), coefs, (ku, kv) = S.to_bspline()
    g = GeomdlBSpline.Surface()
    g.degree_u, g.degree_v = ku, kv
    g.ctrlpts_size_u, g.ctrlpts_size_v = coefs.shape[:2]
    g.ctrlpts = coefs.reshape(-1, 3).tolist()  # v varies fastest, as in c[i, j]
    g.knotvector_u = ((tu - tu[0]) / (tu[-1] - tu[0])).tolist()
    g.knotvector_v = ((tv - tv[0]) / (tv[-1] - tv[0])).tolist()
    us, vs = surface_params(S, 7)
    su = (us - tu[0]) / (tu[-1] - tu[0])
    sv = (vs - tv[0]) / (tv[-1] - tv[0])
    got = np.array([[g.evaluate_single((a, b)) for b in sv] for a in su])
    np.testing.assert_allclose(S(us, vs), got, rtol=0, atol=1e-12 * scale(got))


def test_surface_derivative_bspline_is_the_derivative():
    S = karkas.BicubicSurface(height_grid())
    D = S.derivative(1, 2)
    (tu, tv), coefs, (ku, kv) = D.to_bspline()
    assert (ku, kv) == (2, 1)
    us, vs = surface_params(S)
    U, V = np.meshgrid(us, vs, indexing="ij")
    want = S(us, vs, 1, 2)
    got = NdBSpline((tu, tv), coefs, (ku, kv))(np.stack([U, V], -1))
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-11 * scale(want))


def test_a_surface_with_no_polynomial_form_raises_a_typed_error():
    # Lagrange blending of 15 curves: degree 14, above what converts exactly.
    S = karkas.CoonsSurface(**dict(zip(("v_curves", "u_curves"), network(15, 4))), kind="gordon")
    with pytest.raises(karkas.NoBSplineFormError, match="no exact B-spline form"):
        S.to_bspline()
    assert issubclass(karkas.NoBSplineFormError, karkas.KarkasError)
    # Inside the domain it evaluates; outside it cannot continue pieces it does not have.
    assert np.isfinite(S(0.5, 0.5)).all()
    with pytest.raises(karkas.NoBSplineFormError):
        S(-0.1, 0.5)
    assert np.isnan(S(-0.1, 0.5, extrapolate=False)).all()
