#!/usr/bin/env python3
"""Dask batch check: examples/dask_batch.py gives what `karkas batch` gives, and resumes.

The corpus (data/batch-foils: 24 foils, foil-*.dat, and 6 damaged files, damaged-*.dat) is run
through `curve fit --tolerance 1e-4` twice:

1. by the command line, `karkas batch curve fit --inputs CORPUS --out T1 --tolerance 1e-4`;
2. by `examples/dask_batch.py` with the same arguments and `--workers 2` (a LocalCluster of two
   processes), under this Python.

Both must exit 1 (some inputs failed) and agree input by input: the same inputs in the same
order, the same status and error line, the same summary apart from `seconds` and `messages`
(which hold times), and outputs of the same names with the same bytes. The damaged files must
be the ones that failed. OUT/results.parquet must hold the 30 records when pyarrow is
installed. Then `examples/dask_batch.py ... --resume` must run only the 6 damaged inputs again,
leaving the foils' outputs and records untouched, and a bad option must exit 2 with one line.
Prints the timings of both runs and their ratio; exit status 1 on any mismatch.

Usage: python3 tests/batch/check_dask.py [--karkas target/release/karkas]
       [--corpus data/batch-foils] [--keep DIR]
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "examples", "dask_batch.py")
JOB = ["curve", "fit", "--tolerance", "1e-4"]
GOOD, DAMAGED = "foil-", "damaged-"
TIMED = ("seconds", "messages")  # summary fields that hold times
RELATIVE = 1e-12
SUMMARY_LINE = re.compile(
    r"dask_batch: .*: (\d+) inputs, (\d+) ok(?: \((\d+) done before\))?, (\d+) failed; "
    r"(\d+) run in ([0-9.]+) s .* on (\d+) workers"
)


class Mismatch(Exception):
    """A difference between the two runs, or an unexpected outcome."""


def run(command, expected):
    """Runs `command`; its standard error and wall time. Raises Mismatch on another exit status."""
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, cwd=ROOT)
    seconds = time.perf_counter() - started
    if done.returncode != expected:
        raise Mismatch(
            f"{' '.join(command)}: exit status {done.returncode}, expected {expected}\n"
            f"{done.stderr.strip()}"
        )
    return done.stderr, seconds


def read_records(out):
    """The records of OUT/results.jsonl, in the file's order."""
    with open(os.path.join(out, "results.jsonl"), encoding="utf-8") as f:
        return [json.loads(line) for line in f if line.strip()]


def read_bytes(folder, name):
    """The bytes of the file `name` in `folder`."""
    with open(os.path.join(folder, name), "rb") as f:
        return f.read()


def same_value(a, b):
    """True when two JSON values are equal, floats to RELATIVE."""
    if isinstance(a, float) or isinstance(b, float):
        if not isinstance(a, (int, float)) or not isinstance(b, (int, float)):
            return False
        return math.isclose(a, b, rel_tol=RELATIVE, abs_tol=0.0)
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same_value(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b))
    return a == b


def figures(record):
    """The summary of `record` without the fields that hold times."""
    return {k: v for k, v in record["summary"].items() if k not in TIMED}


def compare_record(cli, dask, cli_out, dask_out):
    """The differences between the records of one input (empty when they agree)."""
    name = os.path.basename(cli["input"])
    problems = []
    for field in ("status", "error"):
        if cli[field] != dask[field]:
            problems.append(f"{name}: {field} {cli[field]!r} (CLI) != {dask[field]!r} (Dask)")
    a, b = figures(cli), figures(dask)
    for key in sorted(a.keys() | b.keys()):
        if key not in a or key not in b or not same_value(a[key], b[key]):
            problems.append(f"{name}: summary {key} {a.get(key)!r} (CLI) != {b.get(key)!r} (Dask)")
    names = [os.path.relpath(o, cli_out) for o in cli["outputs"]]
    if names != [os.path.relpath(o, dask_out) for o in dask["outputs"]]:
        problems.append(f"{name}: outputs {cli['outputs']} (CLI) != {dask['outputs']} (Dask)")
        return problems
    for output in names:
        if read_bytes(cli_out, output) != read_bytes(dask_out, output):
            problems.append(f"{name}: {output} differs between the CLI and Dask")
    return problems


def compare_runs(cli_records, dask_records, cli_out, dask_out):
    """The differences between the two runs' records and outputs."""
    cli_inputs = [r["input"] for r in cli_records]
    dask_inputs = [r["input"] for r in dask_records]
    if cli_inputs != dask_inputs:
        return [f"inputs differ: CLI {cli_inputs} != Dask {dask_inputs}"]
    problems = []
    for cli, dask in zip(cli_records, dask_records):
        problems += compare_record(cli, dask, cli_out, dask_out)
    return problems


def check_corpus(records):
    """The failed inputs must be exactly the damaged files."""
    for record in records:
        name = os.path.basename(record["input"])
        expected = "error" if name.startswith(DAMAGED) else "ok"
        if record["status"] != expected:
            raise Mismatch(f"{name}: status {record['status']}, expected {expected}")


def check_parquet(out, records):
    """OUT/results.parquet holds `records` (when pandas and pyarrow are installed)."""
    try:
        import pandas
        import pyarrow  # noqa: F401
    except ImportError:
        return "results.parquet not checked (no pyarrow)"
    path = os.path.join(out, "results.parquet")
    if not os.path.isfile(path):
        raise Mismatch(f"{path} missing")
    frame = pandas.read_parquet(path)
    if len(frame) != len(records) or list(frame["input"]) != [r["input"] for r in records]:
        raise Mismatch(f"{path}: {len(frame)} rows, expected the {len(records)} records")
    summaries = [json.loads(s) for s in frame["summary"]]
    if not same_value(summaries, [r["summary"] for r in records]):
        raise Mismatch(f"{path}: the summaries differ from results.jsonl")
    return f"results.parquet: {len(frame)} rows"


def summary_figures(stderr):
    """inputs, ok, done before, failed, run, seconds and workers of dask_batch's last line."""
    found = SUMMARY_LINE.search(stderr)
    if found is None:
        raise Mismatch(f"no summary line in:\n{stderr.strip()}")
    inputs, ok, before, failed, ran, seconds, workers = found.groups()
    counts = [int(inputs), int(ok), int(before or 0), int(failed), int(ran)]
    return (*counts, float(seconds), int(workers))


def mtimes(records):
    """The modification times of the records' outputs."""
    return {o: os.stat(o).st_mtime_ns for r in records for o in r["outputs"]}


def check_resume(dask_command, out, records):
    """A second run with --resume runs the damaged inputs only; the foils stay as they were."""
    before = mtimes(records)
    stderr, seconds = run(dask_command + ["--resume"], 1)
    inputs, ok, done, failed, ran, _, _ = summary_figures(stderr)
    damaged = sum(os.path.basename(r["input"]).startswith(DAMAGED) for r in records)
    if (inputs, done, ran, failed) != (len(records), len(records) - damaged, damaged, damaged):
        raise Mismatch(
            f"--resume: {inputs} inputs, {done} done before, {ran} run, {failed} failed; expected "
            f"{len(records)}, {len(records) - damaged}, {damaged}, {damaged}"
        )
    again = read_records(out)
    kept = [a == b for a, b in zip(records, again) if a["status"] == "ok"]
    if len(again) != len(records) or not all(kept):
        raise Mismatch("--resume: the records of the foils changed")
    if mtimes(again) != before:
        raise Mismatch("--resume: outputs of the foils were written again")
    return seconds


def check_usage(corpus, out):
    """A bad option is one error line and exit status 2."""
    command = [sys.executable, SCRIPT, "curve", "fit", "--inputs", corpus, "--out", out, "--bogus"]
    stderr, _ = run(command, 2)
    lines = stderr.strip().splitlines()
    if len(lines) != 1 or not lines[0].startswith("dask_batch: error: "):
        raise Mismatch(f"bad usage: expected one line 'dask_batch: error: ...', got:\n{stderr}")


def check(karkas, corpus, folder):
    """Runs both batches into `folder` and compares them; the report lines."""
    cli_out, dask_out = os.path.join(folder, "cli"), os.path.join(folder, "dask")
    cli_command = [karkas, "batch", *JOB[:2], "--inputs", corpus, "--out", cli_out, *JOB[2:]]
    dask_command = [sys.executable, SCRIPT, *JOB[:2], "--inputs", corpus, "--out", dask_out,
                    *JOB[2:], "--workers", "2"]
    _, cli_seconds = run(cli_command, 1)
    stderr, dask_seconds = run(dask_command, 1)
    cli_records, dask_records = read_records(cli_out), read_records(dask_out)
    problems = compare_runs(cli_records, dask_records, cli_out, dask_out)
    if problems:
        raise Mismatch("\n".join(problems))
    check_corpus(dask_records)
    parquet = check_parquet(dask_out, dask_records)
    _, _, _, _, ran, run_seconds, workers = summary_figures(stderr)
    resume_seconds = check_resume(dask_command, dask_out, dask_records)
    check_usage(corpus, os.path.join(folder, "usage"))
    ok = sum(r["status"] == "ok" for r in dask_records)
    outputs = sum(len(r["outputs"]) for r in dask_records)
    return [
        f"{len(dask_records)} inputs ({ok} ok, {len(dask_records) - ok} failed): same status, "
        f"error and figures, {outputs} outputs byte for byte (CLI vs Dask); {parquet}",
        f"CLI batch: {cli_seconds:.2f} s",
        f"Dask batch: {dask_seconds:.2f} s on {workers} workers ({ran} run in {run_seconds:.2f} s "
        f"once the cluster was up), {dask_seconds / cli_seconds:.1f}x the CLI's time",
        f"Dask --resume: damaged inputs only, foils untouched, {resume_seconds:.2f} s",
        "bad usage: exit 2, one line",
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--karkas", default=os.path.join(ROOT, "target", "release", "karkas"))
    parser.add_argument("--corpus", default=os.path.join(ROOT, "data", "batch-foils"))
    parser.add_argument("--keep", help="run in this folder and keep it (default: a temporary one)")
    args = parser.parse_args()
    karkas, corpus = os.path.abspath(args.karkas), os.path.abspath(args.corpus)
    try:
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            lines = check(karkas, corpus, os.path.abspath(args.keep))
        else:
            with tempfile.TemporaryDirectory(prefix="check-dask-") as folder:
                lines = check(karkas, corpus, folder)
    except Mismatch as e:
        print(f"check_dask: FAILED: {e}", file=sys.stderr)
        return 1
    for line in lines:
        print(f"check_dask: {line}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
