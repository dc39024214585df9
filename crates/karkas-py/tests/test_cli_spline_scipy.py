"""`karkas curve spline` against SciPy's `CubicSpline(t, points, bc_type=...)`: on the same
points, with the parameters computed here from their formulas (uniform, chord, centripetal),
the CLI's CSV rows t,x,y[,z] equal SciPy's spline at those t (to 1e-12 relative), for every
end condition: not-a-knot, natural, clamped (first derivatives) and periodic (the first
point appended when the last does not repeat it); and `karkas.CubicSpline` with the same
options (and both defaults) is the same curve.

The binary is $KARKAS_BIN, else target/release/karkas of this repository (build it with
`cargo build --release -p karkas-cli`); without it these tests are skipped."""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
from scipy.interpolate import CubicSpline

REPO = Path(__file__).resolve().parents[3]
BIN = Path(os.environ.get("KARKAS_BIN", REPO / "target" / "release" / "karkas"))

pytestmark = pytest.mark.skipif(not BIN.is_file(), reason=f"no karkas binary at {BIN}")

RTOL = 1e-12


def run_spline(tmp_path, pts, *options):
    """The CLI's CSV rows for the spline through pts (written to a file) with options."""
    src = tmp_path / "pts.csv"
    out = tmp_path / "spline.csv"
    header = "x,y,z"[: 2 * pts.shape[1] - 1]
    np.savetxt(src, pts, delimiter=",", header=header, comments="", fmt="%.17g")
    args = [str(BIN), "curve", "spline", str(src), "-o", str(out), "--samples", "157"]
    done = subprocess.run([*args, *map(str, options)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with open(out) as f:
        assert f.readline().strip() == "t," + header
    return np.loadtxt(out, delimiter=",", skiprows=1, ndmin=2)


def parameters(pts, rule):
    """The formulas: t_0 = 0, steps 1, |p_k - p_{k-1}| or its square root."""
    chords = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    steps = {"uniform": np.ones_like(chords), "chord": chords, "centripetal": np.sqrt(chords)}
    return np.concatenate([[0.0], np.cumsum(steps[rule])])


def assert_matches(rows, t, pts, bc_type):
    ref = CubicSpline(t, pts, bc_type=bc_type)
    assert rows[0, 0] == 0.0
    np.testing.assert_allclose(rows[-1, 0], t[-1], rtol=RTOL)
    expected = ref(rows[:, 0])
    scale = max(1.0, float(np.max(np.abs(expected))))
    np.testing.assert_allclose(rows[:, 1:], expected, rtol=RTOL, atol=RTOL * scale)


def components(d):
    """X,Y[,Z] as the options take it."""
    return ",".join(f"{v:.17g}" for v in d)


def wavy(n, dim):
    s = np.linspace(0.0, 3.0, n) ** 1.3
    cols = [np.cos(s) * (1 + 0.3 * np.sin(5 * s)), np.sin(2 * s) + 0.1 * s, 0.2 * np.cos(3 * s)]
    return np.column_stack(cols[:dim])


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("rule", ["uniform", "chord", "centripetal"])
@pytest.mark.parametrize("ends", ["not-a-knot", "natural"])
def test_named_ends_match_scipy(tmp_path, dim, rule, ends):
    pts = wavy(13, dim)
    rows = run_spline(tmp_path, pts, "--ends", ends, "--param", rule)
    assert_matches(rows, parameters(pts, rule), pts, ends)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("rule", ["chord", "centripetal"])
def test_clamped_matches_scipy(tmp_path, dim, rule):
    pts = wavy(9, dim)
    d0 = np.array([0.5, -2.0, 1.5])[:dim]
    d1 = np.array([-1.0, 0.25, 3.0])[:dim]
    rows = run_spline(
        tmp_path, pts, "--ends", "clamped", "--param", rule,
        f"--start-tangent={components(d0)}", f"--end-tangent={components(d1)}",
    )
    assert_matches(rows, parameters(pts, rule), pts, ((1, d0), (1, d1)))


@pytest.mark.parametrize("dim", [2, 3])
def test_periodic_matches_scipy_with_the_first_point_appended(tmp_path, dim):
    a = np.linspace(0.0, 2 * np.pi, 10, endpoint=False)
    pts = np.column_stack([np.cos(a) * (1.5 + 0.4 * np.cos(3 * a)), np.sin(a), 0.3 * np.sin(2 * a)])
    pts = pts[:, :dim]
    rows = run_spline(tmp_path, pts, "--ends", "periodic")
    closed = np.vstack([pts, pts[:1]])
    assert_matches(rows, parameters(closed, "chord"), closed, "periodic")
    # Given closed, the same curve.
    again = run_spline(tmp_path, closed, "--ends", "periodic")
    np.testing.assert_array_equal(again, rows)


@pytest.mark.parametrize(
    "options, bc",
    [
        ((), None),
        (("--ends", "natural", "--param", "uniform"), "natural"),
        (("--ends", "periodic", "--param", "centripetal"), "periodic"),
        (("--ends", "clamped", "--start-tangent=1,-2,0.5", "--end-tangent=0,3,1"),
         ("clamped", [1.0, -2.0, 0.5], [0.0, 3.0, 1.0])),
    ],
)
def test_the_python_class_builds_the_same_curve(tmp_path, options, bc):
    """karkas.CubicSpline with the same options (and the same defaults) is the CLI's curve."""
    karkas = pytest.importorskip("karkas")
    pts = wavy(11, 3)
    rows = run_spline(tmp_path, pts, *options)
    rule = options[options.index("--param") + 1] if "--param" in options else None
    kwargs = {"parameterization": rule} if rule else {}
    if bc is not None:
        kwargs["bc"] = bc
    curve = karkas.CubicSpline(pts, **kwargs)
    assert curve.domain[1] == rows[-1, 0]
    expected = curve(rows[:, 0])
    np.testing.assert_allclose(rows[:, 1:], expected, rtol=RTOL, atol=RTOL * np.max(np.abs(expected)))
