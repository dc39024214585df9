#!/usr/bin/env python3
"""Checks that two `karkas` binaries fit curves identically, byte for byte.

Runs `karkas curve fit` in every mode (given knots, a knot count, a tolerance, a jump bound
with either penalty rule, closed, pinned, free and closed-trailing-edge ends, no smoothing,
the JSON summary) on real airfoils of the corpus (~/.cache/karkas-corpus/files, see
.ci/corpus.sh) and the repository's data/ files, and compares every output file, the exit
code, standard error and the JSON summary (the wall times, `seconds` and "fitted in",
left out) between
the two binaries. Meant for a restructuring of the fit that must not change what it
computes:

    python3 tests/fit/same_outputs.py BEFORE_BINARY AFTER_BINARY [--files N]

Exits 1 and names the first differences when any output differs.
"""

import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CORPUS = Path.home() / ".cache" / "karkas-corpus" / "files"

# Each mode: the options after `curve fit INPUT`, and the output's extension.
MODES = {
    "count": (["--knots", "12"], "csv"),
    "list": (["--knots", "0,0.05,0.15,0.3,0.45,0.5,0.55,0.7,0.85,0.95,1"], "csv"),
    "tolerance": (["--tolerance", "1e-4"], "csv"),
    "tolerance-coarse": (["--tolerance", "2e-3", "--eps", "1e-1"], "csv"),
    "eps-active": (["--knots", "14", "--eps", "1e-2"], "csv"),
    "eps-paper": (["--knots", "14", "--eps", "1e-2", "--penalty", "paper"], "csv"),
    "corner": (["--knots", "0,0.25,0.5,0.75,1", "--corner", "0.5", "--eps", "1e-3"], "csv"),
    "closed-count": (["--closed", "--knots", "10"], "csv"),
    "closed-tolerance": (["--closed", "--tolerance", "1e-3"], "csv"),
    "pin-ends": (["--knots", "12", "--pin-ends"], "csv"),
    "free-ends": (["--knots", "12", "--free-ends"], "csv"),
    "free-tolerance": (["--tolerance", "5e-4", "--free-ends"], "csv"),
    "close-te": (["--knots", "12", "--close-te"], "dxf"),
    "smoothing-0": (["--knots", "16", "--smoothing", "0"], "csv"),
    "smoothing-0-tol": (["--tolerance", "3e-4", "--smoothing", "0"], "csv"),
    "json": (["--knots", "10", "--json"], "csv"),
    "json-tolerance": (["--tolerance", "1e-3", "--json"], "csv"),
}


def inputs(count):
    """About `count` airfoils spread over the corpus, then the data/ files."""
    found = sorted(CORPUS.rglob("*.dat")) if CORPUS.is_dir() else []
    step = max(1, len(found) // max(1, count))
    chosen = found[::step][:count]
    data = ROOT / "data"
    chosen += sorted(data.glob("*.csv"))
    chosen += sorted((data / "batch-foils").glob("*.dat"))[::3]
    return chosen


def run(binary, source, mode, work):
    """Every observable output of one fit: exit code, stderr, output files, JSON summary."""
    options, ext = MODES[mode]
    out = work / f"fit.{ext}"
    report = work / "dev.csv"
    command = [binary, "curve", "fit", str(source), *options, "-o", str(out), "--report", str(report)]
    done = subprocess.run(command, capture_output=True, timeout=600)
    stdout = done.stdout
    if "--json" in options and done.returncode == 0:
        lines = []
        for line in stdout.decode().splitlines():
            try:
                summary = json.loads(line)
            except ValueError:
                lines.append(line)
                continue
            summary.pop("seconds", None)
            lines.append(json.dumps(summary, sort_keys=True))
        stdout = "\n".join(lines).encode()
    stderr = done.stderr.replace(str(source).encode(), b"INPUT").replace(str(work).encode(), b"WORK")
    # The wall time of the fit ("fitted in 7.4 ms") is left out.
    stderr = re.sub(rb"fitted in [0-9.e+-]+ ?[a-z\xc2\xb5]*s", b"fitted in T", stderr)
    files = {}
    for path in (out, report):
        if path.exists():
            files[path.name] = path.read_bytes()
            path.unlink()
    return {"code": done.returncode, "stdout": stdout, "stderr": stderr, "files": files}


def compare(before, after, source, mode):
    with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
        first = run(before, source, mode, Path(a))
        second = run(after, source, mode, Path(b))
    if first == second:
        return None, first["code"]
    keys = [k for k in first if first[k] != second[k]]
    return f"{source} [{mode}]: differs in {keys}", first["code"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--files", type=int, default=40, help="corpus airfoils to fit")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    before, after = os.path.abspath(args.before), os.path.abspath(args.after)
    sources = inputs(args.files)
    cases = [(s, m) for s in sources for m in MODES]
    differences, codes = [], {}
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        for diff, code in pool.map(lambda c: compare(before, after, *c), cases):
            codes[code] = codes.get(code, 0) + 1
            if diff:
                differences.append(diff)
    print(f"{len(cases)} fits ({len(sources)} inputs x {len(MODES)} modes), exit codes {codes}")
    for line in differences[:20]:
        print(line)
    if differences:
        print(f"{len(differences)} of {len(cases)} fits differ")
        return 1
    print("all outputs byte-identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
