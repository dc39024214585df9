//! Helpers shared by the CLI contract tests of `section` and `vary`.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the karkas binary.
pub fn karkas(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args(args)
        .output()
        .expect("the karkas binary runs")
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

/// Runs a failing command: exit code 2, one line naming `needle`, and `out` untouched
/// (`before`: its content, or `None` when it must not exist).
pub fn assert_rejected(args: &[&str], needle: &str, out: &Path, before: Option<&str>) {
    let o = karkas(args);
    assert_eq!(o.status.code(), Some(2), "args {args:?}: {}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "one line expected: {err}"
    );
    assert!(err.contains(needle), "'{needle}' not in: {err}");
    match before {
        Some(content) => assert_eq!(std::fs::read_to_string(out).unwrap(), content),
        None => assert!(!out.exists(), "{} was created", out.display()),
    }
}
