//! Fitting measured points (Kuznetsov, Filatov): `fit_curve` and the Python class
//! `HermiteSpline` it returns.

use std::sync::Arc;

use karkas::fit::{self, FitOptions, HermiteSpline};
use pyo3::prelude::*;

use crate::convert::{as_points, by_dim, count, extract_vector, FlatPoints, Numbers, PointsArray};
use crate::curve::PyCurve;
use crate::errors::{library_error, KnotsError, OptionError};
use crate::limits::{bytes_of, check_memory};
use crate::wrapper::{CurveImpl, Wrapped};

/// A C^1 cubic Hermite spline (a cubic spline of defect 2) on [0, 1], as returned by
/// fit_curve: values and derivatives at its knots.
#[pyclass(extends = PyCurve, module = "karkas", name = "HermiteSpline", frozen)]
pub struct PyHermiteSpline {
    /// The knots 0 = T_1 < ... < T_N = 1.
    #[pyo3(get)]
    knots: Numbers,
    /// The values R_L at the knots, (N, d).
    #[pyo3(get)]
    values: FlatPoints,
    /// The derivatives H_L at the knots, (N, d).
    #[pyo3(get)]
    derivatives: FlatPoints,
    /// The largest distance of a fitted point from the curve.
    #[pyo3(get)]
    max_distance: f64,
    /// The root-mean-square distance of the fitted points from the curve.
    #[pyo3(get)]
    rms_distance: f64,
    /// f = sum delta_L |J_L|^2, the weighted sum of squared second-derivative jumps.
    #[pyo3(get)]
    jump_sum: f64,
    /// For a fit by tolerance: whether every point is within it (None otherwise).
    #[pyo3(get)]
    tolerance_met: Option<bool>,
    /// The foot parameter of every fitted point, (n,).
    #[pyo3(get)]
    parameters: Numbers,
    /// The distance of every fitted point from the curve, (n,).
    #[pyo3(get)]
    distances: Numbers,
}

/// What a fit is asked for.
enum Target {
    /// The knots of the spline.
    Knots(Vec<f64>),
    /// The largest distance allowed: knots are added until every point is within it.
    Tolerance(f64),
}

/// The bytes a fit of `points` points in `dim` dimensions with `knots` knots works in: per
/// knot the knots and spline, the Newton solver's per-piece blocks (16 and `16 dim^2` numbers,
/// twice), its vectors of `2 dim` unknowns and the banded normal equations (bandwidth
/// `4 dim`); per point the foot parameters, distances and projections.
fn fit_bytes(points: usize, knots: usize, dim: usize) -> u128 {
    let per_knot = 8 * (32 + 48 * dim * dim + 2 * dim * (16 + 8 * dim)) as u128;
    let per_point = 8 * (4 * dim + 8) as u128;
    bytes_of(&[knots], per_knot).saturating_add(bytes_of(&[points], per_point))
}

/// fit_curve(points, knots=None, tolerance=None, eps=None, pin_ends=False, corners=None,
/// fairness=None) -> HermiteSpline
///
/// Fits measured points (n, d) with a C^1 cubic Hermite spline on [0, 1], minimizing the sum of
/// squared foot-point distances with the sum of squared second-derivative jumps bounded by eps
/// (None: no bound). knots: an int (that many uniform knots) or an increasing array from 0 to
/// 1; tolerance: knots are added until every point is within it. Give knots or tolerance.
#[pyfunction]
#[pyo3(signature = (points, knots = None, tolerance = None, eps = None, pin_ends = false, corners = None, fairness = None))]
#[allow(clippy::too_many_arguments)]
pub fn fit_curve(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    knots: Option<&Bound<'_, PyAny>>,
    tolerance: Option<f64>,
    eps: Option<f64>,
    pin_ends: bool,
    corners: Option<&Bound<'_, PyAny>>,
    fairness: Option<f64>,
) -> PyResult<Py<PyHermiteSpline>> {
    let (pts, dim) = PointsArray::extract_checked(points, "points")?;
    let knots: Option<Vec<f64>> = match knots {
        None => None,
        Some(k) => match k.extract::<i64>() {
            Ok(n) => {
                let n = count(n, "knots")?;
                if n < 2 {
                    return Err(KnotsError::new_err(format!(
                        "knots must be at least 2 (got {n})"
                    )));
                }
                check_memory(
                    py,
                    &format!("fit_curve(knots={n})"),
                    fit_bytes(pts.len(), n, dim),
                )?;
                Some(fit::uniform_knots(n))
            }
            Err(_) => Some(extract_vector(k, "knots")?),
        },
    };
    let target = match (knots, tolerance) {
        (Some(_), Some(_)) => {
            return Err(OptionError::new_err("give knots or tolerance, not both"))
        }
        (Some(knots), None) => Target::Knots(knots),
        (None, Some(tolerance)) => Target::Tolerance(tolerance),
        (None, None) => return Err(OptionError::new_err("give the knots or a tolerance")),
    };
    let mut options = FitOptions {
        pin_ends,
        corners: corners
            .map(|c| extract_vector(c, "corners"))
            .transpose()?
            .unwrap_or_default(),
        ..FitOptions::default()
    };
    if let Some(eps) = eps {
        options.eps = eps;
    }
    if let Some(fairness) = fairness {
        options.fairness = fairness;
    }
    if let Target::Knots(knots) = &target {
        check_memory(
            py,
            &format!("fit_curve with {} knots", knots.len()),
            fit_bytes(pts.len(), knots.len(), dim),
        )?;
    }
    let flat = pts.flat();
    let (inner, sub): (Arc<dyn CurveImpl>, PyHermiteSpline) = by_dim!(dim, D => {
        let p = as_points::<D>(&flat);
        let (result, met) = py
            .detach(|| -> karkas::Result<(fit::CurveFit<D>, Option<bool>)> {
                match &target {
                    Target::Knots(knots) => Ok((fit::fit_curve(p, knots, &options)?, None)),
                    Target::Tolerance(tol) => {
                        let a = fit::fit_curve_adaptive(p, *tol, &options)?;
                        Ok((a.fit, Some(a.tolerance_met)))
                    }
                }
            })
            .map_err(library_error)?;
        let spline: HermiteSpline<D> = result.spline.clone();
        let sub = PyHermiteSpline {
            knots: Numbers(spline.knots().to_vec()),
            values: FlatPoints::of(spline.values()),
            derivatives: FlatPoints::of(spline.derivatives()),
            max_distance: result.max_distance(),
            rms_distance: result.rms_distance(),
            jump_sum: result.jump_sum,
            tolerance_met: met,
            parameters: Numbers(result.parameters.clone()),
            distances: Numbers(result.distances.clone()),
        };
        (Arc::new(Wrapped::<_, D>(spline)) as Arc<dyn CurveImpl>, sub)
    });
    let description = format!(
        "<karkas.HermiteSpline fit of {} points in {dim}-D, {} knots, max_distance={:.3e}, rms_distance={:.3e}",
        pts.len(),
        sub.knots.0.len(),
        sub.max_distance,
        sub.rms_distance
    );
    Py::new(
        py,
        PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(sub),
    )
}
