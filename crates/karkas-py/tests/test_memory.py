"""karkas.max_memory: requests whose size the caller gives are refused with MemoryError before
anything is allocated, and an allocation NumPy cannot make is NumPy's MemoryError, never an
abort of the interpreter or a PanicException.

The four defects below aborted the interpreter (sample, fit_curve) or raised PanicException
(DiscreteSpline.values, a surface grid); each runs in a subprocess so that an abort fails the
test instead of killing pytest."""

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import karkas

PRELUDE = """
import resource, numpy as np, karkas
resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))
pts = np.column_stack([np.linspace(0, 1, 20), np.sin(np.linspace(0, 3, 20)), np.cos(np.linspace(0, 2, 20))])
u, v = np.meshgrid(np.linspace(0, 1, 6), np.linspace(0, 1, 7), indexing="ij")
grid = np.stack([u, v, u * v], axis=-1)
"""


def run_isolated(code):
    """Runs `code` after PRELUDE in a fresh interpreter; returns (exit status, output)."""
    env = dict(os.environ, RUST_BACKTRACE="0", OPENBLAS_NUM_THREADS="1")
    done = subprocess.run(
        [sys.executable, "-c", PRELUDE + textwrap.dedent(code)],
        capture_output=True,
        text=True,
        timeout=300,
        env=env,
    )
    return done.returncode, done.stdout + done.stderr


def expect_memory_error(call, *words):
    status, output = run_isolated(
        f"""
        try:
            {call}
        except MemoryError as e:
            print("MemoryError:", e)
        """
    )
    assert status == 0, f"exit status {status}:\n{output[-2000:]}"
    assert "MemoryError:" in output, output[-2000:]
    for word in words:
        assert word in output, output
    return output


def test_sampling_a_curve_at_10_12_points_is_a_memory_error():
    out = expect_memory_error("karkas.LLCurve(pts).sample(10**12)", "sample(1000000000000)", "max_memory")
    # The estimate (parameters and 3-D points, 8 bytes each) and the default cap are named.
    assert "32000000000000 bytes" in out and "2147483648 bytes" in out


def test_a_fit_with_10_9_knots_is_a_memory_error():
    expect_memory_error("karkas.fit_curve(pts, knots=10**9)", "knots=1000000000", "max_memory")


def test_the_values_of_a_discrete_spline_with_n_10_9_is_a_memory_error():
    expect_memory_error("karkas.DiscreteSpline(pts, n=10**9).values()", "DiscreteSpline.values()")


def test_a_surface_grid_numpy_cannot_allocate_is_a_memory_error():
    # Under the cap (removed here), NumPy's own allocation fails: MemoryError, no panic.
    expect_memory_error(
        """karkas.max_memory = None
            S = karkas.LLSurface(grid)
            S(np.linspace(0, 1, 10**5), np.linspace(0, 1, 10**5))""",
    )


def test_the_surface_grid_above_the_cap_names_its_shape():
    expect_memory_error(
        "karkas.LLSurface(grid)(np.linspace(0, 1, 10**5), np.linspace(0, 1, 10**5))",
        "(100000, 100000, 3)",
    )


def test_the_default_cap_is_the_command_lines():
    status, output = run_isolated("print(karkas.max_memory)")
    assert status == 0 and output.split()[-1] == str(2 << 30)


def test_karkas_max_memory_environment_variable_sets_the_default():
    env = dict(os.environ, KARKAS_MAX_MEMORY="512M")
    done = subprocess.run(
        [sys.executable, "-c", "import karkas; print(karkas.max_memory)"], capture_output=True, text=True, env=env
    )
    assert done.stdout.split()[-1] == str(512 << 20)


@pytest.fixture
def cap():
    saved = karkas.max_memory
    yield
    karkas.max_memory = saved


def test_the_cap_is_read_at_every_check(cap):
    c = karkas.LLCurve(np.column_stack([np.linspace(0, 1, 10), np.linspace(0, 1, 10) ** 2]))
    assert c.sample(200_000).shape == (200_000, 2)
    karkas.max_memory = 1 << 20
    with pytest.raises(MemoryError, match="Curve.sample"):
        c.sample(200_000)
    # Small requests are not checked at all.
    assert c.sample(1000).shape == (1000, 2)
    karkas.max_memory = None
    assert c.sample(200_000).shape == (200_000, 2)


@pytest.mark.parametrize("bad, error", [(-1, ValueError), (0, ValueError), ("2G", TypeError), (1.5, TypeError)])
def test_a_bad_cap_is_refused_when_used(cap, bad, error):
    c = karkas.LLCurve(np.column_stack([np.linspace(0, 1, 10), np.linspace(0, 1, 10) ** 2]))
    karkas.max_memory = bad
    with pytest.raises(error, match="max_memory"):
        c.sample(200_000)


def test_every_sized_request_is_checked(cap):
    karkas.max_memory = 1 << 20
    pts = np.column_stack([np.linspace(0, 1, 12), np.sin(np.linspace(0, 3, 12)), np.linspace(0, 1, 12) ** 2])
    u, v = np.meshgrid(np.linspace(0, 1, 6), np.linspace(0, 1, 7), indexing="ij")
    S = karkas.LLSurface(np.stack([u, v, u * v], axis=-1))
    calls = {
        "Curve.sample": lambda: karkas.LLCurve(pts).sample(10**6),
        "Curve.__call__": lambda: karkas.LLCurve(pts)(np.broadcast_to(0.5, (10**6,))),
        "Surface.sample": lambda: S.sample(1000, 1000),
        "Surface.__call__ du=1": lambda: S(np.linspace(0, 1, 1000), np.linspace(0, 1, 1000), 1, 0),
        "Surface.section": lambda: S.section([0, 0, 1], 0.2, cells=(10**4, 10**4)),
        "fit_curve": lambda: karkas.fit_curve(pts, knots=10**5),
        "fit_curve knots array": lambda: karkas.fit_curve(pts, knots=np.linspace(0, 1, 10**5)),
        "DiscreteSpline.values": lambda: karkas.DiscreteSpline(pts, n=10**5).values(),
        "DiscreteSpline.interpolate": lambda: karkas.DiscreteSpline.interpolate(pts, n=10**6),
        "trace_net": lambda: karkas.ImplicitSurface("x^2+y^2+z^2-1").trace_net([1, 0, 0], (10**4, 10**4), (0.1, 0.1)),
        "hausdorff_to_implicit": lambda: karkas.hausdorff_to_implicit(
            S, karkas.ImplicitSurface("z"), [[0, 0, 0], [1, 1, 0]], samples=(10**4, 10**4)
        ),
        "broadcast input": lambda: karkas.LLCurve(np.broadcast_to(pts[:1], (10**6, 3))),
    }
    for name, call in calls.items():
        with pytest.raises(MemoryError, match="max_memory"):
            call()
            pytest.fail(name)


@pytest.mark.parametrize(
    "call, error",
    [
        (lambda c: c.sample(-1), OverflowError),
        (lambda c: c.sample(10**30), OverflowError),
        (lambda c: c.sample(2.5), TypeError),
        (lambda c: c.sample("3"), TypeError),
        (lambda c: c.sample(True), TypeError),
        (lambda c: karkas.ImplicitSurface("x^2+y^2+z^2-1").trace_net([1, 0, 0], (True, 3), (0.1, 0.1)), TypeError),
        (lambda c: c(0.5, -1), karkas.OptionError),
        (lambda c: c.derivative(-1), karkas.OptionError),
        (lambda c: karkas.LLCurve(c.control_points, order=10**30), OverflowError),
        (lambda c: karkas.LLCurve(c.control_points, order=10**6), karkas.OptionError),
        (lambda c: karkas.LLCurve(c.control_points, order=-1), karkas.OptionError),
        (lambda c: karkas.DiscreteSpline(c.control_points, n=0), karkas.OptionError),
        (lambda c: karkas.fit_curve(c.control_points, knots=-5), karkas.KnotsError),
        (lambda c: karkas.fit_curve(c.control_points, tolerance=0.0), ValueError),
        (lambda c: karkas.fit_curve(c.control_points, tolerance=float("nan")), ValueError),
    ],
)
def test_bad_integers_and_values_raise_errors(call, error):
    c = karkas.LLCurve(np.column_stack([np.linspace(0, 1, 10), np.linspace(0, 1, 10) ** 2]))
    with pytest.raises(error):
        call(c)
