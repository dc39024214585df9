"""Type stubs of the karkas Python package (built from crates/karkas-py)."""

import os
from typing import Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

__version__: str
# The memory cap in bytes for one request (None: no cap); read at every size check.
max_memory: int | None
__all__: list[str]

Floats = NDArray[np.float64]
Params = Union[float, ArrayLike]
Bc = Union[str, Tuple[str, ArrayLike, ArrayLike]]

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

class FileFormatError(KarkasError):
    """A file whose content the readers cannot read, with the command line's message naming the
    file and the line or grid cell: a malformed number, a missing column or cell, binary data,
    a line longer than 1 MiB, or an input larger than the memory cap (set_max_input_bytes)."""

class Curve:
    """Base class of every curve: c(t) -> points, c.derivative(t, k)."""

    def __call__(self, t: Params, out: Optional[Floats] = None) -> Floats:
        """The curve at t: float -> (d,), array -> t.shape + (d,); out= is written and returned."""
    def derivative(self, t: Params, k: int = 1, out: Optional[Floats] = None) -> Floats:
        """The k-th derivative with respect to the parameter (same shapes as calling)."""
    def sample(self, n: int) -> Floats:
        """n points at uniformly spaced parameters over the domain, (n, d)."""
    @property
    def domain(self) -> Tuple[float, float]: ...
    @property
    def dim(self) -> int: ...
    @property
    def closed(self) -> bool: ...
    @property
    def breakpoints(self) -> Floats: ...
    @property
    def continuity(self) -> int: ...

class LLCurve(Curve):
    """The LL approximation of a support polygon (points (n, d), d in {2, 3})."""

    def __init__(self, points: ArrayLike, order: int = 5, closed: bool = False) -> None: ...
    @staticmethod
    def interpolate(points: ArrayLike, order: int = 5, closed: bool = False) -> "LLCurve":
        """The interpolating LL curve: through every point at t_i = i/(K+1)."""
    @property
    def order(self) -> int: ...
    @property
    def interpolating(self) -> bool: ...
    @property
    def control_points(self) -> Floats: ...

class CubicSpline(Curve):
    """A C^2 cubic interpolating spline through points (n, d)."""

    def __init__(
        self,
        points: ArrayLike,
        t: Optional[ArrayLike] = None,
        parameterization: str = "chord",
        bc: Optional[Bc] = None,
    ) -> None:
        """bc: 'not-a-knot' (default), 'natural', 'periodic' or ('clamped', d0, d1);
        parameterization: 'uniform', 'chord', 'centripetal' (ignored when t is given)."""
    @property
    def knots(self) -> Floats: ...
    @property
    def values(self) -> Floats: ...
    @property
    def slopes(self) -> Floats: ...

class HermiteSpline(Curve):
    """A C^1 cubic Hermite spline on [0, 1], the result of fit_curve."""

    max_distance: float
    rms_distance: float
    jump_sum: float
    tolerance_met: Optional[bool]
    @property
    def knots(self) -> Floats: ...
    @property
    def values(self) -> Floats: ...
    @property
    def derivatives(self) -> Floats: ...
    @property
    def parameters(self) -> Floats: ...
    @property
    def distances(self) -> Floats: ...

def fit_curve(
    points: ArrayLike,
    knots: Union[None, int, ArrayLike] = None,
    tolerance: Optional[float] = None,
    eps: Optional[float] = None,
    pin_ends: bool = False,
    corners: Optional[Sequence[float]] = None,
    fairness: Optional[float] = None,
) -> HermiteSpline:
    """Fits points (n, d) with a C^1 cubic Hermite spline; give knots (count or array) or tolerance."""

class Surface:
    """Base class of every surface: S(u, v, grid=True) -> points."""

    def __call__(
        self, u: Params, v: Params, grid: bool = True, out: Optional[Floats] = None
    ) -> Floats:
        """grid=True: (mu, mv, d) on u x v; grid=False: u.shape + (d,) at the pairs (u, v)."""
    def derivative(
        self,
        u: Params,
        v: Params,
        ku: int = 1,
        kv: int = 0,
        grid: bool = True,
        out: Optional[Floats] = None,
    ) -> Floats: ...
    def sample(self, nu: int, nv: int) -> Floats: ...
    def section(
        self,
        normal: Sequence[float],
        offset: float,
        tolerance: Optional[float] = None,
        cells: Tuple[int, int] = (64, 64),
    ) -> "list[SectionCurve]":
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

class LLSurface(Surface):
    """The LL approximation of a grid (nu, nv, d)."""

    def __init__(
        self, grid: ArrayLike, order: int = 5, closed_u: bool = False, closed_v: bool = False
    ) -> None: ...
    @staticmethod
    def interpolate(
        grid: ArrayLike, order: int = 5, closed_u: bool = False, closed_v: bool = False
    ) -> "LLSurface": ...
    @property
    def order(self) -> int: ...
    @property
    def interpolating(self) -> bool: ...

class BicubicSurface(Surface):
    """Bicubic (C^2, not-a-knot or periodic) interpolation of a grid (nu, nv, d)."""

    def __init__(
        self,
        grid: ArrayLike,
        parameterization: str = "chord",
        closed_u: bool = False,
        closed_v: bool = False,
    ) -> None:
        """parameterization: 'uniform', 'chord', 'averaged-chord', 'centripetal'."""
    @staticmethod
    def from_knots(
        grid: ArrayLike,
        knots_u: ArrayLike,
        knots_v: ArrayLike,
        closed_u: bool = False,
        closed_v: bool = False,
    ) -> "BicubicSurface": ...
    @property
    def knots_u(self) -> Floats: ...
    @property
    def knots_v(self) -> Floats: ...

class DiscreteSpline:
    """A closed discrete curve: N = m n periodic values of a discrete spline of order r."""

    def __init__(self, poles: ArrayLike, order: int = 3, n: int = 10) -> None: ...
    @staticmethod
    def interpolate(nodes: ArrayLike, order: int = 3, n: int = 10) -> "DiscreteSpline": ...
    def values(self, out: Optional[Floats] = None) -> Floats:
        """The N values, (m n, d)."""
    @property
    def poles(self) -> Floats: ...
    @property
    def order(self) -> int: ...
    @property
    def n(self) -> int: ...
    @property
    def period(self) -> int: ...
    @property
    def dim(self) -> int: ...

class TubeSurface:
    """A closed tube through a skeleton of closed discrete curves."""

    def __init__(
        self, along: ArrayLike, across: ArrayLike, n1: int, n2: int, r1: int = 3, r2: int = 3
    ) -> None: ...
    def values(self) -> Floats:
        """c(p, q), (N1, N2, d)."""
    def closed_grid(self) -> Floats:
        """The values with the seams repeated, (N1 + 1, N2 + 1, d)."""

class SectionCurve:
    """One connected piece of a plane section: a polyline on the surface."""

    closed: bool
    length: float
    @property
    def points(self) -> Floats:
        """(n, d)."""
    @property
    def params(self) -> Floats:
        """The surface parameters (u, v) of the points, (n, 2)."""
    def __len__(self) -> int: ...

class CoonsSurface(Surface):
    """Generalized Coons surfaces over a network of curves given by points."""

    kind: str
    def __init__(
        self,
        v_curves: Sequence[ArrayLike],
        u_curves: Sequence[ArrayLike],
        kind: str = "gordon-spline",
        u_derivs: Optional[Sequence[ArrayLike]] = None,
        v_derivs: Optional[Sequence[ArrayLike]] = None,
        fit: Union[None, str, Tuple[str, int]] = None,
        crossing_tolerance: float = 1e-6,
        tolerance: float = 1e-4,
    ) -> None:
        """kind: 'bilinear', 'bicubic', 'gordon', 'gordon-spline', 'composite'."""

class ImplicitSurface:
    """An implicit surface F(x, y, z) = 0 given as an expression."""

    def __init__(self, expression: str) -> None: ...
    @property
    def expression(self) -> str: ...
    def value(self, points: ArrayLike) -> Floats: ...
    def gradient(self, points: ArrayLike) -> Floats: ...
    def project(self, points: ArrayLike) -> Floats: ...
    def curvatures(self, point: Sequence[float]) -> dict:
        """normal, k1, k2, d1, d2, gaussian, mean."""
    def trace_net(
        self,
        start: Sequence[float],
        nodes: Tuple[int, int],
        steps: Tuple[float, float],
        directions: str = "principal",
        angle: float = 0.0,
        plane_normal: Optional[Sequence[float]] = None,
        closed_v: bool = False,
        substeps: int = 32,
    ) -> Floats:
        """A node grid (nu, nv, 3) on F = 0 along lines of curvature (or turned nets)."""

def hausdorff(a: ArrayLike, b: ArrayLike) -> dict:
    """Two-sided Hausdorff distance of point sets (n, 3), (m, 3): distance, forward, backward."""

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
) -> Floats:
    """The least change of matrix with the given row and column sums (LL surface variation)."""

def curve_parameters(points: ArrayLike, parameterization: str = "chord") -> Floats: ...
def grid_parameters(grid: ArrayLike, parameterization: str = "chord") -> Tuple[Floats, Floats]: ...
def export_obj(path: Union[str, "os.PathLike[str]"], grid: ArrayLike) -> None: ...
def export_stl(path: Union[str, "os.PathLike[str]"], grid: ArrayLike) -> None: ...
def export_curve_csv(path: Union[str, "os.PathLike[str]"], t: ArrayLike, points: ArrayLike) -> None: ...
def export_surface_csv(
    path: Union[str, "os.PathLike[str]"], u: ArrayLike, v: ArrayLike, grid: ArrayLike
) -> None: ...

FilePath = Union[str, "os.PathLike[str]"]

def read_curve(path: FilePath) -> Floats:
    """The ordered points of a curve file, (n, d) with d 2 or 3, as the command line's curve
    commands read it: CSV (an optional header naming x, y and optionally z), whitespace
    columns, or an airfoil .dat (Selig or Lednicer).

    Raises OSError (FileNotFoundError, PermissionError, IsADirectoryError) when the file
    cannot be opened, FileFormatError ("file:line: ...") when its content cannot be read."""

def read_airfoil(path: FilePath) -> Tuple[str, Floats]:
    """An airfoil .dat file (Selig or Lednicer): its name line and its contour (n, 2) in Selig
    order (trailing edge, upper surface, leading edge, lower surface, trailing edge)."""

def read_grid(path: FilePath) -> Floats:
    """A surface frame, CSV rows i,j,x,y,z, as an (m, n, 3) array: grid[i, j] is cell (i, j)."""

def read_network(path: FilePath) -> list[Floats]:
    """One family of curves of a curve network, CSV rows curve,x,y,z: one (k, 3) array per
    curve, in the order of the curve numbers (0, 1, ...)."""

def read_mesh(path: FilePath) -> Tuple[Floats, NDArray[np.int64]]:
    """A triangle mesh (.obj, .stl binary or ASCII, .ply, by extension): vertices (n, 3)
    float64 and faces (m, 3) int64 indexing the vertices from 0."""

def set_max_input_bytes(nbytes: int) -> None:
    """The most memory one read may keep, in bytes, for every reader of the process (default
    2 GiB, as the command line's --max-memory); a larger input raises FileFormatError."""

def max_input_bytes() -> int:
    """The most memory one read may keep, in bytes (see set_max_input_bytes)."""
