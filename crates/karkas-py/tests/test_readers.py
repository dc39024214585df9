"""The readers: curve points, airfoils, surface frames, curve networks and meshes from files, as
the command line reads them, with the command line's messages."""

import errno
import faulthandler
import os
import pathlib
import subprocess
import threading

import numpy as np
import pytest

import karkas


def write(path, text):
    path.write_text(text)
    return path


def selig_text(name, n=9):
    """A symmetric 12%-thick section in Selig order: trailing edge, upper surface, leading
    edge, lower surface, trailing edge; coordinates as a database prints them."""
    x = (1 + np.cos(np.linspace(0.0, np.pi, n))) / 2  # 1 .. 0
    t = 0.6 * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    upper = [(a, b) for a, b in zip(x, t)]
    lower = [(a, -b) for a, b in zip(x[::-1][1:], t[::-1][1:])]
    rows = [f"  {a:.6f}  {b: .6f}" for a, b in upper + lower]
    return name + "\n" + "\n".join(rows) + "\n", np.array(upper + lower).round(6)


# --- read_curve ---------------------------------------------------------------------------


def test_a_csv_with_a_header_reads_as_points(tmp_path):
    p = write(tmp_path / "pts.csv", "x,y,z\n0,0,0\n1.5,2,-3\n1e-3,4,5.25\n")
    a = karkas.read_curve(p)
    assert a.dtype == np.float64 and a.shape == (3, 3) and a.flags["C_CONTIGUOUS"]
    np.testing.assert_array_equal(a, [[0, 0, 0], [1.5, 2, -3], [1e-3, 4, 5.25]])
    assert a.flags["WRITEABLE"]
    a[0, 0] = 7.0  # the caller's own array


def test_columns_are_taken_by_name_and_planar_points_have_two(tmp_path):
    p = write(tmp_path / "pts.csv", "# exported\nid,y,x\n1,10,20\n2,11,21\n\n3,12,22\n")
    np.testing.assert_array_equal(karkas.read_curve(str(p)), [[20, 10], [21, 11], [22, 12]])
    p = write(tmp_path / "pts.txt", "0 0\n1\t2\n  3   4  \n")
    np.testing.assert_array_equal(karkas.read_curve(p), [[0, 0], [1, 2], [3, 4]])


def test_a_path_is_str_or_path_like(tmp_path):
    p = write(tmp_path / "pts.csv", "1,2\n3,4\n")

    class Custom:
        def __fspath__(self):
            return str(p)

    for path in (str(p), p, pathlib.PurePath(p), Custom()):
        np.testing.assert_array_equal(karkas.read_curve(path), [[1, 2], [3, 4]])
    with pytest.raises(TypeError):
        karkas.read_curve(42)


def test_curve_csv_round_trip_is_exact(tmp_path, wavy3d):
    t = np.linspace(0.0, 1.0, len(wavy3d))
    karkas.export_curve_csv(tmp_path / "c.csv", t, wavy3d)
    np.testing.assert_array_equal(karkas.read_curve(tmp_path / "c.csv"), wavy3d)


def test_a_large_curve_file_reads_into_one_array(tmp_path, rng):
    points = rng.standard_normal((20000, 3))
    np.savetxt(
        tmp_path / "big.csv", points, fmt="%.17g", delimiter=",", header="x,y,z", comments=""
    )
    np.testing.assert_array_equal(karkas.read_curve(tmp_path / "big.csv"), points)


def test_dash_is_a_file_name_not_standard_input(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    write(tmp_path / "-", "1,2\n3,4\n")
    np.testing.assert_array_equal(karkas.read_curve("-"), [[1, 2], [3, 4]])


# --- read_airfoil ---------------------------------------------------------------------------


def test_a_selig_airfoil_reads_with_its_name(tmp_path):
    text, expected = selig_text("SYMMETRIC 12% SECTION")
    name, points = karkas.read_airfoil(write(tmp_path / "sym12.dat", text))
    assert name == "SYMMETRIC 12% SECTION"
    assert points.shape == (17, 2) and points.dtype == np.float64
    np.testing.assert_array_equal(points, expected)
    # The curve reader sees the same contour.
    np.testing.assert_array_equal(karkas.read_curve(tmp_path / "sym12.dat"), expected)


def test_a_lednicer_airfoil_reads_in_selig_order(tmp_path):
    text = (
        "CAMBERED TEST SECTION\n"
        "       4.       4.\n"
        "\n"
        " 0.0000000 0.0000000\n 0.2500000 0.0800000\n 0.6000000 0.0600000\n 1.0000000 0.0010000\n"
        "\n"
        " 0.0000000 0.0000000\n 0.2500000 -0.0300000\n"
        " 0.6000000 -0.0200000\n 1.0000000 -0.0010000\n"
    )
    name, points = karkas.read_airfoil(write(tmp_path / "cts.dat", text))
    assert name == "CAMBERED TEST SECTION"
    expected = [
        [1, 0.001],
        [0.6, 0.06],
        [0.25, 0.08],
        [0, 0],
        [0.25, -0.03],
        [0.6, -0.02],
        [1, -0.001],
    ]
    np.testing.assert_array_equal(points, expected)


def test_an_airfoil_needs_its_name_line(tmp_path):
    p = write(tmp_path / "noname.dat", "1 0\n0.5 0.05\n0 0\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_airfoil(p)
    assert str(e.value) == f"{p}:1: expected the airfoil name line, found numbers"


# --- read_grid ------------------------------------------------------------------------------


def grid_text(grid, order):
    rows = ["i,j,x,y,z"]
    for i, j in order:
        rows.append(f"{i},{j}," + ",".join(repr(float(c)) for c in grid[i, j]))
    return "\n".join(rows) + "\n"


def test_a_grid_csv_reads_as_an_m_n_3_array_in_any_row_order(tmp_path, rng):
    grid = rng.random((4, 5, 3))
    cells = [(i, j) for i in range(4) for j in range(5)]
    order = [cells[k] for k in rng.permutation(len(cells))]
    g = karkas.read_grid(write(tmp_path / "frame.csv", grid_text(grid, order)))
    assert g.shape == (4, 5, 3) and g.dtype == np.float64 and g.flags["C_CONTIGUOUS"]
    np.testing.assert_array_equal(g, grid)
    # The surfaces take it as it is.
    assert karkas.LLSurface(g, order=3).sample(6, 7).shape == (6, 7, 3)


def test_a_grid_cell_given_twice_or_missing_is_named(tmp_path):
    p = write(tmp_path / "g.csv", "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,1,1,1,0\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_grid(p)
    assert str(e.value) == f"{p}: grid cell (i=1, j=0): missing"
    p = write(tmp_path / "g.csv", "i,j,x,y,z\n0,0,0,0,0\n0,0,0,1,0\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_grid(p)
    assert str(e.value) == f"{p}: grid cell (i=0, j=0): given twice, on lines 2 and 3"


# --- read_network ---------------------------------------------------------------------------


def test_a_network_csv_reads_as_one_array_per_curve(tmp_path):
    s = np.linspace(0.0, 1.0, 4)
    curves = [np.column_stack([s, np.full(4, v), np.sin(s + v)]) for v in (0.0, 0.5, 1.0)]
    rows = ["curve,x,y,z"]
    for c in (2, 0, 1):  # blocks in any order
        rows += [f"{c}," + ",".join(repr(float(x)) for x in p) for p in curves[c]]
    family = karkas.read_network(write(tmp_path / "u.csv", "\n".join(rows) + "\n"))
    assert isinstance(family, list) and len(family) == 3
    for got, expected in zip(family, curves):
        assert got.shape == (4, 3) and got.dtype == np.float64
        np.testing.assert_array_equal(got, expected)


def test_a_network_curve_that_resumes_is_refused_with_its_line(tmp_path):
    p = write(tmp_path / "u.csv", "curve,x,y,z\n0,0,0,0\n1,0,1,0\n0,1,0,0\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_network(p)
    assert str(e.value) == (
        f"{p}:4: curve 0 resumes here, but its points began on line 2 and another curve came "
        "in between (give each curve's points together)"
    )


# --- read_mesh ------------------------------------------------------------------------------

CUBE_OBJ = """# Blender v2.93 OBJ File: ''
# www.blender.org
mtllib cube.mtl
o Cube
v 1.000000 1.000000 -1.000000
v 1.000000 -1.000000 -1.000000
v 1.000000 1.000000 1.000000
v 1.000000 -1.000000 1.000000
v -1.000000 1.000000 -1.000000
v -1.000000 -1.000000 -1.000000
v -1.000000 1.000000 1.000000
v -1.000000 -1.000000 1.000000
vt 0.625000 0.500000
vt 0.875000 0.500000
vt 0.875000 0.750000
vt 0.625000 0.750000
vn 0.0000 1.0000 0.0000
vn 0.0000 0.0000 1.0000
vn -1.0000 0.0000 0.0000
vn 0.0000 -1.0000 0.0000
vn 1.0000 0.0000 0.0000
vn 0.0000 0.0000 -1.0000
usemtl Material
s off
f 1/1/1 5/2/1 7/3/1 3/4/1
f 4/1/2 3/2/2 7/3/2 8/4/2
f 8/1/3 7/2/3 5/3/3 6/4/3
f 6/1/4 2/2/4 4/3/4 8/4/4
f 2/1/5 1/2/5 3/3/5 4/4/5
f 6/1/6 5/2/6 1/3/6 2/4/6
"""

SQUARE_STL = """solid square
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 1 1 0
    endloop
  endfacet
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 1 0
      vertex 0 1 0
    endloop
  endfacet
endsolid square
"""


def test_an_obj_of_quads_reads_as_triangles(tmp_path):
    vertices, faces = karkas.read_mesh(write(tmp_path / "cube.obj", CUBE_OBJ))
    assert vertices.shape == (8, 3) and vertices.dtype == np.float64
    assert faces.shape == (12, 3) and faces.dtype == np.int64
    assert faces.min() == 0 and faces.max() == 7
    np.testing.assert_array_equal(np.abs(vertices), np.ones((8, 3)))
    # Six square faces of area 4: twelve triangles of area 2.
    a, b, c = (vertices[faces[:, k]] for k in range(3))
    np.testing.assert_allclose(np.linalg.norm(np.cross(b - a, c - a), axis=1) / 2, 2.0)


def test_an_ascii_stl_reads_as_its_triangles(tmp_path):
    vertices, faces = karkas.read_mesh(write(tmp_path / "square.stl", SQUARE_STL))
    assert faces.shape == (2, 3) and vertices.shape[1] == 3
    triangles = vertices[faces]
    expected = np.array([[[0, 0, 0], [1, 0, 0], [1, 1, 0]], [[0, 0, 0], [1, 1, 0], [0, 1, 0]]])
    np.testing.assert_array_equal(triangles, expected)


def test_meshes_written_by_karkas_read_back(tmp_path):
    x = np.linspace(0.0, 1.0, 4)
    X, Y = np.meshgrid(x, x[:3], indexing="ij")
    grid = np.stack([X, Y, X * Y], axis=-1)
    karkas.export_obj(tmp_path / "s.obj", grid)
    vertices, faces = karkas.read_mesh(tmp_path / "s.obj")
    np.testing.assert_array_equal(vertices, grid.reshape(-1, 3))
    assert faces.shape == (12, 3)
    karkas.export_stl(tmp_path / "s.stl", grid)
    vertices, faces = karkas.read_mesh(tmp_path / "s.stl")
    assert faces.shape == (12, 3)
    corners = vertices[faces].reshape(-1, 3)
    # Binary STL holds float32: every corner is one of the grid's points to that precision.
    d = np.linalg.norm(corners[:, None, :] - grid.reshape(1, -1, 3), axis=2).min(axis=1)
    assert d.max() < 1e-6


def test_a_file_that_is_not_a_mesh_is_refused(tmp_path):
    p = write(tmp_path / "cube.txt", CUBE_OBJ)
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_mesh(p)
    assert str(e.value) == f"{p}: not a mesh file (use .obj, .stl or .ply)"
    p = write(tmp_path / "bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_mesh(p)
    assert str(e.value) == f"{p}:3: index 9 does not name one of the 2 vertices defined so far"


# --- errors ---------------------------------------------------------------------------------

READERS = [
    karkas.read_curve,
    karkas.read_airfoil,
    karkas.read_grid,
    karkas.read_network,
    karkas.read_mesh,
]


@pytest.mark.parametrize("reader", READERS, ids=lambda r: r.__name__)
def test_a_missing_file_is_file_not_found_error(tmp_path, reader):
    p = tmp_path / "missing.obj"
    with pytest.raises(FileNotFoundError) as e:
        reader(p)
    assert e.value.errno == errno.ENOENT and e.value.filename == str(p)
    assert str(e.value) == f"[Errno 2] No such file or directory: '{p}'"
    assert not isinstance(e.value, ValueError)


@pytest.mark.parametrize("reader", READERS, ids=lambda r: r.__name__)
def test_a_directory_is_is_a_directory_error(tmp_path, reader):
    d = tmp_path / "folder.stl"
    d.mkdir()
    with pytest.raises(IsADirectoryError) as e:
        reader(d)
    assert e.value.errno == errno.EISDIR and e.value.filename == str(d)


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="needs a non-root POSIX user")
def test_an_unreadable_file_is_permission_error(tmp_path):
    p = write(tmp_path / "secret.csv", "1,2\n3,4\n")
    p.chmod(0)
    with pytest.raises(PermissionError) as e:
        karkas.read_curve(p)
    assert e.value.errno == errno.EACCES and e.value.filename == str(p)


def test_a_bad_number_names_its_line_and_column(tmp_path):
    p = write(tmp_path / "pts.csv", "x,y\n0,0\n1,abc\n2,0\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_curve(p)
    assert str(e.value) == f"{p}:3: 'abc' is not a number (column 2)"
    assert isinstance(e.value, karkas.KarkasError) and isinstance(e.value, ValueError)
    p = write(tmp_path / "g.csv", "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,inf\n")
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_grid(p)
    assert str(e.value) == f"{p}:3: non-finite value 'inf' in column 5"


@pytest.mark.parametrize("reader", READERS, ids=lambda r: r.__name__)
def test_binary_garbage_is_refused_at_its_line(tmp_path, reader):
    garbage = b"x,y,z\n1,2,3\n" + bytes(range(256)) * 64
    p = tmp_path / "garbage.obj"
    p.write_bytes(garbage)
    with pytest.raises(karkas.FileFormatError) as e:
        reader(p)
    assert (
        str(e.value)
        == f"{p}:3: binary data (a NUL byte): expected a text file, one line per record"
    )


def test_text_that_is_not_utf8_is_refused_at_its_line(tmp_path):
    p = tmp_path / "latin1.csv"
    p.write_bytes("x,y\n0,0\n1,2 # Ma\u00dfe\n".encode("latin-1"))
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_curve(p)
    assert str(e.value).startswith(f"{p}:3: not UTF-8 text")


def test_an_endless_line_is_refused_after_one_mib(tmp_path):
    p = tmp_path / "long.csv"
    p.write_bytes(b"7" * (3 << 20))
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_curve(p)
    assert str(e.value).startswith(f"{p}:1: line longer than 1 MiB")


def test_the_memory_cap_bounds_what_a_read_keeps(tmp_path):
    p = write(
        tmp_path / "g.csv",
        "i,j,x,y,z\n" + "".join(f"{i},{j},{i},{j},0\n" for i in range(3) for j in range(3)),
    )
    assert karkas.max_input_bytes() == 2 << 30
    try:
        karkas.set_max_input_bytes(64)
        assert karkas.max_input_bytes() == 64
        with pytest.raises(karkas.FileFormatError) as e:
            karkas.read_grid(p)
        assert str(e.value).startswith(f"{p}: the input needs more than the memory cap of 64 bytes")
    finally:
        karkas.set_max_input_bytes(2 << 30)
    assert karkas.read_grid(p).shape == (3, 3, 3)
    for bad in (0, -1, 1 << 64):
        with pytest.raises(karkas.OptionError):
            karkas.set_max_input_bytes(bad)


def test_the_readers_have_signatures_and_stubs():
    stubs = (pathlib.Path(__file__).parent.parent / "karkas.pyi").read_text()
    for f in READERS + [karkas.set_max_input_bytes, karkas.max_input_bytes]:
        assert f.__name__ in karkas.__all__
        assert f.__text_signature__ in (
            "(path)",
            "(nbytes)",
            "()",
            "(path, *, columns=None, decimal_comma=False)",
        )
        assert "Returns\n-------" in f.__doc__  # numpy style; the signature is __text_signature__
        assert f"def {f.__name__}(" in stubs
    assert "class FileFormatError(KarkasError)" in stubs


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes")
def test_a_pipe_is_read_in_one_pass_with_the_gil_released(tmp_path):
    """A reader blocked on a named pipe leaves the interpreter to other threads (the writer
    here), and reads what arrives in one pass."""
    fifo = tmp_path / "frame.csv"
    os.mkfifo(fifo)
    result = {}

    def read():
        try:
            result["grid"] = karkas.read_grid(fifo)
        except Exception as e:  # reported below
            result["error"] = e

    # Were the GIL held while the reader waits for a writer, this test would hang: end the
    # process with a traceback instead.
    faulthandler.dump_traceback_later(120, exit=True)
    try:
        reader = threading.Thread(target=read, daemon=True)
        reader.start()
        with open(fifo, "w") as f:
            f.write("i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,0,1,0,0\n1,1,1,1,1\n")
        reader.join(60)
        if reader.is_alive():  # a second open of the pipe: let it finish, then fail
            with open(fifo, "w"):
                pass
            reader.join(60)
            pytest.fail("the reader opened the pipe twice")
    finally:
        faulthandler.cancel_dump_traceback_later()
    assert "error" not in result, result.get("error")
    np.testing.assert_array_equal(result["grid"][1, 1], [1, 1, 1])


# --- the same messages as the command line --------------------------------------------------


def karkas_cli():
    """The command-line program of the same source tree: `$KARKAS_CLI`, or
    target/release/karkas when it is newer than every Rust source of the tree (a program
    built from other sources would not give the same messages)."""
    if os.environ.get("KARKAS_CLI"):
        return os.environ["KARKAS_CLI"]
    root = pathlib.Path(__file__).resolve().parents[3]
    program = root / "target" / "release" / "karkas"
    if not program.is_file():
        return None
    built = program.stat().st_mtime
    sources = (root / "crates").rglob("*.rs")
    if any(source.stat().st_mtime > built for source in sources):
        return None
    return str(program)


BAD_FILES = [
    (
        karkas.read_curve,
        "pts.csv",
        "x,y\n0,0\n1,abc\n2,0\n",
        ["curve", "ll", "pts.csv", "-o", "out.csv"],
    ),
    (
        karkas.read_curve,
        "pts.csv",
        "x,y\n0,0\n1,nan\n2,0\n",
        ["curve", "ll", "pts.csv", "-o", "out.csv"],
    ),
    # A header naming no x and y columns is read by position (with a warning); a cell that is
    # not a number is refused, naming the line and column.
    (karkas.read_curve, "pts.csv", "a,b\n0,zero\n", ["curve", "ll", "pts.csv", "-o", "out.csv"]),
    (karkas.read_curve, "pts.csv", "", ["curve", "ll", "pts.csv", "-o", "out.csv"]),
    (karkas.read_curve, "none.csv", None, ["curve", "ll", "none.csv", "-o", "out.csv"]),
    (
        karkas.read_grid,
        "g.csv",
        "i,j,x,y,z\nzero,1,0,1,0\n",
        ["surface", "ll", "g.csv", "-o", "out.csv"],
    ),
    (karkas.read_grid, "g.csv", "i,j,x,y\n0,0,0,0\n", ["surface", "ll", "g.csv", "-o", "out.csv"]),
    (
        karkas.read_network,
        "u.csv",
        "curve,x,y,z\n0,0,0,0\n2,1,0,0\n",
        [
            "surface",
            "coons",
            "--kind",
            "bilinear",
            "--u-curves",
            "u.csv",
            "--v-curves",
            "u.csv",
            "-o",
            "out.csv",
        ],
    ),
    (karkas.read_mesh, "m.obj", "v 0 0 0\nv 1 0\n", ["convert", "m.obj", "out.stl"]),
    (karkas.read_mesh, "m.stl", "solid x\nendsolid x\n", ["convert", "m.stl", "out.obj"]),
]


@pytest.mark.parametrize("reader,name,text,args", BAD_FILES)
def test_messages_are_the_command_lines(tmp_path, monkeypatch, reader, name, text, args):
    cli = karkas_cli()
    if cli is None:
        pytest.skip("the karkas program is not built from these sources (cargo build --release)")
    monkeypatch.chdir(tmp_path)
    if text is not None:
        write(tmp_path / name, text)
    with pytest.raises((karkas.FileFormatError, OSError)) as e:
        reader(name)
    run = subprocess.run([cli, *args], capture_output=True, text=True, timeout=60)
    assert run.returncode == 2
    if isinstance(e.value, OSError):
        assert e.value.filename == name and e.value.strerror in run.stderr
    else:
        assert run.stderr == f"karkas: error: {e.value}\n"


# --- files as other tools write them ---------------------------------------------------------


PAIRS = "1 0\n0.5 0.05\n0 0\n0.5 -0.05\n1 0\n"
CONTOUR = np.array([[1, 0], [0.5, 0.05], [0, 0], [0.5, -0.05], [1, 0]])


@pytest.mark.parametrize(
    "name,text",
    [
        ("notes.dat", f"MY FOIL\n{PAIRS}\nsource: http://x\nThickness: 7.99%\nZZ\n"),
        ("notes-at-once.dat", f"MY FOIL\n{PAIRS}20 nov 2005\n"),
        ("comma.dat", f"NACA 63,3-418\n{PAIRS}"),
        ("comma.txt", f"NACA 63,3-418\n{PAIRS}"),
        ("preamble.dat", f"ORNITHOPTER\nOrnithopter airfoil\n{PAIRS}"),
        ("mses.dat", f"TASOPT SECTION\n-2.0 3.0 -2.0 2.0\n{PAIRS}"),
        ("blocks.dat", "FOIL\n1 0\n0.5 0.05\n\n0 0\n\n0.5 -0.05\n1 0\n"),
    ],
)
def test_airfoils_as_found_are_read(tmp_path, name, text):
    got_name, points = karkas.read_airfoil(write(tmp_path / name, text))
    assert got_name == text.splitlines()[0]
    np.testing.assert_array_equal(points, CONTOUR)
    np.testing.assert_array_equal(karkas.read_curve(tmp_path / name), CONTOUR)


@pytest.mark.parametrize(
    "text,message",
    [
        (f"FOIL\n1 0\n0.0 ......\n{PAIRS}", ":3: '......' is not a number (column 2)"),
        ("FOIL\n1 0\n1.0 (0.0022)\n", ":3: '(0.0022)' is not a number (column 2)"),
        (f"FOIL\n{PAIRS}ZZ\n0.3 0.1\n", ":8: a point after the notes that begin on line 7"),
    ],
)
def test_damaged_airfoils_are_refused_naming_the_line(tmp_path, text, message):
    p = write(tmp_path / "a.dat", text)
    with pytest.raises(karkas.FileFormatError) as e:
        karkas.read_airfoil(p)
    assert str(e.value).startswith(f"{p}{message}")


def facet(a, b, c, eol):
    corners = "".join(f"      vertex {p[0]} {p[1]} {p[2]}{eol}" for p in (a, b, c))
    return f"  facet normal 0 0 1{eol}    outer loop{eol}{corners}    endloop{eol}  endfacet{eol}"


def test_meshes_from_other_tools_are_read(tmp_path):
    o, x, y, xy = (0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)
    # A bare `solid`, CRLF ends, then a second solid `solid<TAB>name`: both solids read.
    stl = (
        "solid\r\n" + facet(o, x, xy, "\r\n") + "endsolid\r\n"
        "solid\tlid\r\n" + facet(o, xy, y, "\r\n") + "endsolid\tlid\r\n"
    )
    vertices, faces = karkas.read_mesh(write(tmp_path / "two.stl", stl))
    assert (vertices.shape, faces.shape) == ((4, 3), (2, 3))
    # OBJ vertex colours and a quad with texture and normal indices.
    obj = "mtllib m.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 1 1 1\n" \
        "vt 0 0\nvn 0 0 1\ng quad\nusemtl red\nf 1/1/1 2/1/1 3/1/1 4/1/1\n"
    vertices, faces = karkas.read_mesh(write(tmp_path / "scan.obj", obj))
    np.testing.assert_array_equal(vertices, [o, x, xy, y])
    assert faces.shape == (2, 3)
    # PLY with float32/uint8 type names, comments, colours and a list property on the face.
    ply = (
        "ply\nformat ascii 1.0\ncomment made by a scanner\nobj_info sample\n"
        "element vertex 4\nproperty float32 x\nproperty float32 y\nproperty float32 z\n"
        "property uint8 red\nelement face 1\nproperty list uint8 int32 vertex_indices\n"
        "property list uchar float texcoord\nend_header\n"
        "0 0 0 255\n1 0 0 0\n1 1 0 9\n0 1 0 7\n4 0 1 2 3 2 0.5 0.5\n"
    )
    vertices, faces = karkas.read_mesh(write(tmp_path / "scan.ply", ply))
    np.testing.assert_array_equal(vertices, [o, x, xy, y])
    assert faces.shape == (2, 3)
    with pytest.raises(karkas.FileFormatError, match="not a PLY file: the first line is 'solid x'"):
        karkas.read_mesh(write(tmp_path / "fake.ply", "solid x\n"))
