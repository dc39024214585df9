"""The stubs (karkas.pyi) match the built module: `python -m mypy.stubtest karkas` is clean.

stubtest imports the installed package and compares every name, signature, default and
property of the stub with the runtime objects; the allowlist names only what it cannot see in
an extension module. Skipped where mypy is not installed (CI installs it).
"""

import pathlib
import subprocess
import sys

import pytest

ALLOWLIST = pathlib.Path(__file__).parent.parent / "stubtest-allowlist.txt"


def test_stubtest_is_clean(tmp_path):
    pytest.importorskip("mypy.stubtest")
    run = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "karkas", "--allowlist", str(ALLOWLIST)],
        capture_output=True,
        text=True,
        cwd=tmp_path,  # the installed package, not a source folder of the same name
    )
    assert run.returncode == 0, run.stdout + run.stderr
