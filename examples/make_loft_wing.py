"""Writes the shipped demo wing of `karkas loft` into data/loft-wing: three NACA 4-digit
sections (their closed-form equations, 81 points per side in cosine spacing, Selig order,
blunt trailing edges as the equations give them) and the sections table wing.csv.

    python3 examples/make_loft_wing.py [OUT_DIR]
"""

import math
import os
import sys


def naca4(digits, n=81):
    m, p, t = int(digits[0]) / 100, int(digits[1]) / 10, int(digits[2:]) / 100

    def point(x, upper):
        yt = 5 * t * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
        if m == 0:
            yc, slope = 0.0, 0.0
        elif x < p:
            yc, slope = m / p**2 * (2 * p * x - x * x), 2 * m / p**2 * (p - x)
        else:
            yc = m / (1 - p) ** 2 * (1 - 2 * p + 2 * p * x - x * x)
            slope = 2 * m / (1 - p) ** 2 * (p - x)
        th = math.atan(slope)
        s = 1 if upper else -1
        return x - s * yt * math.sin(th), yc + s * yt * math.cos(th)

    xs = [0.5 * (1 - math.cos(math.pi * k / (n - 1))) for k in range(n)]
    upper = [point(x, True) for x in reversed(xs)]
    lower = [point(x, False) for x in xs[1:]]
    # The leading edge exactly at the origin.
    upper[-1] = (0.0, 0.0)
    return upper + lower


WING = [  # file, leading edge x y z, chord, twist (degrees)
    ("naca4415.dat", (0.0, 0.0, 0.0), 1.6, 2.0),
    ("naca2412.dat", (0.35, 3.0, 0.15), 1.2, 0.0),
    ("naca0009.dat", (0.9, 6.0, 0.45), 0.6, -3.0),
]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "data", "loft-wing")
    os.makedirs(out, exist_ok=True)
    for name, *_ in WING:
        digits = name[4:8]
        with open(os.path.join(out, name), "w") as f:
            f.write(f"NACA {digits}\n")
            for x, y in naca4(digits):
                f.write(f"{x:.7f} {y:.7f}\n")
    with open(os.path.join(out, "wing.csv"), "w") as f:
        f.write("file,x,y,z,chord,twist,dihedral\n")
        for name, (x, y, z), chord, twist in WING:
            f.write(f"{name},{x},{y},{z},{chord},{twist},\n")


if __name__ == "__main__":
    main()
