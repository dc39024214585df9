"""Curve files as spreadsheets and other tools write them, read by karkas.read_curve: ``;``
and tab separators, decimal commas, quoted fields, units and other languages in the header,
``columns=`` and ``decimal_comma=``, and the reader's warnings (karkas.KarkasWarning): a first
column that counts the rows, points far out of order, a header read in order."""

import warnings

import numpy as np
import pytest

import karkas


def contour(n=61):
    """An airfoil-like closed loop, to six decimals as the writers print it."""
    t = np.linspace(0.0, 2 * np.pi, n)
    x = 0.5 + 0.5 * np.cos(t)
    y = 0.12 * np.sin(t) * np.sqrt(1 - x)
    return np.round(np.column_stack([x, y]), 6)


def rows(points, fmt, end="\n", comma=False):
    text = "".join(fmt(f"{x:.6f}", f"{y:.6f}") + end for x, y in points)
    return text.replace(".", ",") if comma else text


def read_quietly(path, **options):
    """read_curve, failing on any warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return karkas.read_curve(path, **options)


@pytest.mark.parametrize(
    "name, text, options",
    [
        (
            "excel-de.csv",
            "\ufeffX [mm];Y [mm]\r\n" + rows(contour(), lambda x, y: f"{x};{y}", "\r\n", True),
            {},
        ),
        ("calc.txt", rows(contour(), lambda x, y: f"{x}\t{y}", comma=True), {}),
        ("quoted.csv", '"x","y"\n' + rows(contour(), lambda x, y: f'"{x}","{y}"'), {}),
        ("units.csv", "x [mm],y (mm)\n" + rows(contour(), lambda x, y: f"{x},{y}"), {}),
        (
            "quoted-commas.csv",
            rows(contour(), lambda x, y: f'"{x}","{y}"', comma=True),
            {"decimal_comma": True},
        ),
        (
            "ru.csv",
            "№;Абсцисса;Ордината\n"
            + "".join(f"{k + 1};{x:.6f};{y:.6f}\n".replace(".", ",") for k, (x, y) in enumerate(contour())),
            {"columns": ("Абсцисса", "Ордината")},
        ),
        (
            "numbered.csv",
            "".join(f"{k},{x:.6f},{y:.6f}\n" for k, (x, y) in enumerate(contour())),
            {"columns": [2, 3]},
        ),
    ],
)
def test_every_dialect_reads_the_same_points(tmp_path, name, text, options):
    path = tmp_path / name
    path.write_bytes(text.encode("utf-8"))
    np.testing.assert_array_equal(read_quietly(path, **options), contour())


def test_a_header_that_names_no_x_and_y_is_read_in_order_with_a_warning(tmp_path):
    path = tmp_path / "ru.csv"
    path.write_text("Абсцисса,Ордината\n" + rows(contour(), lambda x, y: f"{x},{y}"), encoding="utf-8")
    with pytest.warns(karkas.KarkasWarning, match="names no x and y columns: its 2 columns are read in order"):
        points = karkas.read_curve(path)
    np.testing.assert_array_equal(points, contour())


def test_a_counting_first_column_warns_once_naming_columns(tmp_path):
    path = tmp_path / "indexed.csv"
    path.write_text("".join(f"{k},{x:.6f},{y:.6f}\n" for k, (x, y) in enumerate(contour())))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        points = karkas.read_curve(path)
    assert points.shape == (61, 3)
    messages = [str(w.message) for w in caught if issubclass(w.category, karkas.KarkasWarning)]
    assert len(messages) == 1, messages
    assert "counts 0, 1, 2" in messages[0] and "columns=(2, 3)" in messages[0]


def test_shuffled_points_warn_once_and_ordered_ones_do_not(tmp_path):
    ordered = contour()
    shuffled = ordered[(37 * np.arange(61)) % 61]
    path = tmp_path / "shuffled.csv"
    path.write_text("x,y\n" + rows(shuffled, lambda x, y: f"{x},{y}"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        karkas.read_curve(path)
    messages = [str(w.message) for w in caught if issubclass(w.category, karkas.KarkasWarning)]
    assert len(messages) == 1 and "far out of order" in messages[0], messages
    path = tmp_path / "ordered.csv"
    path.write_text("x,y\n" + rows(ordered, lambda x, y: f"{x},{y}"))
    read_quietly(path)


def test_a_warning_can_be_made_an_error(tmp_path):
    path = tmp_path / "indexed.csv"
    path.write_text("".join(f"{k},{x:.6f},{y:.6f}\n" for k, (x, y) in enumerate(contour())))
    with warnings.catch_warnings():
        warnings.simplefilter("error", karkas.KarkasWarning)
        with pytest.raises(karkas.KarkasWarning):
            karkas.read_curve(path)
    assert issubclass(karkas.KarkasWarning, UserWarning)


@pytest.mark.parametrize(
    "columns, error, match",
    [
        ([1], karkas.OptionError, "two or three columns"),
        ([0, 1], karkas.OptionError, "count from 1"),
        ([1, 4], karkas.FileFormatError, "column 4 is not there"),
        (["x", "q"], karkas.FileFormatError, "no column 'q'"),
    ],
)
def test_bad_columns_are_refused_naming_them(tmp_path, columns, error, match):
    path = tmp_path / "p.csv"
    path.write_text("x,y\n0,0\n1,1\n2,0\n")
    with pytest.raises(error, match=match):
        karkas.read_curve(path, columns=columns)


def test_no_points_names_what_was_seen(tmp_path):
    path = tmp_path / "words.csv"
    path.write_text("x;y\nsee the attached drawing\n")
    with pytest.raises(karkas.FileFormatError, match="line 2 \\('see the attached drawing'\\) is not a row of 2 numbers separated by semicolons"):
        karkas.read_curve(path)
