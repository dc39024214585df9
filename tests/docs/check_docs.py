#!/usr/bin/env python3
"""Runs the commands and Python code of the book (docs/) and README.md and fails when their
output no longer matches what the page shows.

What runs, by the fence's info string:

- ```console: lines starting with `$ ` are commands (a line ending with a backslash continues
  on the next), run by bash with the karkas binary first on PATH; the lines after a command,
  up to the next `$ `, are its expected output (standard error and standard output in one
  stream). `...` alone on a line matches any number of lines; `...` inside a line matches any
  text. A command with no expected lines must only succeed. A last expected line `[exit N]`
  states a non-zero exit status.
- ```python with `>>>` prompts: a doctest (ELLIPSIS, NORMALIZE_WHITESPACE); ```python without
  prompts: run as a script, which must not raise.
- ```sh, ```text and every other fence: shown, not run (installation and build commands,
  which CI runs in its own steps).

Every page runs in a fresh folder holding links to the repository's data/ and examples/, its
blocks in order, the Python blocks of a page in one namespace (the interpreter running this
script must import karkas: the wheel's venv).

Pictures: every image a page names (`![alt](path)` or `<img src="path">` outside code blocks,
other than web addresses) must exist, relative to the page; every file under docs/images/
must be named by some page and stay under 300 KB (docs/images/regenerate.sh remakes them).

Usage: tests/docs/check_docs.py --karkas target/release/karkas [PAGE.md ...]
(default: README.md and every page under docs/ listed in docs/SUMMARY.md).
"""

from __future__ import annotations

import argparse
import doctest
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
FENCE = re.compile(r"^(`{3,})(.*)$")
SHOW = False  # --show: print every command's output (to write a page's expected lines)


def blocks(text: str):
    """(info string, first line number, body) of every fenced block, in order."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        ticks, info = m.group(1), m.group(2).strip()
        start, body = i + 1, []
        i += 1
        while i < len(lines) and not lines[i].startswith(ticks):
            body.append(lines[i])
            i += 1
        yield info, start + 1, body
        i += 1


def line_matches(expected: str, actual: str) -> bool:
    if "..." not in expected:
        return expected.rstrip() == actual.rstrip()
    pattern = ".*".join(re.escape(part) for part in expected.rstrip().split("..."))
    return re.fullmatch(pattern, actual.rstrip()) is not None


def output_matches(expected: list[str], actual: list[str]) -> bool:
    """Doctest's ELLIPSIS over lines: `...` alone matches any run of lines."""
    if not expected:
        return not actual
    head, rest = expected[0], expected[1:]
    if head.strip() == "...":
        return any(output_matches(rest, actual[k:]) for k in range(len(actual) + 1))
    return bool(actual) and line_matches(head, actual[0]) and output_matches(rest, actual[1:])


def console_commands(body: list[str]):
    """(command, expected lines) pairs of a console block."""
    commands: list[tuple[str, list[str]]] = []
    i = 0
    while i < len(body):
        line = body[i]
        if not line.startswith("$ "):
            if line.strip():
                raise ValueError(f"output before any command: {line!r}")
            i += 1
            continue
        command = line[2:]
        while command.endswith("\\") and i + 1 < len(body):
            i += 1
            command = command + "\n" + body[i]
        i += 1
        expected = []
        while i < len(body) and not body[i].startswith("$ "):
            expected.append(body[i])
            i += 1
        while expected and not expected[-1].strip():
            expected.pop()
        commands.append((command, expected))
    return commands


def run_console(body, where, cwd, env, failures) -> int:
    count = 0
    for command, expected in console_commands(body):
        count += 1
        status = 0
        if expected and re.fullmatch(r"\[exit \d+\]", expected[-1].strip()):
            status = int(expected[-1].strip()[6:-1])
            expected = expected[:-1]
        try:
            done = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, timeout=300,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        except subprocess.TimeoutExpired:
            failures.append(f"{where}: `{command}` ran over 300 s")
            continue
        actual = done.stdout.rstrip("\n").split("\n") if done.stdout.strip() else []
        if SHOW:
            print(f"{where}: $ {command}\n" + "\n".join(actual))
        if done.returncode != status:
            failures.append(f"{where}: `{command}` exited {done.returncode}, the page says "
                            f"{status}:\n" + done.stdout)
        elif expected and not output_matches(expected, actual):
            failures.append(f"{where}: `{command}` printed\n" + "\n".join(actual)
                            + "\nbut the page shows\n" + "\n".join(expected))
    return count


def run_python(body, where, globs, failures) -> int:
    source = "\n".join(body) + "\n"
    if ">>>" in source:
        test = doctest.DocTestParser().get_doctest(source, globs, where, where, 0)
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
        report: list[str] = []
        runner.run(test, out=report.append, clear_globs=False)
        if runner.failures:
            failures.append(f"{where}: doctest failed:\n" + "".join(report))
        return len(test.examples)
    try:
        exec(compile(source, where, "exec"), globs)
    except Exception as e:  # the page's code failed: report it with the page's line
        failures.append(f"{where}: {type(e).__name__}: {e}")
    return 1


def readme_shape(failures: list[str]) -> None:
    """The README stays a front door: at most 250 lines, none over 200 characters outside code
    blocks."""
    lines = (REPO / "README.md").read_text(encoding="utf-8").split("\n")
    if len(lines) > 251:
        failures.append(f"README.md: {len(lines)} lines, at most 250")
    fence = False
    for number, line in enumerate(lines, 1):
        if line.startswith("```"):
            fence = not fence
        elif not fence and len(line) > 200:
            failures.append(f"README.md:{number}: {len(line)} characters, at most 200 outside code")


IMAGE = re.compile(r"!\[[^\]]*\]\(([^)\s]+)[^)]*\)|<img[^>]*\ssrc=\"([^\"]+)\"")
IMAGE_LIMIT = 300 * 1024


def images(pages: list[Path], failures: list[str]) -> int:
    """Every picture a page names exists; every file of docs/images/ is named and small."""
    named: set[Path] = set()
    for page in pages:
        fence = False
        for number, line in enumerate(page.read_text(encoding="utf-8").split("\n"), 1):
            if line.lstrip().startswith("```"):
                fence = not fence
                continue
            if fence:
                continue
            for m in IMAGE.finditer(line):
                target = m.group(1) or m.group(2)
                if re.match(r"^[a-z]+:", target):
                    continue
                path = (page.parent / target.split("#")[0]).resolve()
                named.add(path)
                if not path.is_file():
                    failures.append(f"{page.relative_to(REPO)}:{number}: picture {target} is missing")
    folder = REPO / "docs" / "images"
    for path in sorted(folder.glob("*")) if folder.is_dir() else []:
        if path.suffix.lower() not in (".png", ".svg", ".jpg", ".gif", ".webp"):
            continue
        if path.resolve() not in named:
            failures.append(f"{path.relative_to(REPO)}: no page shows it")
        if path.stat().st_size > IMAGE_LIMIT:
            failures.append(f"{path.relative_to(REPO)}: {path.stat().st_size} bytes, at most {IMAGE_LIMIT}")
    return len(named)


def pages_of_book() -> list[Path]:
    summary = (REPO / "docs" / "SUMMARY.md").read_text(encoding="utf-8")
    pages = [REPO / "docs" / p for p in re.findall(r"\]\(([^)]+\.md)\)", summary)]
    return [REPO / "README.md"] + pages


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--karkas", required=True, help="the karkas binary the commands run")
    ap.add_argument("pages", nargs="*", type=Path)
    ap.add_argument("--show", action="store_true", help="print every command's output")
    args = ap.parse_args()
    global SHOW
    SHOW = args.show
    karkas = Path(args.karkas).resolve()
    bindir = Path(tempfile.mkdtemp(prefix="karkas-docs-bin-"))
    (bindir / "karkas").symlink_to(karkas)
    env = dict(os.environ, PATH=f"{bindir}{os.pathsep}{os.environ['PATH']}", MPLBACKEND="Agg")
    pages = [p.resolve() for p in args.pages] or pages_of_book()
    failures: list[str] = []
    readme_shape(failures)
    pictures = images(pages_of_book(), failures)
    totals = {"commands": 0, "python": 0, "shown": 0}
    start = time.monotonic()
    here = os.getcwd()
    for page in pages:
        rel = page.relative_to(REPO)
        work = Path(tempfile.mkdtemp(prefix="karkas-docs-"))
        for name in ("data", "examples"):
            (work / name).symlink_to(REPO / name)
        globs: dict = {"__name__": "__main__"}
        os.chdir(work)
        try:
            for info, line, body in blocks(page.read_text(encoding="utf-8")):
                lang = info.split(",")[0].split()[0] if info else ""
                where = f"{rel}:{line}"
                if lang == "console":
                    totals["commands"] += run_console(body, where, work, env, failures)
                elif lang == "python":
                    totals["python"] += run_python(body, where, globs, failures)
                else:
                    totals["shown"] += 1
        finally:
            os.chdir(here)
            shutil.rmtree(work, ignore_errors=True)
    shutil.rmtree(bindir, ignore_errors=True)
    for f in failures:
        print(f"FAIL {f}\n", file=sys.stderr)
    print(f"docs: {len(pages)} pages, {totals['commands']} commands and {totals['python']} Python "
          f"examples run, {totals['shown']} blocks shown only, {pictures} pictures found; "
          f"{len(failures)} failures "
          f"({time.monotonic() - start:.1f} s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
