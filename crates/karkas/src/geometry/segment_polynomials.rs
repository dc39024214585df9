//! The curve on each segment of the projector's polyline as an explicit polynomial, with the
//! bounds that make the squared distance to a point provably convex there.
//!
//! A segment `[t_j, t_{j+1}]` lies inside one polynomial piece of degree `n`, where the curve
//! equals its Taylor polynomial about the midpoint `m_j` in `v = (t - m_j) / h_j` (`h_j` the
//! half width): `P = Σ_k c_k v^k`, `c_k = P^(k)(m_j) h_j^k / k!`. For `|v| <= 1`:
//! - `|P''(v)| <= A_j = Σ_{k>=2} k (k - 1) |c_k|` (derivatives in `v`),
//! - `|P'(v)| >= S_j = |c_1| - Σ_{k>=2} k |c_k|`,
//! - `|P(v) - c_0| <= R_j = Σ_{k>=1} |c_k|`.
//!
//! For a query `q`, `g(v) = (P(v) - q) . P'(v)` (half the derivative of `|P - q|^2`) has
//! `g' = |P'|^2 + (P - q) . P'' >= S_j^2 - (|q - c_0| + R_j) A_j`: where that is positive, `g`
//! increases across the segment and `|P - q|^2` is strictly convex on it. Across a joint where
//! the curve's tangent is continuous, `g` is continuous, so a run of such segments has at most
//! one local minimum of the distance (`nearest_grid` builds on this).
//!
//! The coefficients are checked against the curve itself at five points of every segment; a
//! curve whose derivatives do not give back its values (not a polynomial of the stated degree,
//! or coefficients out of floating-point range at extreme scales) gets no polynomials, and its
//! projection keeps to the general search.

use super::curve_nearest::bracketed_newton;
use crate::core::Curve;
use crate::Point;

/// The highest degree handled; higher pieces keep to the general search.
const MAX_DEGREE: usize = 15;
/// How far a polynomial may stray from the curve's own value, relative to the segment's size.
const MATCH_TOLERANCE: f64 = 1e-9;
/// How close the tangents on either side of a joint must be (relative) for `g` to count as
/// continuous there.
const JOINT_TOLERANCE: f64 = 1e-8;

/// The local polynomials of every polyline segment, and their bounds.
pub(super) struct SegmentPolynomials<const D: usize> {
    degree: usize,
    /// `c_0 .. c_n` of segment `j` at `j (n + 1) ..`.
    coefficients: Vec<Point<D>>,
    /// Midpoint and half width of each segment, in the curve's parameter.
    mids: Vec<f64>,
    halves: Vec<f64>,
    /// `S_j^2` (zero when `S_j <= 0`), `A_j`, `R_j`.
    speed_sq: Vec<f64>,
    bend: Vec<f64>,
    spread: Vec<f64>,
    /// `P(-1), P'(-1), P(1), P'(1)` of each segment (derivatives in `v`).
    ends: Vec<[Point<D>; 4]>,
    /// Whether the tangent is continuous at the start of segment `j` (for `j = 0`: across the
    /// seam of a closed curve).
    smooth_start: Vec<bool>,
}

impl<const D: usize> SegmentPolynomials<D> {
    /// The polynomials of the segments between consecutive `params` (a polyline of `curve`
    /// that subdivides its pieces); `None` when the curve does not tell its pieces, has too
    /// high a degree, or its derivatives do not reproduce its values.
    pub(super) fn new<C: Curve<D> + ?Sized>(
        curve: &C,
        params: &[f64],
        closed: bool,
    ) -> Option<Self> {
        let degree = curve.polynomial_pieces()?.degree;
        if degree == 0 || degree > MAX_DEGREE || params.len() < 2 {
            return None;
        }
        let segments = params.len() - 1;
        let mut this = SegmentPolynomials {
            degree,
            coefficients: Vec::with_capacity(segments * (degree + 1)),
            mids: Vec::with_capacity(segments),
            halves: Vec::with_capacity(segments),
            speed_sq: Vec::with_capacity(segments),
            bend: Vec::with_capacity(segments),
            spread: Vec::with_capacity(segments),
            ends: Vec::with_capacity(segments),
            smooth_start: vec![false; segments],
        };
        for w in params.windows(2) {
            this.push_segment(curve, w[0], w[1])?;
        }
        for j in 0..segments {
            let before = match (j, closed) {
                (0, false) => continue,
                (0, true) => segments - 1,
                _ => j - 1,
            };
            let left = this.ends[before][3] * (1.0 / this.halves[before]);
            let right = this.ends[j][1] * (1.0 / this.halves[j]);
            let scale = left.norm().max(right.norm());
            this.smooth_start[j] = scale > 0.0 && left.distance(right) <= JOINT_TOLERANCE * scale;
        }
        Some(this)
    }

    /// Appends the segment `[a, b]`; `None` when its polynomial does not match the curve.
    fn push_segment<C: Curve<D> + ?Sized>(&mut self, curve: &C, a: f64, b: f64) -> Option<()> {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        if half.is_nan() || half <= 0.0 {
            return None;
        }
        let n = self.degree;
        let start = self.coefficients.len();
        let mut scale = 1.0;
        for k in 0..=n {
            if k > 0 {
                scale *= half / k as f64;
            }
            self.coefficients.push(curve.deriv(mid, k) * scale);
        }
        let c = &self.coefficients[start..];
        if c.iter().any(|p| !p.is_finite()) {
            return None;
        }
        let size = |k: usize| c[k].norm();
        let spread: f64 = (1..=n).map(size).sum();
        let bend: f64 = (2..=n).map(|k| (k * (k - 1)) as f64 * size(k)).sum();
        let speed = size(1) - (2..=n).map(|k| k as f64 * size(k)).sum::<f64>();
        let tolerance = MATCH_TOLERANCE * (spread + 1e-3 * c[0].norm()) + f64::MIN_POSITIVE;
        for v in [-1.0, -0.5, 0.0, 0.5, 1.0] {
            let at = if v == -1.0 {
                a
            } else if v == 1.0 {
                b
            } else {
                mid + v * half
            };
            // The curve's value at a segment end may come from the next piece: the curve is
            // continuous, so the two agree to rounding.
            if self.jet_of(c, v)[0].distance(curve.eval(at)) > tolerance {
                return None;
            }
        }
        let [p0, d0, _] = self.jet_of(c, -1.0);
        let [p1, d1, _] = self.jet_of(c, 1.0);
        self.ends.push([p0, d0, p1, d1]);
        self.mids.push(mid);
        self.halves.push(half);
        self.spread.push(spread);
        self.bend.push(bend);
        self.speed_sq
            .push(if speed > 0.0 { speed * speed } else { 0.0 });
        Some(())
    }

    /// `[P, P', P'']` (in `v`) of the polynomial with coefficients `c` at `v`, by Horner.
    #[inline]
    fn jet_of(&self, c: &[Point<D>], v: f64) -> [Point<D>; 3] {
        let n = self.degree;
        let (mut p, mut d1, mut d2) = (c[n], Point::ZERO, Point::ZERO);
        for k in (0..n).rev() {
            d2 = d2 * v + d1;
            d1 = d1 * v + p;
            p = p * v + c[k];
        }
        [p, d1, d2 * 2.0]
    }

    /// `[P, P', P'']` of segment `j` at `v`.
    #[inline]
    pub(super) fn jet(&self, j: usize, v: f64) -> [Point<D>; 3] {
        let n = self.degree + 1;
        self.jet_of(&self.coefficients[j * n..(j + 1) * n], v)
    }

    /// `g` at the start (`v = -1`) and at the end (`v = 1`) of segment `j`.
    #[inline]
    pub(super) fn end_slopes(&self, j: usize, q: Point<D>) -> (f64, f64) {
        let [p0, d0, p1, d1] = self.ends[j];
        ((p0 - q).dot(d0), (p1 - q).dot(d1))
    }

    /// The ends `P(-1)`, `P(1)` of segment `j`'s polynomial.
    #[inline]
    pub(super) fn end_points(&self, j: usize) -> [Point<D>; 2] {
        let [p0, _, p1, _] = self.ends[j];
        [p0, p1]
    }

    /// True when `|P - x|^2` is strictly convex on segment `j` for every `x` within `radius`
    /// of `centre`: with `x = centre + e`, `|e| <= radius`, and `P'' = 2 c_2 + E(v)`,
    /// `|E| <= A3 = Σ_{k>=3} k (k - 1) |c_k|`,
    /// `(P - x) . P'' >= 2 (c_0 - centre) . c_2 - 2 radius |c_2| - (|c_0 - centre| + radius) A3 - R A`
    /// (the first term keeps the sign of the side `x` is on: positive on the convex side).
    pub(super) fn convex_for(&self, j: usize, centre: Point<D>, radius: f64) -> bool {
        let c = &self.coefficients[j * (self.degree + 1)..];
        let offset = c[0] - centre;
        let (c2, a3) = if self.degree >= 2 {
            let a3: f64 = (3..=self.degree)
                .map(|k| (k * (k - 1)) as f64 * c[k].norm())
                .sum();
            (c[2], a3)
        } else {
            (Point::ZERO, 0.0)
        };
        let along = 2.0 * offset.dot(c2);
        let worst = 2.0 * radius * c2.norm()
            + (offset.norm() + radius) * a3
            + self.spread[j] * self.bend[j];
        // A relative margin for the rounding of the bound and of `g'` itself.
        let scale = self.speed_sq[j] + along.abs() + worst;
        self.speed_sq[j] + along - worst > 1e-9 * scale
    }

    /// Whether the tangent is continuous where segment `j` starts.
    pub(super) fn smooth_start(&self, j: usize) -> bool {
        self.smooth_start[j]
    }

    /// The curve parameter at `v` on segment `j`.
    #[inline]
    pub(super) fn parameter(&self, j: usize, v: f64) -> f64 {
        self.mids[j] + v * self.halves[j]
    }

    /// The root of `g` on segment `j` where `g(-1) <= 0 < g(1)`: Newton's method in `v` from
    /// `start`, safeguarded by bisection, to a step below `tolerance` (in the curve's
    /// parameter; at least the rounding of the parameter).
    pub(super) fn root(&self, j: usize, q: Point<D>, start: f64, tolerance: f64) -> f64 {
        // The parameter's own rounding, as in the general search.
        let ends = self.mids[j].abs() + self.halves[j];
        let floor = 4.0 * f64::EPSILON * ends / self.halves[j];
        let tolerance = (tolerance / self.halves[j]).max(floor);
        bracketed_newton(-1.0, 1.0, start, tolerance, floor, |v| {
            let [p, d1, d2] = self.jet(j, v);
            let r = p - q;
            (r.dot(d1), d1.norm_sq() + r.dot(d2))
        })
    }
}
