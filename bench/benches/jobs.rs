//! The jobs of the side-by-side comparison (`bench/compare.py`), each at four or more sizes so
//! that the cost exponent can be fitted (`python3 bench/exponents.py` reads criterion's
//! estimates and fits `time ~ size^p`).
//!
//! Run: `cargo bench -p karkas-bench --bench jobs -- --warm-up-time 1 --measurement-time 3`.
//! The group names are the job names; the benchmark parameter is the size (points, or
//! evaluated values).

use criterion::measurement::WallTime;
use criterion::{
    criterion_group, criterion_main, BenchmarkGroup, BenchmarkId, Criterion, Throughput,
};
use karkas::dps::DiscreteSpline;
use karkas::fit::{fit_curve_adaptive, FitOptions};
use karkas::param::{
    BicubicSurface, CubicSpline, CurveParameterization, GridParameterization, SplineEnds,
};
use karkas::{Curve, Grid, Point2, Point3, Surface};
use std::hint::black_box;
use std::time::Duration;

/// `n` points of an open 3-D curve with uneven spacing.
fn open_curve(n: usize) -> Vec<Point3> {
    (0..n)
        .map(|i| {
            let s = 20.0 * i as f64 / n as f64;
            let s = s + 0.3 * (0.7 * s).sin();
            Point3::new([s.cos() * (1.0 + 0.3 * (7.0 * s).sin()), s.sin(), 0.2 * s])
        })
        .collect()
}

/// `n` distinct points of a closed 3-D curve (the seam is not repeated).
fn closed_curve(n: usize) -> Vec<Point3> {
    (0..n)
        .map(|l| {
            let s = std::f64::consts::TAU * l as f64 / n as f64;
            Point3::new([
                s.cos() * (1.0 + 0.3 * (7.0 * s).sin()),
                s.sin(),
                0.2 * (3.0 * s).cos(),
            ])
        })
        .collect()
}

/// `n` points of the spiral `(1 + s) (cos 3s, sin 3s)` with uniform noise of half-width
/// `5e-4` per coordinate (fixed seed).
fn noisy_spiral(n: usize) -> Vec<Point2> {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut noise = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 1e-3
    };
    (0..n)
        .map(|i| {
            let s = i as f64 / (n - 1) as f64;
            let a = 3.0 * s;
            Point2::new([(1.0 + s) * a.cos() + noise(), (1.0 + s) * a.sin() + noise()])
        })
        .collect()
}

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

fn short<'a>(c: &'a mut Criterion, name: &str) -> BenchmarkGroup<'a, WallTime> {
    let mut group = c.benchmark_group(name);
    group.sample_size(10);
    group.warm_up_time(Duration::from_millis(500));
    group
}

/// A cubic spline through 1000 points evaluated at `m` sorted parameters: values, and values
/// plus first derivatives.
fn curve_eval(c: &mut Criterion) {
    let curve = CubicSpline::through(
        &open_curve(1000),
        CurveParameterization::ChordLength,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    let d = curve.domain();
    for (name, with_derivative) in [("curve_eval_value", false), ("curve_eval_value_d1", true)] {
        let mut group = short(c, name);
        for m in [100_000, 1_000_000, 3_000_000, 10_000_000] {
            let ts: Vec<f64> = (0..m).map(|i| d.uniform(i, m)).collect();
            let mut out = vec![Point3::ZERO; m];
            let mut d1 = vec![Point3::ZERO; if with_derivative { m } else { 0 }];
            group.throughput(Throughput::Elements(m as u64));
            group.bench_function(BenchmarkId::from_parameter(m), |b| {
                b.iter(|| {
                    curve.eval_into(black_box(&ts), &mut out);
                    if with_derivative {
                        curve.deriv_into(&ts, 1, &mut d1);
                    }
                })
            });
        }
        group.finish();
    }
}

/// Chord-length not-a-knot cubic spline through `n` 3-D points.
fn curve_interp(c: &mut Criterion) {
    let mut group = short(c, "curve_interp_not_a_knot");
    for n in [10_000, 100_000, 300_000, 1_000_000] {
        let points = open_curve(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                CubicSpline::through(
                    black_box(&points),
                    CurveParameterization::ChordLength,
                    SplineEnds::NotAKnot,
                )
                .unwrap()
            })
        });
    }
    group.finish();
}

/// Closed curves through `n` points: periodic cubic spline (chord length) and the discrete
/// periodic spline of order 3 with 10 values per node.
fn closed_interp(c: &mut Criterion) {
    let sizes = [1_000, 10_000, 100_000, 300_000];
    let mut group = short(c, "closed_interp_periodic_cubic");
    for n in sizes {
        let points = closed_curve(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                CubicSpline::through(
                    black_box(&points),
                    CurveParameterization::ChordLength,
                    SplineEnds::Periodic,
                )
                .unwrap()
            })
        });
    }
    group.finish();
    let mut group = short(c, "closed_interp_dps");
    for n in sizes {
        let points = closed_curve(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| DiscreteSpline::interpolating(black_box(&points), 3, 10).unwrap())
        });
    }
    group.finish();
}

/// Adaptive smoothing fit of `n` noisy 2-D points to the tolerance 1e-3.
fn smoothing_fit(c: &mut Criterion) {
    let mut group = short(c, "smoothing_fit_adaptive");
    let options = FitOptions::default();
    for n in [3_000, 10_000, 30_000, 100_000] {
        let points = noisy_spiral(n);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| fit_curve_adaptive(black_box(&points), 1e-3, &options).unwrap())
        });
    }
    group.finish();
}

/// Bicubic interpolation of an `n x n` grid of 3-D points (chord parameters), and the
/// evaluation of the 1000 x 1000 surface on `m x m`.
fn bicubic(c: &mut Criterion) {
    let mut group = short(c, "bicubic_construct");
    for n in [250, 500, 1000, 1400] {
        let grid = sheet(n);
        group.throughput(Throughput::Elements((n * n) as u64));
        group.bench_function(BenchmarkId::from_parameter(n * n), |b| {
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
    }
    group.finish();
    let surface =
        BicubicSurface::new(&sheet(1000), GridParameterization::default(), false, false).unwrap();
    let mut group = short(c, "bicubic_eval_grid");
    for m in [250, 500, 632, 1000, 2000] {
        let us: Vec<f64> = (0..m).map(|i| surface.domain_u().uniform(i, m)).collect();
        let vs: Vec<f64> = (0..m).map(|i| surface.domain_v().uniform(i, m)).collect();
        let mut out = vec![Point3::ZERO; m * m];
        group.throughput(Throughput::Elements((m * m) as u64));
        group.bench_function(BenchmarkId::from_parameter(m * m), |b| {
            b.iter(|| surface.eval_grid_into(black_box(&us), black_box(&vs), &mut out))
        });
    }
    group.finish();
}

criterion_group!(
    benches,
    curve_eval,
    curve_interp,
    closed_interp,
    smoothing_fit,
    bicubic
);
criterion_main!(benches);
