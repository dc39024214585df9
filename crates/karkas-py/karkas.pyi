"""Type stubs of the karkas Python package (built from crates/karkas-py).

Checked against the built module in CI by ``python -m mypy.stubtest karkas`` (allowlist:
stubtest-allowlist.txt). The docstrings of the module itself are the reference; these are
summaries.
"""

from __future__ import annotations

import os
from typing import Any, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray
from typing_extensions import Self, TypeAlias, disjoint_base, final

__version__: str
# The memory cap in bytes for one request (None: no cap); read at every size check.
max_memory: int | None
__all__ = [
    "__version__",
    "batch",
    "batch_inputs",
    "BicubicSurface",
    "LoftSurface",
    "loft",
    "loft_windio",
    "CadFace",
    "CadModel",
    "ConvergenceError",
    "CoonsSurface",
    "CubicSpline",
    "Curve",
    "curve_parameters",
    "CurveDerivative",
    "DiscreteSpline",
    "export",
    "export_curve_csv",
    "export_obj",
    "export_stl",
    "export_surface_csv",
    "ExpressionError",
    "FileFormatError",
    "fit_curve",
    "fair_curve",
    "grid_parameters",
    "hausdorff",
    "hausdorff_to_implicit",
    "HermiteSpline",
    "FairCurve",
    "ImplicitSurface",
    "IncompatibleDataError",
    "KarkasError",
    "KarkasWarning",
    "KnotsError",
    "LLCurve",
    "LLSurface",
    "max_input_bytes",
    "max_memory",
    "NoBSplineFormError",
    "NurbsCurve",
    "NurbsSurface",
    "OptionError",
    "PointsError",
    "read_airfoil",
    "read_cad",
    "read_curve",
    "read_grid",
    "read_mask",
    "read_mesh",
    "read_network",
    "read_point_set",
    "read_skeleton",
    "read_surface_samples",
    "relay_grid",
    "SectionCurve",
    "set_max_input_bytes",
    "Surface",
    "SurfaceDerivative",
    "TubeSurface",
    "vary",
    "_restore",
]

# Stub-only aliases (private: not names of the module).
_Floats: TypeAlias = NDArray[np.float64]
_Params: TypeAlias = Union[float, ArrayLike]
_Bc: TypeAlias = Union[str, Tuple[str, ArrayLike, ArrayLike]]
_FilePath: TypeAlias = Union[str, "os.PathLike[str]"]

class KarkasError(ValueError):
    """An error of karkas: bad input, or a method that could not finish.

    The message is the library's and names the offending input. The subclasses say which kind
    of mistake it is; other errors are KarkasError itself. A file that cannot be opened, read
    or written is OSError (FileNotFoundError, PermissionError, ...), not KarkasError."""

class PointsError(KarkasError):
    """Too few points, grid points or skeleton curves, a non-finite coordinate, coinciding
    neighbours, or an array of the wrong shape or dimension."""

class KnotsError(KarkasError):
    """Knots (parameters) that are not finite and strictly increasing, too close together,
    outside their range, or too few."""

class OptionError(KarkasError):
    """An order, step, tolerance or other option outside its range, an unknown name (end
    condition, parameterization, kind, ...), or options that exclude each other."""

class IncompatibleDataError(KarkasError):
    """Curves of a network or of a tube skeleton that do not meet where they must, or
    prescribed row and column sums that cannot all hold."""

class ConvergenceError(KarkasError):
    """A singular linear system, a projection or a continuation that did not converge, or a
    singular point of an implicit surface."""

class ExpressionError(KarkasError):
    """An implicit-surface expression that does not parse (the message gives the position)."""

class KarkasWarning(UserWarning):
    """A warning of karkas about its input (a first column that counts the rows, points far
    out of order, a header read in order), issued with warnings.warn."""

class FileFormatError(KarkasError):
    """A file whose content the readers cannot read, with the command line's message naming the
    file and the line or grid cell: a malformed number, a missing column or cell, binary data,
    a line longer than 1 MiB, or an input larger than the memory cap (set_max_input_bytes)."""

class NoBSplineFormError(KarkasError):
    """An object with no exact B-spline form (to_bspline, or an evaluation outside the domain
    of a surface that is not a piecewise polynomial, with extrapolate None or True)."""

@disjoint_base
class Curve:
    """Base class of every curve: c(t, nu=0, out=None, extrapolate=None) -> points or
    derivatives. Outside the domain a closed curve wraps by its period; an open curve continues
    its end polynomial pieces (extrapolate None or True) or gives NaN (extrapolate=False)."""

    def _repr_html_(self) -> str:
        """The SVG picture with the curvature comb, for Jupyter."""
    def __call__(
        self,
        t: _Params,
        nu: int = 0,
        out: Optional[_Floats] = None,
        extrapolate: Optional[bool] = None,
    ) -> _Floats:
        """The nu-th derivative at t: float -> (d,), array -> t.shape + (d,); out= is written
        and returned."""
    def derivative(self, nu: int = 1) -> "CurveDerivative":
        """The nu-th derivative as a curve object."""
    def to_bspline(self) -> Tuple[_Floats, _Floats, int]:
        """The exact B-spline form (t, c, k) for scipy.interpolate.BSpline."""
    def sample(self, n: int) -> _Floats:
        """n points at uniformly spaced parameters over the domain, (n, d)."""
    def arc_length(
        self, t0: Optional[float] = None, t1: Optional[_Params] = None, tol: float = 1e-10
    ) -> Union[float, _Floats]:
        """Length from t0 to t1 (domain ends by default) to tol; float, or an array of t1's shape."""
    def inverse_arc_length(
        self, s: _Params, t0: Optional[float] = None, tol: float = 1e-10
    ) -> Union[float, _Floats]:
        """The parameter reached after walking s from t0 (stops at an open curve's end)."""
    def curvature(self, t: _Params) -> Union[float, _Floats]:
        """Curvature: signed in 2-D (positive counter-clockwise), non-negative in 3-D."""
    def torsion(self, t: _Params) -> Union[float, _Floats]:
        """Torsion of a 3-D curve (KarkasError in 2-D)."""
    def project(self, points: ArrayLike, tol: float = 0.0) -> Tuple[_Floats, _Floats, _Floats]:
        """Globally nearest points: (t (n,), distance (n,), foot (n, d))."""
    def fairness(self, points: Optional[ArrayLike] = None) -> dict[str, Any]:
        """Length, curvature range, curvature extrema, inflections, max_distance_to_polygon
        (None without points), fairness_energy, pieces, curvature_jump (curve analyze --json)."""
    @property
    def domain(self) -> Tuple[float, float]: ...
    @property
    def dim(self) -> int: ...
    @property
    def closed(self) -> bool: ...
    @property
    def breakpoints(self) -> _Floats: ...
    @property
    def continuity(self) -> int: ...

@final
class CurveDerivative(Curve):
    """The nu-th derivative of a curve as a curve (Curve.derivative)."""

    @property
    def parent(self) -> Curve: ...
    @property
    def nu(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[int]]: ...

@final
class LLCurve(Curve):
    """The LL approximation of a support polygon (points (n, d), d in {2, 3})."""

    def __new__(
        cls,
        points: ArrayLike,
        order: int = 3,
        closed: bool = False,
        interpolate: bool = False,
        within: Optional[float] = None,
    ) -> Self:
        """The defaults are those of karkas curve ll; within=D as its --within D."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    @staticmethod
    def interpolate(points: ArrayLike, order: int = 3, closed: bool = False) -> LLCurve:
        """The interpolating LL curve: through every point at t_i = i/(K+1)."""
    @property
    def order(self) -> int: ...
    @property
    def interpolating(self) -> bool: ...
    @property
    def within(self) -> Optional[float]: ...
    @property
    def largest_deviation(self) -> Optional[float]: ...
    @property
    def control_points(self) -> _Floats: ...

@final
class CubicSpline(Curve):
    """A C^2 cubic interpolating spline through points (n, d)."""

    def __new__(
        cls,
        points: ArrayLike,
        t: Optional[ArrayLike] = None,
        parameterization: str = "chord",
        bc: Optional[_Bc] = None,
        extrapolate: Union[bool, Literal["periodic"], None] = None,
        *,
        bc_type: Optional[Any] = None,
    ) -> Self:
        """bc: 'not-a-knot' (default), 'natural', 'periodic', 'clamped' (zero first
        derivatives) or ('clamped', d0, d1); bc_type: SciPy's name of bc, also
        ((1, d0), (1, d1)) and ((2, 0), (2, 0)); extrapolate: what a call with
        extrapolate=None gives outside the domain (None, True: the end pieces continued;
        False: NaN; 'periodic': the parameter wrapped); parameterization: 'uniform', 'chord'
        (also 'chord-length', 'chordlength'), 'centripetal' (ignored when t is given)."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def knots(self) -> _Floats: ...
    @property
    def values(self) -> _Floats: ...
    @property
    def slopes(self) -> _Floats: ...

@final
class HermiteSpline(Curve):
    """A C^1 cubic Hermite spline on [0, 1], the result of fit_curve (no constructor)."""

    def __new__(cls, knots: ArrayLike, values: ArrayLike, derivatives: ArrayLike) -> Self:
        """The spline with these values and derivatives at the knots (no fit statistics)."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def knots(self) -> _Floats: ...
    @property
    def values(self) -> _Floats: ...
    @property
    def derivatives(self) -> _Floats: ...
    @property
    def max_distance(self) -> float: ...
    @property
    def rms_distance(self) -> float: ...
    @property
    def jump_sum(self) -> float: ...
    @property
    def tolerance_met(self) -> Optional[bool]: ...
    @property
    def parameters(self) -> _Floats: ...
    @property
    def distances(self) -> _Floats: ...
    @property
    def noise(self) -> float: ...
    @property
    def warnings(self) -> list[str]: ...

def fit_curve(
    points: ArrayLike,
    knots: Union[None, int, ArrayLike] = None,
    tolerance: Optional[float] = None,
    eps: Optional[float] = None,
    pin_ends: bool = False,
    corners: Optional[Sequence[float]] = None,
    fairness: float = 3e-11,
    smoothing: Optional[float] = None,
    penalty: Literal["active", "paper"] = "active",
    free_ends: bool = False,
    closed: bool = False,
    starts: int = 1,
) -> HermiteSpline:
    """Fits points (n, d) with a C^1 cubic Hermite spline; give knots (count or array) or
    tolerance. The options and defaults are those of karkas curve fit."""

@final
class FairCurve(Curve):
    """The fairest C^2 cubic B-spline within a tolerance of points (fair_curve)."""

    def __reduce__(self) -> Tuple[object, ...]: ...
    @staticmethod
    def _from_state(
        knots: ArrayLike,
        control_points: ArrayLike,
        closed: bool,
        points: ArrayLike,
        parameters: ArrayLike,
        distances: ArrayLike,
        tolerance: float,
    ) -> FairCurve: ...
    def report(self) -> dict[str, dict[str, Any]]:
        """The fairness before and after (the keys of Curve.fairness)."""
    @property
    def knots(self) -> _Floats: ...
    @property
    def control_points(self) -> _Floats: ...
    @property
    def points(self) -> _Floats: ...
    @property
    def parameters(self) -> _Floats: ...
    @property
    def distances(self) -> _Floats: ...
    @property
    def max_distance(self) -> float: ...
    @property
    def tolerance(self) -> float: ...

def fair_curve(
    points: Union[ArrayLike, Curve],
    tolerance: float,
    keep_ends: bool = False,
    keep_tangents: bool = False,
    corners: Optional[Sequence[int]] = None,
    closed: bool = False,
) -> FairCurve:
    """The fairest C^2 cubic within tolerance of points (n, d) or of a curve (karkas curve fair)."""

@disjoint_base
class Surface:
    """Base class of every surface: S(u, v, du=0, dv=0, grid=True, out=None,
    extrapolate=None) -> points or partial derivatives. Outside the domain, per direction: a
    closed one wraps by its period; an open one continues the end polynomial pieces
    (extrapolate None or True) or gives NaN (extrapolate=False)."""

    def _repr_html_(self) -> str:
        """The 3-D viewer page in an <iframe srcdoc>, for Jupyter."""

    def __call__(
        self,
        u: _Params,
        v: _Params,
        du: int = 0,
        dv: int = 0,
        grid: bool = True,
        out: Optional[_Floats] = None,
        extrapolate: Optional[bool] = None,
        *,
        dx: Optional[int] = None,
        dy: Optional[int] = None,
    ) -> _Floats:
        """grid=True: (mu, mv, d) on u x v; grid=False: u.shape + (d,) at the pairs (u, v);
        dx, dy are RectBivariateSpline's names of du, dv."""
    def derivative(
        self,
        du: Optional[int] = None,
        dv: Optional[int] = None,
        *,
        dx: Optional[int] = None,
        dy: Optional[int] = None,
    ) -> "SurfaceDerivative":
        """The partial derivative d^(du+dv) S / du^du dv^dv as a surface object (du 1, dv 0
        when not given; dx, dy: RectBivariateSpline's names)."""
    def to_bspline(
        self,
    ) -> Tuple[Tuple[_Floats, _Floats], _Floats, Tuple[int, int]]:
        """The exact B-spline form ((tu, tv), c (nu, nv, d), (ku, kv)) for NdBSpline."""
    def sample(self, nu: int, nv: int) -> _Floats: ...
    def normal(self, u: _Params, v: _Params, grid: bool = False) -> _Floats:
        """Unit normals S_u x S_v / |S_u x S_v|, shape (..., 3)."""
    @overload
    def principal_curvatures(
        self, u: _Params, v: _Params, grid: bool = False, directions: Literal[False] = False
    ) -> Tuple[Union[float, _Floats], Union[float, _Floats]]: ...
    @overload
    def principal_curvatures(
        self, u: _Params, v: _Params, grid: bool = False, *, directions: Literal[True]
    ) -> Tuple[Union[float, _Floats], Union[float, _Floats], _Floats, _Floats]: ...
    @overload
    def principal_curvatures(
        self, u: _Params, v: _Params, grid: bool, directions: Literal[True]
    ) -> Tuple[Union[float, _Floats], Union[float, _Floats], _Floats, _Floats]: ...
    @overload
    def project(
        self,
        points: ArrayLike,
        cells: Tuple[int, int] = (64, 64),
        tol: float = 0.0,
        foot: Literal[False] = False,
    ) -> Tuple[_Floats, _Floats, _Floats]:
        """Globally nearest points: (u (n,), v (n,), distance (n,))."""
    @overload
    def project(
        self,
        points: ArrayLike,
        cells: Tuple[int, int] = (64, 64),
        tol: float = 0.0,
        *,
        foot: Literal[True],
    ) -> Tuple[_Floats, _Floats, _Floats, _Floats]:
        """With foot=True also the foot points (n, d)."""
    def section(
        self,
        normal: Sequence[float],
        offset: float,
        tolerance: Optional[float] = None,
        cells: Tuple[int, int] = (64, 64),
    ) -> list[SectionCurve]:
        """Where the plane normal . x = offset cuts the surface, as polylines on it."""
    @property
    def domain_u(self) -> Tuple[float, float]: ...
    @property
    def domain_v(self) -> Tuple[float, float]: ...
    @property
    def dim(self) -> int: ...
    @property
    def closed_u(self) -> bool: ...
    @property
    def closed_v(self) -> bool: ...

@final
class SurfaceDerivative(Surface):
    """A partial derivative of a surface as a surface (Surface.derivative)."""

    @property
    def parent(self) -> Surface: ...
    @property
    def du(self) -> int: ...
    @property
    def dv(self) -> int: ...
    def __reduce__(self) -> Tuple[Any, Tuple[int, int]]: ...

@final
class LLSurface(Surface):
    """The LL approximation of a grid (nu, nv, d)."""

    def __new__(
        cls,
        grid: ArrayLike,
        order: int = 3,
        closed_u: bool = False,
        closed_v: bool = False,
        interpolate: bool = False,
        within: Optional[float] = None,
        crease_u: bool = False,
        crease_v: bool = False,
    ) -> Self:
        """The defaults are those of karkas surface ll; within=D as its --within D;
        crease_u/crease_v as its --crease-u/--crease-v (a C^0 seam)."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    @staticmethod
    def interpolate(
        grid: ArrayLike, order: int = 3, closed_u: bool = False, closed_v: bool = False
    ) -> LLSurface: ...
    def section(  # type: ignore[override]
        self,
        normal: Sequence[float],
        offset: float,
        tolerance: Optional[float] = None,
        cells: Optional[Tuple[int, int]] = None,
    ) -> "list[SectionCurve]":
        """As Surface.section; cells=None: 2 per grid line, at least 16 (karkas section)."""
    @property
    def order(self) -> int: ...
    @property
    def interpolating(self) -> bool: ...
    @property
    def within(self) -> Optional[float]: ...
    @property
    def largest_deviation(self) -> Optional[float]: ...

@final
class BicubicSurface(Surface):
    """Bicubic (C^2, not-a-knot or periodic) interpolation of a grid (nu, nv, d)."""

    def __new__(
        cls,
        grid: ArrayLike,
        parameterization: str = "chord",
        closed_u: bool = False,
        closed_v: bool = False,
        origin: Optional[Tuple[int, int]] = None,
        crease_u: bool = False,
        crease_v: bool = False,
    ) -> Self:
        """parameterization (karkas surface bicubic --param): 'uniform', 'chord', 'averaged'
        (also 'averaged-chord'), 'centripetal'; origin (--origin I,J): the origin node (i, j)
        of 'chord'; crease_u/crease_v (--crease-u/--crease-v): closed with a C^0 seam."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    def condition_measure(self, paper: bool = False) -> _Floats:
        """The condition measure (2.4) of the parameters at every node, (nu, nv), in [0, 1];
        1 for arc lengths along orthogonal directions (karkas surface bicubic --report);
        paper=True: the paper's |D| itself, the sine of the angle between the lines."""
    @staticmethod
    def from_knots(
        grid: ArrayLike,
        knots_u: ArrayLike,
        knots_v: ArrayLike,
        closed_u: bool = False,
        closed_v: bool = False,
    ) -> BicubicSurface: ...
    @property
    def knots_u(self) -> _Floats: ...
    @property
    def knots_v(self) -> _Floats: ...

@final
class LoftSurface(Surface):
    """A surface lofted through placed sections (karkas.loft): u along the span (the stations),
    v along each section over [0, 1] (leading edge at 0.5)."""

    def __reduce__(self) -> Tuple[object, ...]: ...
    def section_at(self, station: float, n: int = 200) -> _Floats:
        """The surface's section at a span station, n points (n, 3)."""
    @property
    def stations(self) -> _Floats: ...
    @property
    def deviations(self) -> _Floats: ...
    @property
    def tolerance_met(self) -> bool: ...
    @property
    def control_points(self) -> Tuple[int, int]: ...
    @property
    def span(self) -> str: ...
    @property
    def tolerance(self) -> float: ...
    @property
    def airfoil_stations(self) -> Optional[_Floats]:
        """The stations of a windIO blade's airfoils (karkas.loft_windio); None for a wing."""

def loft(
    profiles: Sequence[ArrayLike],
    leading_edges: ArrayLike,
    chords: ArrayLike,
    twists: ArrayLike,
    dihedrals: Optional[ArrayLike] = None,
    span: Literal["monotone", "linear", "spline"] = "monotone",
    tolerance: float = 1e-5,
) -> LoftSurface:
    """Lofts a wing through airfoil profiles in unit chord placed as aerosandbox's WingXSec
    places them (karkas loft)."""

def loft_windio(
    path: _FilePath,
    span: Literal["monotone", "linear", "spline"] = "monotone",
    tolerance: float = 1e-5,
) -> LoftSurface:
    """Lofts the blade of a windIO 2 turbine file as windIO places its airfoils (karkas loft
    --windio)."""

@final
class DiscreteSpline:
    """A closed discrete curve: N = m n periodic values of a discrete spline of order r."""

    def __new__(cls, poles: ArrayLike, order: int = 3, n: int = 10) -> Self: ...
    def __reduce__(self) -> Tuple[object, ...]: ...
    @staticmethod
    def interpolate(nodes: ArrayLike, order: int = 3, n: int = 10) -> DiscreteSpline: ...
    def values(self, out: Optional[_Floats] = None) -> _Floats:
        """The N values, (m n, d)."""
    @property
    def poles(self) -> _Floats: ...
    @property
    def order(self) -> int: ...
    @property
    def n(self) -> int: ...
    @property
    def period(self) -> int: ...
    @property
    def dim(self) -> int: ...

@final
class TubeSurface:
    """A closed tube through a skeleton of closed discrete curves."""

    def __new__(
        cls, along: ArrayLike, across: ArrayLike, n1: int, n2: int, r1: int = 2, r2: int = 2
    ) -> Self:
        """The defaults are those of karkas surface dps-tube."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    def values(self) -> _Floats:
        """c(p, q), (N1, N2, d)."""
    def closed_grid(self) -> _Floats:
        """The values with the seams repeated, (N1 + 1, N2 + 1, d)."""

@final
class SectionCurve:
    """One connected piece of a plane section: a polyline on the surface (no constructor)."""

    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def closed(self) -> bool: ...
    @property
    def length(self) -> float: ...
    @property
    def points(self) -> _Floats:
        """(n, d)."""
    @property
    def params(self) -> _Floats:
        """The surface parameters (u, v) of the points, (n, 2)."""
    def __len__(self) -> int: ...

@final
class CoonsSurface(Surface):
    """Generalized Coons surfaces over a network of curves given by points."""

    def __new__(
        cls,
        *,
        u_curves: Sequence[ArrayLike],
        v_curves: Sequence[ArrayLike],
        kind: str = "gordon-spline",
        u_derivs: Optional[Sequence[ArrayLike]] = None,
        v_derivs: Optional[Sequence[ArrayLike]] = None,
        fit: Union[None, str, Tuple[str, int]] = None,
        crossing_tolerance: float = 1e-6,
        tolerance: float = 1e-4,
        twists: Optional[ArrayLike] = None,
    ) -> Self:
        """kind: 'bilinear', 'bicubic', 'gordon', 'gordon-spline', 'composite'; u_curves and
        v_curves by keyword, as karkas surface coons's --u-curves and --v-curves; twists:
        (len(v_curves), len(u_curves), d), as --twists."""
    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def kind(self) -> str: ...

@final
class ImplicitSurface:
    """An implicit surface F(x, y, z) = 0 given as an expression."""

    def __new__(cls, expression: str) -> Self: ...
    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def expression(self) -> str: ...
    def value(self, points: ArrayLike) -> _Floats: ...
    def gradient(self, points: ArrayLike) -> _Floats: ...
    def project(self, points: ArrayLike) -> _Floats: ...
    def curvatures(self, point: Sequence[float]) -> dict:
        """normal, k1, k2, d1, d2, gaussian, mean."""
    def trace_net(
        self,
        start: Sequence[float],
        nodes: Tuple[int, int],
        steps: Optional[Tuple[float, float]] = None,
        directions: str = "principal",
        angle: float = 0.0,
        plane_normal: Optional[Sequence[float]] = None,
        closed_v: bool = False,
        substeps: int = 32,
        *,
        step: Union[None, float, Tuple[float, float]] = None,
        turn: Optional[float] = None,
    ) -> _Floats:
        """A node grid (nu, nv, 3) on F = 0 along lines of curvature (or turned nets)."""

def hausdorff(a: ArrayLike, b: Optional[ArrayLike] = None, expr: Optional[str] = None) -> dict:
    """Two-sided Hausdorff distance of point sets (n, 3), (m, 3), or of a and the patch of
    F = expr = 0 inside a's bounding box: distance, forward, backward."""

def hausdorff_to_implicit(
    surface: Surface,
    implicit: ImplicitSurface,
    patch: ArrayLike,
    samples: Tuple[int, int] = (50, 50),
) -> dict: ...
def vary(
    matrix: ArrayLike,
    row_sums: Sequence[float],
    column_sums: Sequence[float],
    fixed: Optional[ArrayLike] = None,
    penalty: Optional[float] = None,
    scale_with_total: bool = False,
    total: Optional[float] = None,
) -> _Floats:
    """The least change of matrix with the given row and column sums (LL surface variation)."""

def curve_parameters(points: ArrayLike, parameterization: str = "chord") -> _Floats: ...
def grid_parameters(
    grid: ArrayLike, parameterization: str = "chord", origin: Optional[Tuple[int, int]] = None
) -> Tuple[_Floats, _Floats]: ...
def relay_grid(
    grid: ArrayLike,
    size: Optional[Tuple[int, int]] = None,
    start: Optional[Tuple[int, int]] = None,
) -> _Floats:
    """The grid re-laid along the lines of curvature of its bicubic interpolant, (M, N, 3).

    Raises PointsError for a grid that is not (nu, nv, 3), a size below 2, a start outside
    the grid or an umbilic region (a plane, a sphere), ConvergenceError when the net does not
    fit the interpolant's domain."""
def export_obj(path: _FilePath, grid: ArrayLike) -> None: ...
def export_stl(path: _FilePath, grid: ArrayLike) -> None: ...
def export_curve_csv(path: _FilePath, t: ArrayLike, points: ArrayLike) -> None: ...
def export_surface_csv(path: _FilePath, u: ArrayLike, v: ArrayLike, grid: ArrayLike) -> None: ...

def read_curve(
    path: _FilePath,
    *,
    columns: Optional[Sequence[Union[int, str]]] = None,
    decimal_comma: bool = False,
) -> _Floats:
    """The ordered points of a curve file, (n, d) with d 2 or 3, as the command line's curve
    commands read it: CSV (an optional header naming x, y and optionally z; fields separated
    by commas, semicolons or tabs, decimal commas where the comma does not separate, quoted
    fields, units in brackets), whitespace columns, or an airfoil .dat (Selig or Lednicer).
    columns= chooses the x, y (and z) columns by name or position from 1 (--columns);
    decimal_comma=True makes the comma a decimal mark (--decimal-comma).

    Raises OSError (FileNotFoundError, PermissionError, IsADirectoryError) when the file
    cannot be opened, FileFormatError ("file:line: ...") when its content cannot be read,
    OptionError for columns= that is not two or three columns. Warns (KarkasWarning) of a
    first column that counts the rows and of points far out of order."""

def read_airfoil(path: _FilePath) -> Tuple[str, _Floats]:
    """An airfoil .dat file (Selig or Lednicer): its name line and its contour (n, 2) in Selig
    order (trailing edge, upper surface, leading edge, lower surface, trailing edge)."""

def read_grid(path: _FilePath) -> _Floats:
    """A surface frame, CSV rows i,j,x,y,z, as an (m, n, 3) array: grid[i, j] is cell (i, j)."""

def read_network(path: _FilePath) -> list[_Floats]:
    """One family of curves of a curve network, CSV rows curve,x,y,z: one (k, 3) array per
    curve, in the order of the curve numbers (0, 1, ...)."""

@final
class NurbsCurve(Curve):
    """A rational B-spline curve: control points (n, d), knots, degree, weights."""

    def __new__(
        cls,
        control_points: ArrayLike,
        knots: ArrayLike,
        degree: int,
        weights: Optional[ArrayLike] = None,
        closed: bool = False,
    ) -> Self: ...
    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def degree(self) -> int: ...
    @property
    def knots(self) -> _Floats: ...
    @property
    def control_points(self) -> _Floats: ...
    @property
    def weights(self) -> _Floats: ...
    @property
    def rational(self) -> bool: ...

@final
class NurbsSurface(Surface):
    """A rational tensor-product B-spline surface: control grid (nu, nv, d), knots, degrees,
    weights (nu, nv)."""

    def __new__(
        cls,
        control_points: ArrayLike,
        knots_u: ArrayLike,
        knots_v: ArrayLike,
        degree_u: int,
        degree_v: int,
        weights: Optional[ArrayLike] = None,
        closed_u: bool = False,
        closed_v: bool = False,
    ) -> Self: ...
    def __reduce__(self) -> Tuple[object, ...]: ...
    @property
    def degrees(self) -> Tuple[int, int]: ...
    @property
    def knots_u(self) -> _Floats: ...
    @property
    def knots_v(self) -> _Floats: ...
    @property
    def control_points(self) -> Any: ...
    @property
    def weights(self) -> Any: ...
    @property
    def rational(self) -> bool: ...

@final
class CadFace:
    """A face of a CAD file: a NurbsSurface inside its loops of edges (no constructor)."""

    @property
    def surface(self) -> NurbsSurface: ...
    @property
    def loops(self) -> List[List[NurbsCurve]]: ...
    @property
    def same_sense(self) -> bool: ...
    @property
    def bounds_solid(self) -> bool: ...
    def contains(self, u: float, v: float) -> bool: ...

@final
class CadModel:
    """The geometry of a STEP or IGES file (no constructor; read_cad makes it)."""

    @property
    def faces(self) -> List[CadFace]: ...
    @property
    def curves(self) -> List[NurbsCurve]: ...
    @property
    def unit(self) -> Tuple[str, float]: ...
    @property
    def unread(self) -> List[Tuple[str, int, str]]: ...
    @property
    def warning(self) -> Optional[str]: ...
    @property
    def format(self) -> str: ...
    @property
    def entities(self) -> int: ...

def read_cad(path: _FilePath) -> CadModel:
    """The faces, free curves, unit and unread entities of a STEP or IGES file."""

def read_mesh(path: _FilePath) -> Tuple[_Floats, NDArray[np.int64]]:
    """A triangle mesh (.obj, .stl binary or ASCII, .ply, by extension): vertices (n, 3)
    float64 and faces (m, 3) int64 indexing the vertices from 0."""

def read_skeleton(path: _FilePath, across: bool = False) -> _Floats:
    """The skeleton curves of a tube, CSV rows i,q,x,y,z (along) or j,p,x,y,z (across=True),
    as an (m, N, 3) array: one row per curve."""

def read_point_set(path: _FilePath) -> _Floats:
    """A point set (n, 3): the vertices of an .obj file or the x,y,z columns of a CSV file."""

def read_surface_samples(path: _FilePath) -> _Floats:
    """The samples of a surface, CSV rows u,v,x,y,z, as an (nu, nv, 3) array."""

def read_mask(path: _FilePath, rows: int, cols: int) -> NDArray[np.bool_]:
    """A cell mask, CSV rows i,j, as a (rows, cols) bool array."""

def export(
    obj: object,
    path: _FilePath,
    *,
    format: Optional[str] = None,
    samples: Union[None, int, Tuple[int, int]] = None,
    title: Optional[str] = None,
    points: Optional[ArrayLike] = None,
    closed_points: bool = False,
    net: Optional[ArrayLike] = None,
    comb: bool = False,
    ascii: bool = False,
    flip_normals: bool = False,
    mesh_tolerance: Optional[float] = None,
    cap: bool = False,
) -> "os.PathLike[str]":
    """Writes a curve, surface, discrete spline, tube, point list (n, d), grid (nu, nv, 3),
    mesh (vertices, faces) or SciPy B-spline in the format of the path's extension (or
    format=), as the command line writes the same result; returns the path. A curve's .dxf
    is its exact SPLINE with points= as POINT entities on layer POINTS. A surface's mesh
    without samples= lies within mesh_tolerance of it (default 1e-4 of its size), sampled
    where it bends (--mesh-tolerance). cap=True (a surface in STEP, IGES or a triangle mesh)
    closes its open planar boundary loops with planar faces (--cap): a closed solid in STEP,
    a closed mesh sampled uniformly."""

def set_max_input_bytes(nbytes: int) -> None:
    """The most memory one read may keep, in bytes, for every reader of the process (default
    2 GiB, as the command line's --max-memory); a larger input raises FileFormatError."""

def _restore(name: str, args: Tuple[object, ...], kwargs: Optional[dict] = None) -> object:
    """Unpickling: calls the karkas constructor name (e.g. 'DiscreteSpline.interpolate')."""

def max_input_bytes() -> int:
    """The most memory one read may keep, in bytes (see set_max_input_bytes)."""

def batch(
    job: Union[str, list[str], Tuple[str, ...]],
    inputs: Union[_FilePath, list[_FilePath], Tuple[_FilePath, ...]],
    out: _FilePath,
    options: Optional[Union[list[str], Tuple[str, ...]]] = None,
    format: Optional[str] = None,
    tree: Optional[_FilePath] = None,
    jobs: Optional[int] = None,
    resume: bool = False,
    results_file: bool = True,
    as_frame: Optional[bool] = None,
    progress: bool = False,
    **job_options: Any,
) -> Any:
    """One command run on many input files (the command line's karkas batch): a list of
    record dicts (input, outputs, status, error, summary, seconds), or a pandas DataFrame."""

def batch_inputs(inputs: Union[_FilePath, list[_FilePath], Tuple[_FilePath, ...]]) -> list[str]:
    """The input files a batch of inputs (folders, patterns, .txt lists, files) would run."""
