//! Discrete periodic spline benchmarks (Malozemov et al.): interpolation with m = 10^6 nodes and
//! evaluation of N = 10^7 values, orders 2 and 4, points in R^3.
//!
//! Run: `cargo bench -p karkas-bench --bench dps`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::dps::{DiscreteSpline, InterpolationPlan};
use karkas::Point3;
use std::hint::black_box;

/// Nodes (or poles) per curve.
const M: usize = 1_000_000;
/// Values per node: N = M * STEP = 10^7.
const STEP: usize = 10;

/// A closed wavy 3-D curve sampled at `m` points.
fn closed_curve(m: usize) -> Vec<Point3> {
    (0..m)
        .map(|l| {
            let s = std::f64::consts::TAU * l as f64 / m as f64;
            Point3::new([
                s.cos() * (1.0 + 0.3 * (700.0 * s).sin()),
                s.sin(),
                0.2 * (3000.0 * s).cos(),
            ])
        })
        .collect()
}

fn interpolation(c: &mut Criterion) {
    let mut group = c.benchmark_group("dps_interpolation_3d_m1e6_n10");
    group.sample_size(10);
    group.throughput(Throughput::Elements(M as u64));
    let nodes = closed_curve(M);
    for order in [2, 4] {
        // Everything: the symbol T_r (O(N)), the FFT plans and one solve.
        group.bench_function(BenchmarkId::new("plan_and_solve", order), |b| {
            b.iter(|| DiscreteSpline::interpolating(black_box(&nodes), order, STEP).unwrap())
        });
        // One more right-hand side with a ready plan: two real FFTs of length m per coordinate.
        let mut plan = InterpolationPlan::new(M, STEP, order).unwrap();
        let mut poles = vec![Point3::ZERO; M];
        group.bench_function(BenchmarkId::new("solve_with_plan", order), |b| {
            b.iter(|| plan.poles_into(black_box(&nodes), &mut poles).unwrap())
        });
    }
    group.finish();
}

fn evaluation(c: &mut Criterion) {
    let mut group = c.benchmark_group("dps_values_3d_N1e7");
    group.sample_size(10);
    let period = M * STEP;
    group.throughput(Throughput::Elements(period as u64));
    let poles = closed_curve(M);
    let mut out = vec![Point3::ZERO; period];
    for order in [2, 4] {
        let spline = DiscreteSpline::from_poles(&poles, order, STEP).unwrap();
        group.bench_function(BenchmarkId::new("order", order), |b| {
            b.iter(|| spline.values(black_box(&mut out)))
        });
    }
    group.finish();
}

criterion_group!(benches, interpolation, evaluation);
criterion_main!(benches);
