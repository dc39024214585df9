#!/usr/bin/env bash
# Regenerates the book's pictures from the data the repository ships:
#   docs/images/regenerate.sh [path/to/karkas]      (default: target/release/karkas)
# The curvature pictures are karkas's own SVG output; the screenshots of the workbench page
# and of the demo's report are taken by headless Chromium (Debian's `chromium` package), at a
# fixed window size. tests/docs/check_docs.py fails when a page names a picture that is missing
# or one of them grows past 300 KB.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
karkas=$(realpath "${1:-$repo/target/release/karkas}")
out=$repo/docs/images
foil=$repo/data/batch-foils/foil-00003.dat
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Curvature combs: the interpolating spline of a measured airfoil, then the fair curve within
# 1e-4 of its points; and the curvature against arc length of three methods on Pavlov's hydrofoil
# (the commands docs/guide/fitting.md and docs/guide/which-method.md show).
"$karkas" curve spline "$foil" --comb -o "$out/foil-spline-comb.svg"
"$karkas" curve fair "$foil" --tolerance 1e-4 --comb -o "$out/foil-fair-comb.svg"
"$karkas" curve analyze "$repo/data/hydrofoil-profile.csv" --compare ll,spline,fit --knots 6 \
    -o "$out/hydrofoil-curvature.svg"

shot() { # shot PAGE_URL OUT.png WIDTH,HEIGHT
    chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$3" \
        --virtual-time-budget=10000 --screenshot="$2" "$1" 2>/dev/null >/dev/null
}
# The workbench page as it opens (the demo airfoil with its three curves and their combs).
shot "file://$repo/web/dist/karkas-workbench.html" "$out/workbench.png" 1280,800
# The top of the demo's report.
"$karkas" demo --out "$scratch/demo" >/dev/null 2>&1
shot "file://$scratch/demo/index.html" "$out/demo-report.png" 1280,900
ls -l "$out"
