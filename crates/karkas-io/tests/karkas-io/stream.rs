//! Samples written as they are sampled (`export::stream`): the same bytes as the writers of
//! samples held in memory, and `.npy` arrays read back by an independent reader of the format.

use std::path::Path;

use karkas::ll::{LlCurve, LlSurface};
use karkas::{Grid, Point, Point2, Point3};
use karkas_io::export::samples::{sample_curve, sample_surface};
use karkas_io::export::stream::{write_curve_samples, write_surface_samples, BLOCK};
use karkas_io::write::{write_curve_csv, write_surface_csv};
use karkas_io::OutputFormat;

use crate::util::scratch;

fn helix(n: usize) -> Vec<Point3> {
    (0..n)
        .map(|k| {
            let s = 0.37 * k as f64;
            Point3::new([s.cos() * 1e3, s.sin() * 1e-4, -0.2 * s])
        })
        .collect()
}

fn wave_grid(rows: usize, cols: usize) -> Grid<Point3> {
    let points = (0..rows * cols)
        .map(|k| {
            let (i, j) = ((k / cols) as f64, (k % cols) as f64);
            Point3::new([i, j, (0.3 * i).sin() * (0.2 * j).cos()])
        })
        .collect();
    Grid::from_row_major(rows, cols, points).unwrap()
}

/// The array of an `.npy` file: its shape and values, read by the format's definition (magic,
/// version 1.0, a `u16` header length, the header dict, `<f8` values in C order).
fn read_npy(path: &Path) -> (Vec<usize>, Vec<f64>) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[..8], b"\x93NUMPY\x01\x00");
    let len = u16::from_le_bytes([bytes[8], bytes[9]]) as usize;
    assert_eq!((10 + len) % 16, 0, "data aligned");
    let dict = std::str::from_utf8(&bytes[10..10 + len]).unwrap();
    assert!(dict.contains("'descr': '<f8'"), "{dict}");
    assert!(dict.contains("'fortran_order': False"), "{dict}");
    let shape = dict.split("'shape': (").nth(1).unwrap();
    let shape: Vec<usize> = shape[..shape.find(')').unwrap()]
        .split(',')
        .filter(|s| !s.trim().is_empty())
        .map(|s| s.trim().parse().unwrap())
        .collect();
    let values: Vec<f64> = bytes[10 + len..]
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect();
    assert_eq!(values.len(), shape.iter().product::<usize>());
    (shape, values)
}

#[test]
fn streamed_curve_csv_is_the_held_one() {
    let curve = LlCurve::new(&helix(300), 3, false).unwrap();
    let (_dir, streamed) = scratch("streamed.csv");
    let held = streamed.with_file_name("held.csv");
    for n in [1, 2, 1000, 2 * BLOCK + 7] {
        write_curve_samples(&curve, n, OutputFormat::Csv, &streamed).unwrap();
        let (ts, points) = sample_curve(&curve, n);
        write_curve_csv(&held, &ts, &points).unwrap();
        let (a, b) = (
            std::fs::read(&streamed).unwrap(),
            std::fs::read(&held).unwrap(),
        );
        assert!(a == b, "{n} samples");
    }
    // A planar curve: header t,x,y.
    let planar: Vec<Point2> = helix(50).iter().map(|p| Point([p[0], p[1]])).collect();
    let curve = LlCurve::new(&planar, 2, true).unwrap();
    write_curve_samples(&curve, 777, OutputFormat::Csv, &streamed).unwrap();
    let (ts, points) = sample_curve(&curve, 777);
    write_curve_csv(&held, &ts, &points).unwrap();
    let text = std::fs::read_to_string(&streamed).unwrap();
    assert!(text.starts_with("t,x,y\n"));
    assert_eq!(text, std::fs::read_to_string(&held).unwrap());
}

#[test]
fn streamed_surface_csv_is_the_held_one() {
    let surface = LlSurface::new(&wave_grid(12, 9), 3, false, false).unwrap();
    let (_dir, streamed) = scratch("streamed.csv");
    let held = streamed.with_file_name("held.csv");
    // 1000 samples a row: 65 rows a block, the last block short.
    for (nu, nv) in [(1, 1), (3, 2), (140, 1000), (2, BLOCK + 3)] {
        write_surface_samples(&surface, (nu, nv), OutputFormat::Csv, &streamed).unwrap();
        let (us, vs, points) = sample_surface(&surface, nu, nv);
        write_surface_csv(&held, &us, &vs, &points).unwrap();
        let (a, b) = (
            std::fs::read(&streamed).unwrap(),
            std::fs::read(&held).unwrap(),
        );
        assert!(a == b, "{nu} x {nv} samples");
    }
}

#[test]
fn npy_arrays_hold_the_samples_csv_values() {
    let curve = LlCurve::new(&helix(200), 3, false).unwrap();
    let (_dir, npy) = scratch("c.npy");
    let csv = npy.with_file_name("c.csv");
    let n = BLOCK + 11;
    write_curve_samples(&curve, n, OutputFormat::Npy, &npy).unwrap();
    write_curve_samples(&curve, n, OutputFormat::Csv, &csv).unwrap();
    let (shape, values) = read_npy(&npy);
    assert_eq!(shape, [n, 3]);
    // The CSV's x,y,z read back, bit for bit.
    let text = std::fs::read_to_string(&csv).unwrap();
    let from_csv: Vec<f64> = text
        .lines()
        .skip(1)
        .flat_map(|l| l.split(',').skip(1).map(|f| f.parse::<f64>().unwrap()))
        .collect();
    assert_eq!(from_csv.len(), values.len());
    assert!(from_csv
        .iter()
        .zip(&values)
        .all(|(a, b)| a.to_bits() == b.to_bits()));

    let surface = LlSurface::new(&wave_grid(7, 8), 2, false, true).unwrap();
    let npy = npy.with_file_name("s.npy");
    write_surface_samples(&surface, (90, 800), OutputFormat::Npy, &npy).unwrap();
    let (shape, values) = read_npy(&npy);
    assert_eq!(shape, [90, 800, 3]);
    let (_, _, points) = sample_surface(&surface, 90, 800);
    let flat: Vec<f64> = points.iter().flat_map(|p| p.0).collect();
    assert!(flat
        .iter()
        .zip(&values)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
}

#[test]
fn other_formats_are_refused() {
    let curve = LlCurve::new(&helix(20), 3, false).unwrap();
    let (_dir, path) = scratch("c.svg");
    let e = write_curve_samples(&curve, 10, OutputFormat::Svg, &path).unwrap_err();
    assert!(e.to_string().contains("c.svg"), "{e}");
    assert!(!path.exists());
}
