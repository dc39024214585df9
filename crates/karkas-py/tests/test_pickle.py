"""Pickling and copying of every karkas class: pickle round trips, copy.copy, copy.deepcopy,
multiprocessing (spawn and fork) and joblib (loky) give objects that evaluate bit-identically
to the original, whatever happens to the caller's arrays afterwards."""

import copy
import multiprocessing
import operator
import pickle

import numpy as np
import pytest

import karkas

RNG = np.random.default_rng(7)


def wavy(n=12, d=3):
    t = np.linspace(0.0, 3.0, n)
    cols = [t, np.sin(2 * t), np.cos(t)][:d]
    return np.column_stack(cols)


def wavy_grid(nu=6, nv=7):
    u, v = np.meshgrid(np.linspace(0, 1, nu), np.linspace(0, 2, nv), indexing="ij")
    return np.stack([u, v, np.sin(2 * u) * np.cos(v)], -1)


def torus_skeleton(m1=4, m2=6, n1=4, n2=4, R=3.0, r=1.0):
    N1, N2 = m1 * n1, m2 * n2

    def torus(p, q):
        a, b = np.broadcast_arrays(2 * np.pi * np.asarray(p) / N1, 2 * np.pi * np.asarray(q) / N2)
        return np.stack([(R + r * np.cos(a)) * np.cos(b), (R + r * np.cos(a)) * np.sin(b), r * np.sin(a)], -1)

    along = np.stack([torus(i * n1, np.arange(N2)) for i in range(m1)])
    across = np.stack([torus(np.arange(N1), j * n2) for j in range(m2)])
    return along, across


def network():
    s = np.linspace(-1.0, 1.0, 10)
    xs = s[::3]
    v = [np.column_stack([np.full_like(s, x), s, x**2 + s**3]) for x in xs]
    u = [np.column_stack([s, np.full_like(s, y), s**2 + y**3]) for y in xs]
    return u, v


def fitted():
    t = np.linspace(0.0, 1.0, 40)
    pts = np.column_stack([t, np.sin(3 * t)]) + 1e-3 * RNG.standard_normal((40, 2))
    return karkas.fit_curve(pts, knots=6, eps=0.5, pin_ends=True)


# Every class, built with options other than the defaults where it has them.
MAKERS = {
    "LLCurve": lambda: karkas.LLCurve(wavy(), order=4, closed=True),
    "LLCurve.interpolate": lambda: karkas.LLCurve.interpolate(wavy(d=2), order=2),
    "LLSurface": lambda: karkas.LLSurface(wavy_grid(), order=2, closed_v=True, interpolate=True),
    "LLCurve.within": lambda: karkas.LLCurve(wavy(), order=3, within=0.01),
    "LLSurface.within": lambda: karkas.LLSurface(wavy_grid(), order=2, closed_v=True, within=0.01),
    "CubicSpline": lambda: karkas.CubicSpline(wavy(), parameterization="centripetal", bc="natural"),
    "CubicSpline.clamped": lambda: karkas.CubicSpline(
        wavy(d=2), t=np.arange(12.0) ** 1.1, bc=("clamped", [1.0, 0.0], [0.0, -1.0])
    ),
    "HermiteSpline": fitted,
    "HermiteSpline.tolerance": lambda: karkas.fit_curve(wavy(30, 2), tolerance=1e-3),
    "HermiteSpline.new": lambda: karkas.HermiteSpline(
        [0.0, 0.4, 1.0], [[0, 0, 0], [1, 2, 0], [2, 0, 1.0]], [[1, 1, 0], [1, 0, 0], [0, -1, 1.0]]
    ),
    "BicubicSurface": lambda: karkas.BicubicSurface(wavy_grid(), parameterization="averaged"),
    "BicubicSurface.from_knots": lambda: karkas.BicubicSurface.from_knots(
        wavy_grid(), np.linspace(0, 1, 6) ** 2, np.arange(7.0)
    ),
    "DiscreteSpline": lambda: karkas.DiscreteSpline(wavy(8), order=2, n=5),
    "DiscreteSpline.interpolate": lambda: karkas.DiscreteSpline.interpolate(wavy(8, 2), order=4, n=3),
    "TubeSurface": lambda: karkas.TubeSurface(*torus_skeleton(), 4, 4, r1=3),
    "CoonsSurface": lambda: karkas.CoonsSurface(**dict(zip(("u_curves", "v_curves"), network())), kind="gordon"),
    "CoonsSurface.twists": lambda: karkas.CoonsSurface(
        **dict(zip(("u_curves", "v_curves"), network())), kind="composite",
        twists=np.full((len(network()[1]), len(network()[0]), 3), 0.1),
    ),
    "CoonsSurface.ll": lambda: karkas.CoonsSurface(
        **dict(zip(("u_curves", "v_curves"), network())), fit=("ll", 3), tolerance=1e-3
    ),
    "SectionCurve": lambda: karkas.LLSurface(wavy_grid()).section([0.0, 0.0, 1.0], 0.2)[0],
    "ImplicitSurface": lambda: karkas.ImplicitSurface("x^2 + y^2/4 + z^2 - 1"),
    "NurbsCurve": lambda: karkas.NurbsCurve(
        wavy(6), [0.0, 0.0, 0.0, 0.3, 0.5, 0.5, 1.0, 1.0, 1.0], 2, [1.0, 0.5, 2.0, 1.0, 0.7, 1.0]
    ),
    "NurbsSurface": lambda: karkas.NurbsSurface(
        wavy_grid(4, 3), [0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0], [0.0, 0.0, 1.0, 2.0, 2.0], 2, 1,
        np.linspace(0.5, 2.0, 12).reshape(4, 3), closed_u=False,
    ),
}


def evaluate(obj):
    """Everything an object computes, as arrays and numbers, for bit-for-bit comparison."""
    out = {"type": type(obj).__name__, "repr": repr(obj)}
    if isinstance(obj, karkas.Curve):
        a, b = obj.domain
        t = np.linspace(a - 0.1, b + 0.1, 57)
        out["points"] = obj(t)
        out["d1"] = obj(t, 1)
        for name in ("order", "interpolating", "within", "largest_deviation", "control_points", "knots", "values", "slopes", "weights",
                     "derivatives", "max_distance", "rms_distance", "jump_sum", "tolerance_met",
                     "parameters", "distances"):
            if hasattr(obj, name):
                out[name] = getattr(obj, name)
    elif isinstance(obj, karkas.Surface):
        (a, b), (c, d) = obj.domain_u, obj.domain_v
        u, v = np.linspace(a, b, 9), np.linspace(c, d, 11)
        out["points"] = obj(u, v)
        out["du"] = obj(u, v, 1, 0)
        for name in ("order", "interpolating", "within", "largest_deviation", "knots_u", "knots_v", "kind", "weights"):
            if hasattr(obj, name):
                out[name] = getattr(obj, name)
    elif isinstance(obj, karkas.DiscreteSpline):
        out.update(values=obj.values(), poles=obj.poles, order=obj.order, n=obj.n)
    elif isinstance(obj, karkas.TubeSurface):
        out.update(values=obj.values())
    elif isinstance(obj, karkas.SectionCurve):
        out.update(points=obj.points, params=obj.params, closed=obj.closed, length=obj.length, n=len(obj))
    elif isinstance(obj, karkas.ImplicitSurface):
        p = np.array([[0.5, 0.3, 0.2], [1.0, 1.0, 1.0]])
        out.update(expression=obj.expression, value=obj.value(p), project=obj.project(p))
    return out


def assert_identical(a, b):
    ea, eb = evaluate(a), evaluate(b)
    assert ea.keys() == eb.keys()
    for key in ea:
        x, y = ea[key], eb[key]
        if isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and x.shape == y.shape, key
            assert np.array_equal(x, y, equal_nan=True), key  # bit-identical up to NaN payloads
            assert x.tobytes() == y.tobytes() or np.isnan(x).any(), key
        elif isinstance(x, float) and np.isnan(x):
            assert np.isnan(y), key
        else:
            assert x == y, key


@pytest.fixture(params=sorted(MAKERS))
def obj(request):
    return MAKERS[request.param]()


@pytest.mark.parametrize("protocol", [2, pickle.DEFAULT_PROTOCOL, pickle.HIGHEST_PROTOCOL])
def test_pickle_round_trip_is_bit_identical(obj, protocol):
    back = pickle.loads(pickle.dumps(obj, protocol=protocol))
    assert type(back) is type(obj)
    assert back is not obj
    assert_identical(obj, back)


def test_copy_and_deepcopy(obj):
    assert_identical(obj, copy.copy(obj))
    assert_identical(obj, copy.deepcopy(obj))
    assert_identical(obj, copy.deepcopy([obj, {"k": obj}])[1]["k"])


def test_state_is_a_copy_of_the_input():
    """Changing the caller's array after construction changes neither the object nor its
    pickle."""
    pts = wavy()
    c = karkas.LLCurve(pts)
    expected = pickle.dumps(c)
    pts[:] = 0.0
    back = pickle.loads(expected)
    t = np.linspace(*c.domain, 9)
    assert np.array_equal(back(t), c(t))
    assert np.array_equal(pickle.loads(pickle.dumps(c))(t), c(t))


def test_hermite_spline_from_its_coefficients():
    """HermiteSpline(knots, values, derivatives) rebuilds a fit exactly, without the fit's
    statistics; the pickle keeps them."""
    f = fitted()
    g = karkas.HermiteSpline(f.knots, f.values, f.derivatives)
    t = np.linspace(0, 1, 101)
    assert np.array_equal(f(t), g(t))
    assert np.isnan(g.max_distance) and g.tolerance_met is None and g.parameters.size == 0
    back = pickle.loads(pickle.dumps(f))
    assert back.max_distance == f.max_distance and np.array_equal(back.distances, f.distances)
    # Cubic Hermite pieces: the midpoint of [0, 1] with values 0, 1 and slopes 1, 1 is 0.5.
    h = karkas.HermiteSpline([0.0, 1.0], [[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [1.0, 0.0]])
    np.testing.assert_allclose(h(0.5), [0.5, 0.0], atol=1e-15)
    with pytest.raises(karkas.KarkasError):
        karkas.HermiteSpline([0.0, 0.0], [[0, 0], [1, 0.0]], [[1, 0], [1, 0.0]])


def test_restore_refuses_other_names():
    with pytest.raises(karkas.KarkasError):
        karkas._restore("read_curve", ("x.csv",))


def _objects():
    return [MAKERS[name]() for name in sorted(MAKERS)]


@pytest.mark.parametrize("method", ["spawn", "fork"])
def test_multiprocessing_ships_objects_both_ways(method):
    if method not in multiprocessing.get_all_start_methods():
        pytest.skip(f"no {method} start method here")
    objs = _objects()
    ctx = multiprocessing.get_context(method)
    with ctx.Pool(2) as pool:
        back = pool.map(copy.copy, objs)
        reprs = pool.map(repr, objs)
    for a, b in zip(objs, back):
        assert_identical(a, b)
    assert reprs == [repr(o) for o in objs]


def test_multiprocessing_evaluates_in_workers():
    curves = [o for o in _objects() if isinstance(o, karkas.Curve)]
    ts = [np.linspace(*c.domain, 33) for c in curves]
    ctx = multiprocessing.get_context("spawn")
    with ctx.Pool(2) as pool:
        results = pool.starmap(operator.call if hasattr(operator, "call") else _call, zip(curves, ts))
    for c, t, r in zip(curves, ts, results):
        assert np.array_equal(c(t), r)


def _call(f, *args):
    return f(*args)


def test_joblib_loky_ships_objects_both_ways():
    joblib = pytest.importorskip("joblib")
    objs = _objects()
    back = joblib.Parallel(n_jobs=2, backend="loky")(joblib.delayed(copy.copy)(o) for o in objs)
    for a, b in zip(objs, back):
        assert_identical(a, b)
