//! Plane sections of an LL surface: sections per second for 100 planes through a 200 x 200
//! surface (L = 3), traced (oblique planes) and by the fast path (x = const, formula (21)).
//!
//! Run: `cargo bench -p karkas-bench --bench sections`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use karkas::ll::LlSurface;
use karkas::section::{Plane, SectionOptions, Sectioner};
use karkas::{Grid, Point3};
use std::hint::black_box;

/// A wavy sheet over the unit square, 200 x 200 grid points; x depends on the row only.
fn surface() -> LlSurface<3> {
    let (kx, ky) = (200, 200);
    let grid = Grid::from_fn(kx, ky, |i, j| {
        let (x, y) = (i as f64 / kx as f64, j as f64 / ky as f64);
        Point3::new([x, y, 0.2 * (6.0 * x).sin() * (4.0 * y).cos()])
    });
    LlSurface::new(&grid, 3, false, false).unwrap()
}

fn sections(c: &mut Criterion) {
    let surface = surface();
    let options = SectionOptions {
        cells: (400, 400),
        ..SectionOptions::default()
    };
    let mut group = c.benchmark_group("ll_sections_200x200_L3");
    group.sample_size(10);
    group.bench_function("sectioner_new_400x400_cells", |b| {
        b.iter(|| Sectioner::new(black_box(&surface), &options).unwrap())
    });
    let sectioner = Sectioner::new(&surface, &options).unwrap();
    // 100 oblique planes (traced): normals turning about z, offsets across the sheet.
    let oblique: Vec<Plane<3>> = (0..100)
        .map(|k| {
            let angle = 0.3 + 1.0 * k as f64 / 100.0;
            let normal = Point3::new([angle.cos(), angle.sin(), 0.5]);
            let offset = 0.1 + 0.9 * (k as f64 / 100.0) * (angle.cos() + angle.sin());
            Plane::new(normal, offset).unwrap()
        })
        .collect();
    // 100 stations x = const (the fast path).
    let stations: Vec<Plane<3>> = (0..100)
        .map(|k| Plane::coordinate(0, 0.01 + 0.98 * k as f64 / 100.0).unwrap())
        .collect();
    for (name, planes) in [("traced_oblique", &oblique), ("fast_path_x", &stations)] {
        let pieces: usize = planes.iter().map(|p| sectioner.plane(p).curves.len()).sum();
        assert!(pieces >= planes.len(), "{name}: {pieces} pieces");
        group.throughput(Throughput::Elements(planes.len() as u64));
        group.bench_function(BenchmarkId::new(name, planes.len()), |b| {
            b.iter(|| {
                for p in planes.iter() {
                    black_box(sectioner.plane(black_box(p)));
                }
            })
        });
    }
    group.finish();
}

criterion_group!(benches, sections);
criterion_main!(benches);
