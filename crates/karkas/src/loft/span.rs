//! The spanwise rules of a loft (docs/methods.md §7.3): how the surface runs from one
//! section to the next. The sections share their knot vector along the section (`v`), so
//! every control point of a section has one partner in every other section, and the surface
//! is the tensor-product B-spline whose `u` direction interpolates each such row of partners
//! at the span stations:
//!
//! - [`SpanRule::Linear`]: straight lines between partners (degree 1, `C^0` at the sections):
//!   a ruled surface between consecutive sections.
//! - [`SpanRule::Monotone`]: the shape-preserving cubic Hermite interpolant (Fritsch and
//!   Carlson's slopes, as SciPy's `PchipInterpolator` chooses them) of every coordinate of
//!   every control point, `C^1` (double knots at the stations). Where a coordinate is monotone
//!   over two consecutive sections it stays monotone between them, and it never leaves the
//!   range of its two end values. The leading edge (the surface at `v = 1/2`) and the two
//!   trailing-edge control points get their own slopes: the leading edge is the same
//!   interpolant of the placed leading edges, and the trailing edge's middle and its gap (upper
//!   minus lower end) are each interpolated so, so that a sharp trailing edge stays sharp and a
//!   gap never changes sign between sections whose gaps have one sign.
//! - [`SpanRule::Spline`]: the not-a-knot cubic spline (`C^2`) of every control point, as
//!   [`CubicSpline`](crate::param::CubicSpline) builds it: the smoothest, but it may overshoot
//!   between sections.

#![allow(clippy::needless_range_loop)] // slopes and values of a grid's columns by station

use super::pchip::pchip_slopes;
use super::placed_slopes::placed_slopes;
use super::placement::SectionFrame;
use super::wing_path::{Rows, WingPath};
use crate::bspline::{hermite_curve, BSplineSurface, ToBSplineCurve};
use crate::core::Grid;
use crate::param::{CubicSpline, SplineEnds};
use crate::{Error, Point2, Point3, Result};

/// How the surface runs between sections.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SpanRule {
    /// Ruled between consecutive sections (`C^0` at them).
    Linear,
    /// Shape-preserving cubic Hermite (`C^1`): no overshoot between sections (the default).
    #[default]
    Monotone,
    /// Not-a-knot cubic spline (`C^2`).
    Spline,
}

impl SpanRule {
    /// The names the command line and Python use: `linear`, `monotone`, `spline`.
    pub const NAMES: [&'static str; 3] = ["linear", "monotone", "spline"];

    /// The rule's name.
    pub fn name(self) -> &'static str {
        match self {
            SpanRule::Linear => "linear",
            SpanRule::Monotone => "monotone",
            SpanRule::Spline => "spline",
        }
    }
}

impl std::str::FromStr for SpanRule {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self> {
        match s {
            "linear" => Ok(SpanRule::Linear),
            "monotone" => Ok(SpanRule::Monotone),
            "spline" => Ok(SpanRule::Spline),
            _ => Err(Error::UnknownName {
                what: "span rule",
                name: s.to_owned(),
                expected: &SpanRule::NAMES,
            }),
        }
    }
}

/// What the monotone rule keeps besides each control point: the leading edge as the
/// combination `weights` of the control points from `first`, and the trailing-edge pair (the
/// first and last control points).
#[derive(Clone, Copy, Debug)]
pub(crate) struct KeptLines<'a> {
    pub leading_edge: Option<(usize, [f64; 4])>,
    /// The sections' frames and their control points in their planes, when the loft knows
    /// them: the slopes are then taken through the placement (`placed_slopes.rs`).
    pub placement: Option<(&'a [SectionFrame], &'a Grid<Point2>)>,
    /// The loft's tolerance (a share of each section's chord): how far the monotone rule lets
    /// a wing's chord and twist pass their neighbours' range between sections.
    pub tolerance: f64,
}

/// The surface over the span `stations` through the placed control nets `nets` (row `k`
/// the control points of section `k`) with the knot vector `knots_v` along the sections.
pub(crate) fn span_surface(
    rule: SpanRule,
    stations: &[f64],
    nets: &Grid<Point3>,
    knots_v: Vec<f64>,
    kept: KeptLines,
) -> Result<BSplineSurface<3>> {
    let (n, m) = (nets.rows(), nets.cols());
    match rule {
        SpanRule::Linear => {
            let mut knots = vec![stations[0]];
            knots.extend_from_slice(stations);
            knots.push(stations[n - 1]);
            BSplineSurface::new((1, knots), (3, knots_v), nets.clone())
        }
        SpanRule::Spline => {
            let mut columns = Vec::with_capacity(m);
            let mut knots_u = Vec::new();
            let mut column = vec![Point3::ZERO; n];
            for i in 0..m {
                for (k, c) in column.iter_mut().enumerate() {
                    *c = *nets.get(k, i);
                }
                let curve =
                    CubicSpline::new(stations, &column, SplineEnds::NotAKnot)?.to_bspline()?;
                knots_u = curve.knots().to_vec();
                columns.push(curve.control_points().to_vec());
            }
            let rows = columns[0].len();
            let control = Grid::from_fn(rows, m, |r, i| columns[i][r]);
            BSplineSurface::new((3, knots_u), (3, knots_v), control)
        }
        SpanRule::Monotone => {
            let path = match (kept.leading_edge, kept.placement) {
                (Some(le), Some(placement)) => WingPath::new(stations, placement, nets, le),
                _ => None,
            };
            let slopes = monotone_slopes(stations, nets, kept, path.as_ref());
            let rows = match &path {
                Some(path) => path.refine(nets, &slopes, kept.tolerance),
                None => Rows {
                    stations: stations.to_vec(),
                    values: nets.as_slice().to_vec(),
                    slopes: slopes.as_slice().to_vec(),
                },
            };
            hermite_surface(&rows, m, knots_v)
        }
    }
}

/// The surface whose `u` direction is the cubic Hermite interpolant (`C^1`, double knots) of
/// the control rows `rows` (`m` control points a row) at their stations.
fn hermite_surface(rows: &Rows, m: usize, knots_v: Vec<f64>) -> Result<BSplineSurface<3>> {
    let n = rows.stations.len();
    let mut columns = Vec::with_capacity(m);
    let mut knots_u = Vec::new();
    let (mut values, mut derivs) = (vec![Point3::ZERO; n], vec![Point3::ZERO; n]);
    for i in 0..m {
        for k in 0..n {
            values[k] = rows.values[k * m + i];
            derivs[k] = rows.slopes[k * m + i];
        }
        let curve = hermite_curve(&rows.stations, &values, &derivs, 2)?;
        knots_u = curve.knots().to_vec();
        columns.push(curve.control_points().to_vec());
    }
    let count = columns[0].len();
    let control = Grid::from_fn(count, m, |r, i| columns[i][r]);
    BSplineSurface::new((3, knots_u), (3, knots_v), control)
}

/// The monotone rule's slopes of every control point at every station (see the module docs).
fn monotone_slopes(
    stations: &[f64],
    nets: &Grid<Point3>,
    kept: KeptLines,
    path: Option<&WingPath>,
) -> Grid<Point3> {
    let (n, m) = (nets.rows(), nets.cols());
    let placed = match path {
        Some(path) => Some(path.station_slopes()),
        None => kept.placement.and_then(|(frames, profiles)| {
            placed_slopes(stations, frames, profiles, kept.leading_edge)
        }),
    };
    let through_placement = placed.is_some();
    let mut slopes = placed.unwrap_or_else(|| coordinate_slopes(stations, nets));
    // The trailing edge: its middle (through the placement, or interpolated on its own) and
    // its gap, interpolated on its own.
    for c in 0..3 {
        let gap: Vec<f64> = (0..n)
            .map(|k| nets.get(k, 0)[c] - nets.get(k, m - 1)[c])
            .collect();
        let mid: Vec<f64> = (0..n)
            .map(|k| 0.5 * (nets.get(k, 0)[c] + nets.get(k, m - 1)[c]))
            .collect();
        let (mut dg, mut dm) = (vec![0.0; n], vec![0.0; n]);
        pchip_slopes(stations, &gap, &mut dg);
        if through_placement {
            for k in 0..n {
                dm[k] = 0.5 * (slopes.get(k, 0)[c] + slopes.get(k, m - 1)[c]);
            }
        } else {
            pchip_slopes(stations, &mid, &mut dm);
        }
        for k in 0..n {
            let mid = dm[k];
            slopes.get_mut(k, 0)[c] = mid + 0.5 * dg[k];
            slopes.get_mut(k, m - 1)[c] = mid - 0.5 * dg[k];
        }
    }
    // The leading edge: the least change of its control points' slopes that gives it the
    // slopes of its own interpolant.
    if let Some((first, w)) = kept.leading_edge {
        let norm_sq: f64 = w.iter().map(|x| x * x).sum();
        for c in 0..3 {
            let le: Vec<f64> = (0..n)
                .map(|k| (0..4).map(|a| w[a] * nets.get(k, first + a)[c]).sum())
                .collect();
            let mut want = vec![0.0; n];
            pchip_slopes(stations, &le, &mut want);
            for (k, &target) in want.iter().enumerate() {
                let have: f64 = (0..4).map(|a| w[a] * slopes.get(k, first + a)[c]).sum();
                let fix = (target - have) / norm_sq;
                for (a, &wa) in w.iter().enumerate() {
                    slopes.get_mut(k, first + a)[c] += wa * fix;
                }
            }
        }
    }
    slopes
}

/// Fritsch and Carlson's slopes of every coordinate of every control point on its own.
fn coordinate_slopes(stations: &[f64], nets: &Grid<Point3>) -> Grid<Point3> {
    let (n, m) = (nets.rows(), nets.cols());
    let mut slopes = Grid::from_fn(n, m, |_, _| Point3::ZERO);
    let mut values = vec![0.0; n];
    let mut out = vec![0.0; n];
    for i in 0..m {
        for c in 0..3 {
            for k in 0..n {
                values[k] = nets.get(k, i)[c];
            }
            pchip_slopes(stations, &values, &mut out);
            for k in 0..n {
                slopes.get_mut(k, i)[c] = out[k];
            }
        }
    }
    slopes
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::hermite_basis;

    #[test]
    fn pchip_keeps_monotone_data_monotone_and_flat_at_extrema() {
        let x = [0.0, 1.0, 1.5, 4.0, 5.0];
        let y = [0.0, 0.1, 3.0, 3.1, 0.0];
        let mut m = [0.0; 5];
        pchip_slopes(&x, &y, &mut m);
        assert_eq!(m[3], 0.0, "{m:?}"); // 3.1 is a maximum
        for k in 0..4 {
            let (lo, hi) = (y[k].min(y[k + 1]), y[k].max(y[k + 1]));
            for s in 1..100 {
                let t = s as f64 / 100.0;
                let b = hermite_basis(t, x[k + 1] - x[k], 0);
                let v = b[0] * y[k] + b[1] * m[k] + b[2] * y[k + 1] + b[3] * m[k + 1];
                assert!(v >= lo - 1e-15 && v <= hi + 1e-15, "{k} {t} {v}");
            }
        }
    }
}
