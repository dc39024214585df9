//! The Python exceptions of karkas and the mapping of library errors onto them.
//!
//! Every error karkas raises for bad input or a failed method is a `karkas.KarkasError`, a
//! subclass of `ValueError` (so `except ValueError` keeps working), or one of its typed
//! subclasses, one per kind of mistake a caller would handle:
//!
//! ```text
//! ValueError
//! └── KarkasError                 anything else (the fallback)
//!     ├── PointsError             points, grids or skeleton curves that cannot be used
//!     ├── KnotsError              knots or parameters not finite and increasing
//!     ├── OptionError             an order, step, option or name outside what is allowed
//!     ├── IncompatibleDataError   input parts that contradict each other
//!     ├── ConvergenceError        a numerical method that could not finish
//!     ├── ExpressionError         an implicit-surface expression that does not parse
//!     └── FileFormatError         a file whose content the readers cannot read
//! ```
//!
//! File errors of the readers and exports are not karkas errors: they are `OSError` (its
//! subclass for the operating system's error kind, e.g. `FileNotFoundError`), as Python's own
//! `open` raises, so that `except ValueError` never swallows a full disk or a missing file.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

pyo3::create_exception!(
    karkas,
    KarkasError,
    PyValueError,
    "An error of karkas: bad input, or a method that could not finish.\n\
     \n\
     A subclass of ValueError. The message is the library's and names the\n\
     offending input. The subclasses PointsError, KnotsError, OptionError,\n\
     IncompatibleDataError, ConvergenceError, ExpressionError and\n\
     FileFormatError say which kind of mistake it is; other errors are\n\
     KarkasError itself. A file that cannot be opened, read or written is\n\
     OSError, not KarkasError."
);
pyo3::create_exception!(
    karkas,
    PointsError,
    KarkasError,
    "Points that cannot be used.\n\
     \n\
     Too few points, grid points or skeleton curves, a non-finite coordinate,\n\
     coinciding neighbours, or an array of the wrong shape or dimension."
);
pyo3::create_exception!(
    karkas,
    KnotsError,
    KarkasError,
    "Knots that cannot be used.\n\
     \n\
     Knots (parameters) that are not finite and strictly increasing, too close\n\
     together, outside their range, or too few."
);
pyo3::create_exception!(
    karkas,
    OptionError,
    KarkasError,
    "An option outside what is allowed.\n\
     \n\
     An order, step, tolerance or other option outside its range, an unknown\n\
     name (end condition, parameterization, kind, ...), or options that exclude\n\
     each other."
);
pyo3::create_exception!(
    karkas,
    IncompatibleDataError,
    KarkasError,
    "Input parts that contradict each other.\n\
     \n\
     Curves of a network or of a tube skeleton that do not meet where they must,\n\
     or prescribed row and column sums that cannot all hold."
);
pyo3::create_exception!(
    karkas,
    ConvergenceError,
    KarkasError,
    "A numerical method that could not finish.\n\
     \n\
     A singular linear system, a projection or a continuation that did not\n\
     converge, or a singular point of an implicit surface."
);
pyo3::create_exception!(
    karkas,
    ExpressionError,
    KarkasError,
    "An implicit-surface expression that does not parse.\n\
     \n\
     The message gives the character position of the problem."
);

pyo3::create_exception!(
    karkas,
    NoBSplineFormError,
    KarkasError,
    "An object with no exact B-spline form.\n\
     \n\
     Raised by to_bspline for a surface that is not a piecewise polynomial of its\n\
     parameters (e.g. a Coons surface over data that are not), and by an evaluation\n\
     of such a surface outside its domain with extrapolate=None or True (the end\n\
     pieces cannot be continued; extrapolate=False gives NaN there)."
);

pyo3::create_exception!(
    karkas,
    FileFormatError,
    KarkasError,
    "A file whose content cannot be read.\n\
     \n\
     Raised by the readers (read_curve, read_airfoil, read_grid, read_network,\n\
     read_mesh) with the command line's message, which names the file and the\n\
     line or grid cell: a malformed number, a missing column or cell, binary\n\
     data, a line longer than 1 MiB, or an input larger than the memory cap\n\
     (set_max_input_bytes). A file that cannot be opened is OSError instead."
);

pyo3::create_exception!(
    karkas,
    KarkasWarning,
    pyo3::exceptions::PyUserWarning,
    "A warning of karkas about its input, issued with warnings.warn.\n\
     \n\
     The readers warn of a first column that counts the rows (row numbers\n\
     read as x), of points far out of their order along the curve, and of a\n\
     header whose columns are read in order; each message names the file and\n\
     the fix (columns=, sorting the points). A subclass of UserWarning, so\n\
     warnings.simplefilter(\"error\", karkas.KarkasWarning) makes them errors."
);

/// Issues every message of `warnings` about the file `name` as a [`KarkasWarning`].
pub fn warn_all(py: Python<'_>, name: &std::path::Path, warnings: &[String]) -> PyResult<()> {
    let category = py.get_type::<KarkasWarning>();
    for warning in warnings {
        let message =
            std::ffi::CString::new(format!("{}: {warning}", name.display())).unwrap_or_default();
        PyErr::warn(py, &category, &message, 1)?;
    }
    Ok(())
}

/// Adds the exception classes to the module `m`.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("KarkasError", py.get_type::<KarkasError>())?;
    m.add("PointsError", py.get_type::<PointsError>())?;
    m.add("KnotsError", py.get_type::<KnotsError>())?;
    m.add("OptionError", py.get_type::<OptionError>())?;
    m.add(
        "IncompatibleDataError",
        py.get_type::<IncompatibleDataError>(),
    )?;
    m.add("ConvergenceError", py.get_type::<ConvergenceError>())?;
    m.add("ExpressionError", py.get_type::<ExpressionError>())?;
    m.add("FileFormatError", py.get_type::<FileFormatError>())?;
    m.add("NoBSplineFormError", py.get_type::<NoBSplineFormError>())?;
    m.add("KarkasWarning", py.get_type::<KarkasWarning>())?;
    Ok(())
}

/// A library error as the exception of its kind, carrying the library's message.
///
/// Variants not listed (among them any added to the non-exhaustive enum later) raise the
/// base class `KarkasError`.
pub fn library_error(e: karkas::Error) -> PyErr {
    let message = e.to_string();
    library_error_saying(&e, message)
}

/// A library error as the exception of its kind, carrying `message` (e.g. the library's
/// message prefixed with the file and the item it came from).
pub fn library_error_saying(e: &karkas::Error, message: String) -> PyErr {
    match kind(e) {
        Kind::Points => PointsError::new_err(message),
        Kind::Knots => KnotsError::new_err(message),
        Kind::Option => OptionError::new_err(message),
        Kind::Incompatible => IncompatibleDataError::new_err(message),
        Kind::Convergence => ConvergenceError::new_err(message),
        Kind::Expression => ExpressionError::new_err(message),
        Kind::NoBSplineForm => NoBSplineFormError::new_err(message),
        Kind::Other => KarkasError::new_err(message),
    }
}

/// The exception class of a library error.
enum Kind {
    Points,
    Knots,
    Option,
    Incompatible,
    Convergence,
    Expression,
    NoBSplineForm,
    Other,
}

/// The group a library error belongs to; an error about one curve of a network is of the kind
/// of its cause.
fn kind(e: &karkas::Error) -> Kind {
    use karkas::Error as E;
    match e {
        E::NetworkCurve { source, .. } => kind(source),
        E::TooFewPoints { .. }
        | E::NonFinitePoint { .. }
        | E::NonFiniteCell { .. }
        | E::NonFiniteEntry { .. }
        | E::NonFiniteArgument { .. }
        | E::GridShape { .. }
        | E::InvalidGridSize { .. }
        | E::OutsideGrid { .. }
        | E::CountMismatch { .. }
        | E::CoincidentPoints { .. }
        | E::CoincidentGridLines { .. }
        | E::TooFewCurves { .. }
        | E::TooFewNetworkCurves { .. }
        | E::SkeletonLength { .. }
        | E::NonFiniteSkeletonPoint { .. }
        | E::OpenPeriodicData { .. }
        | E::UmbilicRegion { .. }
        | E::LoftSection { .. } => Kind::Points,
        E::InvalidKnot { .. } => Kind::Knots,
        E::InvalidOrder { .. }
        | E::InvalidStep { .. }
        | E::PeriodTooLarge { .. }
        | E::InvalidSetting { .. }
        | E::InvalidDomain { .. }
        | E::InvalidPeriod { .. }
        | E::EmptyBlendingFamily { .. }
        | E::UnsupportedEnds { .. }
        | E::InvalidPlane { .. }
        | E::UnknownName { .. } => Kind::Option,
        E::IncompatibleSkeleton { .. }
        | E::IncompatibleCurves { .. }
        | E::NetworkCrossing { .. }
        | E::CurveClosure { .. }
        | E::MixedClosure { .. }
        | E::NotFourSided { .. }
        | E::UnevenCrossings { .. }
        | E::UnclosedCrossDerivative { .. }
        | E::FixedLineSum { .. }
        | E::InconsistentTotals { .. }
        | E::InconsistentBlock { .. } => Kind::Incompatible,
        E::SingularSystem { .. }
        | E::NoSurfaceNear { .. }
        | E::SingularPoint { .. }
        | E::ContinuationFailed { .. } => Kind::Convergence,
        E::ExpressionParse { .. } => Kind::Expression,
        E::NotExactlyConvertible { .. } => Kind::NoBSplineForm,
        _ => Kind::Other,
    }
}

/// A file error of karkas-io as `OSError`: the subclass of the operating system's error kind
/// when it reported one (`FileNotFoundError`, `PermissionError`, ...), with karkas-io's
/// message naming the file.
pub fn file_error(e: karkas_io::IoError) -> PyErr {
    let kind = match &e {
        karkas_io::IoError::Open { source, .. } | karkas_io::IoError::Write { source, .. } => {
            source.kind()
        }
        _ => std::io::ErrorKind::Other,
    };
    PyErr::from(std::io::Error::new(kind, e.to_string()))
}
