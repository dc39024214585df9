#!/usr/bin/env python3
"""Reading 3-D points from CSV: karkas.read_curve beside numpy.loadtxt and pandas.read_csv.

Writes (or reuses) a CSV of N random 3-D points (header x,y,z, values printed with %.17g so
that every reader must parse full-precision numbers; about 58 bytes a row, 580 MB at the
default N = 10^7) in a temporary folder, then

1. reads it once with each reader and checks that the arrays are equal (pandas after
   .to_numpy()), value for value;
2. times ROUNDS interleaved rounds in this process (karkas, pandas, numpy, karkas, ...) and
   prints the median seconds of each reader, its rate, and its time relative to pandas;
3. measures the peak memory of each read in a fresh subprocess: the child's peak resident set
   (VmHWM of /proc/self/status, which counts Rust and C allocations that tracemalloc does not
   see; not ru_maxrss, which Linux carries over from the parent through fork and exec) minus
   its resident set after the imports, printed against the size of the points themselves
   (N x 3 x 8 bytes). Linux only.

numpy.loadtxt is slow (about a minute per 10^7 rows): above --loadtxt-rows rows it is timed on
the first --loadtxt-rows rows (a file of its own) and its time scaled to N, which the output
says; --skip-loadtxt leaves it out.

    python3 bench/read_csv.py                      # 10^7 points
    python3 bench/read_csv.py --n 2000000          # a quicker run
    python3 bench/read_csv.py --threads 1          # with RAYON_NUM_THREADS=1

Needs numpy, pandas and the karkas package (pip install ./crates/karkas-py).
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

CHILD = r"""
import sys
which, path = sys.argv[1], sys.argv[2]
import numpy as np
if which == "karkas":
    import karkas
    read = karkas.read_curve
elif which == "pandas":
    import pandas as pd
    read = lambda p: pd.read_csv(p, engine="c").to_numpy()
else:
    read = lambda p: np.loadtxt(p, delimiter=",", skiprows=1)

def status_kib(field):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field + ":"):
                return int(line.split()[1])

before = status_kib("VmRSS")
a = read(path)
print(before, status_kib("VmHWM"), a.shape[0], a.nbytes)
"""


def write_points(path, n, seed=20261123, chunk=500_000):
    """N points uniform in [-1000, 1000)^3, %.17g, header x,y,z, written in chunks."""
    import numpy as np

    rng = np.random.default_rng(seed)
    tmp = path + ".part"
    with open(tmp, "w") as f:
        f.write("x,y,z\n")
        left = n
        while left > 0:
            k = min(chunk, left)
            np.savetxt(f, rng.uniform(-1000.0, 1000.0, (k, 3)), fmt="%.17g", delimiter=",")
            left -= k
    os.replace(tmp, path)


def first_rows(src, dst, rows):
    """The header and the first ROWS data rows of SRC, as the file DST."""
    with open(src) as f, open(dst, "w") as g:
        for k, line in enumerate(f):
            if k > rows:
                break
            g.write(line)


def readers(skip_loadtxt):
    import numpy as np
    import pandas as pd

    import karkas

    out = {
        "karkas.read_curve": karkas.read_curve,
        "pandas.read_csv(engine='c')": lambda p: pd.read_csv(p, engine="c").to_numpy(),
    }
    if not skip_loadtxt:
        out["numpy.loadtxt"] = lambda p: np.loadtxt(p, delimiter=",", skiprows=1)
    return out


CHILD_NAMES = {
    "karkas.read_curve": "karkas",
    "pandas.read_csv(engine='c')": "pandas",
    "numpy.loadtxt": "numpy",
}


def peak_memory(which, path, env):
    """(RSS after imports, peak RSS, rows, array bytes) of one read in a fresh process, bytes."""
    run = subprocess.run(
        [sys.executable, "-c", CHILD, which, path],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    before, peak, rows, nbytes = (int(v) for v in run.stdout.split())
    return before * 1024, peak * 1024, rows, nbytes


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=10_000_000, help="points (default 10^7)")
    ap.add_argument("--rounds", type=int, default=3, help="timed rounds (default 3)")
    ap.add_argument(
        "--dir",
        default=os.path.join(tempfile.gettempdir(), "karkas-read-bench"),
        help="folder of the CSV files, reused between runs",
    )
    ap.add_argument("--threads", type=int, help="RAYON_NUM_THREADS for karkas")
    ap.add_argument("--skip-loadtxt", action="store_true", help="leave numpy.loadtxt out")
    ap.add_argument(
        "--loadtxt-rows",
        type=int,
        default=1_000_000,
        help="time numpy.loadtxt on at most this many rows, scaled (default 10^6)",
    )
    ap.add_argument("--no-memory", action="store_true", help="skip the peak-memory runs")
    args = ap.parse_args()

    env = dict(os.environ)
    if args.threads:
        env["RAYON_NUM_THREADS"] = str(args.threads)
        os.environ["RAYON_NUM_THREADS"] = str(args.threads)

    import numpy as np
    import pandas as pd

    import karkas

    os.makedirs(args.dir, exist_ok=True)
    path = os.path.join(args.dir, f"points-{args.n}.csv")
    if not os.path.exists(path):
        t0 = time.perf_counter()
        write_points(path, args.n)
        print(f"wrote {path} in {time.perf_counter() - t0:.1f} s")
    size = os.path.getsize(path)
    points_bytes = args.n * 3 * 8
    print(
        f"file: {path}, {args.n} points, {size / 1e6:.0f} MB; "
        f"the points: {points_bytes / 1e6:.0f} MB"
    )
    print(
        f"karkas {karkas.__version__}, numpy {np.__version__}, pandas {pd.__version__}, "
        f"python {sys.version.split()[0]}, {os.cpu_count()} CPUs, "
        f"RAYON_NUM_THREADS={env.get('RAYON_NUM_THREADS', 'unset')}"
    )

    funcs = readers(args.skip_loadtxt)
    files = {name: path for name in funcs}
    scale = {name: 1.0 for name in funcs}
    if "numpy.loadtxt" in funcs and args.n > args.loadtxt_rows:
        subset = os.path.join(args.dir, f"points-{args.n}-first-{args.loadtxt_rows}.csv")
        if not os.path.exists(subset):
            first_rows(path, subset, args.loadtxt_rows)
        files["numpy.loadtxt"] = subset
        scale["numpy.loadtxt"] = args.n / args.loadtxt_rows
        print(
            f"numpy.loadtxt: timed on the first {args.loadtxt_rows} rows, "
            f"scaled x{scale['numpy.loadtxt']:g}"
        )

    # Equal results first.
    reference = funcs["karkas.read_curve"](path)
    assert reference.shape == (args.n, 3) and reference.dtype == np.float64
    for name, f in funcs.items():
        if name == "karkas.read_curve":
            continue
        a = f(files[name])
        b = reference[: a.shape[0]]
        assert a.shape == b.shape, (name, a.shape, b.shape)
        if not np.array_equal(a, b):
            diff = np.count_nonzero(a != b)
            ulps = np.max(np.abs(a - b) / np.spacing(np.abs(b)))
            print(f"{name}: {diff} of {a.size} values differ from karkas (at most {ulps:.0f} ulp)")
        else:
            print(f"{name}: equal to karkas.read_curve, value for value ({a.shape[0]} rows)")
        del a
    del reference

    # Interleaved timed rounds.
    times = {name: [] for name in funcs}
    for _ in range(args.rounds):
        for name, f in funcs.items():
            t0 = time.perf_counter()
            a = f(files[name])
            times[name].append((time.perf_counter() - t0) * scale[name])
            del a
    pandas_median = statistics.median(times["pandas.read_csv(engine='c')"])
    print(f"\ntime of a read, median of {args.rounds} interleaved rounds:")
    print(f"{'reader':32} {'median s':>9} {'Mpoints/s':>10} {'MB/s':>7} {'vs pandas':>10}")
    for name, ts in times.items():
        m = statistics.median(ts)
        note = " (scaled)" if scale[name] != 1.0 else ""
        print(
            f"{name:32} {m:9.2f} {args.n / m / 1e6:10.2f} {size / m / 1e6:7.0f} "
            f"{m / pandas_median:9.2f}x{note}"
        )

    if args.no_memory:
        return
    print("\npeak memory of a read in a fresh process (peak RSS minus RSS after the imports):")
    print(f"{'reader':32} {'peak MB':>8} {'x points':>9}")
    for name in funcs:
        before, peak, rows, nbytes = peak_memory(CHILD_NAMES[name], files[name], env)
        own = rows * 3 * 8
        extra = peak - before
        note = f" (on {rows} rows)" if rows != args.n else ""
        print(f"{name:32} {extra / 1e6:8.0f} {extra / own:8.2f}x{note}")


if __name__ == "__main__":
    main()
