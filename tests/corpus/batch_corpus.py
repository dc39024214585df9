#!/usr/bin/env python3
"""`karkas batch curve fit` over every airfoil file of the real-file corpus.

    python3 tests/corpus/batch_corpus.py --karkas target/release/karkas --dir CORPUS/files

1. A glob of every .dat file under --dir is refused with exit 2 when two files share a stem
   (their outputs would share a name), naming both.
2. The files go into one .txt list, the later files of a shared stem into a second, and each list
   runs as a batch (`--tolerance 1e-4 --jobs 2`): every file must be fitted (status ok, its
   output written) except those tests/corpus/expected_refusals.txt lists for `curve fit` or
   `*`, which must be error records whose message holds the listed text; the exit status must
   be 1 exactly when such a file is in the batch.
3. `--resume` on the first list must run only the refused files again.

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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--karkas", required=True)
    ap.add_argument("--dir", required=True, type=Path)
    args = ap.parse_args()
    root = args.dir.resolve()
    files = sorted(root.rglob("*.dat"))
    if not files:
        sys.exit(f"batch corpus: no .dat file under {root}")
    refusals = expected_refusals()
    problems = []
    work = Path(tempfile.mkdtemp(prefix="karkas-batch-corpus-"))

    first, later, seen = [], [], {}
    for f in files:
        (later if f.stem in seen else first).append(f)
        seen.setdefault(f.stem, f)
    if later:
        done, _ = batch(args.karkas, ["--inputs", str(root / "**" / "*.dat"), "--out",
                                      str(work / "glob"), "--tolerance", "1e-4"])
        twin = seen[later[0].stem]
        if done.returncode != 2 or str(twin) not in done.stderr or str(later[0]) not in done.stderr:
            problems.append(f"shared stem {later[0].stem}: exit {done.returncode}, {done.stderr.strip()}")

    counts = {"files": 0, "ok": 0, "refused": 0}
    for k, group in enumerate(g for g in (first, later) if g):
        listing = work / f"list-{k}.txt"
        listing.write_text("".join(f"{f}\n" for f in group))
        out = work / f"out-{k}"
        done, seconds = batch(args.karkas, ["--inputs", str(listing), "--out", str(out),
                                            "--tolerance", "1e-4", "--jobs", "2"])
        records = [json.loads(line) for line in (out / "results.jsonl").read_text().splitlines()]
        if [r["input"] for r in records] != [str(f) for f in group]:
            problems.append(f"batch {k}: the records are not one per input in order")
        expected = 0
        for r in records:
            rel = str(Path(r["input"]).relative_to(root))
            if rel in refusals:
                expected += 1
                if r["status"] != "error" or refusals[rel] not in (r["error"] or ""):
                    problems.append(f"{rel}: expected refused with '{refusals[rel]}', got {r}")
            elif r["status"] != "ok" or not all(Path(o).is_file() for o in r["outputs"]):
                problems.append(f"{rel}: {r['status']}: {r['error']}")
        if done.returncode != (1 if expected else 0):
            problems.append(f"batch {k}: exit {done.returncode} with {expected} refusals")
        counts["files"] += len(records)
        counts["ok"] += sum(r["status"] == "ok" for r in records)
        counts["refused"] += expected
        print(f"batch corpus: list {k}: {len(records)} files in {seconds:.1f} s "
              f"({len(records) / seconds:.0f} files/s), exit {done.returncode}")
        if k == 0:
            again, seconds = batch(args.karkas, ["--inputs", str(listing), "--out", str(out),
                                                 "--tolerance", "1e-4", "--resume"])
            tail = again.stderr.strip().splitlines()[-1] if again.stderr.strip() else ""
            want = f"{len(records) - expected} done before), {expected} failed; {expected} run in"
            if want not in tail:
                problems.append(f"resume: expected '{want}' in: {tail}")
            print(f"batch corpus: resume ran {expected} refused files again in {seconds:.1f} s")
    print(f"batch corpus: {counts['files']} airfoil files, {counts['ok']} fitted, "
          f"{counts['refused']} refused as expected; {len(later)} in a second batch (shared stems)")
    shutil.rmtree(work, ignore_errors=True)
    for p in problems[:20]:
        print(f"batch corpus: MISMATCH {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
