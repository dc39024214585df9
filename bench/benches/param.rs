//! Parameterization and bicubic interpolation benchmarks (Kuznetsov and Filatov).
//!
//! Run: `cargo bench -p karkas-bench --bench param`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::param::{
    BicubicSurface, CubicSpline, CurveParameterization, GridParameterization, SplineEnds,
};
use karkas::{Curve, Grid, Point3, Surface};
use std::hint::black_box;

/// A wavy sheet of `n x n` points with uneven spacing.
fn sheet(n: usize) -> Grid<Point3> {
    Grid::from_fn(n, n, |i, j| {
        let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
        let x = x + 0.2 * x * x;
        Point3::new([
            x,
            y + 0.05 * (3.0 * x).sin(),
            (6.0 * x).sin() * (4.0 * y).cos(),
        ])
    })
}

fn bicubic(c: &mut Criterion) {
    let mut group = c.benchmark_group("bicubic_1000x1000");
    group.sample_size(10);
    let n = 1000;
    let grid = sheet(n);
    group.throughput(Throughput::Elements((n * n) as u64));
    group.bench_function(BenchmarkId::new("construct_chord", n * n), |b| {
        b.iter(|| {
            BicubicSurface::new(
                black_box(&grid),
                GridParameterization::default(),
                false,
                false,
            )
            .unwrap()
        })
    });
    let surface =
        BicubicSurface::new(&grid, GridParameterization::default(), false, false).unwrap();
    let m = 2000;
    let us: Vec<f64> = (0..m).map(|i| surface.domain_u().uniform(i, m)).collect();
    let vs: Vec<f64> = (0..m).map(|i| surface.domain_v().uniform(i, m)).collect();
    let mut out = vec![Point3::ZERO; m * m];
    group.throughput(Throughput::Elements((m * m) as u64));
    group.bench_function(BenchmarkId::new("eval_grid_2000x2000", m * m), |b| {
        b.iter(|| surface.eval_grid_into(black_box(&us), black_box(&vs), &mut out))
    });
    group.finish();
}

fn spline(c: &mut Criterion) {
    let mut group = c.benchmark_group("cubic_spline_not_a_knot_3d");
    group.sample_size(10);
    let n = 1_000_000;
    let points: Vec<Point3> = (0..n)
        .map(|i| {
            let s = i as f64 * 1e-3;
            Point3::new([s.cos() * (1.0 + 0.3 * (7.0 * s).sin()), s.sin(), 0.2 * s])
        })
        .collect();
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function(BenchmarkId::new("chord_length", n), |b| {
        b.iter(|| {
            CubicSpline::through(
                black_box(&points),
                CurveParameterization::ChordLength,
                SplineEnds::NotAKnot,
            )
            .unwrap()
        })
    });
    group.finish();
}

/// Batch evaluation of a cubic spline (values, first derivatives) at 10^6 sorted parameters
/// into a reused buffer: the kernel the Python package's `CubicSpline(t, out=...)` runs.
fn spline_eval(c: &mut Criterion) {
    let mut group = c.benchmark_group("cubic_spline_eval_3d");
    group.sample_size(20);
    let points: Vec<Point3> = (0..1000)
        .map(|i| {
            let s = i as f64 * 1e-2;
            Point3::new([s.cos() * (1.0 + 0.3 * (7.0 * s).sin()), s.sin(), 0.2 * s])
        })
        .collect();
    let curve = CubicSpline::through(
        &points,
        CurveParameterization::ChordLength,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    let n = 1_000_000;
    let d = curve.domain();
    let ts: Vec<f64> = (0..n).map(|i| d.uniform(i, n)).collect();
    let mut out = vec![Point3::ZERO; n];
    group.throughput(Throughput::Elements(n as u64));
    for k in [0usize, 1] {
        group.bench_function(BenchmarkId::new("sorted_1000_knots_order", k), |b| {
            b.iter(|| curve.deriv_into(black_box(&ts), k, &mut out))
        });
    }
    group.finish();
}

criterion_group!(benches, bicubic, spline, spline_eval);
criterion_main!(benches);
