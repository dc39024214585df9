//! Where a polygon of points crosses itself, and distances between polylines: what the fitting
//! demo (Pavlov, docs/methods.md §4) says about its data and measures against a true contour.

use karkas::Point2;

/// A crossing of two segments of an open polygon: the segments (by their first point's index,
/// from 0) and the crossing point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// The first segment, `points[first]` to `points[first + 1]`.
    pub first: usize,
    /// The second segment, `points[second]` to `points[second + 1]`.
    pub second: usize,
    /// Where they cross.
    pub at: Point2,
}

/// Every crossing of two non-adjacent segments of the open polygon through `points`
/// (all pairs: the polygons here are short).
pub fn self_crossings(points: &[Point2]) -> Vec<Crossing> {
    let mut found = Vec::new();
    let segments = points.len().saturating_sub(1);
    for i in 0..segments {
        for j in i + 2..segments {
            let (a, b, c, d) = (points[i], points[i + 1], points[j], points[j + 1]);
            let r = [b[0] - a[0], b[1] - a[1]];
            let s = [d[0] - c[0], d[1] - c[1]];
            let denominator = r[0] * s[1] - r[1] * s[0];
            if denominator == 0.0 {
                continue;
            }
            let ac = [c[0] - a[0], c[1] - a[1]];
            let t = (ac[0] * s[1] - ac[1] * s[0]) / denominator;
            let u = (ac[0] * r[1] - ac[1] * r[0]) / denominator;
            if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&u) {
                found.push(Crossing {
                    first: i,
                    second: j,
                    at: Point2::new([a[0] + t * r[0], a[1] + t * r[1]]),
                });
            }
        }
    }
    found
}

/// The distance from `p` to the segment `a`..`b`.
fn segment_distance(p: Point2, a: Point2, b: Point2) -> f64 {
    let ab = [b[0] - a[0], b[1] - a[1]];
    let ap = [p[0] - a[0], p[1] - a[1]];
    let length2 = ab[0] * ab[0] + ab[1] * ab[1];
    let t = if length2 > 0.0 {
        ((ap[0] * ab[0] + ap[1] * ab[1]) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (ap[0] - t * ab[0]).hypot(ap[1] - t * ab[1])
}

/// The largest distance from a point of `from` to the polyline `to`, and that point (one
/// direction of the Hausdorff distance; all pairs).
pub fn farthest_from(from: &[Point2], to: &[Point2]) -> (f64, Point2) {
    let mut worst = (0.0, Point2::new([f64::NAN, f64::NAN]));
    for &p in from {
        let near = match to {
            [single] => (p[0] - single[0]).hypot(p[1] - single[1]),
            _ => to
                .windows(2)
                .map(|w| segment_distance(p, w[0], w[1]))
                .fold(f64::INFINITY, f64::min),
        };
        if near > worst.0 {
            worst = (near, p);
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new([x, y])
    }

    #[test]
    fn a_bow_tie_crosses_once_in_its_middle() {
        let found = self_crossings(&[p(0.0, 0.0), p(2.0, 2.0), p(2.0, 0.0), p(0.0, 2.0)]);
        assert_eq!(found.len(), 1);
        assert_eq!((found[0].first, found[0].second), (0, 2));
        assert!((found[0].at[0] - 1.0).abs() < 1e-15 && (found[0].at[1] - 1.0).abs() < 1e-15);
        assert!(self_crossings(&[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]).is_empty());
    }

    #[test]
    fn distances_to_a_polyline_are_to_its_segments() {
        let line = [p(0.0, 0.0), p(4.0, 0.0)];
        let (d, at) = farthest_from(&[p(1.0, 0.5), p(2.0, -1.5), p(6.0, 0.0)], &line);
        assert_eq!((d, at), (2.0, p(6.0, 0.0)));
        let (d, _) = farthest_from(&[p(2.0, 3.0)], &line);
        assert_eq!(d, 3.0);
    }
}
