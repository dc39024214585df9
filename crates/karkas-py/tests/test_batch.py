"""karkas.batch: the command line's batch from Python. Records for every input (a bad file is a
record, never an exception), keywords as the command's options, resume, the records file, the
same records and output bytes as `karkas batch` (when the binary is built), and bad usage
raised as exceptions."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import karkas

REPO = Path(__file__).resolve().parents[3]
BIN = Path(os.environ.get("KARKAS_BIN", REPO / "target" / "release" / "karkas"))
SHIPPED = REPO / "data" / "batch-foils"


def ellipse(n, a, b, noise, rng):
    t = np.linspace(0.0, np.pi, n)
    pts = np.column_stack([a * np.cos(t), b * np.sin(t)])
    return pts + rng.normal(0.0, noise, pts.shape)


@pytest.fixture
def corpus(tmp_path, rng):
    """Five noisy half-ellipses and two damaged files."""
    folder = tmp_path / "in"
    folder.mkdir()
    for k in range(5):
        np.savetxt(folder / f"e{k}.csv", ellipse(80, 1.0, 0.2 + 0.1 * k, 1e-5, rng), delimiter=",")
    (folder / "z-empty.csv").write_text("")
    (folder / "z-nan.csv").write_text("0,0\n1,nan\n2,0\n")
    return folder


def test_every_input_has_a_record_and_bad_files_do_not_raise(corpus, tmp_path):
    out = tmp_path / "out"
    records = karkas.batch("curve fit", corpus, out, tolerance=1e-4, as_frame=False)
    assert [Path(r["input"]).name for r in records] == sorted(p.name for p in corpus.iterdir())
    good = [r for r in records if r["status"] == "ok"]
    bad = [r for r in records if r["status"] == "error"]
    assert len(good) == 5 and len(bad) == 2
    for r in good:
        assert r["error"] is None
        assert r["summary"]["tolerance_met"] is True
        assert r["summary"]["max_deviation"] <= 1e-4
        assert r["outputs"] == [str(out / (Path(r["input"]).stem + ".csv"))]
        assert Path(r["outputs"][0]).read_text().startswith("t,x,y\n")
        assert r["seconds"] > 0
    assert "z-nan.csv:2: non-finite value" in bad[1]["error"]
    assert all(r["outputs"] == [] for r in bad)
    lines = (out / "results.jsonl").read_text().splitlines()
    assert [json.loads(line) for line in lines] == records


def test_keywords_are_the_commands_options(corpus, tmp_path):
    knots = [0.0, 0.2, 0.5, 0.8, 1.0]
    records = karkas.batch(
        ["curve", "fit"], [corpus / "e1.csv", corpus / "e2.csv"], tmp_path / "o",
        knots=knots, pin_ends=True, report=True, smoothing=None, as_frame=False,
    )
    for r in records:
        assert r["status"] == "ok", r["error"]
        assert r["summary"]["knots"] == len(knots)
        assert r["outputs"][1].endswith(".deviations.csv")
        assert Path(r["outputs"][1]).read_text().startswith("point,t,distance\n")
    svg = karkas.batch("curve ll --order 3", str(corpus / "e*.csv"), tmp_path / "svg",
                       format="svg", results_file=False, as_frame=False)
    assert [Path(r["outputs"][0]).suffix for r in svg] == [".svg"] * 5
    assert not (tmp_path / "svg" / "results.jsonl").exists()
    with pytest.raises(karkas.OptionError, match="unexpected argument '--no-such'"):
        karkas.batch("curve fit", corpus, tmp_path / "x", no_such=3)
    with pytest.raises(karkas.OptionError, match="leave out -o"):
        karkas.batch("curve fit", corpus, tmp_path / "x", options=["-o", "a.csv", "--knots", "5"])


def test_resume_runs_only_what_is_not_done(corpus, tmp_path):
    out = tmp_path / "out"
    first = karkas.batch("curve fit", corpus, out, knots=6, as_frame=False)
    (corpus / "z-nan.csv").write_text("0,0\n1,1\n2,0\n3,1\n")
    again = karkas.batch("curve fit", corpus, out, knots=6, resume=True, as_frame=False)
    by_input = {r["input"]: r for r in first}
    for r in again:
        name = Path(r["input"]).name
        if name.startswith("e"):
            assert r == by_input[r["input"]], "a done input ran again"
        elif name == "z-nan.csv":
            assert r["status"] == "ok" and r != by_input[r["input"]]
        else:
            assert r["status"] == "error"
    assert len((out / "results.jsonl").read_text().splitlines()) == 7


def test_a_data_frame_when_pandas_is_there(corpus, tmp_path):
    pd = pytest.importorskip("pandas")
    frame = karkas.batch("curve spline", corpus, tmp_path / "o")
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == ["input", "outputs", "status", "error", "summary", "seconds"]
    assert (frame["status"] == "ok").sum() == 5


def test_bad_usage_raises(corpus, tmp_path):
    with pytest.raises(karkas.OptionError, match="no such file or folder"):
        karkas.batch("curve fit", tmp_path / "nothing", tmp_path / "o", knots=5)
    with pytest.raises(karkas.OptionError, match="reads several inputs"):
        karkas.batch("surface coons", corpus, tmp_path / "o")
    with pytest.raises(karkas.OptionError, match="jobs"):
        karkas.batch("curve fit", corpus, tmp_path / "o", knots=5, jobs=0)
    with pytest.raises(karkas.OptionError):
        karkas.batch(3, corpus, tmp_path / "o")
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(OSError):
        karkas.batch("curve fit", corpus, blocker, knots=5)
    assert karkas.batch_inputs([corpus / "e0.csv", str(corpus / "e*.csv")]) == [
        str(corpus / f"e{k}.csv") for k in range(5)
    ]


@pytest.mark.skipif(not BIN.is_file(), reason=f"no karkas binary at {BIN}")
def test_the_same_records_and_files_as_the_command_line(tmp_path):
    py_out, cli_out = tmp_path / "py", tmp_path / "cli"
    records = karkas.batch("curve fit", SHIPPED, py_out, tolerance=1e-4, as_frame=False)
    done = subprocess.run(
        [str(BIN), "batch", "curve", "fit", "--inputs", str(SHIPPED), "--out", str(cli_out),
         "--tolerance", "1e-4"],
        capture_output=True, text=True,
    )
    assert done.returncode == 1, done.stderr  # the shipped corpus holds damaged files
    cli_records = [json.loads(line) for line in (cli_out / "results.jsonl").read_text().splitlines()]
    assert len(records) == len(cli_records) == 30
    for py, cli in zip(records, cli_records):
        assert py["input"] == cli["input"] and py["status"] == cli["status"]
        assert py["error"] == cli["error"]
        figures = lambda r: {k: v for k, v in r["summary"].items() if k not in ("seconds", "messages")}
        assert figures(py) == figures(cli)
        for a, b in zip(py["outputs"], cli["outputs"]):
            assert Path(a).read_bytes() == Path(b).read_bytes()
    assert sum(r["status"] == "ok" for r in records) == 24


def test_a_tree_names_outputs_after_their_folders(tmp_path, rng):
    for folder in ["wing", "tail/root"]:
        (tmp_path / "db" / folder).mkdir(parents=True)
        np.savetxt(tmp_path / "db" / folder / "x.csv", ellipse(40, 1.0, 0.3, 0.0, rng), delimiter=",")
    pattern = str(tmp_path / "db" / "**" / "*.csv")
    with pytest.raises(karkas.OptionError, match="--tree"):
        karkas.batch("curve spline", pattern, tmp_path / "out")
    records = karkas.batch("curve spline", pattern, tmp_path / "out", tree=tmp_path / "db",
                           as_frame=False)
    assert sorted(r["outputs"][0] for r in records) == [
        str(tmp_path / "out" / "tail" / "root" / "x.csv"),
        str(tmp_path / "out" / "wing" / "x.csv"),
    ]
    with pytest.raises(karkas.OptionError, match="not in that folder"):
        karkas.batch("curve spline", pattern, tmp_path / "out", tree=tmp_path / "db" / "wing")
