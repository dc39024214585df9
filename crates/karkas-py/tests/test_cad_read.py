"""Reading CAD files (karkas.read_cad) and rational B-splines (NurbsCurve, NurbsSurface):
round trips through karkas's own STEP and IGES files, exact conics against closed forms,
bad files raising FileFormatError with the line and the entity."""

import os

import numpy as np
import pytest

import karkas

W = np.sqrt(0.5)


def quarter_circle():
    return karkas.NurbsCurve([[1, 0, 0], [1, 1, 0], [0, 1, 0]], [0, 0, 0, 1, 1, 1], 2, [1, W, 1])


def test_a_rational_quarter_circle_is_exact_with_its_derivatives():
    c = quarter_circle()
    t = np.linspace(0.0, 1.0, 101)
    p, d1, d2 = c(t), c(t, 1), c(t, 2)
    np.testing.assert_allclose(np.linalg.norm(p, axis=1), 1.0, atol=1e-15)
    # On a circle the tangent is square to the radius, and |p x p'| = |p'|.
    np.testing.assert_allclose(np.einsum("ij,ij->i", p, d1), 0.0, atol=1e-14)
    # d/dt (p . p') = |p'|^2 + p . p'' = 0.
    np.testing.assert_allclose(np.einsum("ij,ij->i", d1, d1) + np.einsum("ij,ij->i", p, d2), 0.0, atol=1e-13)
    assert c.rational and c.degree == 2
    with pytest.raises(karkas.NoBSplineFormError):
        c.to_bspline()
    # Outside the domain the end pieces continue; extrapolate=False gives NaN.
    assert np.isfinite(c(1.2)).all() and np.isnan(c(1.2, extrapolate=False)).all()


def test_equal_weights_are_the_polynomial_bspline(tmp_path):
    pts = np.array([[0, 0], [1, 2], [2, 1], [3, 3], [4, 0]], float)
    spline = karkas.CubicSpline(pts)
    t, coefs, k = spline.to_bspline()
    n = karkas.NurbsCurve(coefs, t, k, np.full(len(coefs), 3.0))
    s = np.linspace(*spline.domain, 57)
    np.testing.assert_allclose(n(s), spline(s), atol=1e-13)
    np.testing.assert_allclose(n(s, 2), spline(s, 2), atol=1e-11)
    assert not n.rational


@pytest.mark.parametrize("ext", ["step", "igs"])
def test_karkas_files_read_back_bit_for_bit(tmp_path, ext):
    pts = np.array([[0, 0], [1, 2], [2, 1], [3, 3], [4, 0], [5, 1]], float)
    ll = karkas.LLCurve(pts, order=2)
    path = str(tmp_path / f"c.{ext}")
    karkas.export(ll, path)
    m = karkas.read_cad(path)
    assert (len(m.curves), len(m.faces), m.warning) == (1, 0, None)
    assert m.format == ("step" if ext == "step" else "iges")
    t, coefs, k = ll.to_bspline()
    c = m.curves[0]
    assert c.degree == k
    assert np.array_equal(c.knots, t)
    assert np.array_equal(c.control_points[:, :2], coefs) and not c.control_points[:, 2].any()
    assert np.array_equal(c.weights, np.ones(len(coefs)))
    grid = np.array([[[i, j, np.sin(i + 0.3 * j)] for j in range(5)] for i in range(4)], float)
    surface = karkas.BicubicSurface(grid)
    path = str(tmp_path / f"s.{ext}")
    karkas.export(surface, path)
    face = karkas.read_cad(path).faces[0]
    (tu, tv), coefs, (ku, kv) = surface.to_bspline()
    S = face.surface
    assert S.degrees == (ku, kv)
    assert np.array_equal(S.knots_u, tu) and np.array_equal(S.knots_v, tv)
    assert np.array_equal(S.control_points, coefs)
    u, v = np.linspace(*S.domain_u, 7), np.linspace(*S.domain_v, 9)
    np.testing.assert_allclose(S(u, v), surface(u, v), atol=1e-12)
    assert face.contains(*np.mean([S.domain_u, S.domain_v], axis=1))


def test_pickled_nurbs_evaluate_alike():
    import pickle

    c = quarter_circle()
    back = pickle.loads(pickle.dumps(c))
    t = np.linspace(-0.1, 1.1, 13)
    assert np.array_equal(back(t), c(t)) and np.array_equal(back.weights, c.weights)


def test_bad_files_name_the_line_and_the_entity(tmp_path):
    good = tmp_path / "c.step"
    karkas.export(karkas.CubicSpline([[0, 0], [1, 2], [2, 1], [3, 3]]), str(good))
    text = good.read_text()
    cases = {
        "truncated": text[: len(text) // 2],
        "dangling": text.replace("B_SPLINE_CURVE_WITH_KNOTS('c_0',3,(#", "B_SPLINE_CURVE_WITH_KNOTS('c_0',3,(#999999,#"),
        "arity": text.replace(".UNSPECIFIED.,.F.,.F.,(", ".UNSPECIFIED.,.F.,("),
        "binary": text[:200] + "\x00\x01\x02" + text[200:],
    }
    for name, bad in cases.items():
        path = tmp_path / f"{name}.step"
        path.write_text(bad)
        with pytest.raises(karkas.FileFormatError) as e:
            karkas.read_cad(str(path))
        message = str(e.value)
        assert f"{name}.step:" in message, (name, message)
        if name in ("dangling", "arity"):
            assert "B_SPLINE_CURVE_WITH_KNOTS" in message and "#" in message, (name, message)
    with pytest.raises(FileNotFoundError):
        karkas.read_cad(str(tmp_path / "missing.step"))
    other = tmp_path / "points.csv"
    other.write_text("x,y\n1,2\n")
    with pytest.raises(karkas.FileFormatError, match="not a CAD file"):
        karkas.read_cad(str(other))
