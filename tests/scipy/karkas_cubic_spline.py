"""SciPy's ``CubicSpline`` interface over ``karkas.CubicSpline``: the thin adapter that lets
SciPy's own tests of ``CubicSpline`` run against karkas.

What the adapter does, and only that:

- arrays: ``y`` of any shape along ``axis`` is read as ``m`` columns of values, each column a
  coordinate of karkas points (karkas interpolates points of 2 or 3 coordinates: the columns
  go three at a time into as many ``karkas.CubicSpline`` objects, the last padded with zero
  columns); results are put back in SciPy's shapes. A cubic spline interpolates every
  coordinate on its own, so this is the same spline. ``y`` with no values (``y.size == 0``)
  has nothing to interpolate: the adapter answers with empty arrays of SciPy's shapes.
- end conditions: SciPy's ``bc_type`` is handed to karkas's ``bc_type`` as given, the values
  of ``(order, value)`` pairs split by columns like ``y``;
- ``S.x`` and ``S.c`` (the piecewise polynomial coefficients SciPy's tests check) are computed
  from karkas's knots, values and slopes (the Hermite form the spline is held in);
- ``S(x, nu, extrapolate)`` and ``S.derivative(nu)`` call karkas's evaluation and karkas's
  derivative objects.

What karkas does not claim (``pytest.skip`` with the reason, listed by the runner): complex
values, end conditions of different kinds at the two ends, end second derivatives other than
zero, ``antiderivative``, ``integrate``, ``roots`` and ``solve``. In fallback mode (the
runner's second pass over the skipped tests) those are handed to SciPy instead, so that the
rest of such a test still checks every spline karkas builds.
"""

import os

import numpy as np
import pytest
import scipy.interpolate

import karkas

#: The names of end conditions and their ``(order, value)`` forms in SciPy.
_NAMED = {"natural": (2, 0.0), "clamped": (1, 0.0)}


class Unclaimed(Exception):
    """A feature karkas does not claim, met in fallback mode."""


#: Fallback mode (environment KARKAS_SCIPY_FALLBACK=1): a construction or method karkas does
#: not claim is handed to SciPy itself instead of skipping the whole test, so that the rest of
#: the test still checks what karkas builds. Counts of the splines each built are appended to
#: the file named by KARKAS_SCIPY_COUNTS.
FALLBACK = os.environ.get("KARKAS_SCIPY_FALLBACK") == "1"


def unclaimed(reason):
    """Skips the test (it exercises a feature karkas does not claim), or in fallback mode
    raises `Unclaimed` for the caller to hand the work to SciPy."""
    if FALLBACK:
        raise Unclaimed(reason)
    pytest.skip("not claimed by karkas: " + reason)


def _count(who):
    path = os.environ.get("KARKAS_SCIPY_COUNTS")
    if path:
        with open(path, "a") as f:
            f.write(who + "\n")


def _end_kind(end):
    """The kind of one end as SciPy reads it: a name, ``(order, value)``, or None when the
    form is not one SciPy accepts (karkas is then left to refuse it)."""
    if isinstance(end, str):
        return end
    try:
        order, value = end
    except (TypeError, ValueError):
        return None
    if order not in (1, 2):
        return None
    return ("first", order, value) if order == 1 else ("second", order, value)


def _claimed_ends(bc_type):
    """Skips when the end conditions are valid in SciPy but not claimed by karkas."""
    if isinstance(bc_type, str):
        return
    try:
        start, end = bc_type
    except (TypeError, ValueError):
        return
    kinds = []
    for e in (start, end):
        k = _end_kind(e)
        if k is None:
            return
        if isinstance(k, str):
            if k in _NAMED:
                order, value = _NAMED[k]
                k = ("first" if order == 1 else "second", order, value)
            elif k not in ("not-a-knot", "periodic"):
                return
        kinds.append(k)
    if any(isinstance(k, str) for k in kinds):
        if kinds[0] != kinds[1] and "periodic" not in kinds:
            unclaimed("end conditions of different kinds at the two ends")
        return
    if kinds[0][0] != kinds[1][0]:
        unclaimed("end conditions of different kinds at the two ends")
    if kinds[0][0] == "second":
        for _, _, value in kinds:
            if np.iscomplexobj(value):
                unclaimed("complex values")
            if np.any(np.asarray(value, dtype=float) != 0):
                unclaimed("end second derivatives other than zero")
    elif any(np.iscomplexobj(v) for _, _, v in kinds):
        unclaimed("complex values")


def _split_bc(bc_type, shape, groups):
    """``bc_type`` for each group of columns: names as they are, the values of ``(order,
    value)`` pairs (of the shape of one value of ``y``, SciPy's rule: a ValueError otherwise)
    flattened and cut like the columns."""
    m = int(np.prod(shape, dtype=int))
    if isinstance(bc_type, str):
        return [bc_type] * len(groups)
    try:
        start, end = bc_type
        pairs = []
        for e in (start, end):
            named = isinstance(e, str)
            if named:
                e = _NAMED.get(e, e)
                if isinstance(e, str):
                    return [bc_type] * len(groups)
            order, value = e
            if not named and np.shape(value) != tuple(shape):
                raise ValueError(
                    f"bc_type: an end value of shape {np.shape(value)}, the values of y "
                    f"{tuple(shape)} (SciPy's shape rule)"
                )
            value = np.broadcast_to(np.asarray(value, dtype=float), tuple(shape)).reshape(-1)
            pairs.append((order, value))
    except TypeError:
        return [bc_type] * len(groups)
    out = []
    for g in groups:
        ends = []
        for order, value in pairs:
            if value.size != m:
                return [bc_type] * len(groups)
            v = np.zeros(max(len(g), 2))
            v[: len(g)] = value[g]
            ends.append((order, v))
        out.append(tuple(ends))
    return out


class CubicSpline:
    """``scipy.interpolate.CubicSpline(x, y, axis=0, bc_type='not-a-knot',
    extrapolate=None)``, computed by ``karkas.CubicSpline``."""

    def __new__(cls, x, y, axis=0, bc_type="not-a-knot", extrapolate=None):
        try:
            spline = super().__new__(cls)
            spline._build(x, y, axis, bc_type, extrapolate)
        except Unclaimed:
            _count("scipy")
            return scipy.interpolate.CubicSpline(x, y, axis, bc_type, extrapolate)
        _count("karkas")
        return spline

    def __init__(self, *args, **kwargs):
        pass

    def _build(self, x, y, axis, bc_type, extrapolate):
        x = np.asarray(x)
        y = np.asarray(y)
        if np.iscomplexobj(x) or np.iscomplexobj(y):
            unclaimed("complex values")
        _claimed_ends(bc_type)
        y = np.moveaxis(y, axis, 0)
        self.axis = axis % max(np.ndim(np.asarray(y)), 1)
        self._shape = y.shape[1:]
        n = y.shape[0]
        m = int(np.prod(self._shape, dtype=int))
        self.x = np.asarray(x, dtype=float)
        self.extrapolate = extrapolate
        self._m = m
        if m == 0:
            # Nothing to interpolate: SciPy's shapes only (the adapter's answer, not karkas's).
            if self.x.ndim != 1 or self.x.size != n or n < 2:
                raise ValueError("x and y must be 1-D arrays of the same length, at least 2")
            self._splines = []
            self.c = np.zeros((4, n - 1) + self._shape)
            return
        columns = y.reshape(n, m).astype(float)
        groups = [list(range(k, min(k + 3, m))) for k in range(0, m, 3)]
        self._groups = groups
        bcs = _split_bc(bc_type, self._shape, groups)
        self._splines = []
        for g, bc in zip(groups, bcs):
            points = np.zeros((n, max(len(g), 2)))
            points[:, : len(g)] = columns[:, g]
            self._splines.append(
                karkas.CubicSpline(points, t=x, bc_type=bc, extrapolate=extrapolate)
            )
        self.c = self._coefficients()

    def _coefficients(self):
        """The coefficients of SciPy's ``PPoly`` (highest power first, per piece) from
        karkas's knots, values and slopes."""
        t = self._splines[0].knots
        n = t.size
        h = np.diff(t)[:, None]
        c = np.zeros((4, n - 1, self._m))
        for g, s in zip(self._groups, self._splines):
            y, m = s.values[:, : len(g)], s.slopes[:, : len(g)]
            delta = np.diff(y, axis=0) / h
            c[3, :, g] = y[:-1].T
            c[2, :, g] = m[:-1].T
            c[1, :, g] = ((3 * delta - 2 * m[:-1] - m[1:]) / h).T
            c[0, :, g] = ((m[:-1] + m[1:] - 2 * delta) / h**2).T
        return c.reshape((4, n - 1) + self._shape)

    def _evaluate(self, splines, x, nu, extrapolate):
        x = np.asarray(x, dtype=float)
        flat = x.reshape(-1)
        out = np.empty((flat.size, self._m))
        for g, s in zip(self._groups, splines):
            if extrapolate is None:
                values = s(flat, nu)
            else:
                values = s(flat, nu, extrapolate=extrapolate)
            out[:, g] = np.asarray(values)[:, : len(g)]
        out = out.reshape(x.shape + self._shape)
        return np.moveaxis(out, list(range(x.ndim)), list(range(self.axis, self.axis + x.ndim)))

    def __call__(self, x, nu=0, extrapolate=None):
        if self._m == 0:
            x = np.asarray(x)
            return np.zeros(self._shape[: self.axis] + x.shape + self._shape[self.axis :])
        return self._evaluate(self._splines, x, nu, extrapolate)

    def derivative(self, nu=1):
        """The ``nu``-th derivative (karkas's derivative curve objects)."""
        return _Derivative(self, nu)

    def _ppoly(self, what):
        """In fallback mode, SciPy's ``PPoly`` of karkas's coefficients (for `what`, which
        karkas does not claim); else a skip."""
        try:
            unclaimed(what)
        except Unclaimed:
            _count("scipy")
            poly = scipy.interpolate.PPoly(self.c, self.x, self.extrapolate)
            poly.axis = self.axis  # as SciPy's CubicSpline sets it
            return poly

    def antiderivative(self, nu=1):
        return self._ppoly("antiderivative").antiderivative(nu)

    def integrate(self, a, b, extrapolate=None):
        return self._ppoly("integrate").integrate(a, b, extrapolate)

    def roots(self, discontinuity=True, extrapolate=None):
        return self._ppoly("roots").roots(discontinuity, extrapolate)

    def solve(self, y=0.0, discontinuity=True, extrapolate=None):
        return self._ppoly("solve").solve(y, discontinuity, extrapolate)


class _Derivative:
    """The derivative of an adapted spline, evaluated by karkas's derivative objects."""

    def __init__(self, spline, nu):
        self._spline = spline
        self._nu = nu
        self._splines = [s.derivative(nu) for s in spline._splines]

    def __call__(self, x, nu=0, extrapolate=None):
        s = self._spline
        if s._m == 0:
            return s(x)
        return s._evaluate(self._splines, x, nu, extrapolate)
