#!/usr/bin/env python3
"""The workbench's benchmark: update time per drag for a 200-point airfoil with LL, the cubic
spline and the fit on (build by the library in WebAssembly and redraw), median and 95th
percentile, and the size of the WebAssembly module, in headless Chromium.

    python3 web/bench.py [PAGE] [--rounds 3]

PAGE defaults to target/web/karkas-workbench.html (python3 web/build.py). The same figures
show in the page itself when it is opened as karkas-workbench.html#bench.
"""
import argparse
import pathlib
import statistics
import sys

from playwright.sync_api import sync_playwright

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "tests" / "browser"))
from check_page import ARGS, CHROMIUM  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("page", nargs="?", default=str(ROOT / "target" / "web" / "karkas-workbench.html"))
    ap.add_argument("--rounds", type=int, default=3, help="page loads, each 200 drags")
    ap.add_argument("--points", type=int, default=200)
    args = ap.parse_args()
    results = []
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True, args=ARGS)
        for _ in range(args.rounds):
            page = browser.new_page(viewport={"width": 1280, "height": 800})
            page.goto(pathlib.Path(args.page).resolve().as_uri(), wait_until="load")
            page.evaluate("window.karkasWorkbench.ready")
            results.append(page.evaluate(f"window.karkasWorkbench.bench({args.points}, 200)"))
            page.close()
        browser.close()
    for r in results:
        print(f"{r['points']} points, {r['drags']} drags ({', '.join(r['methods'])}): "
              f"median {r['median']:.2f} ms, 95th percentile {r['p95']:.2f} ms")
    median = statistics.median(r["median"] for r in results)
    p95 = statistics.median(r["p95"] for r in results)
    print(f"update per drag: median {median:.2f} ms, 95th percentile {p95:.2f} ms "
          f"(medians of {len(results)} page loads); WebAssembly {results[0]['wasmBytes'] / 1e6:.2f} MB, "
          f"page {pathlib.Path(args.page).stat().st_size / 1e6:.2f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
