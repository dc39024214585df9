"""The exception classes: every karkas error is a KarkasError (a ValueError), typed by kind."""

import numpy as np
import pytest

import karkas

SUBCLASSES = [
    karkas.PointsError,
    karkas.KnotsError,
    karkas.OptionError,
    karkas.IncompatibleDataError,
    karkas.ConvergenceError,
    karkas.ExpressionError,
    karkas.FileFormatError,
]


def test_the_hierarchy_is_exported_and_rooted_in_value_error():
    assert issubclass(karkas.KarkasError, ValueError)
    assert "KarkasError" in karkas.__all__
    for cls in SUBCLASSES:
        assert issubclass(cls, karkas.KarkasError) and cls is not karkas.KarkasError
        assert cls.__module__ == "karkas" and cls.__name__ in karkas.__all__
        assert cls.__doc__
    assert "ValueError" in karkas.KarkasError.__doc__


ZIGZAG = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])


def _crossing_missed():
    """The edges of the unit square as two v-curves and two u-curves, the last corner of the
    second u-curve lifted off the second v-curve."""
    s = np.linspace(0.0, 1.0, 3)
    zero, one = np.zeros(3), np.ones(3)
    v = [np.column_stack([zero, s, zero]), np.column_stack([one, s, zero])]
    u = [np.column_stack([s, zero, zero]), np.column_stack([s, one, [0.0, 0.0, 0.5]])]
    return v, u


@pytest.mark.parametrize(
    "cls, make, message",
    [
        (karkas.PointsError, lambda: karkas.LLCurve(np.zeros((2, 2))), "at least 3 points"),
        (karkas.PointsError, lambda: karkas.LLCurve([[0, 0], [1, np.nan], [2, 0]]), "finite"),
        (karkas.PointsError, lambda: karkas.LLCurve(np.zeros((5, 4))), "2 or 3 coordinates"),
        (karkas.PointsError, lambda: karkas.curve_parameters(np.zeros((3, 2))), "coincid"),
        (karkas.KnotsError, lambda: karkas.CubicSpline(ZIGZAG, t=[0.0, 2.0, 1.0, 3.0]), "knot 2"),
        (
            karkas.KnotsError,
            lambda: karkas.fit_curve(np.column_stack([np.linspace(0, 1, 20), np.zeros(20)]), knots=[0.0, 0.6, 0.4, 1.0]),
            "knot",
        ),
        (karkas.OptionError, lambda: karkas.LLCurve(np.eye(3), order=0), "order"),
        (karkas.OptionError, lambda: karkas.CubicSpline(np.eye(3), bc="quadratic"), "unknown bc"),
        (karkas.OptionError, lambda: karkas.DiscreteSpline(np.eye(3), n=1), "step"),
        (karkas.IncompatibleDataError, lambda: karkas.vary(np.eye(2), [1.0, 1.0], [1.0, 2.0]), "sums"),
        (karkas.IncompatibleDataError, lambda: karkas.CoonsSurface(**dict(zip(("v_curves", "u_curves"), _crossing_missed())), kind="bilinear"), "u-curve 1"),
        (
            karkas.ConvergenceError,
            lambda: karkas.ImplicitSurface("x^2 + y^2 + z^2 + 1").project([[1.0, 2.0, 3.0]]),
            "no surface",
        ),
        (
            karkas.ConvergenceError,
            lambda: karkas.ImplicitSurface("x^2 + y^2 - z^2").curvatures([0.0, 0.0, 0.0]),
            "gradient",
        ),
        (karkas.ExpressionError, lambda: karkas.ImplicitSurface("x^2 + * y"), "character"),
    ],
)
def test_each_kind_of_mistake_raises_its_class(cls, make, message):
    with pytest.raises(cls, match=message) as caught:
        make()
    assert isinstance(caught.value, karkas.KarkasError)
    assert isinstance(caught.value, ValueError)
    with pytest.raises(ValueError):
        make()
    with pytest.raises(karkas.KarkasError):
        make()


def test_the_same_knot_mistake_is_one_class_everywhere():
    pts = np.column_stack([np.linspace(0, 1, 20), np.sin(np.linspace(0, 1, 20))])
    for make in [
        lambda: karkas.CubicSpline(ZIGZAG, t=[0.0, 2.0, 1.0, 3.0]),
        lambda: karkas.fit_curve(pts, knots=[0.0, 0.6, 0.4, 1.0]),
        lambda: karkas.BicubicSurface.from_knots(np.ones((4, 3, 3)), [0.0, 2.0, 1.0, 3.0], [0.0, 1.0, 2.0]),
    ]:
        with pytest.raises(karkas.KnotsError):
            make()


def test_binding_errors_are_karkas_errors_too():
    c = karkas.LLCurve(np.eye(3))
    with pytest.raises(karkas.KarkasError, match="shape"):
        c(np.linspace(*c.domain, 10), out=np.empty((10, 2)))
    with pytest.raises(karkas.OptionError, match="not both"):
        karkas.fit_curve(np.eye(3)[:, :2], knots=4, tolerance=1e-3)


def test_file_errors_are_os_errors_not_value_errors(tmp_path):
    with pytest.raises(FileNotFoundError) as caught:
        karkas.export_obj(tmp_path / "missing" / "s.obj", np.zeros((3, 3, 3)))
    assert not isinstance(caught.value, ValueError)
    assert "s.obj" in str(caught.value)
