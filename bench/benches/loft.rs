//! Lofting: a wing through 11, 101 and 1,000 NACA sections of 200 points each (thickness 18%
//! to 9%, camber 4% to 1%, taper, twist, sweep and dihedral: the wing of `bench/loft_peers.py`),
//! monotone rule, tolerance 1e-5 of the chord. Goals: 101 sections in under 50 ms and 1,000 in
//! under 1 s on one core, the cost linear in the sections.
//!
//! Run: `cargo bench -p karkas-bench --bench loft`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::loft::{Loft, LoftOptions, WingPlacement};
use karkas::{Point2, Point3};
use std::hint::black_box;

/// A NACA 4-digit section of 200 points in Selig's order: 100 on the upper side from the
/// trailing edge to the leading edge, 100 on the lower side after it (cosine spacing).
fn naca(m: f64, p: f64, t: f64) -> Vec<Point2> {
    let n = 100;
    let point = |x: f64, upper: bool| {
        let yt = 5.0
            * t
            * (0.2969 * x.sqrt() - 0.126 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                - 0.1015 * x.powi(4));
        let (yc, dy) = if x < p {
            (
                m / (p * p) * (2.0 * p * x - x * x),
                2.0 * m / (p * p) * (p - x),
            )
        } else {
            let q = (1.0 - p) * (1.0 - p);
            (
                m / q * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
                2.0 * m / q * (p - x),
            )
        };
        let th = dy.atan();
        let sign = if upper { 1.0 } else { -1.0 };
        Point2::new([x - sign * yt * th.sin(), yc + sign * yt * th.cos()])
    };
    let pi = std::f64::consts::PI;
    let upper = (0..n).map(|k| {
        let beta = pi * k as f64 / (n - 1) as f64;
        point(0.5 * (1.0 + beta.cos()), true)
    });
    let lower = (1..=n).map(|k| {
        let beta = pi * k as f64 / n as f64;
        point(0.5 * (1.0 - beta.cos()), false)
    });
    upper.chain(lower).collect()
}

/// The profiles and placements of a wing of `count` sections.
fn wing(count: usize) -> (Vec<Vec<Point2>>, Vec<WingPlacement>) {
    (0..count)
        .map(|k| {
            let f = k as f64 / (count - 1) as f64;
            let y = 8.0 * f;
            let placement = WingPlacement {
                leading_edge: Point3::new([0.3 * y, y, 0.05 * y + 0.01 * y * y]),
                chord: 2.0 - 1.2 * f,
                twist: 3.0 - 5.0 * f,
                dihedral: None,
            };
            (naca(0.04 - 0.03 * f, 0.4, 0.18 - 0.09 * f), placement)
        })
        .unzip()
}

fn loft(c: &mut Criterion) {
    let mut group = c.benchmark_group("loft_wing_200_points");
    group.sample_size(10);
    let options = LoftOptions::default();
    for count in [11, 101, 1000] {
        let (profiles, placements) = wing(count);
        let built = Loft::wing(&profiles, &placements, &options).unwrap();
        assert!(
            built.tolerance_met(),
            "{count}: {:?}",
            built.max_relative_deviation()
        );
        eprintln!(
            "{count} sections: {:?} control points, {} rounds, worst {:.2e} of the chord",
            built.control_counts(),
            built.rounds(),
            built.max_relative_deviation()
        );
        group.throughput(Throughput::Elements(count as u64));
        group.bench_function(BenchmarkId::new("sections", count), |b| {
            b.iter(|| Loft::wing(black_box(&profiles), &placements, &options).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, loft);
criterion_main!(benches);
