"""Every array argument of every constructor, function and evaluator is read by its values,
whatever form it comes in: C or Fortran order, a strided or reversed view, a read-only array,
a nested Python list, integers, booleans or float32 holding the same numbers. Each form must
give exactly the result of the C-ordered float64 array. Complex numbers raise TypeError
(never a silent cast dropping the imaginary part), and so do strings and dates.

The data are dyadic (multiples of 1/64), so that float32, and integers where the values are
whole, hold them exactly."""

import numpy as np
import pytest

import karkas


def dyadic(a):
    return np.round(np.asarray(a, dtype=np.float64) * 64) / 64


def forms(a):
    """(label, array-like) pairs that all hold the values of the float64 array `a`."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    out = [("fortran", np.asfortranarray(a)), ("list", a.tolist())]
    wide = np.zeros(a.shape[:-1] + (2 * a.shape[-1],)) if a.ndim else None
    if a.ndim:
        wide[..., ::2] = a
        out.append(("strided", wide[..., ::2]))
        out.append(("reversed", np.ascontiguousarray(a[::-1])[::-1]))
    ro = a.copy()
    ro.flags.writeable = False
    out.append(("read-only", ro))
    out.append(("float32", a.astype(np.float32)))
    if np.all(a == np.round(a)):
        out.append(("int64", a.astype(np.int64)))
        out.append(("uint16", a.astype(np.uint16)) if np.all(a >= 0) else ("int32", a.astype(np.int32)))
        if np.all((a == 0) | (a == 1)):
            out.append(("bool", a.astype(bool)))
    for label, f in out:
        np.testing.assert_array_equal(np.asarray(f, dtype=np.float64), a, err_msg=label)
    return out


# -- Data ------------------------------------------------------------------------------------

S = np.linspace(0.0, 3.0, 24)
PTS3 = dyadic(np.column_stack([np.cos(S) * (1 + 0.2 * S), np.sin(S), 0.3 * np.cos(2 * S)]))
PTS2 = dyadic(PTS3[:, :2])
INT_PTS = np.column_stack([np.arange(12.0), (np.arange(12.0) - 5) ** 2, np.arange(12.0) % 3])
U, V = np.meshgrid(np.linspace(0, 1, 6), np.linspace(0, 2, 7), indexing="ij")
GRID = dyadic(np.stack([U, V, np.sin(2 * U) * np.cos(V)], axis=-1))
T = dyadic(np.linspace(0.3, 0.6, 9))
UU, VV = dyadic(np.linspace(0.3, 0.6, 4)), dyadic(np.linspace(0.3, 0.6, 5))
SPHERE = np.array([[2.0, 0.125, 0.25], [0.125, 2.125, 0.0], [0.0, 0.375, -1.875]])


def torus_skeleton(m1=4, m2=6, n1=4, n2=4, R=3.0, r=1.0):
    N1, N2 = m1 * n1, m2 * n2

    def torus(p, q):
        a, b = np.broadcast_arrays(2 * np.pi * np.asarray(p) / N1, 2 * np.pi * np.asarray(q) / N2)
        return np.stack([(R + r * np.cos(a)) * np.cos(b), (R + r * np.cos(a)) * np.sin(b), r * np.sin(a)], -1)

    along = np.stack([torus(i * n1, np.arange(N2)) for i in range(m1)])
    across = np.stack([torus(np.arange(N1), j * n2) for j in range(m2)])
    return along, across


ALONG, ACROSS = (dyadic(a) for a in torus_skeleton())
NET_S = np.linspace(0.0, 1.0, 5)
V_CURVE = np.column_stack([np.full(5, 0.5), NET_S, 0.25 + NET_S**2])
LL = karkas.LLCurve(PTS3, order=3)
SURF = karkas.LLSurface(GRID, order=3)
IMPLICIT = karkas.ImplicitSurface("x^2 + y^2 + z^2 - 4")


def network(v1):
    xs = ys = np.linspace(0.0, 1.0, 3)
    v = [np.column_stack([np.full_like(NET_S, x), NET_S, x**2 + NET_S**2]) for x in xs]
    u = [np.column_stack([NET_S, np.full_like(NET_S, y), NET_S**2 + y**2]) for y in ys]
    v[1] = v1
    return v, u


# Each case: (name, the arguments in C-ordered float64, f(*arguments) -> an array to compare).
CASES = [
    ("LLCurve", [PTS3], lambda p: karkas.LLCurve(p, order=3)(T)),
    ("LLCurve 2-D", [PTS2], lambda p: karkas.LLCurve(p, order=3, closed=True)(T)),
    ("LLCurve.interpolate", [PTS3], lambda p: karkas.LLCurve.interpolate(p, order=3)(T)),
    ("CubicSpline", [PTS3], lambda p: karkas.CubicSpline(p)(T)),
    ("CubicSpline t", [INT_PTS, np.arange(12.0)], lambda p, t: karkas.CubicSpline(p, t=t)(T)),
    ("fit_curve", [PTS3], lambda p: karkas.fit_curve(p, knots=6)(T)),
    ("fit_curve knots", [dyadic(np.linspace(0, 1, 6))], lambda k: karkas.fit_curve(PTS3, knots=k)(T)),
    ("curve_parameters", [INT_PTS], lambda p: karkas.curve_parameters(p)),
    ("Curve.__call__", [T], lambda t: LL(t)),
    ("Curve.__call__ nu=2", [T], lambda t: LL(t, 2)),
    ("LLSurface", [GRID], lambda g: karkas.LLSurface(g, order=3)(UU, VV)),
    ("LLSurface.interpolate", [GRID], lambda g: karkas.LLSurface.interpolate(g, order=3)(UU, VV)),
    ("BicubicSurface", [GRID], lambda g: karkas.BicubicSurface(g)(UU, VV)),
    (
        "BicubicSurface.from_knots",
        [GRID, np.arange(6.0), np.arange(7.0)],
        lambda g, ku, kv: karkas.BicubicSurface.from_knots(g, ku, kv)(UU, VV),
    ),
    ("grid_parameters", [GRID], lambda g: np.concatenate(karkas.grid_parameters(g))),
    ("Surface.__call__", [UU, VV], lambda u, v: SURF(u, v)),
    ("Surface.__call__ grid=False", [UU, UU[::-1]], lambda u, v: SURF(u, v, grid=False)),
    ("Surface.__call__ du=dv=1", [UU, VV], lambda u, v: SURF(u, v, 1, 1)),
    (
        "Surface.section",
        [np.array([0.0, 0.0, 1.0])],
        lambda n: np.concatenate([c.points for c in SURF.section(n, 0.125)]),
    ),
    ("CoonsSurface", [V_CURVE], lambda c: karkas.CoonsSurface(**dict(zip(("v_curves", "u_curves"), network(c))))(UU, VV)),
    ("DiscreteSpline", [INT_PTS], lambda p: karkas.DiscreteSpline(p, order=2, n=4).values()),
    ("DiscreteSpline.interpolate", [PTS3[:8]], lambda p: karkas.DiscreteSpline.interpolate(p, order=2, n=4).values()),
    ("TubeSurface", [ALONG, ACROSS], lambda a, b: karkas.TubeSurface(a, b, 4, 4, 2, 2).values()),
    ("vary", [np.ones((3, 4)), np.full(3, 5.0), np.full(4, 3.75)], lambda m, r, c: karkas.vary(m, r, c)),
    ("ImplicitSurface.value", [SPHERE], lambda p: IMPLICIT.value(p)),
    ("ImplicitSurface.gradient", [SPHERE], lambda p: IMPLICIT.gradient(p)),
    ("ImplicitSurface.project", [SPHERE], lambda p: IMPLICIT.project(p)),
    ("ImplicitSurface.curvatures", [np.array([2.0, 0.0, 0.0])], lambda p: IMPLICIT.curvatures(p)["normal"]),
    (
        "ImplicitSurface.trace_net",
        [np.array([2.0, 0.0, 0.0])],
        lambda p: IMPLICIT.trace_net(p, (3, 3), (0.125, 0.125), directions="turned", substeps=4),
    ),
    ("hausdorff", [PTS3, INT_PTS], lambda a, b: np.array(karkas.hausdorff(a, b)["distance"])),
    (
        "hausdorff_to_implicit",
        [np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 2.0, 1.0], [1.0, 2.0, 1.0]])],
        lambda p: np.array(
            karkas.hausdorff_to_implicit(SURF, karkas.ImplicitSurface("z - 1"), p, samples=(6, 6))["distance"]
        ),
    ),
]


def _params():
    for name, args, f in CASES:
        for i in range(len(args)):
            yield pytest.param(name, args, f, i, id=f"{name}-arg{i}")


@pytest.mark.parametrize("name, args, f, i", list(_params()))
def test_every_form_of_an_array_argument_gives_the_same_result(name, args, f, i):
    expected = np.asarray(f(*args))
    assert np.all(np.isfinite(expected))
    for label, form in forms(args[i]):
        got = f(*(args[:i] + [form] + args[i + 1 :]))
        np.testing.assert_array_equal(np.asarray(got), expected, err_msg=f"{name}: argument {i} as {label}")


@pytest.mark.parametrize("name, args, f, i", list(_params()))
def test_complex_strings_and_dates_raise_type_error(name, args, f, i):
    a = np.asarray(args[i])
    for bad in (a + 1j, a.astype(np.complex64), a.astype(str), np.zeros(a.shape, dtype="datetime64[s]")):
        with pytest.raises(TypeError):
            f(*(args[:i] + [bad] + args[i + 1 :]))


@pytest.mark.parametrize("name, args, f, i", list(_params()))
def test_an_argument_whose_array_raises_propagates_its_error(name, args, f, i):
    class Refused(Exception):
        pass

    class Hostile:
        def __array__(self, dtype=None, copy=None):
            raise Refused("no")

        def __len__(self):
            raise Refused("no")

        def __iter__(self):
            raise Refused("no")

    with pytest.raises((Refused, TypeError, ValueError)):
        f(*(args[:i] + [Hostile()] + args[i + 1 :]))


def test_exports_read_every_form(tmp_path):
    written = {}
    for label, form in [("c", GRID)] + forms(GRID):
        karkas.export_obj(tmp_path / f"{label}.obj", form)
        karkas.export_surface_csv(tmp_path / f"{label}.csv", np.arange(6.0), np.arange(7.0), form)
        written[label] = ((tmp_path / f"{label}.obj").read_text(), (tmp_path / f"{label}.csv").read_text())
    for label, text in written.items():
        assert text == written["c"], label
    for label, form in [("c", PTS3)] + forms(PTS3):
        karkas.export_curve_csv(tmp_path / f"k{label}.csv", np.arange(24.0), form)
        assert (tmp_path / f"k{label}.csv").read_text() == (tmp_path / "kc.csv").read_text(), label


def test_a_tube_reads_every_layout_of_its_skeleton():
    expected = karkas.TubeSurface(ALONG, ACROSS, 4, 4, 2, 2).values()
    for a in (np.asfortranarray(ALONG), ALONG[:, ::-1][:, ::-1], np.asfortranarray(ALONG).T.T):
        np.testing.assert_array_equal(karkas.TubeSurface(a, ACROSS, 4, 4, 2, 2).values(), expected)
    for b in (np.asfortranarray(ACROSS), ACROSS.transpose(1, 0, 2).transpose(1, 0, 2)):
        np.testing.assert_array_equal(karkas.TubeSurface(ALONG, b, 4, 4, 2, 2).values(), expected)


# -- out= ------------------------------------------------------------------------------------


def _outs():
    return [
        ("Curve.__call__", lambda out: LL(T, out=out), (9, 3)),
        ("Curve.__call__ nu=1", lambda out: LL(T, 1, out=out), (9, 3)),
        ("Surface.__call__", lambda out: SURF(UU, VV, out=out), (4, 5, 3)),
        ("Surface.__call__ du=1", lambda out: SURF(UU, VV, 1, 0, out=out), (4, 5, 3)),
        ("DiscreteSpline.values", lambda out: karkas.DiscreteSpline(PTS3[:8], 2, 4).values(out=out), (32, 3)),
    ]


@pytest.mark.parametrize("name, call, shape", _outs(), ids=[o[0] for o in _outs()])
def test_out_is_filled_and_returned(name, call, shape):
    out = np.full(shape, np.nan)
    assert call(out) is out
    np.testing.assert_array_equal(out, call(None))


@pytest.mark.parametrize("name, call, shape", _outs(), ids=[o[0] for o in _outs()])
def test_a_wrong_out_raises_type_or_value_error(name, call, shape):
    read_only = np.zeros(shape)
    read_only.flags.writeable = False
    wrong = [
        (TypeError, "numpy.ndarray", np.zeros(shape).tolist()),
        (TypeError, "numpy.ndarray", "out"),
        (TypeError, "float64", np.zeros(shape, dtype=np.float32)),
        (TypeError, "float64", np.zeros(shape, dtype=np.int64)),
        (TypeError, "float64", np.zeros(shape, dtype=complex)),
        (ValueError, "shape", np.zeros(shape[:-1] + (shape[-1] + 1,))),
        (ValueError, "shape", np.zeros(shape[::-1])),
        (ValueError, "C-contiguous", np.zeros(shape[::-1]).T),
        (ValueError, "C-contiguous", np.zeros(shape[:-1] + (2 * shape[-1],))[..., ::2]),
        (ValueError, "read-only", read_only),
    ]
    for error, message, out in wrong:
        before = np.array(out, copy=True) if isinstance(out, np.ndarray) else None
        with pytest.raises(error, match=message):
            call(out)
        if before is not None:
            np.testing.assert_array_equal(out, before)
