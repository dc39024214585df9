//! The faired curve and its report, and the pipeline from points (or a curve) to it: scale,
//! split at corners, fair every piece, join, scale back.

use super::options::{check, FairEnds, FairOptions};
use super::piece::{fair_piece, End, Piece};
use crate::bspline::{BSplineCurve, ToBSplineCurve};
use crate::geometry::fairness::sampled_fairness_energy;
use crate::geometry::{curve_fairness, CurveFairness};
use crate::param::{CubicSpline, CurveParameterization};
use crate::spline::SplineEnds;
use crate::{Curve, Error, Point, Result};

/// A faired curve.
#[derive(Clone, Debug)]
pub struct FairCurve<const D: usize> {
    /// The curve: a cubic B-spline on `[0, 1]` (simple inner knots, triple at corners).
    pub curve: BSplineCurve<D>,
    /// The points it was faired to (the input points, or the samples of the curve given to
    /// [`fair_existing_curve`]).
    pub points: Vec<Point<D>>,
    /// The parameter of every point on the curve (its foot point).
    pub parameters: Vec<f64>,
    /// The distance of every point from the curve at its parameter (at most the tolerance).
    pub distances: Vec<f64>,
}

impl<const D: usize> FairCurve<D> {
    /// The largest distance of a point from the curve.
    pub fn max_distance(&self) -> f64 {
        self.distances.iter().fold(0.0, |a, &b| a.max(b))
    }

    /// The fairness figures of the faired curve, its distance measured to the polygon of
    /// [`points`](Self::points).
    pub fn fairness(&self) -> CurveFairness {
        curve_fairness(&self.curve, &self.points)
    }

    /// The fairness figures of the curve through the points before fairing: the cubic spline
    /// through them with chord-length parameters (not-a-knot ends, periodic when closed), or
    /// `None` when there is none (coincident neighbours).
    pub fn fairness_before(&self) -> Option<CurveFairness> {
        let ends = if self.curve.is_closed() {
            SplineEnds::Periodic
        } else {
            SplineEnds::NotAKnot
        };
        let spline =
            CubicSpline::through(&self.points, CurveParameterization::ChordLength, ends).ok()?;
        Some(curve_fairness(&spline, &self.points))
    }
}

/// The frame the points are fairer in: `(p - corner - half) / size`, with `corner` the low
/// corner of their bounding box, `half` its half-sides and `size` the largest of them.
///
/// The corner is made of input coordinates, so `p - corner` and `half` are exact for points
/// far from the origin (Sterbenz) and the same for points moved by a representable offset:
/// the fairer then sees the same numbers wherever the points are, and the curve moves with
/// them to the rounding of the final `corner + ...` (a few units in the last place).
struct Frame<const D: usize> {
    corner: Point<D>,
    half: Point<D>,
    size: f64,
}

impl<const D: usize> Frame<D> {
    fn of(points: &[Point<D>]) -> Self {
        let mut lo = points[0];
        let mut hi = points[0];
        for p in points {
            for d in 0..D {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        let half = (hi - lo) * 0.5;
        let size = (0..D).map(|d| half[d]).fold(0.0, f64::max);
        Frame {
            corner: lo,
            half,
            size,
        }
    }

    /// A point in the fairer's frame.
    fn unit(&self, p: Point<D>) -> Point<D> {
        ((p - self.corner) - self.half) * (1.0 / self.size)
    }

    /// A point of the fairer's frame back in the points' frame.
    fn back(&self, c: Point<D>) -> Point<D> {
        self.corner + (self.half + c * self.size)
    }
}

/// The fairest `C^2` cubic B-spline within `options.tolerance` of every point of `points`
/// (see the module documentation).
///
/// Errors: a tolerance that is not positive or below what the coordinates resolve, a
/// non-finite point, fewer than four points (in any piece between corners), points not in
/// order ([`Error::PointsOutOfOrder`]), corners that are not inner points in increasing
/// order, all points equal.
///
/// ```
/// use karkas::fair::{fair_curve, FairOptions};
/// use karkas::{Curve, Point};
/// // A parabola with a wave of 1e-3 on it.
/// let points: Vec<Point<2>> = (0..60)
///     .map(|i| {
///         let x = i as f64 / 59.0;
///         Point([x, x * x + 1e-3 * (40.0 * x).sin()])
///     })
///     .collect();
/// let fair = fair_curve(&points, &FairOptions::new(2e-3)).unwrap();
/// assert!(fair.max_distance() <= 2e-3);
/// let (before, after) = (fair.fairness_before().unwrap(), fair.fairness());
/// assert!(before.curvature_extrema > 10);
/// assert_eq!(after.curvature_extrema, 0);
/// assert!(after.fairness_energy < 1e-2 * before.fairness_energy);
/// ```
pub fn fair_curve<const D: usize>(
    points: &[Point<D>],
    options: &FairOptions,
) -> Result<FairCurve<D>> {
    let mut points = points;
    if options.closed && points.len() > 1 && points[0] == points[points.len() - 1] {
        points = &points[..points.len() - 1];
    }
    check(points, options)?;
    let tangents = if options.ends == FairEnds::KeptWithTangents {
        let n = points.len();
        Some([points[1] - points[0], points[n - 2] - points[n - 1]])
    } else {
        None
    };
    fair_points(points, options, tangents)
}

/// Fairs an existing curve: [`fair_curve`] of `samples` points of it at even parameter steps
/// (closed when the curve is), with its own end tangents when the ends keep tangents.
/// Its fairness before is [`curve_fairness`] of the curve itself.
///
/// Errors: those of [`fair_curve`] on the samples (fewer than four samples among them).
///
/// # Examples
///
/// ```
/// use karkas::bspline::BSplineCurve;
/// use karkas::fair::{fair_existing_curve, FairOptions};
/// use karkas::Point;
///
/// // A cubic with a small wiggle; fairing moves no sample farther than the tolerance.
/// let control = [[0.0, 0.0], [1.0, 0.3], [2.0, -0.1], [3.0, 0.4], [4.0, 0.0]].map(Point);
/// let knots = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
/// let curve = BSplineCurve::new(3, knots, control.to_vec())?;
/// let faired = fair_existing_curve(&curve, 40, &FairOptions::new(0.05))?;
/// assert_eq!(faired.points.len(), 40);
/// assert!(faired.max_distance() <= 0.05 * (1.0 + 1e-9));
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn fair_existing_curve<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    samples: usize,
    options: &FairOptions,
) -> Result<FairCurve<D>> {
    let domain = curve.domain();
    let closed = curve.is_closed();
    let count = samples.max(1);
    let last = if closed {
        count
    } else {
        count.saturating_sub(1).max(1)
    };
    let points: Vec<Point<D>> = (0..count)
        .map(|i| curve.eval(domain.start + (domain.end - domain.start) * i as f64 / last as f64))
        .collect();
    let options = FairOptions {
        closed,
        ..options.clone()
    };
    check(&points, &options)?;
    let tangents = (options.ends == FairEnds::KeptWithTangents)
        .then(|| [curve.deriv(domain.start, 1), -curve.deriv(domain.end, 1)]);
    fair_points(&points, &options, tangents)
}

/// The pipeline on checked points.
fn fair_points<const D: usize>(
    points: &[Point<D>],
    options: &FairOptions,
    tangents: Option<[Point<D>; 2]>,
) -> Result<FairCurve<D>> {
    let frame = Frame::of(points);
    let size = frame.size;
    if size.is_nan() || size <= 0.0 {
        return Err(Error::TooFewPoints {
            what: "a fair curve (distinct points)",
            needed: 2,
            got: 1,
        });
    }
    let scaled: Vec<Point<D>> = points.iter().map(|&p| frame.unit(p)).collect();
    let tolerance = options.tolerance / size;
    let ends = [0, 1].map(|side| end_condition(options.ends, tangents, side));
    let (pieces, order) = fair_pieces(&scaled, tolerance, ends, options)?;
    let total = pieces
        .last()
        .map_or(1.0, |p| *p.space.breaks().last().unwrap_or(&1.0));
    let first_break = pieces[0].space.breaks()[0];
    let length = total - first_break;
    let curve = join_pieces(&pieces, &frame, [first_break, total], options.closed)?;
    // The parameters and distances of the input points, in their input order.
    let n = scaled.len();
    let mut parameters = vec![0.0; n];
    let mut distances = vec![0.0; n];
    for (k, piece) in pieces.iter().enumerate() {
        let offset: usize = pieces[..k].iter().map(|p| p.params.len() - 1).sum();
        for (j, &u) in piece.params.iter().enumerate() {
            let i = order[(offset + j) % order.len()];
            parameters[i] = (u - first_break) / length;
            let (span, s) = piece.space.locate(u);
            distances[i] = piece
                .space
                .eval(&piece.controls, span, s, 0)
                .distance(scaled[i])
                * size;
        }
    }
    let faired = FairCurve {
        curve,
        points: points.to_vec(),
        parameters,
        distances,
    };
    // Energies compared in the fairer's frame (size one): they scale as 1/size^3 and would
    // overflow both for points of size 1e-103 and below.
    let energy = |fair: &FairCurve<D>| {
        let controls = fair.curve.control_points().iter().map(|&c| frame.unit(c));
        BSplineCurve::new(3, fair.curve.knots().to_vec(), controls.collect())
            .map_or(f64::INFINITY, |unit| sampled_fairness_energy(&unit))
    };
    Ok(match interpolant(points, options) {
        Some(through) if energy(&through) < energy(&faired) => through,
        _ => faired,
    })
}

/// The cubic spline through the points (chord-length parameters, not-a-knot ends or
/// periodic: the curve [`FairCurve::fairness_before`] measures) as a fair curve, when the
/// options allow it (no corners, no kept tangents). It is within every tolerance (it passes
/// through every point), so the fairer returns it where its own result, a local minimum of a
/// problem that is not convex, has the higher energy: sparse points under a tolerance far
/// below their spacing, where the barrier can end in a near-cusp between its quadrature
/// nodes. The result's energy is then never above the one reported before fairing.
fn interpolant<const D: usize>(points: &[Point<D>], options: &FairOptions) -> Option<FairCurve<D>> {
    if !options.corners.is_empty() || options.ends == FairEnds::KeptWithTangents {
        return None;
    }
    let ends = if options.closed {
        SplineEnds::Periodic
    } else {
        SplineEnds::NotAKnot
    };
    let spline = CubicSpline::through(points, CurveParameterization::ChordLength, ends).ok()?;
    let curve = spline.to_bspline().ok()?;
    let knots = spline.knots();
    let (first, length) = (knots[0], knots[knots.len() - 1] - knots[0]);
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    let unit = |k: f64| ((k - first) / length).clamp(0.0, 1.0);
    let curve_knots: Vec<f64> = curve.knots().iter().map(|&k| unit(k)).collect();
    let curve = BSplineCurve::new(3, curve_knots, curve.control_points().to_vec())
        .ok()?
        .with_closed(options.closed);
    let parameters: Vec<f64> = knots[..points.len()].iter().map(|&k| unit(k)).collect();
    let distances = parameters
        .iter()
        .zip(points)
        .map(|(&t, &p)| curve.eval(t).distance(p))
        .collect();
    Some(FairCurve {
        curve,
        points: points.to_vec(),
        parameters,
        distances,
    })
}

/// The condition at the curve's end `side` (0 first, 1 last): free, its point, or its point
/// and the unit tangent given (when that is not zero).
fn end_condition<const D: usize>(
    ends: FairEnds,
    tangents: Option<[Point<D>; 2]>,
    side: usize,
) -> End<D> {
    match (ends, tangents) {
        (FairEnds::Free, _) => End::Free,
        (FairEnds::KeptWithTangents, Some(t)) if t[side].norm() > 0.0 => {
            End::Tangent(t[side] * (1.0 / t[side].norm()))
        }
        _ => End::Point,
    }
}

/// The faired pieces between the corners (one piece without corners), and the order of the
/// points along them (a closed curve with corners starts at its first corner and ends there
/// again).
fn fair_pieces<const D: usize>(
    scaled: &[Point<D>],
    tolerance: f64,
    [first_end, last_end]: [End<D>; 2],
    options: &FairOptions,
) -> Result<(Vec<Piece<D>>, Vec<usize>)> {
    let n = scaled.len();
    if options.corners.is_empty() {
        let piece = fair_piece(
            scaled,
            tolerance,
            [first_end, last_end],
            options.closed,
            0.0,
        )?;
        return Ok((vec![piece], (0..n).collect()));
    }
    let mut cuts: Vec<usize> = options.corners.clone();
    let rotated: Vec<usize> = if options.closed {
        let first = cuts[0];
        cuts = cuts.iter().map(|c| c - first).collect();
        cuts.push(n);
        (first..n).chain(0..=first).collect()
    } else {
        cuts.insert(0, 0);
        cuts.push(n - 1);
        (0..n).collect()
    };
    let mut list = Vec::with_capacity(cuts.len() - 1);
    let mut start = 0.0;
    for (k, w) in cuts.windows(2).enumerate() {
        let ids = &rotated[w[0]..=w[1]];
        let piece_points: Vec<Point<D>> = ids.iter().map(|&i| scaled[i]).collect();
        if piece_points.len() < super::options::MIN_POINTS {
            return Err(Error::TooFewPoints {
                what: "a fair curve's piece between corners",
                needed: super::options::MIN_POINTS,
                got: piece_points.len(),
            });
        }
        let first = if k == 0 && !options.closed {
            first_end
        } else {
            End::Point
        };
        let last = if k + 2 == cuts.len() && !options.closed {
            last_end
        } else {
            End::Point
        };
        let piece = fair_piece(&piece_points, tolerance, [first, last], false, start)?;
        start = *piece.space.breaks().last().unwrap_or(&start);
        list.push(piece);
    }
    Ok((list, rotated))
}

/// The pieces' clamped B-splines joined into one (sharing the corner controls), its knots
/// mapped from `[first_break, total]` to `[0, 1]` and its controls back to the points' frame.
fn join_pieces<const D: usize>(
    pieces: &[Piece<D>],
    frame: &Frame<D>,
    [first_break, total]: [f64; 2],
    closed: bool,
) -> Result<BSplineCurve<D>> {
    let length = total - first_break;
    let unscale = |c: &Point<D>| frame.back(*c);
    if pieces.len() == 1 {
        let spline = pieces[0].space.to_bspline(&pieces[0].controls)?;
        let ks: Vec<f64> = spline
            .knots()
            .iter()
            .map(|k| (k - first_break) / length)
            .collect();
        let cs: Vec<Point<D>> = spline.control_points().iter().map(unscale).collect();
        return Ok(BSplineCurve::new(3, ks, cs)?.with_closed(closed));
    }
    let mut knots: Vec<f64> = Vec::new();
    let mut controls: Vec<Point<D>> = Vec::new();
    for (k, piece) in pieces.iter().enumerate() {
        let spline = piece.space.to_bspline(&piece.controls)?;
        let ks = spline.knots();
        let cs = spline.control_points();
        if k == 0 {
            knots.extend_from_slice(&ks[..ks.len() - 1]);
            controls.extend(cs.iter().map(unscale));
        } else {
            knots.extend_from_slice(&ks[4..ks.len() - 1]);
            controls.extend(cs[1..].iter().map(unscale));
        }
    }
    knots.push(total);
    for k in knots.iter_mut() {
        *k = (*k - first_break) / length;
    }
    Ok(BSplineCurve::new(3, knots, controls)?.with_closed(closed))
}
