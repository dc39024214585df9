#!/usr/bin/env python3
"""The workbench's benchmark: update time while dragging a point of a 200-point airfoil with LL,
the cubic spline and the fit on (built by the library in WebAssembly and redrawn), median and
95th percentile; the full rebuild when a drag ends; the size of the WebAssembly module; in
headless Chromium (20 drags of 10 moves each, per page load).

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
            results.append(page.evaluate(f"window.karkasWorkbench.bench({args.points}, 20, 10)"))
            page.close()
        browser.close()
    for r in results:
        print(f"{r['points']} points, {r['updates']} updates while dragging ({', '.join(r['methods'])}): "
              f"median {r['median']:.1f} ms, 95th percentile {r['p95']:.1f} ms; "
              f"drag end {r['dragEndMedian']:.1f} ms")
    if any(r["points"] != args.points for r in results):
        print(f"bench: the page did not load the {args.points}-point section")
        return 1
    median = statistics.median(r["median"] for r in results)
    p95 = statistics.median(r["p95"] for r in results)
    end = statistics.median(r["dragEndMedian"] for r in results)
    print(f"update while dragging: median {median:.1f} ms, 95th percentile {p95:.1f} ms; "
          f"when a drag ends {end:.1f} ms (medians of {len(results)} page loads); "
          f"WebAssembly {results[0]['wasmBytes'] / 1e6:.2f} MB, "
          f"page {pathlib.Path(args.page).stat().st_size / 1e6:.2f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
