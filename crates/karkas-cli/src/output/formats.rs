//! The output formats of each kind of result, by extension (karkas-io's lists, shared with
//! the Python package).

pub use karkas_io::export::formats::{
    CURVE_FORMATS, EXACT_CURVE_FORMATS, EXACT_SURFACE_FORMATS, STREAMED_CURVE_FORMATS,
    STREAMED_SURFACE_FORMATS, SURFACE_FORMATS,
};
