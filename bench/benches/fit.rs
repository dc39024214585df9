//! Fit benchmark (issue 12): 10^5 noisy points on an open spiral, 200 uniform knots, fitted
//! to convergence with the default settings: unconstrained, and with the jump bound
//! `eps = 1e-4` (active: the unconstrained fit's jump sum is about 5e-4).
//!
//! Run: `cargo bench -p karkas-bench --bench fit -- --warm-up-time 1 --measurement-time 3`.

use criterion::{criterion_group, criterion_main, Criterion};
use karkas::fit::{fit_curve, uniform_knots, FitOptions};
use karkas::Point2;
use std::hint::black_box;

/// `n` points of the spiral `(1 + s) (cos 3s, sin 3s)`, `s` uniform in `[0, 1]`, with
/// uniform noise in `[-5e-4, 5e-4]` per coordinate (fixed seed).
fn points(n: usize) -> Vec<Point2> {
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

fn fit(c: &mut Criterion) {
    let mut group = c.benchmark_group("fit_1e5_points_200_knots");
    group.sample_size(10);
    let pts = points(100_000);
    let knots = uniform_knots(200);
    let unconstrained = FitOptions::default();
    group.bench_function("unconstrained", |b| {
        b.iter(|| fit_curve(black_box(&pts), &knots, &unconstrained).unwrap())
    });
    let bounded = FitOptions {
        eps: 1e-4,
        ..Default::default()
    };
    let check = fit_curve(&pts, &knots, &bounded).unwrap();
    assert!(check.penalty > 0.0 && check.jump_sum <= 1e-4);
    group.bench_function("bound_eps_1e-4_active", |b| {
        b.iter(|| fit_curve(black_box(&pts), &knots, &bounded).unwrap())
    });
    group.finish();
}

criterion_group!(benches, fit);
criterion_main!(benches);
