#!/usr/bin/env python3
"""Load a local HTML page in headless Chromium and check that it works.

Fails (exit 1, one line per problem) on: any console error, any uncaught page error, any
failed request (including any request leaving the machine, which a self-contained page never
makes), any <img> that did not load (naturalWidth 0), and a screenshot whose fraction of
non-background pixels is below --min-foreground. The background colour is the colour of the
screenshot's top-left pixel.

Usage: check_page.py PAGE [--screenshot OUT.png] [--min-foreground FRACTION]
                          [--width W] [--height H] [--wait-ms MS]

Needs Python Playwright, Pillow and NumPy. Uses the system Chromium (/usr/bin/chromium, or $CHROMIUM); Playwright
never downloads a browser here.
"""
import argparse
import os
import pathlib
import sys
import tempfile

from playwright.sync_api import sync_playwright

CHROMIUM = os.environ.get("CHROMIUM", "/usr/bin/chromium")
ARGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    # WebGL without a GPU: Chromium's software rasterizer (SwiftShader) must be allowed.
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
]


def foreground_fraction(png_path):
    """The fraction of pixels that differ from the top-left pixel (by more than 8 levels)."""
    import numpy
    from PIL import Image

    pixels = numpy.asarray(Image.open(png_path).convert("RGB")).astype(int)
    differ = numpy.abs(pixels - pixels[0, 0]).max(axis=2) > 8
    return float(differ.mean())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("page")
    parser.add_argument("--screenshot")
    parser.add_argument("--min-foreground", type=float, default=0.0)
    parser.add_argument("--width", type=int, default=1280)
    parser.add_argument("--height", type=int, default=800)
    parser.add_argument("--wait-ms", type=int, default=1500)
    args = parser.parse_args()

    page_path = pathlib.Path(args.page).resolve()
    if not page_path.is_file():
        print(f"check_page: {args.page}: no such file")
        return 1
    url = page_path.as_uri()
    problems = []
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=ARGS)
        page = browser.new_page(viewport={"width": args.width, "height": args.height})
        page.on("console", lambda m: m.type == "error" and problems.append(f"console error: {m.text}"))
        page.on("pageerror", lambda e: problems.append(f"page error: {e}"))
        page.on("requestfailed", lambda r: problems.append(
            f"request failed: {r.url[:120]} ({r.failure})"))

        def outside(route):
            problems.append(f"network request: {route.request.url[:120]}")
            route.abort()

        page.route("http://*/**", outside)
        page.route("https://*/**", outside)
        page.goto(url, wait_until="load")
        page.wait_for_timeout(args.wait_ms)
        broken = page.evaluate(
            "Array.from(document.images).filter(i => !i.complete || i.naturalWidth === 0)"
            ".map(i => i.getAttribute('src') || '(no src)')")
        for src in broken:
            problems.append(f"image did not load: {src[:120]}")
        shot = args.screenshot or os.path.join(tempfile.mkdtemp(), "page.png")
        page.screenshot(path=shot, full_page=False)
        browser.close()
    fraction = foreground_fraction(shot)
    if fraction < args.min_foreground:
        problems.append(
            f"screenshot {shot}: {fraction:.4f} of the pixels are foreground, below {args.min_foreground}")
    for line in problems:
        print(f"check_page: {args.page}: {line}")
    if not problems:
        print(f"check_page: {args.page}: ok (foreground {fraction:.3f})")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
