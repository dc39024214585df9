"""Curve and surface geometry against SciPy and closed forms: arc length (scipy.integrate.quad
of the speed), curvature and torsion (from the derivatives, and 1/r of sampled circles),
projection (dense sampling refined by scipy.optimize), normals and principal curvatures
(shape operator from the derivatives with numpy.linalg)."""

import numpy as np
import pytest
from scipy import integrate, optimize

import karkas

RNG = np.random.default_rng(20)


def _curves():
    """One curve of every type, in 2-D and 3-D."""
    p2 = np.cumsum(RNG.normal(size=(12, 2)), axis=0)
    p3 = np.cumsum(RNG.normal(size=(12, 3)), axis=0)
    s = np.linspace(0.0, 1.0, 40)
    wave = np.c_[s, 0.1 * np.sin(6 * s)]
    return [
        karkas.LLCurve(p2, order=3),
        karkas.LLCurve(p3, order=5, closed=True),
        karkas.LLCurve.interpolate(p2, order=3),
        karkas.CubicSpline(p2),
        karkas.CubicSpline(p3, bc="natural"),
        karkas.fit_curve(wave, knots=8),
    ]


CURVES = _curves()
IDS = [f"{type(c).__name__}-{c.dim}d-{i}" for i, c in enumerate(CURVES)]


def _speed(c):
    return lambda t: float(np.linalg.norm(c(t, 1)))


def _quad_length(c, a, b):
    """The length by scipy.integrate.quad, split at the breakpoints (kinks of the speed)."""
    bps = np.asarray(c.breakpoints)
    inner = bps[(bps > min(a, b)) & (bps < max(a, b))]
    lo, hi = min(a, b), max(a, b)
    edges = np.concatenate([[lo], inner, [hi]])
    total = sum(
        integrate.quad(_speed(c), x0, x1, epsabs=1e-13, epsrel=1e-13, limit=200)[0]
        for x0, x1 in zip(edges[:-1], edges[1:])
    )
    return total if b >= a else -total


@pytest.mark.parametrize("c", CURVES, ids=IDS)
def test_arc_length_matches_quad(c):
    a, b = c.domain
    assert c.arc_length() == pytest.approx(_quad_length(c, a, b), abs=1e-8)
    t1 = np.linspace(a, b, 7)[1:]
    t0 = a + 0.1 * (b - a)
    got = c.arc_length(t0, t1, tol=1e-11)
    assert got.shape == t1.shape
    want = [_quad_length(c, t0, x) for x in t1]
    np.testing.assert_allclose(got, want, atol=1e-9)
    assert isinstance(c.arc_length(a, b), float)


@pytest.mark.parametrize("c", CURVES, ids=IDS)
def test_accuracy_is_honoured(c):
    reference = _quad_length(c, *c.domain)
    for tol in (1e-3, 1e-6, 1e-9):
        assert abs(c.arc_length(tol=tol) - reference) <= tol + 1e-12


@pytest.mark.parametrize("c", CURVES, ids=IDS)
def test_inverse_arc_length_round_trip(c):
    a, b = c.domain
    total = c.arc_length()
    s = np.array([0.1, 0.35, 0.8]) * total
    t = c.inverse_arc_length(s, tol=1e-10)
    np.testing.assert_allclose([_quad_length(c, a, x) for x in t], s, atol=1e-8)
    if not c.closed:
        assert c.inverse_arc_length(2 * total) == b


@pytest.mark.parametrize("c", CURVES, ids=IDS)
def test_curvature_from_derivatives(c):
    a, b = c.domain
    t = np.linspace(a, b, 23)[1:-1] + 1e-3
    d1, d2 = c(t, 1), c(t, 2)
    speed = np.linalg.norm(d1, axis=-1)
    if c.dim == 2:
        want = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / speed**3
    else:
        want = np.linalg.norm(np.cross(d1, d2), axis=-1) / speed**3
    np.testing.assert_allclose(c.curvature(t), want, rtol=1e-9, atol=1e-12)
    assert isinstance(c.curvature(float(t[3])), float)
    assert c.curvature(t.reshape(3, 7)).shape == (3, 7)


@pytest.mark.parametrize("r", [0.5, 3.0])
def test_sampled_circles_have_curvature_one_over_r(r):
    s = np.linspace(0.0, 2 * np.pi, 400)
    pts = np.c_[r * np.cos(s), r * np.sin(s)]
    spline = karkas.CubicSpline(pts, t=s, bc="periodic")
    t = np.linspace(0.0, 2 * np.pi, 50)
    np.testing.assert_allclose(spline.curvature(t), 1 / r, rtol=1e-4)
    assert spline.arc_length() == pytest.approx(2 * np.pi * r, rel=1e-8)
    # Clockwise: negative curvature.
    backwards = karkas.CubicSpline(pts[::-1].copy(), t=s, bc="periodic")
    np.testing.assert_allclose(backwards.curvature(t), -1 / r, rtol=1e-4)
    # An LL curve bends mostly near its nodes, so its curvature is not 1/r pointwise; its
    # total curvature is the turning angle 2 pi of a closed convex curve.
    ll = karkas.LLCurve.interpolate(pts[:-1], order=3, closed=True)
    total = integrate.quad(
        lambda x: ll.curvature(x) * _speed(ll)(x), *ll.domain, limit=2000, epsabs=1e-10
    )[0]
    assert total == pytest.approx(2 * np.pi, rel=1e-6)
    assert ll.arc_length() == pytest.approx(2 * np.pi * r, rel=1e-4)


def test_helix_torsion_and_curvature():
    r, h = 2.0, 0.5
    s = np.linspace(0.0, 4 * np.pi, 600)
    helix = karkas.CubicSpline(np.c_[r * np.cos(s), r * np.sin(s), h * s], t=s)
    t = np.linspace(1.0, 11.0, 20)
    np.testing.assert_allclose(helix.torsion(t), h / (r * r + h * h), rtol=1e-4)
    np.testing.assert_allclose(helix.curvature(t), r / (r * r + h * h), rtol=1e-4)
    # Against the derivatives.
    d1, d2, d3 = (helix(t, k) for k in (1, 2, 3))
    b = np.cross(d1, d2)
    want = np.einsum("ij,ij->i", b, d3) / np.einsum("ij,ij->i", b, b)
    np.testing.assert_allclose(helix.torsion(t), want, rtol=1e-10)


def test_torsion_of_a_2d_curve_is_an_error():
    with pytest.raises(ValueError, match="3-D"):
        CURVES[0].torsion(0.5)


def _reference_projection(c, q):
    """Dense sampling, then scipy.optimize.minimize_scalar around the best sample."""
    a, b = c.domain
    t = np.linspace(a, b, 20001)
    pts = c(t)
    k = int(np.argmin(np.linalg.norm(pts - q, axis=1)))
    lo, hi = t[max(k - 1, 0)], t[min(k + 1, len(t) - 1)]
    res = optimize.minimize_scalar(
        lambda x: float(np.linalg.norm(c(x) - q)),
        bounds=(lo, hi),
        method="bounded",
        options={"xatol": 1e-12},
    )
    return min(res.fun, float(np.linalg.norm(pts[k] - q)))


@pytest.mark.parametrize("c", CURVES, ids=IDS)
def test_projection_matches_brute_force(c):
    lo = c.sample(50).min(axis=0) - 1.0
    hi = c.sample(50).max(axis=0) + 1.0
    q = RNG.uniform(lo, hi, size=(12, c.dim))
    t, dist, foot = c.project(q)
    assert t.shape == (12,) and dist.shape == (12,) and foot.shape == (12, c.dim)
    want = np.array([_reference_projection(c, x) for x in q])
    assert np.all(dist <= want + 1e-9)
    np.testing.assert_allclose(dist, want, atol=1e-7)
    np.testing.assert_allclose(foot, c(t), atol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(foot - q, axis=1), dist, atol=1e-12)
    a, b = c.domain
    assert np.all((t >= a) & (t <= b))


@pytest.mark.parametrize("c", CURVES, ids=IDS)
def test_points_on_the_curve_project_to_themselves(c):
    t = np.linspace(*c.domain, 17)
    _, dist, foot = c.project(c(t))
    np.testing.assert_allclose(dist, 0.0, atol=1e-9)
    np.testing.assert_allclose(foot, c(t), atol=1e-9)


def test_centre_of_a_circle_projects_at_the_radius():
    s = np.linspace(0.0, 2 * np.pi, 100)
    circle = karkas.CubicSpline(np.c_[np.cos(s), np.sin(s)], t=s, bc="periodic")
    _, dist, _ = circle.project([[0.0, 0.0]])
    assert dist[0] == pytest.approx(1.0, abs=1e-6)


def test_bad_projection_input():
    c = CURVES[0]
    with pytest.raises(karkas.PointsError):
        c.project(np.zeros((3, 3)))
    with pytest.raises(karkas.OptionError):
        c.arc_length(tol=-1.0)


def _sphere_patch(r=2.0, n=41):
    u = np.linspace(0.2, 2.6, n)
    v = np.linspace(-1.0, 1.0, n)
    U, V = np.meshgrid(u, v, indexing="ij")
    grid = np.stack([r * np.cos(V) * np.cos(U), r * np.cos(V) * np.sin(U), r * np.sin(V)], -1)
    return karkas.BicubicSurface.from_knots(grid, u, v)


def _wavy_surface():
    x = np.linspace(-1.0, 1.0, 15)
    X, Y = np.meshgrid(x, x, indexing="ij")
    grid = np.stack([X, Y, 0.3 * np.sin(2 * X) * np.cos(3 * Y)], -1)
    return karkas.LLSurface.interpolate(grid, order=3)


SURFACES = [_sphere_patch(), _wavy_surface()]


def _shape_operator(S, u, v):
    """k1 >= k2 and the normal from the derivatives, by numpy.linalg."""
    su, sv = S(u, v, 1, 0, grid=False), S(u, v, 0, 1, grid=False)
    suu = S(u, v, 2, 0, grid=False)
    suv = S(u, v, 1, 1, grid=False)
    svv = S(u, v, 0, 2, grid=False)
    n = np.cross(su, sv)
    n /= np.linalg.norm(n)
    first = np.array([[su @ su, su @ sv], [su @ sv, sv @ sv]])
    second = np.array([[suu @ n, suv @ n], [suv @ n, svv @ n]])
    k = np.sort(np.linalg.eigvals(np.linalg.solve(first, second)).real)[::-1]
    return k, n


@pytest.mark.parametrize("S", SURFACES, ids=["sphere", "wavy"])
def test_normals_and_principal_curvatures_from_derivatives(S):
    us = np.linspace(*S.domain_u, 5)[1:-1]
    vs = np.linspace(*S.domain_v, 5)[1:-1]
    normals = S.normal(us, vs, grid=True)
    assert normals.shape == (3, 3, 3)
    k1, k2, d1, d2 = S.principal_curvatures(us, vs, grid=True, directions=True)
    for i, u in enumerate(us):
        for j, v in enumerate(vs):
            k, n = _shape_operator(S, u, v)
            np.testing.assert_allclose(normals[i, j], n, atol=1e-12)
            np.testing.assert_allclose([k1[i, j], k2[i, j]], k, rtol=1e-9, atol=1e-10)
            np.testing.assert_allclose(np.cross(d1[i, j], d2[i, j]), n, atol=1e-9)
    assert isinstance(S.principal_curvatures(float(us[0]), float(vs[0]))[0], float)


def test_sphere_curvature_and_normal_closed_form():
    S = _sphere_patch(r=2.0)
    u, v = np.array([0.5, 1.0, 2.0]), np.array([-0.5, 0.0, 0.7])
    n = S.normal(u, v)
    np.testing.assert_allclose(n, S(u, v, grid=False) / 2.0, atol=1e-5)
    k1, k2 = S.principal_curvatures(u, v)
    np.testing.assert_allclose(k1, -0.5, atol=1e-3)
    np.testing.assert_allclose(k2, -0.5, atol=1e-3)


def _reference_surface_distance(S, q):
    us = np.linspace(*S.domain_u, 201)
    vs = np.linspace(*S.domain_v, 201)
    pts = S(us, vs)
    d = np.linalg.norm(pts - q, axis=-1)
    i, j = np.unravel_index(np.argmin(d), d.shape)
    res = optimize.minimize(
        lambda x: float(np.sum((S(x[0], x[1], grid=False) - q) ** 2)),
        [us[i], vs[j]],
        bounds=[S.domain_u, S.domain_v],
        method="L-BFGS-B",
        options={"ftol": 1e-15, "gtol": 1e-12},
    )
    return min(np.sqrt(res.fun), d[i, j])


@pytest.mark.parametrize("S", SURFACES, ids=["sphere", "wavy"])
def test_surface_projection_matches_brute_force(S):
    box = S.sample(20, 20).reshape(-1, 3)
    q = RNG.uniform(box.min(0) - 0.5, box.max(0) + 0.5, size=(8, 3))
    u, v, dist, foot = S.project(q, foot=True)
    want = np.array([_reference_surface_distance(S, x) for x in q])
    assert np.all(dist <= want + 1e-8)
    np.testing.assert_allclose(dist, want, atol=1e-6)
    np.testing.assert_allclose(foot, S(u, v, grid=False), atol=1e-12)
    on = S(u, v, grid=False)
    _, _, d0 = S.project(on)
    np.testing.assert_allclose(d0, 0.0, atol=1e-9)


def test_sphere_projection_closed_form():
    S = _sphere_patch(r=2.0)
    # Points along the normals over the patch: the distance is |rho - r|.
    u, v = np.array([0.6, 1.4, 2.2]), np.array([-0.6, 0.1, 0.8])
    dirs = S(u, v, grid=False) / 2.0
    q = dirs * np.array([[3.0], [1.2], [2.5]])
    _, _, dist = S.project(q)
    np.testing.assert_allclose(dist, [1.0, 0.8, 0.5], atol=1e-6)


def test_derivative_objects_have_geometry_too():
    # The hodograph of a circle of radius r traversed at unit angular speed is a circle of
    # radius r: its length over one turn is 2 pi r and its curvature 1/r.
    t = np.linspace(0.0, 2 * np.pi, 401)
    pts = np.column_stack([2 * np.cos(t), 2 * np.sin(t)])
    c = karkas.CubicSpline(pts, t=t, bc="periodic")
    d = c.derivative()
    assert d.arc_length() == pytest.approx(4 * np.pi, rel=1e-6)
    assert np.allclose(d.curvature(np.linspace(0.5, 5.5, 7)), 0.5, rtol=1e-4)
    t_near, distance, foot = d.project(np.array([[4.0, 0.0]]))
    assert distance[0] == pytest.approx(2.0, rel=1e-6)
    assert np.allclose(foot[0], [2.0, 0.0], atol=1e-5)


def test_open_curves_are_measured_within_their_domain():
    # A cubic spline continues its end pieces outside the domain when evaluated, but its
    # length is measured along the curve itself: parameters far outside are clamped (and a
    # start at -1e30 neither hangs nor overflows).
    pts = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
    c = karkas.CubicSpline(pts)
    a, b = c.domain
    assert c.arc_length(-1e30, 1e30) == pytest.approx(c.arc_length(a, b), rel=1e-12)
    assert c.inverse_arc_length(0.5, t0=-1e30) == pytest.approx(c.inverse_arc_length(0.5, t0=a), rel=1e-12)
