"""Every public callable of karkas, found by introspection, gets a valid call and a sweep of
hostile calls; no call may crash the interpreter, raise ``PanicException`` or raise an
exception outside the documented ones.

- The public API is ``karkas.__all__``: its functions, its classes (called as constructors),
  and every public method and property of every class (keyed by the class that defines it,
  e.g. ``Curve.sample``). A callable added later is found automatically; the test fails until
  it has an entry in ``VALID`` below (a valid call), so that it is swept too.
- The hostile sweep replaces each argument of the valid call in turn by each of ``HOSTILE``
  (None, strings, nan, inf, negative, zero, huge and overflowing integers, empty arrays, wrong
  shapes and dtypes, Fortran-ordered, strided, read-only and broadcast views of huge shape,
  objects whose ``__array__`` raises), and also calls with no arguments and with one argument
  too many. Properties are also assigned to (they are read-only). ``nested_calls`` puts
  hostile values inside otherwise valid arguments (a clamped end's vector, a curve of a
  network, a tuple of counts).
- Each callable is swept in its own subprocess, with ``resource.RLIMIT_AS`` at a few GiB and
  ``karkas.max_memory`` lowered, so that a crash (a signal, an abort) fails the test instead of
  killing pytest, and a runaway allocation is refused rather than swapping.

Run ``python test_hostile.py NAME`` to sweep one callable by hand.
"""

import json
import math
import os
import subprocess
import sys
from types import SimpleNamespace

import numpy as np
import pytest

import karkas

# -- The public API, by introspection --------------------------------------------------------


def _is_exception(obj):
    return isinstance(obj, type) and issubclass(obj, BaseException)


def public_callables():
    """Names of every public callable: 'fit_curve', 'LLCurve' (its constructor),
    'LLCurve.interpolate', 'Curve.sample', 'Curve.domain' (a property), ..."""
    names = []
    for name in karkas.__all__:
        obj = getattr(karkas, name)
        if _is_exception(obj):
            continue
        if isinstance(obj, type):
            names.append(name)
            for attr in dir(obj):
                if attr.startswith("_") and attr not in ("__call__", "__len__", "__getitem__", "__iter__"):
                    continue
                owner = next((c for c in obj.__mro__ if attr in c.__dict__), None)
                if owner is obj:
                    names.append(f"{name}.{attr}")
        elif callable(obj):
            names.append(name)
    return names


def is_property(name):
    if "." not in name:
        return False
    cls, attr = name.split(".", 1)
    return isinstance(getattr(karkas, cls).__dict__[attr], property) or type(
        getattr(karkas, cls).__dict__[attr]
    ).__name__ in ("getset_descriptor", "member_descriptor")


# -- Valid inputs ----------------------------------------------------------------------------


def _curve_points(n=20, d=3):
    s = np.linspace(0.0, 3.0, n)
    cols = [np.cos(s) * (1 + 0.2 * s), np.sin(s), 0.3 * np.cos(2 * s)]
    return np.column_stack(cols[:d])


def _grid(nu=6, nv=7):
    u, v = np.meshgrid(np.linspace(0, 1, nu), np.linspace(0, 2, nv), indexing="ij")
    return np.stack([u, v, np.sin(2 * u) * np.cos(v)], axis=-1)


def _cylinder_grid(nu=7, nv=9):
    """A grid on the cylinder x^2 + y^2 = 1 along helices (no umbilic point, unlike _grid)."""
    s, t = np.meshgrid(0.15 * np.arange(nu), 0.15 * np.arange(nv), indexing="ij")
    angle, z = 0.5 * s + 0.87 * t, 0.87 * s - 0.5 * t
    return np.stack([np.cos(angle), np.sin(angle), z], axis=-1)


def _torus_skeleton(m1=4, m2=6, n1=4, n2=4, R=3.0, r=1.0):
    N1, N2 = m1 * n1, m2 * n2

    def torus(p, q):
        a, b = np.broadcast_arrays(2 * np.pi * np.asarray(p) / N1, 2 * np.pi * np.asarray(q) / N2)
        return np.stack([(R + r * np.cos(a)) * np.cos(b), (R + r * np.cos(a)) * np.sin(b), r * np.sin(a)], -1)

    along = np.stack([torus(i * n1, np.arange(N2)) for i in range(m1)])
    across = np.stack([torus(np.arange(N1), j * n2) for j in range(m2)])
    return along, across


def _windio_blade(profile):
    """A windIO 2 file of a blade 20 long with `profile` at its root and tip."""
    coordinates = f"{{x: {profile[:, 0].tolist()}, y: {profile[:, 1].tolist()}}}"
    return f"""windIO_version: '2.0'
components:
  blade:
    reference_axis:
      x: {{grid: [0.0, 1.0], values: [0.0, 0.0]}}
      y: {{grid: [0.0, 1.0], values: [0.0, 0.0]}}
      z: {{grid: [0.0, 1.0], values: [0.0, 20.0]}}
    outer_shape:
      chord: {{grid: [0.0, 1.0], values: [2.0, 0.8]}}
      twist: {{grid: [0.0, 1.0], values: [10.0, 0.0]}}
      section_offset_y: {{grid: [0.0, 1.0], values: [0.5, 0.2]}}
      airfoils:
        - {{name: root, spanwise_position: 0.0}}
        - {{name: tip, spanwise_position: 1.0}}
airfoils:
  - {{name: root, coordinates: {coordinates}}}
  - {{name: tip, coordinates: {coordinates}}}
"""


def _network():
    s = np.linspace(0.0, 1.0, 5)
    xs = ys = np.linspace(0.0, 1.0, 3)
    v = [np.column_stack([np.full_like(s, x), s, x**2 + s**2]) for x in xs]
    u = [np.column_stack([s, np.full_like(s, y), s**2 + y**2]) for y in ys]
    return v, u


def fixtures(directory):
    """The objects and files the valid calls use, made in `directory`."""
    o = SimpleNamespace()
    o.dir = directory
    o.pts3 = _curve_points()
    o.pts2 = _curve_points(d=2)
    o.grid = _grid()
    o.curve = karkas.LLCurve(o.pts3, order=3)
    o.llcurve = o.curve
    o.cubic = karkas.CubicSpline(o.pts3)
    o.hermite = karkas.fit_curve(o.pts3, knots=5)
    o.surface = karkas.LLSurface(o.grid, order=3)
    o.llsurface = o.surface
    o.bicubic = karkas.BicubicSurface(o.grid)
    o.coons = karkas.CoonsSurface(**dict(zip(("v_curves", "u_curves"), _network())))
    o.curve_derivative = o.curve.derivative(1)
    o.surface_derivative = o.surface.derivative(1, 0)
    o.dps = karkas.DiscreteSpline(o.pts3[:8], order=2, n=4)
    o.along, o.across = _torus_skeleton()
    o.tube = karkas.TubeSurface(o.along, o.across, 4, 4, 2, 2)
    o.implicit = karkas.ImplicitSurface("x^2 + y^2 + z^2 - 4")
    o.plane = karkas.ImplicitSurface("z - 1")
    o.plane_points = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 2.0, 1.0], [1.0, 2.0, 1.0]])
    o.sphere_points = np.array([[2.0, 0.1, 0.2], [0.1, 2.1, 0.0], [0.0, 0.3, -1.9]])
    o.section = o.surface.section([0.0, 0.0, 1.0], 0.1)[0]
    o.curve_csv = os.path.join(directory, "curve.csv")
    karkas.export_curve_csv(o.curve_csv, np.arange(20.0), o.pts3)
    o.grid_csv = os.path.join(directory, "grid.csv")
    with open(o.grid_csv, "w") as f:
        f.write("i,j,x,y,z\n")
        for i in range(o.grid.shape[0]):
            for j in range(o.grid.shape[1]):
                f.write(f"{i},{j}," + ",".join(repr(float(x)) for x in o.grid[i, j]) + "\n")
    o.network_csv = os.path.join(directory, "network.csv")
    with open(o.network_csv, "w") as f:
        f.write("curve,x,y,z\n")
        for c, curve in enumerate(_network()[0]):
            for p in curve:
                f.write(f"{c}," + ",".join(repr(float(x)) for x in p) + "\n")
    o.airfoil = os.path.join(directory, "foil.dat")
    x = np.linspace(1.0, 0.0, 9)
    upper = np.column_stack([x, 0.06 * np.sqrt(x) * (1 - x)])
    lower = np.column_stack([x[::-1][1:], -upper[::-1][1:, 1]])
    with open(o.airfoil, "w") as f:
        f.write("TEST FOIL\n")
        for p in np.vstack([upper, lower]):
            f.write(f"{p[0]:.6f} {p[1]:.6f}\n")
    o.obj = os.path.join(directory, "s.obj")
    karkas.export_obj(o.obj, o.grid)
    o.out_path = os.path.join(directory, "out")
    o.skeleton_csv = os.path.join(directory, "along.csv")
    with open(o.skeleton_csv, "w") as f:
        f.write("i,q,x,y,z\n")
        for i, line in enumerate(o.along):
            for q, p in enumerate(line):
                f.write(f"{i},{q}," + ",".join(repr(float(x)) for x in p) + "\n")
    o.samples_csv = os.path.join(directory, "samples.csv")
    karkas.export(o.surface, o.samples_csv, samples=(4, 5))
    w = np.sqrt(0.5)
    o.nurbs_curve = karkas.NurbsCurve([[1, 0, 0], [1, 1, 0], [0, 1, 0]], [0, 0, 0, 1, 1, 1], 2, [1, w, 1])
    ring = [[1, 0], [1, 1], [0, 1]]
    o.nurbs_grid = np.array([[[x, y, 0.0], [x, y, 2.0]] for x, y in ring])
    o.nurbs_surface = karkas.NurbsSurface(o.nurbs_grid, [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], 2, 1, [[1, 1], [w, w], [1, 1]])
    o.step = os.path.join(directory, "s.step")
    karkas.export(o.bicubic, o.step)
    o.cad = karkas.read_cad(o.step)
    o.cad_face = o.cad.faces[0]
    o.profile = np.vstack([upper, lower])
    o.loft_surface = karkas.loft([o.profile, o.profile], [[0.0, 0.0, 0.0], [0.1, 2.0, 0.0]], [1.0, 0.8], [0.0, 1.0])
    o.fair = karkas.fair_curve(o.pts3, 0.05)
    o.windio = os.path.join(directory, "blade.yaml")
    with open(o.windio, "w") as f:
        f.write(_windio_blade(o.profile))
    o.mask_csv = os.path.join(directory, "mask.csv")
    with open(o.mask_csv, "w") as f:
        f.write("i,j\n0,0\n2,1\n")
    return o


# A valid call of every public callable: name -> f(o) giving (callable, args, kwargs), where o
# is what fixtures() made. Methods of a base class are called on one of its subclasses'
# objects. Properties need no entry (reading them is their valid call); a class that Python
# cannot construct maps to NO_CONSTRUCTOR (calling it must raise TypeError).
NO_CONSTRUCTOR = "no constructor"

VALID = {
    # Curves.
    "Curve": NO_CONSTRUCTOR,
    "Curve.__call__": lambda o: (
        o.curve, (np.linspace(0.3, 0.6, 5),), {"nu": 1, "out": None, "extrapolate": False}
    ),
    "Curve.derivative": lambda o: (o.curve.derivative, (1,), {}),
    "Curve.to_bspline": lambda o: (o.curve.to_bspline, (), {}),
    "Curve.arc_length": lambda o: (o.curve.arc_length, (0.3, 0.6), {"tol": 1e-8}),
    "Curve.inverse_arc_length": lambda o: (o.curve.inverse_arc_length, (0.1,), {"t0": 0.3}),
    "Curve.curvature": lambda o: (o.curve.curvature, (np.linspace(0.3, 0.6, 5),), {}),
    "Curve.torsion": lambda o: (o.curve.torsion, (np.linspace(0.3, 0.6, 5),), {}),
    "Curve.project": lambda o: (o.curve.project, (o.pts3[:4],), {"tol": 0.0}),
    "Curve.fairness": lambda o: (o.curve.fairness, (), {"points": o.pts3}),
    "CurveDerivative": NO_CONSTRUCTOR,
    "Curve.sample": lambda o: (o.curve.sample, (11,), {}),
    "LLCurve": lambda o: (karkas.LLCurve, (o.pts3,), {"order": 3, "closed": False}),
    "LLCurve.interpolate": lambda o: (karkas.LLCurve.interpolate, (o.pts3,), {"order": 3, "closed": False}),
    "CubicSpline": lambda o: (
        karkas.CubicSpline,
        (o.pts3,),
        {"t": None, "parameterization": "chord", "bc": "natural"},
    ),
    "HermiteSpline": lambda o: (
        karkas.HermiteSpline,
        ([0.0, 1.0], [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]),
        {},
    ),
    "fit_curve": lambda o: (
        karkas.fit_curve,
        (o.pts3,),
        {"knots": 5, "tolerance": None, "eps": None, "pin_ends": False, "corners": None, "fairness": 3e-11, "smoothing": 0.3, "free_ends": False, "closed": False},
    ),
    "curve_parameters": lambda o: (karkas.curve_parameters, (o.pts3,), {"parameterization": "chord"}),
    # Surfaces.
    "Surface": NO_CONSTRUCTOR,
    "Surface.__call__": lambda o: (
        o.surface,
        (np.linspace(0.3, 0.6, 4), np.linspace(0.3, 0.6, 3)),
        {"du": 1, "dv": 0, "grid": True, "out": None, "extrapolate": None},
    ),
    "Surface.derivative": lambda o: (o.surface.derivative, (1, 0), {}),
    "Surface.to_bspline": lambda o: (o.surface.to_bspline, (), {}),
    "Surface.normal": lambda o: (o.surface.normal, (0.4, 0.5), {"grid": False}),
    "Surface.principal_curvatures": lambda o: (
        o.surface.principal_curvatures, (0.4, 0.5), {"grid": False, "directions": True}
    ),
    "Surface.project": lambda o: (o.surface.project, (o.grid[1:3, 1],), {"cells": (8, 8)}),
    "SurfaceDerivative": NO_CONSTRUCTOR,
    "LLSurface.section": lambda o: (o.surface.section, ([0.0, 0.0, 1.0], 0.1), {"cells": None}),
    "Surface.sample": lambda o: (o.surface.sample, (5, 6), {}),
    "Surface.section": lambda o: (
        o.surface.section,
        ([0.0, 0.0, 1.0], 0.1),
        {"tolerance": None, "cells": (16, 16)},
    ),
    "LLSurface": lambda o: (karkas.LLSurface, (o.grid,), {"order": 3, "closed_u": False, "closed_v": False}),
    "LLSurface.interpolate": lambda o: (karkas.LLSurface.interpolate, (o.grid,), {"order": 3}),
    "BicubicSurface": lambda o: (karkas.BicubicSurface, (o.grid,), {"parameterization": "chord", "origin": (1, 2)}),
    "BicubicSurface.condition_measure": lambda o: (o.bicubic.condition_measure, (), {}),
    "BicubicSurface.from_knots": lambda o: (
        karkas.BicubicSurface.from_knots,
        (o.grid, np.linspace(0, 1, 6), np.linspace(0, 1, 7)),
        {},
    ),
    "CoonsSurface": lambda o: (
        karkas.CoonsSurface,
        (),
        {
            "v_curves": _network()[0],
            "u_curves": _network()[1],
            "kind": "gordon-spline",
            "crossing_tolerance": 1e-6,
            "tolerance": 1e-4,
        },
    ),
    "relay_grid": lambda o: (karkas.relay_grid, (_cylinder_grid(),), {"size": (4, 5), "start": (2, 3)}),
    "grid_parameters": lambda o: (karkas.grid_parameters, (o.grid,), {"parameterization": "chord", "origin": (1, 2)}),
    "vary": lambda o: (
        karkas.vary,
        (np.ones((3, 4)), [4.0, 4.0, 4.0], [3.0, 3.0, 3.0, 3.0]),
        {"fixed": None, "penalty": None, "scale_with_total": False},
    ),
    # Discrete splines.
    "DiscreteSpline": lambda o: (karkas.DiscreteSpline, (o.pts3[:8],), {"order": 2, "n": 4}),
    "DiscreteSpline.interpolate": lambda o: (karkas.DiscreteSpline.interpolate, (o.pts3[:8],), {"order": 2, "n": 4}),
    "DiscreteSpline.values": lambda o: (o.dps.values, (), {"out": None}),
    "TubeSurface": lambda o: (karkas.TubeSurface, (o.along, o.across, 4, 4), {"r1": 2, "r2": 2}),
    "TubeSurface.values": lambda o: (o.tube.values, (), {}),
    "TubeSurface.closed_grid": lambda o: (o.tube.closed_grid, (), {}),
    # Sections.
    "SectionCurve": NO_CONSTRUCTOR,
    "SectionCurve.__len__": lambda o: (o.section.__len__, (), {}),
    # Implicit surfaces and distances.
    "ImplicitSurface": lambda o: (karkas.ImplicitSurface, ("x^2 + y^2 + z^2 - 4",), {}),
    "ImplicitSurface.value": lambda o: (o.implicit.value, (o.sphere_points,), {}),
    "ImplicitSurface.gradient": lambda o: (o.implicit.gradient, (o.sphere_points,), {}),
    "ImplicitSurface.project": lambda o: (o.implicit.project, (o.sphere_points,), {}),
    "ImplicitSurface.curvatures": lambda o: (o.implicit.curvatures, ([2.0, 0.0, 0.0],), {}),
    "ImplicitSurface.trace_net": lambda o: (
        o.implicit.trace_net,
        ([2.0, 0.0, 0.0], (3, 4), (0.1, 0.1)),
        {"directions": "turned", "angle": 0.0, "plane_normal": None, "closed_v": False, "substeps": 4},
    ),
    "hausdorff": lambda o: (karkas.hausdorff, (o.pts3, o.pts3[::-1] * 1.1), {}),
    "hausdorff_to_implicit": lambda o: (
        karkas.hausdorff_to_implicit,
        (o.surface, o.plane, o.plane_points),
        {"samples": (8, 8)},
    ),
    # Files.
    "export_obj": lambda o: (karkas.export_obj, (o.out_path + ".obj", o.grid), {}),
    "export_stl": lambda o: (karkas.export_stl, (o.out_path + ".stl", o.grid), {}),
    "export_curve_csv": lambda o: (karkas.export_curve_csv, (o.out_path + "c.csv", np.arange(20.0), o.pts3), {}),
    "export_surface_csv": lambda o: (
        karkas.export_surface_csv,
        (o.out_path + "s.csv", np.arange(6.0), np.arange(7.0), o.grid),
        {},
    ),
    "read_curve": lambda o: (karkas.read_curve, (o.curve_csv,), {}),
    "batch": lambda o: (
        karkas.batch,
        ("curve fit", [o.airfoil, o.curve_csv], o.out_path + "-batch"),
        {"knots": 6, "format": "csv", "jobs": 1, "as_frame": False, "options": ["--eps", "1"]},
    ),
    "batch_inputs": lambda o: (karkas.batch_inputs, ([o.airfoil, o.curve_csv],), {}),
    "read_airfoil": lambda o: (karkas.read_airfoil, (o.airfoil,), {}),
    "read_grid": lambda o: (karkas.read_grid, (o.grid_csv,), {}),
    "read_network": lambda o: (karkas.read_network, (o.network_csv,), {}),
    "read_mesh": lambda o: (karkas.read_mesh, (o.obj,), {}),
    "read_skeleton": lambda o: (karkas.read_skeleton, (o.skeleton_csv,), {"across": False}),
    "read_point_set": lambda o: (karkas.read_point_set, (o.obj,), {}),
    "read_surface_samples": lambda o: (karkas.read_surface_samples, (o.samples_csv,), {}),
    "read_mask": lambda o: (karkas.read_mask, (o.mask_csv, 3, 3), {}),
    "export": lambda o: (karkas.export, (o.curve, o.out_path + "e.svg"), {"samples": 50}),
    "_restore": lambda o: (karkas._restore, ("LLCurve", (o.pts3, 3), None), {}),
    # The cap in force, so that the valid call leaves it as it was.
    "set_max_input_bytes": lambda o: (karkas.set_max_input_bytes, (karkas.max_input_bytes(),), {}),
    "max_input_bytes": lambda o: (karkas.max_input_bytes, (), {}),
    # Rational B-splines and CAD files.
    "NurbsCurve": lambda o: (
        karkas.NurbsCurve, (o.nurbs_curve.control_points, o.nurbs_curve.knots, 2), {"weights": o.nurbs_curve.weights, "closed": False}
    ),
    "NurbsSurface": lambda o: (
        karkas.NurbsSurface, (o.nurbs_grid, [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], 2, 1),
        {"weights": o.nurbs_surface.weights, "closed_u": False, "closed_v": False},
    ),
    "read_cad": lambda o: (karkas.read_cad, (o.step,), {}),
    "CadModel": NO_CONSTRUCTOR,
    "CadFace": NO_CONSTRUCTOR,
    "CadFace.contains": lambda o: (o.cad_face.contains, (0.5, 0.5), {}),
    # Lofts and fair curves.
    "loft": lambda o: (
        karkas.loft,
        ([o.profile, o.profile], [[0.0, 0.0, 0.0], [0.1, 2.0, 0.0]], [1.0, 0.8], [0.0, 1.0]),
        {"dihedrals": None, "span": "monotone", "tolerance": 1e-4},
    ),
    "loft_windio": lambda o: (karkas.loft_windio, (o.windio,), {"span": "monotone", "tolerance": 1e-4}),
    "LoftSurface": NO_CONSTRUCTOR,
    "LoftSurface.section_at": lambda o: (o.loft_surface.section_at, (1.0,), {"n": 50}),
    "fair_curve": lambda o: (
        karkas.fair_curve,
        (o.pts3, 0.05),
        {"keep_ends": False, "keep_tangents": False, "corners": None, "closed": False},
    ),
    "FairCurve": NO_CONSTRUCTOR,
    "FairCurve.report": lambda o: (o.fair.report, (), {}),
}

# The object a property is read from: class name -> attribute of fixtures().
INSTANCES = {
    "Curve": "curve",
    "CurveDerivative": "curve_derivative",
    "SurfaceDerivative": "surface_derivative",
    "LLCurve": "llcurve",
    "CubicSpline": "cubic",
    "HermiteSpline": "hermite",
    "Surface": "surface",
    "LLSurface": "llsurface",
    "BicubicSurface": "bicubic",
    "CoonsSurface": "coons",
    "DiscreteSpline": "dps",
    "TubeSurface": "tube",
    "SectionCurve": "section",
    "ImplicitSurface": "implicit",
    "NurbsCurve": "nurbs_curve",
    "NurbsSurface": "nurbs_surface",
    "CadModel": "cad",
    "CadFace": "cad_face",
    "LoftSurface": "loft_surface",
    "FairCurve": "fair",
}


# -- Hostile inputs --------------------------------------------------------------------------


class Boom(Exception):
    """Raised by HostileArray.__array__: must propagate unchanged (or as a karkas error)."""


class HostileArray:
    def __array__(self, dtype=None, copy=None):
        raise Boom("__array__ refuses")

    def __len__(self):
        raise Boom("__len__ refuses")


class HostileFloat:
    def __float__(self):
        raise Boom("__float__ refuses")

    def __index__(self):
        raise Boom("__index__ refuses")


def hostile_values():
    """(label, value) pairs, made fresh for each call (arrays may be written into)."""
    rng = np.random.default_rng(7)
    pts = rng.random((12, 3))
    fortran = np.asfortranarray(pts)
    strided = np.zeros((12, 6))[:, ::2]
    read_only = pts.copy()
    read_only.flags.writeable = False
    return [
        ("None", None),
        ("str", "x"),
        ("empty str", ""),
        ("bytes", b"\x00"),
        ("nan", math.nan),
        ("inf", math.inf),
        ("-inf", -math.inf),
        ("-1", -1),
        ("0", 0),
        ("1", 1),
        ("True", True),
        ("2.5", 2.5),
        ("1e308", 1e308),
        ("5e-324", 5e-324),
        ("10**12", 10**12),
        ("10**30", 10**30),
        ("-10**30", -(10**30)),
        ("object", object()),
        ("dict", {}),
        ("tuple", (1, 2, 3)),
        ("ragged list", [[1.0, 2.0], [3.0]]),
        ("nested list", [[1.0, 2.0, 3.0]] * 4),
        ("empty (0,)", np.empty(0)),
        ("empty (0, 3)", np.empty((0, 3))),
        ("empty (0, 0, 3)", np.empty((0, 0, 3))),
        ("(5,)", np.linspace(0.0, 1.0, 5)),
        ("(4, 7)", np.ones((4, 7))),
        ("(2, 3, 4, 3)", np.ones((2, 3, 4, 3))),
        ("complex", pts + 1j),
        ("strings", np.array([["a", "b", "c"]] * 4)),
        ("objects", np.array([[1.0, None, 2.0]] * 4, dtype=object)),
        ("datetime", np.array(["2020-01-01"] * 3, dtype="datetime64[D]")),
        ("int", np.arange(36).reshape(12, 3)),
        ("bool", np.ones((12, 3), dtype=bool)),
        ("float32", pts.astype(np.float32)),
        ("nan array", np.full((12, 3), np.nan)),
        ("inf array", np.full((12, 3), np.inf)),
        ("fortran", fortran),
        ("strided", strided),
        ("reversed", pts[::-1]),
        ("read-only", read_only),
        ("huge broadcast", np.broadcast_to(np.float64(0.5), (10**5, 10**5, 3))),
        ("huge 1-D broadcast", np.broadcast_to(np.float64(0.5), (10**11,))),
        ("__array__ raises", HostileArray()),
        ("__float__ raises", HostileFloat()),
        ("list of arrays", [pts, pts[:3]]),
        ("tuple of huge", (10**12, 10**12)),
        ("tuple of negative", (-1, -1)),
        ("3 floats", [0.0, 0.0, 0.0]),
        ("zero normal", np.zeros(3)),
    ]


ALLOWED = (ValueError, TypeError, OverflowError, MemoryError, OSError, IndexError, KeyError, Boom)


def hostile_calls(name, o):
    """(label, thunk) pairs for the hostile calls of `name`."""
    if is_property(name):
        cls, attr = name.split(".", 1)
        obj = getattr(o, INSTANCES[cls])
        for label, value in hostile_values():
            yield f"{name} = {label}", (lambda v=value: setattr(obj, attr, v)), (AttributeError, TypeError)
        return
    entry = VALID[name]
    if entry == NO_CONSTRUCTOR:
        target = getattr(karkas, name)
        yield f"{name}()", target, (TypeError,)
        for label, value in hostile_values():
            yield f"{name}({label})", (lambda v=value: target(v)), (TypeError,)
        return
    for suffix, variant in _subclass_variants(name, o):
        yield from _mutations(name + suffix, entry(variant))


# The base classes' methods are swept on an object of every concrete subclass.
SUBCLASS_OBJECTS = {"Curve": ("curve", ["llcurve", "cubic", "hermite"]), "Surface": ("surface", ["llsurface", "bicubic", "coons"])}


def _subclass_variants(name, o):
    base = name.split(".", 1)[0]
    if base not in SUBCLASS_OBJECTS or "." not in name:
        return [("", o)]
    slot, objects = SUBCLASS_OBJECTS[base]
    return [
        (f" on {type(getattr(o, a)).__name__}", SimpleNamespace(**dict(vars(o), **{slot: getattr(o, a)})))
        for a in objects
    ]


def _mutations(name, call):
    fn, args, kwargs = call
    yield f"{name}()", fn, ALLOWED
    yield f"{name}(... + extra)", (lambda: fn(*args, None, **kwargs)), ALLOWED
    for i in range(len(args)):
        for label, value in hostile_values():
            bad = list(args)
            bad[i] = value
            yield f"{name} arg {i} = {label}", (lambda b=bad: fn(*b, **kwargs)), ALLOWED
    for key in kwargs:
        for label, value in hostile_values():
            bad = dict(kwargs, **{key: value})
            yield f"{name} {key}={label}", (lambda b=bad: fn(*args, **b)), ALLOWED


def nested_calls(o):
    """Hostile values inside otherwise valid arguments (a tuple's element, a list's item)."""
    huge = np.broadcast_to(np.float64(0.5), (10**10,))
    s = np.linspace(0.0, 1.0, 5)
    v, u = _network()
    calls = {
        "bc clamped huge": lambda: karkas.CubicSpline(o.pts3, bc=("clamped", huge, [1.0, 0.0, 0.0])),
        "bc clamped complex": lambda: karkas.CubicSpline(o.pts3, bc=("clamped", [1j, 0, 0], [1.0, 0.0, 0.0])),
        "bc clamped short": lambda: karkas.CubicSpline(o.pts3, bc=("clamped", [1.0], [1.0, 0.0, 0.0])),
        "coons fit ll huge order": lambda: karkas.CoonsSurface(v, u, fit=("ll", 10**30)),
        "coons fit ll bool": lambda: karkas.CoonsSurface(v, u, fit=("ll", True)),
        "coons curve huge": lambda: karkas.CoonsSurface([v[0], np.broadcast_to(v[1][:1], (10**8, 3)), v[2]], u),
        "coons curve complex": lambda: karkas.CoonsSurface([v[0], v[1] + 1j, v[2]], u),
        "coons curves huge list": lambda: karkas.CoonsSurface(np.broadcast_to(v[0], (10**8, 5, 3)), u),
        "coons derivs short": lambda: karkas.CoonsSurface(
            v, u, kind="composite", u_derivs=[np.zeros((4, 3))] * 3, v_derivs=[np.zeros((5, 3))] * 3
        ),
        "fit corners huge": lambda: karkas.fit_curve(o.pts3, knots=5, corners=huge),
        "fit knots huge": lambda: karkas.fit_curve(o.pts3, knots=huge),
        "fit closed knots huge": lambda: karkas.fit_curve(o.pts3, knots=huge, closed=True),
        "fit closed tolerance tiny": lambda: karkas.fit_curve(o.pts3, tolerance=1e-300, closed=True),
        "fit closed two points": lambda: karkas.fit_curve(o.pts3[:2], knots=5, closed=True),
        "fit closed pinned": lambda: karkas.fit_curve(o.pts3, knots=5, closed=True, pin_ends=True),
        "vary fixed wrong shape": lambda: karkas.vary(
            np.ones((3, 4)), [4.0] * 3, [3.0] * 4, fixed=np.ones((2, 2), bool)
        ),
        "vary fixed huge": lambda: karkas.vary(
            np.ones((3, 4)), [4.0] * 3, [3.0] * 4, fixed=np.broadcast_to(True, (10**5, 10**5))
        ),
        "vary matrix huge": lambda: karkas.vary(np.broadcast_to(1.0, (10**5, 10**5)), [4.0] * 3, [3.0] * 4),
        "section cells huge": lambda: o.surface.section([0, 0, 1], 0.1, cells=(10**12, 10**12)),
        "section cells zero": lambda: o.surface.section([0, 0, 1], 0.1, cells=(0, 0)),
        "samples huge": lambda: karkas.hausdorff_to_implicit(o.surface, o.plane, o.plane_points, samples=(10**9, 10**9)),
        "trace_net steps huge": lambda: o.implicit.trace_net([2.0, 0, 0], (3, 3), (1e308, -1e308)),
        "trace_net nodes huge": lambda: o.implicit.trace_net([2.0, 0, 0], (10**9, 10**9), (0.1, 0.1)),
        "derivative order huge": lambda: o.curve.derivative(0.5, 10**12),
        "surface derivative order huge": lambda: o.surface.derivative(0.5, 0.5, 10**12, 10**12),
        "out huge broadcast": lambda: o.curve(np.linspace(0.3, 0.6, 5), out=np.broadcast_to(0.0, (5, 3))),
        "t huge broadcast": lambda: o.curve(np.broadcast_to(0.5, (10**11,))),
        "grid huge u x v": lambda: o.surface(np.broadcast_to(0.5, (10**6,)), np.broadcast_to(0.5, (10**6,))),
        "points huge broadcast": lambda: karkas.hausdorff(np.broadcast_to(o.pts3[:1], (10**10, 3)), o.pts3),
        "expression huge": lambda: karkas.ImplicitSurface("(" * 100000 + "x" + ")" * 100000),
    }
    for label, thunk in calls.items():
        yield f"nested: {label}", thunk, ALLOWED


def sweep(name, directory):
    """Runs every hostile call of `name`; returns the calls that broke the rules."""
    import warnings

    warnings.simplefilter("ignore")
    os.chdir(directory)
    o = fixtures(directory)
    failures = []
    calls = nested_calls(o) if name == "nested" else hostile_calls(name, o)
    for label, thunk, allowed in calls:
        sys.stderr.write(f"CALL {label}\n")
        sys.stderr.flush()
        try:
            thunk()
        except allowed:
            pass
        except BaseException as e:  # noqa: BLE001 - PanicException derives from BaseException
            failures.append(f"{label}: {type(e).__module__}.{type(e).__name__}: {str(e)[:300]}")
    return failures


def limit_resources():
    """A few GiB of address space and a low karkas.max_memory, for a sweep's process."""
    import resource

    cap = 4 << 30
    resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
    karkas.max_memory = 256 << 20


# -- The tests -------------------------------------------------------------------------------


def test_every_public_callable_has_a_valid_call():
    names = public_callables()
    missing = [n for n in names if n not in VALID and not is_property(n)]
    assert not missing, f"add a valid call to VALID in {__file__} for: {missing}"
    stale = [n for n in VALID if n not in names]
    assert not stale, f"VALID names callables that are not public (any more): {stale}"


@pytest.mark.parametrize("name", public_callables())
def test_the_valid_call_succeeds(name, tmp_path):
    o = fixtures(str(tmp_path))
    if is_property(name):
        cls, attr = name.split(".", 1)
        getattr(getattr(o, INSTANCES[cls]), attr)
        return
    entry = VALID.get(name)
    if entry is None:
        pytest.fail(f"no valid call for {name}")
    if entry == NO_CONSTRUCTOR:
        with pytest.raises(TypeError):
            getattr(karkas, name)()
        return
    fn, args, kwargs = entry(o)
    fn(*args, **kwargs)


@pytest.mark.parametrize("name", public_callables() + ["nested"])
def test_hostile_calls_raise_documented_errors(name, tmp_path):
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", RAYON_NUM_THREADS="2", RUST_BACKTRACE="0")
    try:
        done = subprocess.run(
            [sys.executable, os.path.abspath(__file__), name, str(tmp_path)],
            capture_output=True,
            text=True,
            timeout=600,
            env=env,
        )
    except subprocess.TimeoutExpired as e:
        err = e.stderr.decode() if isinstance(e.stderr, bytes) else (e.stderr or "")
        calls = [line[5:] for line in err.splitlines() if line.startswith("CALL ")]
        pytest.fail(f"the sweep of {name} ran for over 600 s, in: {calls[-1] if calls else '?'}")
    calls = [line[5:] for line in done.stderr.splitlines() if line.startswith("CALL ")]
    last = calls[-1] if calls else "(before the first call)"
    assert done.returncode >= 0, f"killed by signal {-done.returncode} in: {last}\n{done.stderr[-2000:]}"
    assert done.returncode == 0, f"the sweep failed in: {last}\n{done.stderr[-3000:]}"
    failures = json.loads(done.stdout.strip().splitlines()[-1])
    assert not failures, "\n".join(failures)
    assert len(calls) >= 2


if __name__ == "__main__":
    limit_resources()
    directory = sys.argv[2] if len(sys.argv) > 2 else os.getcwd()
    print(json.dumps(sweep(sys.argv[1], directory)))
