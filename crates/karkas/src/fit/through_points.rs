//! The last repair of a tolerance-mode fit of Pavlov's defect-2 spline that crosses itself or
//! turns more than its points (docs/methods.md §4, "Shape faults in the tolerance mode"): a
//! C^1 cubic through some of the points, with tangents that turn as the points do.
//!
//! The curve is a [`HermiteSpline`] whose knots are points of the data (the nodes), at their
//! cumulative chord length, so that it runs at about the same speed everywhere. At each node
//! the tangent bisects the angle between the chords to the neighbouring nodes (at an end it
//! is the neighbour's tangent mirrored in the end chord, the end piece a near circular arc;
//! at a shared end where the points turn by more than pi/2, a sharp trailing edge, it is the
//! points' own end chord, so that the corner turns as the polygon's and the two branches
//! reach it in the points' order),
//! so a piece turns by half the polygon's angle at either of its nodes, and the curve about
//! as much as the polygon through its nodes, which turns no more than the points' polygon (a
//! polygon inscribed in another turns no more than it). The tangent's length on a piece is a
//! share of the piece's reach (its polygon length), one share per node to keep the curve
//! C^1: 1, shortened where a piece that bends one way needs it to keep its control polygon
//! convex (then it does not inflect) and where a piece inflects (there shorter tangents turn
//! less beyond the ends' angles: [`INFLECTING_SHARES`]).
//!
//! It starts through every point and drops nodes greedily, one at a time along the curve,
//! pass after pass, keeping a drop when every point between the nodes around it stays
//! within the tolerance and no new piece turns more than its points
//! ([`PIECE_TURNING_SLACK`]).
//!
//! On the corpus this is the one repair that removes hooks where the coordinates kink or
//! ripple at a leading edge, or at a sparse sharp edge: a least-squares fit smooths such
//! points into a curve that swings past them, while within the tolerance a curve must turn as
//! they do. It takes more knots than a least-squares fit (on the 38 files it repairs, 0.69
//! per point at the median). Hand-written: it is a few lines of geometry on the fit's own
//! spline type.

use super::hermite::HermiteSpline;
use super::knots::MIN_KNOT_SPACING;
use super::noise::NoiseEstimate;
use super::penalty::Settings;
use super::penalty::{knot_weights, DEFAULT_SMOOTHING};
use super::power::PowerForm;
use super::problem::Taper;
use super::project::foot_point_near;
use super::result::CurveFit;
use crate::Point;

/// The most a piece may turn beyond the points it spans (from its first node's tangent along
/// their chords to its last node's tangent), in radians.
const PIECE_TURNING_SLACK: f64 = 0.02;
/// The shortest end tangent, as a share of its piece's reach (below it a node is nearly a
/// corner).
const SHORTEST: f64 = 0.1;
/// A piece whose end tangents lie within this angle of its chord, together, is straight:
/// its tangents are not shortened.
const STRAIGHT: f64 = 1e-3;
/// The lengths of the end tangents of a piece that inflects, at most, as shares of its
/// reach, tried in turn: shorter tangents make the piece turn less beyond its ends' angles
/// (on the corpus 0.5 leaves 3 of the files this step repairs turning too much; 0.3 none),
/// longer ones make it rounder.
pub(crate) const INFLECTING_SHARES: [f64; 2] = [0.5, 0.3];
/// The most passes of node drops.
const MAX_PASSES: usize = 8;
/// Samples per piece for its turning and for the first guess of a foot point.
const SAMPLES: usize = 32;

/// The curve through some of `points` (see the module docs) with every point within
/// `tolerance`; `None` for fewer than 3 points, points that all coincide, or a curve that
/// does not come out finite.
pub(crate) fn through_points<const D: usize>(
    points: &[Point<D>],
    tolerance: f64,
    inflecting: f64,
    options: &Settings<'_>,
    noise: &NoiseEstimate,
) -> Option<CurveFit<D>> {
    let n = points.len();
    if n < 3 {
        return None;
    }
    let mut s = vec![0.0; n];
    for i in 1..n {
        s[i] = s[i - 1] + points[i].distance(points[i - 1]);
    }
    let total = s[n - 1];
    if !(total > 0.0 && total.is_finite()) {
        return None;
    }
    s.iter_mut().for_each(|v| *v /= total);
    let nodes = Nodes {
        points,
        s: &s,
        tolerance,
        inflecting,
        corner: corner_chords(points),
    };
    let mut at = vec![0];
    for i in 1..n - 1 {
        let clear = |a: f64, b: f64| b - a >= 2.0 * MIN_KNOT_SPACING;
        if clear(s[at[at.len() - 1]], s[i]) && clear(s[i], 1.0) {
            at.push(i);
        }
    }
    at.push(n - 1);
    for _ in 0..MAX_PASSES {
        let before = at.len();
        let mut k = 1;
        while k + 1 < at.len() {
            let mut fewer = at.clone();
            fewer.remove(k);
            if nodes.holds(&fewer, k.saturating_sub(3)..(k + 2).min(fewer.len() - 1)) {
                at = fewer;
            } else {
                k += 1;
            }
        }
        if at.len() == before {
            break;
        }
    }
    nodes.fit(&at, total, options, noise)
}

/// The points, their cumulative chord lengths (`s`, from 0 to 1) and the tolerance.
struct Nodes<'a, const D: usize> {
    points: &'a [Point<D>],
    s: &'a [f64],
    tolerance: f64,
    /// The length of the end tangents of an inflecting piece, as a share of its reach.
    inflecting: f64,
    /// At a shared end that is a corner ([`corner_chords`]): the unit directions of the
    /// points' first and last chords, the curve's end tangents there.
    corner: Option<(Point<D>, Point<D>)>,
}

impl<const D: usize> Nodes<'_, D> {
    /// The unit tangent at node `j` of the nodes `at` (indices of points).
    fn tangent(&self, at: &[usize], j: usize) -> Point<D> {
        let p = |k: usize| self.points[at[k]];
        let unit = |v: Point<D>| {
            let length = v.norm();
            if length > 0.0 {
                v * (1.0 / length)
            } else {
                v
            }
        };
        let last = at.len() - 1;
        if let (Some((first, final_chord)), true) = (self.corner, j == 0 || j == last) {
            return if j == 0 { first } else { final_chord };
        }
        if j == 0 || j == last {
            let (end, next) = if j == 0 { (0, 1) } else { (last, last - 1) };
            if at.len() == 2 {
                return unit(p(last) - p(0));
            }
            // The neighbour's tangent mirrored in the end chord.
            let chord = unit(p(next) - p(end));
            let beside = self.tangent(at, next);
            return chord * (2.0 * chord.dot(beside)) - beside;
        }
        let (before, after) = (unit(p(j) - p(j - 1)), unit(p(j + 1) - p(j)));
        let bisector = before + after;
        if bisector.norm() > 1e-8 {
            unit(bisector)
        } else {
            // The polygon turns back on itself here: along the chord across the node.
            unit(p(j + 1) - p(j - 1))
        }
    }

    /// The polygon length from node `j` to node `j + 1` of `at`.
    fn reach(&self, at: &[usize], j: usize) -> f64 {
        self.points[at[j]..=at[j + 1]]
            .windows(2)
            .map(|w| w[0].distance(w[1]))
            .sum()
    }

    /// The longest end tangents that the piece from node `j` to node `j + 1` of `at` allows,
    /// as shares of its reach: where it bends one way (its end tangents on either side of
    /// the chord, meeting at `V`), 3 |V - a| and 3 |V - b| (the control polygon of the
    /// cubic stays convex, so it does not inflect; the parabola has 2); where it inflects,
    /// `inflecting`; where it is straight, no bound.
    fn caps(&self, at: &[usize], j: usize) -> (f64, f64) {
        let (a, b) = (self.points[at[j]], self.points[at[j + 1]]);
        let (ua, ub) = (self.tangent(at, j), self.tangent(at, j + 1));
        let length = a.distance(b);
        let c = (b - a) * (1.0 / length);
        let (alpha, beta) = (ua.angle_to(c), c.angle_to(ub));
        if alpha + beta <= STRAIGHT {
            return (f64::INFINITY, f64::INFINITY);
        }
        let across = |u: Point<D>| u - c * u.dot(c);
        if across(ua).dot(across(ub)) >= 0.0 {
            return (self.inflecting, self.inflecting);
        }
        // The triangle a, V, b: |V - a| = |b - a| sin(beta) / sin(alpha + beta).
        let spread = (alpha + beta).sin();
        if spread <= 0.0 {
            return (f64::INFINITY, f64::INFINITY);
        }
        let reach = self.reach(at, j);
        let leg = |angle: f64| 3.0 * length * angle.sin() / spread / reach;
        (leg(beta), leg(alpha))
    }

    /// The length of the tangent at node `j` of `at` on either of its pieces, as a share of
    /// the piece's reach: 1 (the chord length on a straight stretch), shortened to what its
    /// pieces allow ([`Nodes::caps`]), at least [`SHORTEST`]. One share for both pieces keeps
    /// the curve C^1 in the chord-length parameter.
    fn share(&self, at: &[usize], j: usize) -> f64 {
        let mut share = 1.0f64;
        if j > 0 {
            share = share.min(self.caps(at, j - 1).1);
        }
        if j + 1 < at.len() {
            share = share.min(self.caps(at, j).0);
        }
        share.max(SHORTEST)
    }

    /// The power-form coefficients of the piece from node `j` to node `j + 1` of `at`, in its
    /// local coordinate `u` in `[0, 1]`.
    fn piece(&self, at: &[usize], j: usize) -> [Point<D>; 4] {
        let (a, b) = (self.points[at[j]], self.points[at[j + 1]]);
        let reach = self.reach(at, j);
        let ta = self.tangent(at, j) * (self.share(at, j) * reach);
        let tb = self.tangent(at, j + 1) * (self.share(at, j + 1) * reach);
        let chord = b - a;
        [a, ta, chord * 3.0 - ta * 2.0 - tb, chord * -2.0 + ta + tb]
    }

    /// Whether the pieces `pieces` of the nodes `at` hold every point between their nodes
    /// within the tolerance and turn no more than those points (plus
    /// [`PIECE_TURNING_SLACK`]).
    fn holds(&self, at: &[usize], pieces: std::ops::Range<usize>) -> bool {
        pieces.into_iter().all(|j| {
            let c = self.piece(at, j);
            let (first, last) = (at[j], at[j + 1]);
            let turns = turning_of(&c);
            // From the first tangent along the chords to the last tangent (zero chords skipped).
            let path = std::iter::once(self.tangent(at, j))
                .chain(self.points[first..=last].windows(2).map(|w| w[1] - w[0]))
                .chain(std::iter::once(self.tangent(at, j + 1)))
                .filter(|d| d.norm() > 0.0);
            let (allowed, _) =
                path.fold((0.0, None), |(sum, before): (f64, Option<Point<D>>), d| {
                    (sum + before.map_or(0.0, |b| b.angle_to(d)), Some(d))
                });
            turns <= allowed + PIECE_TURNING_SLACK
                && self.points[first + 1..last]
                    .iter()
                    .all(|&r| distance_to(&c, r) <= self.tolerance)
        })
    }

    /// The fit whose knots are the nodes `at`: the spline on `[0, 1]` (the chord lengths over
    /// `total`), every point's foot parameter (the nodes their own, the others projected and
    /// kept in order) and distance, and the figures of a fit; `None` when the curve or a
    /// distance does not come out finite.
    fn fit(
        &self,
        at: &[usize],
        total: f64,
        options: &Settings<'_>,
        noise: &NoiseEstimate,
    ) -> Option<CurveFit<D>> {
        let m = at.len();
        let knots: Vec<f64> = at.iter().map(|&i| self.s[i]).collect();
        let values = at.iter().map(|&i| self.points[i]).collect();
        // A piece's tangent is share * reach, its knot span reach / total.
        let derivatives: Vec<Point<D>> = (0..m)
            .map(|j| self.tangent(at, j) * (self.share(at, j) * total))
            .collect();
        if !derivatives.iter().all(|d| d.is_finite()) {
            return None;
        }
        let spline = HermiteSpline::from_parts(knots.clone(), values, derivatives);
        let form = PowerForm::new(&spline);
        let n = self.points.len();
        let (mut parameters, mut distances) = (vec![0.0; n], vec![0.0; n]);
        let mut node = 0;
        for (i, &r) in self.points.iter().enumerate() {
            if at[node] == i {
                parameters[i] = knots[node];
                node = (node + 1).min(m - 1);
                continue;
            }
            // Between nodes `node - 1` and `node`: from the point's chord length.
            let mut piece = node - 1;
            let (t, d_sq) = foot_point_near(&form, r, self.s[i], &mut piece);
            let ordered = t.clamp(parameters[i - 1], knots[node]);
            parameters[i] = ordered;
            distances[i] = if ordered == t {
                d_sq.sqrt()
            } else {
                form.point(form.piece_near(ordered, piece), ordered)
                    .distance(r)
            };
        }
        let pieces = knots.len() - 1;
        let (fairness, smoothing) = noise.bending_parts(
            n,
            pieces,
            options.fairness,
            options.smoothing.unwrap_or(DEFAULT_SMOOTHING),
        );
        let taper = Taper::towards_ends(fairness, smoothing, n);
        let weights =
            knot_weights(&knots, options.corners).unwrap_or_else(|_| vec![0.0; knots.len()]);
        let fit = CurveFit {
            jump_sum: spline.jump_penalty(&weights),
            bending_energy: taper.bending_energy(&spline),
            bending_shares: knots.windows(2).map(|w| taper.share(w[0], w[1])).collect(),
            bending_weight: fairness + smoothing,
            data_term: distances.iter().map(|d| d * d).sum(),
            distances,
            parameters,
            spline,
            penalty: 0.0,
            seed_bound: 0.0,
            weights,
            iterations: 0,
            noise: *noise,
            warnings: Vec::new(),
        };
        fit.distances.iter().all(|d| d.is_finite()).then_some(fit)
    }
}

/// The unit directions of the first and the last chord of `points` (repeated points
/// skipped) when the points' ends are one shared end ([`crate::core::shared_end`]: a sharp
/// trailing edge) where the polygon turns by more than pi/2: a corner whose two branches
/// the curve must reach in the points' order. The mirrored end tangents of the module docs
/// can pass each other on a thin edge (on fx38153 of the corpus, with the end nodes a few
/// points in, by 2 degrees: the branches cross at the corner); along the points' own end
/// chords the curve's corner turns as the polygon's.
fn corner_chords<const D: usize>(points: &[Point<D>]) -> Option<(Point<D>, Point<D>)> {
    crate::core::shared_end(points)?;
    let (start, end) = (points[0], points[points.len() - 1]);
    let unit = |v: Point<D>| v * (1.0 / v.norm());
    let second = points.iter().find(|&&p| p != start)?;
    let before_last = points.iter().rev().find(|&&p| p != end)?;
    let (out, into) = (unit(*second - start), unit(end - *before_last));
    let corner = into.angle_to(out) > 0.5 * std::f64::consts::PI;
    (corner && out.is_finite() && into.is_finite()).then_some((out, into))
}

/// The point of the piece `c` (power form) at `u`, and its derivative.
fn on_piece<const D: usize>(c: &[Point<D>; 4], u: f64) -> (Point<D>, Point<D>) {
    let point = ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
    let slope = (c[3] * (3.0 * u) + c[2] * 2.0) * u + c[1];
    (point, slope)
}

/// How much the piece `c` turns: the angles between its tangents at [`SAMPLES`] steps.
fn turning_of<const D: usize>(c: &[Point<D>; 4]) -> f64 {
    let slopes: Vec<Point<D>> = (0..=SAMPLES)
        .map(|k| on_piece(c, k as f64 / SAMPLES as f64).1)
        .filter(|d| d.norm() > 0.0)
        .collect();
    slopes.windows(2).map(|w| w[0].angle_to(w[1])).sum()
}

/// The distance of `r` from the piece `c`: the nearest of [`SAMPLES`] steps, refined by
/// Newton's method on `(R(u) - r) . R'(u)` (kept in `[0, 1]`).
fn distance_to<const D: usize>(c: &[Point<D>; 4], r: Point<D>) -> f64 {
    let mut best = (0.0, f64::INFINITY);
    for k in 0..=SAMPLES {
        let u = k as f64 / SAMPLES as f64;
        let d = on_piece(c, u).0.distance_sq(r);
        if d < best.1 {
            best = (u, d);
        }
    }
    let mut u = best.0;
    for _ in 0..8 {
        let (point, slope) = on_piece(c, u);
        let curvature = c[3] * (6.0 * u) + c[2] * 2.0;
        let e = point - r;
        let g = e.dot(slope);
        let h = slope.norm_sq() + e.dot(curvature);
        if h <= 0.0 {
            break;
        }
        u = (u - g / h).clamp(0.0, 1.0);
    }
    best.1.min(on_piece(c, u).0.distance_sq(r)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::guards::shape_warnings;
    use crate::fit::noise::estimate_noise;
    use crate::fit::result::FitWarningKind;
    use crate::{Curve, Point2};

    fn curve_through(points: &[Point2], tolerance: f64, inflecting: f64) -> CurveFit<2> {
        let noise = estimate_noise(points);
        through_points(
            points,
            tolerance,
            inflecting,
            &Settings::of(&crate::fit::FitOptions::default()),
            &noise,
        )
        .unwrap()
    }

    #[test]
    fn pieces_that_bend_one_way_do_not_inflect() {
        // A circular arc sampled unevenly: short chords beside long ones make the halves of
        // the polygon's angles at the ends of a piece unequal (0.025 against 0.35 rad).
        let angles = [0.0, 0.05, 0.1, 0.8, 0.85, 1.6, 1.65, 2.4, 2.45, 2.5];
        let points: Vec<Point2> = angles
            .iter()
            .map(|&a: &f64| Point2::new([a.cos(), a.sin()]))
            .collect();
        let fit = curve_through(&points, 1e-12, INFLECTING_SHARES[0]);
        assert_eq!(fit.spline.knots().len(), points.len());
        // The curve turns left all along: R' x R'' > 0.
        for i in 0..=10_000 {
            let t = i as f64 / 10_000.0;
            let (d1, d2) = (fit.spline.deriv(t, 1), fit.spline.deriv(t, 2));
            let cross = d1[0] * d2[1] - d1[1] * d2[0];
            assert!(cross > 0.0, "inflects at t = {t}");
        }
    }

    #[test]
    fn every_point_lies_within_the_tolerance_of_a_curve_through_fewer_of_them() {
        // 400 points of a thick symmetric section, a cusp-free closed-nose contour.
        let n = 400;
        let points: Vec<Point2> = (0..n)
            .map(|i| {
                let a = std::f64::consts::PI * (2.0 * i as f64 / (n - 1) as f64 - 1.0);
                let x = 0.5 * (1.0 + a.cos());
                Point2::new([x, 0.12 * x.sqrt() * (1.0 - x) * a.sin().signum()])
            })
            .collect();
        let tolerance = 1e-4;
        let fit = curve_through(&points, tolerance, INFLECTING_SHARES[0]);
        let knots = fit.spline.knots();
        assert!(knots.len() < n / 4, "{} knots", knots.len());
        // Every node is one of the points, at its own parameter.
        for (k, &t) in knots.iter().enumerate() {
            let i = fit.parameters.iter().position(|&p| p == t).unwrap();
            assert!(fit.spline.eval(t).distance(points[i]) < 1e-15, "knot {k}");
        }
        assert!(fit.parameters.windows(2).all(|w| w[0] <= w[1]));
        // The distances, measured on 200 001 samples of the curve (steps of 1e-5 along it, so
        // within 5e-6 of the true distance), and the fit's own figures, from its foot points.
        let samples: Vec<Point2> = (0..=200_000)
            .map(|i| fit.spline.eval(i as f64 / 200_000.0))
            .collect();
        for (i, p) in points.iter().enumerate() {
            let nearest = samples
                .iter()
                .map(|s| s.distance(*p))
                .fold(f64::INFINITY, f64::min);
            assert!(nearest <= tolerance + 5e-6, "point {i}: {nearest}");
            assert!(fit.distances[i] <= tolerance, "point {i}");
            assert!(fit.distances[i] <= nearest + 1e-12, "point {i}");
        }
    }

    #[test]
    fn a_thin_sharp_edge_keeps_the_order_of_its_branches_at_the_corner() {
        // FX 38-153 (UIUC, data/sharp-edges/fx38153.dat): a cambered section whose sharp
        // trailing edge is 2.7 degrees thin, its lower branch arriving from above the chord.
        let text = include_str!("../../../../data/sharp-edges/fx38153.dat");
        let points: Vec<Point2> = text
            .lines()
            .skip(1)
            .filter(|l| !l.trim().is_empty())
            .map(|l| {
                let v: Vec<f64> = l.split_whitespace().map(|f| f.parse().unwrap()).collect();
                Point2::new([v[0], v[1]])
            })
            .collect();
        // The signed turn from the direction `a` into `b`.
        let turn = |a: Point2, b: Point2| (a[0] * b[1] - a[1] * b[0]).atan2(a.dot(b));
        let n = points.len();
        let polygon = turn(points[n - 1] - points[n - 2], points[1] - points[0]);
        assert!((polygon.to_degrees() - 177.3).abs() < 0.1, "{polygon}");
        for tolerance in [1e-4, 3e-4, 1e-3] {
            for inflecting in INFLECTING_SHARES {
                let fit = curve_through(&points, tolerance, inflecting);
                let d = fit.spline.domain();
                let curve = turn(fit.spline.deriv(d.end, 1), fit.spline.deriv(d.start, 1));
                // The same corner as the points': the end chords' 2.7 degrees.
                assert!(
                    (curve - polygon).abs() < 1e-12,
                    "{tolerance}: {curve} vs {polygon}"
                );
                let crossing: Vec<_> = shape_warnings(&points, &fit)
                    .into_iter()
                    .filter(|w| w.kind == FitWarningKind::SelfIntersection)
                    .collect();
                assert!(crossing.is_empty(), "{tolerance}: {crossing:?}");
                assert!(fit.distances.iter().all(|&e| e <= tolerance));
            }
        }
    }

    #[test]
    fn a_rippled_nose_turns_no_more_than_its_points() {
        // A parabolic nose, x = y^2, its points 5e-4 to either side in turn (coordinates
        // rounded coarsely): the polygon zigzags, every piece through it inflects.
        let points: Vec<Point2> = (0..41)
            .map(|i| {
                let y = -0.2 + 0.01 * i as f64;
                let ripple = if i % 2 == 0 { 2e-4 } else { -2e-4 };
                Point2::new([y * y + ripple, y])
            })
            .collect();
        let fit = curve_through(&points, 1e-6, INFLECTING_SHARES[1]);
        assert_eq!(fit.spline.knots().len(), points.len());
        let excess: Vec<_> = shape_warnings(&points, &fit)
            .into_iter()
            .filter(|w| w.kind == FitWarningKind::ExcessTurning)
            .collect();
        assert!(excess.is_empty(), "{excess:?}");
    }
}
