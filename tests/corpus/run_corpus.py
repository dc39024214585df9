#!/usr/bin/env python3
"""Run every file of a real-file corpus through the karkas CLI and hold it to one rule:
every file is read, except the ones listed, with their reason, in
tests/corpus/expected_refusals.txt: files truly damaged (placeholders instead of coordinates,
empty files, faces naming missing vertices) and files that are not what the command reads (a
point cloud has no surface to convert).

The corpus is what tests/corpus/fetch_corpus.py unpacks from pinned public packages (airfoil
coordinate files from PyPI packages such as aerosandbox's UIUC database; sample meshes from
PyPI wheels and sdists and from Debian packages such as assimp-testmodels, cura and
prusa-slicer). Files are classed by extension:

    airfoil (.dat)          karkas curve ll IN -o out.csv
                            karkas curve fit IN --tolerance 1e-3 -o out.csv   (unit chord)
                            karkas convert IN out.svg
    mesh (.stl .obj .ply)   karkas convert IN out.obj
                            karkas convert IN out.ply

Every run gets --max-memory (default 1G), a limit of 60 s of CPU time (--timeout; CPU time,
so that a machine busy with other work does not fail a run) and is killed as hung after four
times that on the wall clock; runs go in parallel (default 2 at a time). A run passes when
  - it exits 0 and its (file, command) is not listed (a fit that misses its tolerance warns
    and still exits 0, which passes), or
  - it exits 2 with a `karkas: error:` line and no panic, its (file, command) is listed, and
    the error line contains the listed substring;
and fails otherwise: an unlisted refusal, a listed file that is read (the list stays honest),
an exit 0 with no or an empty output file, any other exit status (a crash, a signal, a panic),
a run over its CPU or wall-clock limit, or a peak resident memory above the cap plus 64 MiB.
A listed entry whose file is not in the corpus, and an entry without a reason, fail too.

expected_refusals.txt holds one refusal a line, tab-separated:

    file<TAB>command<TAB>expected error substring<TAB>why the file is truly damaged

`file` is the path under --dir (source/path inside the package); `command` is one of
`curve ll`, `curve fit`, `convert svg`, `convert obj`, `convert ply`, or `*` for every command
run on that file. Lines starting with '#' and blank lines are ignored.

    python3 tests/corpus/run_corpus.py --karkas target/release/karkas --dir CORPUS/files
    python3 tests/corpus/run_corpus.py ... --update   # rewrite the list from today's refusals

--update writes the list from the current refusals, keeping the reason of every entry that is
still refused and marking new ones 'TODO', which fails until a person writes the reason.
The last line reads 'corpus: N passed, N failed' (runs).
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
KINDS = {".dat": "airfoil", ".stl": "mesh", ".obj": "mesh", ".ply": "mesh"}
COMMANDS = {
    "airfoil": ("curve ll", "curve fit", "convert svg"),
    "mesh": ("convert obj", "convert ply"),
}
ALL = "*"
RSS_OVERHEAD = 64 << 20
HEADER = """\
# Corpus files that karkas refuses: each truly damaged, or not what the command reads (a point
# set is no surface; UTF-16 is not UTF-8 text). tests/corpus/run_corpus.py fails when a file not
# listed here is refused, or a listed one is read.
# file<TAB>command (or * for every command)<TAB>expected error substring<TAB>why
"""


@dataclass(frozen=True)
class Run:
    file: str  # relative to the corpus folder
    kind: str
    command: str


@dataclass
class Outcome:
    run: Run
    status: int | None  # exit code; negative for a signal; None when killed as hung
    seconds: float  # wall-clock
    rss: int  # peak resident set size in bytes
    error: str  # the error line (or the last line of stderr)
    stderr: str
    cpu: float = 0.0  # user + system seconds
    wrote: bool = True  # the output file exists and is not empty


@dataclass
class Entry:
    file: str
    command: str
    expected: str
    why: str
    line: int


def parse_size(text: str) -> int:
    m = re.fullmatch(r"(\d+)([KMG]?)", text.strip().upper())
    if not m:
        raise argparse.ArgumentTypeError(f"bad size {text!r}, expected like 512M or 1G")
    return int(m.group(1)) << {"": 0, "K": 10, "M": 20, "G": 30}[m.group(2)]


def corpus_files(root: Path) -> list[tuple[str, str]]:
    """(relative path, kind) of every corpus file, sorted; hidden files are skipped."""
    found = []
    for path in root.rglob("*"):
        if path.is_file() and not path.name.startswith("."):
            kind = KINDS.get(path.suffix.lower())
            if kind:
                found.append((path.relative_to(root).as_posix(), kind))
    return sorted(found)


def argv_for(karkas: str, run: Run, src: Path, out_dir: Path, args) -> list[str]:
    cap = ["--max-memory", args.max_memory]
    if run.command == "curve ll":
        return [karkas, "curve", "ll", str(src), "-o", str(out_dir / "out.csv"), *cap]
    if run.command == "curve fit":
        return [karkas, "curve", "fit", str(src), "--tolerance", args.tolerance,
                "-o", str(out_dir / "out.csv"), *cap]
    ext = run.command.split()[1]
    return [karkas, "convert", str(src), str(out_dir / f"out.{ext}"), *cap]


def error_line(stderr: str) -> str:
    lines = [ln for ln in stderr.splitlines() if ln.strip()]
    for ln in lines:
        if ln.startswith("karkas: error:"):
            return ln
    return lines[-1] if lines else ""


def execute(run: Run, root: Path, work: Path, args) -> Outcome:
    """One karkas run, killed after the wall-clock limit; its CPU time and peak memory come
    from wait4's resource usage."""
    with tempfile.TemporaryDirectory(dir=work) as tmp:
        out_dir = Path(tmp)
        err_path = out_dir / "stderr"
        argv = argv_for(args.karkas, run, root / run.file, out_dir, args)
        start = time.monotonic()
        with err_path.open("wb") as err:
            proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                    stderr=err)
        timed_out = threading.Event()

        def kill() -> None:
            timed_out.set()
            proc.kill()

        timer = threading.Timer(args.wall_timeout, kill)
        timer.start()
        try:
            _, wait_status, usage = os.wait4(proc.pid, 0)
        finally:
            timer.cancel()
        proc.returncode = os.waitstatus_to_exitcode(wait_status)
        seconds = time.monotonic() - start
        stderr = err_path.read_bytes().decode("utf-8", "replace")
        output = Path(argv[argv.index("-o") + 1] if "-o" in argv else argv[3])
        wrote = output.exists() and output.stat().st_size > 0
    status = None if timed_out.is_set() and seconds >= args.wall_timeout else proc.returncode
    return Outcome(run, status, seconds, usage.ru_maxrss * 1024, error_line(stderr), stderr,
                   usage.ru_utime + usage.ru_stime, wrote)


def load_list(path: Path) -> tuple[list[Entry], list[str]]:
    entries, problems = [], []
    if not path.exists():
        return entries, problems
    for number, raw in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not raw.strip() or raw.startswith("#"):
            continue
        fields = raw.split("\t")
        if len(fields) != 4:
            problems.append(f"{path.name}:{number}: expected 4 tab-separated fields, found "
                            f"{len(fields)}")
            continue
        entries.append(Entry(*(f.strip() for f in fields), line=number))
    return entries, problems


def judge(outcome: Outcome, entry: Entry | None, cap: int, cpu_limit: float) -> str | None:
    """Why this run fails, or None when it passes."""
    status = outcome.status
    if status is None:
        return f"killed after {outcome.seconds:.0f} s (wall clock): it hangs"
    if outcome.cpu > cpu_limit:
        return f"took {outcome.cpu:.1f} s of CPU, over the {cpu_limit:g} s limit"
    if "panicked" in outcome.stderr:
        return f"panicked (exit {status}): {outcome.error}"
    if outcome.rss > cap + RSS_OVERHEAD:
        return (f"peak memory {outcome.rss >> 20} MiB over the cap "
                f"{cap >> 20} MiB + {RSS_OVERHEAD >> 20} MiB")
    if status == 0:
        if entry is not None:
            return f"listed as refused (line {entry.line}) but read"
        if not outcome.wrote:
            return "exit 0 but no output written"
        return None
    if status != 2:
        return f"exit status {status} (a crash?): {outcome.error}"
    if not outcome.error.startswith("karkas: error:"):
        return f"exit 2 without a 'karkas: error:' line: {outcome.error}"
    if entry is None:
        return f"refused, not listed: {outcome.error}"
    if entry.expected not in outcome.error:
        return f"refused with another error than listed (line {entry.line}): {outcome.error}"
    if not entry.why or entry.why.upper().startswith("TODO"):
        return f"listed without a reason (line {entry.line})"
    return None


def draft_expected(outcome: Outcome) -> str:
    """The error line without 'karkas: error:' and the file's path: the stable part."""
    text = outcome.error.removeprefix("karkas: error:").strip()
    name = outcome.run.file
    i = text.find(name)
    if i >= 0:
        text = text[i + len(name):].lstrip(":").strip()
    return text[:100].replace("\t", " ")


def write_update(path: Path, outcomes: list[Outcome], old: list[Entry]) -> int:
    """Rewrite the list from today's refusals; keep the reasons of entries still refused."""
    reasons = {(e.file, e.command): e.why for e in old}
    refused: dict[str, list[Outcome]] = {}
    runs_of: dict[str, int] = {}
    for o in outcomes:
        runs_of[o.run.file] = runs_of.get(o.run.file, 0) + 1
        if o.status == 2 and "panicked" not in o.stderr:
            refused.setdefault(o.run.file, []).append(o)
    lines = []
    for file in sorted(refused):
        group = refused[file]
        drafts = {draft_expected(o) for o in group}
        if len(group) == runs_of[file] and len(drafts) == 1:
            why = reasons.get((file, ALL)) or next(
                (reasons[(file, o.run.command)] for o in group if (file, o.run.command) in reasons),
                "TODO")
            lines.append(f"{file}\t{ALL}\t{drafts.pop()}\t{why}")
            continue
        for o in sorted(group, key=lambda o: o.run.command):
            why = reasons.get((file, o.run.command)) or reasons.get((file, ALL)) or "TODO"
            lines.append(f"{file}\t{o.run.command}\t{draft_expected(o)}\t{why}")
    path.write_text(HEADER + "".join(line + "\n" for line in lines), encoding="utf-8")
    return len(lines)


def self_test() -> int:
    """The pass/fail rules on made-up outcomes: each rule must be able to fail."""
    run = Run("src/a.dat", "airfoil", "curve ll")
    err = "karkas: error: /c/src/a.dat:2: '......' is not a number (column 2)"
    listed = Entry(run.file, ALL, "'......' is not a number", "placeholders", 4)
    cap = 1 << 30

    def out(status, error="", stderr=None, rss=10 << 20, cpu=0.1, wrote=True):
        return Outcome(run, status, 0.1, rss, error, error if stderr is None else stderr, cpu,
                       wrote)

    cases = [
        ("read, not listed", out(0), None, True),
        ("read, listed", out(0), listed, False),
        ("exit 0, nothing written", out(0, wrote=False), None, False),
        ("refused, listed, message matches", out(2, err), listed, True),
        ("refused, not listed", out(2, err), None, False),
        ("refused, listed, another message", out(2, err.replace("......", "x")), listed, False),
        ("refused, listed without a reason", out(2, err),
         Entry(run.file, ALL, "is not a number", "TODO", 4), False),
        ("panic with exit 2", out(2, err, "thread 'main' panicked at src/x.rs"), listed, False),
        ("crash (signal)", out(-11, ""), None, False),
        ("exit 1", out(1, "Error: x"), None, False),
        ("exit 2 without an error line", out(2, "error: unexpected argument"), listed, False),
        ("killed as hung", out(None), None, False),
        ("over the CPU limit", out(0, cpu=60.5), None, False),
        ("peak memory over the cap", out(0, rss=cap + RSS_OVERHEAD + 1), None, False),
        ("peak memory at the cap + overhead", out(0, rss=cap + RSS_OVERHEAD), None, True),
    ]
    failed = 0
    for name, outcome, entry, passes in cases:
        verdict = judge(outcome, entry, cap, 60.0)
        if (verdict is None) != passes:
            failed += 1
            print(f"self-test: {name}: expected {'pass' if passes else 'fail'}, got {verdict}")
    draft = draft_expected(Outcome(run, 2, 0.1, 0, err, err))
    if draft != "2: '......' is not a number (column 2)":
        failed += 1
        print(f"self-test: draft_expected gave {draft!r}")
    print(f"self-test: {len(cases) + 1 - failed} passed, {failed} failed")
    return 1 if failed else 0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--karkas", help="the karkas binary")
    parser.add_argument("--dir", type=Path, help="the corpus folder")
    parser.add_argument("--refusals", type=Path, default=HERE / "expected_refusals.txt")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=60.0,
                        help="CPU seconds a run may take (CPU, so a busy machine does not fail it)")
    parser.add_argument("--wall-timeout", type=float,
                        help="wall-clock seconds before a run is killed as hung "
                             "(default 4x --timeout)")
    parser.add_argument("--max-memory", default="1G", help="passed to every run")
    parser.add_argument("--tolerance", default="1e-3", help="curve fit --tolerance")
    parser.add_argument("--results", type=Path, help="write every run as TSV here")
    parser.add_argument("--show", type=int, default=100, help="failure lines printed at most")
    parser.add_argument("--self-test", action="store_true",
                        help="check the pass/fail rules on made-up runs and stop")
    parser.add_argument("--update", action="store_true",
                        help="rewrite --refusals from the current refusals (reasons kept)")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    if args.karkas is None or args.dir is None:
        parser.error("--karkas and --dir are required")
    cap = parse_size(args.max_memory)
    if args.wall_timeout is None:
        args.wall_timeout = 4 * args.timeout
    args.karkas = str(Path(args.karkas).resolve())
    root = args.dir.resolve()

    files = corpus_files(root)
    if not files:
        print(f"corpus: no .dat, .stl, .obj or .ply file under {root}", file=sys.stderr)
        return 1
    runs = [Run(f, kind, c) for f, kind in files for c in COMMANDS[kind]]
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="karkas-corpus-") as work, \
            ThreadPoolExecutor(max_workers=args.jobs) as pool:
        outcomes = list(pool.map(lambda r: execute(r, root, Path(work), args), runs))
    elapsed = time.monotonic() - started

    if args.results:
        with args.results.open("w", encoding="utf-8") as out:
            out.write("file\tkind\tcommand\tstatus\tseconds\tcpu_seconds\trss_mib\terror\n")
            for o in outcomes:
                out.write(f"{o.run.file}\t{o.run.kind}\t{o.run.command}\t{o.status}\t"
                          f"{o.seconds:.3f}\t{o.cpu:.3f}\t{o.rss / (1 << 20):.1f}\t"
                          f"{o.error.replace(chr(9), ' ')}\n")

    entries, problems = load_list(args.refusals)
    if args.update:
        n = write_update(args.refusals, outcomes, entries)
        print(f"corpus: wrote {n} entries to {args.refusals}; write the reason of each TODO")
        entries, problems = load_list(args.refusals)

    by_key = {}
    for e in entries:
        if (e.file, e.command) in by_key:
            problems.append(f"{args.refusals.name}:{e.line}: {e.file} [{e.command}] listed twice")
        by_key[(e.file, e.command)] = e
    kind_of = dict(files)
    for e in entries:
        if e.file not in kind_of:
            problems.append(f"{args.refusals.name}:{e.line}: {e.file} is not in the corpus")
        elif e.command != ALL and e.command not in COMMANDS[kind_of[e.file]]:
            problems.append(f"{args.refusals.name}:{e.line}: {e.file}: no command "
                            f"'{e.command}' runs on a {kind_of[e.file]} file")

    # One failure line per file and reason, naming the commands it holds for.
    grouped: dict[tuple[str, str], list[str]] = {}
    passed = 0
    for o in outcomes:
        entry = by_key.get((o.run.file, o.run.command)) or by_key.get((o.run.file, ALL))
        why = judge(o, entry, cap, args.timeout)
        if why is None:
            passed += 1
        else:
            grouped.setdefault((o.run.file, why), []).append(o.run.command)
    failures = list(problems) + [f"{file} [{', '.join(commands)}]: {why}"
                                 for (file, why), commands in grouped.items()]

    # Counts: files per source and kind, read (every command exit 0), refused (listed).
    refused_files = {o.run.file for o in outcomes if o.status == 2}
    table: dict[tuple[str, str], list[int]] = {}
    for f, kind in files:
        row = table.setdefault((f.split("/", 1)[0], kind), [0, 0])
        row[1 if f in refused_files else 0] += 1
    print(f"{'source':<20} {'kind':<8} {'files':>6} {'read':>6} {'refused':>8}")
    for (source, kind), (read, refused) in sorted(table.items()):
        print(f"{source:<20} {kind:<8} {read + refused:>6} {read:>6} {refused:>8}")
    for kind in COMMANDS:
        rows = [v for (s, k), v in table.items() if k == kind]
        read, refused = sum(r for r, _ in rows), sum(x for _, x in rows)
        print(f"{'all':<20} {kind:<8} {read + refused:>6} {read:>6} {refused:>8}")
    slowest = max(outcomes, key=lambda o: o.cpu)
    largest = max(outcomes, key=lambda o: o.rss)
    print(f"corpus: {len(runs)} runs in {elapsed:.1f} s on {args.jobs} workers; slowest "
          f"{slowest.cpu:.2f} s CPU ({slowest.run.file} [{slowest.run.command}]); largest peak "
          f"memory {largest.rss >> 20} MiB ({largest.run.file} [{largest.run.command}])")
    for why in failures[:args.show]:
        print(f"FAIL {why}")
    if len(failures) > args.show:
        print(f"FAIL ... and {len(failures) - args.show} more (all runs: --results FILE)")
    print(f"corpus: {passed} passed, {len(runs) - passed + len(problems)} failed")
    return 0 if not failures else 1


if __name__ == "__main__":
    sys.exit(main())
