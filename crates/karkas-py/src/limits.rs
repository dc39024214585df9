//! The memory cap of the Python module, `karkas.max_memory`, and the one checked way to make
//! an output array.
//!
//! Every entry point that allocates in proportion to a size the caller gives (a sample count,
//! a step `n`, a knot count, a grid of parameters, a section's cells) estimates the bytes it
//! will need before allocating anything and raises `MemoryError` naming the request, the
//! estimate and the cap when the estimate exceeds `karkas.max_memory`. The cap is a plain
//! module attribute, read again at every check (`karkas.max_memory = 2**30` takes effect at
//! once; `None` removes the cap). Requests of at most `CHECK_ABOVE` (2^20) bytes are never checked,
//! so that evaluating one point costs no attribute lookup.
//!
//! The default is the command line's: `KARKAS_MAX_MEMORY` when set when the module is
//! imported (a size such as `512M` or `2G`), else [`DEFAULT_MAX_MEMORY`], 2 GiB, the default
//! of `--max-memory`.
//!
//! Arrays are made by NumPy called through Python (`numpy.empty` for results written in full,
//! [`new_empty_array`]; `numpy.zeros`, [`zeros`]): a failed allocation is NumPy's own
//! `MemoryError`, never a null pointer inside the extension.

use karkas_io::picture::budget::{human_bytes, parse_size};
use numpy::PyArrayDyn;
use pyo3::exceptions::{PyMemoryError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::sync::PyOnceLock;
use pyo3::types::PyTuple;

/// The default cap, as the command line's `--max-memory`: 2 GiB.
pub const DEFAULT_MAX_MEMORY: u64 = karkas_io::input::DEFAULT_MAX_INPUT_BYTES;

/// Requests of at most this many bytes (1 MiB) are not checked against the cap.
const CHECK_ABOVE: u128 = 1 << 20;

/// The name of the module attribute holding the cap.
const ATTRIBUTE: &str = "max_memory";

/// The cap the module starts with: `KARKAS_MAX_MEMORY` if set, else [`DEFAULT_MAX_MEMORY`].
pub fn initial_max_memory() -> PyResult<u64> {
    match std::env::var("KARKAS_MAX_MEMORY") {
        Ok(text) => {
            parse_size(&text).map_err(|e| PyValueError::new_err(format!("KARKAS_MAX_MEMORY: {e}")))
        }
        Err(_) => Ok(DEFAULT_MAX_MEMORY),
    }
}

/// The product of `factors` times `bytes_each`, saturating (a product past `u128` is as
/// impossible as `u128::MAX` bytes).
pub fn bytes_of(factors: &[usize], bytes_each: u128) -> u128 {
    factors
        .iter()
        .fold(bytes_each, |acc, &f| acc.saturating_mul(f as u128))
}

/// The cap in force, `None` when `karkas.max_memory` is `None`.
///
/// It is read from the module the caller imported as `karkas` (the package that re-exports
/// this extension when installed as one, else the extension itself); the default when neither
/// has the attribute (it was deleted).
pub(crate) fn current_cap(py: Python<'_>) -> PyResult<Option<u128>> {
    let Some(value) = py.import("karkas")?.getattr_opt(ATTRIBUTE)? else {
        return Ok(Some(u128::from(initial_max_memory()?)));
    };
    if value.is_none() {
        return Ok(None);
    }
    let bad = || {
        PyTypeError::new_err(format!(
            "karkas.max_memory must be a positive int (bytes) or None, not {}",
            value.repr().map_or_else(|_| "?".into(), |r| r.to_string())
        ))
    };
    if value.is_instance_of::<pyo3::types::PyBool>() {
        return Err(bad());
    }
    let cap: i128 = value.extract().map_err(|_| bad())?;
    if cap <= 0 {
        return Err(PyValueError::new_err(format!(
            "karkas.max_memory must be positive (got {cap})"
        )));
    }
    Ok(Some(cap as u128))
}

/// Fails with `MemoryError` when `request` (e.g. "Curve.sample(1000000000000)") would need
/// `bytes`, more than `karkas.max_memory`.
pub fn check_memory(py: Python<'_>, request: &str, bytes: u128) -> PyResult<()> {
    if bytes <= CHECK_ABOVE {
        return Ok(());
    }
    let Some(cap) = current_cap(py)? else {
        return Ok(());
    };
    if bytes > cap {
        return Err(PyMemoryError::new_err(format!(
            "{request} would need {} ({bytes} bytes) of memory, above karkas.max_memory = {} \
             ({cap} bytes); raise karkas.max_memory or ask for less",
            human_bytes(bytes),
            human_bytes(cap)
        )));
    }
    Ok(())
}

/// `numpy.zeros`, looked up once.
static NUMPY_ZEROS: PyOnceLock<Py<PyAny>> = PyOnceLock::new();

/// `numpy.empty`, looked up once.
static NUMPY_EMPTY: PyOnceLock<Py<PyAny>> = PyOnceLock::new();

/// A new float64 array of `shape` whose contents are not set (`numpy.empty`), checked against
/// the cap first (as `request`): for results the caller overwrites entirely, so that no
/// zeroing pass precedes the writes (`numpy.zeros` of an array from the heap, rather than
/// from fresh pages, clears it first).
pub fn new_empty_array<'py>(
    py: Python<'py>,
    shape: &[usize],
    request: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    check_memory(py, request, bytes_of(shape, 8))?;
    let empty = NUMPY_EMPTY.get_or_try_init(py, || -> PyResult<Py<PyAny>> {
        Ok(py.import("numpy")?.getattr("empty")?.unbind())
    })?;
    let array = empty.bind(py).call1((PyTuple::new(py, shape)?,))?;
    Ok(array.cast_into::<PyArrayDyn<f64>>()?)
}

/// A new zeroed float64 array of `shape` (no cap check: for sizes already checked or held).
pub fn zeros<'py>(py: Python<'py>, shape: &[usize]) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let zeros = NUMPY_ZEROS.get_or_try_init(py, || -> PyResult<Py<PyAny>> {
        Ok(py.import("numpy")?.getattr("zeros")?.unbind())
    })?;
    let shape = PyTuple::new(py, shape)?;
    let array = zeros.bind(py).call1((shape,))?;
    Ok(array.cast_into::<PyArrayDyn<f64>>()?)
}

/// A shape as Python prints it: `(3, 4)`, `(5,)`.
pub fn shape_text(shape: &[usize]) -> String {
    match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(|n| n.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}
