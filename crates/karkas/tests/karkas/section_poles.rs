//! Sections through poles (docs/methods.md §1.4): a border line of the parameter domain that is
//! one point in space (the nose or tail of a body of revolution). A plane through the pole
//! cuts one curve through it, not pieces along the collapsed line: no zero-length pieces, no
//! warnings of a plane touching the surface, the two arcs that meet at the pole joined into
//! one curve; whether the pole is the first border line, the last, or both; and along either
//! parameter.

use karkas::ll::LlSurface;
use karkas::section::{
    LevelFunction, Plane, Section, SectionCurve, SectionOptions, SectionWarning, Sectioner,
};
use karkas::{Grid, Interval, Point3, Surface};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

fn sin_k(t: f64, k: usize) -> f64 {
    (t + k as f64 * FRAC_PI_2).sin()
}
fn cos_k(t: f64, k: usize) -> f64 {
    (t + k as f64 * FRAC_PI_2).cos()
}

/// The prolate spheroid `x = 2 cos(theta)`, `y = sin(theta) cos(phi)`, `z = sin(theta)
/// sin(phi)` in closed form, `theta` over `[first, last]` (open; `0` and `pi` are poles),
/// `phi` over a turn (closed). With `swapped`, `theta` is the parameter `v` and `phi` is `u`.
struct Spheroid {
    theta: (f64, f64),
    swapped: bool,
}

impl Spheroid {
    fn polar(&self, theta: f64, phi: f64, kt: usize, kp: usize) -> Point3 {
        let x = if kp == 0 { 2.0 * cos_k(theta, kt) } else { 0.0 };
        Point3::new([
            x,
            sin_k(theta, kt) * cos_k(phi, kp),
            sin_k(theta, kt) * sin_k(phi, kp),
        ])
    }
}

impl Surface<3> for Spheroid {
    fn domain_u(&self) -> Interval {
        if self.swapped {
            Interval::new(0.0, TAU)
        } else {
            Interval::new(self.theta.0, self.theta.1)
        }
    }
    fn domain_v(&self) -> Interval {
        if self.swapped {
            Interval::new(self.theta.0, self.theta.1)
        } else {
            Interval::new(0.0, TAU)
        }
    }
    fn is_closed_u(&self) -> bool {
        self.swapped
    }
    fn is_closed_v(&self) -> bool {
        !self.swapped
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.deriv(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        if self.swapped {
            self.polar(v, u, kv, ku)
        } else {
            self.polar(u, v, ku, kv)
        }
    }
}

fn plane(n: [f64; 3], c: f64) -> Plane<3> {
    Plane::new(Point3::new(n), c).unwrap()
}

const NOSE: Point3 = Point3::new([2.0, 0.0, 0.0]);
const TAIL: Point3 = Point3::new([-2.0, 0.0, 0.0]);

/// The length of the arc `theta in [a, b]` of the ellipse `(2 cos theta, sin theta)`, by the
/// composite Simpson rule on 20 000 intervals (exact to about 1e-15 here).
fn ellipse_arc(a: f64, b: f64) -> f64 {
    let n = 20_000;
    let h = (b - a) / n as f64;
    let speed = |t: f64| (4.0 * t.sin().powi(2) + t.cos().powi(2)).sqrt();
    let inner: f64 = (1..n)
        .map(|k| speed(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    h / 3.0 * (speed(a) + inner + speed(b))
}

/// The chords of a curve, the closing one included.
fn chords(curve: &SectionCurve<3>) -> Vec<(Point3, Point3)> {
    let n = curve.points.len();
    let mut out: Vec<_> = curve.points.windows(2).map(|w| (w[0], w[1])).collect();
    if curve.closed {
        out.push((curve.points[n - 1], curve.points[0]));
    }
    out
}

/// Every point on the plane and the surface's point at its parameters; no chord of zero
/// length; no warning at all.
fn assert_clean<S: Surface<3>>(surface: &S, p: &Plane<3>, section: &Section<3>, what: &str) {
    assert!(
        section.warnings.is_empty(),
        "{what}: {:?}",
        section.warnings
    );
    for curve in &section.curves {
        for (&(u, v), &q) in curve.params.iter().zip(&curve.points) {
            assert!(p.value(q).abs() < 1e-12, "{what}: {q:?} off the plane");
            assert_eq!(surface.eval(u, v), q, "{what}");
        }
        for (a, b) in chords(curve) {
            assert!(a.distance(b) > 1e-9, "{what}: a zero-length chord at {a:?}");
        }
    }
}

/// How many points of `curve` are `target` (to 1e-12).
fn visits(curve: &SectionCurve<3>, target: Point3) -> usize {
    curve
        .points
        .iter()
        .filter(|q| q.distance(target) < 1e-12)
        .count()
}

/// Planes through the axis of the spheroid (so through both poles): the meridian ellipse.
const MERIDIAN_PLANES: [[f64; 3]; 3] = [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [0.0, 0.3, 1.0]];

#[test]
fn a_plane_through_both_poles_cuts_one_closed_loop() {
    let tolerance = 1e-5;
    let options = SectionOptions {
        tolerance: Some(tolerance),
        ..SectionOptions::default()
    };
    for swapped in [false, true] {
        let body = Spheroid {
            theta: (0.0, PI),
            swapped,
        };
        let sectioner = Sectioner::new(&body, &options).unwrap();
        for n in MERIDIAN_PLANES {
            let what = format!("swapped {swapped}, plane {n:?}");
            let p = plane(n, 0.0);
            let section = sectioner.plane(&p);
            assert_clean(&body, &p, &section, &what);
            assert_eq!(section.curves.len(), 1, "{what}: {section:?}");
            let curve = &section.curves[0];
            assert!(curve.closed, "{what}");
            assert_eq!(visits(curve, NOSE), 1, "{what}");
            assert_eq!(visits(curve, TAIL), 1, "{what}");
            let full = 2.0 * ellipse_arc(0.0, PI);
            assert!(
                (curve.length() - full).abs() < 1e-3,
                "{what}: {} vs {full}",
                curve.length()
            );
        }
    }
}

#[test]
fn a_plane_through_one_pole_cuts_one_curve_through_it() {
    let options = SectionOptions {
        tolerance: Some(1e-5),
        ..SectionOptions::default()
    };
    // (theta range, the pole in it, the angle at the open end)
    let cases = [
        ((0.0, 2.0 * PI / 3.0), NOSE, 2.0 * PI / 3.0),
        ((PI / 3.0, PI), TAIL, PI / 3.0),
    ];
    for swapped in [false, true] {
        for (theta, pole, open_end) in cases {
            let body = Spheroid { theta, swapped };
            let sectioner = Sectioner::new(&body, &options).unwrap();
            for n in MERIDIAN_PLANES {
                let what = format!("theta {theta:?}, swapped {swapped}, plane {n:?}");
                let p = plane(n, 0.0);
                let section = sectioner.plane(&p);
                assert_clean(&body, &p, &section, &what);
                assert_eq!(section.curves.len(), 1, "{what}: {section:?}");
                let curve = &section.curves[0];
                assert!(!curve.closed, "{what}");
                assert_eq!(visits(curve, pole), 1, "{what}");
                // Both ends on the open border, at x = 2 cos(open_end).
                let ends = [curve.points[0], curve.points[curve.points.len() - 1]];
                for end in ends {
                    assert!((end[0] - 2.0 * open_end.cos()).abs() < 1e-12, "{what}");
                }
                let arc = 2.0 * ellipse_arc(0.0, theta.1 - theta.0);
                assert!(
                    (curve.length() - arc).abs() < 1e-3,
                    "{what}: {} vs {arc}",
                    curve.length()
                );
            }
        }
    }
}

#[test]
fn planes_off_the_poles_and_touching_them() {
    let body = Spheroid {
        theta: (0.0, PI),
        swapped: false,
    };
    let sectioner = Sectioner::new(&body, &SectionOptions::default()).unwrap();
    // Off the poles: one closed loop each, as before.
    for (n, c) in [
        ([1.0, 0.0, 0.0], 1.0),
        ([0.3, 0.0, 1.0], 0.2),
        ([1.0, 0.0, 0.0], 1.99),
    ] {
        let p = plane(n, c);
        let section = sectioner.plane(&p);
        assert_clean(&body, &p, &section, &format!("{n:?} {c}"));
        assert_eq!(section.curves.len(), 1);
        assert!(section.curves[0].closed);
    }
    // x = 2 and x = -2 touch the spheroid at its poles only: no curve, one warning at the pole.
    for (c, theta) in [(2.0, 0.0), (-2.0, PI)] {
        let section = sectioner.plane(&plane([1.0, 0.0, 0.0], c));
        assert!(section.curves.is_empty(), "x = {c}: {section:?}");
        assert_eq!(section.warnings.len(), 1, "x = {c}");
        assert!(matches!(
            section.warnings[0],
            SectionWarning::SingularPoint { u, .. } if u == theta
        ));
    }
}

/// The LL surface of a spheroid's grid whose first and last rows are its poles (each row one
/// repeated point), on both paths of a section.
#[test]
fn ll_surfaces_with_collapsed_rows_cut_through_their_poles() {
    let grid = Grid::from_fn(7, 9, |i, j| {
        let (theta, phi) = (PI * i as f64 / 6.0, TAU * (j % 8) as f64 / 8.0);
        Point3::new([
            2.0 * theta.cos(),
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
        ])
    });
    for surface in [
        LlSurface::new(&grid, 3, false, true).unwrap(),
        LlSurface::interpolating(&grid, 3, false, true).unwrap(),
    ] {
        let nose = surface.eval(surface.domain_u().start, 0.0);
        let tail = surface.eval(surface.domain_u().end, 0.0);
        let sectioner = Sectioner::new(&surface, &SectionOptions::default()).unwrap();
        for n in MERIDIAN_PLANES {
            let p = plane(n, 0.0);
            let section = sectioner.plane(&p);
            assert_clean(&surface, &p, &section, &format!("{n:?}"));
            assert_eq!(section.curves.len(), 1, "{n:?}: {section:?}");
            assert!(section.curves[0].closed);
            assert_eq!(visits(&section.curves[0], nose), 1);
            assert_eq!(visits(&section.curves[0], tail), 1);
        }
    }
}
