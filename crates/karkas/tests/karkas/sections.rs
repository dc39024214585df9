//! Plane sections and isolines (docs/methods.md §1.4): every point on the plane and on the surface,
//! the expected pieces on known surfaces (closed when they should be), nothing for a plane that
//! misses, termination at saddles and tangencies, and the fast path against the traced one.

use karkas::ll::LlSurface;
use karkas::section::{
    plane_section, LevelFunction, Plane, Section, SectionOptions, SectionWarning, Sectioner,
};
use karkas::{Grid, Interval, Point3, Surface};
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Every point of every curve lies on the plane (to `1e-9`) and is the surface's point at
/// its reported parameters.
fn assert_on_plane_and_surface<S: Surface<3>>(surface: &S, plane: &Plane<3>, section: &Section<3>) {
    for curve in &section.curves {
        assert_eq!(curve.params.len(), curve.points.len());
        for (&(u, v), &p) in curve.params.iter().zip(&curve.points) {
            let off = plane.normal().dot(p) - plane.offset();
            assert!(off.abs() <= 1e-9, "point {p:?} is {off:e} off the plane");
            assert!(surface.domain_u().contains(u) && surface.domain_v().contains(v));
            assert_eq!(surface.eval(u, v), p, "not the surface point at ({u}, {v})");
        }
    }
}

fn plane(n: [f64; 3], c: f64) -> Plane<3> {
    Plane::new(Point3::new(n), c).unwrap()
}

/// The LL interpolant of a sphere-like grid: latitudes -80..80 degrees (rows, u, open),
/// 18 longitudes (columns, v, closed).
fn sphere_like() -> LlSurface<3> {
    let grid = Grid::from_fn(17, 18, |i, j| {
        let lat = (-80.0 + 10.0 * i as f64).to_radians();
        let lon = (20.0 * j as f64).to_radians();
        Point3::new([lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin()])
    });
    LlSurface::interpolating(&grid, 3, false, true).unwrap()
}

/// The LL interpolant of a torus, closed both ways: u around the axis, v around the tube.
fn torus() -> LlSurface<3> {
    let (big, small) = (2.0, 0.6);
    let grid = Grid::from_fn(24, 16, |i, j| {
        let (theta, phi) = (TAU * i as f64 / 24.0, TAU * j as f64 / 16.0);
        let r = big + small * phi.cos();
        Point3::new([r * theta.cos(), r * theta.sin(), small * phi.sin()])
    });
    LlSurface::interpolating(&grid, 3, true, true).unwrap()
}

#[test]
fn sphere_like_surface_sections_have_the_expected_pieces() {
    let sphere = sphere_like();
    let sectioner = Sectioner::new(&sphere, &SectionOptions::default()).unwrap();
    // (plane, pieces, closed, fast path)
    let cases = [
        // z depends on the row only: the paper's fast path, one circle of latitude.
        (plane([0.0, 0.0, 1.0], 0.3), 1, true, true),
        // A circle around the x axis, inside the domain.
        (plane([1.0, 0.0, 0.0], 0.3), 1, true, false),
        // A tilted circle around the z axis: it crosses the seam of the closed v.
        (plane([0.2, 0.3, 1.0], 0.1), 1, true, false),
        // Through both (cut-off) poles: two meridian arcs from border to border.
        (plane([1.0, 0.0, 0.0], 0.0), 2, false, false),
        // Missing the surface.
        (plane([1.0, 0.0, 0.0], 2.0), 0, false, false),
        (plane([0.0, 0.0, 1.0], 0.999), 0, false, true),
    ];
    for (k, (p, pieces, closed, fast)) in cases.iter().enumerate() {
        let section = sectioner.plane(p);
        assert_eq!(section.curves.len(), *pieces, "case {k}: {section:?}");
        assert_eq!(section.fast_path, *fast, "case {k}");
        assert!(
            section.warnings.is_empty(),
            "case {k}: {:?}",
            section.warnings
        );
        for c in &section.curves {
            assert_eq!(c.closed, *closed, "case {k}");
            assert!(c.points.len() > 10, "case {k}: {} points", c.points.len());
        }
        assert_on_plane_and_surface(&sphere, p, &section);
    }
    // The open arcs run from one border of u to the other.
    let arcs = sectioner.plane(&plane([1.0, 0.0, 0.0], 0.0));
    let d = sphere.domain_u();
    for c in &arcs.curves {
        let (first, last) = (c.params[0].0, c.params[c.params.len() - 1].0);
        let ends = [first.min(last), first.max(last)];
        assert!((ends[0] - d.start).abs() < 1e-12 && (ends[1] - d.end).abs() < 1e-12);
    }
}

#[test]
fn torus_sections_close_in_both_directions() {
    let torus = torus();
    let sectioner = Sectioner::new(&torus, &SectionOptions::default()).unwrap();
    let cases = [
        // z depends on the column only: two lines v = const (outer and inner equator).
        (plane([0.0, 0.0, 1.0], 0.0), 2, true),
        // A plane through the axis: two meridian circles, traced.
        (plane([1.0, 0.0, 0.0], 0.0), 2, false),
        // Slightly tilted through the centre: two closed curves around the axis.
        (plane([0.0, 0.1, 1.0], 0.0), 2, false),
        // Cutting off one side of the tube ring: one closed curve.
        (plane([1.0, 0.0, 0.0], 2.2), 1, false),
    ];
    for (k, (p, pieces, fast)) in cases.iter().enumerate() {
        let section = sectioner.plane(p);
        assert_eq!(section.curves.len(), *pieces, "case {k}");
        assert_eq!(section.fast_path, *fast, "case {k}");
        assert!(
            section.warnings.is_empty(),
            "case {k}: {:?}",
            section.warnings
        );
        assert!(section.curves.iter().all(|c| c.closed), "case {k}");
        assert_on_plane_and_surface(&torus, p, &section);
    }
}

/// The unit sphere in closed form, without its polar caps: u the polar angle (open), v the
/// longitude (closed). Not an LL surface: the general path through the trait alone.
struct UnitSphere;

fn sin_k(t: f64, k: usize) -> f64 {
    (t + k as f64 * FRAC_PI_2).sin()
}
fn cos_k(t: f64, k: usize) -> f64 {
    (t + k as f64 * FRAC_PI_2).cos()
}

impl Surface<3> for UnitSphere {
    fn domain_u(&self) -> Interval {
        Interval::new(0.2, PI - 0.2)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn is_closed_u(&self) -> bool {
        false
    }
    fn is_closed_v(&self) -> bool {
        true
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.deriv(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let z = if kv == 0 { cos_k(u, ku) } else { 0.0 };
        Point3::new([sin_k(u, ku) * cos_k(v, kv), sin_k(u, ku) * sin_k(v, kv), z])
    }
}

#[test]
fn sections_of_an_exact_sphere_are_its_circles_within_the_tolerance() {
    let tolerance = 1e-5;
    let options = SectionOptions {
        tolerance: Some(tolerance),
        ..SectionOptions::default()
    };
    let sectioner = Sectioner::new(&UnitSphere, &options).unwrap();
    for (n, c) in [
        ([0.3, -0.5, 0.8], 0.4),
        ([1.0, 2.0, 0.5], -0.7),
        ([0.0, 1.0, 0.0], 0.0),
    ] {
        let p = plane(n, c);
        let section = sectioner.plane(&p);
        assert!(!section.fast_path);
        assert_on_plane_and_surface(&UnitSphere, &p, &section);
        // The circle: centre d n, radius sqrt(1 - d^2) (d the plane's distance from 0).
        let d = p.offset();
        let radius = (1.0 - d * d).sqrt();
        let centre = p.normal() * d;
        let total: f64 = section.curves.iter().map(|c| c.length()).sum();
        for curve in &section.curves {
            let n = curve.points.len();
            let pairs = (0..n - 1).map(|k| (k, k + 1));
            let closing = curve.closed.then_some((n - 1, 0));
            for (a, b) in pairs.chain(closing) {
                // The chord's midpoint is inside the circle by its deviation from the arc.
                let mid = curve.points[a].lerp(curve.points[b], 0.5);
                let deviation = radius - mid.distance(centre);
                assert!(deviation <= tolerance, "chord deviates by {deviation:e}");
            }
            assert!(curve.points.iter().all(|q| (q.norm() - 1.0).abs() < 1e-12));
        }
        // The caps are cut off, so a circle may be split; the length can only fall short of
        // the full circle by the arcs inside the caps, and never exceed it.
        assert!(total <= TAU * radius + 1e-12);
        if section.curves.len() == 1 && section.curves[0].closed {
            assert!(
                (total - TAU * radius).abs() < 8.0 * tolerance,
                "{total} vs {}",
                TAU * radius
            );
        }
    }
    // y = 0 passes through both cut-off poles: two open half circles, each of length
    // pi - 0.4 (the caps take 0.2 rad at each end).
    let section = sectioner.plane(&plane([0.0, 1.0, 0.0], 0.0));
    assert_eq!(section.curves.len(), 2);
    for c in &section.curves {
        assert!(!c.closed);
        assert!((c.length() - (PI - 0.4)).abs() < 1e-4, "{}", c.length());
    }
    // A circle well inside the domain closes.
    let section = sectioner.plane(&plane([1.0, 0.0, 0.0], 0.5));
    assert_eq!(section.curves.len(), 1);
    assert!(section.curves[0].closed);
}

#[test]
fn a_plane_through_a_saddle_or_touching_terminates() {
    // z = x^2 - y^2 over [-1, 1]^2, interpolated: z = 0 is two lines crossing at the saddle.
    let grid = Grid::from_fn(9, 9, |i, j| {
        let (x, y) = (-1.0 + 0.25 * i as f64, -1.0 + 0.25 * j as f64);
        Point3::new([x, y, x * x - y * y])
    });
    let saddle = LlSurface::interpolating(&grid, 3, false, false).unwrap();
    for options in [
        SectionOptions::default(),
        SectionOptions {
            cells: (8, 8), // the saddle on a grid vertex
            ..SectionOptions::default()
        },
    ] {
        let sectioner = Sectioner::new(&saddle, &options).unwrap();
        let p = plane([0.0, 0.0, 1.0], 0.0);
        let section = sectioner.level_set(&p);
        assert_on_plane_and_surface(&saddle, &p, &section);
        assert!(!section.curves.is_empty() && section.curves.len() <= 4);
        // All four arms reach the border, whichever way the branches were joined.
        let ends = section
            .curves
            .iter()
            .flat_map(|c| [c.params[0], c.params[c.params.len() - 1]])
            .filter(|&(u, v)| {
                let (du, dv) = (saddle.domain_u(), saddle.domain_v());
                [u - du.start, du.end - u, v - dv.start, dv.end - v]
                    .iter()
                    .any(|d| d.abs() < 1e-12)
            })
            .count();
        assert_eq!(ends, 4, "{:?}", section.curves.len());
        // The saddle is reported, whether the trace stopped there or ran through it.
        let near_saddle = |u: f64, v: f64| (u - 0.5).abs() < 0.1 && (v - 0.5).abs() < 0.1;
        assert!(
            section.warnings.iter().any(|w| matches!(
                *w,
                SectionWarning::SingularPoint { u, v }
                    | SectionWarning::ThroughSingularPoint { u, v } if near_saddle(u, v)
            )),
            "{:?}",
            section.warnings
        );
    }
    // A plane touching the torus at a saddle point of its inner equator (x = R - r): the
    // section is a figure eight through that point; the trace ends.
    let torus = torus();
    let at_vertex = torus.eval(torus.domain_u().start, torus.axis_v().node(9));
    let touching = plane([1.0, 0.0, 0.0], at_vertex[0]);
    let section = plane_section(&torus, &touching, &SectionOptions::default()).unwrap();
    assert_on_plane_and_surface(&torus, &touching, &section);
    assert!(!section.curves.is_empty() && !section.warnings.is_empty());
    // A plane touching the top of the tube: at most a tiny loop, and it terminates.
    let top = plane([0.0, 0.0, 1.0], 0.6);
    let section = Sectioner::new(&torus, &SectionOptions::default())
        .unwrap()
        .level_set(&top);
    assert_on_plane_and_surface(&torus, &top, &section);
    assert!(section.warnings.len() <= 17, "warnings are condensed");
    // The fast path finds that circle of contact exactly (a double root).
    let section = plane_section(&torus, &top, &SectionOptions::default()).unwrap();
    assert!(section.fast_path);
    assert_eq!(section.curves.len(), 1);
    assert_on_plane_and_surface(&torus, &top, &section);
}

#[test]
fn the_step_budget_bounds_a_trace_and_warns() {
    let options = SectionOptions {
        max_steps: 3,
        ..SectionOptions::default()
    };
    let p = plane([1.0, 0.0, 0.0], 0.3);
    let section = plane_section(&UnitSphere, &p, &options).unwrap();
    assert!(section
        .warnings
        .iter()
        .any(|w| matches!(w, SectionWarning::StepLimit { steps: 3, .. })));
    assert_on_plane_and_surface(&UnitSphere, &p, &section);
}

#[test]
fn the_fast_path_agrees_with_the_traced_section() {
    // A body like the paper's: x depends on the row only.
    let grid = Grid::from_fn(12, 15, |i, j| {
        let x = i as f64;
        let r = 1.0 + 0.5 * (x * 0.5).sin();
        let t = -FRAC_PI_2 + PI * j as f64 / 14.0;
        Point3::new([x, r * t.cos() * (1.0 + 0.3 * (2.0 * t).cos()), r * t.sin()])
    });
    let body = LlSurface::new(&grid, 4, false, false).unwrap();
    let tolerance = 1e-4;
    let options = SectionOptions {
        tolerance: Some(tolerance),
        ..SectionOptions::default()
    };
    let sectioner = Sectioner::new(&body, &options).unwrap();
    // (x = 0 and x = 11 run along the borders of the domain, where the traced path, which
    // looks for sign changes inside, sees none: the fast path covers them, tested below.)
    for x in [0.4, 3.3, 7.77, 10.9] {
        let p = plane([1.0, 0.0, 0.0], x);
        let fast = sectioner.plane(&p);
        let traced = sectioner.level_set(&p);
        assert!(fast.fast_path && !traced.fast_path);
        assert_eq!(fast.curves.len(), 1, "x = {x}");
        assert_eq!(traced.curves.len(), 1, "x = {x}");
        assert_on_plane_and_surface(&body, &p, &fast);
        assert_on_plane_and_surface(&body, &p, &traced);
        // Each traced point lies within the tolerance of the fast polyline.
        let line = &fast.curves[0].points;
        for q in &traced.curves[0].points {
            let d = line
                .windows(2)
                .map(|w| distance_to_segment(*q, w[0], w[1]))
                .fold(f64::INFINITY, f64::min);
            assert!(d < 2.0 * tolerance, "x = {x}: {d:e}");
        }
        let (lf, lt) = (fast.curves[0].length(), traced.curves[0].length());
        assert!((lf - lt).abs() < 1e-3 * lf, "x = {x}: {lf} vs {lt}");
    }
    for x in [0.0, 11.0] {
        let p = plane([1.0, 0.0, 0.0], x);
        let fast = sectioner.plane(&p);
        assert_eq!(fast.curves.len(), 1, "x = {x}");
        assert_on_plane_and_surface(&body, &p, &fast);
    }
    // Beyond the body: nothing, on both paths.
    let p = plane([1.0, 0.0, 0.0], 11.5);
    assert!(sectioner.plane(&p).curves.is_empty());
    assert!(sectioner.level_set(&p).curves.is_empty());
}

fn distance_to_segment(p: Point3, a: Point3, b: Point3) -> f64 {
    let ab = b - a;
    let t = ((p - a).dot(ab) / ab.norm_sq()).clamp(0.0, 1.0);
    p.distance(a.add_scaled(t, ab))
}

#[test]
fn bad_options_are_errors() {
    let sphere = sphere_like();
    let bad = [
        SectionOptions {
            tolerance: Some(0.0),
            ..SectionOptions::default()
        },
        SectionOptions {
            tolerance: Some(f64::NAN),
            ..SectionOptions::default()
        },
        SectionOptions {
            cells: (2, 64),
            ..SectionOptions::default()
        },
        SectionOptions {
            cells: (64, 1_000_000),
            ..SectionOptions::default()
        },
        SectionOptions {
            max_steps: 0,
            ..SectionOptions::default()
        },
    ];
    for options in bad {
        assert!(Sectioner::new(&sphere, &options).is_err(), "{options:?}");
    }
}

/// A plane that does not bound itself over boxes: every block of the grid is searched.
struct Unbounded(Plane<3>);

impl LevelFunction<3> for Unbounded {
    fn value(&self, p: Point3) -> f64 {
        self.0.value(p)
    }
    fn gradient(&self, p: Point3) -> Point3 {
        self.0.gradient(p)
    }
}

#[test]
fn skipping_blocks_the_plane_cannot_reach_changes_nothing() {
    let torus = torus();
    let sphere = sphere_like();
    let planes = [
        plane([0.3, -0.2, 1.0], 0.25),
        plane([1.0, 0.0, 0.1], 0.5),
        plane([0.0, 1.0, 0.2], -0.8),
    ];
    for cells in [(64, 64), (13, 29)] {
        let options = SectionOptions {
            cells,
            ..SectionOptions::default()
        };
        for sectioner in [
            Sectioner::new(&torus, &options).unwrap(),
            Sectioner::new(&sphere, &options).unwrap(),
        ] {
            for p in &planes {
                let culled = sectioner.level_set(p);
                let full = sectioner.level_set(&Unbounded(*p));
                assert!(!full.curves.is_empty());
                assert_eq!(culled, full);
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Any plane through the sphere-like surface: points on the plane and on the surface,
    /// and every open piece ends on the open border (u at its ends; v is closed).
    #[test]
    fn any_plane_gives_valid_pieces(
        nx in -1.0..1.0f64,
        ny in -1.0..1.0f64,
        nz in -1.0..1.0f64,
        c in -0.9..0.9f64,
    ) {
        prop_assume!(nx.abs() + ny.abs() + nz.abs() > 0.1);
        let sphere = sphere_like();
        let p = plane([nx, ny, nz], c);
        let section = plane_section(&sphere, &p, &SectionOptions::default()).unwrap();
        assert_on_plane_and_surface(&sphere, &p, &section);
        let d = sphere.domain_u();
        for curve in section.curves.iter().filter(|c| !c.closed) {
            for &(u, _) in [curve.params[0], curve.params[curve.params.len() - 1]].iter() {
                prop_assert!((u - d.start).abs() < 1e-9 || (d.end - u).abs() < 1e-9);
            }
        }
    }
}
