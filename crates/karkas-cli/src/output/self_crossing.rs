//! The warning of a plane curve that crosses itself where its points do not.
//!
//! An interpolating curve keeps to its points but not to their polygon between them: where
//! neighbouring points lie very unevenly apart (a point `4e-4` from the leading edge of an
//! airfoil whose next points are `6e-3` away), a curve with uniform node parameters (the
//! interpolating LL curve of Aulchenko et al.) overshoots into a small loop. CAD systems make
//! no valid face from a looping profile, so `curve ll` and `curve spline` say so in one line
//! naming the file. The crossings are found by the shape guards' sweep
//! ([`karkas::fit::polyline_crossings`]) on dense samples: `O(m log m)` for `m` samples.

use super::console::note;
use karkas::fit::polyline_crossings;
use karkas::{Curve, Point, Point2};
use karkas_io::export::samples::sample_curve;
use std::path::Path;

/// Samples of the curve per input point when looking for crossings.
const SAMPLES_PER_POINT: usize = 32;
/// At most this many samples, whatever the number of points.
const MAX_CROSSING_SAMPLES: usize = 1 << 20;

/// Warns, in one line naming `input`, when the plane curve `curve` through `points` crosses
/// itself while the polygon through `points` does not. Space curves (`D != 2`) are not
/// checked: they do not meet in general. `remedy` ends the line (what keeps the curve to the
/// points).
pub fn warn_self_crossing<const D: usize>(
    curve: &impl Curve<D>,
    points: &[Point<D>],
    input: &Path,
    remedy: &str,
) {
    if D != 2 || points.len() < 4 {
        return;
    }
    let plane = |p: &Point<D>| Point2::new([p[0], p[1]]);
    let polygon: Vec<Point2> = points.iter().map(plane).collect();
    if !polyline_crossings(&polygon).is_empty() {
        return;
    }
    let n = (SAMPLES_PER_POINT * points.len()).min(MAX_CROSSING_SAMPLES);
    let (_, samples) = sample_curve(curve, n);
    let mut line: Vec<Point2> = samples.iter().map(plane).collect();
    if polygon[0] == polygon[polygon.len() - 1] {
        // The points' ends are one point (a shared end, or a closed curve's seam): the curve's
        // ends meet there by construction, its two end samples only to round-off (the ends of
        // the domain evaluate apart in the last bit). One bit apart, the first and last
        // segments cross properly at the corner: a crossing of round-off, not of the curve.
        let first = line[0];
        if let Some(last) = line.last_mut() {
            *last = first;
        }
    }
    let found = polyline_crossings(&line);
    let Some(first) = found.first() else {
        return;
    };
    let near = polygon
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.distance(first.at).total_cmp(&b.1.distance(first.at)))
        .map_or(0, |(k, _)| k);
    note(format!(
        "karkas: warning: {}: the curve crosses itself {} time{} where the points do not, \
         first at ({:.6}, {:.6}) near point {} of {} (the loop makes no valid CAD face); {remedy}",
        input.display(),
        found.len(),
        if found.len() == 1 { "" } else { "s" },
        first.at[0],
        first.at[1],
        near + 1,
        points.len()
    ));
}
