//! LL curve and surface benchmarks (issue targets in BENCHMARKS.md).
//!
//! Run: `cargo bench -p karkas-bench --bench ll`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::ll::{interpolation_controls, LlCurve, LlKernel, LlSurface};
use karkas::{Curve, Grid, Point3, Surface};
use std::hint::black_box;

/// A wavy 3-D polygon of `k` points.
fn polygon(k: usize) -> Vec<Point3> {
    (0..k)
        .map(|i| {
            let s = i as f64 * 0.01;
            Point3::new([
                s.cos() * (1.0 + 0.3 * (7.0 * s).sin()),
                s.sin(),
                0.2 * (3.0 * s).cos(),
            ])
        })
        .collect()
}

/// A pseudo-random permutation of parameters (fixed seed, no dependency).
fn shuffled(ts: &[f64]) -> Vec<f64> {
    let mut out = ts.to_vec();
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    for i in (1..out.len()).rev() {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        out.swap(i, (state % (i as u64 + 1)) as usize);
    }
    out
}

/// The ceiling: a plain cubic evaluated into an array of 3-D points (one store stream).
fn plain_cubic_into(ts: &[f64], out: &mut [Point3]) {
    for (p, &t) in out.iter_mut().zip(ts) {
        let x = ((0.5 * t - 1.0) * t + 2.0) * t + 0.25;
        *p = Point3::new([x, t, 1.0 - x]);
    }
}

fn curve_eval(c: &mut Criterion) {
    let mut group = c.benchmark_group("ll_curve_eval_L5_3d");
    let n = 1_000_000;
    {
        let ts: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
        let mut out = vec![Point3::ZERO; n];
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function("reference_plain_cubic", |b| {
            b.iter(|| plain_cubic_into(black_box(&ts), &mut out))
        });
    }
    for &k in &[1_000usize, 100_000] {
        let curve = LlCurve::new(&polygon(k), 5, false).unwrap();
        let d = curve.domain();
        let ts: Vec<f64> = (0..n).map(|i| d.uniform(i, n)).collect();
        let mut out = vec![Point3::ZERO; n];
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("sorted", k), &ts, |b, ts| {
            b.iter(|| curve.eval_into(black_box(ts), &mut out))
        });
        let random = shuffled(&ts);
        group.bench_with_input(BenchmarkId::new("shuffled", k), &random, |b, ts| {
            b.iter(|| curve.eval_into(black_box(ts), &mut out))
        });
    }
    group.finish();
}

/// 10^7 points of an LL curve into a reused buffer: the job the Python package's `out=`
/// evaluation is compared with (crates/karkas-py/tests/bench_eval.py does the same from Python).
fn curve_eval_10m(c: &mut Criterion) {
    let mut group = c.benchmark_group("ll_curve_eval_L5_3d_1e7");
    group.sample_size(10);
    let n = 10_000_000;
    let curve = LlCurve::new(&polygon(1_000), 5, false).unwrap();
    let d = curve.domain();
    let ts: Vec<f64> = (0..n).map(|i| d.uniform(i, n)).collect();
    let mut out = vec![Point3::ZERO; n];
    group.throughput(Throughput::Elements(n as u64));
    group.bench_function(BenchmarkId::new("sorted", 1_000), |b| {
        b.iter(|| curve.eval_into(black_box(&ts), &mut out))
    });
    group.finish();
}

fn prefilter(c: &mut Criterion) {
    let mut group = c.benchmark_group("ll_interpolation_prefilter_3d");
    let n = 1_000_000;
    let pts = polygon(n);
    let d_l = LlKernel::new(5).unwrap().d_l();
    group.throughput(Throughput::Elements(n as u64));
    for closed in [false, true] {
        let mut input = pts.clone();
        if closed {
            input.push(input[0]);
        }
        let mut work = input.clone();
        let name = if closed { "closed" } else { "open" };
        group.bench_function(BenchmarkId::new(name, n), |b| {
            b.iter(|| {
                work.copy_from_slice(&input);
                interpolation_controls(black_box(&mut work), d_l, closed).unwrap();
            })
        });
    }
    group.finish();
}

fn surface_grid(c: &mut Criterion) {
    let mut group = c.benchmark_group("ll_surface_grid_eval_L5");
    group.sample_size(20);
    let (kx, ky) = (200, 200);
    let grid = Grid::from_fn(kx, ky, |i, j| {
        let (x, y) = (i as f64 / kx as f64, j as f64 / ky as f64);
        Point3::new([x, y, (6.0 * x).sin() * (4.0 * y).cos()])
    });
    let surface = LlSurface::new(&grid, 5, false, false).unwrap();
    let n = 2000;
    let us: Vec<f64> = (0..n).map(|i| surface.domain_u().uniform(i, n)).collect();
    let vs: Vec<f64> = (0..n).map(|i| surface.domain_v().uniform(i, n)).collect();
    let mut out = vec![Point3::ZERO; n * n];
    group.throughput(Throughput::Elements((n * n) as u64));
    group.bench_function(BenchmarkId::new("2000x2000_from_200x200", n * n), |b| {
        b.iter(|| surface.eval_grid_into(black_box(&us), black_box(&vs), &mut out))
    });
    group.finish();
}

criterion_group!(benches, curve_eval, curve_eval_10m, prefilter, surface_grid);
criterion_main!(benches);
