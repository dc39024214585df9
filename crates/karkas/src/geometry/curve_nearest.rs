//! The point of a curve nearest to a given point, found globally.
//!
//! The curve is sampled into a polyline (a few vertices per polynomial piece) whose vertices
//! go into a k-d tree (the `kiddo` crate), and the arc length `ℓ_j` of every polyline segment
//! is measured. For a query `q`, the two segments at the nearest vertex are searched first,
//! giving an upper bound `d_0` on the distance; every curve point within `d_0` of `q` lies
//! within `ℓ_j / 2` of a vertex of its segment, so only segments with a vertex within
//! `d_0 + max ℓ_j / 2` can hold the nearest point. Of those, a segment with ends `a`, `b` is
//! skipped when `dist(q, [a, b]) - sqrt(ℓ_j^2 - |b - a|^2) / 2` is no better than the best so
//! far: its points lie in the ellipse of foci `a`, `b` and major axis `ℓ_j`, all within the
//! semi-minor axis `sqrt(ℓ_j^2 - |b - a|^2) / 2` of the chord `[a, b]`, a bound that is
//! tight (of order `ℓ_j^2` times the curvature) on a finely sampled curve. The others
//! (smallest bound first) are searched for a minimum of `|P(t) - q|^2 / 2`: where
//! `g(t) = (P(t) - q) . P'(t)` changes sign from negative to positive, the root is found by
//! Newton's method on `g` (`g' = |P'|^2 + (P - q) . P''`, started where `q` projects onto the
//! chord) safeguarded by bisection; its ends are candidates too. A segment whose bound is
//! below the best but which shows no such sign change is split into 8 parts and searched
//! again: this finds a minimum between two roots of `g`, as next to a cusp (where `P' = 0`
//! and `g` vanishes at a vertex). Only minima hidden inside an eighth of a segment can be
//! missed, which the sampling density makes negligible.
//!
//! Parameters stay in the domain: clamped on an open curve (the foot may be an end), wrapped
//! on a closed one. Ties (a point at the centre of a circle) resolve to the first
//! segment searched.
//!
//! A batch of 4096 points or more (`CurveProjector::nearest_all`) on a piecewise
//! polynomial curve shares this work by grid cells (`nearest_grid`): one search per
//! cell proves that the distance has a single local minimum on a run of segments for every
//! point of the cell, and each point then takes one Newton solve on one segment's polynomial.

use kiddo::immutable::float::kdtree::ImmutableKdTree;
use kiddo::SquaredEuclidean;

use super::arc_length::piece_length;
use crate::core::Curve;
use crate::{Error, Point, Result};

/// Polyline segments per polynomial piece (at least; more for high degrees).
const SEGMENTS_PER_PIECE: usize = 4;
/// Polyline segments when the curve does not tell its pieces.
const SEGMENTS_UNKNOWN: usize = 256;
/// The fewest and most polyline segments.
const MIN_SEGMENTS: usize = 64;
const MAX_SEGMENTS: usize = 1 << 18;
/// Most Newton or bisection steps per candidate segment.
const MAX_STEPS: usize = 100;
/// The relative accuracy of the segments' arc lengths (their chord-width bounds grow as its
/// square root).
const LENGTH_ACCURACY: f64 = 1e-10;
/// Where the tangent at a segment's end is taken, as a share of the segment before its end.
const LEFT_LIMIT: f64 = 1e-9;
/// Parts a segment is split into when it may hold a minimum with no sign change of `g`
/// across it.
const FINE_PARTS: usize = 8;

/// The point of a curve nearest to a query point (kurbo's `Nearest`, with the foot point).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveNearest<const D: usize> {
    /// The parameter of the foot point (in the domain).
    pub t: f64,
    /// The distance from the query point to the curve.
    pub distance: f64,
    /// The foot point `P(t)`.
    pub point: Point<D>,
}

impl<const D: usize> CurveNearest<D> {
    /// The result for a query that has no nearest point (a NaN or infinite coordinate).
    pub const UNDEFINED: Self = CurveNearest {
        t: f64::NAN,
        distance: f64::NAN,
        point: Point([f64::NAN; D]),
    };
}

/// A curve prepared for nearest-point queries: a sampled polyline in a k-d tree.
///
/// Building costs `O(n log n)` for `n` polyline vertices (a few per piece); a query then
/// costs a tree search and a few Newton steps per candidate segment.
///
/// ```
/// use karkas::geometry::CurveProjector;
/// use karkas::{ll::LlCurve, Point};
/// let pts = [Point([0.0, 0.0]), Point([1.0, 0.0]), Point([2.0, 0.0]), Point([3.0, 0.0])];
/// let line = LlCurve::new(&pts, 3, false).unwrap();
/// let projector = CurveProjector::new(&line, 1e-12).unwrap();
/// let near = projector.nearest(Point([1.5, 2.0]));
/// assert!((near.distance - 2.0).abs() < 1e-12);
/// assert!((near.point[0] - 1.5).abs() < 1e-12);
/// ```
pub struct CurveProjector<'a, C: ?Sized, const D: usize> {
    pub(super) curve: &'a C,
    /// Vertex parameters `t_0 < .. < t_n` (`t_n` the domain end; on a closed curve vertex
    /// `n` is vertex 0 and is not in the tree).
    pub(super) params: Vec<f64>,
    pub(super) points: Vec<Point<D>>,
    tree: ImmutableKdTree<f64, u64, D, 16>,
    /// Tangents at the start of every segment, `P'(t_j)` (from the right).
    starts: Vec<Point<D>>,
    /// Tangents at the end of every segment, `P'(t_{j+1})` from the left (a piecewise curve
    /// may turn at a vertex: a polyline's next edge can point back against this one).
    ends: Vec<Point<D>>,
    /// How far each segment strays from its chord at most (see [`Self::lower_bound`]).
    widths: Vec<f64>,
    /// The largest half arc length of a segment (with a safety margin).
    pub(super) reach: f64,
    pub(super) accuracy: f64,
    pub(super) closed: bool,
}

impl<'a, C: Curve<D> + ?Sized, const D: usize> CurveProjector<'a, C, D> {
    /// Samples `curve` and builds the tree. `accuracy` is the tolerance on the foot
    /// parameter (Newton stops when its step is below it; the distance is then exact to about
    /// `|P'| accuracy` squared over the distance); non-positive asks for full precision.
    ///
    /// Errors: a non-finite domain or a sample of the curve that is not finite
    /// ([`Error::NonFiniteArgument`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineCurve;
    /// use karkas::geometry::CurveProjector;
    /// use karkas::Point;
    ///
    /// let segment = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 1.0], vec![Point([0.0, 0.0]), Point([2.0, 0.0])])?;
    /// let projector = CurveProjector::new(&segment, 0.0)?;
    /// let foot = projector.nearest(Point([0.5, 1.0]));
    /// assert!((foot.t - 0.25).abs() < 1e-12 && (foot.distance - 1.0).abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(curve: &'a C, accuracy: f64) -> Result<Self> {
        let domain = curve.domain();
        if !domain.start.is_finite() || !domain.end.is_finite() {
            return Err(Error::NonFiniteArgument {
                what: "the curve's domain",
            });
        }
        let closed = curve.is_closed() && domain.length() > 0.0;
        let mut params = sample_parameters(curve);
        if domain.length() <= 0.0 {
            params = vec![domain.start, domain.end];
        }
        let points: Vec<Point<D>> = params.iter().map(|&t| curve.eval(t)).collect();
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NonFiniteArgument {
                what: "a sample of the curve",
            });
        }
        let starts: Vec<Point<D>> = params[..params.len() - 1]
            .iter()
            .map(|&t| curve.deriv(t, 1))
            .collect();
        // The left limit, by the derivative a hair before the end (the `Curve` trait gives
        // values at a parameter, not one-sided limits).
        let ends: Vec<Point<D>> = params
            .windows(2)
            .map(|w| curve.deriv(w[1] - LEFT_LIMIT * (w[1] - w[0]), 1))
            .collect();
        let size = points.iter().fold(0.0f64, |m, p| m.max(p.max_abs()));
        let mut longest: f64 = 0.0;
        let widths: Vec<f64> = params
            .windows(2)
            .zip(points.windows(2))
            .map(|(w, p)| {
                let chord = p[0].distance(p[1]);
                let length = piece_length(curve, w[0], w[1], LENGTH_ACCURACY * chord + 1e-300);
                // Rounded up by the quadrature's error and rounding.
                let length = length.max(chord) * (1.0 + 2.0 * LENGTH_ACCURACY) + 1e-12 * size;
                longest = longest.max(length);
                0.5 * ((length - chord) * (length + chord)).sqrt() + 1e-12 * size
            })
            .collect();
        let reach = 0.5 * longest * (1.0 + 1e-6) + 1e-12 * size;
        let in_tree = if closed {
            points.len() - 1
        } else {
            points.len()
        };
        let coords: Vec<[f64; D]> = points[..in_tree].iter().map(|p| p.0).collect();
        Ok(CurveProjector {
            curve,
            tree: ImmutableKdTree::new_from_slice(&coords),
            params,
            points,
            starts,
            ends,
            widths,
            reach,
            accuracy: accuracy.max(0.0),
            closed,
        })
    }

    /// The nearest point of the curve to `q` ([`CurveNearest::UNDEFINED`] for a non-finite
    /// `q`).
    pub fn nearest(&self, q: Point<D>) -> CurveNearest<D> {
        if !q.is_finite() {
            return CurveNearest::UNDEFINED;
        }
        let segments = self.params.len() - 1;
        let vertices = if self.closed { segments } else { segments + 1 };
        let first =
            (self.tree.nearest_one::<SquaredEuclidean>(&q.0).item as usize).min(vertices - 1);
        let mut best = self.result(self.params[first], self.points[first], q);
        // The segments at the nearest vertex first: they usually hold the foot, and the
        // distance they give shrinks the search below.
        let around = self.segments_at(first);
        let mut rooted = [false; 2];
        for (k, j) in around.into_iter().enumerate() {
            if let Some(j) = j {
                let (found, root) = self.search_segment(q, j, 1);
                rooted[k] = root;
                if found.distance < best.distance {
                    best = found;
                }
            }
        }
        let radius = best.distance + self.reach;
        let mut candidates: Vec<(f64, usize)> = Vec::new();
        for found in self
            .tree
            .within_unsorted::<SquaredEuclidean>(&q.0, radius * radius)
        {
            let i = (found.item as usize).min(vertices - 1);
            for j in self.segments_at(i).into_iter().flatten() {
                // A segment at the nearest vertex whose minimum was found needs no more.
                if (0..2).any(|k| rooted[k] && around[k] == Some(j)) {
                    continue;
                }
                let bound = self.lower_bound(q, j);
                if bound < best.distance {
                    candidates.push((bound, j));
                }
            }
        }
        candidates.sort_unstable_by_key(|c| c.1);
        candidates.dedup_by_key(|c| c.1);
        candidates.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for (bound, j) in candidates {
            if bound >= best.distance {
                break;
            }
            // A segment that may still hold a nearer point is searched more finely: a
            // minimum between two roots of `g` (near a cusp, where `P' = 0`) shows no sign
            // change across the whole segment.
            let parts = if around.contains(&Some(j)) {
                FINE_PARTS
            } else {
                1
            };
            let (mut found, root) = self.search_segment(q, j, parts);
            if !root && parts == 1 {
                found = self.search_segment(q, j, FINE_PARTS).0;
            }
            if found.distance < best.distance {
                best = found;
            }
        }
        if self.closed {
            best.t = self.curve.domain().wrap(best.t);
        }
        best
    }

    /// The segments that end at vertex `i` (the one before it and the one after it).
    pub(super) fn segments_at(&self, i: usize) -> [Option<usize>; 2] {
        let segments = self.params.len() - 1;
        let before = if i > 0 {
            Some(i - 1)
        } else if self.closed {
            Some(segments - 1)
        } else {
            None
        };
        let after = (i < segments).then_some(i);
        [before, after]
    }

    /// A lower bound on the distance from `q` to segment `j`: the segment (ends `a`, `b`,
    /// chord `c`, arc length `l`) lies in the ellipse of foci `a`, `b` and major axis `l`,
    /// whose points are within its semi-minor axis `h = sqrt(l^2 - c^2) / 2` of the chord
    /// `[a, b]`; so the distance is at least `dist(q, [a, b]) - h`.
    pub(super) fn lower_bound(&self, q: Point<D>, j: usize) -> f64 {
        let (a, b) = (self.points[j], self.points[j + 1]);
        let (ab, aq) = (b - a, q - a);
        let c2 = ab.norm_sq();
        let s = if c2 > 0.0 {
            (aq.dot(ab) / c2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (aq - ab * s).norm() - self.widths[j]
    }

    /// The polyline vertices within `radius` of `q` (closed curves: vertex 0 stands for the
    /// last one too).
    pub(super) fn vertices_within(&self, q: Point<D>, radius: f64) -> Vec<usize> {
        let segments = self.params.len() - 1;
        let vertices = if self.closed { segments } else { segments + 1 };
        self.tree
            .within_unsorted::<SquaredEuclidean>(&q.0, radius * radius)
            .into_iter()
            .map(|found| (found.item as usize).min(vertices - 1))
            .collect()
    }

    /// The best of the ends of segment `j` and the minima of the squared distance inside it,
    /// split into `parts` equal parts (a minimum is where `g` turns from `<= 0` to `> 0`);
    /// true when a minimum inside was found.
    fn search_segment(&self, q: Point<D>, j: usize, parts: usize) -> (CurveNearest<D>, bool) {
        let (a, b) = (self.params[j], self.params[j + 1]);
        let (pa, pb) = (self.points[j], self.points[j + 1]);
        let mut best = if pa.distance_sq(q) <= pb.distance_sq(q) {
            self.result(a, pa, q)
        } else {
            self.result(b, pb, q)
        };
        let mut rooted = false;
        let (mut lo, mut p_lo, mut g_lo) = (a, pa, (pa - q).dot(self.starts[j]));
        for k in 1..=parts {
            let (hi, p_hi, g_hi) = if k == parts {
                (b, pb, (pb - q).dot(self.ends[j]))
            } else {
                let t = a + (b - a) * (k as f64 / parts as f64);
                let p = self.curve.eval(t);
                (t, p, (p - q).dot(self.curve.deriv(t, 1)))
            };
            if p_hi.distance(q) < best.distance {
                best = self.result(hi, p_hi, q);
            }
            if g_lo <= 0.0 && g_hi > 0.0 {
                // Start where q projects onto the chord.
                let (chord, c2) = (p_hi - p_lo, p_lo.distance_sq(p_hi));
                let s = if c2 > 0.0 {
                    ((q - p_lo).dot(chord) / c2).clamp(0.0, 1.0)
                } else {
                    0.5
                };
                let t = self.newton_root(q, lo, hi, lo + (hi - lo) * s);
                let p = self.curve.eval(t);
                rooted = true;
                if p.distance(q) < best.distance {
                    best = self.result(t, p, q);
                }
            }
            (lo, p_lo, g_lo) = (hi, p_hi, g_hi);
        }
        (best, rooted)
    }

    /// The root of `g` in `(lo, hi)` with `g(lo) < 0 < g(hi)`: Newton from `start` safeguarded
    /// by bisection.
    fn newton_root(&self, q: Point<D>, lo: f64, hi: f64, start: f64) -> f64 {
        let floor = 4.0 * f64::EPSILON * (lo.abs().max(hi.abs()));
        bracketed_newton(lo, hi, start, self.accuracy.max(floor), floor, |t| {
            let [p, d1, d2] = self.curve.eval_with_derivatives(t);
            let r = p - q;
            (r.dot(d1), d1.norm_sq() + r.dot(d2))
        })
    }

    pub(super) fn result(&self, t: f64, p: Point<D>, q: Point<D>) -> CurveNearest<D> {
        CurveNearest {
            t,
            distance: p.distance(q),
            point: p,
        }
    }
}

/// The root of a function `g` with `g(lo) < 0 < g(hi)` (`step(t)` gives `g(t)` and its
/// slope): Newton's method from `start`, a bisection whenever Newton leaves the bracket or the
/// slope is not positive, until a step is below `tolerance` or the bracket below `floor`.
pub(super) fn bracketed_newton(
    mut lo: f64,
    mut hi: f64,
    start: f64,
    tolerance: f64,
    floor: f64,
    mut step: impl FnMut(f64) -> (f64, f64),
) -> f64 {
    let mut t = if start > lo && start < hi {
        start
    } else {
        0.5 * (lo + hi)
    };
    for _ in 0..MAX_STEPS {
        let (g, slope) = step(t);
        if g == 0.0 {
            return t;
        }
        if g < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - g / slope;
        if slope > 0.0 && (newton - t).abs() <= tolerance {
            // Converged: the step is below the tolerance (Newton landing on `t` itself, a
            // bracket end, must not fall back to bisection).
            return newton.clamp(lo, hi);
        }
        t = if slope > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if hi - lo <= floor {
            break;
        }
    }
    t
}

/// The vertex parameters of the polyline: a few per polynomial piece.
fn sample_parameters<C: Curve<D> + ?Sized, const D: usize>(curve: &C) -> Vec<f64> {
    let domain = curve.domain();
    let (breaks, per_piece) = match curve.polynomial_pieces() {
        Some(p) if p.breaks.len() >= 2 => {
            let per = SEGMENTS_PER_PIECE.max(p.degree + 1);
            (p.breaks, per)
        }
        _ => (vec![domain.start, domain.end], SEGMENTS_UNKNOWN),
    };
    let pieces = breaks.len() - 1;
    let mut per_piece = per_piece.max(MIN_SEGMENTS.div_ceil(pieces));
    if pieces * per_piece > MAX_SEGMENTS {
        per_piece = (MAX_SEGMENTS / pieces).max(1);
    }
    let mut params = Vec::with_capacity(pieces * per_piece + 1);
    for w in breaks.windows(2) {
        for k in 0..per_piece {
            params.push(w[0] + (w[1] - w[0]) * (k as f64 / per_piece as f64));
        }
    }
    params.push(domain.end);
    params[0] = domain.start;
    params
}
