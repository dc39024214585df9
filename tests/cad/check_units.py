#!/usr/bin/env python3
"""CAD units check: Open CASCADE reads the unit karkas states (`--units`) and the coordinates
karkas scales (`--scale`); ezdxf reads DXF's `$INSUNITS`.

A curve (`curve ll` of data/contour-53.csv) and a surface (`surface ll` of
data/aircraft-15x31.csv) are written as STEP and IGES in every unit, and with a scale. Open
CASCADE imports each in its default unit, millimetres (it converts what the file states), so
the length (curve) or area (surface) of the imported shape must be that of the file written
without a unit (read as millimetres, its bounding box within 1e-2 of karkas's CSV samples' box)
times the unit in millimetres times the scale (squared for an area), to 1e-6 relative: a unit chord written with
`--units m` reads as 1000 mm. ezdxf must read `$INSUNITS` of `--units` (and 0, no unit,
without it). One line per file; exit status 1 on any failure.

Usage: python3 tests/cad/check_units.py [--karkas target/release/karkas]
"""

import argparse
import csv
import os
import subprocess
import sys
import tempfile

from OCP.Bnd import Bnd_Box
from OCP.BRepBndLib import BRepBndLib
from OCP.BRepGProp import BRepGProp
from OCP.GProp import GProp_GProps
from OCP.IFSelect import IFSelect_RetDone
from OCP.IGESControl import IGESControl_Reader
from OCP.STEPControl import STEPControl_Reader

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MILLIMETRES = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4}
TOLERANCE = 1e-6
SAMPLES_TOLERANCE = 1e-2


def run(karkas, args):
    done = subprocess.run([karkas, *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"karkas {' '.join(args)}: {done.stderr.strip()}")


def csv_box(path):
    """The bounding box (lo, hi) of the points of a karkas samples CSV (last 2 or 3 columns
    are x, y[, z])."""
    with open(path) as f:
        rows = list(csv.reader(f))
    header, rows = rows[0], rows[1:]
    first = header.index("x")
    points = [[float(v) for v in r[first:]] + [0.0] * (3 - len(r[first:])) for r in rows]
    lo = [min(p[c] for p in points) for c in range(3)]
    hi = [max(p[c] for p in points) for c in range(3)]
    return lo, hi


def occ_shape(path):
    reader = STEPControl_Reader() if path.endswith(".step") else IGESControl_Reader()
    if reader.ReadFile(path) != IFSelect_RetDone or reader.TransferRoots() < 1:
        raise RuntimeError("Open CASCADE did not read the file")
    return reader.OneShape()


def occ_measure(path, kind):
    """The length of a curve's or the area of a surface's shape, as Open CASCADE imports it."""
    props = GProp_GProps()
    if kind == "curve":
        BRepGProp.LinearProperties_s(occ_shape(path), props)
    else:
        BRepGProp.SurfaceProperties_s(occ_shape(path), props)
    return props.Mass()


def occ_box(path):
    shape = occ_shape(path)
    box = Bnd_Box()
    box.SetGap(0.0)
    add = getattr(BRepBndLib, "AddOptimal_s", None) or BRepBndLib.AddOptimal
    add(shape, box, False, False)
    lo, hi = box.CornerMin(), box.CornerMax()
    return [lo.X(), lo.Y(), lo.Z()], [hi.X(), hi.Y(), hi.Z()]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default=os.path.join(ROOT, "target", "release", "karkas"))
    args = parser.parse_args()
    folder = tempfile.mkdtemp(prefix="karkas-units-")
    data = os.path.join(ROOT, "data")
    builders = {
        "curve": ["curve", "ll", "--order", "3", os.path.join(data, "contour-53.csv")],
        "surface": ["surface", "ll", "--order", "3", os.path.join(data, "aircraft-15x31.csv")],
    }
    failures = 0
    for kind, command in builders.items():
        samples = os.path.join(folder, f"{kind}.csv")
        run(args.karkas, [*command, "-o", samples])
        lo, hi = csv_box(samples)
        size = max(h - l for l, h in zip(lo, hi))
        for ext in (".step", ".iges"):
            # The file without a unit: Open CASCADE's box of the exact shape holds the samples'
            # box, and is it to the samples' chordal error (well under 1e-2 of the size).
            base = os.path.join(folder, f"{kind}-none{ext}")
            run(args.karkas, [*command, "-o", base])
            blo, bhi = occ_box(base)
            base_measure = occ_measure(base, kind)
            loose = max(abs(a - b) / size for a, b in zip(blo + bhi, lo + hi))
            ok = loose <= SAMPLES_TOLERANCE
            print(
                f"{'ok  ' if ok else 'FAIL'} {os.path.basename(base)}: Open CASCADE's box is "
                f"karkas's samples' box in mm to {loose:.1e} of its size"
            )
            failures += 0 if ok else 1
            for unit, scale in [("mm", None), ("cm", None), ("m", None), ("in", None), ("m", 0.001)]:
                path = os.path.join(folder, f"{kind}-{unit}-{scale or 1}{ext}")
                options = ["--units", unit] + (["--scale", str(scale)] if scale else [])
                try:
                    run(args.karkas, [*command, "-o", path, *options])
                    factor = MILLIMETRES[unit] * (scale or 1.0)
                    # The same shape in millimetres times the unit and the scale: its length
                    # (a curve) or area (a surface) times the factor or its square. (Open
                    # CASCADE's bounding box of a surface is itself approximate.)
                    power = 1 if kind == "curve" else 2
                    measure = occ_measure(path, kind)
                    worst = abs(measure - base_measure * factor**power) / (base_measure * factor**power)
                    ok = worst <= TOLERANCE
                except Exception as e:  # noqa: BLE001 - report and go on
                    print(f"FAIL {os.path.basename(path)}: {e}")
                    failures += 1
                    continue
                print(
                    f"{'ok  ' if ok else 'FAIL'} {os.path.basename(path)}: Open CASCADE's "
                    f"{'length' if kind == 'curve' else 'area'} is the unitless file's x ({factor:g} mm)"
                    f"^{1 if kind == 'curve' else 2} to {worst:.1e}"
                )
                failures += 0 if ok else 1
    try:
        import ezdxf
    except ImportError:
        ezdxf = None
    if ezdxf is not None:
        codes = {None: 0, "mm": 4, "cm": 5, "m": 6, "in": 1}
        for unit, code in codes.items():
            path = os.path.join(folder, f"curve-{unit}.dxf")
            run(args.karkas, [*builders["curve"], "-o", path] + (["--units", unit] if unit else []))
            read = ezdxf.readfile(path).units
            ok = read == code
            print(f"{'ok  ' if ok else 'FAIL'} {os.path.basename(path)}: ezdxf reads $INSUNITS {read}")
            failures += 0 if ok else 1
    if failures:
        print(f"{failures} failure(s)")
        return 1
    print("every unit and scale read as stated")
    return 0


if __name__ == "__main__":
    sys.exit(main())
