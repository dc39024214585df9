//! karkas for JavaScript: the library's curves, fits and surfaces behind the workbench page
//! (`web/`), compiled to WebAssembly with `wasm-bindgen`.
//!
//! Inputs arrive as the text of a file and its name, and are read by the command line's
//! readers (`karkas_io`), so a bad file is refused with the same words, naming the line.
//! Curves and surfaces are built as the command line builds them ([`curves`], [`surfaces`])
//! and exported by its writers, so a STEP file from the page is the command line's file for
//! the same points and options. Arrays cross as `Float64Array`s. Without threads in the
//! browser, the library's parallel paths run on the one thread (rayon's fallback).

pub mod curves;
pub mod loft;
pub mod surfaces;

use std::path::Path;

use karkas::Point;
use karkas_io::points::{parse_curve_points, CurvePoints};
use karkas_io::OutputFormat;
use wasm_bindgen::prelude::*;

use curves::{build_curve, BuiltCurve, CurveRequest};
use surfaces::{grid_surface, loft_surface, network_surface, BuiltSurface};

/// An error as the command line words it (`karkas: error: ` and the message).
fn refusal(message: impl std::fmt::Display) -> JsError {
    JsError::new(&format!("karkas: error: {message}"))
}

/// The points of a curve file (CSV or whitespace columns `x,y[,z]`, or an airfoil `.dat`).
#[wasm_bindgen]
pub struct CurveInput {
    coords: Vec<f64>,
    dim: usize,
}

#[wasm_bindgen]
impl CurveInput {
    /// The coordinates, point after point.
    pub fn coords(&self) -> Vec<f64> {
        self.coords.clone()
    }
    /// 2 or 3.
    pub fn dim(&self) -> usize {
        self.dim
    }
}

/// Reads the curve points of the file `name` whose text is `text`.
#[wasm_bindgen(js_name = readCurve)]
pub fn read_curve(text: &str, name: &str) -> Result<CurveInput, JsError> {
    let points = parse_curve_points(text, Path::new(name)).map_err(refusal)?;
    let (coords, dim) = match points {
        CurvePoints::Planar(p) => (p.iter().flat_map(|p| p.0).collect(), 2),
        CurvePoints::Spatial(p) => (p.iter().flat_map(|p| p.0).collect(), 3),
    };
    Ok(CurveInput { coords, dim })
}

/// A curve built from points: samples, curvature and exports.
#[wasm_bindgen]
pub struct CurveView {
    built: Box<dyn BuiltCurve>,
}

#[wasm_bindgen]
impl CurveView {
    /// `n` samples, 9 numbers each: `t, x, y, z, x', y', z', κ, s`.
    pub fn samples(&self, n: usize) -> Vec<f64> {
        self.built.samples(n)
    }
    /// Curvature against arc length: `t, s, κ` at `per_piece` samples of every piece.
    pub fn profile(&self, per_piece: usize) -> Vec<f64> {
        self.built.profile(per_piece)
    }
    /// The degree of the exact B-spline form.
    pub fn degree(&self) -> usize {
        self.built.bspline_size().0
    }
    /// The number of control points of the exact B-spline form.
    pub fn poles(&self) -> usize {
        self.built.bspline_size().1
    }
    /// The breakpoints of the polynomial pieces (for a fit: its knots).
    pub fn knots(&self) -> Vec<f64> {
        self.built.breaks()
    }
    /// A fit's foot parameters of the points (empty for the other methods).
    pub fn parameters(&self) -> Vec<f64> {
        self.built.parameters()
    }
    /// The command line's file in `format` (`step`, `iges`, `dxf`) for a file of stem `name`
    /// made from the input `input`; `csv` (the samples, `t,x,y[,z]`) and `svg` (the picture
    /// with its comb, `name` its title) as the command line writes them.
    pub fn export(&self, format: &str, name: &str, input: &str) -> Result<String, JsError> {
        match format {
            "csv" => Ok(self.built.csv()),
            "svg" => self.built.svg(name).map_err(refusal),
            _ => {
                let format = cad_format(format, &OutputFormat::CURVE_CAD)?;
                self.built.cad(format, name, input).map_err(refusal)
            }
        }
    }
}

fn cad_format(name: &str, allowed: &[OutputFormat]) -> Result<OutputFormat, JsError> {
    let format = OutputFormat::from_path(Path::new(&format!("x.{name}")), allowed)
        .map_err(|e| refusal(e.to_string()))?;
    Ok(format)
}

/// Builds a curve through `coords` (`dim` numbers a point) as the command line's `curve ll`
/// (`method` `ll`, `ll-interpolate`), `curve spline` (`spline`) or `curve fit` (`fit`) does
/// with the options of the same names (`knots`, when not empty, in place of the fit's
/// tolerance, with the points' starting parameters `start` when it holds one a point);
/// errors name `input`.
#[allow(clippy::too_many_arguments)]
#[wasm_bindgen(js_name = buildCurve)]
pub fn build_curve_js(
    method: &str,
    coords: &[f64],
    dim: usize,
    order: usize,
    closed: bool,
    ends: &str,
    param: &str,
    tolerance: f64,
    eps: f64,
    corners: &[f64],
    knots: &[f64],
    start: &[f64],
    input: &str,
) -> Result<CurveView, JsError> {
    let request = CurveRequest {
        method: method.to_owned(),
        order,
        closed,
        ends: ends.to_owned(),
        param: param.to_owned(),
        tolerance,
        eps: if eps > 0.0 { eps } else { f64::INFINITY },
        corners: corners.to_vec(),
        knots: knots.to_vec(),
        start: start.to_vec(),
    };
    let built = match dim {
        2 => build_curve(&points::<2>(coords), &request, input),
        3 => build_curve(&points::<3>(coords), &request, input),
        _ => return Err(refusal("points must have 2 or 3 coordinates")),
    };
    Ok(CurveView {
        built: built.map_err(refusal)?,
    })
}

fn points<const D: usize>(coords: &[f64]) -> Vec<Point<D>> {
    coords
        .chunks_exact(D)
        .map(|c| Point(std::array::from_fn(|k| c[k])))
        .collect()
}

/// A surface: samples, sections and exports.
#[wasm_bindgen]
pub struct SurfaceView {
    built: Box<dyn BuiltSurface>,
    loft: Option<LoftFacts>,
}

/// What the page shows of a loft beside its surface.
struct LoftFacts {
    controls: (usize, usize),
    max_relative_deviation: f64,
    tolerance_met: bool,
    stations: Vec<f64>,
    curves: Vec<f64>,
}

/// Points a section's curve is drawn with.
const STATION_CURVE_POINTS: usize = 121;

#[wasm_bindgen]
impl SurfaceView {
    /// `nu x nv` samples, `v` fastest, 3 numbers each.
    pub fn samples(&self, nu: usize, nv: usize) -> Vec<f64> {
        self.built.samples(nu, nv)
    }
    /// The section by the plane `n . x = offset`: polylines ended by NaN triples.
    pub fn section(&self, nx: f64, ny: f64, nz: f64, offset: f64) -> Result<Vec<f64>, JsError> {
        self.built.section([nx, ny, nz], offset).map_err(refusal)
    }
    /// The command line's STEP or IGES file for a file of stem `name`, or its OBJ or ASCII
    /// STL mesh (`obj`, `stl`) at the default samples.
    pub fn export(&self, format: &str, name: &str, input: &str) -> Result<String, JsError> {
        if format == "obj" || format == "stl" {
            return self.built.mesh(format).map_err(refusal);
        }
        let format = cad_format(format, &OutputFormat::CAD)?;
        self.built.cad(format, name, input).map_err(refusal)
    }
    /// A loft's control points along the span and along the sections (empty for the other
    /// surfaces).
    #[wasm_bindgen(js_name = loftControls)]
    pub fn loft_controls(&self) -> Vec<u32> {
        self.loft.as_ref().map_or(Vec::new(), |f| {
            vec![f.controls.0 as u32, f.controls.1 as u32]
        })
    }
    /// A loft's largest distance of a section's points from the surface at its station, as a
    /// share of that section's chord (NaN for the other surfaces).
    #[wasm_bindgen(js_name = loftDeviation)]
    pub fn loft_deviation(&self) -> f64 {
        self.loft
            .as_ref()
            .map_or(f64::NAN, |f| f.max_relative_deviation)
    }
    /// True when every section of a loft is within its tolerance.
    #[wasm_bindgen(js_name = loftToleranceMet)]
    pub fn loft_tolerance_met(&self) -> bool {
        self.loft.as_ref().is_some_and(|f| f.tolerance_met)
    }
    /// A loft's span stations (empty for the other surfaces).
    #[wasm_bindgen(js_name = loftStations)]
    pub fn loft_stations(&self) -> Vec<f64> {
        self.loft
            .as_ref()
            .map_or(Vec::new(), |f| f.stations.clone())
    }
    /// The surface's curve at every station of a loft, 121 points of 3 numbers each,
    /// section after section (empty for the other surfaces).
    #[wasm_bindgen(js_name = loftSectionCurves)]
    pub fn loft_section_curves(&self) -> Vec<f64> {
        self.loft.as_ref().map_or(Vec::new(), |f| f.curves.clone())
    }
}

/// The grid of a grid CSV file (`row,col,x,y,z`), as `rows, cols, x, y, z, ...`.
#[wasm_bindgen(js_name = readGrid)]
pub fn read_grid(text: &str, name: &str) -> Result<Vec<f64>, JsError> {
    let grid = karkas_io::grid::parse_grid(text, Path::new(name)).map_err(refusal)?;
    let mut out = vec![grid.rows() as f64, grid.cols() as f64];
    out.extend(grid.as_slice().iter().flat_map(|p| p.0));
    Ok(out)
}

/// The surface `method` (`ll`, `ll-interpolate`, `bicubic`) of a grid from [`read_grid`].
#[wasm_bindgen(js_name = buildGridSurface)]
pub fn build_grid_surface(
    grid: &[f64],
    method: &str,
    order: usize,
    input: &str,
) -> Result<SurfaceView, JsError> {
    let (rows, cols) = (grid[0] as usize, grid[1] as usize);
    let points = points::<3>(&grid[2..]);
    let grid = karkas::Grid::from_row_major(rows, cols, points).map_err(refusal)?;
    Ok(SurfaceView {
        built: grid_surface(&grid, method, order, input).map_err(refusal)?,
        loft: None,
    })
}

/// The Coons or Gordon surface (`kind`: `bilinear`, `gordon`, `gordon-spline`) of the
/// network of the curve files `u` and `v` (CSV `curve,x,y,z`).
#[wasm_bindgen(js_name = buildNetworkSurface)]
pub fn build_network_surface(
    u_text: &str,
    u_name: &str,
    v_text: &str,
    v_name: &str,
    kind: &str,
) -> Result<SurfaceView, JsError> {
    let read = |text: &str, name: &str| {
        karkas_io::network::parse_curve_family(text, Path::new(name)).map_err(refusal)
    };
    let (u, v) = (read(u_text, u_name)?, read(v_text, v_name)?);
    let input = format!("{u_name}, {v_name}");
    Ok(SurfaceView {
        built: network_surface(&u, &v, kind, &input).map_err(refusal)?,
        loft: None,
    })
}

/// The rows of a sections table (`file,x,y,z,chord,twist[,dihedral]`) read by the command
/// line's reader.
#[wasm_bindgen]
pub struct SectionsTable {
    files: Vec<String>,
    lines: Vec<u32>,
    placements: Vec<f64>,
}

#[wasm_bindgen]
impl SectionsTable {
    /// The profile files, as the table names them, in span order.
    pub fn files(&self) -> Vec<String> {
        self.files.clone()
    }
    /// The table's line of every row.
    pub fn lines(&self) -> Vec<u32> {
        self.lines.clone()
    }
    /// Six numbers a row: `x, y, z, chord, twist, dihedral` (NaN: none given).
    pub fn placements(&self) -> Vec<f64> {
        self.placements.clone()
    }
}

/// Reads the sections table `name` whose text is `text`.
#[wasm_bindgen(js_name = readSectionsTable)]
pub fn read_sections_table(text: &str, name: &str) -> Result<SectionsTable, JsError> {
    let rows =
        karkas_io::sections_table::parse_sections_table(text, Path::new(name), Path::new(""))
            .map_err(refusal)?;
    Ok(SectionsTable {
        files: rows.iter().map(|r| r.file.clone()).collect(),
        lines: rows.iter().map(|r| r.line as u32).collect(),
        placements: loft::row_placements(&rows),
    })
}

/// The wing lofted through the profiles `coords` (`x, y` pairs in unit chord, `counts[k]`
/// points for section `k`, in span order) placed by `placements` (six numbers a section:
/// `x, y, z` of the leading edge, chord, twist and dihedral in degrees, NaN for none), as
/// `karkas loft` builds it with `--span rule --tolerance tolerance`; `labels` (one line a
/// section) name the sections in errors, `input` the rest.
#[wasm_bindgen(js_name = buildLoft)]
pub fn build_loft(
    coords: &[f64],
    counts: &[u32],
    placements: &[f64],
    rule: &str,
    tolerance: f64,
    labels: &str,
    input: &str,
) -> Result<SurfaceView, JsError> {
    let placements = loft::placements(placements).map_err(refusal)?;
    let counts: Vec<usize> = counts.iter().map(|&n| n as usize).collect();
    let labels: Vec<String> = labels.lines().map(str::to_owned).collect();
    let built = loft::wing_loft(
        coords,
        &counts,
        &placements,
        rule,
        tolerance,
        &labels,
        input,
    )
    .map_err(refusal)?;
    let facts = LoftFacts {
        controls: built.loft.control_counts(),
        max_relative_deviation: built.loft.max_relative_deviation(),
        tolerance_met: built.loft.tolerance_met(),
        stations: built.loft.stations().to_vec(),
        curves: built.station_curves(STATION_CURVE_POINTS),
    };
    Ok(SurfaceView {
        built: loft_surface(built.loft, built.samples),
        loft: Some(facts),
    })
}
