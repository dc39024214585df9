//! Exact B-spline conversion benchmarks: an LL curve, an LL surface and a composite Coons
//! surface to their B-spline form.
//!
//! Run: `cargo bench -p karkas-bench --bench bspline`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use karkas::bspline::{ToBSplineCurve, ToBSplineSurface};
use karkas::coons::{CoonsSurface, CurveFit, PointNetwork};
use karkas::ll::{LlCurve, LlSurface};
use karkas::{Grid, Point3};
use std::hint::black_box;

fn polygon(k: usize) -> Vec<Point3> {
    (0..k)
        .map(|i| {
            let s = i as f64 * 0.01;
            Point3::new([s.cos(), s.sin(), 0.2 * (3.0 * s).cos()])
        })
        .collect()
}

fn curves(c: &mut Criterion) {
    let mut group = c.benchmark_group("bspline_ll_curve");
    for k in [100usize, 10_000] {
        for order in [2usize, 5] {
            let curve = LlCurve::new(&polygon(k), order, false).unwrap();
            group.bench_with_input(BenchmarkId::new(format!("L{order}"), k), &curve, |b, c| {
                b.iter(|| black_box(c.to_bspline().unwrap()))
            });
        }
    }
    group.finish();
}

fn surfaces(c: &mut Criterion) {
    let mut group = c.benchmark_group("bspline_surface");
    let grid = Grid::from_fn(15, 31, |i, j| {
        let (x, y) = (i as f64, j as f64 * 0.2);
        Point3::new([x, y.cos(), y.sin() * (1.0 + 0.1 * x)])
    });
    let ll = LlSurface::new(&grid, 5, false, false).unwrap();
    group.bench_function("ll_15x31_L5", |b| {
        b.iter(|| black_box(ll.to_bspline().unwrap()))
    });
    let s = |u: f64, v: f64| Point3::new([3.0 * u, 2.0 * v, (2.0 * u).sin() * (1.0 + v * v)]);
    let v_lists: Vec<Vec<Point3>> = (0..6)
        .map(|i| {
            (0..=20)
                .map(|k| s(i as f64 / 5.0, k as f64 / 20.0))
                .collect()
        })
        .collect();
    let u_lists: Vec<Vec<Point3>> = (0..5)
        .map(|j| {
            (0..=25)
                .map(|k| s(k as f64 / 25.0, j as f64 / 4.0))
                .collect()
        })
        .collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    let coons = CoonsSurface::composite(net.network(), None, 1e-6).unwrap();
    group.bench_function("composite_coons_6x5", |b| {
        b.iter(|| black_box(coons.to_bspline().unwrap()))
    });
    group.finish();
}

criterion_group!(benches, curves, surfaces);
criterion_main!(benches);
