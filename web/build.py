#!/usr/bin/env python3
"""Build the karkas workbench: one self-contained HTML page (the WebAssembly module, its
JavaScript glue, three.js and the page script inlined), which opens from disk.

    python3 web/build.py             # writes target/web/karkas-workbench.html
    python3 web/build.py --install   # and copies it to web/dist/, which `karkas demo` embeds
    python3 web/build.py --check     # fails when web/dist/ is stale against the sources

Needs the `wasm32-unknown-unknown` Rust target and `wasm-bindgen` (the CLI of the version
crates/karkas-wasm pins). The page carries a SHA-256 of every source it is built from
(`karkas-sources`), so `--check` tells a stale committed page without rebuilding it
byte for byte.
"""
import argparse
import base64
import hashlib
import json
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
WEB = ROOT / "web"
OUT = ROOT / "target" / "web"
INSTALLED = WEB / "dist" / "karkas-workbench.html"
THREE = ROOT / "crates" / "karkas-io" / "vendor" / "three"
# The shipped data the page offers to start from (name shown: path).
DEMO = {
    "foil-00000.dat": ROOT / "data" / "batch-foils" / "foil-00000.dat",
    "contour-53.csv": ROOT / "data" / "contour-53.csv",
    "aircraft-15x31.csv": ROOT / "data" / "aircraft-15x31.csv",
    # The demo wing of the loft: its sections table first, then the profiles it names.
    "loft-wing/wing.csv": ROOT / "data" / "loft-wing" / "wing.csv",
    "loft-wing/naca4415.dat": ROOT / "data" / "loft-wing" / "naca4415.dat",
    "loft-wing/naca2412.dat": ROOT / "data" / "loft-wing" / "naca2412.dat",
    "loft-wing/naca0009.dat": ROOT / "data" / "loft-wing" / "naca0009.dat",
}


def tracked(folder):
    """The files of `folder` that git tracks or would (not ignored): the same before and after
    they are added; all of them outside a git work tree."""
    try:
        names = subprocess.run(["git", "ls-files", "-z", "--cached", "--others",
                                "--exclude-standard", folder], cwd=ROOT, check=True,
                               capture_output=True).stdout.decode().split("\0")
        return [ROOT / n for n in names if n]
    except (OSError, subprocess.CalledProcessError):
        return [p for p in (ROOT / folder).rglob("*") if p.is_file()]


def sources():
    """Every file the page is built from, sorted."""
    files = []
    for folder in ["crates/karkas/src", "crates/karkas-io/src", "crates/karkas-wasm"]:
        files += tracked(folder)
    files += [WEB / "workbench.html", WEB / "workbench.js", WEB / "build.py", ROOT / "Cargo.lock"]
    files += [THREE / "three.module.min.js", THREE / "OrbitControls.js"]
    files += list(DEMO.values())
    return sorted(p for p in set(files) if p.is_file())


def sources_hash():
    digest = hashlib.sha256()
    for path in sources():
        digest.update(str(path.relative_to(ROOT)).encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()


def installed_hash():
    if not INSTALLED.is_file():
        return None
    text = INSTALLED.read_text(encoding="utf-8")
    marker = '<meta name="karkas-sources" content="'
    at = text.find(marker)
    return text[at + len(marker):text.find('"', at + len(marker))] if at >= 0 else None


def data_url(text):
    return "data:text/javascript;base64," + base64.b64encode(text.encode()).decode()


def build():
    # `dist` (thin LTO, one code-generation unit), as the command line users install: a
    # tenth smaller than `release`.
    subprocess.run(["cargo", "build", "--profile", "dist", "--target", "wasm32-unknown-unknown",
                    "-p", "karkas-wasm"], cwd=ROOT, check=True)
    wasm_in = ROOT / "target" / "wasm32-unknown-unknown" / "dist" / "karkas_wasm.wasm"
    bindgen = OUT / "bindgen"
    bindgen.mkdir(parents=True, exist_ok=True)
    subprocess.run(["wasm-bindgen", "--target", "web", "--no-typescript", "--out-dir",
                    str(bindgen), str(wasm_in)], cwd=ROOT, check=True)
    glue = (bindgen / "karkas_wasm.js").read_text(encoding="utf-8")
    wasm = (bindgen / "karkas_wasm_bg.wasm").read_bytes()
    imports = {
        "imports": {
            "three": data_url((THREE / "three.module.min.js").read_text(encoding="utf-8")),
            "three/addons/controls/OrbitControls.js":
                data_url((THREE / "OrbitControls.js").read_text(encoding="utf-8")),
            "karkas-wasm": data_url(glue),
        }
    }
    demo = {name: path.read_text(encoding="utf-8") for name, path in DEMO.items()}
    script = (WEB / "workbench.js").read_text(encoding="utf-8")
    page = (WEB / "workbench.html").read_text(encoding="utf-8")
    for key, value in [
        ("@SOURCES@", sources_hash()),
        ("@IMPORTMAP@", json.dumps(imports)),
        ("@WASM@", base64.b64encode(wasm).decode()),
        # "</" would end the script element early.
        ("@DEMO@", json.dumps(demo).replace("</", "<\\/")),
        ("@SCRIPT@", script),
    ]:
        page = page.replace(key, value)
    out = OUT / "karkas-workbench.html"
    out.write_text(page, encoding="utf-8")
    print(f"wrote {out.relative_to(ROOT)}: {len(page) / 1e6:.2f} MB page, "
          f"{len(wasm) / 1e6:.2f} MB WebAssembly")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--install", action="store_true", help="copy the page to web/dist/")
    ap.add_argument("--check", action="store_true",
                    help="only check that web/dist/ was built from the current sources")
    args = ap.parse_args()
    if args.check:
        if installed_hash() != sources_hash():
            print(f"{INSTALLED.relative_to(ROOT)} is stale against its sources: "
                  "run python3 web/build.py --install and commit it")
            return 1
        print(f"{INSTALLED.relative_to(ROOT)} is built from the current sources")
        return 0
    out = build()
    if args.install:
        INSTALLED.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(out, INSTALLED)
        print(f"installed {INSTALLED.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
