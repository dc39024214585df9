//! Fairing benchmark (issue 53): `fair_curve` of a 200-point NACA 2412 contour (cosine
//! spacing, closed trailing edge) with Gaussian noise of 1e-4 chord (fixed seed), tolerance
//! 3e-4, on one core. The aim is under 10 ms.
//!
//! Run: `RAYON_NUM_THREADS=1 cargo bench -p karkas-bench --bench fair -- --warm-up-time 1
//! --measurement-time 5`.

use criterion::{criterion_group, criterion_main, Criterion};
use karkas::fair::{fair_curve, FairOptions};
use karkas::Point2;
use std::f64::consts::PI;
use std::hint::black_box;

/// NACA 2412 at `n` points, noise `sigma` per coordinate (Box–Muller on a xorshift).
fn airfoil(n: usize, sigma: f64) -> Vec<Point2> {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut uniform = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    };
    let mut normal = || (-2.0 * uniform().ln()).sqrt() * (2.0 * PI * uniform()).cos();
    let (m, p, t) = (0.02, 0.4, 0.12);
    (0..n)
        .map(|i| {
            let beta = 2.0 * PI * i as f64 / (n - 1) as f64;
            let x = 0.5 * (1.0 + beta.cos());
            let yt = 5.0
                * t
                * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                    - 0.1036 * x.powi(4));
            let (yc, slope) = if x < p {
                (
                    m / (p * p) * (2.0 * p * x - x * x),
                    2.0 * m / (p * p) * (p - x),
                )
            } else {
                (
                    m / ((1.0 - p) * (1.0 - p)) * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
                    2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - x),
                )
            };
            let theta = slope.atan();
            let side = if beta <= PI { 1.0 } else { -1.0 };
            Point2::new([
                x - side * yt * theta.sin() + sigma * normal(),
                yc + side * yt * theta.cos() + sigma * normal(),
            ])
        })
        .collect()
}

fn fair(c: &mut Criterion) {
    let mut group = c.benchmark_group("fair_naca2412");
    group.sample_size(10);
    let pts = airfoil(200, 1e-4);
    let options = FairOptions::new(3e-4);
    group.bench_function("200_points_sigma_1e-4", |b| {
        b.iter(|| fair_curve(black_box(&pts), &options).unwrap())
    });
    group.finish();
}

criterion_group!(benches, fair);
criterion_main!(benches);
