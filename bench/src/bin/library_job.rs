//! The library's side of `bench/cli.py`: the same job as `karkas curve ll` / `karkas surface
//! ll`, done with the library alone, so that the command line's cost can be quoted as a ratio.
//!
//! `library_job curve POINTS.csv SAMPLES REPEATS` builds the LL curve (order 3, open) of the
//! points and samples it uniformly into memory; `library_job surface GRID.csv NU NV REPEATS`
//! builds the LL surface of the grid and samples an `NU x NV` grid. The input is read (with a
//! plain split, not timed) before the clock starts; each repeat is timed from the build to the
//! samples in memory, and the times are printed in seconds as one JSON line.

use karkas::ll::{LlCurve, LlSurface};
use karkas::{Curve, Grid, Point3, Surface};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let number = |k: usize| -> usize { args[k].parse().expect("a count") };
    let times = match args.get(1).map(String::as_str) {
        Some("curve") => curve_job(&read_rows(&args[2], 0), number(3), number(4)),
        Some("surface") => surface_job(&read_rows(&args[2], 2), (number(3), number(4)), number(5)),
        _ => {
            panic!("usage: library_job curve POINTS.csv N REPEATS | surface GRID.csv NU NV REPEATS")
        }
    };
    let list: Vec<String> = times.iter().map(|t| format!("{t:.6}")).collect();
    println!("{{\"seconds\": [{}]}}", list.join(", "));
}

/// The numeric rows of a CSV file with a header, from column `skip` on (three values each),
/// and the leading integer columns.
fn read_rows(path: &str, skip: usize) -> Vec<(Vec<usize>, Point3)> {
    let text = std::fs::read_to_string(path).expect("the input file");
    text.lines()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            let index = fields[..skip].iter().map(|f| f.parse().unwrap()).collect();
            let v: Vec<f64> = fields[skip..].iter().map(|f| f.parse().unwrap()).collect();
            (index, Point3::new([v[0], v[1], v[2]]))
        })
        .collect()
}

/// Times `repeats` runs of: the LL curve of the points, `n` samples into memory.
fn curve_job(rows: &[(Vec<usize>, Point3)], n: usize, repeats: usize) -> Vec<f64> {
    let points: Vec<Point3> = rows.iter().map(|r| r.1).collect();
    (0..repeats)
        .map(|_| {
            let start = Instant::now();
            let curve = LlCurve::new(&points, 3, false).expect("an LL curve");
            let (mut ts, mut out) = (vec![0.0; n], vec![Point3::ZERO; n]);
            curve.sample_into(&mut ts, &mut out);
            std::hint::black_box((&ts, &out));
            start.elapsed().as_secs_f64()
        })
        .collect()
}

/// Times `repeats` runs of: the LL surface of the grid, `nu x nv` samples into memory.
fn surface_job(
    rows: &[(Vec<usize>, Point3)],
    (nu, nv): (usize, usize),
    repeats: usize,
) -> Vec<f64> {
    let rows_n = rows.iter().map(|r| r.0[0]).max().unwrap() + 1;
    let cols_n = rows.iter().map(|r| r.0[1]).max().unwrap() + 1;
    let mut points = vec![Point3::ZERO; rows_n * cols_n];
    for (index, p) in rows {
        points[index[0] * cols_n + index[1]] = *p;
    }
    let grid = Grid::from_row_major(rows_n, cols_n, points).expect("a grid");
    (0..repeats)
        .map(|_| {
            let start = Instant::now();
            let surface = LlSurface::new(&grid, 3, false, false).expect("an LL surface");
            let (mut us, mut vs) = (vec![0.0; nu], vec![0.0; nv]);
            let mut out = vec![Point3::ZERO; nu * nv];
            surface.sample_grid_into(&mut us, &mut vs, &mut out);
            std::hint::black_box((&us, &vs, &out));
            start.elapsed().as_secs_f64()
        })
        .collect()
}
