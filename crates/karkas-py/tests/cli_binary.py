"""The karkas command-line binary for the tests that compare the package with it: KARKAS_BIN,
then the release and debug builds of the workspace (or of CARGO_TARGET_DIR), then PATH."""

import os
import pathlib
import shutil

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


def find_cli():
    candidates = [os.environ.get("KARKAS_BIN")]
    for target in (os.environ.get("CARGO_TARGET_DIR"), str(ROOT / "target")):
        if target:
            candidates += [os.path.join(target, "release", "karkas"), os.path.join(target, "debug", "karkas")]
    candidates.append(shutil.which("karkas"))
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    return None


CLI = find_cli()
needs_cli = pytest.mark.skipif(CLI is None, reason="the karkas binary is not built (cargo build --release -p karkas-cli)")
