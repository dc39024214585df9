//! Coons surface benchmarks: grid evaluation of a composite Coons surface on a network of
//! 11 x 11 curves (10 x 10 patches), on a 1000 x 1000 grid.
//!
//! Run: `cargo bench -p karkas-bench --bench coons`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::coons::{
    curve_ref, CoonsSurface, CrossDerivatives, CurveFit, CurveNetwork, CurveRef, NetworkAxis,
    PointNetwork, DEFAULT_TOLERANCE,
};
use karkas::{Curve, Interval, Point3, Surface};
use std::hint::black_box;

/// A wavy sheet over `[0, 10] x [0, 10]` and its partial derivatives.
fn sheet(u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
    let d = |x: f64, a: f64, k: usize| match k % 4 {
        0 => (a * x).sin(),
        1 => (a * x).cos(),
        2 => -(a * x).sin(),
        _ => -(a * x).cos(),
    } * a.powi(k as i32);
    let lin = |x: f64, k: usize| match k {
        0 => x,
        1 => 1.0,
        _ => 0.0,
    };
    let one = |k: usize| if k == 0 { 1.0 } else { 0.0 };
    Point3::new([
        lin(u, ku) * one(kv),
        one(ku) * lin(v, kv),
        0.5 * d(u, 0.7, ku) * d(v, 0.9, kv),
    ])
}

/// A line of the sheet (or the first derivative across it).
struct Line {
    along_u: bool,
    at: f64,
    across: usize,
}

impl Curve<3> for Line {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 10.0)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval(&self, t: f64) -> Point3 {
        self.deriv(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point3 {
        if self.along_u {
            sheet(t, self.at, k, self.across)
        } else {
            sheet(self.at, t, self.across, k)
        }
    }
}

fn line(along_u: bool, at: f64, across: usize) -> CurveRef<3> {
    curve_ref(Line {
        along_u,
        at,
        across,
    })
}

fn composite_grid(c: &mut Criterion) {
    let mut group = c.benchmark_group("coons_composite_grid_eval");
    group.sample_size(20);
    let n = 1000;
    let mut out = vec![Point3::ZERO; n * n];
    group.throughput(Throughput::Elements((n * n) as u64));

    // Closed-form curves and cross-derivatives: the Boolean sum alone.
    let axis = NetworkAxis::uniform(11, false).unwrap();
    let nodes: Vec<f64> = axis.nodes().to_vec();
    let net = CurveNetwork::new(
        axis.clone(),
        nodes.iter().map(|&u| line(false, u, 0)).collect(),
        axis.clone(),
        nodes.iter().map(|&v| line(true, v, 0)).collect(),
    )
    .unwrap();
    let cross = CrossDerivatives {
        v_curves: nodes.iter().map(|&u| line(false, u, 1)).collect(),
        u_curves: nodes.iter().map(|&v| line(true, v, 1)).collect(),
    };
    let exact = CoonsSurface::composite(&net, Some(&cross), DEFAULT_TOLERANCE).unwrap();
    let us: Vec<f64> = (0..n).map(|i| exact.domain_u().uniform(i, n)).collect();
    let vs: Vec<f64> = (0..n).map(|i| exact.domain_v().uniform(i, n)).collect();
    group.bench_function(BenchmarkId::new("10x10_closed_form_curves", n * n), |b| {
        b.iter(|| exact.eval_grid_into(black_box(&us), black_box(&vs), &mut out))
    });

    // The command line's path: spline curves through 101 points each, cross-derivatives
    // derived from the network.
    let samples: Vec<f64> = (0..=100).map(|k| k as f64 / 10.0).collect();
    let v_lists: Vec<Vec<Point3>> = nodes
        .iter()
        .map(|&u| samples.iter().map(|&v| sheet(u, v, 0, 0)).collect())
        .collect();
    let u_lists: Vec<Vec<Point3>> = nodes
        .iter()
        .map(|&v| samples.iter().map(|&u| sheet(u, v, 0, 0)).collect())
        .collect();
    let points = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-6).unwrap();
    let derived = CoonsSurface::composite(points.network(), None, DEFAULT_TOLERANCE).unwrap();
    let us: Vec<f64> = (0..n).map(|i| derived.domain_u().uniform(i, n)).collect();
    let vs: Vec<f64> = (0..n).map(|i| derived.domain_v().uniform(i, n)).collect();
    group.bench_function(
        BenchmarkId::new("10x10_from_points_derived_cross", n * n),
        |b| b.iter(|| derived.eval_grid_into(black_box(&us), black_box(&vs), &mut out)),
    );
    group.finish();
}

criterion_group!(benches, composite_grid);
criterion_main!(benches);
