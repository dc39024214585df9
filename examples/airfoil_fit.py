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
   freely and once with the paper's bound on the second-derivative jumps (eps = 0.01).
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

    fig, (ax, bx) = plt.subplots(2, 1, figsize=(9, 7.5), gridspec_kw={"height_ratios": [1, 1]})
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
    bx.set_title("Hydrofoil of the source paper (its printed table has transcription errors)")

    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
