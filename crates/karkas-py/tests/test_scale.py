"""Every method at every scale from Python: data times s in 1e-150..1e150 give s times the unit
result (the fit on given knots to 1e-9: on exact points it settles to about 3e-10 of the size);
the fit on given knots and in tolerance mode exactly at power-of-two scales; coordinates past 1e152 or
below 1e-152 raise karkas.PointsError saying they are out of range (docs/reference/bad-input.md, "Scale")."""

import numpy as np
import pytest

import karkas

T = np.linspace(0.0, 2.8, 15)
POINTS = np.column_stack([np.cos(3 * T) * (1 + 0.3 * T), np.sin(2 * T) + 0.2 * T, 0.1 * T * T])
U, V = np.meshgrid(np.arange(7.0), np.arange(9.0), indexing="ij")
GRID = np.stack([0.3 * U, 0.2 * V + 0.01 * U * U, np.sin(0.4 * U) * np.cos(0.3 * V)], axis=-1)
SAMPLES = np.linspace(0.0, 1.0, 57)


def close(scaled, unit, s, tol=1e-12):
    scaled, unit = np.asarray(scaled), np.asarray(unit)
    size = np.max(np.abs(unit))
    assert np.max(np.abs(scaled / s - unit)) <= tol * size


@pytest.mark.parametrize("s", [1e-150, 3.7e-77, 2.9e41, 1e150])
def test_curves_and_surfaces_are_scale_equivariant(s):
    for make in (
        lambda p: karkas.LLCurve(p, order=3),
        lambda p: karkas.LLCurve(p, order=3, interpolate=True),
        lambda p: karkas.CubicSpline(p, parameterization="uniform"),
    ):
        close(make(POINTS * s)(SAMPLES), make(POINTS)(SAMPLES), s)
    fit = lambda p: karkas.fit_curve(p, knots=5)
    close(fit(POINTS * s)(SAMPLES), fit(POINTS)(SAMPLES), s, tol=1e-9)
    for make in (lambda g: karkas.LLSurface(g), lambda g: karkas.BicubicSurface(g, parameterization="uniform")):
        unit, scaled = make(GRID), make(GRID * s)
        u0, u1 = unit.domain_u
        v0, v1 = unit.domain_v
        uu, vv = np.linspace(u0, u1, 11), np.linspace(v0, v1, 13)
        close(scaled(uu, vv), unit(uu, vv), s)


@pytest.mark.parametrize("exponent", [-498, -300, 0, 200, 498])
def test_the_tolerance_mode_is_exactly_equivariant_at_powers_of_two(exponent):
    s = 2.0**exponent
    unit = karkas.fit_curve(POINTS, tolerance=1e-3)
    scaled = karkas.fit_curve(POINTS * s, tolerance=1e-3 * s)
    assert np.array_equal(scaled.knots, unit.knots)
    close(karkas.fit_curve(POINTS * s, knots=5)(SAMPLES), karkas.fit_curve(POINTS, knots=5)(SAMPLES), s)
    assert np.array_equal(scaled(SAMPLES) / s, unit(SAMPLES))
    assert scaled.max_distance / s == unit.max_distance


@pytest.mark.parametrize("s, words", [(2e152, "above 1e152"), (1e-153, "below 1e-152"), (1e300, "above 1e152")])
def test_coordinates_out_of_range_raise_points_error(s, words):
    for make in (lambda: karkas.LLCurve(POINTS * s), lambda: karkas.fit_curve(POINTS * s, knots=5),
                 lambda: karkas.BicubicSurface(GRID * s)):
        with pytest.raises(karkas.PointsError, match=f"coordinates out of range.*{words}"):
            make()
