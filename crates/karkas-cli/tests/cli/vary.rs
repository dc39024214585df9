//! The CLI contract of `karkas vary` (docs/reference/contract.md): the varied grid meets the sums,
//! keeps the mask's cells and the other coordinates, and bad input exits 2 with no output.

use crate::common::{assert_rejected, grid_csv, karkas, read_csv, s, stderr, temp_dir, write};
/// A 3 x 4 grid with z = i * j + 1.
fn grid(dir: &std::path::Path) -> std::path::PathBuf {
    let text = grid_csv(3, 4, |i, j| [i as f64, j as f64, (i * j + 1) as f64]);
    write(dir, "g.csv", &text)
}

#[test]
fn varied_grid_meets_the_sums_and_keeps_fixed_cells() {
    let dir = temp_dir();
    let input = grid(dir.path());
    let mask = write(dir.path(), "mask.csv", "i,j\n0,0\n2,3 # a corner\n");
    let out = dir.path().join("v.csv");
    // Rows 0 and 1 given, the last from --total; columns all given.
    let o = karkas(&[
        "vary",
        s(&input),
        "--coord",
        "z",
        "--rows",
        "5,9.5",
        "--cols",
        "4,6,8,6.5",
        "--total",
        "24.5",
        "--fixed",
        s(&mask),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["i", "j", "x", "y", "z"]);
    assert_eq!(rows.len(), 12);
    let z = |i: usize, j: usize| rows[i * 4 + j][4];
    let row_sum = |i: usize| (0..4).map(|j| z(i, j)).sum::<f64>();
    let col_sum = |j: usize| (0..3).map(|i| z(i, j)).sum::<f64>();
    for (i, want) in [5.0, 9.5, 10.0].into_iter().enumerate() {
        assert!((row_sum(i) - want).abs() < 1e-12, "row {i}");
    }
    for (j, want) in [4.0, 6.0, 8.0, 6.5].into_iter().enumerate() {
        assert!((col_sum(j) - want).abs() < 1e-12, "column {j}");
    }
    assert_eq!((z(0, 0), z(2, 3)), (1.0, 7.0));
    for (k, r) in rows.iter().enumerate() {
        assert_eq!(
            r[..4],
            [
                (k / 4) as f64,
                (k % 4) as f64,
                (k / 4) as f64,
                (k % 4) as f64
            ]
        );
    }
}

#[test]
fn unchanged_sums_give_the_same_grid() {
    let dir = temp_dir();
    let input = grid(dir.path());
    let out = dir.path().join("same.csv");
    // z rows: 4, 10, 16; columns: 3, 6, 9, 12.
    let o = karkas(&[
        "vary",
        s(&input),
        "--coord",
        "z",
        "--rows",
        "4,10,16",
        "--cols",
        "3,6,9,12",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(read_csv(&out), read_csv(&input));
}

#[test]
fn bad_vary_input_exits_2_and_writes_nothing() {
    let dir = temp_dir();
    let input = grid(dir.path());
    let out = dir.path().join("v.csv");
    let run = |extra: &[&str], needle: &str| {
        let mut args = vec!["vary", s(&input), "--coord", "z"];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["-o", s(&out)]);
        assert_rejected(&args, needle, &out, None);
    };
    run(
        &["--rows", "4,8", "--cols", "3,6,9,12"],
        "--rows: 2 sums given for 3 lines",
    );
    run(
        &["--rows", "4,8,12,1", "--cols", "3,6,9,12"],
        "--rows: the grid has 3 of them",
    );
    run(
        &["--rows", "4,10,16", "--cols", "3,6,9,12", "--total", "31"],
        "--rows: the 3 sums add up to 30, not to --total 31",
    );
    run(
        &["--rows", "4,10,17", "--cols", "3,6,9,12"],
        "g.csv: inconsistent sums: the row sums add up to 31 and the column sums to 30",
    );
    run(
        &["--rows", "4,10,16", "--cols", "3,6,9,12", "--penalty", "0"],
        "--penalty",
    );
    run(&["--cols", "3,6,9,12"], "--rows");
    let full_row = write(dir.path(), "row.csv", "i,j\n1,0\n1,1\n1,2\n1,3\n");
    run(
        &[
            "--rows",
            "4,11,15",
            "--cols",
            "3,6,9,12",
            "--fixed",
            s(&full_row),
        ],
        "g.csv: row 1 has every entry fixed: its sum 10 cannot become 11",
    );
    let outside = write(dir.path(), "outside.csv", "i,j\n0,0\n3,0\n");
    run(
        &[
            "--rows",
            "4,10,16",
            "--cols",
            "3,6,9,12",
            "--fixed",
            s(&outside),
        ],
        "outside.csv:3: i = 3 is outside the grid (i < 3)",
    );
    let png = dir.path().join("v.png");
    assert_rejected(
        &[
            "vary",
            s(&input),
            "--coord",
            "z",
            "--rows",
            "4,10,16",
            "--cols",
            "3,6,9,12",
            "-o",
            s(&png),
        ],
        "unknown output extension (use one of: .csv)",
        &png,
        None,
    );
}
