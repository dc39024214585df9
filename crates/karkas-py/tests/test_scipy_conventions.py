"""SciPy's conventions: c(t, nu, out, extrapolate), c.derivative(nu) as a curve object,
S(u, v, du, dv, grid, out, extrapolate), S.derivative(du, dv), and one rule for parameters
outside the domain (closed: wrap; open: the end pieces continued, or NaN), checked against
SciPy's BSpline / NdBSpline on the objects' own B-spline forms."""

import pickle

import numpy as np
import pytest
from scipy.interpolate import BSpline, NdBSpline
from scipy.interpolate import CubicSpline as SciCubicSpline

import karkas


def wavy(n, d):
    s = np.linspace(0.0, 3.0, n)
    pts = np.column_stack([np.cos(s) * (1 + 0.3 * np.sin(5 * s)), np.sin(s), 0.2 * np.cos(3 * s)])
    return pts[:, :d]


def ring(n, d):
    a = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    pts = np.column_stack([np.cos(a), np.sin(a) * (1 + 0.2 * np.cos(3 * a)), 0.3 * np.sin(2 * a)])
    return pts[:, :d]


def open_curves(d):
    rng = np.random.default_rng(11)
    return {
        "LLCurve": karkas.LLCurve(wavy(15, d), order=3),
        "LLCurve.interpolate": karkas.LLCurve.interpolate(wavy(15, d), order=2),
        "CubicSpline": karkas.CubicSpline(wavy(11, d)),
        "HermiteSpline": karkas.fit_curve(wavy(60, d) + 0.01 * rng.normal(size=(60, d)), knots=7),
    }


OPEN = [(d, name) for d in (2, 3) for name in open_curves(2)]


def outside_params(c, reach=0.05):
    """Parameters below and above the domain, within `reach` of its length."""
    a, b = c.domain
    h = reach * (b - a)
    return np.r_[np.linspace(a - h, a, 9, endpoint=False), np.linspace(b, b + h, 10)[1:]]


def scale(values):
    return max(1.0, float(np.abs(values).max()))


# ---------------------------------------------------------------- calling conventions


def test_nu_is_the_second_positional_argument(wavy3d):
    c = karkas.LLCurve(wavy3d, order=3)
    t = float(np.mean(c.domain))
    d1 = c(t, 1)  # raised "out must be a float64 numpy.ndarray" before
    assert d1.shape == (3,)
    h = 1e-6
    np.testing.assert_allclose(d1, (c(t + h) - c(t - h)) / (2 * h), rtol=1e-6, atol=1e-7)
    np.testing.assert_array_equal(c(t, nu=2), c(t, 2))
    out = np.empty(3)
    assert c(t, 1, out) is out
    np.testing.assert_array_equal(out, d1)


def test_negative_orders_are_refused(wavy3d):
    c = karkas.CubicSpline(wavy3d)
    with pytest.raises(karkas.OptionError):
        c(0.5, -1)
    with pytest.raises(karkas.OptionError):
        c.derivative(-2)
    S = karkas.BicubicSurface(np.random.default_rng(1).normal(size=(4, 5, 3)))
    with pytest.raises(karkas.OptionError):
        S(0.5, 0.5, du=-1)
    with pytest.raises(karkas.OptionError):
        S.derivative(0, -1)


def test_cubic_spline_matches_scipy_including_extrapolation(wavy3d):
    t = np.linspace(0.0, 4.0, len(wavy3d))
    ours = karkas.CubicSpline(wavy3d, t=t)
    ref = SciCubicSpline(t, wavy3d)
    ts = np.linspace(-0.5, 4.5, 301)
    for nu in range(4):
        np.testing.assert_allclose(ours(ts, nu), ref(ts, nu), rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(ours.derivative(nu)(ts), ref.derivative(nu)(ts) if nu else ref(ts), rtol=1e-9, atol=1e-9)


# ---------------------------------------------------------------- derivative objects


@pytest.mark.parametrize("d,name", OPEN)
def test_derivative_objects_are_curves(d, name):
    c = open_curves(d)[name]
    ts = np.linspace(*c.domain, 50)
    for nu in (1, 2, 3):
        dc = c.derivative(nu)
        assert isinstance(dc, karkas.Curve) and isinstance(dc, karkas.CurveDerivative)
        assert dc.nu == nu and dc.parent is c
        assert dc.domain == c.domain and dc.closed == c.closed and dc.dim == d
        np.testing.assert_array_equal(dc.breakpoints, c.breakpoints)
        assert dc.continuity == max(c.continuity - nu, 0)
        np.testing.assert_array_equal(dc(ts), c(ts, nu))
        np.testing.assert_array_equal(dc(ts, 1), c(ts, nu + 1))
        np.testing.assert_array_equal(dc.derivative(1)(ts), c(ts, nu + 1))
        assert repr(dc).startswith(f"<karkas.CurveDerivative nu={nu} of {type(c).__name__}")
    assert c.derivative()(ts).shape == (50, d)  # nu defaults to 1
    np.testing.assert_array_equal(c.derivative()(ts), c(ts, 1))


def test_derivative_objects_reduce_to_the_parents_derivative(wavy3d):
    c = karkas.LLCurve(wavy3d, order=3)
    dc = c.derivative(2)
    fn, args = dc.__reduce__()
    assert args == (2,)
    again = fn(*args)
    ts = np.linspace(*c.domain, 20)
    np.testing.assert_array_equal(again(ts), dc(ts))
    try:
        pickle.dumps(c)
    except Exception:
        pytest.skip("the parent class does not pickle in this build")
    back = pickle.loads(pickle.dumps(dc))
    np.testing.assert_array_equal(back(ts), dc(ts))


def test_surface_derivative_objects(rng):
    g = rng.normal(size=(6, 7, 3))
    S = karkas.BicubicSurface(g)
    us = np.linspace(*S.domain_u, 9)
    vs = np.linspace(*S.domain_v, 8)
    D = S.derivative()
    assert isinstance(D, karkas.SurfaceDerivative) and (D.du, D.dv) == (1, 0)
    np.testing.assert_array_equal(D(us, vs), S(us, vs, 1, 0))
    D = S.derivative(1, 2)
    assert D.parent is S and D.domain_u == S.domain_u and D.closed_v == S.closed_v
    np.testing.assert_array_equal(D(us, vs, dv=1), S(us, vs, du=1, dv=3))
    np.testing.assert_array_equal(D(us[:5], vs[:5], grid=False), S(us[:5], vs[:5], 1, 2, grid=False))
    fn, args = D.__reduce__()
    assert args == (1, 2)
    np.testing.assert_array_equal(fn(*args)(us, vs), D(us, vs))
    assert repr(D).startswith("<karkas.SurfaceDerivative du=1, dv=2 of BicubicSurface")
    with pytest.raises(karkas.KarkasError):
        D.section([0.0, 0.0, 1.0], 0.0)


# ---------------------------------------------------------------- outside the domain


@pytest.mark.parametrize("d,name", OPEN)
def test_open_curves_continue_their_end_pieces_as_scipy(d, name):
    c = open_curves(d)[name]
    ref = BSpline(*c.to_bspline())  # extrapolate=True by default, as ours
    ts = outside_params(c)
    inside = np.linspace(*c.domain, 201)
    for nu in range(4):
        want = ref(ts, nu)
        # Relative to the size of the derivative over the domain (an LL curve's higher
        # derivatives vanish at its ends: there both sides are rounding noise).
        # Rounding grows about tenfold per order of differentiation beyond the first.
        atol = 1e-11 * scale(c(inside, nu)) * 10.0 ** max(nu - 1, 0)
        np.testing.assert_allclose(c(ts, nu), want, rtol=0, atol=atol)
        np.testing.assert_allclose(c(ts, nu, extrapolate=True), want, rtol=0, atol=atol)
        np.testing.assert_allclose(c.derivative(nu)(ts), want, rtol=0, atol=atol)


@pytest.mark.parametrize("d,name", OPEN)
def test_extrapolate_false_gives_nan_outside_only(d, name):
    c = open_curves(d)[name]
    a, b = c.domain
    ts = np.r_[a - 0.1, a, 0.5 * (a + b), b, b + 0.1]
    for nu in (0, 1):
        got = c(ts, nu, extrapolate=False)
        assert np.isnan(got[[0, -1]]).all()
        np.testing.assert_array_equal(got[1:-1], c(ts[1:-1], nu))
    ref = BSpline(*c.to_bspline(), extrapolate=False)
    np.testing.assert_array_equal(np.isnan(ref(ts)), np.isnan(c(ts, extrapolate=False)))


@pytest.mark.parametrize("d,name", OPEN)
def test_no_clamping_outside_the_domain(d, name):
    """Clamped parameters repeated the end point with nonzero derivatives there."""
    c = open_curves(d)[name]
    a, b = c.domain
    ts = np.linspace(a - 0.02 * (b - a), a, 5)
    pts = c(ts)
    assert len(np.unique(pts.round(12), axis=0)) == 5  # no repeated samples
    # The derivative is the derivative of the positions (finite differences agree).
    h = 1e-6 * (b - a)
    fd = (c(ts[:-1] + h) - c(ts[:-1] - h)) / (2 * h)
    np.testing.assert_allclose(c(ts[:-1], 1), fd, rtol=1e-5, atol=1e-5 * scale(fd))
    t = b + 0.01 * (b - a)
    assert np.linalg.norm(c(t) - c(b)) > 0.5 * 0.01 * (b - a) * np.linalg.norm(c(b, 1))


def test_ll_curve_sampled_past_its_domain_has_no_repeated_samples(wavy3d):
    c = karkas.LLCurve(wavy3d)
    pts = c(np.linspace(0, 1, 1000))
    assert len(np.unique(pts, axis=0)) == 1000


@pytest.mark.parametrize("d", [2, 3])
def test_closed_curves_wrap_by_the_period(d):
    for c in (
        karkas.LLCurve(ring(12, d), order=3, closed=True),
        karkas.CubicSpline(np.vstack([ring(10, d), ring(10, d)[:1]]), bc="periodic"),
    ):
        a, b = c.domain
        ts = np.linspace(a, b, 40, endpoint=False)
        for nu in (0, 1, 2):
            for shift in (-2, -1, 1, 3):
                np.testing.assert_allclose(c(ts + shift * (b - a), nu), c(ts, nu), atol=1e-9 * scale(c(ts, nu)))
            # extrapolate does not apply to closed curves: no NaN.
            assert np.isfinite(c(ts + (b - a), nu, extrapolate=False)).all()


def test_nan_parameters_stay_nan(wavy3d):
    c = karkas.CubicSpline(wavy3d)
    assert np.isnan(c(np.nan)).all()


# ---------------------------------------------------------------- surfaces outside the domain


def height_grid(nu=7, nv=6):
    u = np.linspace(0.0, 1.0, nu)
    v = np.linspace(0.0, 1.3, nv)
    U, V = np.meshgrid(u, v, indexing="ij")
    return np.stack([U + 0.1 * V, V, np.sin(2 * U) * np.cos(3 * V)], axis=-1)


@pytest.mark.parametrize("make", [
    lambda: karkas.LLSurface(height_grid(), order=2),
    lambda: karkas.BicubicSurface(height_grid()),
    lambda: karkas.LLSurface(height_grid()[..., :2], order=3),
])
def test_open_surfaces_continue_their_end_pieces_as_ndbspline(make):
    S = make()
    ref = NdBSpline(*S.to_bspline())
    (a, b), (c, e) = S.domain_u, S.domain_v
    hu, hv = 0.05 * (b - a), 0.05 * (e - c)
    us = np.r_[a - hu, a - 0.3 * hu, 0.5 * (a + b), b + 0.5 * hu, b + hu]
    vs = np.r_[c - hv, 0.3 * (c + e), e + hv]
    U, V = np.meshgrid(us, vs, indexing="ij")
    xi = np.stack([U, V], -1)
    (tu, tv), coefs, (ku, kv) = S.to_bspline()
    gap = lambda t: np.diff(t)[np.diff(t) > 0].min()  # noqa: E731
    for du, dv in [(0, 0), (1, 0), (0, 1), (1, 1)]:
        want = ref(xi, nu=(du, dv))
        # Two de Boor evaluations (SciPy's and ours) differ by rounding, relative to the
        # bound |c| (k / h)^order of a B-spline's derivative (h: the smallest knot gap).
        bound = np.abs(coefs).max() * (ku / gap(tu)) ** du * (kv / gap(tv)) ** dv
        atol = 1e-11 * max(bound, 1.0)
        np.testing.assert_allclose(S(us, vs, du, dv), want, rtol=0, atol=atol)
        np.testing.assert_allclose(S(U, V, du, dv, grid=False), want, rtol=0, atol=atol)
    # extrapolate=False: NaN exactly where u or v is outside.
    got = S(us, vs, extrapolate=False)
    outside = (U < a) | (U > b) | (V < c) | (V > e)
    assert np.isnan(got[outside]).all() and np.isfinite(got[~outside]).all()


def test_surface_closed_direction_wraps_and_open_one_extends():
    u = np.linspace(0.0, 1.0, 6)
    ang = np.linspace(0.0, 2 * np.pi, 8, endpoint=False)
    U, A = np.meshgrid(u, ang, indexing="ij")
    g = np.stack([np.cos(A) * (1 + 0.2 * U), np.sin(A) * (1 + 0.2 * U), U], -1)
    S = karkas.LLSurface(g, order=2, closed_v=True)
    (a, b), (c, e) = S.domain_u, S.domain_v
    vs = np.linspace(c, e, 9, endpoint=False)
    us = np.linspace(a, b, 5)
    np.testing.assert_allclose(S(us, vs + (e - c)), S(us, vs), atol=1e-12)
    np.testing.assert_allclose(S(us, vs - 2 * (e - c), dv=1), S(us, vs, dv=1), atol=1e-10)
    # Outside in u (open) and wrapped in v at once, as NdBSpline on one period.
    ref = NdBSpline(*S.to_bspline())
    uo = np.array([a - 0.03, b + 0.03])
    U, V = np.meshgrid(uo, vs, indexing="ij")
    want = ref(np.stack([U, V], -1))
    np.testing.assert_allclose(S(uo, vs + (e - c)), want, atol=1e-11 * scale(want))
    assert np.isnan(S(uo, vs, extrapolate=False)).all()
    assert np.isfinite(S(us, vs + (e - c), extrapolate=False)).all()


def test_surfaces_no_longer_clamp():
    S = karkas.BicubicSurface(height_grid())
    a, b = S.domain_u
    us = np.linspace(a - 0.05, a, 4)
    pts = S(us, 0.5)
    assert len(np.unique(pts.round(12), axis=0)) == 4


def test_orders_beyond_the_degree_are_zero_everywhere(wavy3d):
    rng = np.random.default_rng(5)
    for c in (karkas.LLCurve(wavy3d, order=3), karkas.CubicSpline(wavy3d)):
        a, b = c.domain
        ts = np.array([a - 0.1, 0.5 * (a + b), b + 0.1])
        for nu in (7, 200, 10**6):
            np.testing.assert_array_equal(c(ts, nu), 0.0)
            np.testing.assert_array_equal(c.derivative(nu)(ts), 0.0)
        t, coefs, k = c.derivative(10**6).to_bspline()
        assert k == 0 and not coefs.any()
    for S in (karkas.LLSurface(rng.normal(size=(5, 6, 3))), karkas.BicubicSurface(rng.normal(size=(5, 6, 3)))):
        us = np.array([-0.1, 0.5, 1.1])
        np.testing.assert_array_equal(S(us, us, 10**6, 0), 0.0)
        np.testing.assert_array_equal(S(us, us, 0, 300, grid=False), 0.0)


def test_extrapolate_must_be_a_bool(wavy3d):
    c = karkas.CubicSpline(wavy3d)
    with pytest.raises(TypeError):
        c(0.5, extrapolate="periodic")
