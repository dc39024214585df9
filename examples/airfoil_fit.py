"""Fitting an airfoil with karkas from Python: a short tutorial.

Install the package first (from the repository root):

    pip install ./crates/karkas-py

then run `python3 examples/airfoil_fit.py` (writes airfoil_fit.png; add `--out PATH` to choose).
It runs headless: matplotlib's Agg backend draws straight to the PNG.

1. A NACA 2412 section is sampled at 61 points (cosine spacing, denser at the nose), with a
   little measurement noise.
2. Three curves go through or near those points:
   - karkas.CubicSpline: the C^2 interpolating spline on chord-length parameters (what SciPy's
     CubicSpline gives for the same parameters);
   - karkas.LLCurve.interpolate: the LL curve of order 5, C^5, through every point;
   - karkas.fit_curve: a C^1 cubic Hermite spline fitted to the noisy points with knots added
     until every point is within a tolerance (a smoothing fit, it does not chase the noise).
3. The hydrofoil of data/hydrofoil-profile.csv is fitted on the knots of its source paper, once
   freely and once with the paper's bound on the second-derivative jumps (eps = 0.01). Its
   printed points cross themselves (the upper-surface point 8 lies below the lower surface), so
   no smooth loop-free curve follows them closely.
4. Beside it, a clean hydrofoil with known truth: a NACA 6508-type section (4-digit mean line
   and thickness, a 3% blunt trailing edge, cambered toward the lower surface, chord 280,
   turned 40 degrees) sampled at the paper's 20 x stations in its order, fitted with the
   paper's knots and eps; the largest distance of the fit from the true contour is printed.
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import karkas  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def naca4(code="2412", n=61):
    """A NACA 4-digit section as one contour: upper trailing edge -> nose -> lower trailing edge."""
    m, p, t = int(code[0]) / 100, int(code[1]) / 10, int(code[2:]) / 100
    x = 0.5 * (1 - np.cos(np.linspace(0.0, np.pi, n // 2 + 1)))
    yt = 5 * t * (0.2969 * np.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
    yc = np.where(x < p, m / p**2 * (2 * p * x - x**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x**2))
    dyc = np.where(x < p, 2 * m / p**2 * (p - x), 2 * m / (1 - p) ** 2 * (p - x))
    th = np.arctan(dyc)
    upper = np.column_stack([x - yt * np.sin(th), yc + yt * np.cos(th)])
    lower = np.column_stack([x + yt * np.sin(th), yc - yt * np.cos(th)])
    return np.vstack([upper[::-1], lower[1:]])


def clean_section(u, upper):
    """The clean hydrofoil's surface (upper: the side of the paper's points 1 to 10) at chordwise
    positions u in [0, 1], in the paper's units."""
    m, p, t = -0.06, 0.5, 0.08
    u = np.asarray(u, float)
    yt = 5 * t * (0.2969 * np.sqrt(u) - 0.1260 * u - 0.3516 * u**2 + 0.2843 * u**3 - 0.1015 * u**4) + 0.015 * u
    yc = np.where(u < p, m / p**2 * (2 * p * u - u**2), m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * u - u**2))
    th = np.arctan(np.where(u < p, 2 * m / p**2 * (p - u), 2 * m / (1 - p) ** 2 * (p - u)))
    s = 1.0 if upper else -1.0
    a, b = u - s * yt * np.sin(th), yc + s * yt * np.cos(th)
    c, d = np.cos(np.radians(40.0)), np.sin(np.radians(40.0))
    return np.stack([-114.8 + 280 * (a * c - b * d), -102.6 + 280 * (a * d + b * c)], -1)


def clean_hydrofoil():
    """The clean section sampled like the paper's: its x stations, upper surface from the
    trailing edge to the nose (point 10: the leftmost point), then the lower surface; and the
    true contour between the first and last points."""
    fine = 0.5 * (1 - np.cos(np.linspace(0.0, np.pi, 8001)))
    upper, lower = clean_section(fine, True), clean_section(fine, False)
    nose = int(np.argmin(upper[:, 0]))

    def at(x, side, start):
        lo, hi = fine[start], 1.0  # x grows along each surface beyond the nose: bisection
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if clean_section(mid, side)[0] < x else (lo, mid)
        return 0.5 * (lo + hi)

    stations = [94.8, 71.1, 47.4, 23.7, 0.0, -23.7, -47.1, -74.8, -106.6]
    u_upper = [at(x, True, nose) for x in stations] + [fine[nose]]
    u_lower = [at(x, False, 0) for x in [-106.6, -94.8, -71.1, -47.4, -23.7, 0.0, 23.7, 47.4, 71.1, 94.8]]
    points = np.vstack([clean_section(np.array(u_upper), True), clean_section(np.array(u_lower), False)])
    truth = np.vstack([upper[fine <= u_upper[0]][::-1], lower[(fine > 0) & (fine <= u_lower[-1])]])
    return points, truth


def farthest(points, line):
    """The largest distance from a point of `points` to the polyline `line`."""
    a, ab = line[:-1], np.diff(line, axis=0)
    worst = 0.0
    for chunk in np.array_split(points, max(1, len(points) // 50)):
        ap = chunk[:, None, :] - a[None]
        t = np.clip((ap * ab).sum(-1) / (ab * ab).sum(-1), 0.0, 1.0)
        d = np.linalg.norm(ap - t[..., None] * ab, axis=-1).min(axis=1)
        worst = max(worst, float(d.max()))
    return worst


def hydrofoil():
    path = os.path.join(HERE, "..", "data", "hydrofoil-profile.csv")
    rows = [line for line in open(path) if line[:1] not in "#x"]
    return np.array([[float(v) for v in line.split(",")[:2]] for line in rows])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="airfoil_fit.png", help="the PNG to write")
    args = parser.parse_args()

    rng = np.random.default_rng(7)
    exact = naca4()
    noisy = exact + rng.normal(0.0, 2e-4, exact.shape)

    spline = karkas.CubicSpline(noisy, parameterization="chord")
    ll = karkas.LLCurve.interpolate(noisy, order=5)
    fit = karkas.fit_curve(noisy, tolerance=5e-4, pin_ends=True)
    print(spline)
    print(ll)
    print(fit)
    print(f"fit: {len(fit.knots)} knots, largest distance {fit.max_distance:.2e}, rms {fit.rms_distance:.2e}")

    fig = plt.figure(figsize=(12, 8))
    grid = fig.add_gridspec(2, 2, height_ratios=[0.55, 1.2])
    ax = fig.add_subplot(grid[0, :])
    bx, cx = fig.add_subplot(grid[1, 0]), fig.add_subplot(grid[1, 1])
    ax.plot(*noisy.T, "k.", ms=4, label="61 noisy points (NACA 2412)")
    ax.plot(*spline.sample(2000).T, lw=1.0, label="CubicSpline (chord, not-a-knot)")
    ax.plot(*ll.sample(2000).T, lw=1.0, ls="--", label="LLCurve.interpolate(order=5)")
    ax.plot(*fit.sample(2000).T, lw=1.6, alpha=0.7, label=f"fit_curve(tolerance=5e-4): {len(fit.knots)} knots")
    ax.plot(*fit(fit.knots).T, "rs", ms=4, label="fit knots")
    ax.set_aspect("equal")
    ax.legend(fontsize=8, loc="upper right")
    ax.set_title("Airfoil through noisy points")
    # Inset: the nose, where the curves differ most.
    inset = ax.inset_axes([0.02, 0.05, 0.25, 0.55])
    for c, style in ((spline, "-"), (ll, "--"), (fit, "-")):
        inset.plot(*c.sample(4000).T, style, lw=1.0)
    inset.plot(*noisy.T, "k.", ms=4)
    inset.set_xlim(-0.005, 0.03)
    inset.set_ylim(-0.02, 0.03)
    inset.set_xticks([])
    inset.set_yticks([])

    foil = hydrofoil()
    knots = [0.0, 0.445, 0.449, 0.587, 1.0]  # the knot grid of the paper
    free = karkas.fit_curve(foil, knots=knots)
    bounded = karkas.fit_curve(foil, knots=knots, eps=0.01)
    print(free)
    print(bounded)
    bx.plot(*foil.T, "k.", ms=6, label=f"{len(foil)} points (data/hydrofoil-profile.csv)")
    bx.plot(*free.sample(2000).T, lw=1.2, label=f"fit_curve(knots=paper's): largest distance {free.max_distance:.3g}")
    bx.plot(*bounded.sample(2000).T, lw=1.2, ls="--",
            label=f"... with eps=0.01 (jumps bounded): largest distance {bounded.max_distance:.3g}")
    bx.plot(*free(free.knots).T, "rs", ms=4, label="knots")
    bx.set_aspect("equal")
    bx.legend(fontsize=8)
    bx.set_title("The paper's hydrofoil: its printed points cross themselves", fontsize=10)

    points, truth = clean_hydrofoil()
    clean = karkas.fit_curve(points, knots=knots, eps=0.01)
    curve = clean.sample(4000)
    to_truth, from_truth = farthest(curve, truth), farthest(truth, curve)
    print(clean)
    print(f"paper's hydrofoil: largest point distance {bounded.max_distance:.3g}")
    print(
        f"clean hydrofoil: largest point distance {clean.max_distance:.3g}, rms {clean.rms_distance:.3g}; "
        f"largest distance from the true contour {max(to_truth, from_truth):.3g} "
        f"(fit to truth {to_truth:.3g}, truth to fit {from_truth:.3g}), chord 280"
    )
    cx.plot(*truth.T, "g-", lw=0.8, label="true section (NACA 6508 type)")
    cx.plot(*points.T, "k.", ms=6, label="20 points at the paper's x stations")
    cx.plot(*curve.T, lw=1.2, label=f"fit_curve(knots=paper's, eps=0.01): points within {clean.max_distance:.3g}")
    cx.plot(*clean(clean.knots).T, "rs", ms=4, label=f"knots; {max(to_truth, from_truth):.3g} from the truth")
    cx.set_aspect("equal")
    cx.legend(fontsize=8)
    cx.set_title("A clean hydrofoil with known truth, sampled and fitted the same way", fontsize=10)

    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
