//! The monotone rule's path of a wing's placement between sections, and the spanwise pieces
//! refined along it until chord and twist stay within their neighbours' range
//! (docs/methods.md §7.3).
//!
//! A wing section restated on its chord line (`placed_slopes.rs`) is
//! `P_j = O + X q_{j,x} + Y q_{j,y}`: its leading edge `O`, its chord vector `X` (to the
//! trailing edge's middle), its plane's second axis `Y` and the profile's control points `q_j`
//! in that frame. For a wing (every section's plane normal `s` in the `y`-`z` plane, as
//! aerosandbox's `WingXSec` places sections), the chord line's direction is fixed by two
//! angles: the twist `t` about `s` and the roll `psi` of `s = (0, cos psi, sin psi)` about `x`,
//! `X / |X| = (cos t, sin t sin psi, -sin t cos psi)`; the twist is then the chord line's
//! angle from the `x` axis, signed nose up. The path between sections interpolates each of `O`
//! (per coordinate), `|X|`, `Y`'s shear and length, `t`, `psi`, the trailing-edge gap (per
//! world coordinate) and the `q_j` by Fritsch and Carlson's shape-preserving Hermite cubic
//! ([`pchip_from_secants`]) and places them; each profile is mapped by the similarity that
//! keeps its leading edge at `(0, 0)` and its trailing edge's middle at `(1, 0)`. Along the
//! path the leading edge, the chord `|X|` and the twist `t` are exactly their shape-preserving
//! interpolants, within their neighbours' range.
//!
//! The surface is polynomial and the path is not (a chord line turning at constant length
//! draws a circle): the surface is the Hermite cubic of the path's control rows and slopes,
//! at the sections and, where a piece between two rows lets the chord or the twist leave the
//! neighbours' range by more than half the loft's tolerance (the chord by that share of the
//! longer chord, the twist by that many radians: the trailing edge moves by that share of the
//! chord), at the piece's middle too, halving until every piece holds or [`MAX_HALVINGS`]
//! halvings. The leading edge and the trailing-edge gap are cubics of the path that the
//! halving reproduces exactly: the leading edge stays the PCHIP interpolant of the placed
//! leading edges and the gap keeps its sign.
//!
//! Hand-written: the slopes are Fritsch and Carlson's; the rest is the placement's
//! derivative.

#![allow(clippy::needless_range_loop)] // quantities by station

use super::pchip::pchip_from_secants;
use super::placed_slopes::{on_chord_lines, SplitFrame};
use super::placement::{cross, SectionFrame};
use crate::core::Grid;
use crate::spline::hermite_basis;
use crate::{Point2, Point3};

/// Halvings of a piece between sections at most (`2^6` pieces).
const MAX_HALVINGS: usize = 6;
/// Points inside a piece at which its chord and twist are checked (spaced as Chebyshev's
/// extrema, closer at the ends, where an excess lies in a narrow band beside the station).
const CHECKS_PER_PIECE: usize = 48;
/// The largest roll `psi` (radians) of a section's plane the path takes: beyond it the
/// twist measured from the `x` axis loses its sign (a fin), and the rule keeps its slopes.
const MAX_ROLL: f64 = 1.2;

/// A quantity's values at the stations and its shape-preserving slopes.
struct Quantity {
    values: Vec<f64>,
    slopes: Vec<f64>,
}

impl Quantity {
    fn new(h: &[f64], values: Vec<f64>) -> Quantity {
        let delta: Vec<f64> = (0..h.len())
            .map(|k| (values[k + 1] - values[k]) / h[k])
            .collect();
        let mut slopes = vec![0.0; values.len()];
        pchip_from_secants(h, &delta, &mut slopes);
        Quantity { values, slopes }
    }

    /// The value and derivative at `s` (0 to 1) of piece `k` of length `h`.
    #[inline]
    fn at(&self, k: usize, s: f64, h: f64) -> (f64, f64) {
        let c = [
            self.values[k],
            self.slopes[k],
            self.values[k + 1],
            self.slopes[k + 1],
        ];
        let (b0, b1) = (hermite_basis(s, h, 0), hermite_basis(s, h, 1));
        let dot = |b: [f64; 4]| b[0] * c[0] + b[1] * c[1] + b[2] * c[2] + b[3] * c[3];
        (dot(b0), dot(b1))
    }
}

/// A point with its derivative along the span.
type Moving<P> = (P, P);

fn point3_at(q: &[Quantity; 3], k: usize, s: f64, h: f64) -> Moving<Point3> {
    let (a, b, c) = (q[0].at(k, s, h), q[1].at(k, s, h), q[2].at(k, s, h));
    (Point3::new([a.0, b.0, c.0]), Point3::new([a.1, b.1, c.1]))
}

/// The placement path of a wing's sections (see the module docs).
pub(crate) struct WingPath {
    stations: Vec<f64>,
    steps: Vec<f64>,
    origin: [Quantity; 3],
    chord: Quantity,
    shear: Quantity,
    height: Quantity,
    twist: Quantity,
    roll: Quantity,
    gap: [Quantity; 3],
    /// Each control point's plane coordinates (restated on the chord lines).
    plane: Vec<[Quantity; 2]>,
    leading_edge: (usize, [f64; 4]),
}

/// The twist (radians, nose up) of the chord vector `e`: its angle from the `x` axis, positive
/// when it points down (`-z`), the measure of a spanwise line.
pub(crate) fn twist_of(e: Point3) -> f64 {
    let across = e[1].hypot(e[2]) * if e[2] > 0.0 { -1.0 } else { 1.0 };
    across.atan2(e[0])
}

impl WingPath {
    /// The path through the sections placed by `frames` with the control points `profiles`
    /// in their planes (`nets` placed), the leading edge the combination `leading_edge`;
    /// `None` unless every section is placed as a wing's (its plane normal in the `y`-`z`
    /// plane, rolled at most [`MAX_ROLL`], its chord line within 90 degrees of `x`).
    pub(crate) fn new(
        stations: &[f64],
        (frames, profiles): (&[SectionFrame], &Grid<Point2>),
        nets: &Grid<Point3>,
        leading_edge: (usize, [f64; 4]),
    ) -> Option<WingPath> {
        let (frames, profiles) = on_chord_lines(frames, profiles, leading_edge)?;
        let (n, m) = (profiles.rows(), profiles.cols());
        let steps: Vec<f64> = stations.windows(2).map(|w| w[1] - w[0]).collect();
        let split: Vec<SplitFrame> = frames.iter().map(SplitFrame::new).collect::<Option<_>>()?;
        let (mut twist, mut roll) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for f in &split {
            let normal = cross(f.e[1], f.e[0]);
            let psi = normal[2].atan2(normal[1]);
            let size = normal.norm();
            if normal[0].abs() > 1e-9 * size || psi.abs() > MAX_ROLL || f.e[0][0] <= 0.0 {
                return None;
            }
            let (sp, cp) = psi.sin_cos();
            let e = f.e[0];
            twist.push((e[1] * sp - e[2] * cp).atan2(e[0]));
            roll.push(psi);
        }
        let q = |f: &dyn Fn(usize) -> f64| Quantity::new(&steps, (0..n).map(f).collect());
        let gap = |c: usize| q(&|k| nets.get(k, 0)[c] - nets.get(k, m - 1)[c]);
        let plane = (0..m)
            .map(|i| [q(&|k| profiles.get(k, i)[0]), q(&|k| profiles.get(k, i)[1])])
            .collect();
        Some(WingPath {
            origin: [0, 1, 2].map(|c| q(&|k| frames[k].origin[c])),
            chord: q(&|k| split[k].x_len),
            shear: q(&|k| split[k].y1),
            height: q(&|k| split[k].y2),
            twist: Quantity::new(&steps, twist),
            roll: Quantity::new(&steps, roll),
            gap: [gap(0), gap(1), gap(2)],
            plane,
            leading_edge,
            stations: stations.to_vec(),
            steps,
        })
    }

    /// The chord line's frame at `s` of piece `k`: origin, chord vector and second axis, each
    /// with its derivative.
    fn frame_at(&self, k: usize, s: f64) -> [Moving<Point3>; 3] {
        let h = self.steps[k];
        let (rho, d_rho) = self.chord.at(k, s, h);
        let (y1, d_y1) = self.shear.at(k, s, h);
        let (y2, d_y2) = self.height.at(k, s, h);
        let (t, d_t) = self.twist.at(k, s, h);
        let (psi, d_psi) = self.roll.at(k, s, h);
        let ((sp, cp), (st, ct)) = (psi.sin_cos(), t.sin_cos());
        let normal = Point3::new([0.0, cp, sp]);
        let e = Point3::new([ct, st * sp, -st * cp]);
        let up = cross(e, normal);
        let omega = Point3::new([d_psi, 0.0, 0.0]) + normal * d_t;
        let (d_e, d_up) = (cross(omega, e), cross(omega, up));
        let x = (e * rho, e * d_rho + d_e * rho);
        let y = (
            e * y1 + up * y2,
            e * d_y1 + d_e * y1 + up * d_y2 + d_up * y2,
        );
        [point3_at(&self.origin, k, s, h), x, y]
    }

    /// The control row of the path at `s` of piece `k` and its derivative along the span.
    fn row(&self, k: usize, s: f64, values: &mut [Point3], slopes: &mut [Point3]) {
        let h = self.steps[k];
        let [(o, d_o), (x, d_x), (y, d_y)] = self.frame_at(k, s);
        let m = self.plane.len();
        let q: Vec<Moving<Point2>> = self
            .plane
            .iter()
            .map(|[a, b]| {
                let (a, b) = (a.at(k, s, h), b.at(k, s, h));
                (Point2::new([a.0, b.0]), Point2::new([a.1, b.1]))
            })
            .collect();
        let (first, w) = self.leading_edge;
        let (mut le, mut d_le) = (Point2::ZERO, Point2::ZERO);
        for a in 0..4 {
            le = le.add_scaled(w[a], q[first + a].0);
            d_le = d_le.add_scaled(w[a], q[first + a].1);
        }
        // The similarity z -> (z - le) / (mid - le) of the plane (complex numbers).
        let chord = (q[0].0 + q[m - 1].0) * 0.5 - le;
        let d_chord = (q[0].1 + q[m - 1].1) * 0.5 - d_le;
        for i in 0..m {
            let (z, d_z) = (q[i].0 - le, q[i].1 - d_le);
            let f = divide(z, chord);
            let d_f = divide(d_z, chord) - divide(multiply(z, d_chord), multiply(chord, chord));
            values[i] = o + x * f[0] + y * f[1];
            slopes[i] = d_o + d_x * f[0] + d_y * f[1] + x * d_f[0] + y * d_f[1];
        }
        let (g, d_g) = point3_at(&self.gap, k, s, h);
        let (mid, d_mid) = (o + x, d_o + d_x);
        (values[0], slopes[0]) = (mid + g * 0.5, d_mid + d_g * 0.5);
        (values[m - 1], slopes[m - 1]) = (mid - g * 0.5, d_mid - d_g * 0.5);
    }

    /// The path's slopes of every control point at the stations.
    pub(crate) fn station_slopes(&self) -> Grid<Point3> {
        let (n, m) = (self.stations.len(), self.plane.len());
        let mut slopes = Grid::from_fn(n, m, |_, _| Point3::ZERO);
        let mut values = vec![Point3::ZERO; m];
        let mut row = vec![Point3::ZERO; m];
        for k in 0..n {
            let (piece, s) = if k + 1 < n { (k, 0.0) } else { (k - 1, 1.0) };
            self.row(piece, s, &mut values, &mut row);
            for i in 0..m {
                *slopes.get_mut(k, i) = row[i];
            }
        }
        slopes
    }
}

fn multiply(a: Point2, b: Point2) -> Point2 {
    Point2::new([a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]])
}

fn divide(a: Point2, b: Point2) -> Point2 {
    let n = b.dot(b);
    Point2::new([
        (a[0] * b[0] + a[1] * b[1]) / n,
        (a[1] * b[0] - a[0] * b[1]) / n,
    ])
}

/// The spanwise rows of a refined surface: their parameters, control rows and slopes.
pub(crate) struct Rows {
    pub stations: Vec<f64>,
    pub values: Vec<Point3>,
    pub slopes: Vec<Point3>,
}

/// One row of a piece being refined: where it is in its piece, its values and slopes.
struct Row {
    s: f64,
    values: Vec<Point3>,
    slopes: Vec<Point3>,
}

impl WingPath {
    /// The rows of the surface through `nets` with the station `slopes`: the stations, and
    /// inside every piece whose chord or twist leaves the neighbours' range by more than
    /// half of `tolerance` the path's rows at the halvings (see the module docs).
    pub(crate) fn refine(
        &self,
        nets: &Grid<Point3>,
        slopes: &Grid<Point3>,
        tolerance: f64,
    ) -> Rows {
        let (n, m) = (nets.rows(), nets.cols());
        let station_row = |k: usize, s: f64| Row {
            s,
            values: nets.row(k).to_vec(),
            slopes: slopes.row(k).to_vec(),
        };
        let mut rows = Rows {
            stations: Vec::with_capacity(n),
            values: Vec::with_capacity(n * m),
            slopes: Vec::with_capacity(n * m),
        };
        let push = |rows: &mut Rows, k: usize, r: &Row| {
            rows.stations.push(self.stations[k] + r.s * self.steps[k]);
            rows.values.extend_from_slice(&r.values);
            rows.slopes.extend_from_slice(&r.slopes);
        };
        for k in 0..n - 1 {
            let (a, b) = (station_row(k, 0.0), station_row(k + 1, 1.0));
            push(&mut rows, k, &a);
            let mut inside = Vec::new();
            self.halve(k, (&a, &b), 0.5 * tolerance, MAX_HALVINGS, &mut inside);
            for r in &inside {
                push(&mut rows, k, r);
            }
        }
        rows.stations.push(self.stations[n - 1]);
        rows.values.extend_from_slice(nets.row(n - 1));
        rows.slopes.extend_from_slice(slopes.row(n - 1));
        rows
    }

    /// Appends to `inside`, in order, the rows that piece `k` needs between `a` and `b`.
    fn halve(
        &self,
        k: usize,
        (a, b): (&Row, &Row),
        slack: f64,
        depth: usize,
        inside: &mut Vec<Row>,
    ) {
        if depth == 0 || self.holds(k, (a, b), slack) {
            return;
        }
        let m = self.plane.len();
        let s = 0.5 * (a.s + b.s);
        let mut mid = Row {
            s,
            values: vec![Point3::ZERO; m],
            slopes: vec![Point3::ZERO; m],
        };
        self.row(k, s, &mut mid.values, &mut mid.slopes);
        self.halve(k, (a, &mid), slack, depth - 1, inside);
        let mut after = Vec::new();
        self.halve(k, (&mid, b), slack, depth - 1, &mut after);
        inside.push(mid);
        inside.append(&mut after);
    }

    /// True when the Hermite piece between rows `a` and `b` of piece `k` keeps the chord
    /// within `slack` times the longer neighbouring chord of the range of the two sections'
    /// chords, and the twist within `slack` radians of theirs.
    fn holds(&self, k: usize, (a, b): (&Row, &Row), slack: f64) -> bool {
        let m = self.plane.len();
        let (first, w) = self.leading_edge;
        // The chord vector (trailing edge's middle minus leading edge) of a row, and its slope.
        let chord_of = |r: &Row| {
            let mut e = (r.values[0] + r.values[m - 1]) * 0.5;
            let mut d = (r.slopes[0] + r.slopes[m - 1]) * 0.5;
            for j in 0..4 {
                e = e.add_scaled(-w[j], r.values[first + j]);
                d = d.add_scaled(-w[j], r.slopes[first + j]);
            }
            (e, d)
        };
        let ((ea, da), (eb, db)) = (chord_of(a), chord_of(b));
        let (c0, c1) = (self.chord.values[k], self.chord.values[k + 1]);
        let (t0, t1) = (self.twist.values[k], self.twist.values[k + 1]);
        let chord_slack = slack * c0.max(c1);
        let h = (b.s - a.s) * self.steps[k];
        (1..CHECKS_PER_PIECE).all(|j| {
            let at = std::f64::consts::PI * j as f64 / CHECKS_PER_PIECE as f64;
            let basis = hermite_basis(0.5 * (1.0 - at.cos()), h, 0);
            let e = ea * basis[0] + da * basis[1] + eb * basis[2] + db * basis[3];
            let (chord, twist) = (e.norm(), twist_of(e));
            chord >= c0.min(c1) - chord_slack
                && chord <= c0.max(c1) + chord_slack
                && twist >= t0.min(t1) - slack
                && twist <= t0.max(t1) + slack
        })
    }
}
