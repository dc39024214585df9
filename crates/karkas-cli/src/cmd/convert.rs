//! `karkas convert IN OUT`: one file format into another, where both hold the same kind of
//! thing.
//!
//! Input kinds, by extension and (for CSV) header:
//! - a triangle mesh: `.obj`, `.stl` (binary or ASCII), `.ply`;
//! - a surface grid: CSV with header `i,j,x,y,z` (a frame) or `u,v,x,y,z` (samples, `u`
//!   outer, as the surface commands write them);
//! - a curve: any other CSV or whitespace columns `x,y[,z]`, or an airfoil `.dat`;
//! - a CAD model: `.step`, `.stp`, `.p21`, `.iges`, `.igs`, or any other input (standard
//!   input, a pipe, a file named otherwise) that starts as STEP or IGES does (read by
//!   `karkas_io::cad::read::read_cad`), meshed to the chordal tolerance `--tolerance`
//!   (`karkas_io::mesh::shape_mesh`) and written as a mesh.
//!
//! Outputs: a mesh or a CAD model to `.obj .stl .ply .vtk .glb .html`; a grid to those and `.vts .svg .png`
//! and `.csv` (`i,j,x,y,z`); a curve to `.svg .png .html`. Any other pair is refused.
//! `--flip-normals` turns a mesh output over (reversed winding and normals).

use crate::args::MeshOutput;
use crate::input::faces_of_model;
use crate::output::console::note;
use crate::output::curve::{to_space, write_curve_figure};
use crate::output::formats::SURFACE_FORMATS;
use crate::output::memory::{check_memory, mesh_output_bytes, surface_output_bytes};
use crate::output::overwrite::ensure_distinct;
use crate::output::surface::write_surface;
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::{Grid, Point3};
use karkas_io::cad::read::{cad_format_of, read_cad, read_cad_from, CadModel};
use karkas_io::export::mesh::write_triangle_mesh;
use karkas_io::grid::parse_grid;
use karkas_io::input::{display_name, Input as Source};
use karkas_io::mesh::TriangleMesh;
use karkas_io::mesh::{read_mesh, read_mesh_from, shape_mesh, MeshOptions};
use karkas_io::points::{parse_curve_points_with, CurvePoints, ReadOptions};
use karkas_io::samples::parse_surface_samples;
use karkas_io::svg::CurveOverlay;
use karkas_io::write::write_grid_csv;
use karkas_io::OutputFormat;
use std::io::BufRead;
use std::path::{Path, PathBuf};

/// Arguments of `karkas convert`.
#[derive(Debug, Args)]
pub struct ConvertArgs {
    /// Input: a mesh (.obj .stl .ply), a CAD model (.step .stp .p21 .iges .igs), a grid CSV
    /// (i,j,x,y,z or u,v,x,y,z) or curve points (CSV / columns x,y[,z], airfoil .dat). An
    /// input named otherwise (- for standard input, a pipe) is told by its first bytes.
    input: PathBuf,
    /// Output, by extension: .obj .stl .ply .vtk .vts .glb .html .svg .png .csv (which ones
    /// depend on the input, see karkas convert --help).
    output: PathBuf,
    /// Write .stl and .ply as ASCII instead of binary.
    #[arg(long)]
    ascii: bool,
    /// A CAD model (STEP or IGES): the largest distance of the mesh from the model's
    /// faces, in the file's units (default: 1e-3 of the model's bounding-box diagonal).
    #[arg(long, value_name = "T")]
    tolerance: Option<f64>,
    #[command(flatten)]
    mesh: MeshOutput,
}

/// What the input holds.
enum Input {
    Mesh(TriangleMesh),
    /// A grid, and whether it is a frame of nodes (`i,j`) rather than samples (`u,v`).
    Grid(Grid<Point3>, bool),
    Curve(Vec<Point3>, bool),
}

const MESH_OUT: [OutputFormat; 6] = [
    OutputFormat::Obj,
    OutputFormat::Stl,
    OutputFormat::Ply,
    OutputFormat::Vtk,
    OutputFormat::Glb,
    OutputFormat::Html,
];
/// A grid converts to every format of a sampled surface.
const GRID_OUT: [OutputFormat; 10] = SURFACE_FORMATS;
const CURVE_OUT: [OutputFormat; 3] = [OutputFormat::Svg, OutputFormat::Png, OutputFormat::Html];

/// Runs `karkas convert`.
pub fn run(args: &ConvertArgs) -> Result<()> {
    // Every format some input converts to: the grid's, which include the others.
    let format = output_format(&args.output, &GRID_OUT)?;
    args.mesh.check(format)?;
    ensure_distinct(&args.input, &args.output)?;
    let input = read_input(&args.input, args.tolerance)?;
    check_allowed(&args.input, &input, format)?;
    check_memory(
        &format!("convert {}", args.input.display()),
        match &input {
            Input::Mesh(mesh) => mesh_output_bytes(mesh.positions.len(), mesh.triangles.len()),
            Input::Grid(grid, _) => surface_output_bytes(format, grid.rows(), grid.cols()),
            Input::Curve(points, _) => points.len() as u128 * 48,
        },
    )?;
    let title = args
        .input
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    let options = args.mesh.options(args.ascii);
    let count = match input {
        Input::Mesh(mesh) => {
            let count = mesh.positions.len();
            write_any_mesh(&args.output, format, mesh, &options, &title)?;
            count
        }
        Input::Grid(grid, is_frame) => {
            let net = is_frame.then_some(&grid);
            match format {
                OutputFormat::Csv => write_grid_csv(&args.output, &grid)?,
                OutputFormat::Stl | OutputFormat::Ply if args.ascii => {
                    let mesh = TriangleMesh::from_grid(&grid)
                        .map_err(anyhow::Error::msg)
                        .with_context(|| args.input.display().to_string())?;
                    write_any_mesh(&args.output, format, mesh, &options, &title)?;
                }
                _ => write_surface(&args.output, format, &grid, &title, net, &options)?,
            }
            grid.rows() * grid.cols()
        }
        Input::Curve(points, planar) => {
            let overlay = CurveOverlay::default();
            if planar {
                let flat: Vec<karkas::Point2> = points
                    .iter()
                    .map(|p| karkas::Point2::new([p[0], p[1]]))
                    .collect();
                write_curve_figure(&args.output, format, &title, &flat, &[], false, &overlay)?;
            } else {
                write_curve_figure(&args.output, format, &title, &points, &[], false, &overlay)?;
            }
            points.len()
        }
    };
    crate::output::console::record("points", count);
    note(format!(
        "karkas: wrote {} ({count} points)",
        shown(&args.output).display()
    ));
    Ok(())
}

/// Refuses an output `format` that `input`'s kind (read from `path`) does not convert to.
fn check_allowed(path: &Path, input: &Input, format: OutputFormat) -> Result<()> {
    let (kind, allowed): (&str, &[OutputFormat]) = match input {
        Input::Mesh(_) if is_cad(path) => ("a CAD model", &MESH_OUT),
        Input::Mesh(_) => ("a triangle mesh", &MESH_OUT),
        Input::Grid(..) => ("a surface grid", &GRID_OUT),
        Input::Curve(..) => ("a curve", &CURVE_OUT),
    };
    if !allowed.contains(&format) {
        let list: Vec<String> = allowed
            .iter()
            .map(|f| format!(".{}", f.extension()))
            .collect();
        bail!(
            "cannot convert {} ({kind}) to .{}: {kind} converts to {}",
            path.display(),
            format.extension(),
            list.join(", ")
        );
    }
    Ok(())
}

/// Writes a mesh in a mesh format (turned over in place when `options` say so) or as the
/// viewer page.
fn write_any_mesh(
    output: &Path,
    format: OutputFormat,
    mesh: TriangleMesh,
    options: &MeshOptions,
    title: &str,
) -> Result<()> {
    Ok(write_triangle_mesh(output, format, mesh, options, title)?)
}

/// Reads `path` as a mesh, a grid or a curve (see the module docs). A mesh or CAD extension
/// decides the reader; any other input (standard input `-`, a pipe such as `<(cat m.step)`,
/// a file named otherwise) is opened once and its first bytes decide: STEP or IGES, a mesh,
/// else text whose header decides which reader parses it. A CAD model is meshed to
/// `tolerance` (see [`cad_mesh`]); `tolerance` on any other input is refused.
fn read_input(path: &Path, tolerance: Option<f64>) -> Result<Input> {
    let ext = extension(path);
    if is_cad(path) {
        return Ok(Input::Mesh(cad_mesh(path, read_cad(path)?, tolerance)?));
    }
    if matches!(ext.as_deref(), Some("obj" | "stl" | "ply")) {
        if tolerance.is_some() {
            bail!("{}", not_a_model(path));
        }
        return Ok(Input::Mesh(read_mesh(path)?));
    }
    let name = display_name(path);
    let mut input = Source::open(path)?;
    let head = input
        .fill_buf()
        .with_context(|| format!("cannot read {}", name.display()))?;
    if let Some(format) = cad_format_of(head) {
        let model = read_cad_from(&name, format, &mut input)?;
        return Ok(Input::Mesh(cad_mesh(path, model, tolerance)?));
    }
    if tolerance.is_some() {
        bail!("{}", not_a_model(path));
    }
    if looks_like_a_mesh(&mut input)? {
        return Ok(Input::Mesh(read_mesh_from(input, None)?));
    }
    let text = input.read_text()?;
    match csv_header(&text).as_deref() {
        Some(h) if h.contains(&"i".to_owned()) && h.contains(&"j".to_owned()) => {
            Ok(Input::Grid(parse_grid(&text, &name)?, true))
        }
        Some(h) if h.contains(&"u".to_owned()) && h.contains(&"v".to_owned()) => {
            Ok(Input::Grid(parse_surface_samples(&text, &name)?, false))
        }
        _ => {
            let read = parse_curve_points_with(&text, &name, &ReadOptions::default())?;
            crate::input::warn_of_reading(&name, &read.warnings);
            Ok(match read.points {
                CurvePoints::Planar(points) => Input::Curve(to_space(&points), true),
                CurvePoints::Spatial(points) => Input::Curve(points, false),
            })
        }
    }
}

/// The lower-case extension of `path`.
fn extension(path: &Path) -> Option<String> {
    path.extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
}

/// True when `path` names a CAD model by its extension.
pub(crate) fn is_cad(path: &Path) -> bool {
    matches!(
        extension(path).as_deref(),
        Some("step" | "stp" | "p21" | "iges" | "igs")
    )
}

/// The mesh of the CAD model read from `path` within `tolerance` of its faces (1e-3 of its
/// size when not given); what the reader skipped is warned in one line. A model without
/// faces, or whose faces all collapse to one point, is refused before the tolerance is
/// looked at.
fn cad_mesh(path: &Path, model: CadModel, tolerance: Option<f64>) -> Result<TriangleMesh> {
    let name = display_name(path);
    faces_of_model(path, &model, "cannot mesh ", "mesh")?;
    let shape = &model.shape;
    let mut corners = shape
        .faces
        .iter()
        .flat_map(|f| f.surface.control_points().as_slice());
    let first = corners.next().copied();
    if corners.all(|p| Some(*p) == first) {
        bail!(
            "cannot mesh {}: the model's faces collapse to one point (their size is 0)",
            name.display()
        );
    }
    let tolerance = tolerance.unwrap_or(1e-3 * model.shape.size());
    shape_mesh(&model.shape, tolerance).with_context(|| format!("cannot mesh {}", name.display()))
}

/// The refusal of `--tolerance` on an input that is not a CAD model.
fn not_a_model(path: &Path) -> String {
    format!(
        "--tolerance: only a CAD model (STEP or IGES: .step .stp .p21 .iges .igs, or content \
         that starts as one does) is meshed to a tolerance, not {}",
        display_name(path).display()
    )
}

/// True when the first bytes of an input named by no mesh extension (looked at, not
/// consumed) are a mesh ([`karkas_io::mesh::is_mesh_prefix`]).
fn looks_like_a_mesh(input: &mut Source) -> Result<bool> {
    let name = input.name.clone();
    let prefix = input
        .fill_buf()
        .with_context(|| format!("cannot read {}", name.display()))?;
    Ok(karkas_io::mesh::is_mesh_prefix(prefix))
}

/// The names of the first content line of CSV `text` with a header (a line with a field that
/// is not a number; lower case, units and quotes aside, split at its separator:
/// [`karkas_io::dialect::header_names`]); `None` when there is none.
fn csv_header(text: &str) -> Option<Vec<String>> {
    let line = text
        .trim_start_matches('\u{feff}')
        .lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .find(|l| !l.is_empty())?;
    karkas_io::dialect::header_names(line)
}
