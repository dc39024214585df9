//! Distances between polylines: what the fitting demo (Pavlov, docs/methods.md §4) measures
//! against a true contour (where its points cross themselves comes from
//! [`karkas::fit::polyline_crossings`]).

use karkas::Point2;

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
    fn distances_to_a_polyline_are_to_its_segments() {
        let line = [p(0.0, 0.0), p(4.0, 0.0)];
        let (d, at) = farthest_from(&[p(1.0, 0.5), p(2.0, -1.5), p(6.0, 0.0)], &line);
        assert_eq!((d, at), (2.0, p(6.0, 0.0)));
        let (d, _) = farthest_from(&[p(2.0, 3.0)], &line);
        assert_eq!(d, 3.0);
    }
}
