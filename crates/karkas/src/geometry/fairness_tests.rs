//! The fairness figures against closed forms and independent quadrature.

use super::fairness::{curve_fairness, sampled_fairness_energy};
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
use crate::Point;
use std::f64::consts::PI;

/// A curve given by a closed form of its derivatives, one piece.
struct Closed<const D: usize> {
    f: fn(f64, usize) -> Point<D>,
    domain: Interval,
    closed: bool,
}

impl<const D: usize> Curve<D> for Closed<D> {
    fn domain(&self) -> Interval {
        self.domain
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn eval(&self, t: f64) -> Point<D> {
        (self.f)(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        (self.f)(t, k)
    }
}

impl<const D: usize> PiecewiseCurve<D> for Closed<D> {
    fn breakpoints(&self) -> Vec<f64> {
        vec![self.domain.start, self.domain.end]
    }
    fn continuity(&self) -> usize {
        usize::MAX
    }
    fn deriv_on_side(&self, t: f64, k: usize, _side: Side) -> Point<D> {
        (self.f)(t, k)
    }
}

/// The graph `(x, y(x))` of a piecewise polynomial: pieces `(a, b, coefficients in x)`.
struct Graph(Vec<(f64, f64, Vec<f64>)>);

impl Graph {
    fn piece(&self, t: f64, side: Side) -> &[f64] {
        let i = match side {
            Side::Above => self.0.iter().rposition(|p| p.0 <= t),
            Side::Below => self.0.iter().position(|p| p.1 >= t),
        };
        &self.0[i.unwrap_or(0)].2
    }
    fn value(c: &[f64], x: f64, k: usize) -> f64 {
        (k..c.len())
            .map(|i| {
                c[i] * ((i - k + 1)..=i).map(|j| j as f64).product::<f64>() * x.powi((i - k) as i32)
            })
            .sum()
    }
}

impl Curve<2> for Graph {
    fn domain(&self) -> Interval {
        Interval::new(self.0[0].0, self.0[self.0.len() - 1].1)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval(&self, t: f64) -> Point<2> {
        self.deriv(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point<2> {
        self.deriv_on_side(t, k, Side::Above)
    }
}

impl PiecewiseCurve<2> for Graph {
    fn breakpoints(&self) -> Vec<f64> {
        let mut b: Vec<f64> = self.0.iter().map(|p| p.0).collect();
        b.push(self.domain().end);
        b
    }
    fn continuity(&self) -> usize {
        1
    }
    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<2> {
        let x = match k {
            0 => t,
            1 => 1.0,
            _ => 0.0,
        };
        Point([x, Graph::value(self.piece(t, side), t, k)])
    }
}

/// The number of local extrema of `f` on `[a, b]` seen on `n` even steps (sign changes of
/// its differences).
fn grid_extrema(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> usize {
    let v: Vec<f64> = (0..=n)
        .map(|i| f(a + (b - a) * i as f64 / n as f64))
        .collect();
    let d: Vec<f64> = v
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| d.abs() > 1e-15)
        .collect();
    d.windows(2)
        .filter(|w| (w[0] > 0.0) != (w[1] > 0.0))
        .count()
}

/// The curvature of the graph of `y` (with derivatives `y1`, `y2`) at `x`.
fn graph_curvature(y1: f64, y2: f64) -> f64 {
    y2 / (1.0 + y1 * y1).powf(1.5)
}

/// `∫ (dκ/ds)^2 ds` of a graph by Simpson's rule, `dκ/dx` by central differences.
fn graph_energy(k: impl Fn(f64) -> f64, y1: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let n = 20_000;
    let h = (b - a) / n as f64;
    let e = 1e-5;
    let g = |x: f64| {
        let dk = (k(x + e) - k(x - e)) / (2.0 * e);
        let speed = (1.0 + y1(x) * y1(x)).sqrt();
        dk * dk / speed
    };
    let inner = |x: f64| g(x.clamp(a + e, b - e));
    (0..=n)
        .map(|i| {
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * inner(a + h * i as f64)
        })
        .sum::<f64>()
        * h
        / 3.0
}

fn circle(t: f64, k: usize) -> Point<2> {
    let (s, c) = t.sin_cos();
    let r = 2.0;
    let p = match k % 4 {
        0 => Point([c, s]),
        1 => Point([-s, c]),
        2 => Point([-c, -s]),
        _ => Point([s, -c]),
    } * r;
    if k == 0 {
        p + Point([3.0, -1.0])
    } else {
        p
    }
}

fn ellipse(t: f64, k: usize) -> Point<2> {
    let (s, c) = t.sin_cos();
    let u = match k % 4 {
        0 => [c, s],
        1 => [-s, c],
        2 => [-c, -s],
        _ => [s, -c],
    };
    Point([3.0 * u[0], u[1]])
}

#[test]
fn a_circle_has_constant_curvature_no_extrema_and_no_energy() {
    let curve = Closed {
        f: circle,
        domain: Interval::new(0.0, 2.0 * PI),
        closed: true,
    };
    let n = 12;
    let polygon: Vec<Point<2>> = (0..n)
        .map(|i| circle(2.0 * PI * i as f64 / n as f64, 0))
        .collect();
    let f = curve_fairness(&curve, &polygon);
    assert!((f.length - 4.0 * PI).abs() < 1e-10, "{f:?}");
    assert!((f.curvature_min - 0.5).abs() < 1e-12 && (f.curvature_max - 0.5).abs() < 1e-12);
    assert_eq!((f.curvature_extrema, f.inflections), (0, 0));
    assert!(f.fairness_energy < 1e-20, "{f:?}");
    let sagitta = 2.0 * (1.0 - (PI / n as f64).cos());
    assert!((f.max_distance_to_polygon - sagitta).abs() < 1e-10, "{f:?}");
}

#[test]
fn an_ellipse_has_four_extrema_and_its_energy_by_independent_quadrature() {
    let (a, b) = (3.0f64, 1.0f64);
    let curve = Closed {
        f: ellipse,
        domain: Interval::new(0.0, 2.0 * PI),
        closed: true,
    };
    let f = curve_fairness(&curve, &[]);
    assert_eq!((f.curvature_extrema, f.inflections), (4, 0));
    assert!((f.curvature_min - b / (a * a)).abs() < 1e-12, "{f:?}");
    assert!((f.curvature_max - a / (b * b)).abs() < 1e-12, "{f:?}");
    assert!(f.max_distance_to_polygon.is_nan());
    // Periodic trapezoid rule (spectrally accurate) on the closed form
    // κ(θ) = a b / D^{3/2}, D = a² sin² θ + b² cos² θ, ds = sqrt(D) dθ.
    let n = 4000;
    let energy: f64 = (0..n)
        .map(|i| {
            let th = 2.0 * PI * i as f64 / n as f64;
            let (s, c) = th.sin_cos();
            let d = a * a * s * s + b * b * c * c;
            let dd = 2.0 * (a * a - b * b) * s * c;
            let dk = -1.5 * a * b * d.powf(-2.5) * dd;
            dk * dk / d.sqrt()
        })
        .sum::<f64>()
        * 2.0
        * PI
        / n as f64;
    assert!(
        (f.fairness_energy - energy).abs() < 1e-9 * energy,
        "{} {energy}",
        f.fairness_energy
    );
    // The perimeter by the same rule.
    let perimeter: f64 = (0..n)
        .map(|i| {
            let (s, c) = (2.0 * PI * i as f64 / n as f64).sin_cos();
            (a * a * s * s + b * b * c * c).sqrt()
        })
        .sum::<f64>()
        * 2.0
        * PI
        / n as f64;
    assert!((f.length - perimeter).abs() < 1e-10 * perimeter);
}

#[test]
fn the_sampled_energy_is_near_the_exact_one_on_smooth_curves() {
    let ellipse = Closed {
        f: ellipse,
        domain: Interval::new(0.0, 2.0 * PI),
        closed: true,
    };
    let exact = curve_fairness(&ellipse, &[]).fairness_energy;
    let sampled = sampled_fairness_energy(&ellipse);
    assert!((sampled - exact).abs() < 0.02 * exact, "{sampled} {exact}");
    // y = x³ - x, the graph of the test below: its energy from the independent quadrature.
    let cubic = Graph(vec![(-1.5, 1.5, vec![0.0, -1.0, 0.0, 1.0])]);
    let y1 = |x: f64| 3.0 * x * x - 1.0;
    let exact = graph_energy(|x| graph_curvature(y1(x), 6.0 * x), y1, -1.5, 1.5);
    let sampled = sampled_fairness_energy(&cubic);
    assert!((sampled - exact).abs() < 0.05 * exact, "{sampled} {exact}");
}

#[test]
fn a_cubic_has_one_inflection_and_its_extrema_and_energy_match_the_closed_form() {
    // y = x³ - x on [-1.5, 1.5]: one inflection at 0.
    let curve = Graph(vec![(-1.5, 1.5, vec![0.0, -1.0, 0.0, 1.0])]);
    let y1 = |x: f64| 3.0 * x * x - 1.0;
    let k = |x: f64| graph_curvature(y1(x), 6.0 * x);
    let f = curve_fairness(&curve, &[]);
    assert_eq!(f.inflections, 1);
    let expected = grid_extrema(k, -1.5, 1.5, 200_000);
    assert!(expected >= 2);
    assert_eq!(f.curvature_extrema, expected, "{f:?}");
    let energy = graph_energy(k, y1, -1.5, 1.5);
    assert!(
        (f.fairness_energy - energy).abs() < 1e-6 * energy,
        "{} {energy}",
        f.fairness_energy
    );
    let grid_max = (0..=200_000)
        .map(|i| k(-1.5 + 3.0 * i as f64 / 200_000.0))
        .fold(f64::MIN, f64::max);
    assert!(
        (f.curvature_max - grid_max).abs() < 1e-8 && f.curvature_max >= grid_max,
        "{f:?}"
    );
    assert!((f.curvature_min + f.curvature_max).abs() < 1e-12);
}

#[test]
fn an_extremum_on_a_knot_counts() {
    // y = x² - x³ on [-1, 0], x² + x³ on [0, 1]: C², κ has a corner minimum at the knot 0
    // (dκ/ds jumps from negative to positive) and a maximum on each side.
    let curve = Graph(vec![
        (-1.0, 0.0, vec![0.0, 0.0, 1.0, -1.0]),
        (0.0, 1.0, vec![0.0, 0.0, 1.0, 1.0]),
    ]);
    let y1 = |x: f64| 2.0 * x + 3.0 * x * x.abs();
    let k = |x: f64| graph_curvature(y1(x), 2.0 + 6.0 * x.abs());
    let expected = grid_extrema(k, -1.0, 1.0, 200_001);
    assert_eq!(expected, 3);
    let f = curve_fairness(&curve, &[]);
    assert_eq!((f.curvature_extrema, f.inflections), (3, 0), "{f:?}");
    assert!(f.curvature_jump < 1e-12);
}

#[test]
fn an_s_curve_has_one_inflection_and_the_extrema_of_its_closed_form() {
    fn sine(t: f64, k: usize) -> Point<2> {
        let (s, c) = t.sin_cos();
        let y = [s, c, -s, -c][k % 4];
        Point([
            if k == 0 {
                t
            } else if k == 1 {
                1.0
            } else {
                0.0
            },
            y,
        ])
    }
    let curve = Closed {
        f: sine,
        domain: Interval::new(0.0, 2.0 * PI),
        closed: false,
    };
    let f = curve_fairness(&curve, &[Point([0.0, 0.0]), Point([2.0 * PI, 0.0])]);
    assert_eq!(f.inflections, 1, "{f:?}");
    let k = |x: f64| graph_curvature(x.cos(), -x.sin());
    assert_eq!(f.curvature_extrema, grid_extrema(k, 0.0, 2.0 * PI, 200_000));
    assert!((f.max_distance_to_polygon - 1.0).abs() < 1e-12, "{f:?}");
    assert!((f.curvature_min + 1.0).abs() < 1e-12 && (f.curvature_max - 1.0).abs() < 1e-12);
}

#[test]
fn a_helix_has_constant_curvature() {
    fn helix(t: f64, k: usize) -> Point<3> {
        let (s, c) = t.sin_cos();
        let u = [[c, s], [-s, c], [-c, -s], [s, -c]][k % 4];
        let z = match k {
            0 => 0.5 * t,
            1 => 0.5,
            _ => 0.0,
        };
        Point([u[0], u[1], z])
    }
    let curve = Closed {
        f: helix,
        domain: Interval::new(0.0, 4.0 * PI),
        closed: false,
    };
    let f = curve_fairness(&curve, &[]);
    // κ = r / (r² + c²) with r = 1, c = 0.5.
    assert!((f.curvature_min - 0.8).abs() < 1e-12 && (f.curvature_max - 0.8).abs() < 1e-12);
    assert_eq!((f.curvature_extrema, f.inflections), (0, 0));
    assert!(f.fairness_energy < 1e-20);
    assert!((f.length - 4.0 * PI * 1.25f64.sqrt()).abs() < 1e-10);
}
