//! NumPy arrays to karkas points and grids and back, and Python arguments to counts.
//!
//! Input arrays are read in place when they are C-contiguous float64 (anything else array-like
//! is converted once by NumPy, after [`real_array`] has refused complex, string, date and
//! non-numeric object data with `TypeError`; a copy of a strided or broadcast view is checked
//! against `karkas.max_memory` first). Output arrays are written in place: a flat `&mut [f64]` of a
//! C-contiguous `(..., d)` array is viewed as `&mut [Point<D>]` (`Point<D>` is
//! `#[repr(transparent)]` over `[f64; D]` and `Pod`), so evaluation stores straight into the
//! caller's memory.

use std::borrow::Cow;

use karkas::{Grid, Point, Point3};
use karkas_io::range::{check_coordinate_range, check_coordinate_slice};
use numpy::ndarray::{Dimension, Ix2, Ix3};
use numpy::{
    AllowTypeChange, PyArrayDescrMethods, PyArrayDyn, PyArrayLike, PyArrayLike1, PyArrayLikeDyn,
    PyArrayMethods, PyReadonlyArray, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::{PyBool, PyFloat, PyInt};

use crate::errors::{library_error, KarkasError, KnotsError, OptionError, PointsError};
use crate::limits::{bytes_of, check_memory, new_empty_array, shape_text, zeros};

/// Evaluations of at least this many points run with the GIL released (below it the release
/// costs more than it frees).
const DETACH_ABOVE: usize = 4096;

/// Runs `$body` with `$D` bound to the constant dimension `$d` (2 or 3; checked before).
macro_rules! by_dim {
    ($d:expr, $D:ident => $body:expr) => {
        match $d {
            2 => {
                const $D: usize = 2;
                $body
            }
            _ => {
                const $D: usize = 3;
                $body
            }
        }
    };
}
pub(crate) use by_dim;

/// A library object of either dimension kept by a Python object: `A` is its 2-D type, `B` its
/// 3-D type.
pub enum ByDim<A, B> {
    /// The 2-D object.
    D2(A),
    /// The 3-D object.
    D3(B),
}

impl<A: 'static, B: 'static> ByDim<A, B> {
    /// `value`, built for a constant dimension `D` (2 or 3), by its type.
    pub fn of<T: 'static>(value: T) -> Self {
        let any: Box<dyn std::any::Any> = Box::new(value);
        match any.downcast::<A>() {
            Ok(a) => ByDim::D2(*a),
            Err(any) => match any.downcast::<B>() {
                Ok(b) => ByDim::D3(*b),
                Err(_) => unreachable!("objects are built in 2-D or 3-D only"),
            },
        }
    }
}

/// Runs `$body` with `$x` bound to the object inside `$value`, a [`ByDim`].
macro_rules! each {
    ($value:expr, $x:ident => $body:expr) => {
        match $value {
            $crate::convert::ByDim::D2($x) => $body,
            $crate::convert::ByDim::D3($x) => $body,
        }
    };
}
pub(crate) use each;

/// Runs `f` with the GIL released when `work` is large.
pub fn maybe_detach<T: Send, F: FnOnce() -> T + Send>(py: Python<'_>, work: usize, f: F) -> T {
    if work >= DETACH_ABOVE {
        py.detach(f)
    } else {
        f()
    }
}

/// Coordinates in a float64 array whose last axis holds the `d` coordinates of a point:
/// points `(n, d)` ([`PointsArray`]) or a grid `(nu, nv, d)` ([`GridArray`]).
pub struct CoordArray<'py, Dm: Dimension> {
    array: PyArrayLike<'py, f64, Dm, AllowTypeChange>,
}

/// Points of a float64 array of shape `(n, d)`, borrowed when contiguous.
pub type PointsArray<'py> = CoordArray<'py, Ix2>;

/// A grid of points of shape `(nu, nv, d)`.
pub type GridArray<'py> = CoordArray<'py, Ix3>;

impl<'py, Dm: Dimension + 'py> CoordArray<'py, Dm> {
    /// Reads `obj` (anything `numpy.asarray` accepts) as a float64 array of this rank.
    pub fn extract(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<Self> {
        let shape = match Dm::NDIM {
            Some(2) => "a 2-D float array of shape (n, d)",
            _ => "a 3-D float array of shape (nu, nv, d)",
        };
        let real = real_array(obj, what)?;
        let array: PyArrayLike<'py, f64, Dm, AllowTypeChange> = real.extract().map_err(|_| {
            PointsError::new_err(format!(
                "{what} must be {shape} with d in {{2, 3}} (got shape {})",
                shape_of(&real)
            ))
        })?;
        check_copy(&array, what)?;
        let coordinates = array.as_array();
        let path = std::path::Path::new(what);
        match coordinates.as_slice_memory_order() {
            Some(flat) => check_coordinate_slice(flat, path),
            None => check_coordinate_range(coordinates.iter().copied(), path),
        }
        .map_err(|e| PointsError::new_err(e.to_string()))?;
        Ok(CoordArray { array })
    }

    /// Reads `obj` as [`Self::extract`] does, with its dimension checked by [`check_dim`].
    pub fn extract_checked(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<(Self, usize)> {
        let array = Self::extract(obj, what)?;
        let dim = check_dim(array.dim(), what)?;
        Ok((array, dim))
    }

    /// The dimension `d` (the length of the last axis).
    pub fn dim(&self) -> usize {
        self.array.shape().last().copied().unwrap_or(0)
    }

    /// The coordinates as a flat row-major slice (copied only when not contiguous).
    pub fn flat(&self) -> Cow<'_, [f64]> {
        flat_of(&self.array)
    }
}

impl PointsArray<'_> {
    /// The number of points.
    pub fn len(&self) -> usize {
        self.array.shape()[0]
    }
}

impl GridArray<'_> {
    /// The rows and columns `(nu, nv)`.
    pub fn rows_cols(&self) -> (usize, usize) {
        let shape = self.array.shape();
        (shape[0], shape[1])
    }

    /// The number of columns (the second axis).
    pub fn columns(&self) -> usize {
        self.array.shape()[1]
    }

    /// The grid (rows along `u`) as karkas points: one copy of the array, read in place when
    /// it is C-contiguous and in row-major order through its strides otherwise.
    pub fn grid<const D: usize>(&self) -> PyResult<Grid<Point<D>>> {
        let shape = self.array.shape();
        let view = self.array.as_array();
        let points: Vec<Point<D>> = match view.to_slice() {
            Some(flat) => as_points::<D>(flat).to_vec(),
            None => {
                let mut coords = view.iter().copied();
                (0..shape[0] * shape[1])
                    .map(|_| Point(std::array::from_fn(|_| coords.next().unwrap_or(f64::NAN))))
                    .collect()
            }
        };
        Grid::from_row_major(shape[0], shape[1], points).map_err(library_error)
    }
}

/// The contents of `array` as a flat row-major slice: borrowed when the array is C-contiguous,
/// otherwise (Fortran order, strided views) copied in row-major order. NumPy's `as_slice`
/// accepts a Fortran-ordered array too, whose memory is column-major: reading that as
/// row-major would silently permute the coordinates.
fn flat_of<'a, Dm: Dimension>(array: &'a PyReadonlyArray<'_, f64, Dm>) -> Cow<'a, [f64]> {
    let view = array.as_array();
    match view.to_slice() {
        Some(s) => Cow::Borrowed(s),
        None => Cow::Owned(view.iter().copied().collect()),
    }
}

/// `numpy.asarray`, looked up once.
static NUMPY_ASARRAY: PyOnceLock<Py<PyAny>> = PyOnceLock::new();

/// `obj` as a NumPy array of real numbers (`numpy.asarray(obj)`, any layout, not yet
/// float64): booleans, integers and floats of any width are taken (and converted to float64
/// by the caller); complex numbers raise `TypeError` rather than lose their imaginary part,
/// and so do strings, dates, and objects that are not numbers. An exception raised by the
/// object itself (its `__array__`, `__len__`, ...) propagates unchanged.
pub fn real_array<'py>(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<Bound<'py, PyAny>> {
    let py = obj.py();
    let asarray = NUMPY_ASARRAY.get_or_try_init(py, || -> PyResult<Py<PyAny>> {
        Ok(py.import("numpy")?.getattr("asarray")?.unbind())
    })?;
    let array = if obj.cast::<PyUntypedArray>().is_ok() {
        obj.clone()
    } else {
        asarray.bind(py).call1((obj,))?
    };
    let untyped = array.cast::<PyUntypedArray>()?;
    let dtype = untyped.dtype();
    let kind: u8 = dtype.kind();
    match kind {
        b'b' | b'i' | b'u' | b'f' => Ok(array),
        b'O' => {
            // Objects that are all numbers (e.g. a ragged-free list holding Decimal) convert;
            // anything else is a wrong type, not a wrong value.
            let converted = asarray.bind(py).call1((&array, "float64")).map_err(|_| {
                PyTypeError::new_err(format!(
                    "{what} must hold real numbers, not Python objects ({})",
                    type_name(obj)
                ))
            })?;
            Ok(converted)
        }
        b'c' => Err(PyTypeError::new_err(format!(
            "{what} must be real, not complex (dtype {dtype}); pass .real or abs() explicitly"
        ))),
        _ => Err(PyTypeError::new_err(format!(
            "{what} must hold real numbers (got dtype {dtype} from {})",
            type_name(obj)
        ))),
    }
}

/// Checks against `karkas.max_memory` the copy that reading a non-contiguous array (a strided
/// or broadcast view, whose logical size can be far above the memory it occupies) takes.
fn check_copy<Dm: Dimension>(array: &PyReadonlyArray<'_, f64, Dm>, what: &str) -> PyResult<()> {
    if array.is_c_contiguous() {
        return Ok(());
    }
    check_memory(
        array.py(),
        &format!("copying {what} of shape {}", shape_text(array.shape())),
        bytes_of(array.shape(), 8),
    )
}

/// The items of a sequence of arrays (e.g. a list of curves), refused with `TypeError` when
/// `obj` is a string or not a sequence, and checked against `karkas.max_memory` by its
/// length before a list of them is made.
pub fn object_list<'py>(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<Vec<Bound<'py, PyAny>>> {
    if obj.is_instance_of::<pyo3::types::PyString>() || obj.is_instance_of::<pyo3::types::PyBytes>()
    {
        return Err(PyTypeError::new_err(format!(
            "{what} must be a sequence of arrays, not {}",
            type_name(obj)
        )));
    }
    let n = obj.len().map_err(|_| {
        PyTypeError::new_err(format!(
            "{what} must be a sequence of arrays, not {}",
            type_name(obj)
        ))
    })?;
    check_memory(
        obj.py(),
        &format!("{what} of {n} items"),
        bytes_of(&[n], 64),
    )?;
    obj.try_iter()?.collect()
}

/// The type name of `obj`, for messages.
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map_or_else(|_| "?".to_string(), |n| n.to_string())
}

/// The shape of an array as Python prints it.
fn shape_of(array: &Bound<'_, PyAny>) -> String {
    array
        .cast::<PyUntypedArray>()
        .map_or_else(|_| "?".to_string(), |a| shape_text(a.shape()))
}

/// The dimension of `d` columns, or a `ValueError` naming `what`.
pub fn check_dim(d: usize, what: &str) -> PyResult<usize> {
    match d {
        2 | 3 => Ok(d),
        _ => Err(PointsError::new_err(format!(
            "{what} must have 2 or 3 coordinates per point (got {d})"
        ))),
    }
}

/// Checks that `what` has 3 coordinates per point (`d` of them).
pub fn check_dim3(d: usize, what: &str) -> PyResult<()> {
    if d == 3 {
        return Ok(());
    }
    Err(PointsError::new_err(format!(
        "{what} must have 3 coordinates per point (got {d})"
    )))
}

/// A flat slice of `D * n` numbers as `n` points.
pub fn as_points<const D: usize>(flat: &[f64]) -> &[Point<D>] {
    bytemuck::cast_slice(flat)
}

/// A flat mutable slice of `D * n` numbers as `n` points.
pub fn as_points_mut<const D: usize>(flat: &mut [f64]) -> &mut [Point<D>] {
    bytemuck::cast_slice_mut(flat)
}

/// Points as a flat slice of `D * n` numbers.
pub fn flatten<const D: usize>(points: &[Point<D>]) -> &[f64] {
    bytemuck::cast_slice(points)
}

/// `grid` closed with a crease (a `C^0` seam) in the directions `crease` (`crease_u`,
/// `crease_v`): its first row (column) appended after the last unless the last repeats it
/// ([`Grid::closed`]), to be interpolated as an open direction, as the command line's
/// `--crease-u/--crease-v`. A crease in a direction also asked `closed` (periodic) is an
/// `OptionError`; fewer than 3 distinct lines a `PointsError`.
pub fn creased<const D: usize>(
    grid: Grid<Point<D>>,
    crease: (bool, bool),
    closed: (bool, bool),
) -> PyResult<Grid<Point<D>>> {
    for (name, asked, periodic) in [("u", crease.0, closed.0), ("v", crease.1, closed.1)] {
        if asked && periodic {
            return Err(OptionError::new_err(format!(
                "crease_{name} and closed_{name} exclude each other: a crease closes the \
                 direction with a C^0 seam, closed_{name} with a smooth (periodic) one"
            )));
        }
    }
    if !(crease.0 || crease.1) {
        return Ok(grid);
    }
    grid.closed(crease.0, crease.1, "a creased direction (grid lines)")
        .map_err(library_error)
}

/// `n` uniformly spaced parameters over `(a, b)`, ends included.
pub fn uniform((a, b): (f64, f64), n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            if n == 1 {
                a
            } else {
                a + (b - a) * i as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// A 1-D float64 array of parameters (or knots); `KnotsError` when not 1-D.
pub fn extract_vector(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
    vector_of(obj, what, KnotsError::new_err)
}

/// A short 1-D float64 vector such as a plane's normal or a point; `OptionError` when not
/// 1-D.
pub fn small_vector(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<f64>> {
    vector_of(obj, what, OptionError::new_err)
}

/// A 1-D float64 array, `error` for one of another rank.
fn vector_of(obj: &Bound<'_, PyAny>, what: &str, error: fn(String) -> PyErr) -> PyResult<Vec<f64>> {
    let real = real_array(obj, what)?;
    let array: PyArrayLike1<'_, f64, AllowTypeChange> = real.extract().map_err(|_| {
        error(format!(
            "{what} must be a 1-D float array (got shape {})",
            shape_of(&real)
        ))
    })?;
    check_memory(
        obj.py(),
        &format!("reading {what} of shape {}", shape_text(array.shape())),
        bytes_of(array.shape(), 8),
    )?;
    Ok(flat_of(&array).into_owned())
}

/// Parameters given as a scalar or an array of any shape.
pub enum Params<'py> {
    /// One parameter: the result has shape `(d,)`.
    Scalar(f64),
    /// An array: the result has shape `params.shape + (d,)`.
    Array(PyArrayLikeDyn<'py, f64, AllowTypeChange>),
}

impl<'py> Params<'py> {
    /// Reads `obj` as a Python number or an array of numbers.
    pub fn extract(obj: &Bound<'py, PyAny>, what: &str) -> PyResult<Self> {
        if obj.is_exact_instance_of::<PyFloat>() || obj.is_exact_instance_of::<PyInt>() {
            if let Ok(t) = obj.extract::<f64>() {
                return Ok(Params::Scalar(t));
            }
        }
        let real = real_array(obj, what)?;
        let array: PyArrayLikeDyn<'py, f64, AllowTypeChange> = real.extract().map_err(|_| {
            KarkasError::new_err(format!("{what} must be a float or an array of floats"))
        })?;
        check_copy(&array, what)?;
        if array.ndim() == 0 {
            let t = array.as_array().iter().copied().next().unwrap_or(f64::NAN);
            return Ok(Params::Scalar(t));
        }
        Ok(Params::Array(array))
    }

    /// The shape of the parameters (empty for a scalar).
    pub fn shape(&self) -> Vec<usize> {
        match self {
            Params::Scalar(_) => Vec::new(),
            Params::Array(a) => a.shape().to_vec(),
        }
    }

    /// The parameters as a flat slice (copied only when not contiguous).
    pub fn flat(&self) -> Cow<'_, [f64]> {
        match self {
            Params::Scalar(t) => Cow::Owned(vec![*t]),
            Params::Array(a) => flat_of(a),
        }
    }
}

/// The output array of shape `shape`: `out` checked (a float64 `numpy.ndarray`, C-contiguous,
/// writeable, that shape) or a new one, checked against `karkas.max_memory` first. A new
/// array is not zeroed (`numpy.empty`): every caller writes every element, directly through
/// [`write_flat`], so the result is allocated once and written once.
///
/// A wrong type or dtype of `out` raises `TypeError`; a wrong shape, a Fortran-ordered or
/// strided `out` and a read-only one raise `KarkasError` (a `ValueError`).
pub fn output_array<'py>(
    py: Python<'py>,
    out: Option<Bound<'py, PyAny>>,
    shape: &[usize],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let Some(out) = out else {
        return new_empty_array(
            py,
            shape,
            &format!("a result of shape {}", shape_text(shape)),
        );
    };
    let untyped = out.cast::<PyUntypedArray>().map_err(|_| {
        PyTypeError::new_err(format!(
            "out must be a numpy.ndarray of float64, not {}",
            type_name(&out)
        ))
    })?;
    if !untyped.dtype().is_equiv_to(&numpy::dtype::<f64>(py)) {
        return Err(PyTypeError::new_err(format!(
            "out must have dtype float64, not {}",
            untyped.dtype()
        )));
    }
    if untyped.shape() != shape {
        return Err(KarkasError::new_err(format!(
            "out has shape {}, expected {}",
            shape_text(untyped.shape()),
            shape_text(shape)
        )));
    }
    if !untyped.is_c_contiguous() {
        return Err(KarkasError::new_err(
            "out must be C-contiguous (a Fortran-ordered or strided array would be filled \
             in the wrong order); use numpy.empty(shape) or numpy.ascontiguousarray",
        ));
    }
    let array = out
        .cast_into::<PyArrayDyn<f64>>()
        .map_err(|e| PyTypeError::new_err(format!("out must be a float64 numpy.ndarray ({e})")))?;
    if !array
        .getattr("flags")?
        .getattr("writeable")?
        .extract::<bool>()?
    {
        return Err(KarkasError::new_err("out is read-only"));
    }
    Ok(array)
}

/// Runs `write` on the flat contents of `array` (checked C-contiguous and writeable).
pub fn write_flat<R>(
    array: &Bound<'_, PyArrayDyn<f64>>,
    write: impl FnOnce(&mut [f64]) -> R,
) -> PyResult<R> {
    let mut rw = array.try_readwrite().map_err(|e| {
        KarkasError::new_err(format!(
            "out cannot be written ({e}): is it read-only or does it share memory with the input?"
        ))
    })?;
    if !rw.is_c_contiguous() {
        // A Fortran-ordered `out` is contiguous too, but column-major: refuse it rather than
        // fill it in the wrong order.
        return Err(KarkasError::new_err("out must be C-contiguous"));
    }
    let flat = rw
        .as_slice_mut()
        .map_err(|_| KarkasError::new_err("out must be C-contiguous"))?;
    Ok(write(flat))
}

/// A new `(n, d)` float64 array holding `points`.
pub fn points_to_array<'py, const D: usize>(
    py: Python<'py>,
    points: &[Point<D>],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = zeros(py, &[points.len(), D])?;
    write_flat(&array, |flat| flat.copy_from_slice(flatten(points)))?;
    Ok(array)
}

/// A new `(nu, nv, d)` float64 array holding `grid`.
pub fn grid_to_array<'py, const D: usize>(
    py: Python<'py>,
    grid: &Grid<Point<D>>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = zeros(py, &[grid.rows(), grid.cols(), D])?;
    write_flat(&array, |flat| {
        flat.copy_from_slice(flatten(grid.as_slice()))
    })?;
    Ok(array)
}

/// A new 1-D float64 array holding `values` (NumPy's `MemoryError` if it cannot be made).
pub fn vector_to_array<'py>(
    py: Python<'py>,
    values: &[f64],
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let array = zeros(py, &[values.len()])?;
    write_flat(&array, |flat| flat.copy_from_slice(values))?;
    Ok(array)
}

/// A non-negative Python integer as a count, or an `OptionError` naming it.
pub fn count(value: impl Into<i64>, name: &str) -> PyResult<usize> {
    let value: i64 = value.into();
    usize::try_from(value)
        .map_err(|_| OptionError::new_err(format!("{name} must be non-negative (got {value})")))
}

/// An integer argument: a Python `int` or anything with `__index__` (NumPy's integers).
/// `True`/`False` raise `TypeError` (a flag is not a number), as floats and strings do;
/// values beyond 64 bits raise `OverflowError`.
#[derive(Clone, Copy, Debug)]
pub struct Int(pub i64);

impl From<Int> for i64 {
    fn from(value: Int) -> i64 {
        value.0
    }
}

/// A count argument: an [`Int`] that must be non-negative (`OverflowError` otherwise, as
/// Python's own conversions to unsigned integers raise).
#[derive(Clone, Copy, Debug)]
pub struct Size(pub usize);

/// Refuses `bool` where an integer is expected.
fn refuse_bool(ob: &Borrowed<'_, '_, PyAny>) -> PyResult<()> {
    if ob.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(
            "expected an integer, got a bool (True and False are not counts)",
        ));
    }
    Ok(())
}

impl<'a, 'py> FromPyObject<'a, 'py> for Int {
    type Error = PyErr;

    fn extract(ob: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        refuse_bool(&ob)?;
        Ok(Int(ob.extract::<i64>()?))
    }
}

impl<'a, 'py> FromPyObject<'a, 'py> for Size {
    type Error = PyErr;

    fn extract(ob: Borrowed<'a, 'py, PyAny>) -> PyResult<Self> {
        refuse_bool(&ob)?;
        Ok(Size(ob.extract::<usize>()?))
    }
}

/// `True`/`False` as Python spells them.
pub fn py_bool(b: bool) -> &'static str {
    if b {
        "True"
    } else {
        "False"
    }
}

/// `"interpolating "` for the interpolating variant of a class, `""` otherwise (for `repr`).
pub fn variant(interpolating: bool) -> &'static str {
    if interpolating {
        "interpolating "
    } else {
        ""
    }
}

/// Flat coordinates and dimension kept for attributes such as `control_points`.
#[derive(Clone)]
pub struct FlatPoints {
    /// The coordinates, `dim` numbers a point.
    pub coords: Vec<f64>,
    /// The dimension `d`.
    pub dim: usize,
}

impl FlatPoints {
    /// The points of dimension `D`, flattened.
    pub fn of<const D: usize>(points: &[Point<D>]) -> Self {
        FlatPoints {
            coords: flatten(points).to_vec(),
            dim: D,
        }
    }

    /// A new `(n, d)` array.
    pub fn to_array<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        by_dim!(self.dim, D => points_to_array::<D>(py, as_points::<D>(&self.coords)))
    }
}

impl<'py> IntoPyObject<'py> for &FlatPoints {
    type Target = PyArrayDyn<f64>;
    type Output = Bound<'py, PyArrayDyn<f64>>;
    type Error = PyErr;

    /// A new `(n, d)` array, as [`FlatPoints::to_array`] gives.
    fn into_pyobject(self, py: Python<'py>) -> PyResult<Self::Output> {
        self.to_array(py)
    }
}

/// Numbers kept for an attribute such as `knots`, handed to Python as a new 1-D float64 array.
#[derive(Clone)]
pub struct Numbers(pub Vec<f64>);

impl<'py> IntoPyObject<'py> for &Numbers {
    type Target = PyArrayDyn<f64>;
    type Output = Bound<'py, PyArrayDyn<f64>>;
    type Error = PyErr;

    /// A new 1-D array, as [`vector_to_array`] gives.
    fn into_pyobject(self, py: Python<'py>) -> PyResult<Self::Output> {
        vector_to_array(py, &self.0)
    }
}

/// A 3-D point from a sequence of 3 numbers.
pub fn point3(p: &[f64], what: &str) -> PyResult<Point3> {
    match p {
        [x, y, z] => Ok(Point3::new([*x, *y, *z])),
        _ => Err(PointsError::new_err(format!(
            "{what} must have 3 coordinates"
        ))),
    }
}

/// (n, 3) points.
pub fn points3(obj: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<Point3>> {
    let pts = PointsArray::extract(obj, what)?;
    check_dim3(pts.dim(), what)?;
    Ok(as_points::<3>(&pts.flat()).to_vec())
}
