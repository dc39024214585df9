//! Generalized Coons surfaces (Chashnikov): the Python class `CoonsSurface`.

use std::sync::Arc;

use karkas::coons::{CoonsSurface, CurveFit, PointNetwork};
use karkas::Point;
use pyo3::prelude::*;

use crate::convert::{as_points, by_dim, check_dim, count, object_list, Int, PointsArray};
use crate::errors::{library_error, OptionError, PointsError};
use crate::limits::{bytes_of, check_memory};
use crate::surface::PySurface;
use crate::wrapper::{SurfaceImpl, WrappedSurface};

/// A list of point arrays (each (k, d)) as karkas point lists of dimension `D`.
///
/// The copies together are checked against `karkas.max_memory` before each is made (a list
/// of broadcast views can be small in memory and huge once copied).
fn point_lists<const D: usize>(
    lists: &[Bound<'_, PyAny>],
    what: &str,
) -> PyResult<Vec<Vec<Point<D>>>> {
    let mut total: u128 = 0;
    lists
        .iter()
        .enumerate()
        .map(|(i, obj)| {
            let pts = PointsArray::extract(obj, &format!("{what}[{i}]"))?;
            if pts.dim() != D {
                return Err(PointsError::new_err(format!(
                    "{what}[{i}] has {} coordinates per point, expected {D}",
                    pts.dim()
                )));
            }
            total = total.saturating_add(bytes_of(&[pts.len(), D], 8));
            check_memory(obj.py(), &format!("{what}[..{}]", i + 1), total)?;
            Ok(as_points::<D>(&pts.flat()).to_vec())
        })
        .collect()
}

/// The dimension of the first array of a list.
fn first_dim(lists: &[Bound<'_, PyAny>], what: &str) -> PyResult<usize> {
    let first = lists
        .first()
        .ok_or_else(|| PointsError::new_err(format!("{what} must not be empty")))?;
    check_dim(
        PointsArray::extract(first, &format!("{what}[0]"))?.dim(),
        what,
    )
}

/// Generalized Coons surfaces (Chashnikov) over a network of curves given by points.
///
/// CoonsSurface(v_curves, u_curves, kind="gordon-spline", u_derivs=None, v_derivs=None,
/// fit="spline", crossing_tolerance=1e-6, tolerance=1e-4): v_curves run along v (listed by
/// increasing u), u_curves along u (by increasing v); each a (k, d) array, interpolated by a
/// not-a-knot cubic spline (fit="spline") or an interpolating LL curve (fit=("ll", order)).
/// kind: 'bilinear' and 'bicubic' (two curves a family), 'gordon' (Lagrange blending),
/// 'gordon-spline' (cubic-spline blending), 'composite' (C^1 piecewise bicubic).
/// u_derivs / v_derivs: dS/dv along the u-curves and dS/du along the v-curves (one vector per
/// point) for 'bicubic' and 'composite'. A family whose curves repeat their first point at the
/// end is closed.
#[pyclass(extends = PySurface, module = "karkas", name = "CoonsSurface", frozen)]
pub struct PyCoonsSurface {
    /// The kind of surface.
    #[pyo3(get)]
    kind: String,
}

#[pymethods]
impl PyCoonsSurface {
    #[new]
    #[pyo3(signature = (v_curves, u_curves, kind = "gordon-spline", u_derivs = None, v_derivs = None, fit = None, crossing_tolerance = 1e-6, tolerance = 1e-4))]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        v_curves: &Bound<'_, PyAny>,
        u_curves: &Bound<'_, PyAny>,
        kind: &str,
        u_derivs: Option<&Bound<'_, PyAny>>,
        v_derivs: Option<&Bound<'_, PyAny>>,
        fit: Option<Bound<'_, PyAny>>,
        crossing_tolerance: f64,
        tolerance: f64,
    ) -> PyResult<PyClassInitializer<Self>> {
        let fit = match fit {
            None => CurveFit::CubicSpline,
            Some(f) => {
                if let Ok(name) = f.extract::<String>() {
                    match name.as_str() {
                        "spline" => CurveFit::CubicSpline,
                        _ => {
                            return Err(OptionError::new_err(format!(
                                "unknown fit {name:?} (expected 'spline' or ('ll', order))"
                            )))
                        }
                    }
                } else {
                    let (name, order): (String, Int) = f.extract().map_err(|_| {
                        OptionError::new_err("fit must be 'spline' or ('ll', order)")
                    })?;
                    if name != "ll" {
                        return Err(OptionError::new_err(
                            "fit must be 'spline' or ('ll', order)",
                        ));
                    }
                    CurveFit::Ll(count(order, "order")?)
                }
            }
        };
        let known = [
            "bilinear",
            "bicubic",
            "gordon",
            "gordon-spline",
            "composite",
        ];
        if !known.contains(&kind) {
            return Err(OptionError::new_err(format!(
                "unknown kind {kind:?} (expected one of {known:?})"
            )));
        }
        let v_curves = object_list(v_curves, "v_curves")?;
        let u_curves = object_list(u_curves, "u_curves")?;
        let u_derivs = u_derivs.map(|d| object_list(d, "u_derivs")).transpose()?;
        let v_derivs = v_derivs.map(|d| object_list(d, "v_derivs")).transpose()?;
        let dim = first_dim(&v_curves, "v_curves")?;
        let (inner, counts): (Arc<dyn SurfaceImpl>, (usize, usize)) = by_dim!(dim, D => {
            let v = point_lists::<D>(&v_curves, "v_curves")?;
            let u = point_lists::<D>(&u_curves, "u_curves")?;
            let derivs = match (&u_derivs, &v_derivs) {
                (Some(du), Some(dv)) => Some((point_lists::<D>(du, "u_derivs")?, point_lists::<D>(dv, "v_derivs")?)),
                (None, None) => None,
                _ => return Err(OptionError::new_err("give both u_derivs and v_derivs, or neither")),
            };
            let surface = py.detach(|| -> karkas::Result<CoonsSurface<D>> {
                let network = PointNetwork::new(&v, &u, fit, crossing_tolerance)?;
                let cross = match &derivs {
                    Some((du, dv)) => Some(network.cross_derivatives(dv, du)?),
                    None => None,
                };
                let net = network.network();
                match kind {
                    "bilinear" => CoonsSurface::bilinear(net, tolerance),
                    "bicubic" => CoonsSurface::bicubic(net, cross.as_ref(), tolerance),
                    "gordon" => CoonsSurface::gordon(net, tolerance),
                    "composite" => CoonsSurface::composite(net, cross.as_ref(), tolerance),
                    _ => CoonsSurface::gordon_spline(
                        net,
                        karkas::coons::SplineEnds::NotAKnot,
                        tolerance,
                    ),
                }
            })
            .map_err(library_error)?;
            (Arc::new(WrappedSurface::<_, D>(surface)) as Arc<dyn SurfaceImpl>, (v.len(), u.len()))
        });
        let description = format!(
            "<karkas.CoonsSurface kind='{kind}', {} v-curves x {} u-curves in {dim}-D",
            counts.0, counts.1
        );
        Ok(
            PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(
                PyCoonsSurface {
                    kind: kind.to_string(),
                },
            ),
        )
    }
}
