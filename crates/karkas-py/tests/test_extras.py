"""Sections, Coons/Gordon surfaces, implicit surfaces, Hausdorff, variation, parameters."""

import numpy as np
import pytest

import karkas


def paraboloid_network(m=5, k=9):
    """v-curves at x = const (listed by increasing x), u-curves at y = const; z = x^2 + y^2."""
    xs = np.linspace(-1.0, 1.0, m)
    ys = np.linspace(-1.0, 1.0, m)
    s = np.linspace(-1.0, 1.0, (m - 1) * (k - 1) // (m - 1) * (m - 1) + 1)
    v_curves = [np.column_stack([np.full_like(s, x), s, x**2 + s**2]) for x in xs]
    u_curves = [np.column_stack([s, np.full_like(s, y), s**2 + y**2]) for y in ys]
    return v_curves, u_curves


@pytest.mark.parametrize("kind", ["gordon-spline", "gordon", "composite"])
def test_coons_surfaces_reproduce_a_paraboloid(kind):
    v, u = paraboloid_network()
    S = karkas.CoonsSurface(u_curves=u, v_curves=v, kind=kind)
    assert isinstance(S, karkas.Surface) and S.kind == kind
    P = S.sample(17, 13)
    tol = 1e-12 if kind.startswith("gordon") else 2e-2
    np.testing.assert_allclose(P[..., 2], P[..., 0] ** 2 + P[..., 1] ** 2, atol=tol)
    assert "CoonsSurface" in repr(S) and kind in repr(S)


def test_bilinear_coons_of_four_segments_is_the_bilinear_patch():
    s = np.linspace(0.0, 1.0, 5)
    corners = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 1.0], [0.0, 1.0, 0.5], [1.0, 1.0, 3.0]])

    def seg(a, b):
        return a + s[:, None] * (b - a)

    v = [seg(corners[0], corners[2]), seg(corners[1], corners[3])]  # x = 0, x = 1
    u = [seg(corners[0], corners[1]), seg(corners[2], corners[3])]  # y = 0, y = 1
    S = karkas.CoonsSurface(u_curves=u, v_curves=v, kind="bilinear")
    P = S.sample(6, 7)
    x, y = P[..., 0], P[..., 1]
    z = (1 - x) * (1 - y) * 0.0 + x * (1 - y) * 1.0 + (1 - x) * y * 0.5 + x * y * 3.0
    np.testing.assert_allclose(P[..., 2], z, atol=1e-12)


def test_coons_errors():
    v, u = paraboloid_network()
    with pytest.raises(ValueError, match="unknown kind"):
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="hermite")
    with pytest.raises(ValueError):
        karkas.CoonsSurface(u_curves=[c + [0.0, 0.0, 1.0] for c in u], v_curves=v)  # curves do not cross
    with pytest.raises(ValueError, match="both"):
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="composite", u_derivs=u)


def test_bicubic_coons_without_derivatives_warns_naming_them():
    v, u = paraboloid_network()
    v, u = [v[0], v[-1]], [u[0], u[-1]]
    with pytest.warns(karkas.KarkasWarning, match="u_derivs and v_derivs") as caught:
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="bicubic")
    assert len(caught) == 1
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="bilinear")
        v5, u5 = paraboloid_network()
        karkas.CoonsSurface(u_curves=u5, v_curves=v5, kind="composite")


def test_plane_section_lies_on_the_plane_and_the_surface():
    x = np.linspace(0, 1, 8)
    X, Y = np.meshgrid(x, x, indexing="ij")
    grid = np.stack([X, Y, np.sin(2 * X) * np.cos(3 * Y)], axis=-1)
    S = karkas.BicubicSurface(grid, parameterization="uniform")
    curves = S.section([1.0, 0.0, 0.0], 0.37)
    assert len(curves) == 1
    c = curves[0]
    assert not c.closed and len(c) > 10
    np.testing.assert_allclose(c.points[:, 0], 0.37, atol=1e-9)
    uv = c.params
    np.testing.assert_allclose(S(uv[:, 0], uv[:, 1], grid=False), c.points, atol=1e-12)
    assert c.length == pytest.approx(np.sum(np.linalg.norm(np.diff(c.points, axis=0), axis=1)))
    assert S.section([1.0, 0.0, 0.0], 5.0) == []
    with pytest.raises(ValueError, match="3 coordinates"):
        S.section([1.0, 0.0], 0.5)
    assert "SectionCurve" in repr(c)


def test_implicit_sphere_projection_and_curvature():
    sphere = karkas.ImplicitSurface("x^2 + y^2 + z^2 - 4")
    p = sphere.project([[3.0, 0.0, 0.0], [0.0, 1.0, 1.0]])
    np.testing.assert_allclose(np.linalg.norm(p, axis=1), 2.0, atol=1e-12)
    np.testing.assert_allclose(p[0], [2.0, 0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(sphere.value(p), 0.0, atol=1e-12)
    np.testing.assert_allclose(sphere.gradient([[1.0, 2.0, 3.0]]), [[2.0, 4.0, 6.0]])
    k = sphere.curvatures([2.0, 0.0, 0.0])
    assert abs(k["k1"]) == pytest.approx(0.5) and abs(k["k2"]) == pytest.approx(0.5)
    assert k["gaussian"] == pytest.approx(0.25)
    assert "x^2" in repr(sphere)


def test_trace_net_on_a_cylinder_stays_on_it():
    cyl = karkas.ImplicitSurface("x^2 + y^2 - 1")
    net = cyl.trace_net([1.0, 0.0, 0.0], nodes=(4, 5), steps=(0.2, 0.3))
    assert net.shape == (4, 5, 3)
    np.testing.assert_allclose(np.hypot(net[..., 0], net[..., 1]), 1.0, atol=1e-8)
    steps = np.linalg.norm(np.diff(net[:, 0], axis=0), axis=1)
    assert np.all(steps > 0.15) and np.all(steps < 0.25)


def test_implicit_errors():
    with pytest.raises(ValueError):
        karkas.ImplicitSurface("x^2 + * y")
    cyl = karkas.ImplicitSurface("x^2 + y^2 - 1")
    with pytest.raises(ValueError, match="directions"):
        cyl.trace_net([1.0, 0.0, 0.0], nodes=(3, 3), steps=(0.1, 0.1), directions="diagonal")
    with pytest.raises(ValueError, match="3 coordinates"):
        cyl.value(np.zeros((3, 2)))


def test_hausdorff_of_point_sets_matches_brute_force(rng):
    a = rng.standard_normal((200, 3))
    b = rng.standard_normal((150, 3)) + 0.3
    d = np.linalg.norm(a[:, None, :] - b[None, :, :], axis=-1)
    ref = max(d.min(axis=1).max(), d.min(axis=0).max())
    h = karkas.hausdorff(a, b)
    assert h["distance"] == pytest.approx(ref, rel=1e-12)
    assert h["forward"]["distance"] == pytest.approx(d.min(axis=1).max(), rel=1e-12)
    with pytest.raises(ValueError):
        karkas.hausdorff(np.zeros((0, 3)), b)


def test_hausdorff_of_a_bicubic_sphere_patch_is_small():
    th = np.linspace(0.3, 1.2, 10)
    ph = np.linspace(0.0, 1.0, 12)
    T, P = np.meshgrid(th, ph, indexing="ij")
    grid = np.stack([np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)], axis=-1)
    S = karkas.BicubicSurface(grid)
    sphere = karkas.ImplicitSurface("x^2 + y^2 + z^2 - 1")
    T2, P2 = np.meshgrid(np.linspace(0.3, 1.2, 30), np.linspace(0.0, 1.0, 30), indexing="ij")
    patch = np.stack([np.sin(T2) * np.cos(P2), np.sin(T2) * np.sin(P2), np.cos(T2)], -1).reshape(-1, 3)
    h = karkas.hausdorff_to_implicit(S, sphere, patch, samples=(40, 40))
    assert 0.0 < h["distance"] < 1e-4


def test_vary_meets_the_sums_and_keeps_fixed_entries():
    z = np.array([[1.0, 2.0], [3.0, 4.0]])
    fixed = np.array([[True, False], [False, False]])
    out = karkas.vary(z, [4.0, 8.0], [5.0, 7.0], fixed=fixed)
    assert out[0, 0] == 1.0
    np.testing.assert_allclose(out.sum(axis=1), [4.0, 8.0], atol=1e-12)
    np.testing.assert_allclose(out.sum(axis=0), [5.0, 7.0], atol=1e-12)
    with pytest.raises(ValueError):
        karkas.vary(z, [4.0, 8.0], [5.0, 8.0])  # totals disagree


def test_parameterizations():
    pts = np.array([[0.0, 0.0], [3.0, 4.0], [3.0, 5.0]])
    np.testing.assert_allclose(karkas.curve_parameters(pts), [0.0, 5.0, 6.0])
    np.testing.assert_allclose(karkas.curve_parameters(pts, "uniform"), [0.0, 1.0, 2.0])
    np.testing.assert_allclose(karkas.curve_parameters(pts, "centripetal"), [0.0, np.sqrt(5), np.sqrt(5) + 1])
    x = np.array([0.0, 1.0, 3.0])
    X, Y = np.meshgrid(x, 2 * x, indexing="ij")
    grid = np.stack([X, Y], axis=-1)
    u, v = karkas.grid_parameters(grid)
    np.testing.assert_allclose(u, x)
    np.testing.assert_allclose(v, 2 * x)
    with pytest.raises(ValueError, match="coincid"):
        karkas.curve_parameters(np.zeros((3, 2)))


def wave_network(m=5, k=9):
    """v-curves at x = const, u-curves at y = const, over [-1, 1]^2; z = sin x cos y."""
    xs = np.linspace(-1.0, 1.0, m)
    s = np.linspace(-1.0, 1.0, (m - 1) * (k - 1) + 1)
    v_curves = [np.column_stack([np.full_like(s, x), s, np.sin(x) * np.cos(s)]) for x in xs]
    u_curves = [np.column_stack([s, np.full_like(s, y), np.sin(s) * np.cos(y)]) for y in xs]
    return xs, v_curves, u_curves


def test_composite_twists_are_the_surface_twists_at_the_crossings():
    xs, v, u = wave_network()
    # The surface parameters run over [0, 1] where x and y run over [-1, 1]: a factor 2 each.
    twists = np.zeros((len(v), len(u), 3))
    twists[..., 2] = -4.0 * np.outer(np.cos(xs), np.sin(xs))
    S = karkas.CoonsSurface(u_curves=u, v_curves=v, kind="composite", twists=twists)
    nodes = np.linspace(0.0, 1.0, len(xs))
    for i, a in enumerate(nodes):
        for j, b in enumerate(nodes):
            np.testing.assert_allclose(S(a, b, 1, 1), twists[i, j], atol=1e-9)
    # The exact twists bring the surface closer to the wave than the derived ones.
    derived = karkas.CoonsSurface(u_curves=u, v_curves=v, kind="composite")

    def error(surface):
        P = surface.sample(41, 41)
        return np.abs(P[..., 2] - np.sin(P[..., 0]) * np.cos(P[..., 1])).max()

    assert error(S) < error(derived)
    with pytest.raises(ValueError, match="twists are used only by"):
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="gordon", twists=twists)
    with pytest.raises(ValueError, match="not both"):
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="composite", twists=twists, u_derivs=u, v_derivs=v)
    with pytest.raises(ValueError, match="rows of twists"):
        karkas.CoonsSurface(u_curves=u, v_curves=v, kind="composite", twists=twists[:3])
