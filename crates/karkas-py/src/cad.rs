//! `read_cad`: the geometry of a STEP or IGES file (karkas-io's CAD reader) as `NurbsCurve` and
//! `NurbsSurface` objects, in a `CadModel` of `CadFace`s and free curves.

use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

use karkas::shape::{Face, FaceDomain};
use karkas_io::cad::read::{read_cad as read_file, CadFormat, CadModel};
use pyo3::prelude::*;

use crate::errors::library_error;
use crate::nurbs::{PyNurbsCurve, PyNurbsSurface};
use crate::read::{file_path, read_error};

/// The geometry of a STEP or IGES file, as ``read_cad`` reads it.
///
/// ``faces`` are the faces of its shells and solids and its free surfaces (``CadFace``),
/// ``curves`` its free curves (wireframes, curve sets) as ``NurbsCurve`` objects; ``unit`` is
/// the length unit of the coordinates (kept as written); ``unread`` lists what was not read.
///
/// Examples
/// --------
/// >>> c = karkas.CubicSpline([[0, 0], [1, 2], [2, 1], [3, 3]])
/// >>> _ = karkas.export(c, "c.step")
/// >>> m = karkas.read_cad("c.step")
/// >>> type(m).__name__, len(m.curves), len(m.faces), m.unit
/// ('CadModel', 1, 0, ('millimetre', 0.001))
#[pyclass(module = "karkas", name = "CadModel", frozen)]
pub struct PyCadModel {
    faces: Vec<Py<PyCadFace>>,
    curves: Vec<Py<PyNurbsCurve>>,
    unit: (String, f64),
    unread: Vec<(String, usize, String)>,
    warning: Option<String>,
    format: &'static str,
    entities: usize,
}

#[pymethods]
impl PyCadModel {
    /// The faces, a list of ``CadFace``.
    #[getter]
    fn faces(&self, py: Python<'_>) -> Vec<Py<PyCadFace>> {
        self.faces.iter().map(|f| f.clone_ref(py)).collect()
    }

    /// The free curves (bounding no face), a list of ``NurbsCurve``.
    #[getter]
    fn curves(&self, py: Python<'_>) -> Vec<Py<PyNurbsCurve>> {
        self.curves.iter().map(|c| c.clone_ref(py)).collect()
    }

    /// The length unit of the coordinates: ``(name, metres)``, e.g. ``('millimetre', 0.001)``.
    #[getter]
    fn unit(&self) -> (String, f64) {
        self.unit.clone()
    }

    /// What was not read: a list of ``(what, count, reason)``.
    #[getter]
    fn unread(&self) -> Vec<(String, usize, String)> {
        self.unread.clone()
    }

    /// One line naming what was not read with counts and reasons, or None.
    #[getter]
    fn warning(&self) -> Option<String> {
        self.warning.clone()
    }

    /// ``'step'`` or ``'iges'``.
    #[getter]
    fn format(&self) -> &'static str {
        self.format
    }

    /// The number of entities in the file (STEP instances, IGES directory entries).
    #[getter]
    fn entities(&self) -> usize {
        self.entities
    }

    fn __repr__(&self) -> String {
        format!(
            "<karkas.CadModel {} file: {} faces, {} curves, unit {}>",
            self.format,
            self.faces.len(),
            self.curves.len(),
            self.unit.0
        )
    }
}

/// A face of a CAD file: the part of a ``NurbsSurface`` inside its loops of edges.
///
/// ``loops`` holds each bounding loop as a list of ``NurbsCurve`` objects, each running the
/// way the loop runs (the face lies to the loops' left seen from its normal); ``same_sense``
/// tells whether the face's normal is the surface's ``S_u x S_v``; ``bounds_solid`` whether
/// the face bounds a solid (its normal then points out of it). ``contains(u, v)`` tells
/// whether a point of the surface's parameters lies in the face.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 0.1 * i * j] for j in range(3)] for i in range(3)], float)
/// >>> _ = karkas.export(karkas.BicubicSurface(grid), "s.step")
/// >>> face = karkas.read_cad("s.step").faces[0]
/// >>> len(face.loops), len(face.loops[0]), face.contains(0.5, 0.5)
/// (1, 4, True)
#[pyclass(module = "karkas", name = "CadFace", frozen)]
pub struct PyCadFace {
    surface: Py<PyNurbsSurface>,
    loops: Vec<Vec<Py<PyNurbsCurve>>>,
    face: Arc<Face>,
    domain: OnceLock<karkas::Result<FaceDomain>>,
}

#[pymethods]
impl PyCadFace {
    /// The surface the face lies on, a ``NurbsSurface``.
    #[getter]
    fn surface(&self, py: Python<'_>) -> Py<PyNurbsSurface> {
        self.surface.clone_ref(py)
    }

    /// The bounding loops: lists of ``NurbsCurve``, each curve running along its loop.
    #[getter]
    fn loops(&self, py: Python<'_>) -> Vec<Vec<Py<PyNurbsCurve>>> {
        self.loops
            .iter()
            .map(|l| l.iter().map(|c| c.clone_ref(py)).collect())
            .collect()
    }

    /// True when the face's normal is the surface's ``S_u x S_v``.
    #[getter]
    fn same_sense(&self) -> bool {
        self.face.same_sense
    }

    /// True when the face bounds a solid (a closed shell).
    #[getter]
    fn bounds_solid(&self) -> bool {
        self.face.bounds_solid
    }

    /// Whether the point ``(u, v)`` of the surface's parameters lies in the face.
    ///
    /// The loops are found in the parameters once (each edge inverted onto the surface, to
    /// ``1e-7`` of the parameter rectangle), then a point is inside when a ray from it crosses
    /// them an odd number of times.
    ///
    /// Parameters
    /// ----------
    /// u, v : float
    ///     The parameters.
    ///
    /// Returns
    /// -------
    /// bool
    ///     True inside the face (its boundary to rounding), False outside.
    ///
    /// Raises
    /// ------
    /// KarkasError
    ///     The face's surface could not be sampled (not finite).
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, 0.0] for j in range(3)] for i in range(3)], float)
    /// >>> _ = karkas.export(karkas.BicubicSurface(grid, "uniform"), "p.step")
    /// >>> face = karkas.read_cad("p.step").faces[0]
    /// >>> face.contains(1.0, 1.0), face.contains(3.0, 1.0)
    /// (True, False)
    fn contains(&self, py: Python<'_>, u: f64, v: f64) -> PyResult<bool> {
        let face = &self.face;
        let domain = py.detach(|| self.domain.get_or_init(|| FaceDomain::of(face)));
        match domain {
            Ok(d) => Ok(d.contains(u, v)),
            Err(e) => Err(library_error(e.clone())),
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "<karkas.CadFace {} loops, same_sense={}, bounds_solid={}>",
            self.loops.len(),
            crate::convert::py_bool(self.face.same_sense),
            crate::convert::py_bool(self.face.bounds_solid)
        )
    }
}

/// Reads the geometry of a STEP or IGES file.
///
/// STEP (AP203, AP214, AP242): B-spline curves and surfaces (rational too), lines, circles,
/// ellipses, planes, cylinders, cones, spheres, tori, surfaces of revolution and of linear
/// extrusion (converted exactly to NURBS), the faces of shells and solids with their edges,
/// free curves and surfaces. IGES 5.3: entities 100, 102, 110, 124, 126, 128, 142 and 144.
/// The format is told by the content. What is not read is listed in ``unread`` (and
/// ``warning``), never dropped silently.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
///
/// Returns
/// -------
/// CadModel
///     Its faces, free curves, unit and what was not read.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened or read (``FileNotFoundError``, ...).
/// FileFormatError
///     The content is not STEP or IGES, or is malformed: truncated, a reference to an
///     instance the file does not define, a cycle of references, an entity with the wrong
///     parameters, binary data, more than the memory cap (``set_max_input_bytes``). The
///     message names the file, the line and the entity.
///
/// Examples
/// --------
/// >>> c = karkas.LLCurve([[0, 0], [1, 2], [2, 1], [3, 3], [4, 0]], order=2)
/// >>> _ = karkas.export(c, "ll.igs")
/// >>> m = karkas.read_cad("ll.igs")
/// >>> curve = m.curves[0]
/// >>> bool(np.allclose(curve(np.linspace(*c.domain, 9))[:, :2], c(np.linspace(*c.domain, 9)), atol=1e-12))
/// True
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_cad(py: Python<'_>, path: PathBuf) -> PyResult<PyCadModel> {
    let path = file_path(path)?;
    let model: CadModel = py.detach(|| read_file(&path)).map_err(read_error)?;
    let warning = model.warning();
    let curves = model
        .shape
        .curves
        .iter()
        .map(|c| Py::new(py, PyNurbsCurve::initializer(c.clone())))
        .collect::<PyResult<Vec<_>>>()?;
    let faces = model
        .shape
        .faces
        .into_iter()
        .map(|face| {
            let surface = Py::new(py, PyNurbsSurface::initializer(face.surface.clone()))?;
            let loops = face
                .loops
                .iter()
                .map(|l| {
                    l.edges
                        .iter()
                        .map(|e| {
                            let c = if e.forward {
                                e.curve.clone()
                            } else {
                                e.curve.reversed()
                            };
                            Py::new(py, PyNurbsCurve::initializer(c))
                        })
                        .collect::<PyResult<Vec<_>>>()
                })
                .collect::<PyResult<Vec<_>>>()?;
            Py::new(
                py,
                PyCadFace {
                    surface,
                    loops,
                    face: Arc::new(face),
                    domain: OnceLock::new(),
                },
            )
        })
        .collect::<PyResult<Vec<_>>>()?;
    Ok(PyCadModel {
        faces,
        curves,
        unit: (model.unit.name.clone(), model.unit.metres),
        unread: model
            .unread
            .iter()
            .map(|u| (u.what.clone(), u.count, u.reason.clone()))
            .collect(),
        warning,
        format: match model.format {
            CadFormat::Step => "step",
            CadFormat::Iges => "iges",
        },
        entities: model.entities,
    })
}
