//! The output formats of each kind of result, by extension.

use karkas_io::OutputFormat;

/// The formats of a sampled curve.
pub const CURVE_FORMATS: [OutputFormat; 4] = [
    OutputFormat::Csv,
    OutputFormat::Svg,
    OutputFormat::Png,
    OutputFormat::Html,
];

/// [`CURVE_FORMATS`] and the exact B-spline curve as STEP or IGES, for the commands whose
/// curve is a piecewise polynomial.
pub const EXACT_CURVE_FORMATS: [OutputFormat; 6] = [
    OutputFormat::Csv,
    OutputFormat::Svg,
    OutputFormat::Png,
    OutputFormat::Html,
    OutputFormat::Step,
    OutputFormat::Iges,
];

/// Every format a sampled surface can be written in: the sampled CSV, meshes, pictures and
/// the viewer page.
pub const SURFACE_FORMATS: [OutputFormat; 10] = [
    OutputFormat::Csv,
    OutputFormat::Obj,
    OutputFormat::Stl,
    OutputFormat::Ply,
    OutputFormat::Vtk,
    OutputFormat::Vts,
    OutputFormat::Glb,
    OutputFormat::Svg,
    OutputFormat::Png,
    OutputFormat::Html,
];

/// [`SURFACE_FORMATS`] and the exact B-spline surface as STEP or IGES.
pub const EXACT_SURFACE_FORMATS: [OutputFormat; 12] = [
    OutputFormat::Csv,
    OutputFormat::Obj,
    OutputFormat::Stl,
    OutputFormat::Ply,
    OutputFormat::Vtk,
    OutputFormat::Vts,
    OutputFormat::Glb,
    OutputFormat::Svg,
    OutputFormat::Png,
    OutputFormat::Html,
    OutputFormat::Step,
    OutputFormat::Iges,
];
