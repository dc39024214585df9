#!/usr/bin/env python3
"""Drive the karkas workbench page in headless Chromium as a designer would, and compare what
it exports with the command line's files for the same points and options.

1. Opens the page from disk; no console error, page error or network request at any step.
2. Picks the shipped airfoil with the file picker; LL (order 3), the cubic spline and the fit
   are drawn, with a curvature plot.
3. Drags a point with the mouse: the point, every curve and the curvature plot change.
4. Exports STEP, IGES, DXF and CSV of the LL curve and the dragged points; `karkas curve ll
   --order 3` on those points writes the same bytes (the time stamps of the STEP and IGES
   headers aside); the SVG is a picture.
5. Loads a damaged airfoil: the error is the command line's, beside the offending line.
   Drops the shipped contour on the page: it loads.
6. Loads the shipped grid: the LL surface in 3-D with a section; its STEP and OBJ equal
   `karkas surface ll --order 3`'s, its STL is a mesh. Then a curve network of two files: the Gordon surface,
   its STEP equal to `karkas surface coons --kind gordon`'s.
7. Picks the shipped demo wing (a sections table and three airfoils): the loft in 3-D with its
   summary, within its tolerance, its STEP `karkas loft`'s (numbers within 1e-9); turns the tip's twist with
   its slider: the tip section turns by the change, the root and middle sections stay where they
   were, and with the ruled (linear) rule nothing inboard of the middle section moves; times the
   rebuild (`benchLoft`, median of 40). A table dropped without its profiles: the row and file
   named.
8. Keeps a screenshot (--screenshot).

Usage: check_workbench.py PAGE --karkas BIN [--screenshot OUT.png]
Needs Python Playwright, Pillow and NumPy, and the system Chromium (/usr/bin/chromium or
$CHROMIUM); Playwright never downloads a browser here.
"""
import argparse
import io
import pathlib
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree

import numpy
from PIL import Image
from playwright.sync_api import sync_playwright

from check_page import ARGS, CHROMIUM

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
AIRFOIL = ROOT / "data" / "batch-foils" / "foil-00000.dat"
DAMAGED = ROOT / "data" / "batch-foils" / "damaged-002.dat"
GRID = ROOT / "data" / "aircraft-15x31.csv"
WING = ROOT / "data" / "loft-wing" / "wing.csv"


def without_time_stamp(text):
    """STEP or IGES text with its time stamps blanked: FILE_NAME's second field (STEP), and the
    global section's dates, 15HYYYYMMDD.HHNNSS, zeroed in place so the columns stay (IGES)."""
    text = re.sub(r"FILE_NAME\('((?:[^']|'')*)','[^']*'", r"FILE_NAME('\1',''", text)
    return re.sub(r"\b15H\d{8}\.\d{6}", "15H00000000.000000", text)


def network():
    """A curve network on z = 0.2 sin(3x) cos(2y): u-curves y = 0, 0.5, 1 and v-curves
    x = 0, 0.5, 1, five points each, crossing at shared points (CSV curve,x,y,z)."""
    z = lambda x, y: 0.2 * numpy.sin(3 * x) * numpy.cos(2 * y)
    ts = [0.0, 0.25, 0.5, 0.75, 1.0]
    u = ["curve,x,y,z"] + [f"{k},{x},{c},{float(z(x, c))!r}" for k, c in enumerate([0.0, 0.5, 1.0]) for x in ts]
    v = ["curve,x,y,z"] + [f"{k},{c},{y},{float(z(c, y))!r}" for k, c in enumerate([0.0, 0.5, 1.0]) for y in ts]
    return "\n".join(u) + "\n", "\n".join(v) + "\n"


def element_pixels(page, testid):
    png = page.locator(f'[data-testid="{testid}"]').screenshot()
    return numpy.asarray(Image.open(io.BytesIO(png)).convert("L")).astype(int)


def cli_text(karkas, args, points_text, name, ext, work):
    source = work / f"{name}.input.csv"
    source.write_text(points_text)
    out = work / f"{name}.{ext}"
    if out.exists():
        out.unlink()
    subprocess.run([karkas, *args, str(source), "-o", str(out)], check=True,
                   capture_output=True)
    return out.read_text()


def set_slider(page, testid, value):
    """Moves the range input `testid` to `value` as a user's drag does (an input event)."""
    page.evaluate("""([id, v]) => { const e = document.querySelector(`[data-testid="${id}"]`);
        e.value = String(v); e.dispatchEvent(new Event('input', { bubbles: true })); }""", [testid, value])


def check_loft(page, karkas, work, check):
    """Step 7: the shipped demo wing lofted, a twist changed with its slider; returns the
    median rebuild time (ms)."""
    page.select_option('[data-testid="demo"]', "loft-wing/wing.csv")
    page.wait_for_function("window.karkasWorkbench.state().kind === 'loft'")
    loft = page.evaluate("window.karkasWorkbench.loft()")
    state = page.evaluate("window.karkasWorkbench.state()")
    check(state["errors"] == [], f"loft: errors {state['errors']}")
    check(page.locator('[data-testid="view3d"]').is_visible(), "loft: no 3-D view")
    check(page.locator('[data-testid="loft-section"] option').count() == 3, "loft: not 3 sections to choose")
    check(loft["sections"] == 3 and loft["toleranceMet"] and 0 < loft["deviation"] <= 1e-5,
          f"loft: {loft['sections']} sections, deviation {loft['deviation']}")
    check(len(loft["controls"]) == 2 and loft["controls"][0] >= 4 and loft["controls"][1] >= 10,
          f"loft: control points {loft['controls']}")
    summary = page.locator('[data-testid="loft-summary"]').inner_text()
    check(f"{loft['controls'][0]} x {loft['controls'][1]} control points" in summary
          and "largest section deviation" in summary and " ms" in summary, f"loft summary: {summary!r}")
    # The page's STEP is `karkas loft`'s for the same table: the same entities, the numbers
    # within 1e-9 (the wing is 6 long): WebAssembly's sine and cosine of the twist differ
    # from the native ones in the last bit, and the sections' fit carries that to about 1e-11.
    from_page = without_time_stamp(page.evaluate("window.karkasWorkbench.export('step')"))
    subprocess.run([karkas, "loft", str(WING), "-o", str(work / "wing.step")], check=True,
                   capture_output=True)
    from_cli = without_time_stamp((work / "wing.step").read_text())
    number = r"-?\d+\.\d*(?:E[-+]?\d+)?"
    page_numbers = [float(x) for x in re.findall(number, from_page)]
    cli_numbers = [float(x) for x in re.findall(number, from_cli)]
    same = (re.split(number, from_page) == re.split(number, from_cli)
            and len(page_numbers) == len(cli_numbers) > 100
            and max(abs(a - b) for a, b in zip(page_numbers, cli_numbers)) <= 1e-9)
    check(same, "loft STEP from the page differs from the command line's")
    # The sliders show the chosen section's table values.
    page.select_option('[data-testid="loft-section"]', "2")
    twist = float(page.locator('[data-testid="loft-twist"]').input_value())
    check(abs(twist - (-3.0)) < 1e-9, f"loft: the tip's twist slider reads {twist}, the table -3")
    stations = loft["stations"]
    for rule in ("monotone", "linear"):
        page.select_option('[data-testid="loft-rule"]', rule)
        set_slider(page, "loft-twist", -3.0)
        before = page.evaluate("window.karkasWorkbench.loft()")
        set_slider(page, "loft-twist", 2.0)
        after = page.evaluate("window.karkasWorkbench.loft()")
        check(after["placements"][2 * 6 + 4] == 2.0 and after["selected"] == 2,
              f"loft {rule}: the slider did not set the tip's twist: {after['placements']}")
        check(page.evaluate("window.karkasWorkbench.state().errors") == [], f"loft {rule}: errors")
        curves_before = [numpy.array(c) for c in before["curves"]]
        curves_after = [numpy.array(c) for c in after["curves"]]
        moved = [float(numpy.abs(a - b).max()) for a, b in zip(curves_before, curves_after)]
        check(moved[0] < 1e-12 and moved[1] < 1e-12, f"loft {rule}: root or middle section moved {moved}")
        # The tip's chord line (leading edge, the middle of 121 points, to the trailing edge's
        # middle) turned 5 degrees nose up about the span.
        def pitch(c):
            chord = (c[0] + c[-1]) / 2 - c[60]
            return numpy.degrees(numpy.arctan2(chord[2], chord[0]))
        turn = pitch(curves_before[2]) - pitch(curves_after[2])
        check(abs(turn - 5.0) < 0.05, f"loft {rule}: the tip turned {turn:.3f} degrees, not 5")
        mesh_b = numpy.array(before["mesh"]["positions"]).reshape(before["mesh"]["nu"], -1, 3)
        mesh_a = numpy.array(after["mesh"]["positions"]).reshape(after["mesh"]["nu"], -1, 3)
        rows = numpy.abs(mesh_a - mesh_b).max(axis=(1, 2))
        u = numpy.linspace(stations[0], stations[-1], len(rows))
        check(rows[-1] > 0.01, f"loft {rule}: the surface did not move at the tip ({rows[-1]})")
        inboard = rows[u <= stations[1] + 1e-9].max()
        if rule == "linear":
            check(inboard < 1e-12, f"loft linear: the surface moved inboard of the middle section ({inboard})")
        else:
            check(rows[0] < 1e-12, f"loft monotone: the surface moved at the root ({rows[0]})")
    page.select_option('[data-testid="loft-rule"]', "monotone")
    page.click('[data-testid="loft-reset"]')
    bench = page.evaluate("window.karkasWorkbench.benchLoft(40)")
    check(bench["median"] > 0, f"loft benchmark: {bench}")
    # The table alone: its first row's profile is missing.
    page.evaluate("""([text, name]) => {
        const data = new DataTransfer();
        data.items.add(new File([text], name, { type: 'text/csv' }));
        document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true }));
    }""", [WING.read_text(), "lonely.csv"])
    page.wait_for_timeout(300)
    shown = page.locator('[data-testid="errors"]').inner_text()
    check("lonely.csv: row 2 (naca4415.dat)" in shown and "missing" in shown,
          f"a table without profiles: {shown!r}")
    return bench["median"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("page")
    ap.add_argument("--karkas", required=True)
    ap.add_argument("--screenshot")
    args = ap.parse_args()
    problems = []

    def check(ok, what):
        if not ok:
            problems.append(what)
        return ok

    work = pathlib.Path(tempfile.mkdtemp())
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=ARGS)
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.on("console", lambda m: m.type == "error" and problems.append(f"console error: {m.text}"))
        page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
        page.route("http://*/**", lambda r: (problems.append(f"network request: {r.request.url}"), r.abort()))
        page.route("https://*/**", lambda r: (problems.append(f"network request: {r.request.url}"), r.abort()))
        page.goto(pathlib.Path(args.page).resolve().as_uri(), wait_until="load")
        page.evaluate("window.karkasWorkbench.ready")

        # 2. The shipped airfoil through the file picker.
        page.set_input_files('[data-testid="file"]', str(AIRFOIL))
        page.wait_for_function(f"window.karkasWorkbench.state().name === '{AIRFOIL.name}'")
        page.evaluate("""() => { const w = window.karkasWorkbench;
            w.setOption('order', 3); w.setOption('method-ll', true);
            w.setOption('method-spline', true); w.setOption('method-fit', true); }""")
        state = page.evaluate("window.karkasWorkbench.state()")
        check(state["errors"] == [], f"errors on the airfoil: {state['errors']}")
        before = page.evaluate("window.karkasWorkbench.curves()")
        check(set(before) >= {"ll", "spline", "fit"}, f"curves drawn: {sorted(before)}")
        plot_before = element_pixels(page, "curvature-plot")

        # 3. Drag point 20 with the mouse.
        x, y = page.evaluate("window.karkasWorkbench.pointOnScreen(20)")
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + 12, y - 25, steps=6)
        page.mouse.up()
        after = page.evaluate("window.karkasWorkbench.curves()")
        for method in ("ll", "spline", "fit"):
            a, b = numpy.array(before[method]["points"]), numpy.array(after[method]["points"])
            check(a.shape == b.shape and numpy.abs(a - b).max() > 1e-4,
                  f"{method}: the curve did not change with the drag")
            ka, kb = numpy.array(before[method]["curvature"]), numpy.array(after[method]["curvature"])
            check(ka.shape != kb.shape or numpy.abs(ka - kb).max() > 1e-6,
                  f"{method}: the curvature did not change with the drag")
        plot_after = element_pixels(page, "curvature-plot")
        check(plot_before.shape == plot_after.shape and (plot_before != plot_after).mean() > 1e-3,
              "the curvature plot did not change with the drag")
        moved_x, moved_y = page.evaluate("window.karkasWorkbench.pointOnScreen(20)")
        check(abs(moved_x - (x + 12)) < 1.5 and abs(moved_y - (y - 25)) < 1.5,
              f"point 20 is at {moved_x:.1f},{moved_y:.1f}, not where it was dragged")

        # 4. Exports against the command line, on the dragged points.
        points = page.evaluate("window.karkasWorkbench.export('points')")
        stem = AIRFOIL.stem
        for ext in ("step", "iges", "dxf", "csv"):
            from_page = page.evaluate(f"window.karkasWorkbench.export('{ext}')")
            from_cli = cli_text(args.karkas, ["curve", "ll", "--order", "3"], points, stem, ext, work)
            if ext in ("step", "iges"):
                from_page, from_cli = without_time_stamp(from_page), without_time_stamp(from_cli)
            check(from_page == from_cli, f"{ext.upper()} from the page differs from the command line's")
        svg = page.evaluate("window.karkasWorkbench.export('svg')")
        try:
            root = xml.etree.ElementTree.fromstring(svg)
            check(root.tag.endswith("svg") and len(list(root.iter())) > 10, "the SVG export is empty")
        except xml.etree.ElementTree.ParseError as e:
            check(False, f"the SVG export is not XML: {e}")
        if args.screenshot:
            page.screenshot(path=args.screenshot)

        # 5. A damaged airfoil: the command line's words beside the line.
        page.set_input_files('[data-testid="file"]', str(DAMAGED))
        page.wait_for_timeout(300)
        cli = subprocess.run([args.karkas, "curve", "ll", str(DAMAGED), "-o", str(work / "x.csv")],
                             capture_output=True, text=True)
        shown = page.locator('[data-testid="errors"]').inner_text()
        cli_message = cli.stderr.strip().replace(str(DAMAGED), DAMAGED.name)
        check(cli.returncode == 2 and shown.strip() == cli_message,
              f"damaged file: page says {shown!r}, the command line {cli_message!r}")
        check(page.locator('[data-testid="input-lines"] .bad').count() == 1,
              "damaged file: the offending line is not marked")

        # A file dropped on the page: the shipped contour.
        contour = ROOT / "data" / "contour-53.csv"
        page.evaluate("""([text, name]) => {
            const data = new DataTransfer();
            data.items.add(new File([text], name, { type: 'text/csv' }));
            document.body.dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true }));
        }""", [contour.read_text(), contour.name])
        page.wait_for_function(f"window.karkasWorkbench.state().name === '{contour.name}'")
        state = page.evaluate("window.karkasWorkbench.state()")
        check(state["points"] == 53 and state["errors"] == [], f"dropped contour: {state}")

        # 6. The shipped grid: a surface with a section; STEP as the command line's.
        page.set_input_files('[data-testid="file"]', str(GRID))
        page.wait_for_function(f"window.karkasWorkbench.state().name === '{GRID.name}'")
        page.evaluate("window.karkasWorkbench.setOption('section', 0.4)")
        state = page.evaluate("window.karkasWorkbench.state()")
        check(state["kind"] == "grid" and state["errors"] == [], f"grid: {state}")
        check(state["sectionSegments"] > 10, f"grid: the section has {state['sectionSegments']} segments")
        check(page.locator('[data-testid="view3d"]').is_visible(), "grid: no 3-D view")
        for ext in ("step", "obj"):
            from_page = without_time_stamp(page.evaluate(f"window.karkasWorkbench.export('{ext}')"))
            from_cli = without_time_stamp(
                cli_text(args.karkas, ["surface", "ll", "--order", "3"], GRID.read_text(), GRID.stem, ext, work))
            check(from_page == from_cli, f"surface {ext.upper()} from the page differs from the command line's")
        stl = page.evaluate("window.karkasWorkbench.export('stl')")
        check(stl.startswith("solid") and stl.count("facet normal") > 1000, "the STL export is not a mesh")

        # A curve network (two files): the Gordon surface, as `karkas surface coons --kind gordon`.
        u_text, v_text = network()
        (work / "u.csv").write_text(u_text)
        (work / "v.csv").write_text(v_text)
        page.set_input_files('[data-testid="file"]', [str(work / "u.csv"), str(work / "v.csv")])
        page.wait_for_function("window.karkasWorkbench.state().kind === 'network'")
        state = page.evaluate("window.karkasWorkbench.state()")
        check(state["errors"] == [] and state["sectionSegments"] > 10, f"network: {state}")
        from_page = without_time_stamp(page.evaluate("window.karkasWorkbench.export('step')"))
        subprocess.run([args.karkas, "surface", "coons", "--kind", "gordon", "--u-curves",
                        str(work / "u.csv"), "--v-curves", str(work / "v.csv"), "-o",
                        str(work / "u.step")], check=True, capture_output=True)
        from_cli = without_time_stamp((work / "u.step").read_text())
        check(from_page == from_cli, "network STEP from the page differs from the command line's")

        loft_rebuild_ms = check_loft(page, args.karkas, work, check)
        browser.close()

    for line in problems:
        print(f"check_workbench: {line}")
    if not problems:
        print("check_workbench: ok (airfoil loaded, dragged, curves and curvature plot changed; "
              "STEP, IGES, DXF, CSV, surface STEP and OBJ, network STEP equal the command line's; "
              "errors as the command line's; surfaces with sections; the demo wing lofted, its STEP within 1e-9 of "
              f"equal to karkas loft's, a twist slider moving its tip only; loft rebuild "
              f"{loft_rebuild_ms:.1f} ms median)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
