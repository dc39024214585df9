"""Curves: SciPy cross-checks, LL curve properties, shapes, out=, errors."""

import numpy as np
import pytest
from scipy.interpolate import CubicSpline as SciCubicSpline
from scipy.interpolate import make_interp_spline

import karkas


def chord_parameters(points):
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    return np.concatenate([[0.0], np.cumsum(steps)])


# ---------------------------------------------------------------- cubic splines vs SciPy


@pytest.mark.parametrize("bc", ["not-a-knot", "natural"])
def test_cubic_spline_matches_scipy_on_given_parameters(wavy3d, rng, bc):
    t = np.sort(rng.uniform(0.0, 5.0, len(wavy3d)))
    ours = karkas.CubicSpline(wavy3d, t=t, bc=bc)
    ref = SciCubicSpline(t, wavy3d, bc_type=bc)
    ts = np.linspace(t[0], t[-1], 1001)
    np.testing.assert_allclose(ours(ts), ref(ts), rtol=0, atol=1e-11)
    for k in (1, 2, 3):
        np.testing.assert_allclose(ours(ts, k), ref(ts, k), rtol=1e-9, atol=1e-7)


def test_cubic_spline_matches_make_interp_spline_with_chord_parameters(wavy3d):
    ours = karkas.CubicSpline(wavy3d)  # chord length, not-a-knot
    t = chord_parameters(wavy3d)
    np.testing.assert_allclose(ours.knots, t, rtol=0, atol=1e-13)
    ref = make_interp_spline(t, wavy3d, k=3)  # not-a-knot by default
    ts = np.linspace(0.0, t[-1], 777)
    np.testing.assert_allclose(ours(ts), ref(ts), rtol=0, atol=1e-11)


def test_cubic_spline_periodic_matches_scipy(circle2d):
    closed = np.vstack([circle2d, circle2d[:1]])
    t = chord_parameters(closed)
    ours = karkas.CubicSpline(circle2d, bc="periodic")
    assert ours.closed
    ref = SciCubicSpline(t, closed, bc_type="periodic")
    ts = np.linspace(0.0, t[-1], 500)
    np.testing.assert_allclose(ours(ts), ref(ts), rtol=0, atol=1e-12)
    # Wraps by its period.
    np.testing.assert_allclose(ours(ts[:50] + t[-1]), ref(ts[:50]), rtol=0, atol=1e-12)


def test_cubic_spline_clamped_matches_scipy(wavy3d):
    t = np.arange(len(wavy3d), dtype=float)
    d0, d1 = np.array([1.0, 0.0, 0.5]), np.array([0.0, -1.0, 2.0])
    ours = karkas.CubicSpline(wavy3d, t=t, bc=("clamped", d0, d1))
    ref = SciCubicSpline(t, wavy3d, bc_type=((1, d0), (1, d1)))
    ts = np.linspace(0, t[-1], 300)
    np.testing.assert_allclose(ours(ts), ref(ts), rtol=0, atol=1e-12)


def test_cubic_spline_uniform_and_centripetal_parameters(wavy3d):
    u = karkas.CubicSpline(wavy3d, parameterization="uniform")
    np.testing.assert_array_equal(u.knots, np.arange(len(wavy3d), dtype=float))
    c = karkas.CubicSpline(wavy3d, parameterization="centripetal")
    steps = np.sqrt(np.linalg.norm(np.diff(wavy3d, axis=0), axis=1))
    np.testing.assert_allclose(c.knots, np.concatenate([[0], np.cumsum(steps)]), atol=1e-13)
    np.testing.assert_allclose(c(c.knots), wavy3d, atol=1e-12)


# ---------------------------------------------------------------- LL curves


def test_open_ll_curve_passes_through_its_end_points(wavy3d):
    for order in (1, 3, 5, 8):
        c = karkas.LLCurve(wavy3d, order=order)
        a, b = c.domain
        np.testing.assert_allclose(c(a), wavy3d[0], atol=1e-14)
        np.testing.assert_allclose(c(b), wavy3d[-1], atol=1e-14)
        assert c.order == order and c.dim == 3 and not c.closed


def test_interpolating_ll_curve_passes_through_every_point(wavy3d):
    c = karkas.LLCurve.interpolate(wavy3d, order=5)
    k = len(wavy3d)
    nodes = np.arange(1, k + 1) / (k + 1)
    np.testing.assert_allclose(c(nodes), wavy3d, atol=1e-12)
    assert isinstance(c, karkas.LLCurve) and isinstance(c, karkas.Curve)
    assert c.interpolating


def test_closed_ll_curve_is_periodic(circle2d):
    c = karkas.LLCurve(circle2d, order=4, closed=True)
    assert c.closed
    a, b = c.domain
    ts = np.linspace(a, b, 50)
    np.testing.assert_allclose(c(ts + (b - a)), c(ts), atol=1e-12)
    np.testing.assert_allclose(c(a), c(b), atol=1e-12)


def test_ll_derivative_matches_finite_differences(wavy3d):
    c = karkas.LLCurve(wavy3d, order=5)
    a, b = c.domain
    ts = np.linspace(a + 0.01, b - 0.01, 37)
    h = 1e-6
    fd = (c(ts + h) - c(ts - h)) / (2 * h)
    np.testing.assert_allclose(c(ts, 1), fd, rtol=1e-5, atol=1e-6)
    fd2 = (c(ts + h, 1) - c(ts - h, 1)) / (2 * h)
    np.testing.assert_allclose(c(ts, nu=2), fd2, rtol=1e-4, atol=1e-4)


def test_ll_breakpoints_and_control_points(wavy3d):
    c = karkas.LLCurve(wavy3d, order=3)
    bp = c.breakpoints
    assert bp[0] == pytest.approx(c.domain[0]) and bp[-1] == pytest.approx(c.domain[1])
    assert np.all(np.diff(bp) > 0)
    np.testing.assert_array_equal(c.control_points, wavy3d)


# ---------------------------------------------------------------- shapes and out=


def test_shapes_follow_the_parameters(wavy3d):
    c = karkas.LLCurve(wavy3d)
    a, b = c.domain
    assert c(0.5 * (a + b)).shape == (3,)
    assert c(np.float64(0.5)).shape == (3,)
    assert c(np.linspace(a, b, 7)).shape == (7, 3)
    assert c(np.linspace(a, b, 12).reshape(3, 4)).shape == (3, 4, 3)
    assert c([a, b]).shape == (2, 3)  # lists work
    assert c(np.array([1, 0])).shape == (2, 3)  # integer arrays are converted
    assert c(np.empty(0)).shape == (0, 3)
    grid = np.linspace(a, b, 12).reshape(3, 4)
    np.testing.assert_array_equal(c(grid).reshape(12, 3), c(grid.ravel()))
    # Non-contiguous parameters give the same result.
    ts = np.linspace(a, b, 20)
    np.testing.assert_array_equal(c(ts[::2]), c(ts)[::2])
    assert c.sample(11).shape == (11, 3)


def test_out_is_written_in_place_and_returned(wavy3d):
    c = karkas.LLCurve(wavy3d)
    ts = np.linspace(*c.domain, 100)
    out = np.full((100, 3), np.nan)
    r = c(ts, out=out)
    assert r is out
    np.testing.assert_array_equal(out, c(ts))
    d = c(ts, 1, out=out)
    assert d is out
    np.testing.assert_array_equal(out, c(ts, 1))


def test_large_evaluation_releases_the_gil_and_matches_small_batches(wavy3d):
    c = karkas.LLCurve(wavy3d)
    ts = np.linspace(*c.domain, 100_000)
    big = c(ts)
    small = np.vstack([c(ts[i:i + 1000]) for i in range(0, len(ts), 1000)])
    np.testing.assert_array_equal(big, small)


@pytest.mark.parametrize(
    "out, message",
    [
        (np.empty((10, 2)), "shape"),
        (np.empty((3, 10)).T, "contiguous"),
    ],
)
def test_bad_out_raises_value_error(wavy3d, out, message):
    c = karkas.LLCurve(wavy3d)
    with pytest.raises(ValueError, match=message):
        c(np.linspace(*c.domain, 10), out=out)


@pytest.mark.parametrize(
    "out, message",
    [
        (np.empty((10, 3), dtype=np.float32), "float64"),
        ([[0.0] * 3] * 10, "float64"),
    ],
)
def test_out_of_a_wrong_type_raises_type_error(wavy3d, out, message):
    c = karkas.LLCurve(wavy3d)
    with pytest.raises(TypeError, match=message):
        c(np.linspace(*c.domain, 10), out=out)


def test_read_only_out_raises_value_error(wavy3d):
    c = karkas.LLCurve(wavy3d)
    out = np.empty((10, 3))
    out.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        c(np.linspace(*c.domain, 10), out=out)


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: karkas.LLCurve(np.zeros((2, 2))), "at least 3 points"),
        (lambda: karkas.LLCurve(np.zeros((5, 4))), "2 or 3 coordinates"),
        (lambda: karkas.LLCurve(np.zeros(5)), "2-D float array"),
        (lambda: karkas.LLCurve([[0, 0], [1, np.nan], [2, 0]]), "finite"),
        (lambda: karkas.LLCurve(np.eye(3), order=0), "order"),
        (lambda: karkas.LLCurve(np.eye(3), order=-2), "order"),
        (lambda: karkas.LLCurve(np.eye(3), order=65), "order"),
        (lambda: karkas.CubicSpline(np.eye(3), bc="quadratic"), "unknown bc"),
        (lambda: karkas.CubicSpline(np.eye(3), parameterization="arc"), "parameterization"),
        (lambda: karkas.CubicSpline(np.eye(3), t=[0.0, 2.0, 1.0]), "greater than the knot before"),
        (lambda: karkas.CubicSpline(np.eye(3), t=[0.0, 1.0]), "knots"),
        (lambda: karkas.CubicSpline([[0, 0], [0, 0], [1, 1]]), "coincid"),
    ],
)
def test_bad_input_raises_value_error_with_the_library_message(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_reprs_say_what_the_object_is(wavy3d, circle2d):
    r = repr(karkas.LLCurve(circle2d, order=4, closed=True))
    assert r.startswith("<karkas.LLCurve") and "order=4" in r and "closed=True" in r
    assert "24 points in 2-D" in r and "domain=" in r
    assert "interpolating" in repr(karkas.LLCurve.interpolate(wavy3d))
    assert "not-a-knot" in repr(karkas.CubicSpline(wavy3d))
    assert karkas.__version__.count(".") == 2


# ---------------------------------------------------------------- fitting


def test_fit_curve_recovers_a_smooth_curve(rng):
    s = np.linspace(0.0, 1.0, 200)
    truth = np.column_stack([s, 0.3 * np.sin(2 * np.pi * s)])
    noisy = truth + rng.normal(0.0, 1e-4, truth.shape)
    f = karkas.fit_curve(noisy, knots=9)
    assert isinstance(f, karkas.HermiteSpline)
    assert f.domain == (0.0, 1.0)
    assert len(f.knots) == 9
    assert f.max_distance < 1e-3 and f.rms_distance <= f.max_distance
    assert f.distances.shape == (200,) and f.parameters.shape == (200,)
    np.testing.assert_allclose(f.max_distance, f.distances.max())
    # The fitted curve at the foot parameters is within the reported distances.
    dist = np.linalg.norm(f(f.parameters) - noisy, axis=1)
    np.testing.assert_allclose(dist, f.distances, atol=1e-12)


def test_fit_curve_by_tolerance_meets_it():
    s = np.linspace(0.0, 1.0, 300)
    pts = np.column_stack([s, 0.2 * np.sin(6 * s)])
    f = karkas.fit_curve(pts, tolerance=1e-4)
    assert f.tolerance_met is True
    assert f.max_distance <= 1e-4


def test_fit_curve_needs_knots_or_tolerance():
    pts = np.column_stack([np.linspace(0, 1, 20), np.zeros(20)])
    with pytest.raises(ValueError, match="knots or"):
        karkas.fit_curve(pts)
    with pytest.raises(ValueError, match="not both"):
        karkas.fit_curve(pts, knots=4, tolerance=1e-3)
    with pytest.raises(ValueError):
        karkas.fit_curve(pts, knots=[0.0, 0.7, 0.5, 1.0])


def test_fit_penalty_rules():
    """The active bound meets eps with equality (to 1e-3); the paper's rule p = H(q*)/eps
    (times 10 until the bound holds) stays below it, with a larger penalty."""
    a = np.linspace(0.0, 2.0, 30)
    wobble = 1.0 + 0.003 * ((np.arange(30) * 7919) % 13) / 13.0
    pts = np.column_stack([np.cos(a), np.sin(a)]) * wobble[:, None]
    knots, eps = [0.0, 0.3, 0.5, 0.7, 1.0], 1e-4
    active = karkas.fit_curve(pts, knots=knots, eps=eps)
    paper = karkas.fit_curve(pts, knots=knots, eps=eps, penalty="paper")
    assert (1.0 - 1e-3) * eps <= active.jump_sum <= eps
    assert paper.jump_sum <= eps and paper.jump_sum < active.jump_sum
    with pytest.raises(karkas.OptionError, match="penalty must be 'active' or 'paper'"):
        karkas.fit_curve(pts, knots=5, penalty="soft")


def test_fit_starts_keep_a_sound_fit_no_worse_than_one_start():
    """starts=N keeps the sound fit with the smallest sum of squared distances; bad counts
    and starts without given knots raise OptionError."""
    t = np.linspace(0.0, 2.0 * np.pi, 16)
    pts = np.column_stack([0.5 * (1 + np.cos(t)), 0.06 * np.sin(t) * (1 + 0.5 * np.cos(t))])
    one = karkas.fit_curve(pts, knots=6)
    many = karkas.fit_curve(pts, knots=6, starts=8)
    assert np.sum(many.distances**2) <= np.sum(one.distances**2) * (1 + 1e-12)
    assert not any("cross" in str(w) for w in many.warnings)
    for bad in (dict(knots=6, starts=0), dict(knots=6, starts=9), dict(tolerance=1e-3, starts=2), dict(knots=6, closed=True, starts=2)):
        with pytest.raises(karkas.OptionError):
            karkas.fit_curve(pts, **bad)
