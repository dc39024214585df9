#!/usr/bin/env python3
"""SciPy's own tests of ``CubicSpline`` run against ``karkas.CubicSpline``.

The tests are copied at run time (never kept in this repository) from the installed SciPy:
``scipy/interpolate/tests/test_polyint.py``, where ``TestCubicSpline`` and the shape tests
that build ``CubicSpline`` live. When the installed wheel ships no tests, the script fetches
the same version's source with ``pip download scipy==<version> --no-binary :all: --no-deps``
and takes the file from it.

The copy runs under pytest with SciPy's ``conftest`` (its ``xp`` fixture; NumPy only) and
``CubicSpline`` in the test module replaced by the thin adapter of
``karkas_cubic_spline.py``. The tests that build a ``CubicSpline`` are selected; a test
skips when it reaches a feature karkas does not claim (the adapter names it). The skipped
tests then run again with those features handed to SciPy (each unclaimed construction or
method alone), so that the rest of them still checks every spline karkas builds, and must
pass. The run fails when any test fails, when a test skips that ``unclaimed.txt`` does not
list with its reason, when a listed test no longer skips (the list would be stale), or when a
skipped test fails in the second run.

    python3 tests/scipy/run_cubic_spline_tests.py            # prints the passed and skipped
"""

import argparse
import os
import pathlib
import shutil
import subprocess
import sys
import tarfile
import tempfile
from xml.etree import ElementTree

HERE = pathlib.Path(__file__).resolve().parent
TEST_FILE = "scipy/interpolate/tests/test_polyint.py"
# The tests of test_polyint.py that build a CubicSpline.
SELECTED = (
    "TestCubicSpline or test_complex or test_deriv_shapes or (test_zero_size and CubicSpline)"
    " or (test_shapes and not TestKrogh and not TestBarycentric)"
)

CONFTEST = '''
import pytest
import karkas_cubic_spline

pytest_plugins = ["scipy.conftest"]


@pytest.fixture(autouse=True)
def _karkas_cubic_spline(request, monkeypatch):
    """CubicSpline of the test module is the adapter over karkas.CubicSpline."""
    if request.module is not None and hasattr(request.module, "CubicSpline"):
        monkeypatch.setattr(request.module, "CubicSpline", karkas_cubic_spline.CubicSpline)
'''


def scipy_test_file(work):
    """The path of SciPy's test file: in the installed package, else from its source."""
    import scipy

    installed = pathlib.Path(scipy.__file__).parent.parent / TEST_FILE
    if installed.is_file():
        return installed
    download = work / "sdist"
    subprocess.run(
        [sys.executable, "-m", "pip", "download", f"scipy=={scipy.__version__}",
         "--no-binary", ":all:", "--no-deps", "--no-build-isolation", "-d", str(download)],
        check=True,
    )
    archive = next(download.glob("scipy-*.tar.gz"))
    with tarfile.open(archive) as tar:
        member = next(m for m in tar.getmembers() if m.name.endswith(TEST_FILE))
        tar.extract(member, work, filter="data")
    return work / member.name


def expected_skips():
    """The tests listed in unclaimed.txt: `test id<TAB>reason`, `#` comments."""
    listed = {}
    for line in (HERE / "unclaimed.txt").read_text().splitlines():
        line = line.split("#", 1)[0].rstrip()
        if line:
            test, reason = line.split("\t", 1)
            listed[test.strip()] = reason.strip()
    return listed


def run_pytest(run, work, selection, fallback):
    """Runs the selected tests of the copy in `run`; their outcomes by test id, and (in
    fallback mode) how many splines karkas and SciPy built."""
    junit = work / ("fallback.xml" if fallback else "strict.xml")
    counts_file = work / "counts.txt"
    counts_file.write_text("")
    env = {**os.environ, "PYTHONPATH": str(run), "KARKAS_SCIPY_COUNTS": str(counts_file)}
    if fallback:
        env["KARKAS_SCIPY_FALLBACK"] = "1"
    result = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
         f"--junitxml={junit}", "-k", selection, "test_scipy_cubic_spline.py"],
        cwd=run, capture_output=True, text=True, env=env,
    )
    outcomes = {}
    if junit.is_file():
        for case in ElementTree.parse(junit).getroot().iter("testcase"):
            test = case.get("classname", "").split(".")[-1] + "::" + case.get("name", "")
            test = test.removeprefix("test_scipy_cubic_spline::")
            skipped = case.find("skipped")
            bad = case.find("failure") if case.find("failure") is not None else case.find("error")
            if bad is not None:
                outcomes[test] = ("failed", (bad.get("message") or "")[:300])
            elif skipped is not None:
                outcomes[test] = ("skipped", skipped.get("message") or "")
            else:
                outcomes[test] = ("passed", "")
    built = counts_file.read_text().split()
    return outcomes, (built.count("karkas"), built.count("scipy")), result


def pytest_name(test):
    """The -k expression of one test id (`Class::name[param]`)."""
    cls, _, name = test.rpartition("::")
    base = name.split("[")[0]
    return f"({cls} and {base})" if cls else base


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        source = scipy_test_file(work)
        run = work / "run"
        run.mkdir()
        shutil.copy(source, run / "test_scipy_cubic_spline.py")
        shutil.copy(HERE / "karkas_cubic_spline.py", run)
        (run / "conftest.py").write_text(CONFTEST)
        outcomes, (karkas_built, _), result = run_pytest(run, work, SELECTED, False)
        if not outcomes:
            print(result.stdout[-3000:] + result.stderr[-3000:])
            return 1
        skipped = sorted(t for t, (o, _) in outcomes.items() if o == "skipped")
        second = {}
        fallback_counts = (0, 0)
        if skipped:
            selection = " or ".join(sorted({pytest_name(t) for t in skipped}))
            second, fallback_counts, _ = run_pytest(run, work, selection, True)
    listed = expected_skips()
    problems = []
    counts = {"passed": 0, "skipped": 0, "failed": 0}
    for test, (outcome, message) in sorted(outcomes.items()):
        counts[outcome] += 1
        if outcome == "failed":
            problems.append(f"FAILED {test}: {message}")
        elif outcome == "skipped" and test not in listed:
            problems.append(f"skipped but not listed in unclaimed.txt: {test}: {message}")
        elif outcome == "passed" and test in listed:
            problems.append(f"listed in unclaimed.txt but passes (remove it): {test}")
        if outcome == "skipped":
            again, message = second.get(test, ("not run", ""))
            if again != "passed":
                problems.append(
                    f"{test}: with the unclaimed parts handed to SciPy, {again}: {message}"
                )
    for test in listed:
        if test not in outcomes:
            problems.append(f"listed in unclaimed.txt but not run: {test}")
    print(
        f"SciPy {scipy_version()}'s CubicSpline tests against karkas.CubicSpline: "
        f"{counts['passed']} passed ({karkas_built} splines built by karkas), "
        f"{counts['skipped']} not claimed (unclaimed.txt), {counts['failed']} failed"
    )
    for test, (outcome, message) in sorted(outcomes.items()):
        reason = f"  ({listed.get(test, message)})" if outcome == "skipped" else ""
        print(f"  {outcome:8} {test}{reason}")
    if skipped:
        k, sp = fallback_counts
        passed = sum(1 for t in skipped if second.get(t, ("",))[0] == "passed")
        print(
            f"The {len(skipped)} not claimed, run again with the unclaimed constructions and "
            f"methods handed to SciPy: {passed} passed, checking {k} splines built by karkas "
            f"({sp} by SciPy)"
        )
    for p in problems:
        print(p)
    if counts["passed"] == 0:
        problems.append("no test ran")
    return 1 if problems else 0


def scipy_version():
    """The installed SciPy's version."""
    import scipy

    return scipy.__version__


if __name__ == "__main__":
    sys.exit(main())
