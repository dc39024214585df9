//! `.npy` output of `curve ll` and `surface ll`: NumPy arrays of the samples' points, read
//! here by the format's definition and compared with the CSV the same command writes.

use crate::common::{grid_csv, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::Path;

/// The shape and values of an `.npy` file (version 1.0, `<f8`, C order), read by hand.
fn read_npy(path: &Path) -> (Vec<usize>, Vec<f64>) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00", "magic and version 1.0");
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    let dict = std::str::from_utf8(&bytes[10..10 + len]).unwrap();
    assert!(dict.starts_with("{'descr': '<f8', 'fortran_order': False, 'shape': ("));
    assert!(dict.ends_with('\n'));
    let shape = &dict[dict.find("'shape': (").unwrap() + 10..];
    let shape = shape[..shape.find(')').unwrap()]
        .split(',')
        .filter(|d| !d.trim().is_empty())
        .map(|d| d.trim().parse().unwrap())
        .collect();
    let values = bytes[10 + len..]
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect();
    (shape, values)
}

fn same_bits(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits())
}

#[test]
fn curve_ll_writes_the_csv_points_as_an_n_by_dim_array() {
    let dir = temp_dir();
    let mut text = String::from("x,y,z\n");
    for k in 0..40 {
        let t = 0.3 * k as f64;
        text.push_str(&format!("{},{},{}\n", t.cos(), t.sin(), 0.1 * t));
    }
    let points = write(dir.path(), "p.csv", &text);
    let (csv, npy) = (dir.path().join("c.csv"), dir.path().join("c.npy"));
    for out in [&csv, &npy] {
        let o = karkas(&[
            "curve",
            "ll",
            s(&points),
            "--samples",
            "70001",
            "-o",
            s(out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let (header, rows) = read_csv(&csv);
    assert_eq!(header, ["t", "x", "y", "z"]);
    let (shape, values) = read_npy(&npy);
    assert_eq!(shape, [70001, 3]);
    let from_csv: Vec<f64> = rows.iter().flat_map(|r| r[1..].to_vec()).collect();
    assert!(same_bits(&from_csv, &values));
}

#[test]
fn surface_ll_writes_the_csv_points_as_an_nu_by_nv_by_3_array() {
    let dir = temp_dir();
    let grid = grid_csv(6, 7, |i, j| {
        let (u, v) = (i as f64, j as f64);
        [u, v, (0.5 * u).sin() * (0.4 * v).cos()]
    });
    let grid = write(dir.path(), "g.csv", &grid);
    let (csv, npy) = (dir.path().join("s.csv"), dir.path().join("s.npy"));
    for out in [&csv, &npy] {
        let o = karkas(&[
            "surface",
            "ll",
            s(&grid),
            "--samples",
            "31,2500",
            "-o",
            s(out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let (header, rows) = read_csv(&csv);
    assert_eq!(header, ["u", "v", "x", "y", "z"]);
    let (shape, values) = read_npy(&npy);
    assert_eq!(shape, [31, 2500, 3]);
    let from_csv: Vec<f64> = rows.iter().flat_map(|r| r[2..].to_vec()).collect();
    assert!(same_bits(&from_csv, &values));
}

#[test]
fn npy_is_refused_where_it_is_not_written_and_on_a_terminal_only() {
    let dir = temp_dir();
    let points = write(dir.path(), "p.csv", "0,0\n1,1\n2,0\n3,1\n");
    let out = dir.path().join("c.npy");
    let o = karkas(&["curve", "spline", s(&points), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(!out.exists());
    // To a pipe: the bytes of the file.
    let o = karkas(&["curve", "ll", s(&points), "-o", "-", "--format", "npy"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(o.stdout.starts_with(b"\x93NUMPY\x01\x00"));
}
