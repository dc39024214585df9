//! Inputs as they come: airfoil files as found, standard input (`-`), pipes, process
//! substitution and FIFOs read in one pass, and hostile input (binary data, endless streams,
//! huge lines, bad encodings) refused with exit 2 and one short line naming the file and line.

use crate::common::{grid_csv, karkas_in, stderr, temp_dir, write};
use std::path::Path;
use std::process::{Command, Output};

/// Runs `script` with bash in `dir`, `$K` being the karkas binary (no memory cap from the
/// caller's environment).
fn shell(dir: &Path, script: &str) -> Output {
    Command::new("bash")
        .arg("-c")
        .arg(script)
        .current_dir(dir)
        .env("K", env!("CARGO_BIN_EXE_karkas"))
        .env_remove("KARKAS_MAX_MEMORY")
        .output()
        .expect("bash runs")
}

/// Checks a refused run: exit 2, one line starting with `karkas: error: ` + `start`, at most
/// `max_chars` characters (nothing long echoed), and no `out` in `dir`.
fn refused(o: &Output, start: &str, dir: &Path, out: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "one line expected: {err}"
    );
    let expected = format!("karkas: error: {start}");
    assert!(
        err.starts_with(&expected),
        "'{expected}' does not start: {err}"
    );
    assert!(err.len() < 300, "too long ({} bytes): {err}", err.len());
    assert!(!dir.join(out).exists(), "{out} was written");
}

/// A made-up five-point contour in Selig order.
const PAIRS: &str = "1 0\n0.5 0.05\n0 0\n0.5 -0.05\n1 0\n";

/// Points of a quarter circle, `x,y` with a header.
fn arc_csv() -> String {
    let mut text = String::from("x,y\n");
    for k in 0..12 {
        let t = f64::from(k) * 0.13;
        text.push_str(&format!("{},{}\n", t.cos(), t.sin()));
    }
    text
}

#[test]
fn airfoils_as_found_are_read() {
    let dir = temp_dir();
    let cases = [
        ("notes.dat", format!("MY FOIL\n{PAIRS}\nsource: http://x\n")),
        (
            "table.dat",
            format!("FOIL\n{PAIRS}Thickness: 7.99%\n alpha CL CD\n 0 0.25 0.006\nZZ\n"),
        ),
        ("comma.dat", format!("NACA 63,3-418\n{PAIRS}")),
        ("comma.csv", format!("NACA 63,3-418\n{PAIRS}")),
        (
            "preamble.dat",
            format!("FOIL\nOrnithopter airfoil\n-2 3 -2 2\n{PAIRS}"),
        ),
    ];
    for (name, text) in cases {
        write(dir.path(), name, &text);
        let o = karkas_in(dir.path(), &["curve", "ll", name, "-o", "out.csv"]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
    }
    write(
        dir.path(),
        "hole.dat",
        "FOIL\n1 0\n0.5 0.05\n0.0 ......\n0 0\n",
    );
    let o = karkas_in(dir.path(), &["curve", "ll", "hole.dat", "-o", "h.csv"]);
    refused(
        &o,
        "hole.dat:4: '......' is not a number (column 2)",
        dir.path(),
        "h.csv",
    );
    write(
        dir.path(),
        "late.dat",
        &format!("FOIL\n{PAIRS}ZZ\n0.3 0.1\n"),
    );
    let o = karkas_in(dir.path(), &["curve", "ll", "late.dat", "-o", "l.csv"]);
    refused(
        &o,
        "late.dat:8: a point after the notes that begin on line 7 ('ZZ')",
        dir.path(),
        "l.csv",
    );
}

#[test]
fn pipes_fifos_and_standard_input_are_read_once() {
    let dir = temp_dir();
    let d = dir.path();
    write(d, "pts.csv", &arc_csv());
    write(d, "b.csv", "x,y,z\n0,0,0\n1,0,0\n0,1,0\n");
    write(
        d,
        "g.csv",
        &grid_csv(4, 4, |i, j| [i as f64, j as f64, (i * j) as f64 * 0.1]),
    );
    let scripts = [
        "cat pts.csv | $K curve ll - -o o1.csv",
        "$K curve ll <(cat pts.csv) -o o2.csv",
        "$K curve fit --tolerance 0.1 - -o o3.csv < pts.csv",
        "mkfifo f && { cat pts.csv > f & } && $K curve dps --order 2 --n 4 f -o o4.csv",
        "cat g.csv | $K surface ll - -o o5.csv",
        "cat g.csv | $K convert - o6.obj",
        "cat b.csv | $K hausdorff - b.csv",
        "printf 'i,j\\n0,0\\n' | $K vary g.csv --coord z --rows 1,1,1,1 --cols 1,1,1,1 --fixed - -o o7.csv",
        // Meshes on standard input are told by their content: binary STL, OBJ, PLY.
        "$K surface ll g.csv --samples 5,6 -o m.stl && $K convert - o8.obj < m.stl",
        "$K convert - o9.ply < o8.obj",
        "cat o9.ply | $K convert - o10.stl",
    ];
    for script in scripts {
        let o = shell(d, script);
        assert_eq!(o.status.code(), Some(0), "{script}: {}", stderr(&o));
    }
    for out in [
        "o1.csv", "o2.csv", "o3.csv", "o4.csv", "o5.csv", "o6.obj", "o7.csv", "o8.obj", "o9.ply",
        "o10.stl",
    ] {
        assert!(d.join(out).exists(), "{out}");
    }
    // The mesh read from standard input is the 5 x 6 samples (STL corners merged again).
    let obj = std::fs::read_to_string(d.join("o8.obj")).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), 30);
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 40);
    // Standard input is named <stdin> in messages.
    let o = shell(
        d,
        "printf 'x,y\\n0,0\\n1,abc\\n' | $K curve ll - -o bad.csv",
    );
    refused(
        &o,
        "<stdin>:3: 'abc' is not a number (column 2)",
        d,
        "bad.csv",
    );
}

#[test]
fn standard_input_is_one_input_at_most() {
    let dir = temp_dir();
    let d = dir.path();
    let o = shell(d, "$K hausdorff - - < /dev/null");
    refused(&o, "A and B both name standard input ('-')", d, "none");
    let o = shell(
        d,
        "$K surface coons --kind bilinear --u-curves - --v-curves - -o c.csv < /dev/null",
    );
    refused(
        &o,
        "--u-curves and --v-curves both name standard input",
        d,
        "c.csv",
    );
    let o = shell(
        d,
        "$K surface dps-tube --n1 4 --n2 4 --along - --across - -o t.csv < /dev/null",
    );
    refused(
        &o,
        "--along and --across both name standard input",
        d,
        "t.csv",
    );
}

#[test]
fn hostile_input_is_refused_naming_the_file_and_line() {
    let dir = temp_dir();
    let d = dir.path();
    let o = shell(d, "$K curve ll /dev/zero -o z.csv");
    refused(&o, "/dev/zero:1: binary data (a NUL byte)", d, "z.csv");
    // Random bytes hold a newline before their first NUL or invalid byte now and then: the
    // line named is whichever holds the first bad byte.
    let o = shell(d, "$K curve ll /dev/urandom -o r.csv");
    refused(&o, "/dev/urandom:", d, "r.csv");
    let after = stderr(&o)["karkas: error: /dev/urandom:".len()..].to_string();
    let digits = after.chars().take_while(char::is_ascii_digit).count();
    assert!(digits > 0 && after[digits..].starts_with(": "), "{after}");
    let o = shell(d, "$K surface ll /dev/zero -o s.csv");
    refused(&o, "/dev/zero:1: binary data (a NUL byte)", d, "s.csv");
    let o = shell(
        d,
        "head -c 3000000 /dev/zero | tr '\\0' 7 | $K curve ll - -o l.csv",
    );
    refused(&o, "<stdin>:1: line longer than 1 MiB", d, "l.csv");
    let o = shell(d, "printf 'x,y\\n1,2\\n3,4\\0\\n' | $K curve ll - -o n.csv");
    refused(&o, "<stdin>:3: binary data (a NUL byte)", d, "n.csv");
    let o = shell(
        d,
        "printf 'x,y\\n1,2\\n3,\\xff\\n' > u.csv && $K curve ll u.csv -o u2.csv",
    );
    refused(&o, "u.csv:3: not UTF-8 text", d, "u2.csv");
    let o = shell(
        d,
        "printf 'x,y\\n1,2\\n3,%s\\n' $(head -c 5000 /dev/zero | tr '\\0' a) | $K curve ll - -o q.csv",
    );
    refused(&o, "<stdin>:3: 'aaaa", d, "q.csv");
}

#[test]
fn endless_streams_stop_at_the_memory_cap() {
    let dir = temp_dir();
    let d = dir.path();
    let cap = "the input needs more than the memory cap of 16777216 bytes";
    for (script, out) in [
        ("yes 1,2 | $K --max-memory 16M curve ll - -o y.csv", "y.csv"),
        (
            "yes '# c' | $K --max-memory 16M curve ll - -o c.csv",
            "c.csv",
        ),
        (
            "(echo FOIL; echo 1 0; yes ZZ) | $K --max-memory 16M curve ll - -o z.csv",
            "z.csv",
        ),
        (
            "yes 1,2,3 | $K --max-memory 16M hausdorff - --expr 'x'",
            "none",
        ),
    ] {
        let o = shell(d, script);
        refused(&o, "<stdin>:", d, out);
        assert!(stderr(&o).contains(cap), "{script}: {}", stderr(&o));
    }
    let o = shell(
        d,
        "(echo i,j,x,y,z; yes 0,0,1,2,3) | $K --max-memory 16M surface ll - -o g.csv",
    );
    refused(&o, "<stdin>", d, "g.csv");
    assert!(stderr(&o).contains(cap), "{}", stderr(&o));
}
