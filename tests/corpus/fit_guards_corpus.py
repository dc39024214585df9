#!/usr/bin/env python3
"""Fit every airfoil file of the real-file corpus at a tolerance and count the shape warnings
of the fits (docs/methods.md §4, "shape guards"): the fitted curve must not cross itself where
the points do not, nor turn more than the point polygon plus a margin.

    python3 tests/corpus/fit_guards_corpus.py --karkas target/release/karkas --dir CORPUS/files

Every airfoil file (.dat, as tests/corpus/run_corpus.py classes them; the files listed in
tests/corpus/expected_refusals.txt for `curve fit` or `*` are skipped) is fitted with

    karkas curve fit FILE --tolerance 1e-4 -o OUT.csv

and the `karkas: warning:` lines of its stderr are counted by kind: self_intersection,
excess_turning, sparse_pieces, empty_span, tolerance_not_met ("N more warnings like the above
(KIND)" adds N). Runs go in parallel (--jobs, default 2), each killed after --timeout seconds
of wall clock (default 60). --exclude TEXT skips the files whose path contains TEXT (e.g. a
multi-element section, several contours in one file). --limit N fits an even sample of N files (every k-th) instead of
all of them.

Exit status 1 when any fit crosses itself or turns too much (the warnings are listed with their
file; --at-most KIND=FILES allows up to FILES files of a kind, a ratchet), when a fit fails, or
when a run times out (unless --allow-timeouts); 0 otherwise. The
last line reads 'fit guards: N files, N self_intersection, N excess_turning, ...'.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
SHAPE = ("self_intersection", "excess_turning")
KINDS = SHAPE + ("sparse_pieces", "empty_span", "tolerance_not_met", "other")
MORE = re.compile(r"^(\d+) more warnings like the above \((\w+)\)")


def kind_of(message: str) -> str:
    """The kind of a warning, from its message."""
    if "crosses itself" in message:
        return "self_intersection"
    if " rad" in message and "turns" in message:
        return "excess_turning"
    if "fewer than 3" in message:
        return "sparse_pieces"
    if "no point" in message:
        return "empty_span"
    if message.startswith("tolerance") and "not met" in message:
        return "tolerance_not_met"
    return "other"


@dataclass
class Result:
    file: str
    status: int | None  # None: timed out
    seconds: float
    counts: Counter = field(default_factory=Counter)
    shape: list[str] = field(default_factory=list)  # the crossing and turning messages
    error: str = ""


def airfoil_files(root: Path) -> list[str]:
    """The .dat files under root (relative paths, sorted; hidden ones skipped)."""
    return sorted(
        p.relative_to(root).as_posix()
        for p in root.rglob("*")
        if p.is_file() and not p.name.startswith(".") and p.suffix.lower() == ".dat"
    )


def refused(listing: Path) -> set[str]:
    """Files expected to be refused by `curve fit` (or by every command)."""
    out = set()
    if listing.exists():
        for line in listing.read_text(encoding="utf-8").splitlines():
            if not line.strip() or line.startswith("#"):
                continue
            parts = line.split("\t")
            if len(parts) >= 2 and parts[1] in ("curve fit", "*"):
                out.add(parts[0])
    return out


def fit(karkas: str, root: Path, rel: str, tolerance: float, timeout: float, tmp: Path) -> Result:
    out = tmp / (re.sub(r"[^A-Za-z0-9_.-]", "_", rel) + ".csv")
    cmd = [karkas, "curve", "fit", str(root / rel), "--tolerance", str(tolerance), "-o", str(out)]
    started = time.monotonic()
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return Result(rel, None, time.monotonic() - started)
    result = Result(rel, run.returncode, time.monotonic() - started)
    out.unlink(missing_ok=True)
    for line in run.stderr.splitlines():
        if line.startswith("karkas: warning: "):
            message = line[len("karkas: warning: "):]
            more = MORE.match(message)
            if more:
                result.counts[more.group(2)] += int(more.group(1))
                continue
            kind = kind_of(message)
            result.counts[kind] += 1
            if kind in SHAPE:
                result.shape.append(message)
        elif line.startswith("karkas: error:") or "panicked" in line:
            result.error = line
    return result


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--karkas", default="target/release/karkas")
    default_dir = Path(os.environ.get("KARKAS_CORPUS_DIR", Path.home() / ".cache/karkas-corpus")) / "files"
    ap.add_argument("--dir", type=Path, default=default_dir)
    ap.add_argument("--tolerance", type=float, default=1e-4)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds of wall clock per fit")
    ap.add_argument("--limit", type=int, default=0, help="fit an even sample of N files")
    ap.add_argument("--allow-timeouts", action="store_true")
    ap.add_argument(
        "--exclude", action="append", default=[], metavar="TEXT",
        help="skip files whose path contains TEXT (repeat for several)",
    )
    ap.add_argument("--slowest", type=int, default=10, help="list the N slowest fits")
    ap.add_argument(
        "--at-most", action="append", default=[], metavar="KIND=FILES",
        help="allow up to FILES files with warnings of a shape KIND (self_intersection or "
        "excess_turning) instead of none: a ratchet while the fit still makes them",
    )
    args = ap.parse_args()

    skip = refused(HERE / "expected_refusals.txt")
    files = [
        f for f in airfoil_files(args.dir)
        if f not in skip and not any(text in f for text in args.exclude)
    ]
    if not files:
        print(f"fit guards: no airfoil files under {args.dir}", file=sys.stderr)
        return 1
    if 0 < args.limit < len(files):
        step = len(files) / args.limit
        files = [files[int(k * step)] for k in range(args.limit)]
    started = time.monotonic()
    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(args.jobs) as pool:
        results = list(
            pool.map(lambda f: fit(args.karkas, args.dir, f, args.tolerance, args.timeout, Path(tmp)), files)
        )
    wall = time.monotonic() - started

    total = Counter()
    warned = Counter()  # files with at least one warning of a kind
    for r in results:
        total.update(r.counts)
        warned.update(set(r.counts))
    timeouts = [r for r in results if r.status is None]
    failed = [r for r in results if r.status not in (None, 0)]
    fitted = len(results) - len(timeouts) - len(failed)
    for r in results:
        for message in r.shape:
            print(f"{r.file}: {message}")
    for r in failed:
        print(f"{r.file}: exit {r.status}: {r.error}")
    for r in timeouts:
        print(f"{r.file}: timed out after {args.timeout:g} s")
    print(f"slowest fits (of {len(results)}):")
    for r in sorted(results, key=lambda r: -r.seconds)[: args.slowest]:
        print(f"  {r.seconds:7.2f} s  {r.file}")
    times = sorted(r.seconds for r in results)
    print(
        f"time: {wall:.1f} s wall for {len(results)} files ({args.jobs} at a time); "
        f"per file median {times[len(times) // 2]:.3f} s, max {times[-1]:.2f} s"
    )
    for kind in KINDS:
        print(f"  {kind}: {total[kind]} warnings in {warned[kind]} files")
    summary = ", ".join(f"{total[k]} {k}" for k in KINDS)
    print(
        f"fit guards: {len(results)} files, {fitted} fitted, {len(failed)} failed, "
        f"{len(timeouts)} timed out; warnings: {summary}"
    )
    allowed = {kind: 0 for kind in SHAPE}
    for item in args.at_most:
        kind, _, count = item.partition("=")
        if kind not in allowed or not count.isdigit():
            ap.error(f"--at-most {item}: expected KIND=FILES with KIND in {', '.join(SHAPE)}")
        allowed[kind] = int(count)
    over = [kind for kind in SHAPE if warned[kind] > allowed[kind]]
    for kind in over:
        print(f"fit guards: {warned[kind]} files with {kind}, more than the {allowed[kind]} allowed")
    bad = over or failed or (timeouts and not args.allow_timeouts)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
