//! The output formats of each kind of result, by extension.

use karkas_io::OutputFormat;

/// The formats of a sampled curve.
pub const CURVE_FORMATS: [OutputFormat; 4] = [
    OutputFormat::Csv,
    OutputFormat::Svg,
    OutputFormat::Png,
    OutputFormat::Html,
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

/// [`CURVE_FORMATS`] and the exact B-spline curve as STEP or IGES, for the commands whose
/// curve is a piecewise polynomial.
pub const EXACT_CURVE_FORMATS: [OutputFormat; 6] = with_cad(CURVE_FORMATS);

/// [`SURFACE_FORMATS`] and the exact B-spline surface as STEP or IGES.
pub const EXACT_SURFACE_FORMATS: [OutputFormat; 12] = with_cad(SURFACE_FORMATS);

/// `formats` followed by [`OutputFormat::CAD`] (`M` must be `N + 2`).
const fn with_cad<const N: usize, const M: usize>(formats: [OutputFormat; N]) -> [OutputFormat; M] {
    assert!(M == N + OutputFormat::CAD.len());
    let mut all = [OutputFormat::Csv; M];
    let mut k = 0;
    while k < M {
        all[k] = if k < N {
            formats[k]
        } else {
            OutputFormat::CAD[k - N]
        };
        k += 1;
    }
    all
}
