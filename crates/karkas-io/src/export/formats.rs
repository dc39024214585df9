//! The output formats of each kind of result, by extension.

use crate::OutputFormat;

/// The formats of a sampled curve.
pub const CURVE_FORMATS: [OutputFormat; 4] = [
    OutputFormat::Csv,
    OutputFormat::Svg,
    OutputFormat::Png,
    OutputFormat::Html,
];

/// Every format a sampled surface can be written in: the sampled CSV, meshes, pictures and
/// the viewer page.
pub const SURFACE_FORMATS: [OutputFormat; 10] = concat(
    concat::<1, 6, 7>([OutputFormat::Csv], OutputFormat::MESHES),
    [OutputFormat::Svg, OutputFormat::Png, OutputFormat::Html],
);

/// [`CURVE_FORMATS`] and the exact B-spline curve as STEP, IGES or DXF, for the curves that
/// are piecewise polynomials.
pub const EXACT_CURVE_FORMATS: [OutputFormat; 7] = concat(CURVE_FORMATS, OutputFormat::CURVE_CAD);

/// [`SURFACE_FORMATS`] and the exact B-spline surface as STEP or IGES.
pub const EXACT_SURFACE_FORMATS: [OutputFormat; 12] = concat(SURFACE_FORMATS, OutputFormat::CAD);

/// [`EXACT_CURVE_FORMATS`] and the samples' points as a NumPy `.npy` array, for the commands
/// that write their samples as they compute them ([`super::stream`]).
pub const STREAMED_CURVE_FORMATS: [OutputFormat; 8] =
    concat(EXACT_CURVE_FORMATS, [OutputFormat::Npy]);

/// [`EXACT_SURFACE_FORMATS`] and the samples' points as a NumPy `.npy` array, for the
/// commands that write their samples as they compute them ([`super::stream`]).
pub const STREAMED_SURFACE_FORMATS: [OutputFormat; 13] =
    concat(EXACT_SURFACE_FORMATS, [OutputFormat::Npy]);

/// The formats of a point list drawn as a curve (no parameters to write a CSV with).
pub const POINTS_FORMATS: [OutputFormat; 3] =
    [OutputFormat::Svg, OutputFormat::Png, OutputFormat::Html];

/// The formats of a triangle mesh: the mesh formats that keep triangles, and the viewer page.
pub const MESH_FORMATS: [OutputFormat; 6] = [
    OutputFormat::Obj,
    OutputFormat::Stl,
    OutputFormat::Ply,
    OutputFormat::Vtk,
    OutputFormat::Glb,
    OutputFormat::Html,
];

/// `first` followed by `second` (`M` must be `N + K`).
const fn concat<const N: usize, const K: usize, const M: usize>(
    first: [OutputFormat; N],
    second: [OutputFormat; K],
) -> [OutputFormat; M] {
    assert!(M == N + K);
    let mut all = [OutputFormat::Csv; M];
    let mut k = 0;
    while k < M {
        all[k] = if k < N { first[k] } else { second[k - N] };
        k += 1;
    }
    all
}
