//! Fitting measured points (Kuznetsov, Filatov): `fit_curve` and the Python class
//! `HermiteSpline` it returns.

use std::sync::Arc;

use karkas::fit::{self, FitEnds, FitOptions, HermiteSpline, DEFAULT_FAIRNESS};
use pyo3::prelude::*;

use crate::convert::{as_points, by_dim, extract_vector, FlatPoints, Numbers, PointsArray};
use crate::curve::PyCurve;
use crate::erased::{CurveImpl, Wrapped};
use crate::errors::{library_error, KnotsError, OptionError};
use crate::limits::{bytes_of, check_memory};

/// A C^1 cubic Hermite spline (a cubic spline of defect 2) on [0, 1]: the result of
/// ``fit_curve``, with its values and derivatives at its knots and the fit's figures.
///
/// ``HermiteSpline(knots, values, derivatives)`` builds one with these values and first
/// derivatives at the knots ``0 = T_1 < ... < T_N = 1``. Calling the curve is described in
/// ``Curve``.
///
/// Outside the domain (the rule of every curve class): a closed curve wraps the parameter by
/// its period; an open curve continues its end polynomial pieces when ``extrapolate`` is None
/// or True (SciPy's ``BSpline`` default; the values of ``BSpline(*c.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
///
/// Parameters
/// ----------
/// knots : array_like, shape (N,)
///     Strictly increasing, from 0 to 1.
/// values, derivatives : array_like, shape (N, d)
///     The points R_L and the derivatives H_L at the knots, d in {2, 3}.
///
/// Returns
/// -------
/// HermiteSpline
///     A spline that is not a fit: max_distance, rms_distance and jump_sum are NaN,
///     tolerance_met is None, parameters and distances are empty.
///
/// Raises
/// ------
/// KnotsError, PointsError
///     For bad knots, or values and derivatives of the wrong shape.
///
/// Examples
/// --------
/// >>> import karkas
/// >>> c = karkas.HermiteSpline([0.0, 1.0], [[0.0, 0.0], [1.0, 0.0]], [[1.0, 0.0], [1.0, 0.0]])
/// >>> c(0.5).tolist()
/// [0.5, 0.0]
/// >>> s = np.linspace(0.0, 1.0, 50)
/// >>> f = karkas.fit_curve(np.column_stack([s, s * s]), knots=5)
/// >>> f.domain, f.knots.shape, f.values.shape, f.derivatives.shape
/// ((0.0, 1.0), (5,), (5, 2), (5, 2))
/// >>> f.max_distance < 1e-3, f.parameters.shape, f.distances.shape
/// (True, (50,), (50,))
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
    /// The noise estimated from the points, per coordinate (NaN when not a fit).
    #[pyo3(get)]
    noise: f64,
    /// What the distances do not show (crossings, excess turning, sparse pieces, a tolerance
    /// not met), one sentence each; empty when there is nothing to say.
    #[pyo3(get)]
    warnings: Vec<String>,
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

/// Fits measured points with a C^1 cubic Hermite spline on [0, 1] (Pavlov).
///
/// Minimizes the sum of squared foot-point distances, the sum of squared second-derivative
/// jumps at the knots bounded by ``eps``. Give ``knots`` or ``tolerance``.
///
/// Parameters
/// ----------
/// points : array_like
///     The measured points in their order along the curve, shape ``(n, d)``, ``d`` in {2, 3}.
/// knots : int or array_like, optional
///     An int: that many uniformly spaced knots (at least 2); an array: the knots, strictly
///     increasing from 0 to 1.
/// tolerance : float, optional
///     Instead of ``knots``: knots are added until every point is within this distance of
///     the curve (see ``tolerance_met`` of the result).
/// eps : float, optional
///     The bound on the sum of squared second-derivative jumps; None: no bound.
/// pin_ends : bool, optional
///     Make the curve pass through the first and last points.
/// free_ends : bool, optional
///     Leave the ends where the foot points put them (as ``karkas curve fit --free-ends``).
///     By default a first and last point that coincide (within 1e-6 of the points' size: a
///     closed profile, a sharp trailing edge) pin both ends at that point, in every mode, so
///     the curve closes there; on given knots each other end of a noisy fit is held on its
///     tangent line where the points towards it say it lies, and ends that the noise does not
///     tell apart (a closed trailing edge) at their common point.
/// corners : sequence of float, optional
///     Knots where the curve may turn a corner (no smoothness asked there).
/// fairness : float, optional
///     The weight rho of the bending energy that keeps the parameterization even (default
///     3e-11, as ``karkas curve fit --fairness``).
/// smoothing : float, optional
///     The share s of the noise in the bending weight, ``lambda = (fairness + s (sigma /
///     L)^2) n tau`` with sigma the noise estimated from the points (the result's ``noise``),
///     L the size of the points and tau a factor for curves that wind (as ``karkas curve
///     fit --smoothing``; 0 for none), its noise part falling off near the ends of the
///     curve. Default (None): 0.1 on given knots, 0.3 with ``tolerance``.
/// penalty : {"active", "paper"}, optional
///     How the penalty p is chosen when ``eps`` is given, as ``karkas curve fit --penalty``:
///     "active" (default) lowers p until the bound holds with equality (the constrained
///     optimum); "paper" is Pavlov's rule p = H(q*) / eps, times 10 until the bound holds.
/// closed : bool, optional
///     Fit a closed contour with one periodic spline, C^1 across the seam (as ``karkas curve
///     fit --closed``): the seam at the first point (t = 0), closed chord-length start,
///     ``knots`` those of one period (a corner at 0 makes the seam a corner), ``tolerance``
///     inserting knots in every piece, the seam's included; a last point repeating the first
///     is dropped. The result's value and derivative at 1 equal those at 0. Not with
///     ``pin_ends`` or ``free_ends``; with ``eps`` the penalty follows the paper's rule.
/// starts : int, optional
///     Solve Pavlov's system from this many starting parameterizations (1 to 8, default 1:
///     the paper's chord length; then cumulative chords to the powers 0.5, 0, 0.75, 0.25,
///     1.5, 0.875, 0.625) and keep the fit with the smallest sum of squared distances among
///     those that neither cross themselves nor turn beyond their points (as ``karkas curve
///     fit --starts``). Open fits on given knots only.
///
/// Returns
/// -------
/// HermiteSpline
///     The fitted curve, with ``max_distance``, ``rms_distance``, ``parameters``,
///     ``distances``, ``noise`` and ``warnings`` of the fit.
///
/// Raises
/// ------
/// PointsError
///     Too few points, a non-finite coordinate, or a wrong shape.
/// KnotsError
///     Knots not strictly increasing from 0 to 1, or fewer than 2.
/// OptionError
///     Both or neither of ``knots`` and ``tolerance``, an option out of range,
///     ``closed`` with ``pin_ends`` or ``free_ends``, or ``starts`` other than 1 without
///     given knots or with ``closed``.
///
/// Examples
/// --------
/// >>> s = np.linspace(0.0, 1.0, 50)
/// >>> f = karkas.fit_curve(np.column_stack([s, s * s]), knots=5)
/// >>> f.knots
/// array([0.  , 0.25, 0.5 , 0.75, 1.  ])
/// >>> bool(f.max_distance < 1e-3)
/// True
/// >>> g = karkas.fit_curve(np.column_stack([s, np.sin(6 * s)]), tolerance=1e-3)
/// >>> g.tolerance_met
/// True
///
/// A closed ellipse, periodic and C^1 across the seam:
///
/// >>> u = np.linspace(0.0, 2.0 * np.pi, 40, endpoint=False)
/// >>> e = karkas.fit_curve(np.column_stack([3 * np.cos(u), np.sin(u)]), knots=13, closed=True)
/// >>> bool(np.allclose(e(0.0), e(1.0))), bool(np.allclose(e(0.0, nu=1), e(1.0, nu=1)))
/// (True, True)
/// >>> bool(e.max_distance < 1e-3)
/// True
#[pyfunction]
#[pyo3(signature = (points, knots = None, tolerance = None, eps = None, pin_ends = false, corners = None, fairness = DEFAULT_FAIRNESS, smoothing = None, penalty = "active", free_ends = false, closed = false, starts = 1))]
#[pyo3(
    text_signature = "(points, knots=None, tolerance=None, eps=None, pin_ends=False, corners=None, fairness=3e-11, smoothing=None, penalty='active', free_ends=False, closed=False, starts=1)"
)]
#[allow(clippy::too_many_arguments)]
pub fn fit_curve(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    knots: Option<&Bound<'_, PyAny>>,
    tolerance: Option<f64>,
    eps: Option<f64>,
    pin_ends: bool,
    corners: Option<&Bound<'_, PyAny>>,
    fairness: f64,
    smoothing: Option<f64>,
    penalty: &str,
    free_ends: bool,
    closed: bool,
    starts: usize,
) -> PyResult<Py<PyHermiteSpline>> {
    let penalty = penalty_rule(penalty)?;
    let (pts, dim) = PointsArray::extract_checked(points, "points")?;
    let target = Target::parse(py, knots, tolerance, pts.len(), dim)?;
    if starts != 1 && (closed || !matches!(target, Target::Knots(_))) {
        return Err(OptionError::new_err(
            "starts: several starts apply to open fits on given knots (give knots=, not tolerance= or closed=True)",
        ));
    }
    let mut options = FitOptions {
        ends: fit_ends(pin_ends, free_ends, closed)?,
        corners: corners
            .map(|c| extract_vector(c, "corners"))
            .transpose()?
            .unwrap_or_default(),
        fairness,
        smoothing,
        penalty,
        starts,
        ..FitOptions::default()
    };
    if let Some(eps) = eps {
        options.eps = eps;
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
            .detach(|| target.fit(p, closed, &options))
            .map_err(library_error)?;
        let spline: HermiteSpline<D> = result.spline.clone();
        let sub = PyHermiteSpline::of_fit(&result, met);
        (Arc::new(Wrapped::<_, D>(spline)) as Arc<dyn CurveImpl>, sub)
    });
    Py::new(py, sub.with_base(inner, dim))
}

/// The penalty rule of `penalty=`.
fn penalty_rule(penalty: &str) -> PyResult<fit::PenaltyRule> {
    match penalty {
        "active" => Ok(fit::PenaltyRule::ActiveBound),
        "paper" => Ok(fit::PenaltyRule::SeedBound),
        other => Err(OptionError::new_err(format!(
            "penalty must be 'active' or 'paper', got '{other}'"
        ))),
    }
}

/// The end policy of `pin_ends=`, `free_ends=` and `closed=` (at most one of them).
fn fit_ends(pin_ends: bool, free_ends: bool, closed: bool) -> PyResult<FitEnds> {
    if pin_ends && free_ends {
        return Err(OptionError::new_err("give pin_ends or free_ends, not both"));
    }
    if closed && (pin_ends || free_ends) {
        return Err(OptionError::new_err(
            "closed: a closed fit has no ends to pin or free (give closed or pin_ends/free_ends)",
        ));
    }
    Ok(if pin_ends {
        FitEnds::Pinned
    } else if free_ends {
        FitEnds::Free
    } else {
        FitEnds::Auto
    })
}

impl Target {
    /// The target of `knots=` (a count, checked against the memory limit for `points`
    /// points in `dim` dimensions, or the knots) or `tolerance=`: exactly one of them.
    fn parse(
        py: Python<'_>,
        knots: Option<&Bound<'_, PyAny>>,
        tolerance: Option<f64>,
        points: usize,
        dim: usize,
    ) -> PyResult<Self> {
        let knots: Option<Vec<f64>> = match knots {
            None => None,
            Some(k) => match k.extract::<i64>() {
                Ok(n) => {
                    if n < 2 {
                        return Err(KnotsError::new_err(format!(
                            "knots must be at least 2 (got {n})"
                        )));
                    }
                    check_memory(
                        py,
                        &format!("fit_curve(knots={n})"),
                        fit_bytes(points, n as usize, dim),
                    )?;
                    Some(fit::knots_from_list(&[n as f64]).map_err(library_error)?)
                }
                Err(_) => Some(extract_vector(k, "knots")?),
            },
        };
        match (knots, tolerance) {
            (Some(_), Some(_)) => Err(OptionError::new_err("give knots or tolerance, not both")),
            (Some(knots), None) => Ok(Target::Knots(knots)),
            (None, Some(tolerance)) => Ok(Target::Tolerance(tolerance)),
            (None, None) => Err(OptionError::new_err("give the knots or a tolerance")),
        }
    }

    /// The fit of `p` (closed or open) to this target, and for a tolerance whether it was
    /// met.
    fn fit<const D: usize>(
        &self,
        p: &[karkas::Point<D>],
        closed: bool,
        options: &FitOptions,
    ) -> karkas::Result<(fit::CurveFit<D>, Option<bool>)> {
        match self {
            Target::Knots(knots) if closed => Ok((fit::fit_closed_curve(p, knots, options)?, None)),
            Target::Tolerance(tol) if closed => {
                let a = fit::fit_closed_curve_adaptive(p, *tol, options)?;
                Ok((a.fit, Some(a.tolerance_met)))
            }
            Target::Knots(knots) => Ok((fit::fit_curve(p, knots, options)?, None)),
            Target::Tolerance(tol) => {
                let a = fit::fit_curve_adaptive(p, *tol, options)?;
                Ok((a.fit, Some(a.tolerance_met)))
            }
        }
    }
}

impl PyHermiteSpline {
    /// The Python part of the fit `result` (`met`: whether its tolerance was met).
    fn of_fit<const D: usize>(result: &fit::CurveFit<D>, met: Option<bool>) -> Self {
        let spline = &result.spline;
        PyHermiteSpline {
            knots: Numbers(spline.knots().to_vec()),
            values: FlatPoints::of(spline.values()),
            derivatives: FlatPoints::of(spline.derivatives()),
            max_distance: result.max_distance(),
            rms_distance: result.rms_distance(),
            jump_sum: result.jump_sum,
            tolerance_met: met,
            parameters: Numbers(result.parameters.clone()),
            distances: Numbers(result.distances.clone()),
            noise: result.noise.sigma,
            warnings: result.warnings.iter().map(|w| w.message.clone()).collect(),
        }
    }
}

impl PyHermiteSpline {
    /// The object with its base part: the curve `inner` of dimension `dim`.
    fn with_base(self, inner: Arc<dyn CurveImpl>, dim: usize) -> PyClassInitializer<Self> {
        let description = if self.parameters.0.is_empty() {
            format!(
                "<karkas.HermiteSpline {} knots in {dim}-D",
                self.knots.0.len()
            )
        } else {
            format!(
                "<karkas.HermiteSpline fit of {} points in {dim}-D, {} knots, max_distance={:.3e}, rms_distance={:.3e}",
                self.parameters.0.len(),
                self.knots.0.len(),
                self.max_distance,
                self.rms_distance
            )
        };
        PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(self)
    }

    /// The spline of `knots` (N,), `values` and `derivatives` (N, d) with the statistics of
    /// the fit that gave it (`stats`: NaN, None and empty arrays for none).
    pub(crate) fn build(
        py: Python<'_>,
        knots: &Bound<'_, PyAny>,
        values: &Bound<'_, PyAny>,
        derivatives: &Bound<'_, PyAny>,
        stats: FitStats,
    ) -> PyResult<PyClassInitializer<Self>> {
        let knots = extract_vector(knots, "knots")?;
        let (vals, dim) = PointsArray::extract_checked(values, "values")?;
        let (ders, ddim) = PointsArray::extract_checked(derivatives, "derivatives")?;
        if ddim != dim {
            return Err(OptionError::new_err(format!(
                "values have {dim} coordinates per point, derivatives {ddim}"
            )));
        }
        let (vf, df) = (vals.flat(), ders.flat());
        let (inner, values, derivatives): (Arc<dyn CurveImpl>, FlatPoints, FlatPoints) = by_dim!(dim, D => {
            let spline = py
                .detach(|| {
                    HermiteSpline::<D>::new(
                        knots.clone(),
                        as_points::<D>(&vf).to_vec(),
                        as_points::<D>(&df).to_vec(),
                    )
                })
                .map_err(library_error)?;
            let (v, d) = (FlatPoints::of(spline.values()), FlatPoints::of(spline.derivatives()));
            (Arc::new(Wrapped::<_, D>(spline)) as Arc<dyn CurveImpl>, v, d)
        });
        let sub = PyHermiteSpline {
            knots: Numbers(knots),
            values,
            derivatives,
            max_distance: stats.max_distance,
            rms_distance: stats.rms_distance,
            jump_sum: stats.jump_sum,
            tolerance_met: stats.tolerance_met,
            parameters: Numbers(stats.parameters),
            distances: Numbers(stats.distances),
            noise: stats.noise,
            warnings: stats.warnings,
        };
        Ok(sub.with_base(inner, dim))
    }

    /// The statistics of the fit (for pickling).
    pub(crate) fn stats(&self) -> FitStats {
        FitStats {
            max_distance: self.max_distance,
            rms_distance: self.rms_distance,
            jump_sum: self.jump_sum,
            tolerance_met: self.tolerance_met,
            parameters: self.parameters.0.clone(),
            distances: self.distances.0.clone(),
            noise: self.noise,
            warnings: self.warnings.clone(),
        }
    }

    /// The knots, values and derivatives (for pickling).
    pub(crate) fn coefficients(&self) -> (&Numbers, &FlatPoints, &FlatPoints) {
        (&self.knots, &self.values, &self.derivatives)
    }
}

/// What a fit says about its spline besides the coefficients.
pub struct FitStats {
    /// The largest distance of a fitted point.
    pub max_distance: f64,
    /// The root-mean-square distance.
    pub rms_distance: f64,
    /// The weighted sum of squared second-derivative jumps.
    pub jump_sum: f64,
    /// For a fit by tolerance: whether it was met.
    pub tolerance_met: Option<bool>,
    /// The foot parameters of the fitted points.
    pub parameters: Vec<f64>,
    /// The distances of the fitted points.
    pub distances: Vec<f64>,
    /// The noise estimated from the points.
    pub noise: f64,
    /// The warnings of the fit.
    pub warnings: Vec<String>,
}

impl FitStats {
    /// No fit: NaN statistics, no points.
    fn none() -> Self {
        FitStats {
            max_distance: f64::NAN,
            rms_distance: f64::NAN,
            jump_sum: f64::NAN,
            tolerance_met: None,
            parameters: Vec::new(),
            distances: Vec::new(),
            noise: f64::NAN,
            warnings: Vec::new(),
        }
    }
}

#[pymethods]
impl PyHermiteSpline {
    /// The spline of knots, values and derivatives, without fit statistics.
    #[new]
    fn py_new(
        py: Python<'_>,
        knots: &Bound<'_, PyAny>,
        values: &Bound<'_, PyAny>,
        derivatives: &Bound<'_, PyAny>,
    ) -> PyResult<PyClassInitializer<Self>> {
        Self::build(py, knots, values, derivatives, FitStats::none())
    }
}
