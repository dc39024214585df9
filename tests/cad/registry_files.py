#!/usr/bin/env python3
"""karkas on real STEP and IGES files shipped in registry packages (Debian, PyPI, npm): files
read, entities, faces, edges and curves converted, and what was not read, with reasons.

The packages (about 90 MB together):
- Debian 12 (`apt-get download`): occt-misc (Open CASCADE's sample data: 2 STEP, 2 IGES),
  freecad-common (FreeCAD's IDF library of electronic parts: 28 STEP, 4 IGES) and kicad-demos
  (KiCad's demo 3-D models: 4 STEP);
- PyPI (`pip download --no-deps`, the wheel unpacked): gmsh 4.15.2 (the examples of its API and
  boolean operations: 6 STEP) and pyiges 0.3.4 (its examples: 2 IGES);
- npm (`npm pack`): occt-import-js 0.0.23 (its test files: 54 STEP and IGES, among them the
  CAx Implementor Forum's round-robin models written by several CAD systems).
Every .step/.stp/.iges/.igs file in them is read by the `cad_census` example of karkas-io (one
JSON line a file); this script sums them and prints the tables of docs/cad-files.md. Exit
status 1 when a file is refused, or fewer files are read than --expect-read.

    cargo build --release -p karkas-io --example cad_census
    python3 tests/cad/registry_files.py --census target/release/examples/cad_census \
        [--cache DIR] [--expect-read 104]

Not run in CI (the downloads); the files stay in --cache (default ~/.cache/karkas-cad-files).
"""

import argparse
import collections
import json
import os
import shutil
import subprocess
import sys

PACKAGES = ["occt-misc", "freecad-common", "kicad-demos"]
PYPI = ["gmsh==4.15.2", "pyiges==0.3.4"]
NPM = ["occt-import-js@0.0.23"]
EXTENSIONS = (".step", ".stp", ".iges", ".igs")


def fetch(cache):
    """Downloads and unpacks the packages (once); returns {package: [files]}."""
    os.makedirs(cache, exist_ok=True)
    out = {}
    for package in PACKAGES:
        folder = os.path.join(cache, package)
        if not os.path.isdir(folder):
            debs = [f for f in os.listdir(cache) if f.startswith(package + "_") and f.endswith(".deb")]
            if not debs:
                subprocess.run(["apt-get", "download", package], cwd=cache, check=True,
                               stdout=subprocess.DEVNULL)
                debs = [f for f in os.listdir(cache) if f.startswith(package + "_") and f.endswith(".deb")]
            subprocess.run(["dpkg", "-x", os.path.join(cache, sorted(debs)[-1]), folder], check=True)
        files = []
        for root, _, names in os.walk(folder):
            files += [os.path.join(root, n) for n in names if n.lower().endswith(EXTENSIONS)]
        out[package] = sorted(files)
    for spec in PYPI + NPM:
        package = spec.replace("==", "@").split("@")[0]
        folder = os.path.join(cache, package)
        if not os.path.isdir(folder):
            download = os.path.join(cache, "download-" + package)
            os.makedirs(download, exist_ok=True)
            if spec in PYPI:
                subprocess.run([sys.executable, "-m", "pip", "download", "--no-deps", "-q", "-d",
                                download, spec], check=True)
                archive = [f for f in os.listdir(download) if f.endswith(".whl")][0]
                shutil.unpack_archive(os.path.join(download, archive), folder, "zip")
            else:
                subprocess.run(["npm", "pack", "--silent", spec], cwd=download, check=True,
                               stdout=subprocess.DEVNULL)
                archive = [f for f in os.listdir(download) if f.endswith(".tgz")][0]
                shutil.unpack_archive(os.path.join(download, archive), folder, "gztar")
        files = []
        for root, _, names in os.walk(folder):
            files += [os.path.join(root, n) for n in names if n.lower().endswith(EXTENSIONS)]
        out[package] = sorted(files)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--census", default="target/release/examples/cad_census")
    parser.add_argument("--cache", default=os.path.expanduser("~/.cache/karkas-cad-files"))
    parser.add_argument("--expect-read", type=int, default=0)
    parser.add_argument("--list", action="store_true", help="one line per file too")
    args = parser.parse_args()
    by_package = fetch(args.cache)
    rows = []
    for package, files in by_package.items():
        done = subprocess.run([args.census, *files], capture_output=True, text=True, check=True)
        for line in done.stdout.splitlines():
            record = json.loads(line)
            record["package"] = package
            rows.append(record)
    refused = [r for r in rows if "error" in r]
    read = [r for r in rows if "error" not in r]
    print("| package | format | files | read | entities | faces | edges | free curves | seconds |")
    print("|---|---|---|---|---|---|---|---|---|")
    groups = collections.OrderedDict()
    for r in rows:
        fmt = r.get("format") or ("step" if r["file"].lower().endswith((".step", ".stp")) else "iges")
        groups.setdefault((r["package"], fmt), []).append(r)
    for (package, fmt), group in groups.items():
        ok = [r for r in group if "error" not in r]
        total = lambda key: sum(r[key] for r in ok)  # noqa: E731
        print(f"| {package} | {fmt.upper()} | {len(group)} | {len(ok)} | {total('entities'):,} | "
              f"{total('faces'):,} | {total('edges'):,} | {total('curves'):,} | "
              f"{sum(r['seconds'] for r in ok):.2f} |")
    print(f"\n{len(read)} of {len(rows)} files read; "
          f"{sum(r['faces'] for r in read):,} faces, {sum(r['edges'] for r in read):,} edges and "
          f"{sum(r['curves'] for r in read):,} free curves from {sum(r['entities'] for r in read):,} entities.\n")
    unread = collections.Counter()
    files_with = collections.Counter()
    for r in read:
        for u in r["unread"]:
            unread[(u["what"], u["reason"])] += u["count"]
            files_with[(u["what"], u["reason"])] += 1
    if unread:
        print("| not read | count | files | reason |")
        print("|---|---|---|---|")
        for (what, reason), count in sorted(unread.items(), key=lambda kv: -kv[1]):
            print(f"| {what} | {count:,} | {files_with[(what, reason)]} | {reason} |")
    notes = collections.Counter(n.split(" (")[0] if "assembly" not in n else n.split(":")[0][n.find(" ") + 1:]
                                for r in read for n in r["notes"])
    if notes:
        print("\nNotes: " + "; ".join(f"{n} ({c} files)" for n, c in notes.items()))
    for r in refused:
        print(f"REFUSED {os.path.basename(r['file'])}: {r['error']}")
    if args.list:
        for r in rows:
            name = os.path.basename(r["file"])
            if "error" in r:
                continue
            print(f"{name}: {r['entities']} entities, {r['faces']} faces, {r['edges']} edges, "
                  f"{r['curves']} curves, unit {r['unit']}")
    sys.exit(1 if refused or len(read) < args.expect_read else 0)


if __name__ == "__main__":
    main()
