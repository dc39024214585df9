//! Shape guards of a fit (docs/methods.md §4, "shape guards"): what a designer must be told
//! about a fitted curve that the distances alone do not show.
//!
//! Pavlov's fit bounds the distances of the points from the curve, not its shape between
//! them: where points are close (a leading edge) or end at a sharp corner (a trailing edge) a
//! curve within the tolerance of every point can still loop or hook. [`shape_warnings`]
//! compares the fitted curve with the polygon through the points:
//!
//! - crossings: the curve is sampled densely (16 steps a piece, halved while the tangent turns
//!   more than 0.2 rad) and its self-crossings found by a sweep; a crossing is reported unless
//!   the point polygon crosses itself at the same points (within 2 points either way), or
//!   the polygon's two stretches there lie on branches (the polygon turns at least pi/2 from
//!   one to the other) that come within twice the largest point distance of each other: the
//!   points do not tell such branches apart at the fit's accuracy (the two ends of a closed
//!   contour, a thin cusped trailing edge) — except on either side of a shared end that the
//!   fit's ends meet at (a sharp trailing edge, [`crate::core::shared_end`]): there the corner
//!   tells the branches apart, and a crossing near it is a fault the tolerance mode repairs;
//! - turning: between the foot points of points `i < j`, a curve through the points that
//!   does not inflect between them turns at most as much as the polygon from the segment
//!   before `i` to the segment after `j` (the exterior angles at `i..=j`); a run of points
//!   where the curve turns more than that (plus [`TURNING_RELATIVE`] of it) by over
//!   [`HOOK_TURNING`] is a hook or a loop; and in all, the curve may turn [`TURNING_MARGIN`]
//!   plus [`TURNING_RELATIVE`] beyond the polygon (its exterior angles, the first and the
//!   last point counted with the angles of their neighbours);
//! - the pieces: two adjacent pieces holding fewer than 3 points between them (the paper's
//!   condition for a determined fit), and a knot span holding none.
//!
//! Crossings are looked for in the plane only (`D = 2`): space curves do not meet in general.
//! Cost: `O(n log n)` for `n` points and `O(m log m)` for `m` samples of the curve.

mod crossings;
mod sampling;

use super::result::{CurveFit, FitWarning, FitWarningKind};
use crate::{Curve, Point, Point2};
use crossings::{crossing, crossings, Crossing};
use sampling::Samples;

/// The turning the curve may have beyond the point polygon's, in radians.
pub(crate) const TURNING_MARGIN: f64 = 0.1;
/// The turning the curve may have beyond the point polygon's, as a fraction of it.
pub(crate) const TURNING_RELATIVE: f64 = 0.05;
/// The excess turning over a run of points that makes a hook or a loop, in radians.
pub(crate) const HOOK_TURNING: f64 = 0.5;
/// Points of slack either way when a crossing of the curve is matched to one of the polygon.
const CROSSING_SLACK: usize = 2;
/// Warnings of one kind given one by one; the rest are counted in one more.
const MAX_PER_KIND: usize = 10;

/// A crossing of two segments of a plane polyline: the segments, by the index of their first
/// point (`first < second`), and the crossing point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolylineCrossing {
    /// The first segment, `points[first]` to `points[first + 1]`.
    pub first: usize,
    /// The second segment, `points[second]` to `points[second + 1]`.
    pub second: usize,
    /// Where they cross.
    pub at: Point2,
}

/// Every proper crossing of two non-adjacent segments of the open polyline through `points`,
/// ordered by the segments (the sweep of the shape guards, `O(m log m)` plus the pairs that
/// overlap in x).
pub fn polyline_crossings(points: &[Point2]) -> Vec<PolylineCrossing> {
    let vertices: Vec<[f64; 2]> = points.iter().map(|p| p.0).collect();
    let mut found: Vec<PolylineCrossing> = crossings(&vertices)
        .into_iter()
        .map(|c| PolylineCrossing {
            first: c.a,
            second: c.b,
            at: points[c.a].add_scaled(c.sa, points[c.a + 1] - points[c.a]),
        })
        .collect();
    found.sort_by_key(|c| (c.first, c.second));
    found
}

/// The fit with the shape warnings of [`shape_warnings`] appended.
pub(crate) fn with_warnings<const D: usize>(
    points: &[Point<D>],
    mut fit: CurveFit<D>,
) -> CurveFit<D> {
    let found = shape_warnings(points, &fit);
    fit.warnings.extend(found);
    fit
}

/// The parameters where `fit` crosses itself or turns too much (the shape faults among
/// [`shape_warnings`]); empty for a sound fit. The tolerance mode adds knots there, and
/// removes no knot that makes one.
pub(crate) fn shape_faults<const D: usize>(points: &[Point<D>], fit: &CurveFit<D>) -> Vec<f64> {
    shape_warnings(points, fit)
        .into_iter()
        .filter(|w| {
            matches!(
                w.kind,
                FitWarningKind::SelfIntersection | FitWarningKind::ExcessTurning
            )
        })
        .map(|w| w.parameter)
        .collect()
}

/// The shape warnings of a fit of `points` (see the module documentation): crossings of the
/// curve where the point polygon does not cross itself, turning beyond the polygon's (in all,
/// and hooks or loops between the foot points of a run of points), adjacent pieces holding
/// fewer than 3 points between them, and empty knot spans. Each names the place: a parameter
/// and the coordinates of the curve there. At most 10 warnings of a kind are given one by
/// one; the rest are counted in one more.
pub fn shape_warnings<const D: usize>(points: &[Point<D>], fit: &CurveFit<D>) -> Vec<FitWarning> {
    let n = points.len();
    if n < 3 || fit.parameters.len() != n {
        return Vec::new();
    }
    let guard = Guard {
        points,
        fit,
        samples: Samples::of(&fit.spline),
        angle: exterior_angles(points),
    };
    let mut warnings = Vec::new();
    if D == 2 {
        capped(&mut warnings, guard.crossings());
    }
    capped(&mut warnings, guard.turning());
    capped(&mut warnings, guard.sparse_pieces());
    capped(&mut warnings, guard.empty_spans());
    warnings
}

/// Appends `found` (all of one kind), the first [`MAX_PER_KIND`] one by one and the rest
/// counted in one more warning at the first of them.
fn capped(warnings: &mut Vec<FitWarning>, found: Vec<FitWarning>) {
    if found.len() <= MAX_PER_KIND {
        warnings.extend(found);
        return;
    }
    let rest = &found[MAX_PER_KIND..];
    let more = FitWarning {
        kind: rest[0].kind,
        parameter: rest[0].parameter,
        message: format!(
            "{} more warnings like the above ({}) from t = {}",
            rest.len(),
            rest[0].kind.name(),
            short(rest[0].parameter)
        ),
    };
    warnings.extend(found.into_iter().take(MAX_PER_KIND));
    warnings.push(more);
}

/// A number to 6 significant digits, as short as that allows.
fn short(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let decimals = (5 - v.abs().log10().floor() as i32).clamp(0, 17) as usize;
    let text = format!("{v:.decimals$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// A point as `(x, y, ...)`.
fn coordinates<const D: usize>(p: Point<D>) -> String {
    let parts: Vec<String> = p.coords().iter().map(|&v| short(v)).collect();
    format!("({})", parts.join(", "))
}

/// The exterior angle of the point polygon at every point (repeated points skipped; the
/// first and the last point get the angle of their neighbour).
fn exterior_angles<const D: usize>(points: &[Point<D>]) -> Vec<f64> {
    let n = points.len();
    let mut angle = vec![0.0; n];
    let mut last: Option<Point<D>> = None;
    for i in 1..n {
        let d = points[i] - points[i - 1];
        if d.0.iter().all(|&c| c == 0.0) {
            continue;
        }
        if let Some(previous) = last {
            angle[i - 1] = previous.angle_to(d);
        }
        last = Some(d);
    }
    angle[0] = angle[1];
    angle[n - 1] = angle[n - 2];
    angle
}

/// Whether the polygon crosses itself between a segment within [`CROSSING_SLACK`] of `ga`
/// and a later one within it of `gb` (a crossing of the points that excuses the curve's).
/// Only these few pairs are tested: a sweep of a long noisy polygon finds thousands of
/// crossings at its ends, none of which matter elsewhere.
fn polygon_crosses_near(polygon: &[[f64; 2]], ga: usize, gb: usize) -> bool {
    let segments = polygon.len().saturating_sub(1);
    let near = |g: usize| g.saturating_sub(CROSSING_SLACK)..(g + CROSSING_SLACK + 1).min(segments);
    near(ga).any(|i| near(gb).any(|j| i < j && crossing(polygon, i, j).is_some()))
}

/// The distance between segments `ab` and `cd` in the plane.
fn segment_distance(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    if !crossings(&[a, b, c, d]).is_empty() && !crossings(&[c, d, a, b]).is_empty() {
        return 0.0;
    }
    let to_segment = |p: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        let (ux, uy) = (b[0] - a[0], b[1] - a[1]);
        let len = ux * ux + uy * uy;
        let s = if len > 0.0 {
            (((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / len).clamp(0.0, 1.0)
        } else {
            0.0
        };
        (p[0] - a[0] - s * ux).hypot(p[1] - a[1] - s * uy)
    };
    to_segment(a, c, d)
        .min(to_segment(b, c, d))
        .min(to_segment(c, a, b))
        .min(to_segment(d, a, b))
}

/// The data of the guards of one fit.
struct Guard<'a, const D: usize> {
    points: &'a [Point<D>],
    fit: &'a CurveFit<D>,
    samples: Samples<D>,
    /// The exterior angles of the point polygon ([`exterior_angles`]).
    angle: Vec<f64>,
}

impl<const D: usize> Guard<'_, D> {
    /// The gap `[i, i + 1]` between points whose foot parameters hold `t`.
    fn gap(&self, t: f64) -> usize {
        let n = self.points.len();
        self.fit
            .parameters
            .partition_point(|&s| s <= t)
            .saturating_sub(1)
            .min(n - 2)
    }

    /// The place `t` as "t = .. at (x, y)".
    fn place(&self, t: f64) -> String {
        format!(
            "t = {} at {}",
            short(t),
            coordinates(self.fit.spline.eval(t))
        )
    }

    /// Crossings of the curve where the polygon does not cross itself.
    fn crossings(&self) -> Vec<FitWarning> {
        let mut warnings: Vec<FitWarning> = self.crossing_at_shared_end().into_iter().collect();
        warnings.extend(self.crossings_between_samples());
        warnings
    }

    /// A crossing at a shared end that the fit's ends meet at: the curve's two branches
    /// arrive at the corner in the other order than the points' (the corner turns the other
    /// way), so they cross within the last pieces, right up to the corner, where no two
    /// samples cross properly (they meet at the shared vertex).
    fn crossing_at_shared_end(&self) -> Option<FitWarning> {
        let n = self.points.len();
        let spline = &self.fit.spline;
        let d = spline.domain();
        if n < 4 || !self.around_shared_end(0, n - 2) {
            return None;
        }
        // The signed turn from the direction `a` into `b`, in (-pi, pi].
        let turn =
            |a: Point<D>, b: Point<D>| (a[0] * b[1] - a[1] * b[0]).atan2(a[0] * b[0] + a[1] * b[1]);
        let polygon = turn(
            self.points[n - 1] - self.points[n - 2],
            self.points[1] - self.points[0],
        );
        let curve = turn(spline.deriv(d.end, 1), spline.deriv(d.start, 1));
        // Only a corner (the points turn there by over pi/2: a sharp edge, not the seam of a
        // smooth closed contour, whose tiny turn has no reliable sign) has an order of its
        // branches.
        let corner = polygon.abs() > 0.5 * std::f64::consts::PI;
        (corner && polygon * curve < 0.0).then(|| FitWarning {
            kind: FitWarningKind::SelfIntersection,
            parameter: d.end,
            message: format!(
                "the curve crosses itself at its shared end {}: its two branches arrive there \
                 in the other order than the points'",
                coordinates(spline.eval(d.end))
            ),
        })
    }

    /// Crossings of two samples of the curve where the polygon does not cross itself.
    fn crossings_between_samples(&self) -> Vec<FitWarning> {
        let plane = |p: &Point<D>| [p[0], p[1]];
        let curve: Vec<[f64; 2]> = self.samples.p.iter().map(plane).collect();
        let mut found = crossings(&curve);
        if found.is_empty() {
            return Vec::new();
        }
        let polygon: Vec<[f64; 2]> = self.points.iter().map(plane).collect();
        found.sort_by_key(|c| (c.a, c.b));
        let mut kept: Vec<Crossing> = Vec::new();
        for c in found {
            // One crossing of the curve can show in neighbouring samples twice.
            if kept
                .iter()
                .rev()
                .take(4)
                .any(|k| k.a.abs_diff(c.a) <= 2 && k.b.abs_diff(c.b) <= 2)
            {
                continue;
            }
            kept.push(c);
        }
        let t = &self.samples.t;
        let at = |k: usize, s: f64| t[k] + s * (t[k + 1] - t[k]);
        kept.into_iter()
            .filter_map(|c| {
                let (ta, tb) = self.refine_crossing(
                    (at(c.a, c.sa), at(c.b, c.sb)),
                    (t[c.a.saturating_sub(1)], t[(c.a + 2).min(t.len() - 1)]),
                    (t[c.b.saturating_sub(1)], t[(c.b + 2).min(t.len() - 1)]),
                );
                let (ga, gb) = (self.gap(ta), self.gap(tb));
                let matched = polygon_crosses_near(&polygon, ga, gb);
                let unresolved =
                    !self.around_shared_end(ga, gb) && self.branches_touch(&polygon, ga, gb);
                (!matched && !unresolved).then(|| FitWarning {
                    kind: FitWarningKind::SelfIntersection,
                    parameter: ta,
                    message: format!(
                        "the curve crosses itself at {} (t = {} and t = {}, between points {}-{} and {}-{}) where the points do not",
                        coordinates(self.fit.spline.eval(ta)),
                        short(ta),
                        short(tb),
                        ga + 1,
                        ga + 2,
                        gb + 1,
                        gb + 2
                    ),
                })
            })
            .collect()
    }

    /// The parameters of a crossing `R(ta) = R(tb)` by Newton's method from the crossing of
    /// the samples, kept when it converges inside the given ranges (else the start).
    fn refine_crossing(&self, start: (f64, f64), ra: (f64, f64), rb: (f64, f64)) -> (f64, f64) {
        let spline = &self.fit.spline;
        let (mut ta, mut tb) = start;
        for _ in 0..8 {
            let f = spline.eval(ta) - spline.eval(tb);
            let (da, db) = (spline.deriv(ta, 1), spline.deriv(tb, 1));
            // Solve [da, -db] (x, y) = -f.
            let det = -da[0] * db[1] + db[0] * da[1];
            if det == 0.0 || !det.is_finite() {
                return start;
            }
            let x = (f[0] * db[1] - db[0] * f[1]) / det;
            let y = (f[0] * da[1] - da[0] * f[1]) / det;
            (ta, tb) = (ta + x, tb + y);
            if !(ra.0..=ra.1).contains(&ta) || !(rb.0..=rb.1).contains(&tb) {
                return start;
            }
            if x.abs().max(y.abs()) <= 1e-14 {
                break;
            }
        }
        (ta, tb)
    }

    /// Whether the gaps `ga < gb` lie on either side of a shared end that the fit's two ends
    /// meet at ([`crate::core::shared_end`]: a sharp trailing edge), nearer to each other
    /// around that corner than along the points between them. There the two branches are
    /// told apart by the corner itself: the curve must not cross from one to the other
    /// however thin the edge, so [`branches_touch`](Self::branches_touch) excuses no such
    /// crossing (the tolerance mode then repairs it, or warns).
    fn around_shared_end(&self, ga: usize, gb: usize) -> bool {
        let (ga, gb) = (ga.min(gb), ga.max(gb));
        let gaps = self.points.len() - 1;
        let d = self.fit.spline.domain();
        let (first, last) = (self.fit.spline.eval(d.start), self.fit.spline.eval(d.end));
        let Some(end) = crate::core::shared_end(self.points) else {
            return false;
        };
        // Pinned ends meet to rounding (free ends, `--free-ends`, need not).
        let size = end.distance(self.points[gaps / 2]);
        let meet = first.distance(last) <= 1e-12 * size;
        meet && ga + (gaps - gb) < gb - ga
    }

    /// Whether the polygon's gaps `ga` and `gb` are on two branches (the polygon turns by at
    /// least pi/2 from one to the other) that come within twice the largest point distance
    /// of each other there (one gap either way): at the fit's accuracy the points do not
    /// tell such branches apart, and the curve may cross between them (the two ends of a
    /// closed contour, a thin cusped trailing edge).
    fn branches_touch(&self, polygon: &[[f64; 2]], ga: usize, gb: usize) -> bool {
        let (lo, hi) = (ga.min(gb), ga.max(gb));
        let turned: f64 = self.angle[lo + 1..=hi].iter().sum();
        if turned < 0.5 * std::f64::consts::PI {
            return false;
        }
        let reach = 2.0 * self.fit.max_distance();
        let m = polygon.len() - 1;
        let around = |g: usize| g.saturating_sub(1)..(g + 2).min(m);
        around(lo).any(|i| {
            around(hi).any(|j| {
                segment_distance(polygon[i], polygon[i + 1], polygon[j], polygon[j + 1]) <= reach
            })
        })
    }

    /// Turning beyond the polygon's: in all, and over runs of points (hooks, loops).
    fn turning(&self) -> Vec<FitWarning> {
        let n = self.points.len();
        let angle = &self.angle;
        // Per gap: the polygon's turning (a circle's through its ends) and the curve's.
        let curve_at: Vec<f64> = self
            .fit
            .parameters
            .iter()
            .map(|&t| self.samples.turning_at(t))
            .collect();
        let polygon_gap = |i: usize| 0.5 * (angle[i] + angle[i + 1]);
        let curve_gap = |i: usize| (curve_at[i + 1] - curve_at[i]).abs();
        let polygon_total: f64 = angle.iter().sum();
        let curve_total = self.samples.total_turning();
        // Between the foot points of points m < k the curve may turn as much as the polygon
        // from the segment before m to the one after k (so it does on a convex stretch
        // through the points): the angles at m..=k. With S the running sum of the gaps'
        // excess over their share (half the angles at either end), the window's excess is
        // (S_k - r a_k / 2) - (S_m + r a_m / 2), r = 1 + TURNING_RELATIVE. Windows whose
        // excess passes HOOK_TURNING are hooks or loops.
        let r = 1.0 + TURNING_RELATIVE;
        let mut hooks = Vec::new();
        let mut sum = 0.0;
        let (mut low, mut low_at) = (r * 0.5 * angle[0], 0usize);
        let (mut peak, mut peak_at) = (f64::NEG_INFINITY, 0usize);
        let mut worst = (f64::NEG_INFINITY, 0usize, 0usize);
        for i in 0..n - 1 {
            sum += curve_gap(i) - r * polygon_gap(i);
            let k = i + 1;
            let high = sum - r * 0.5 * angle[k];
            if high - low > worst.0 {
                worst = (high - low, low_at, k);
            }
            if high - low > HOOK_TURNING && high > peak {
                (peak, peak_at) = (high, k);
            }
            let closes = peak.is_finite() && (high < peak - HOOK_TURNING || k == n - 1);
            let here = sum + r * 0.5 * angle[k];
            if closes {
                hooks.push(self.hook(low_at, peak_at, &curve_at));
                (low, low_at, peak) = (here, k, f64::NEG_INFINITY);
            } else if here < low {
                (low, low_at) = (here, k);
            }
        }
        let allowed = polygon_total * (1.0 + TURNING_RELATIVE) + TURNING_MARGIN;
        if curve_total > allowed {
            let t = self.middle_turning(curve_at[worst.1], curve_at[worst.2]);
            hooks.insert(
                0,
                FitWarning {
                    kind: FitWarningKind::ExcessTurning,
                    parameter: t,
                    message: format!(
                        "the curve turns {} rad in all, the points' polygon {} rad (allowed {} = {} rad + {}%); most beyond it between points {} and {}, {}",
                        short(curve_total),
                        short(polygon_total),
                        short(allowed),
                        TURNING_MARGIN,
                        100.0 * TURNING_RELATIVE,
                        worst.1 + 1,
                        worst.2 + 1,
                        self.place(t)
                    ),
                },
            );
        }
        hooks
    }

    /// The warning of a hook or loop between points `i` and `j`.
    fn hook(&self, i: usize, j: usize, curve_at: &[f64]) -> FitWarning {
        let curve = (curve_at[j] - curve_at[i]).abs();
        let polygon: f64 = self.angle[i..=j].iter().sum();
        let t = self.middle_turning(curve_at[i], curve_at[j]);
        let params = &self.fit.parameters;
        FitWarning {
            kind: FitWarningKind::ExcessTurning,
            parameter: t,
            message: format!(
                "the curve turns {} rad between points {} and {} (t = {}..{}), the points' polygon {} rad: a hook or a loop at {}",
                short(curve),
                i + 1,
                j + 1,
                short(params[i]),
                short(params[j]),
                short(polygon),
                self.place(t)
            ),
        }
    }

    /// The parameter where the curve's cumulative turning is halfway between `a` and `b`.
    fn middle_turning(&self, a: f64, b: f64) -> f64 {
        let half = 0.5 * (a + b);
        let k = self.samples.turn.partition_point(|&c| c < half);
        self.samples.t[k.min(self.samples.t.len() - 1)]
    }

    /// The number of foot parameters on every piece.
    fn counts(&self) -> Vec<usize> {
        let mut count = vec![0usize; self.fit.spline.pieces()];
        for &t in &self.fit.parameters {
            count[self.fit.spline.locate(t).0] += 1;
        }
        count
    }

    /// Runs of inner knots whose two pieces hold fewer than 3 points between them.
    fn sparse_pieces(&self) -> Vec<FitWarning> {
        let count = self.counts();
        let knots = self.fit.spline.knots();
        let sparse: Vec<usize> = (1..count.len())
            .filter(|&l| count[l - 1] + count[l] < 3)
            .collect();
        runs(&sparse)
            .into_iter()
            .map(|(first, last)| {
                let t = knots[first];
                let held: usize = count[first - 1..=last].iter().sum();
                let message = if first == last {
                    format!(
                        "the two pieces at knot {} ({}) hold {} points between them (fewer than 3)",
                        first + 1,
                        self.place(t),
                        count[first - 1] + count[first]
                    )
                } else {
                    format!(
                        "the pieces at knots {} to {} (t = {}..{}, from {}) hold {} points in all, fewer than 3 in every two adjacent ones",
                        first + 1,
                        last + 1,
                        short(knots[first]),
                        short(knots[last]),
                        coordinates(self.fit.spline.eval(t)),
                        held
                    )
                };
                FitWarning {
                    kind: FitWarningKind::SparsePieces,
                    parameter: t,
                    message,
                }
            })
            .collect()
    }

    /// Runs of knot spans holding no point.
    fn empty_spans(&self) -> Vec<FitWarning> {
        let count = self.counts();
        let knots = self.fit.spline.knots();
        let empty: Vec<usize> = (0..count.len()).filter(|&k| count[k] == 0).collect();
        runs(&empty)
            .into_iter()
            .map(|(first, last)| {
                let t = 0.5 * (knots[first] + knots[last + 1]);
                let which = if first == last {
                    format!("the knot span {} holds", first + 1)
                } else {
                    format!("the knot spans {} to {} hold", first + 1, last + 1)
                };
                FitWarning {
                    kind: FitWarningKind::EmptySpan,
                    parameter: t,
                    message: format!(
                        "{which} no point (t = {}..{}, middle at {})",
                        short(knots[first]),
                        short(knots[last + 1]),
                        coordinates(self.fit.spline.eval(t))
                    ),
                }
            })
            .collect()
    }
}

/// The runs of consecutive numbers in an increasing list, as (first, last).
fn runs(sorted: &[usize]) -> Vec<(usize, usize)> {
    let mut out: Vec<(usize, usize)> = Vec::new();
    for &k in sorted {
        match out.last_mut() {
            Some(run) if run.1 + 1 == k => run.1 = k,
            _ => out.push((k, k)),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearby_test_matches_the_crossings_of_the_whole_polygon() {
        let polygon = crossings::jittered_lissajous(90, 0.04);
        let mut all: Vec<(usize, usize)> = crossings(&polygon).iter().map(|c| (c.a, c.b)).collect();
        all.sort_unstable();
        assert!(all.len() > 5, "{all:?}");
        let segments = polygon.len() - 1;
        let mut excused = 0;
        for ga in 0..segments {
            for gb in ga..segments {
                let swept = all.iter().any(|&(a, b)| {
                    a.abs_diff(ga) <= CROSSING_SLACK && b.abs_diff(gb) <= CROSSING_SLACK
                });
                assert_eq!(polygon_crosses_near(&polygon, ga, gb), swept, "{ga} {gb}");
                excused += usize::from(swept);
            }
        }
        assert!(excused > 40, "{excused}");
    }
}
