//! `karkas.loft` and `LoftSurface`: a wing lofted through airfoil sections placed as
//! aerosandbox places them, and `karkas.loft_windio`: the blade of a windIO turbine file (the
//! library's [`karkas::loft`], karkas-io's windIO reader).

use std::path::PathBuf;
use std::sync::Arc;

use karkas::loft::{Loft, LoftOptions, SpanRule, WingPlacement, DEFAULT_TOLERANCE};
use karkas::{Curve, Point2};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points, extract_vector, object_list, points3, points_to_array, Numbers, PointsArray,
};
use crate::erased::{SurfaceImpl, WrappedSurface};
use crate::errors::{library_error, library_error_saying, OptionError, PointsError};
use crate::read::{file_path, read_error};
use crate::surface::PySurface;

/// What a loft was built from (for pickling).
#[derive(Clone, Debug)]
pub(crate) struct LoftInput {
    pub source: LoftSource,
    pub options: LoftOptions,
}

/// The sections a loft was built from.
#[derive(Clone, Debug)]
pub(crate) enum LoftSource {
    /// Airfoil profiles and their placements (`karkas.loft`).
    Wing {
        profiles: Vec<Vec<Point2>>,
        placements: Vec<WingPlacement>,
    },
    /// The blade of a windIO turbine file (`karkas.loft_windio`).
    Windio { path: PathBuf },
}

/// A surface lofted through placed sections, as returned by :func:`karkas.loft`.
///
/// ``u`` runs along the span (``stations``: the distance from the first leading edge along the
/// leading edges projected onto the y-z plane), ``v`` along each section over ``[0, 1]``: the
/// upper trailing edge at 0, the leading edge at 0.5, the lower trailing edge at 1. The
/// surface at a station is that section's fitted curve, placed; ``to_bspline()`` returns the
/// surface itself (it is a B-spline). It evaluates, samples, cuts by planes and exports like
/// every other surface.
///
/// Examples
/// --------
/// >>> x = 0.5 * (1 + np.cos(np.linspace(0, 2 * np.pi, 61)))
/// >>> t = 0.6 * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
/// >>> foil = np.column_stack([x, np.where(np.arange(61) <= 30, t, -t)])
/// >>> wing = karkas.loft([foil, foil], [[0, 0, 0], [0.3, 4, 0.2]], [1.0, 0.5], [2.0, -1.0])
/// >>> wing.tolerance_met, wing.control_points[0]
/// (True, 4)
/// >>> bool(np.allclose(wing(wing.stations[1], 0.5), [0.3, 4, 0.2], atol=1e-12))
/// True
#[pyclass(extends = PySurface, module = "karkas", name = "LoftSurface", frozen)]
pub struct PyLoftSurface {
    /// The span stations of the sections (the surface's ``u`` at each).
    #[pyo3(get)]
    stations: Numbers,
    /// The largest distance of each section's points from the surface at its station, in
    /// model units.
    #[pyo3(get)]
    deviations: Numbers,
    /// True when every section's points lie within the tolerance (a share of its chord).
    #[pyo3(get)]
    tolerance_met: bool,
    /// The control points along the span and along the sections.
    #[pyo3(get)]
    control_points: (usize, usize),
    /// The spanwise rule: ``'linear'``, ``'monotone'`` or ``'spline'``.
    #[pyo3(get)]
    span: &'static str,
    /// The tolerance, as a share of each section's chord.
    #[pyo3(get)]
    tolerance: f64,
    /// The span stations of a windIO blade's airfoils (its other sections are at the
    /// positions of its distributions' grids); None for a wing.
    #[pyo3(get)]
    airfoil_stations: Option<Numbers>,
    pub(crate) input: LoftInput,
    loft: Arc<Loft>,
}

/// Lofts a wing through airfoil sections placed as aerosandbox's ``WingXSec`` places them.
///
/// Each profile (in unit chord, Selig's order or the other way round) is fitted to
/// ``tolerance`` of its chord by a cubic B-spline on one knot vector shared by all sections,
/// its leading edge (the point of smallest x) at ``v = 0.5`` and its ends at ``v = 0`` and 1.
/// Section ``k`` is placed at ``leading_edges[k] + chords[k] * (x X + y Y)``: ``X`` is the
/// ``x`` axis and ``Y`` the ``z`` axis of the section's frame, both turned by ``twists[k]``
/// degrees (nose up) about its span direction, which is the leading edges' direction projected
/// onto the y-z plane (the mean of the two at an inner section, with ``Y`` stretched to keep
/// the thickness across the kink), or ``(0, cos d, sin d)`` for a given ``dihedrals[k] = d``.
///
/// Parameters
/// ----------
/// profiles : sequence of array_like
///     One ``(n_k, 2)`` array per section, in span order (at least two).
/// leading_edges : array_like
///     ``(s, 3)``: the sections' leading edges.
/// chords, twists : array_like
///     ``(s,)``: chords, and twists in degrees.
/// dihedrals : array_like, optional
///     ``(s,)``: each section's dihedral in degrees, NaN (or None for all) for aerosandbox's
///     direction from the neighbouring leading edges.
/// span : {'monotone', 'linear', 'spline'}, optional
///     How the surface runs between sections: shape-preserving cubic Hermite (``C^1``, no
///     overshoot), ruled (``C^0`` at the sections) or not-a-knot cubic (``C^2``).
/// tolerance : float, optional
///     The largest distance of a section's points from the surface, as a share of its chord.
///
/// Returns
/// -------
/// LoftSurface
///
/// Raises
/// ------
/// PointsError
///     A section with too few points, not in unit chord, without a leading edge between its
///     ends, at the span station of another or out of order (the message names the section).
/// OptionError
///     An unknown ``span``, a tolerance that is not positive, arrays of the wrong lengths.
///
/// Examples
/// --------
/// >>> x = 0.5 * (1 + np.cos(np.linspace(0, 2 * np.pi, 41)))
/// >>> foil = np.column_stack([x, 0.05 * np.sin(np.linspace(0, 2 * np.pi, 41))])
/// >>> S = karkas.loft([foil, foil, foil], [[0, 0, 0], [0.1, 1, 0], [0.2, 2, 0.1]],
/// ...                 [1.0, 0.8, 0.6], [0.0, 0.0, 0.0], span="linear")
/// >>> S.span, len(S.stations)
/// ('linear', 3)
#[pyfunction]
#[pyo3(signature = (profiles, leading_edges, chords, twists, dihedrals = None, span = "monotone", tolerance = DEFAULT_TOLERANCE))]
#[pyo3(
    text_signature = "(profiles, leading_edges, chords, twists, dihedrals=None, span='monotone', tolerance=1e-05)"
)]
#[allow(clippy::too_many_arguments)]
pub fn loft(
    py: Python<'_>,
    profiles: &Bound<'_, PyAny>,
    leading_edges: &Bound<'_, PyAny>,
    chords: &Bound<'_, PyAny>,
    twists: &Bound<'_, PyAny>,
    dihedrals: Option<&Bound<'_, PyAny>>,
    span: &str,
    tolerance: f64,
) -> PyResult<Py<PyLoftSurface>> {
    let rule: SpanRule = span.parse().map_err(library_error)?;
    let mut foils = Vec::new();
    for (k, item) in object_list(profiles, "profiles")?.iter().enumerate() {
        let what = format!("profiles[{k}]");
        let pts = PointsArray::extract(item, &what)?;
        if pts.dim() != 2 {
            return Err(PointsError::new_err(format!(
                "{what} must have 2 columns (x, y in unit chord), got {}",
                pts.dim()
            )));
        }
        foils.push(as_points::<2>(&pts.flat()).to_vec());
    }
    let les = points3(leading_edges, "leading_edges")?;
    let chords = extract_vector(chords, "chords")?;
    let twists = extract_vector(twists, "twists")?;
    let dihedrals = match dihedrals {
        Some(d) if !d.is_none() => Some(extract_vector(d, "dihedrals")?),
        _ => None,
    };
    let s = foils.len();
    for (name, n) in [
        ("leading_edges", les.len()),
        ("chords", chords.len()),
        ("twists", twists.len()),
    ]
    .into_iter()
    .chain(dihedrals.as_ref().map(|d| ("dihedrals", d.len())))
    {
        if n != s {
            return Err(OptionError::new_err(format!(
                "{name} must have one entry per profile ({s}), got {n}"
            )));
        }
    }
    let placements: Vec<WingPlacement> = (0..s)
        .map(|k| WingPlacement {
            leading_edge: les[k],
            chord: chords[k],
            twist: twists[k],
            dihedral: dihedrals.as_ref().map(|d| d[k]).filter(|d| !d.is_nan()),
        })
        .collect();
    let options = LoftOptions { rule, tolerance };
    let loft = py
        .detach(|| Loft::wing(&foils, &placements, &options))
        .map_err(library_error)?;
    let input = LoftInput {
        source: LoftSource::Wing {
            profiles: foils,
            placements,
        },
        options,
    };
    Py::new(py, PyLoftSurface::build(loft, input, None))
}

/// Lofts the blade of a windIO turbine file, as ``karkas loft --windio`` does.
///
/// The file's ``components.blade`` (windIO 2: ``reference_axis`` and ``outer_shape``) and its
/// ``airfoils`` are read; each airfoil listed in ``outer_shape.airfoils`` is placed at its
/// ``spanwise_position`` along the reference axis with the chord, twist and section offsets
/// the distributions give there (PCHIP in their grids), its plane normal to the axis, as
/// windIO places it. Between two airfoils the surface also passes through a section at every
/// grid position of the distributions, placed the same way, whose profile blends the two
/// airfoils' fitted sections linearly. Stations are the positions times the reference axis's
/// length; ``v`` runs as in :func:`karkas.loft` (leading edge at 0.5).
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The windIO turbine file (YAML).
/// span : {'monotone', 'linear', 'spline'}, optional
///     How the surface runs between sections, as in :func:`karkas.loft`.
/// tolerance : float, optional
///     The largest distance of a section's points from the surface, as a share of its chord.
///
/// Returns
/// -------
/// LoftSurface
///     ``airfoil_stations`` holds the stations of the file's airfoils.
///
/// Raises
/// ------
/// FileFormatError
///     YAML that does not parse (with its line), a windIO 1 blade, a missing field, a
///     distribution whose arrays differ in length or whose grid does not increase, an airfoil
///     placed that the file does not define (the message names the file).
/// PointsError
///     Two airfoils at one position, positions out of order or outside [0, 1], an airfoil
///     with too few points or no leading edge between its ends (the message names the file,
///     the airfoil and its position).
/// OptionError
///     An unknown ``span`` or a tolerance that is not positive.
/// OSError
///     A file that cannot be opened (``FileNotFoundError``, ...).
///
/// Examples
/// --------
/// A blade 20 long with two airfoils (windIO files give them with many more points):
///
/// >>> import os, tempfile
/// >>> beta = np.linspace(0, 2 * np.pi, 41)
/// >>> x = 0.5 * (1 + np.cos(beta))
/// >>> def foil(t):
/// ...     y = 5 * t * (0.2969 * np.sqrt(x) - 0.126 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1036 * x**4)
/// ...     return f"{{x: {x.tolist()}, y: {np.where(beta <= np.pi, y, -y).tolist()}}}"
/// >>> text = f'''windIO_version: '2.0'
/// ... components:
/// ...   blade:
/// ...     reference_axis:
/// ...       x: {{grid: [0.0, 1.0], values: [0.0, 0.0]}}
/// ...       y: {{grid: [0.0, 1.0], values: [0.0, 0.0]}}
/// ...       z: {{grid: [0.0, 1.0], values: [0.0, 20.0]}}
/// ...     outer_shape:
/// ...       chord: {{grid: [0.0, 1.0], values: [2.0, 0.8]}}
/// ...       twist: {{grid: [0.0, 1.0], values: [10.0, 0.0]}}
/// ...       section_offset_y: {{grid: [0.0, 1.0], values: [0.5, 0.2]}}
/// ...       airfoils:
/// ...         - {{name: root, spanwise_position: 0.0}}
/// ...         - {{name: tip, spanwise_position: 1.0}}
/// ... airfoils:
/// ...   - {{name: root, coordinates: {foil(0.24)}}}
/// ...   - {{name: tip, coordinates: {foil(0.12)}}}
/// ... '''
/// >>> with tempfile.TemporaryDirectory() as d:
/// ...     path = os.path.join(d, "blade.yaml")
/// ...     with open(path, "w") as f:
/// ...         _ = f.write(text)
/// ...     blade = karkas.loft_windio(path)
/// >>> blade.tolerance_met, blade.airfoil_stations.tolist()
/// (True, [0.0, 20.0])
///
/// The root's leading edge is 0.5 upstream of the axis, turned 10 degrees into the wind (-x):
///
/// >>> le = blade(0.0, 0.5)
/// >>> bool(np.allclose(le, [-0.5 * np.sin(np.radians(10)), -0.5 * np.cos(np.radians(10)), 0], atol=1e-9))
/// True
#[pyfunction]
#[pyo3(signature = (path, span = "monotone", tolerance = DEFAULT_TOLERANCE))]
#[pyo3(text_signature = "(path, span='monotone', tolerance=1e-05)")]
pub fn loft_windio(
    py: Python<'_>,
    path: PathBuf,
    span: &str,
    tolerance: f64,
) -> PyResult<Py<PyLoftSurface>> {
    let rule: SpanRule = span.parse().map_err(library_error)?;
    let options = LoftOptions { rule, tolerance };
    let path = file_path(path)?;
    let (loft, airfoils) = py.detach(|| windio_loft(&path, &options))?;
    let input = LoftInput {
        source: LoftSource::Windio { path },
        options,
    };
    Py::new(py, PyLoftSurface::build(loft, input, Some(airfoils)))
}

/// The loft of the windIO blade at `path` and its airfoils' stations.
fn windio_loft(path: &std::path::Path, options: &LoftOptions) -> PyResult<(Loft, Vec<f64>)> {
    let blade = karkas_io::windio::read_windio_blade(path).map_err(read_error)?;
    let profiles: Vec<Vec<Point2>> = blade.sections.iter().map(|s| s.profile.clone()).collect();
    let positions: Vec<f64> = blade.sections.iter().map(|s| s.position).collect();
    let loft = Loft::blade(&profiles, &positions, &blade.shape, options).map_err(|e| {
        let name = karkas_io::input::display_name(path);
        let message = match &e {
            karkas::Error::LoftSection { section, reason } if *section < blade.sections.len() => {
                let s = &blade.sections[*section];
                format!(
                    "{}: airfoil {} ('{}' at spanwise_position {}): {reason}",
                    name.display(),
                    section + 1,
                    s.airfoil,
                    s.position
                )
            }
            other => format!("{}: {other}", name.display()),
        };
        library_error_saying(&e, message)
    })?;
    let length = blade.shape.axis_length();
    Ok((loft, positions.iter().map(|s| s * length).collect()))
}

impl PyLoftSurface {
    fn build(
        loft: Loft,
        input: LoftInput,
        airfoil_stations: Option<Vec<f64>>,
    ) -> PyClassInitializer<Self> {
        let loft = Arc::new(loft);
        let description = format!(
            "<karkas.LoftSurface span='{}', {} sections, {}x{} control points",
            input.options.rule.name(),
            loft.stations().len(),
            loft.control_counts().0,
            loft.control_counts().1
        );
        let sub = PyLoftSurface {
            stations: Numbers(loft.stations().to_vec()),
            deviations: Numbers(loft.deviations().to_vec()),
            tolerance_met: loft.tolerance_met(),
            control_points: loft.control_counts(),
            span: input.options.rule.name(),
            tolerance: input.options.tolerance,
            airfoil_stations: airfoil_stations.map(Numbers),
            input,
            loft: Arc::clone(&loft),
        };
        let inner: Arc<dyn SurfaceImpl> = Arc::new(WrappedSurface::<_, 3>(SharedLoft(loft)));
        PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(sub)
    }
}

#[pymethods]
impl PyLoftSurface {
    /// The surface's section at span station ``station`` (clamped to the span), as ``n``
    /// points uniform in ``v`` from the upper trailing edge over the leading edge to the lower
    /// one.
    ///
    /// Parameters
    /// ----------
    /// station : float
    ///     The span station.
    /// n : int, optional
    ///     How many points.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(n, 3)``.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     ``n`` outside 2..=1000000, or a station that is not finite.
    ///
    /// Examples
    /// --------
    /// >>> x = 0.5 * (1 + np.cos(np.linspace(0, 2 * np.pi, 41)))
    /// >>> foil = np.column_stack([x, 0.05 * np.sin(np.linspace(0, 2 * np.pi, 41))])
    /// >>> S = karkas.loft([foil, foil], [[0, 0, 0], [0, 2, 0]], [1.0, 1.0], [0.0, 0.0])
    /// >>> S.section_at(1.0, 5).shape
    /// (5, 3)
    #[pyo3(signature = (station, n = 200))]
    fn section_at<'py>(
        &self,
        py: Python<'py>,
        station: f64,
        n: usize,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        if !(2..=1_000_000).contains(&n) {
            return Err(OptionError::new_err(format!(
                "n must be in 2..=1000000, got {n}"
            )));
        }
        if !station.is_finite() {
            return Err(OptionError::new_err("station must be a finite number"));
        }
        let curve = self.loft.section_at(station);
        let pts: Vec<_> = (0..n)
            .map(|j| curve.eval(j as f64 / (n - 1) as f64))
            .collect();
        points_to_array(py, &pts)
    }
}

/// The loft shared between the Python object and its surface interface.
struct SharedLoft(Arc<Loft>);

impl karkas::Surface<3> for SharedLoft {
    fn domain_u(&self) -> karkas::Interval {
        self.0.domain_u()
    }
    fn domain_v(&self) -> karkas::Interval {
        self.0.domain_v()
    }
    fn is_closed_u(&self) -> bool {
        false
    }
    fn is_closed_v(&self) -> bool {
        false
    }
    fn eval(&self, u: f64, v: f64) -> karkas::Point3 {
        self.0.eval(u, v)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> karkas::Point3 {
        self.0.deriv(u, v, ku, kv)
    }
}

impl karkas::bspline::ToBSplineSurface<3> for SharedLoft {
    fn to_bspline(&self) -> karkas::Result<karkas::bspline::BSplineSurface<3>> {
        self.0.to_bspline()
    }
}
