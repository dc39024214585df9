#!/usr/bin/env python3
"""An independent rebuild of Kuznetsov and Filatov's frames (docs/methods.md §5) in NumPy and
SciPy: the nodes in closed form (lines of curvature, a generator or meridian turned by a
constant angle with its step stretched by 1/cos, the cylinder's helix frame), chord-length
parameters through node (0, 0), SciPy's CubicSpline with 'not-a-knot' or 'natural' ends in
both directions, and the interpolant's largest distance to the exact surface on the demo's
64 x 160 samples (the forward direction of the Hausdorff distance; on these frames the
backward direction is below it).

Usage: python3 tests/demo/kf_rebuild.py   (prints the table)
       or import it: rebuild() -> {row label: error}
"""
import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.interpolate import CubicSpline

TAU = 2 * np.pi


def interpolant(nodes, ends, samples=(64, 160)):
    """The bicubic interpolant of `nodes` (rows u, columns v) on a uniform parameter grid."""
    us = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(nodes[:, 0], axis=0), axis=1))])
    vs = np.concatenate([[0], np.cumsum(np.linalg.norm(np.diff(nodes[0, :], axis=0), axis=1))])
    along_u = CubicSpline(us, nodes, axis=0, bc_type=ends)(np.linspace(0, us[-1], samples[0]))
    return CubicSpline(vs, along_u, axis=1, bc_type=ends)(np.linspace(0, vs[-1], samples[1]))


def cylinder_distance(x):
    return np.abs(np.hypot(x[..., 0], x[..., 1]) - 1)


def hyperboloid_distance(x):
    """Distance to x^2 + y^2 - z^2 = 1: Newton on the meridian hyperbola r = sqrt(1 + t^2)."""
    r, z = np.hypot(x[..., 0], x[..., 1]), x[..., 2]
    t = z.copy()
    for _ in range(50):
        s = np.sqrt(1 + t * t)
        g = -(r - s) * t / s - (z - t)
        t = t - g / ((t / s) ** 2 - (r - s) / s**3 + 1)
    s = np.sqrt(1 + t * t)
    return np.hypot(r - s, z - t)


def cylinder_generator(degrees):
    """5 x 9: circles z = 0.5 i, the generator turned into a helix (step 0.5 / cos a)."""
    i, j = np.arange(5)[:, None], np.arange(9)[None, :]
    phi = j * TAU / 8 + 0.5 * i * np.tan(np.radians(degrees))
    return np.stack([np.cos(phi), np.sin(phi), 0.5 * i + 0 * j], -1)


def cylinder_helices(degrees):
    """5 x 9 open: both families turned (constant-angle helices), steps 0.5 and 2 pi / 8."""
    a = np.radians(degrees)
    s, t = 0.5 * np.arange(5)[:, None], TAU / 8 * np.arange(9)[None, :]
    phi = s * np.sin(a) + t * np.cos(a)
    return np.stack([np.cos(phi), np.sin(phi), s * np.cos(a) - t * np.sin(a)], -1)


def hyperboloid_meridian(degrees):
    """5 x 9 from (sqrt(1.25), 0, -0.5): circles, the meridian turned into a loxodrome whose
    meridian arc advances a quarter of the meridian from z = -0.5 to 0.5 a node."""
    length = quad(lambda z: np.sqrt(1 + z * z / (1 + z * z)), -0.5, 0.5)[0]
    sigma = np.arange(5) * length / 4
    tan = np.tan(np.radians(degrees))

    def rhs(_, y):
        r = np.sqrt(1 + y[0] ** 2)
        return [1 / np.sqrt(1 + y[0] ** 2 / r**2), tan / r]

    sol = solve_ivp(rhs, [0, sigma[-1]], [-0.5, 0.0], t_eval=sigma, rtol=1e-12, atol=1e-14)
    z, start = sol.y[0][:, None], sol.y[1][:, None]
    phi = start + np.arange(9)[None, :] * TAU / 8
    r = np.sqrt(1 + z * z)
    return np.stack([r * np.cos(phi), r * np.sin(phi), z + 0 * phi], -1)


FRAMES = {
    "cylinder, lines of curvature": (lambda: cylinder_generator(0), cylinder_distance),
    "cylinder, generator turned 30 deg": (lambda: cylinder_generator(30), cylinder_distance),
    "cylinder, generator turned 45 deg": (lambda: cylinder_generator(45), cylinder_distance),
    "cylinder, helices turned 30 deg": (lambda: cylinder_helices(30), cylinder_distance),
    "hyperboloid, lines of curvature": (lambda: hyperboloid_meridian(0), hyperboloid_distance),
    "hyperboloid, meridian turned 68 deg": (lambda: hyperboloid_meridian(68), hyperboloid_distance),
}

SWEEP = {
    f"cylinder, generator turned {d} deg": (lambda d=d: cylinder_generator(d), cylinder_distance)
    for d in (60, 75)
}


def rebuild():
    """{report label: error}: the table's frames with both end conditions (labels as in
    report.json without the '004 ' prefix) and the sweep's steep generators ('sweep: ...')."""
    out = {}
    for label, (frame, distance) in FRAMES.items():
        nodes = frame()
        out[label] = distance(interpolant(nodes, "not-a-knot")).max()
        out[label + ", natural ends"] = distance(interpolant(nodes, "natural")).max()
    for label, (frame, distance) in SWEEP.items():
        out["sweep: " + label] = distance(interpolant(frame(), "not-a-knot")).max()
    return out


if __name__ == "__main__":
    for label, error in rebuild().items():
        print(f"{label:52s} {error:.5f}")
