//! Where results go and what they may cost: `-o -` (standard output) and `--format` for every
//! command that writes, a closed pipe, the memory cap over every kind of output (measured as
//! the peak resident memory of the child process), error lines that carry the system's message
//! once and never a temporary file's name, and the clean-up of temporary files left by a
//! killed run.

use crate::common::{grid_csv, karkas, karkas_in, s, stderr, stdout, temp_dir, write};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The allowance above the cap for the program itself (code, fonts, allocator).
const OVERHEAD_MIB: u64 = 64;

/// A 6 x 6 grid, gently curved.
fn grid(dir: &Path) -> PathBuf {
    let text = grid_csv(6, 6, |i, j| {
        let (x, y) = (i as f64, j as f64);
        [x, y, 0.1 * (x * y).sin()]
    });
    write(dir, "g.csv", &text)
}

/// Twelve points on an ellipse, as `x,y`.
fn points(dir: &Path) -> PathBuf {
    let mut text = String::from("x,y\n");
    for k in 0..12 {
        let t = std::f64::consts::TAU * k as f64 / 12.0;
        text.push_str(&format!("{},{}\n", 2.0 * t.cos(), t.sin()));
    }
    write(dir, "pts.csv", &text)
}

/// A Coons network of two curves per family on the unit square (z = x y).
fn network(dir: &Path) -> (PathBuf, PathBuf) {
    let mut u = String::from("curve,x,y,z\n");
    let mut v = String::from("curve,x,y,z\n");
    for c in 0..2 {
        for k in 0..5 {
            let (a, t) = (c as f64, k as f64 / 4.0);
            u.push_str(&format!("{c},{t},{a},{}\n", t * a));
            v.push_str(&format!("{c},{a},{t},{}\n", a * t));
        }
    }
    (write(dir, "u.csv", &u), write(dir, "v.csv", &v))
}

/// Every command that writes a result, with its arguments but `-o`/the output (appended by
/// the caller), on small inputs in `dir`; the first word of the CSV header each writes.
fn writing_commands(dir: &Path) -> Vec<(Vec<String>, &'static str)> {
    let g = s(&grid(dir)).to_owned();
    let p = s(&points(dir)).to_owned();
    let (u, v) = network(dir);
    let args = |a: &[&str]| a.iter().map(|x| (*x).to_owned()).collect::<Vec<_>>();
    vec![
        (args(&["curve", "ll", &p]), "t"),
        (args(&["curve", "fit", &p, "--tolerance", "0.1"]), "t"),
        (args(&["curve", "dps", "--order", "2", "--n", "4", &p]), "j"),
        (args(&["surface", "ll", &g]), "u"),
        (args(&["surface", "bicubic", &g]), "u"),
        (
            args(&[
                "surface",
                "coons",
                "--kind",
                "bilinear",
                "--u-curves",
                s(&u),
                "--v-curves",
                s(&v),
            ]),
            "u",
        ),
        (
            args(&[
                "surface",
                "implicit",
                "--expr",
                "x^2+y^2+z^2-1",
                "--start",
                "1,0,0",
                "--nodes",
                "3,3",
                "--step",
                "0.1",
            ]),
            "i",
        ),
        (
            args(&["section", &g, "--method", "ll", "--z", "0.05"]),
            "section",
        ),
        (
            args(&[
                "vary",
                &g,
                "--coord",
                "z",
                "--rows",
                "1,1,1,1,1",
                "--cols",
                "1,1,1,1,1",
                "--total",
                "6",
            ]),
            "i",
        ),
    ]
}

#[test]
fn every_writing_command_writes_csv_to_standard_output() {
    let dir = temp_dir();
    for (mut args, first) in writing_commands(dir.path()) {
        args.extend(["-o".to_owned(), "-".to_owned()]);
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let o = karkas_in(dir.path(), &refs);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        let out = stdout(&o);
        let header = out.lines().next().unwrap_or("");
        assert!(
            header.split(',').next() == Some(first) && out.lines().count() > 2,
            "{args:?}: {header}"
        );
        // Only the result on standard output; the summary names standard output on stderr.
        assert!(!out.contains("karkas"), "{args:?}: {out}");
        assert!(
            stderr(&o).contains("wrote <stdout>"),
            "{args:?}: {}",
            stderr(&o)
        );
        assert!(!dir.path().join("-").exists());
    }
    // convert's OUTPUT is positional.
    let g = grid(dir.path());
    let o = karkas(&["convert", s(&g), "-"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("i,j,x,y,z\n"));
}

#[test]
fn format_picks_another_format_on_standard_output_and_wins_over_the_extension() {
    let dir = temp_dir();
    let g = grid(dir.path());
    let p = points(dir.path());
    let o = karkas(&["surface", "ll", s(&g), "-o", "-", "--format", "svg"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("<svg"));
    let o = karkas(&["curve", "ll", s(&p), "-o", "-", "--format", "html"]);
    assert!(stdout(&o).starts_with("<!DOCTYPE html>"), "{}", stderr(&o));
    let o = karkas(&["surface", "ll", s(&g), "-o", "-", "--format", "obj"]);
    assert!(stdout(&o).contains("\nv "), "{}", stderr(&o));
    let o = karkas(&["surface", "ll", s(&g), "-o", "-", "--format", "step"]);
    assert!(stdout(&o).starts_with("ISO-10303-21;"), "{}", stderr(&o));
    let o = karkas(&["convert", s(&g), "-", "--format", "obj"]);
    assert!(stdout(&o).contains("\nv "), "{}", stderr(&o));
    // A pipe carries bytes: binary formats too.
    let o = karkas(&["surface", "ll", s(&g), "-o", "-", "--format", "png"]);
    assert!(o.stdout.starts_with(b"\x89PNG\r\n\x1a\n"), "{}", stderr(&o));
    let o = karkas(&["surface", "ll", s(&g), "-o", "-", "--format", "stl"]);
    assert!(o.status.success() && o.stdout.len() > 84, "{}", stderr(&o));
    // On a file, --format wins over the extension.
    let out = dir.path().join("result.txt");
    let o = karkas(&["surface", "ll", s(&g), "-o", s(&out), "--format", "csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&out)
        .unwrap()
        .starts_with("u,v,x,y,z\n"));
}

#[test]
fn format_a_command_cannot_write_is_refused() {
    let dir = temp_dir();
    let p = points(dir.path());
    let o = karkas(&["curve", "ll", s(&p), "-o", "-", "--format", "obj"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o),
        "karkas: error: --format obj: this command writes csv, svg, png, html, step, iges, dxf, npy\n"
    );
    assert!(o.stdout.is_empty());
    let o = karkas(&["curve", "ll", s(&p), "-o", "-", "--format", "docx"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("'docx' is not an output format"),
        "{}",
        stderr(&o)
    );
    let o = karkas(&["hausdorff", s(&p), s(&p), "--format", "csv"]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o),
        "karkas: error: --format: this command writes no output file\n"
    );
    // A mesh has no CSV: standard output needs --format.
    let mesh = write(dir.path(), "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let o = karkas(&["convert", s(&mesh), "-"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("a triangle mesh converts to"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_closed_pipe_ends_the_run_quietly() {
    let dir = temp_dir();
    let g = grid(dir.path());
    // Far more output than a pipe holds; the reader takes one line and closes it.
    let mut child = Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args(["surface", "ll", s(&g), "-o", "-", "--samples", "1000,1000"])
        .env_remove("KARKAS_MAX_MEMORY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut out = child.stdout.take().unwrap();
    let mut first = [0u8; 10];
    out.read_exact(&mut first).unwrap();
    assert_eq!(&first, b"u,v,x,y,z\n");
    drop(out);
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stderr(&o), "", "no message, no panic");
}

/// Runs karkas with `args` under a Python parent that reports the child's peak resident
/// memory (`ru_maxrss`, KiB on Linux); the exit code, standard error and the peak in MiB.
fn peak_memory(dir: &Path, args: &[&str]) -> (Option<i32>, String, u64) {
    let script = "import resource, subprocess, sys\n\
                  r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)\n\
                  sys.stderr.write(r.stderr.decode())\n\
                  print(r.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n";
    let o = Command::new("python3")
        .arg("-c")
        .arg(script)
        .arg(env!("CARGO_BIN_EXE_karkas"))
        .args(args)
        .env_remove("KARKAS_MAX_MEMORY")
        .current_dir(dir)
        .output()
        .expect("python3 runs");
    let text = stdout(&o);
    let mut fields = text.split_whitespace();
    let code = fields.next().and_then(|c| c.parse().ok());
    let kib: u64 = fields.next().and_then(|k| k.parse().ok()).expect("peak");
    (code, stderr(&o), kib / 1024)
}

/// Either the cap's refusal (exit 2, one line naming the cap) or success within the cap plus
/// the fixed overhead.
fn assert_within(what: &str, cap_mib: u64, (code, err, peak): (Option<i32>, String, u64)) {
    match code {
        Some(2) => assert!(
            err.contains("cap of") && err.lines().count() == 1,
            "{what}: {err}"
        ),
        Some(0) => {}
        other => panic!("{what}: exit {other:?}: {err}"),
    }
    assert!(
        peak <= cap_mib + OVERHEAD_MIB,
        "{what}: peak {peak} MiB above {cap_mib} MiB + {OVERHEAD_MIB} MiB ({err})"
    );
}

#[test]
fn the_memory_cap_holds_for_pictures_pages_and_meshes() {
    let dir = temp_dir();
    let g = grid(dir.path());
    let p = points(dir.path());
    for cap in [16u64, 48, 128] {
        let cap_arg = format!("{cap}M");
        for (samples, out) in [
            ("800,800", "a.png"),
            ("800,800", "a.svg"),
            ("800,800", "a.html"),
            ("800,800", "a.glb"),
            ("800,800", "a.stl"),
            ("200,200", "b.png"),
        ] {
            let args = [
                "--max-memory",
                &cap_arg,
                "surface",
                "ll",
                s(&g),
                "-o",
                out,
                "--samples",
                samples,
            ];
            let what = format!("{out} {samples} under {cap_arg}");
            assert_within(&what, cap, peak_memory(dir.path(), &args));
        }
        for out in ["c.png", "c.html"] {
            let args = [
                "--max-memory",
                &cap_arg,
                "curve",
                "ll",
                s(&p),
                "-o",
                out,
                "--samples",
                "2000000",
            ];
            let what = format!("curve {out} under {cap_arg}");
            assert_within(&what, cap, peak_memory(dir.path(), &args));
        }
        for out in ["d.svg", "d.csv"] {
            let args = [
                "--max-memory",
                &cap_arg,
                "curve",
                "dps",
                "--order",
                "2",
                "--n",
                "1000000",
                s(&p),
                "-o",
                out,
            ];
            let what = format!("curve dps {out} under {cap_arg}");
            assert_within(&what, cap, peak_memory(dir.path(), &args));
        }
    }
    // The refusal comes before any work: the big PNG is refused at once under 16M.
    let (code, err, _) = peak_memory(
        dir.path(),
        &[
            "--max-memory",
            "16M",
            "surface",
            "ll",
            s(&g),
            "-o",
            "a.png",
            "--samples",
            "800,800",
        ],
    );
    assert_eq!(code, Some(2));
    assert!(err.contains("800 x 800 samples as png would need"), "{err}");
}

#[test]
fn the_memory_cap_holds_for_convert() {
    let dir = temp_dir();
    let g = grid(dir.path());
    // A sampled surface of 250 x 250 and a mesh of 300 x 300, written without a cap: what
    // convert makes of them (a picture, a page, a mesh) takes far more than reading them.
    let o = karkas_in(
        dir.path(),
        &[
            "surface",
            "ll",
            s(&g),
            "-o",
            "s.csv",
            "--samples",
            "250,250",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let o = karkas_in(
        dir.path(),
        &[
            "surface",
            "ll",
            s(&g),
            "-o",
            "m.obj",
            "--samples",
            "300,300",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    for cap in [16u64, 64, 160] {
        let cap_arg = format!("{cap}M");
        for (input, output) in [
            ("s.csv", "c.png"),
            ("s.csv", "c.html"),
            ("s.csv", "c.glb"),
            ("m.obj", "c.stl"),
            ("m.obj", "d.html"),
        ] {
            let args = ["--max-memory", &cap_arg, "convert", input, output];
            let what = format!("convert {input} {output} under {cap_arg}");
            assert_within(&what, cap, peak_memory(dir.path(), &args));
        }
    }
}

#[test]
fn the_demo_refuses_a_small_cap_before_writing_and_stays_within_a_larger_one() {
    let dir = temp_dir();
    let out = dir.path().join("demo");
    let (code, err, peak) = peak_memory(
        dir.path(),
        &["--max-memory", "16M", "demo", "--out", s(&out)],
    );
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(
        err,
        "karkas: error: demo would need 80.0 MiB of memory, above the cap of 16.0 MiB (raise it \
         with --max-memory or KARKAS_MAX_MEMORY, or ask for fewer samples)\n"
    );
    assert!(peak <= 16 + OVERHEAD_MIB);
    assert!(!out.exists(), "nothing written");
    let result = peak_memory(
        dir.path(),
        &["--max-memory", "80M", "demo", "--out", s(&out)],
    );
    assert_eq!(result.0, Some(0), "{}", result.1);
    assert_within("demo under 80M", 80, result);
}

#[test]
fn the_system_message_appears_once_and_no_temporary_name_ever() {
    let dir = temp_dir();
    let g = grid(dir.path());
    let p = points(dir.path());
    let missing = dir.path().join("missing.csv");
    let nowhere = dir.path().join("no-such-folder").join("out.csv");
    let runs: Vec<Vec<&str>> = vec![
        vec!["curve", "ll", s(&missing), "-o", "o.csv"],
        vec!["surface", "ll", s(&missing), "-o", "o.csv"],
        vec!["convert", s(&missing), "o.png"],
        vec!["curve", "ll", s(&p), "-o", s(&nowhere)],
        vec!["surface", "ll", s(&g), "-o", s(&nowhere)],
        vec![
            "curve",
            "fit",
            s(&p),
            "--tolerance",
            "0.1",
            "-o",
            s(&nowhere),
        ],
    ];
    for args in runs {
        let o = karkas_in(dir.path(), &args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        // One error line (a fit may warn about its shape before the write fails).
        let errors = err.lines().filter(|l| !l.starts_with("karkas: warning: "));
        assert_eq!(errors.count(), 1, "{err}");
        assert_eq!(err.matches("No such file or directory").count(), 1, "{err}");
        assert!(
            !err.contains("karkas-tmp") && !err.contains(".karkas-"),
            "{err}"
        );
    }
    let o = karkas_in(dir.path(), &["surface", "ll", s(&g), "-o", s(&nowhere)]);
    assert_eq!(
        stderr(&o),
        format!(
            "karkas: error: cannot write {}: No such file or directory (os error 2)\n",
            nowhere.display()
        )
    );
}

/// The id of a process that has ended (a short-lived child, waited for).
fn dead_pid() -> u32 {
    let mut child = Command::new("true").spawn().unwrap();
    let pid = child.id();
    child.wait().unwrap();
    pid
}

#[test]
fn temporary_files_of_a_killed_run_are_removed_by_the_next_write() {
    let dir = temp_dir();
    let g = grid(dir.path());
    let out = dir.path().join("out.csv");
    std::fs::write(&out, "old result\n").unwrap();
    // What a run killed while writing out.csv leaves: its temporary file, named after it.
    let dead = dead_pid();
    let stale = dir.path().join(format!(".out.csv.karkas-tmp-{dead}-0"));
    std::fs::write(&stale, "u,v,x,y,z\n0,0,1,").unwrap();
    // One of a live process (this test) stays, and so does another destination's.
    let live = dir
        .path()
        .join(format!(".out.csv.karkas-tmp-{}-0", std::process::id()));
    std::fs::write(&live, "").unwrap();
    let other = dir.path().join(format!(".other.csv.karkas-tmp-{dead}-0"));
    std::fs::write(&other, "").unwrap();
    let o = karkas(&["surface", "ll", s(&g), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stale.exists(), "the stale temporary file is removed");
    assert!(live.exists() && other.exists());
    assert!(std::fs::read_to_string(&out)
        .unwrap()
        .starts_with("u,v,x,y,z\n"));
    // Nothing else is left beside the result.
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names.len(), 4, "{names:?}");
}

#[test]
fn a_killed_write_leaves_only_an_obviously_stale_file() {
    let dir = temp_dir();
    let g = grid(dir.path());
    let out = dir.path().join("big.csv");
    std::fs::write(&out, "old result\n").unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args([
            "surface",
            "ll",
            s(&g),
            "-o",
            s(&out),
            "--samples",
            "3000,3000",
        ])
        .env_remove("KARKAS_MAX_MEMORY")
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // Wait until the temporary file exists (or the run is over), then kill -9.
    let temp = loop {
        let found = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .find(|n| n.starts_with(".big.csv.karkas-tmp-"));
        if found.is_some() || child.try_wait().unwrap().is_some() {
            break found;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    };
    child.kill().unwrap();
    child.wait().unwrap();
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "old result\n",
        "untouched"
    );
    if let Some(name) = temp {
        // Named after its destination and its (now dead) writer; the next write removes it.
        assert!(
            name.contains(&format!("karkas-tmp-{}-", child.id())),
            "{name}"
        );
        let o = karkas(&["surface", "ll", s(&g), "-o", s(&out)]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(!dir.path().join(&name).exists());
    }
}

#[test]
fn a_binary_format_is_refused_on_a_terminal() {
    let dir = temp_dir();
    let p = points(dir.path());
    // Standard output a pseudo-terminal, as in an interactive shell.
    let script = "import os, pty, subprocess, sys\n\
                  m, t = pty.openpty()\n\
                  r = subprocess.run(sys.argv[1:], stdout=t, stderr=subprocess.PIPE)\n\
                  os.close(t)\n\
                  sys.stderr.write(r.stderr.decode())\n\
                  print(r.returncode)\n";
    let run = |format: &str| {
        let o = Command::new("python3")
            .arg("-c")
            .arg(script)
            .arg(env!("CARGO_BIN_EXE_karkas"))
            .args(["curve", "ll", s(&p), "-o", "-", "--format", format])
            .env_remove("KARKAS_MAX_MEMORY")
            .output()
            .expect("python3 runs");
        (stdout(&o).trim().to_owned(), stderr(&o))
    };
    let (code, err) = run("png");
    assert_eq!(code, "2");
    assert_eq!(
        err,
        "karkas: error: <stdout>: png is binary and standard output is a terminal (redirect it \
         to a file or a pipe)\n"
    );
    // Text goes to the terminal.
    let (code, err) = run("csv");
    assert_eq!(code, "0", "{err}");
}
