#!/usr/bin/env python3
"""`karkas batch curve fit` over every airfoil file of the real-file corpus.

    python3 tests/corpus/batch_corpus.py --karkas target/release/karkas --dir CORPUS/files

1. A glob of every .dat file below --dir is refused with exit 2 when two files share a stem
   (their outputs would share a name), naming both and suggesting --tree.
2. The same glob with `--tree DIR` (outputs named after each file's path below DIR) runs as one
   batch (`--tolerance 1e-4 --jobs 2`): one record per file, in order; every file fitted
   (status ok, its output written where --tree puts it) except those
   tests/corpus/expected_refusals.txt lists for `curve fit` or `*`, which must be error records
   holding the listed text; exit status 1 exactly when such a file is there.
3. `--resume` must run only the refused files again.

Prints the counts and times; exit status 1 on any mismatch.
"""

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


def expected_refusals():
    """{relative path: expected error text} for `curve fit` (or every command)."""
    out = {}
    for line in (HERE / "expected_refusals.txt").read_text(encoding="utf-8").splitlines():
        parts = line.split("\t")
        if line.startswith("#") or len(parts) < 3:
            continue
        if parts[1] in ("curve fit", "*"):
            out[parts[0]] = parts[2]
    return out


def batch(karkas, args):
    started = time.perf_counter()
    done = subprocess.run([karkas, "batch", "curve", "fit", *args], capture_output=True, text=True)
    return done, time.perf_counter() - started


def check(root, out, records, refusals, problems):
    """Checks the records of the tree batch; the number of expected refusals among them."""
    files = sorted(root.rglob("*.dat"))
    if sorted(r["input"] for r in records) != sorted(map(str, files)):
        problems.append("the records are not one per .dat file")
    expected = 0
    for r in records:
        rel = Path(r["input"]).relative_to(root)
        if str(rel) in refusals:
            expected += 1
            if r["status"] != "error" or refusals[str(rel)] not in (r["error"] or ""):
                problems.append(f"{rel}: expected refused with '{refusals[str(rel)]}', got {r}")
        elif r["status"] != "ok" or r["outputs"] != [str(out / rel.with_suffix(".csv"))]:
            problems.append(f"{rel}: {r['status']}: {r['error']} {r['outputs']}")
        elif not Path(r["outputs"][0]).is_file():
            problems.append(f"{rel}: no output")
    return expected


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--karkas", required=True)
    ap.add_argument("--dir", required=True, type=Path)
    args = ap.parse_args()
    root = args.dir.resolve()
    files = sorted(root.rglob("*.dat"))
    if not files:
        sys.exit(f"batch corpus: no .dat file under {root}")
    problems = []
    work = Path(tempfile.mkdtemp(prefix="karkas-batch-corpus-"))
    pattern = str(root / "**" / "*.dat")

    seen, twins = {}, None
    for f in files:
        if f.stem in seen and twins is None:
            twins = (seen[f.stem], f)
        seen.setdefault(f.stem, f)
    if twins:
        done, _ = batch(args.karkas, ["--inputs", pattern, "--out", str(work / "flat"),
                                      "--tolerance", "1e-4"])
        said = done.stderr
        if done.returncode != 2 or str(twins[0]) not in said or "--tree" not in said:
            problems.append(f"shared stem {twins[0].stem}: exit {done.returncode}, {said.strip()}")

    out = work / "tree"
    run_args = ["--inputs", pattern, "--out", str(out), "--tree", str(root), "--tolerance", "1e-4"]
    done, seconds = batch(args.karkas, run_args + ["--jobs", "2"])
    records = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()]
    expected = check(root, out, records, expected_refusals(), problems)
    if done.returncode != (1 if expected else 0):
        problems.append(f"exit {done.returncode} with {expected} refusals: {done.stderr[-500:]}")
    ok = sum(r["status"] == "ok" for r in records)
    print(f"batch corpus: {len(records)} airfoil files in {seconds:.1f} s "
          f"({len(records) / seconds:.0f} files/s): {ok} fitted, {expected} refused as expected; "
          f"shared stem: {twins[0].stem if twins else 'none'}")

    again, seconds = batch(args.karkas, run_args + ["--resume"])
    tail = again.stderr.strip().splitlines()[-1] if again.stderr.strip() else ""
    want = f"{len(records) - expected} done before), {expected} failed; {expected} run in"
    if want not in tail:
        problems.append(f"resume: expected '{want}' in: {tail}")
    print(f"batch corpus: resume ran the {expected} refused files again in {seconds:.1f} s")
    shutil.rmtree(work, ignore_errors=True)
    for p in problems[:20]:
        print(f"batch corpus: MISMATCH {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
