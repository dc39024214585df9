"""`.npy` output of the command line read with NumPy: `karkas curve ll -o c.npy` loads with
`np.load` as an (n, dim) float64 array equal to the x,y,z columns of the CSV the same command
writes, and `karkas surface ll -o s.npy` as an (nu, nv, 3) array equal to the CSV's x,y,z with
`u` outer."""

import subprocess

import numpy as np
import pytest


from cli_binary import CLI, needs_cli


def run_cli(*args):
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done


@needs_cli
def test_curve_ll_npy_equals_the_csv(tmp_path):
    s = np.linspace(0.0, 6.0, 50)
    pts = np.column_stack([np.cos(s), np.sin(s), 0.1 * s])
    np.savetxt(tmp_path / "p.csv", pts, delimiter=",", header="x,y,z", comments="")
    for ext in ("csv", "npy"):
        run_cli("curve", "ll", tmp_path / "p.csv", "--samples", 100003, "-o", tmp_path / f"c.{ext}")
    array = np.load(tmp_path / "c.npy")
    table = np.loadtxt(tmp_path / "c.csv", delimiter=",", skiprows=1)
    assert array.shape == (100003, 3) and array.dtype == np.float64
    assert np.array_equal(array, table[:, 1:])


@needs_cli
def test_surface_ll_npy_equals_the_csv(tmp_path):
    rows = [f"{i},{j},{i},{j},{float(np.sin(0.5 * i) * np.cos(0.4 * j))!r}" for i in range(5) for j in range(6)]
    (tmp_path / "g.csv").write_text("i,j,x,y,z\n" + "\n".join(rows) + "\n")
    for ext in ("csv", "npy"):
        run_cli("surface", "ll", tmp_path / "g.csv", "--samples", "40,1700", "-o", tmp_path / f"s.{ext}")
    array = np.load(tmp_path / "s.npy")
    table = np.loadtxt(tmp_path / "s.csv", delimiter=",", skiprows=1)
    assert array.shape == (40, 1700, 3) and array.dtype == np.float64
    assert np.array_equal(array.reshape(-1, 3), table[:, 2:])
    # u outer: the first 1700 rows of the CSV share one u.
    assert np.all(table[:1700, 0] == table[0, 0])
