//! What every test of the command line uses: running the binary, temporary folders, writing
//! inputs, reading the CSV and OBJ files the CLI writes, a small CAD model, and the check of a
//! refused command.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The karkas binary, with no memory cap from the caller's environment.
fn command() -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_karkas"));
    command.env_remove("KARKAS_MAX_MEMORY");
    command
}

/// Runs the karkas binary.
pub fn karkas(args: &[&str]) -> Output {
    command()
        .args(args)
        .output()
        .expect("the karkas binary runs")
}

/// Runs the karkas binary in the folder `dir`.
pub fn karkas_in(dir: &Path, args: &[&str]) -> Output {
    command()
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the karkas binary runs")
}

/// A fresh temporary folder, removed when dropped.
pub fn temp_dir() -> tempfile::TempDir {
    tempfile::tempdir().expect("a temporary folder")
}

/// Writes `text` to `dir/name`.
pub fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The path as a string argument.
pub fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Standard output as text.
pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Standard error as text.
pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Header fields and rows of numbers of a CSV file the CLI wrote.
pub fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_owned)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    (header, rows)
}

/// A grid CSV (`i,j,x,y,z`) of `f(i, j)`.
pub fn grid_csv(rows: usize, cols: usize, f: impl Fn(usize, usize) -> [f64; 3]) -> String {
    let mut text = String::from("i,j,x,y,z\n");
    for i in 0..rows {
        for j in 0..cols {
            let p = f(i, j);
            text.push_str(&format!("{i},{j},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    text
}

/// What a refused command's message must contain: one text or several.
pub trait Needles {
    /// The texts.
    fn texts(&self) -> Vec<&str>;
}

impl Needles for &str {
    fn texts(&self) -> Vec<&str> {
        vec![self]
    }
}

impl Needles for &[&str] {
    fn texts(&self) -> Vec<&str> {
        self.to_vec()
    }
}

/// Runs a failing command: exit code 2, one line containing every needle, and `out` untouched
/// (`before`: its content, or `None` when it must not exist).
pub fn assert_rejected(args: &[&str], needles: impl Needles, out: &Path, before: Option<&str>) {
    let o = karkas(args);
    assert_eq!(o.status.code(), Some(2), "args {args:?}: {}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "one line expected: {err}"
    );
    for needle in needles.texts() {
        assert!(err.contains(needle), "'{needle}' not in: {err}");
    }
    match before {
        Some(content) => assert_eq!(std::fs::read_to_string(out).unwrap(), content),
        None => assert!(!out.exists(), "{} was created", out.display()),
    }
}

/// The square [x0, x0 + 3] x [y0, y0 + 3] at z = z0 as a bicubic surface written to `name`.
pub fn square_model(dir: &Path, name: &str, origin: [f64; 3]) -> PathBuf {
    let grid = write(
        dir,
        "square.csv",
        &grid_csv(4, 5, |i, j| {
            [origin[0] + i as f64, origin[1] + 0.75 * j as f64, origin[2]]
        }),
    );
    let out = dir.join(name);
    let o = karkas(&["surface", "bicubic", s(&grid), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    out
}

/// The positions and 0-based triangles of an OBJ file karkas wrote.
pub fn read_obj(path: &Path) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for line in text.lines() {
        let mut fields = line.split_whitespace();
        match fields.next() {
            Some("v") => {
                let v: Vec<f64> = fields.map(|f| f.parse().unwrap()).collect();
                positions.push([v[0], v[1], v[2]]);
            }
            Some("f") => {
                let k: Vec<usize> = fields
                    .map(|f| f.split('/').next().unwrap().parse::<usize>().unwrap() - 1)
                    .collect();
                triangles.push([k[0], k[1], k[2]]);
            }
            _ => {}
        }
    }
    (positions, triangles)
}
