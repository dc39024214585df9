//! Curve files as spreadsheets, scanners and other tools write them: `;` and tab separators,
//! decimal commas, quoted fields, units in the header, headers in other languages,
//! `--columns` and `--decimal-comma`, and the reader's one-line warnings (a first column that
//! counts the rows, points far out of order). Each file is written here in the shape of a
//! real one and read by `curve ll`; its output must equal, byte for byte, the output of the
//! same points in a plain `x,y` file.

use crate::common::{karkas_in, stderr, temp_dir, write};
use std::path::Path;

/// 61 points of a closed contour (an airfoil-like loop), to six decimals, as the writers of
/// the dialects print them.
fn points() -> Vec<(String, String)> {
    (0..61)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 60.0;
            let x = 0.5 + 0.5 * t.cos();
            let y = 0.12 * t.sin() * (1.0 - x).sqrt();
            (format!("{x:.6}"), format!("{y:.6}"))
        })
        .collect()
}

/// `text` with every decimal point made a comma.
fn comma(text: &str) -> String {
    text.replace('.', ",")
}

/// The rows of `points()` as `format(x, y)`, one a line, each ended by `end`.
fn rows(format: impl Fn(&str, &str) -> String, end: &str) -> String {
    points()
        .iter()
        .map(|(x, y)| format!("{}{end}", format(x, y)))
        .collect()
}

/// Runs `curve ll FILE -o out.csv` (with `extra` options) in `dir`; returns the output file's
/// bytes and standard error.
fn ll(dir: &Path, file: &str, extra: &[&str]) -> (Vec<u8>, String) {
    let out = format!("{file}.out.csv");
    let mut args = vec!["curve", "ll", file, "-o", &out];
    args.extend_from_slice(extra);
    let o = karkas_in(dir, &args);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{file}: {err}");
    (std::fs::read(dir.join(&out)).unwrap(), err)
}

/// The warning lines of standard error.
fn warnings(err: &str) -> Vec<&str> {
    err.lines().filter(|l| l.contains("warning")).collect()
}

#[test]
fn every_dialect_reads_the_same_points() {
    let dir = temp_dir();
    let plain = rows(|x, y| format!("{x},{y}"), "\n");
    write(dir.path(), "plain.csv", &format!("x,y\n{plain}"));
    let (expected, _) = ll(dir.path(), "plain.csv", &[]);
    let cases: Vec<(&str, String, Vec<&str>)> = vec![
        // Excel in a locale with decimal commas: a byte-order mark, CRLF, ';', units.
        (
            "excel-de.csv",
            format!(
                "\u{feff}X [mm];Y [mm]\r\n{}",
                rows(|x, y| format!("{};{}", comma(x), comma(y)), "\r\n")
            ),
            vec![],
        ),
        // LibreOffice, tab-separated, decimal commas, no header.
        (
            "calc.txt",
            rows(|x, y| format!("{}\t{}", comma(x), comma(y)), "\n"),
            vec![],
        ),
        // Excel's quoted CSV.
        (
            "quoted.csv",
            format!(
                "\"x\",\"y\"\n{}",
                rows(|x, y| format!("\"{x}\",\"{y}\""), "\n")
            ),
            vec![],
        ),
        // Units in brackets and parentheses.
        ("units.csv", format!("x [mm],y (mm)\n{plain}"), vec![]),
        // Quoted fields with decimal commas, separated by commas: --decimal-comma.
        (
            "quoted-commas.csv",
            rows(|x, y| format!("\"{}\",\"{}\"", comma(x), comma(y)), "\n"),
            vec!["--decimal-comma"],
        ),
        // Spaces between decimal-comma numbers, with --decimal-comma too.
        (
            "spaced.txt",
            rows(|x, y| format!("  {}   {}", comma(x), comma(y)), "\n"),
            vec!["--decimal-comma"],
        ),
        // A header in another language and a row number: the columns by name...
        (
            "ru.csv",
            format!(
                "№;Абсцисса;Ордината\n{}",
                points()
                    .iter()
                    .enumerate()
                    .map(|(k, (x, y))| format!("{};{};{}\n", k + 1, comma(x), comma(y)))
                    .collect::<String>()
            ),
            vec!["--columns", "Абсцисса,Ордината"],
        ),
        // ... or by position.
        (
            "numbered.csv",
            points()
                .iter()
                .enumerate()
                .map(|(k, (x, y))| format!("{k},{x},{y}\n"))
                .collect(),
            vec!["--columns", "2,3"],
        ),
    ];
    for (name, text, options) in cases {
        write(dir.path(), name, &text);
        let (got, err) = ll(dir.path(), name, &options);
        assert!(got == expected, "{name}: another curve was read ({err})");
        assert!(warnings(&err).is_empty(), "{name}: {err}");
    }
}

#[test]
fn a_header_that_names_no_x_and_y_is_read_in_order_with_a_warning() {
    let dir = temp_dir();
    let plain = rows(|x, y| format!("{x},{y}"), "\n");
    write(dir.path(), "plain.csv", &format!("x,y\n{plain}"));
    let (expected, _) = ll(dir.path(), "plain.csv", &[]);
    write(dir.path(), "ru.csv", &format!("Абсцисса,Ордината\n{plain}"));
    let (got, err) = ll(dir.path(), "ru.csv", &[]);
    assert!(got == expected);
    let w = warnings(&err);
    assert_eq!(w.len(), 1, "{err}");
    assert!(
        w[0].starts_with(
            "karkas: warning: ru.csv: the header 'Абсцисса,Ордината' names no x and y"
        ) && w[0].contains("--columns"),
        "{err}"
    );
    // Four columns named otherwise: refused, naming --columns.
    write(
        dir.path(),
        "four.csv",
        "a,b,c,d\n0,0,0,0\n1,1,1,1\n2,0,1,0\n",
    );
    let o = karkas_in(dir.path(), &["curve", "ll", "four.csv", "-o", "f.csv"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert!(
        err.starts_with("karkas: error: four.csv:1: the header 'a,b,c,d' names no 'x' and 'y'")
            && err.contains("--columns"),
        "{err}"
    );
}

#[test]
fn a_counting_first_column_and_shuffled_points_each_get_one_warning_line() {
    let dir = temp_dir();
    // A headerless index,x,y file, as a scanner's export numbers its rows.
    let indexed: String = points()
        .iter()
        .enumerate()
        .map(|(k, (x, y))| format!("{k},{x},{y}\n"))
        .collect();
    write(dir.path(), "indexed.csv", &indexed);
    let (_, err) = ll(dir.path(), "indexed.csv", &[]);
    let w = warnings(&err);
    assert_eq!(w.len(), 1, "{err}");
    assert!(
        w[0].starts_with(
            "karkas: warning: indexed.csv: the first column counts 0, 1, 2, ... (row numbers?)"
        ) && w[0].contains("--columns 2,3"),
        "{err}"
    );
    // The points in a shuffled order (a fixed permutation: k -> 37 k mod 61).
    let all = points();
    let shuffled: String = (0..61)
        .map(|k| {
            let (x, y) = &all[(37 * k) % 61];
            format!("{x},{y}\n")
        })
        .collect();
    write(dir.path(), "shuffled.csv", &format!("x,y\n{shuffled}"));
    let (_, err) = ll(dir.path(), "shuffled.csv", &[]);
    let w = warnings(&err);
    assert_eq!(w.len(), 1, "{err}");
    assert!(
        w[0].starts_with("karkas: warning: shuffled.csv: the points look far out of order"),
        "{err}"
    );
    // The same points in order: nothing to say.
    let ordered = rows(|x, y| format!("{x},{y}"), "\n");
    write(dir.path(), "ordered.csv", &format!("x,y\n{ordered}"));
    let (_, err) = ll(dir.path(), "ordered.csv", &[]);
    assert!(warnings(&err).is_empty(), "{err}");
}

#[test]
fn no_points_names_what_was_seen() {
    let dir = temp_dir();
    let cases = [
        (
            "empty.csv",
            "",
            "empty.csv: no points found: the input is empty",
        ),
        (
            "comments.csv",
            "# a comment\n\n",
            "comments.csv: no points found: its 2 lines are blank or comments ('#')",
        ),
        (
            "header.csv",
            "x;y\n",
            "header.csv: no points found: the header 'x;y' (line 1) and no data rows after it",
        ),
        (
            "words.csv",
            "x,y\nsee the attached drawing\n",
            "words.csv: no points found: after the header 'x,y' (line 1), line 2 ('see the \
             attached drawing') is not a row of 2 numbers separated by commas, and the data end \
             there",
        ),
    ];
    for (name, text, message) in cases {
        write(dir.path(), name, text);
        let o = karkas_in(dir.path(), &["curve", "ll", name, "-o", "o.csv"]);
        assert_eq!(o.status.code(), Some(2), "{name}");
        assert_eq!(stderr(&o), format!("karkas: error: {message}\n"));
    }
}

#[test]
fn bad_column_choices_are_refused_naming_the_option() {
    let dir = temp_dir();
    write(dir.path(), "p.csv", "x,y\n0,0\n1,1\n2,0\n");
    let cases: [(&[&str], &str); 4] = [
        (&["--columns", "1"], "expected two or three columns A,B[,C]"),
        (
            &["--columns", "1,4"],
            "--columns: column 4 is not there: the rows have 2 fields",
        ),
        (
            &["--columns", "x,q"],
            "--columns: the header has no column 'q'",
        ),
        (&["--columns", "0,1"], "positions count from 1"),
    ];
    for (options, needle) in cases {
        let mut args = vec!["curve", "ll", "p.csv", "-o", "o.csv"];
        args.extend_from_slice(options);
        let o = karkas_in(dir.path(), &args);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{options:?}: {err}");
        assert!(err.contains(needle), "{options:?}: {err}");
        assert!(!dir.path().join("o.csv").exists());
    }
}

#[test]
fn grids_in_other_dialects_read_as_plain_ones() {
    let dir = temp_dir();
    let cell = |i: usize, j: usize| {
        let (x, y) = (i as f64 * 0.25, j as f64 * 0.5);
        (x, y, (x * y).sin())
    };
    let mut plain = String::from("i,j,x,y,z\n");
    let mut semi = String::from("\u{feff}\"i\";\"j\";\"x [m]\";\"y [m]\";\"z [m]\"\r\n");
    for i in 0..5 {
        for j in 0..4 {
            let (x, y, z) = cell(i, j);
            plain.push_str(&format!("{i},{j},{x:.6},{y:.6},{z:.6}\n"));
            semi.push_str(&comma(&format!("{i};{j};{x:.6};{y:.6};{z:.6}\r\n")));
        }
    }
    write(dir.path(), "plain.csv", &plain);
    write(dir.path(), "semi.csv", &semi);
    let run = |name: &str| {
        let out = format!("{name}.out.csv");
        let o = karkas_in(dir.path(), &["surface", "bicubic", name, "-o", &out]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
        std::fs::read(dir.path().join(out)).unwrap()
    };
    assert!(run("semi.csv") == run("plain.csv"));
}
