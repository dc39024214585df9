//! `karkas batch`: a corpus of noisy sections with damaged files through `curve fit`, killed
//! half-way and resumed; outputs equal to the single command's; bad usage exits 2.

use crate::common::{karkas, s, stderr, temp_dir, write};
use serde_json::Value;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant, SystemTime};

/// A NACA 4-digit section (closed trailing edge, `n` cosine-spaced points per side) as a
/// Selig `.dat`, each coordinate moved by Gaussian noise of `sigma` chords.
fn noisy_naca(m: f64, p: f64, t: f64, n: usize, sigma: f64, rng: &mut Rng) -> String {
    let mut upper = Vec::new();
    let mut lower = Vec::new();
    for i in 0..n {
        let x = 0.5 * (1.0 - (std::f64::consts::PI * i as f64 / (n - 1) as f64).cos());
        let yt = 5.0
            * t
            * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                - 0.1036 * x.powi(4));
        let (yc, dy) = if m == 0.0 {
            (0.0, 0.0)
        } else if x < p {
            (
                m / (p * p) * (2.0 * p * x - x * x),
                2.0 * m / (p * p) * (p - x),
            )
        } else {
            let q = (1.0 - p) * (1.0 - p);
            (
                m / q * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
                2.0 * m / q * (p - x),
            )
        };
        let th = dy.atan();
        upper.push((x - yt * th.sin(), yc + yt * th.cos()));
        lower.push((x + yt * th.sin(), yc - yt * th.cos()));
    }
    let mut text = format!("NACA {m} {p} {t:.4} noisy\n");
    for &(x, y) in upper.iter().rev().chain(&lower[1..]) {
        let (dx, dy) = (sigma * rng.gauss(), sigma * rng.gauss());
        text.push_str(&format!(" {:.7} {:.7}\n", x + dx, y + dy));
    }
    text
}

/// xorshift64* with Box–Muller: the same noise on every run.
struct Rng(u64);

impl Rng {
    fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11;
        (bits as f64 + 0.5) / (1u64 << 53) as f64
    }

    fn gauss(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// Damaged files, each refused with a line naming it: empty, words, a NaN, one point,
/// binary bytes, a line cut after one number.
const DAMAGED: [&[u8]; 6] = [
    b"",
    b"not an airfoil\nat all, just words\n",
    b"NACA broken\n1.0 0.0\n0.5 nan\n0.0 0.0\n0.5 -0.05\n1.0 0.0\n",
    b"NACA one point\n0.5 0.01\n",
    &[0u8, 1, 2, 3, 255, 254, 0, 7, 10, 0],
    b"NACA cut\n1.0 0.0\n0.5 0.06\n0.0 0.0\n0.5\n",
];

/// Writes `count` noisy sections `foil-NNNNN.dat` into the folder `dir` (made), and the
/// damaged files when `damaged`; returns the names of the damaged ones.
fn corpus(dir: &Path, count: usize, points: usize, damaged: bool) -> Vec<String> {
    std::fs::create_dir_all(dir).unwrap();
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for k in 0..count {
        let m = (k % 7) as f64 / 100.0;
        let p = (2 + k % 5) as f64 / 10.0;
        let t = 0.06 + 0.15 * rng.uniform();
        let text = noisy_naca(m, p, t, points, 2e-5, &mut rng);
        std::fs::write(dir.join(format!("foil-{k:05}.dat")), text).unwrap();
    }
    DAMAGED
        .iter()
        .take(if damaged { DAMAGED.len() } else { 0 })
        .enumerate()
        .map(|(k, bytes)| {
            let name = format!("damaged-{k}.dat");
            std::fs::write(dir.join(&name), bytes).unwrap();
            name
        })
        .collect()
}

/// The records of a results file by input, with their lines (a torn last line skipped).
fn records(out: &Path) -> HashMap<String, (Value, String)> {
    let text = std::fs::read_to_string(out.join("results.jsonl")).unwrap_or_default();
    text.lines()
        .filter_map(|line| {
            let v: Value = serde_json::from_str(line).ok()?;
            Some((v["input"].as_str()?.to_owned(), (v, line.to_owned())))
        })
        .collect()
}

fn modified(path: &str) -> SystemTime {
    std::fs::metadata(path).unwrap().modified().unwrap()
}

#[test]
fn two_thousand_noisy_sections_with_damaged_files_resume_after_a_kill() {
    let dir = temp_dir();
    let (inputs, out) = (dir.path().join("foils"), dir.path().join("fits"));
    let damaged = corpus(&inputs, 2000, 61, true);
    let args = [
        "batch",
        "curve",
        "fit",
        "--inputs",
        s(&inputs),
        "--out",
        s(&out),
        "--tolerance",
        "1e-4",
        "--jobs",
        "2",
    ];
    // The first run, killed half-way: once half of the inputs are recorded.
    let mut child = Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args(args)
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let started = Instant::now();
    let recorded = || {
        let bytes = std::fs::read(out.join("results.jsonl")).unwrap_or_default();
        bytes.iter().filter(|&&b| b == b'\n').count()
    };
    while recorded() < 1003 {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the batch ended before the kill"
        );
        assert!(started.elapsed() < Duration::from_secs(120), "no progress");
        std::thread::sleep(Duration::from_millis(5));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let first = records(&out);
    assert!(
        first.len() < 2006,
        "{} records before the kill",
        first.len()
    );
    let done_before: HashMap<String, (String, Vec<SystemTime>)> = first
        .iter()
        .filter(|(_, (v, _))| v["status"] == "ok")
        .map(|(input, (v, line))| {
            let outputs = v["outputs"].as_array().unwrap();
            let times = outputs
                .iter()
                .map(|o| modified(o.as_str().unwrap()))
                .collect();
            (input.clone(), (line.clone(), times))
        })
        .collect();

    // The resumed run finishes the rest and redoes nothing.
    let resumed = karkas(&[&args[..], &["--resume"]].concat());
    assert_eq!(resumed.status.code(), Some(1), "{}", stderr(&resumed));
    let said = stderr(&resumed);
    let summary = format!(
        "2006 inputs, 2000 ok ({} done before), 6 failed; {} run in",
        done_before.len(),
        2006 - done_before.len()
    );
    assert!(said.contains(&summary), "{said}");
    for name in &damaged {
        assert!(
            said.contains(&format!("karkas: error: {}", s(&inputs.join(name)))),
            "{said}"
        );
    }
    let text = std::fs::read_to_string(out.join("results.jsonl")).unwrap();
    assert_eq!(text.lines().count(), 2006, "one line per input");
    let last = records(&out);
    assert_eq!(last.len(), 2006);
    for (input, (line, times)) in &done_before {
        assert_eq!(&last[input].1, line, "{input} was run again");
        let outputs = last[input].0["outputs"].as_array().unwrap();
        let now: Vec<SystemTime> = outputs
            .iter()
            .map(|o| modified(o.as_str().unwrap()))
            .collect();
        assert_eq!(&now, times, "{input}: its output was written again");
    }
    for (input, (v, _)) in &last {
        let is_damaged = damaged.iter().any(|d| input.ends_with(d.as_str()));
        if is_damaged {
            assert_eq!(v["status"], "error", "{input}");
            assert!(v["error"].as_str().unwrap().contains(input.as_str()), "{v}");
            assert_eq!(v["outputs"], Value::Array(vec![]));
            continue;
        }
        assert_eq!(v["status"], "ok", "{v}");
        assert_eq!(v["error"], Value::Null);
        let summary = &v["summary"];
        assert_eq!(summary["tolerance_met"], true, "{v}");
        assert!(summary["max_deviation"].as_f64().unwrap() <= 1e-4, "{v}");
        assert!(summary["knots"].as_u64().unwrap() >= 2, "{v}");
        let output = v["outputs"][0].as_str().unwrap();
        let stem = Path::new(input).file_stem().unwrap();
        assert_eq!(Path::new(output), out.join(stem).with_extension("csv"));
        assert!(std::fs::read_to_string(output)
            .unwrap()
            .starts_with("t,x,y\n"));
        assert!(v["seconds"].as_f64().unwrap() > 0.0);
    }

    // Once more: only the damaged files run, and still fail.
    let again = karkas(&[&args[..], &["--resume"]].concat());
    assert_eq!(again.status.code(), Some(1));
    assert!(stderr(&again).contains("2000 ok (2000 done before), 6 failed; 6 run"));
}

#[test]
fn each_output_equals_the_single_command_and_a_clean_batch_exits_0() {
    let dir = temp_dir();
    let inputs = dir.path().join("in");
    corpus(&inputs, 3, 41, false);
    let list = write(
        dir.path(),
        "list.txt",
        "# two of them\nin/foil-00002.dat\nin/foil-00000.dat\n",
    );
    let out = dir.path().join("out");
    let batch = karkas(&[
        "batch",
        "--inputs",
        s(&list),
        "curve",
        "fit",
        "--knots",
        "8",
        "--out",
        s(&out),
        "--report",
        "--smoothing",
        "0.1",
    ]);
    assert_eq!(batch.status.code(), Some(0), "{}", stderr(&batch));
    let lines: Vec<Value> = std::fs::read_to_string(out.join("results.jsonl"))
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let order: Vec<&str> = lines.iter().map(|v| v["input"].as_str().unwrap()).collect();
    assert_eq!(
        order,
        [
            s(&dir.path().join("in/foil-00002.dat")),
            s(&dir.path().join("in/foil-00000.dat"))
        ]
    );
    for v in &lines {
        let input = PathBuf::from(v["input"].as_str().unwrap());
        let single = dir.path().join("single.csv");
        let report = dir.path().join("single-dev.csv");
        let alone = karkas(&[
            "curve",
            "fit",
            s(&input),
            "--knots",
            "8",
            "--smoothing",
            "0.1",
            "-o",
            s(&single),
            "--report",
            s(&report),
        ]);
        assert!(alone.status.success(), "{}", stderr(&alone));
        let outputs: Vec<&str> = v["outputs"]
            .as_array()
            .unwrap()
            .iter()
            .map(|o| o.as_str().unwrap())
            .collect();
        assert_eq!(outputs.len(), 2);
        assert!(outputs[1].ends_with(".deviations.csv"));
        assert_eq!(
            std::fs::read(outputs[0]).unwrap(),
            std::fs::read(&single).unwrap()
        );
        assert_eq!(
            std::fs::read(outputs[1]).unwrap(),
            std::fs::read(&report).unwrap()
        );
        assert_eq!(v["summary"]["knots"], 8);
        // The foil's ends lie 3.5e-5 apart: a warning says so before the line of the file.
        let messages = v["summary"]["messages"].as_array().unwrap();
        assert!(
            messages[0].as_str().unwrap().contains("--close-te"),
            "{messages:?}"
        );
        let message = messages
            .iter()
            .filter_map(|m| m.as_str())
            .find(|m| m.starts_with("wrote "))
            .unwrap();
        assert!(message.contains("8 knots"), "{message}");
    }
    // A glob, another command and format: pictures.
    let pattern = format!("{}/*.dat", s(&inputs));
    let svg = dir.path().join("svg");
    let ll = |more: &[&str]| {
        let start = [
            "batch", "curve", "ll", "--order", "3", "--inputs", &pattern, "--out",
        ];
        karkas(&[&start[..], &[s(&svg)], more].concat())
    };
    let pictures = ll(&["--format", "svg"]);
    assert_eq!(pictures.status.code(), Some(0), "{}", stderr(&pictures));
    for k in 0..3 {
        let text = std::fs::read_to_string(svg.join(format!("foil-0000{k}.svg"))).unwrap();
        assert!(
            text.starts_with("<svg") || text.starts_with("<?xml"),
            "{}",
            &text[..40]
        );
    }
    // A resume with another format writes other files: every input runs again.
    let resumed = ll(&["--resume"]);
    assert_eq!(resumed.status.code(), Some(0), "{}", stderr(&resumed));
    assert!(stderr(&resumed).contains("3 inputs, 3 ok, 0 failed; 3 run in"));
    assert!(svg.join("foil-00001.csv").is_file());
    // A pattern the shell expanded: the files after --inputs are all inputs.
    let files: Vec<PathBuf> = (0..3)
        .map(|k| inputs.join(format!("foil-0000{k}.dat")))
        .collect();
    let splines = dir.path().join("splines");
    let mut args = vec!["batch", "curve", "spline", "--inputs"];
    args.extend(files.iter().map(|f| s(f)));
    args.extend(["--out", s(&splines), "--ends", "natural"]);
    let expanded = karkas(&args);
    assert_eq!(expanded.status.code(), Some(0), "{}", stderr(&expanded));
    assert!(stderr(&expanded).contains("3 inputs, 3 ok"));
}

#[test]
fn bad_usage_exits_2_before_any_input() {
    let dir = temp_dir();
    let inputs = dir.path().join("in");
    corpus(&inputs, 1, 21, true);
    let other = dir.path().join("other");
    std::fs::create_dir(&other).unwrap();
    std::fs::copy(inputs.join("foil-00000.dat"), other.join("foil-00000.csv")).unwrap();
    let out = dir.path().join("out");
    let (i, o) = (s(&inputs), s(&out));
    for (args, says) in [
        (
            vec![
                "batch",
                "curve",
                "fit",
                "--inputs",
                i,
                "--tolerance",
                "1e-4",
            ],
            "--out DIR is needed",
        ),
        (
            vec![
                "batch", "curve", "fit", "--inputs", i, "--out", o, "--bogus",
            ],
            "unexpected argument '--bogus'",
        ),
        (
            vec!["batch", "surface", "coons", "--inputs", i, "--out", o],
            "reads several inputs",
        ),
        (
            vec![
                "batch", "curve", "fit", "--inputs", i, "--out", o, "-o", "x.csv",
            ],
            "leave out -o",
        ),
        (
            vec![
                "batch", "curve", "ll", "--inputs", i, "--out", o, "--jobs", "0",
            ],
            "--jobs: at least 1",
        ),
        (
            vec![
                "batch",
                "curve",
                "ll",
                "--inputs",
                "no/such/dir",
                "--out",
                o,
            ],
            "no such file or folder",
        ),
        (
            vec![
                "batch",
                "curve",
                "ll",
                "--inputs",
                i,
                "--inputs",
                s(&other),
                "--out",
                o,
            ],
            "outputs of the same name",
        ),
        (
            vec!["batch", "convert", "--inputs", i, "--out", o],
            "--format",
        ),
    ] {
        let run = karkas(&args);
        assert_eq!(run.status.code(), Some(2), "{args:?}: {}", stderr(&run));
        let said = stderr(&run);
        assert!(said.contains(says), "{args:?}: {said}");
        assert_eq!(said.lines().count(), 1, "{said}");
    }
    assert!(!out.exists(), "nothing is written on bad usage");
}

#[test]
fn a_tree_names_outputs_after_their_folders() {
    let dir = temp_dir();
    let db = dir.path().join("db");
    for folder in ["wing", "tail/root"] {
        corpus(&db.join(folder), 1, 21, false);
    }
    let pattern = format!("{}/**/*.dat", s(&db));
    let out = dir.path().join("out");
    let spline = |more: &[&str]| {
        let start = [
            "batch",
            "curve",
            "spline",
            "--inputs",
            &pattern,
            "--out",
            s(&out),
        ];
        karkas(&[&start[..], more].concat())
    };
    let flat = spline(&[]);
    assert_eq!(flat.status.code(), Some(2));
    assert!(stderr(&flat).contains("--tree DIR"), "{}", stderr(&flat));
    let tree = spline(&["--tree", s(&db)]);
    assert_eq!(tree.status.code(), Some(0), "{}", stderr(&tree));
    for name in ["wing/foil-00000.csv", "tail/root/foil-00000.csv"] {
        let text = std::fs::read_to_string(out.join(name)).unwrap();
        assert!(text.starts_with("t,x,y\n"), "{name}");
    }
    let outside = spline(&["--tree", s(&db.join("wing"))]);
    assert_eq!(outside.status.code(), Some(2));
    assert!(
        stderr(&outside).contains("is not in that folder"),
        "{}",
        stderr(&outside)
    );
}
