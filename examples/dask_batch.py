"""Running a karkas batch on a Dask cluster: `karkas batch` with dask.distributed.

Install karkas and Dask first (pip install ./crates/karkas-py "dask[distributed]"; pandas and
pyarrow for the Parquet table), then, from the repository root:

    python3 examples/dask_batch.py curve fit --inputs data/batch-foils --out fits --tolerance 1e-4
    python3 examples/dask_batch.py curve fit --inputs data/batch-foils --out fits --resume \\
        --tolerance 1e-4
    python3 examples/dask_batch.py curve ll --inputs 'scans/*.csv' --out svg --format svg \\
        --order 3 --workers 8
    python3 examples/dask_batch.py curve fit --inputs /shared/foils --out /shared/fits \\
        --tolerance 1e-4 --scheduler tcp://host:8786

The arguments are those of the command line's `karkas batch` (see `karkas batch --help`): JOB,
one of the commands a batch runs (curve ll, curve fit, curve spline, curve dps, curve analyze,
surface ll, surface bicubic, section, vary, convert); `--inputs`, a folder (its files), a glob
pattern (quoted) or a .txt list of paths, and may be repeated; `--out DIR`; `--format EXT`;
`--resume`; `--tree DIR` (outputs named after the input's path below DIR); `--max-memory SIZE`
(each input's request, as karkas.max_memory on the workers). Every other argument is an option of the job, passed on in its order, and the
script's own options may stand anywhere among them, as on the command line. Two more say where
the work runs:

- by default a `LocalCluster` on this machine: `--workers N` processes (default 2; `--jobs N`
  is the same), one thread each, so that N inputs run at once;
- `--scheduler ADDRESS` (like tcp://host:8786): the workers of an existing cluster.

Each input writes OUT/<input stem>.<EXT>, as `karkas batch` would, and gets a record (input,
outputs, status, error, summary, seconds). The records are appended to OUT/results.jsonl as the
inputs finish, so that a run stopped half-way keeps what it did, and the file is rewritten at
the end with one line per input in the order of the inputs; OUT/results.parquet holds the same
records (the summary as a JSON string) when pandas and pyarrow are installed. A bad file is a
failed record, its error line printed, and the run goes on. `--resume` skips the inputs
recorded ok whose outputs exist and runs the others (and starts no cluster when none is
left). The last line sums up, like the command line's, with the time taken to start or reach
the cluster apart:

    dask_batch: curve fit: 30 inputs, 24 ok, 6 failed; 30 run in 0.34 s (88.8 inputs/s) on 2
    workers (ready in 2.10 s); records in fits/results.jsonl

Exit status 0 when every input is ok, 1 when some failed, 2 on bad usage: one line
`dask_batch: error: ...`, before any cluster starts (the job and its options are tried first on
an empty stand-in of the first input, on this machine).

A cluster of several machines runs the same script. Start a scheduler on one machine and
workers on the others, each with karkas installed (the same version as here):

    host$    dask scheduler                          # listens on tcp://host:8786
    other$   dask worker tcp://host:8786 --nworkers 4 --nthreads 1

or start both over SSH with `dask ssh host other1 other2 ...` (dask-ssh), or on Kubernetes
with the Dask Kubernetes operator (a DaskCluster of an image that has karkas), then pass
`--scheduler tcp://host:8786`. The inputs and the output folder must be on a file system that
every worker sees at the same path (a shared or network file system: NFS, SMB, a cluster file
system), since each worker reads its inputs and writes its outputs itself; only the records
travel back to this process, which writes results.jsonl. Give absolute paths: a relative one
is resolved in each worker's working folder. A worker that does not see an input records it
as failed, saying so.

The inputs are independent of each other, so the work is embarrassingly parallel: it grows
with the workers until the file system's I/O, or the scheduler's overhead per task (a few
milliseconds), is the limit. Inputs that take milliseconds each, like the foils of
data/batch-foils, run faster in one `karkas batch` process; the cluster pays off when each
input takes long, or when there are more inputs than one machine gets through in time.
"""

import json
import os
import sys
import tempfile
import time
from contextlib import contextmanager
from types import SimpleNamespace

from dask.distributed import Client, LocalCluster, as_completed

import karkas

PROGRAM = "dask_batch"
RESULTS_FILE = "results.jsonl"
PARQUET_FILE = "results.parquet"
FIELDS = ["input", "outputs", "status", "error", "summary", "seconds"]
DEFAULT_WORKERS = 2
WORKER_WAIT_SECONDS = 60
# The script's options that take a value; every other argument belongs to the job.
VALUED = ("--inputs", "--out", "--tree", "--format", "--jobs", "--workers", "--scheduler",
          "--max-memory")


class Usage(Exception):
    """Bad usage: reported as one line, exit status 2."""


# The arguments.


def split_arguments(argv):
    """The script's options and the job's line (its words and options, in their order), as
    `karkas batch` splits them: the script's options may stand anywhere, as `--name VALUE` or
    `--name=VALUE`."""
    args = SimpleNamespace(inputs=[], out=None, format=None, workers=None, scheduler=None,
                           resume=False, max_memory=None, tree=None, line=[])
    words = list(argv)[::-1]
    while words:
        word = words.pop()
        name, equals, inline = word.partition("=")
        if word in ("-h", "--help"):
            print(__doc__)
            sys.exit(0)
        if word == "--resume":
            args.resume = True
            continue
        if name not in VALUED:
            args.line.append(word)
            continue
        value = inline if equals else (words.pop() if words else None)
        if value is None:
            raise Usage(f"{name}: a value is needed")
        take_option(args, name, value)
        # The files of a pattern the shell expanded: the job's options all start with '-'.
        while name == "--inputs" and words and not words[-1].startswith("-"):
            args.inputs.append(words.pop())
    return args


def take_option(args, name, value):
    """Stores the script's option `name` of `value` in `args`."""
    if name == "--inputs":
        args.inputs.append(value)
    elif name == "--out":
        args.out = value
    elif name == "--tree":
        args.tree = value
    elif name == "--format":
        args.format = value
    elif name == "--scheduler":
        args.scheduler = value
    elif name in ("--workers", "--jobs"):
        args.workers = count(name, value)
    else:
        args.max_memory = size(name, value)


UNITS = {"": 1, "K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}


def size(name, text):
    """A size like 512M or 4G in bytes, as the command line's --max-memory reads it."""
    number = text.strip().upper().removesuffix("IB").removesuffix("B")
    unit = number[-1:] if number[-1:] in UNITS else ""
    try:
        value = float(number[: len(number) - len(unit)]) * UNITS[unit]
    except ValueError:
        value = 0
    if value < 1:
        raise Usage(f"{name} {text}: not a size (like 512M or 4G)")
    return int(value)


def count(name, value):
    """The positive whole number `value` of option `name`."""
    try:
        number = int(value)
    except ValueError:
        number = 0
    if number < 1:
        raise Usage(f"{name} {value}: not a count (1 or more)")
    return number


def job_and_options(line):
    """The job's words (`curve fit`, `section`) and its options, from the job's line."""
    if not line or line[0].startswith("-"):
        raise Usage("name the command to run first (curve fit, curve ll, section, ...)")
    two = line[0] in ("curve", "surface") and len(line) > 1 and not line[1].startswith("-")
    size = 2 if two else 1
    return line[:size], line[size:]


def check_arguments(args):
    """Refuses what the script cannot run."""
    if args.out is None:
        raise Usage("--out DIR is needed (the outputs and results.jsonl go there)")
    if args.scheduler is not None and args.workers is not None:
        raise Usage("--workers: a --scheduler's workers are its own (`dask worker` starts them)")


# The inputs.


def single_input(path):
    """The `inputs` that names the file `path` alone: the path itself, or for a .txt file
    (which `inputs` would read as a list of paths) a glob pattern matching just that file."""
    if not path.lower().endswith(".txt"):
        return path
    escaped = "".join(f"[{c}]" if c in "*?[" else c for c in path)
    return f"{escaped[:-1]}[{escaped[-1]}]"


def check_stems(inputs, tree=None):
    """Refuses two inputs whose outputs would share a name, and with `tree` an input outside
    that folder, as `karkas batch` does: outputs are named after the input's stem, or its path
    below `tree`."""
    first = {}
    for path in inputs:
        if tree is None:
            stem = os.path.splitext(os.path.basename(path))[0]
            hint = "name the outputs after their folders with --tree DIR, or run them in two batches"
        else:
            below = os.path.relpath(os.path.abspath(path), os.path.abspath(tree))
            if below == os.pardir or below.startswith(os.pardir + os.sep):
                raise Usage(f"--tree {tree}: the input {path} is not in that folder")
            stem = os.path.splitext(below)[0]
            hint = "rename one or run them in two batches"
        if stem in first:
            raise Usage(
                f"{first[stem]} and {path} would write outputs of the same name ({stem}); {hint}"
            )
        first[stem] = path


def check_job(job, options, fmt, first):
    """Tries the job and its options on an empty stand-in of the input `first`, in a temporary
    folder: a command or option the job refuses is bad usage, found before any cluster starts."""
    with tempfile.TemporaryDirectory(prefix="dask-batch-") as folder:
        stand_in = os.path.join(folder, os.path.basename(first))
        open(stand_in, "w").close()
        try:
            karkas.batch(job, [single_input(stand_in)], os.path.join(folder, "out"),
                         options=options, format=fmt, jobs=1, results_file=False, as_frame=False)
        except karkas.OptionError as e:
            raise Usage(str(e)) from None


# The records.


def failed_record(path, error):
    """The record of an input that could not run at all."""
    return {"input": path, "outputs": [], "status": "error", "error": error,
            "summary": {"messages": []}, "seconds": 0.0}


def run_one(path, job, options, out, fmt, max_memory=None, tree=None):
    """Runs the job on the input `path` into the folder `out` and returns its record (on a
    worker: the function is shipped to it, and karkas is the worker's own); `max_memory`
    caps the input's request, as --max-memory does on the command line, and `tree` names the
    outputs after the input's path below it, as --tree does."""
    if max_memory is not None:
        karkas.max_memory = max_memory
    if not os.path.isfile(path):
        why = "no such file on this worker (is the file system shared?)"
        return failed_record(path, f"{path}: {why}")
    try:
        record = karkas.batch(job, [single_input(path)], out, options=options, format=fmt,
                              tree=tree, jobs=1, results_file=False, as_frame=False)[0]
    except (karkas.KarkasError, OSError) as e:
        return failed_record(path, str(e))
    record["input"] = path
    return record


def is_record(value):
    """True when `value` (a parsed line of results.jsonl) has the form of a record."""
    return (
        isinstance(value, dict)
        and isinstance(value.get("input"), str)
        and isinstance(value.get("outputs"), list)
        and value.get("status") in ("ok", "error")
        and all(field in value for field in FIELDS)
    )


def read_records(path):
    """The records of the results file `path` by input, the last one of each input winning,
    in the order of their first appearance; lines that are not records (the last line of a
    run stopped while writing it) are skipped; none when the file does not exist."""
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.readlines()
    except FileNotFoundError:
        return {}
    records = {}
    for line in lines:
        try:
            record = json.loads(line)
        except ValueError:
            continue
        if is_record(record):
            records[record["input"]] = record
    return records


def is_done(record):
    """True when an earlier record makes a new run needless: ok, and its outputs all there."""
    return record["status"] == "ok" and all(os.path.isfile(o) for o in record["outputs"])


def record_line(record):
    """One line of results.jsonl."""
    return json.dumps(record, separators=(",", ":")) + "\n"


def write_atomic(path, write):
    """Writes the file `path` by `write(temporary_path)` beside it, then renames it over `path`."""
    folder, name = os.path.split(path)
    handle, temporary = tempfile.mkstemp(dir=folder or ".", prefix=f".{name}.", suffix=".tmp")
    os.close(handle)
    try:
        write(temporary)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def write_results(path, records):
    """Rewrites the results file `path` with `records`, one line each."""

    def write(temporary):
        with open(temporary, "w", encoding="utf-8") as f:
            f.writelines(record_line(r) for r in records)
            f.flush()
            os.fsync(f.fileno())

    write_atomic(path, write)


def write_parquet(path, records):
    """Writes `records` as a Parquet table (the summary as a JSON string); False when pandas
    or pyarrow is missing."""
    try:
        import pandas
        import pyarrow  # noqa: F401
    except ImportError:
        return False
    frame = pandas.DataFrame(records, columns=FIELDS)
    frame["summary"] = [json.dumps(r["summary"], separators=(",", ":")) for r in records]
    write_atomic(path, lambda temporary: frame.to_parquet(temporary, index=False))
    return True


# The cluster.


@contextmanager
def connected(args):
    """The client of the cluster the work runs on: a LocalCluster of `--workers` processes made
    here (and closed after), or the cluster of `--scheduler` once a worker has joined it."""
    if args.scheduler is None:
        workers = args.workers or DEFAULT_WORKERS
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            yield client
        return
    try:
        client = Client(args.scheduler)
    except OSError as e:
        raise Usage(f"--scheduler {args.scheduler}: cannot connect ({e})") from None
    with client:
        try:
            client.wait_for_workers(1, timeout=WORKER_WAIT_SECONDS)
        except TimeoutError:
            why = f"no worker joined in {WORKER_WAIT_SECONDS} s"
            raise Usage(f"--scheduler {args.scheduler}: {why}") from None
        yield client


def run_on_cluster(client, todo, job, options, out, fmt, max_memory, tree, journal):
    """Runs the inputs `todo` as one task each and returns their records by input, appending
    each to `journal` as it arrives (and printing the error line of a failed one)."""
    futures = client.map(run_one, todo, job=job, options=options, out=out, fmt=fmt,
                         max_memory=max_memory, tree=tree, pure=False)
    paths = {future.key: path for future, path in zip(futures, todo)}
    fresh = {}
    for future in as_completed(futures):
        path = paths[future.key]
        try:
            record = future.result()
        except Exception as e:  # a worker lost on this input: its record says so
            record = failed_record(path, f"{path}: the task failed ({type(e).__name__}: {e})")
        if record["status"] != "ok":
            print(f"{PROGRAM}: error: {record['error']}", file=sys.stderr)
        journal.write(record_line(record))
        journal.flush()
        fresh[path] = record
    return fresh


def run(args):
    """Runs the batch of `args`; the exit status."""
    check_arguments(args)
    job, options = job_and_options(args.line)
    try:
        inputs = karkas.batch_inputs(args.inputs)
    except karkas.OptionError as e:
        raise Usage(str(e)) from None
    check_stems(inputs, args.tree)
    check_job(job, options, args.format, inputs[0])
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        raise Usage(f"--out: cannot create the folder {args.out}: {e}") from None
    results = os.path.join(args.out, RESULTS_FILE)
    earlier = read_records(results) if args.resume else {}
    done = {path: earlier[path] for path in inputs if path in earlier and is_done(earlier[path])}
    todo = [path for path in inputs if path not in done]

    fresh, workers, seconds, ready = {}, 0, 0.0, 0.0
    if todo:
        mode = "a" if args.resume else "w"
        connecting = time.perf_counter()
        with connected(args) as client, open(results, mode, encoding="utf-8") as journal:
            workers = len(client.nthreads())
            started = time.perf_counter()
            ready = started - connecting
            fresh = run_on_cluster(client, todo, job, options, args.out, args.format,
                                   args.max_memory, args.tree, journal)
            seconds = time.perf_counter() - started

    records = [fresh.get(path) or done[path] for path in inputs]
    mine = set(inputs)
    others = [r for path, r in earlier.items() if path not in mine]
    write_results(results, records + others)
    write_parquet(os.path.join(args.out, PARQUET_FILE), records + others)

    failed = sum(r["status"] != "ok" for r in records)
    before = f" ({len(done)} done before)" if done else ""
    rate = len(todo) / max(seconds, 1e-9)
    print(
        f"{PROGRAM}: {' '.join(job)}: {len(inputs)} inputs, {len(inputs) - failed} ok{before}, "
        f"{failed} failed; {len(todo)} run in {seconds:.2f} s ({rate:.1f} inputs/s) on {workers} "
        f"workers (ready in {ready:.2f} s); records in {results}",
        file=sys.stderr,
    )
    return 1 if failed else 0


def main(argv=None):
    try:
        return run(split_arguments(sys.argv[1:] if argv is None else argv))
    except Usage as e:
        print(f"{PROGRAM}: error: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"{PROGRAM}: error: {e}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
