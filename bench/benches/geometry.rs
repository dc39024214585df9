//! Curve geometry benchmarks: projection of many points and many arc lengths.
//!
//! Run: `cargo bench -p karkas-bench --bench geometry`. The curve is the periodic cubic
//! spline (chord parameters) through 1000 points of the rose `r = 1 + 0.3 cos 5θ`, as in
//! `bench/geometry_vs_scipy.py`, which times the same jobs against SciPy.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::geometry::{ArcLengthTable, CurveProjector};
use karkas::param::{CubicSpline, CurveParameterization};
use karkas::spline::SplineEnds;
use karkas::{Curve, Point2};
use std::f64::consts::TAU;
use std::hint::black_box;

/// The closed rose through `n` points (the first repeated at the end).
fn rose(n: usize) -> CubicSpline<2> {
    let pts: Vec<Point2> = (0..=n)
        .map(|k| {
            let th = TAU * (k % n) as f64 / n as f64;
            let r = 1.0 + 0.3 * (5.0 * th).cos();
            Point2::new([r * th.cos(), r * th.sin()])
        })
        .collect();
    CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::Periodic,
    )
    .unwrap()
}

/// A deterministic sequence in [0, 1) (the golden-ratio additive recurrence).
fn unit(k: usize, shift: f64) -> f64 {
    (shift + k as f64 * 0.618_033_988_749_894_9).fract()
}

fn geometry(c: &mut Criterion) {
    let curve = rose(1000);
    let domain = curve.domain();
    let m = 1_000_000;
    // Points within 0.05 of the curve (about 3% of its size) on either side.
    let queries: Vec<Point2> = (0..m)
        .map(|k| {
            let t = domain.start + domain.length() * unit(k, 0.1);
            let (p, d) = (curve.eval(t), curve.deriv(t, 1));
            let normal = Point2::new([-d[1], d[0]]) * (1.0 / d.norm());
            p + normal * (0.1 * unit(k, 0.37) - 0.05)
        })
        .collect();
    let mut group = c.benchmark_group("curve_geometry");
    group.sample_size(10);
    group.throughput(Throughput::Elements(m as u64));
    group.bench_function(BenchmarkId::new("project_1e6_onto_1e3_pieces", m), |b| {
        b.iter(|| {
            let projector = CurveProjector::new(&curve, 0.0).unwrap();
            projector.nearest_all(black_box(&queries))
        })
    });
    let intervals: Vec<(f64, f64)> = (0..m)
        .map(|k| {
            let a = domain.start + domain.length() * unit(k, 0.2);
            let b = domain.start + domain.length() * unit(k, 0.71);
            (a, b)
        })
        .collect();
    group.bench_function(BenchmarkId::new("arc_length_1e6_intervals", m), |b| {
        b.iter(|| {
            let table = ArcLengthTable::new(&curve, 1e-10);
            intervals
                .iter()
                .map(|&(t0, t1)| table.arc_length(&curve, t0, t1))
                .sum::<f64>()
        })
    });
    group.finish();
}

criterion_group!(benches, geometry);
criterion_main!(benches);
