//! The section tolerance is a bound on the chord error (docs/methods.md §1.4): no chord of a
//! section polyline strays farther than the tolerance from the arc of the true section it
//! spans. The arc is found independently of the sectioner: for 31 fractions `t` along each
//! chord, the point of the section in the plane through `a + t (b - a)` across the chord
//! (two equations, plane and cross plane, solved by Newton's method in `(u, v)`), so the
//! largest distance of those points from the chord is the chord error, sampled densely.

use karkas::ll::LlSurface;
use karkas::section::{LevelFunction, Plane, Section, SectionOptions, Sectioner};
use karkas::{Grid, Interval, Point3, Surface};
use std::f64::consts::{FRAC_PI_2, TAU};

fn plane(n: [f64; 3], c: f64) -> Plane<3> {
    Plane::new(Point3::new(n), c).unwrap()
}

/// The LL surfaces (interpolating and approximating) of a torus grid (major radius 2, minor
/// 0.6), closed both ways.
fn ll_tori() -> [LlSurface<3>; 2] {
    let (big, small) = (2.0, 0.6);
    let grid = Grid::from_fn(24, 16, |i, j| {
        let (theta, phi) = (TAU * i as f64 / 24.0, TAU * j as f64 / 16.0);
        let r = big + small * phi.cos();
        Point3::new([r * theta.cos(), r * theta.sin(), small * phi.sin()])
    });
    [
        LlSurface::interpolating(&grid, 3, true, true).unwrap(),
        LlSurface::new(&grid, 3, true, true).unwrap(),
    ]
}

/// A wavy cylinder in closed form: `(r cos v, r sin v, u)` with `r = 1 + 0.3 sin(3v) +
/// 0.2 cos(2u)`, `u` over `[-1, 1]` (open), `v` over a turn (closed).
struct WavyCylinder;

impl WavyCylinder {
    /// `r` and its derivatives: `(d/du)^ku (d/dv)^kv r`.
    fn radius(u: f64, v: f64, ku: usize, kv: usize) -> f64 {
        let k = |t: f64, n: usize| (t + n as f64 * FRAC_PI_2).sin();
        let c = |t: f64, n: usize| (t + n as f64 * FRAC_PI_2).cos();
        let mut r = 0.0;
        if ku == 0 {
            r += 0.3 * 3f64.powi(kv as i32) * k(3.0 * v, kv);
            if kv == 0 {
                r += 1.0;
            }
        }
        if kv == 0 {
            r += 0.2 * 2f64.powi(ku as i32) * c(2.0 * u, ku);
        }
        r
    }
}

impl Surface<3> for WavyCylinder {
    fn domain_u(&self) -> Interval {
        Interval::new(-1.0, 1.0)
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
        // (r cos v, r sin v) by Leibniz's rule in v; r's u-derivatives pass through.
        let (mut x, mut y) = (0.0, 0.0);
        let mut binomial = 1.0;
        for j in 0..=kv {
            let r = Self::radius(u, v, ku, kv - j);
            let n = j as f64 * FRAC_PI_2;
            x += binomial * r * (v + n).cos();
            y += binomial * r * (v + n).sin();
            binomial = binomial * (kv - j) as f64 / (j + 1) as f64;
        }
        let z = match (ku, kv) {
            (0, 0) => u,
            (1, 0) => 1.0,
            _ => 0.0,
        };
        Point3::new([x, y, z])
    }
}

/// The point of the section by `p` in the plane across the chord `a -> b` at `m`, by Newton's
/// method from `(u, v)`; `None` when it does not converge in the domain.
fn across<S: Surface<3>>(
    surface: &S,
    p: &Plane<3>,
    (a, b): (Point3, Point3),
    m: Point3,
    (mut u, mut v): (f64, f64),
) -> Option<Point3> {
    let e = (b - a) * (1.0 / a.distance(b));
    let n = p.normal();
    for _ in 0..60 {
        let q = surface.eval(u, v);
        let f = [p.value(q), (q - m).dot(e)];
        if f[0].abs() < 1e-15 && f[1].abs() < 1e-15 {
            break;
        }
        let (su, sv) = (surface.deriv(u, v, 1, 0), surface.deriv(u, v, 0, 1));
        let j = [[n.dot(su), n.dot(sv)], [e.dot(su), e.dot(sv)]];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        u -= (f[0] * j[1][1] - f[1] * j[0][1]) / det;
        v -= (j[0][0] * f[1] - j[1][0] * f[0]) / det;
    }
    let q = surface.eval(u, v);
    let inside = |d: Interval, closed: bool, t: f64| closed || (d.start..=d.end).contains(&t);
    let ok = p.value(q).abs() < 1e-12
        && ((q - m).dot(e)).abs() < 1e-12
        && inside(surface.domain_u(), surface.is_closed_u(), u)
        && inside(surface.domain_v(), surface.is_closed_v(), v);
    ok.then_some(q)
}

/// The largest chord error of a section, and how many arc points were measured.
fn chord_error<S: Surface<3>>(surface: &S, p: &Plane<3>, section: &Section<3>) -> (f64, usize) {
    let unwrap = |d: Interval, closed: bool, from: f64, to: f64| {
        if closed {
            let period = d.length();
            from + (to - from) - period * ((to - from) / period).round()
        } else {
            to
        }
    };
    let (mut worst, mut measured) = (0.0f64, 0);
    for curve in &section.curves {
        let n = curve.points.len();
        let pairs = (0..n - 1).map(|k| (k, k + 1));
        for (i, k) in pairs.chain(curve.closed.then_some((n - 1, 0))) {
            let (a, b) = (curve.points[i], curve.points[k]);
            let (pa, pb) = (curve.params[i], curve.params[k]);
            let pb = (
                unwrap(surface.domain_u(), surface.is_closed_u(), pa.0, pb.0),
                unwrap(surface.domain_v(), surface.is_closed_v(), pa.1, pb.1),
            );
            for s in 1..32 {
                let t = s as f64 / 32.0;
                let m = a.lerp(b, t);
                let start = (pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1));
                if let Some(q) = across(surface, p, (a, b), m, start) {
                    worst = worst.max(q.distance(m));
                    measured += 1;
                }
            }
        }
    }
    (worst, measured)
}

/// Checks that every chord is within the tolerance of its arc, and that nearly every arc
/// point was measured (Newton may miss a few across a seam or next to a border).
fn assert_bound<S: Surface<3>>(
    surface: &S,
    p: &Plane<3>,
    tolerance: Option<f64>,
    cells: (usize, usize),
    what: &str,
) {
    let options = SectionOptions {
        tolerance,
        cells,
        ..SectionOptions::default()
    };
    let sectioner = Sectioner::new(surface, &options).unwrap();
    let tolerance = sectioner.tolerance();
    let section = sectioner.plane(p);
    assert!(!section.curves.is_empty(), "{what}");
    let chords: usize = section
        .curves
        .iter()
        .map(|c| c.points.len() - 1 + usize::from(c.closed))
        .sum();
    let (worst, measured) = chord_error(surface, p, &section);
    assert_eq!(measured, 31 * chords, "{what}");
    assert!(
        worst <= tolerance,
        "{what}: chord error {worst:e} is {:.3} times the tolerance {tolerance:e}",
        worst / tolerance
    );
}

#[test]
fn the_tolerance_bounds_the_chord_error_on_a_torus() {
    // The cells: the library's default, and the command line's for a 24 x 16 grid.
    for (k, torus) in ll_tori().iter().enumerate() {
        for cells in [(64, 64), (48, 32)] {
            for n in [[0.3, 0.2, 1.0], [0.3, -0.2, 1.0], [1.0, 0.5, 0.2]] {
                for tolerance in [None, Some(1e-3), Some(1e-5)] {
                    let what = format!(
                        "torus {k}, {cells:?}, plane {n:?} = 0.25, tolerance {tolerance:?}"
                    );
                    assert_bound(torus, &plane(n, 0.25), tolerance, cells, &what);
                }
            }
        }
    }
}

/// The wavy cylinder itself, and the LL surfaces (interpolating and approximating) of a
/// 9 x 24 grid of its points: the LL surfaces' curvature changes from patch to patch, which
/// the trace's estimate of the chord error (from the turn of the tangent) does not see.
#[test]
fn the_tolerance_bounds_the_chord_error_on_a_wavy_cylinder() {
    let grid = Grid::from_fn(9, 24, |i, j| {
        WavyCylinder.eval(-1.0 + 0.25 * i as f64, TAU * j as f64 / 24.0)
    });
    let ll = [
        LlSurface::interpolating(&grid, 3, false, true).unwrap(),
        LlSurface::new(&grid, 3, false, true).unwrap(),
    ];
    let planes = [
        ([0.2, 0.1, 1.0], 0.1),
        ([0.5, 0.1, 1.0], 0.1),
        ([1.0, 0.7, 0.3], 0.2),
        ([1.0, 0.0, 0.3], 0.4),
    ];
    for (n, c) in planes {
        for tolerance in [None, Some(1e-3), Some(1e-5)] {
            for cells in [(16, 48), (64, 64)] {
                let what = format!("plane {n:?} = {c}, tolerance {tolerance:?}, {cells:?}");
                assert_bound(&WavyCylinder, &plane(n, c), tolerance, cells, &what);
                for (k, surface) in ll.iter().enumerate() {
                    let what = format!("LL surface {k}, {what}");
                    assert_bound(surface, &plane(n, c), tolerance, cells, &what);
                }
            }
        }
    }
}

/// The fast path (lines of constant parameter) keeps the bound too: the circle of latitude
/// of an LL sphere, cut by z = const.
#[test]
fn the_tolerance_bounds_the_chord_error_on_the_fast_path() {
    let grid = Grid::from_fn(17, 18, |i, j| {
        let lat = (-80.0 + 10.0 * i as f64).to_radians();
        let lon = (20.0 * j as f64).to_radians();
        Point3::new([lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin()])
    });
    let sphere = LlSurface::interpolating(&grid, 3, false, true).unwrap();
    for z in [0.0, 0.5, -0.93] {
        for tolerance in [None, Some(1e-3), Some(1e-6)] {
            let p = plane([0.0, 0.0, 1.0], z);
            assert!(
                Sectioner::new(&sphere, &SectionOptions::default())
                    .unwrap()
                    .plane(&p)
                    .fast_path
            );
            let what = format!("z = {z}, {tolerance:?}");
            for cells in [(34, 36), (64, 64)] {
                assert_bound(&sphere, &p, tolerance, cells, &what);
            }
        }
    }
}

#[test]
fn a_tolerance_below_rounding_is_refused_not_split_to_millions_of_points() {
    // A tolerance of 5e-324 used to split every chord 24 times (2^24 points each), which ran
    // the memory out; the torus is about 3 across.
    let torus = &ll_tori()[0];
    for tolerance in [5e-324, 1e-300, 1e-13] {
        let options = SectionOptions {
            tolerance: Some(tolerance),
            ..SectionOptions::default()
        };
        let Err(e) = Sectioner::new(torus, &options) else {
            panic!("a tolerance of {tolerance:e} was accepted");
        };
        assert!(
            e.to_string().contains("below 1e-12 of the surface's size"),
            "{e}"
        );
    }
    let options = SectionOptions {
        tolerance: Some(1e-10),
        ..SectionOptions::default()
    };
    let section = Sectioner::new(torus, &options)
        .unwrap()
        .plane(&plane([0.3, 0.2, 1.0], 0.25));
    let points: usize = section.curves.iter().map(|c| c.points.len()).sum();
    assert!(points > 1000 && points < 1_000_000, "{points}");
}
