//! A sampled surface in any format: the `u,v,x,y,z` CSV, meshes (`.obj .stl .ply .vtk .vts
//! .glb`), pictures (`.svg .png`: the shaded surface with isoparametric lines, hidden parts
//! removed) and the 3-D viewer page (`.html`).

use super::cad::write_cad_surface;
use super::console::{note, record};
use super::memory::{check_memory, mesh_sample_budget, surface_output_bytes};
use super::samples::{default_surface_samples, report_samples};
use super::target::shown;
use crate::args::{CadOptions, CapOption, GridSamples, MeshOutput, MeshTolerance};
use anyhow::{anyhow, Result};
use karkas::bspline::ToBSplineSurface;
use karkas::{Grid, Point3, Surface};
use karkas_io::export::samples::sample_surface;
use karkas_io::export::stream;
use karkas_io::export::surface::{write_surface_at, SurfaceDrawing};
use karkas_io::mesh::{body_mesh, write_mesh_as, MeshOptions};
use karkas_io::OutputFormat;
use std::path::Path;

pub use karkas_io::export::surface::isoparametric_lines;

/// Samples `surface` on a uniform `nu x nv` grid over its whole domain and writes the samples
/// to `output` as a `u,v,x,y,z` CSV (or `.npy` where the command allows it; both written as
/// sampled, [`stream`]) or any mesh, picture or page format of
/// [`super::formats::SURFACE_FORMATS`], by `format`; then reports what was written. `title`
/// captions pictures and the page; `net` (the input grid) is shown on the page; `mesh` says
/// how meshes are written.
pub fn write_sampled_surface(
    surface: &(impl Surface<3> + Sync),
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
    title: &str,
    net: Option<&Grid<Point3>>,
    mesh: &MeshOptions,
) -> Result<()> {
    check_samples(output, format, (nu, nv), true)?;
    if stream::streams(format) {
        // Checked as held (the same requests pass as before); written block by block.
        stream::write_surface_samples(surface, (nu, nv), format, output)?;
        report_samples(output, nu * nv);
        return Ok(());
    }
    let drawing = SurfaceDrawing {
        title,
        net,
        mesh: *mesh,
    };
    karkas_io::export::surface::write_sampled_surface(surface, (nu, nv), format, output, &drawing)?;
    report_samples(output, nu * nv);
    Ok(())
}

/// Fails when writing `nu x nv` surface samples to `output` in `format` (with their
/// parameters when `parameters`) would take more than the memory cap.
fn check_samples(
    output: &Path,
    format: OutputFormat,
    (nu, nv): (usize, usize),
    parameters: bool,
) -> Result<()> {
    let name = shown(output);
    let request = format!(
        "{}: {nu} x {nv} samples as {}",
        name.display(),
        format.extension()
    );
    let held = if parameters {
        (nu as u128 + nv as u128) * 8
    } else {
        0
    };
    check_memory(&request, surface_output_bytes(format, nu, nv) + held)
}

/// How a command writes the surface it built, besides the format: the samples asked for, how
/// meshes are written and to which tolerance, whether open planar loops are capped, the CAD
/// unit and scale.
pub struct SurfaceWriting<'a> {
    /// `--samples NU,NV`, if given.
    pub samples: Option<(usize, usize)>,
    /// How meshes are written (`--flip-normals`).
    pub mesh: MeshOptions,
    /// `--mesh-tolerance`, if given: meshes are sampled where the surface bends.
    pub tolerance: Option<f64>,
    /// `--cap`: every open planar boundary loop closed (STEP, IGES and triangle meshes).
    pub cap: bool,
    /// `--units`, `--scale` of STEP and IGES.
    pub cad: &'a CadOptions,
}

impl<'a> SurfaceWriting<'a> {
    /// The options of a command writing `formats`, each checked against them (in this order:
    /// `--samples`, `--flip-normals`, `--mesh-tolerance`, `--units` and `--scale`, `--cap`).
    pub fn checked(
        formats: &[OutputFormat],
        (samples, mesh, tolerance): (&GridSamples, &MeshOutput, &MeshTolerance),
        cap: &CapOption,
        cad: &'a CadOptions,
    ) -> Result<Self> {
        samples.check()?;
        mesh.check_all(formats)?;
        tolerance.check(formats)?;
        cad.check(formats)?;
        cap.check(formats, tolerance.mesh_tolerance)?;
        Ok(Self {
            samples: samples.samples,
            mesh: mesh.options(false),
            tolerance: tolerance.mesh_tolerance,
            cap: cap.cap,
            cad,
        })
    }
}

/// Writes `surface` (from the input `what` names in errors) at `output` in `format`: its exact
/// B-spline form as STEP or IGES; a closed mesh with `--cap`; a mesh within `--mesh-tolerance`
/// when given; else its samples (`default` when none are given) as [`write_sampled_surface`]
/// writes them. `title` captions pictures and the page, which shows `net`.
pub fn write_any_surface(
    surface: &(impl Surface<3> + ToBSplineSurface<3> + Sync),
    format: OutputFormat,
    output: &Path,
    writing: &SurfaceWriting<'_>,
    (default, title, net): ((usize, usize), &str, Option<&Grid<Point3>>),
    what: impl std::fmt::Display,
) -> Result<()> {
    if format.is_cad() {
        return write_cad_surface(surface, format, output, writing.cad, what, writing.cap);
    }
    let samples = writing.samples.unwrap_or(default);
    if writing.cap {
        return write_capped_mesh(surface, samples, format, output, &writing.mesh, false);
    }
    if let Some(tolerance) = writing.tolerance {
        if OutputFormat::MESHES.contains(&format) {
            return write_mesh_within(surface, tolerance, format, output, title, &writing.mesh);
        }
    }
    write_sampled_surface(surface, samples, format, output, title, net, &writing.mesh)
}

/// Writes a surface built from `grid` (read from `input`, which errors name) as
/// [`write_any_surface`] does, `samples` by default [`default_surface_samples`] per grid line.
pub fn write_grid_surface(
    surface: &(impl Surface<3> + ToBSplineSurface<3> + Sync),
    format: OutputFormat,
    output: &Path,
    (input, grid): (&Path, &Grid<Point3>),
    writing: &SurfaceWriting<'_>,
    title: &str,
) -> Result<()> {
    let default = (
        default_surface_samples(grid.rows()),
        default_surface_samples(grid.cols()),
    );
    let drawn = (default, title, Some(grid));
    write_any_surface(surface, format, output, writing, drawn, input.display())
}

/// Writes the mesh of `surface` in `format` sampled within `tolerance` of it
/// ([`karkas::geometry::mesh_parameters`], within the memory cap's samples), and reports the
/// samples, the deviation reached, and a warning when the cap stopped the refinement first.
fn write_mesh_within(
    surface: &(impl Surface<3> + Sync),
    tolerance: f64,
    format: OutputFormat,
    output: &Path,
    title: &str,
    mesh: &MeshOptions,
) -> Result<()> {
    let budget = mesh_sample_budget(format);
    let found = karkas::geometry::mesh_parameters(surface, tolerance, budget);
    let (nu, nv) = (found.us.len(), found.vs.len());
    check_samples(output, format, (nu, nv), false)?;
    let drawing = SurfaceDrawing {
        title,
        net: None,
        mesh: *mesh,
    };
    write_surface_at(surface, (&found.us, &found.vs), format, output, &drawing)?;
    record("samples", nu * nv);
    record("mesh_deviation", found.max_deviation);
    if !found.met {
        note(format!(
            "karkas: warning: {}: --mesh-tolerance {tolerance} not met within the memory cap's \
             {budget} samples: largest deviation {:.3e}",
            shown(output).display(),
            found.max_deviation
        ));
    }
    note(format!(
        "karkas: wrote {} ({nu} x {nv} samples, {} triangles, largest deviation {:.3e} within \
         --mesh-tolerance {tolerance})",
        shown(output).display(),
        2 * (nu - 1) * (nv - 1),
        found.max_deviation
    ));
    Ok(())
}

/// Samples `surface` on a uniform `nu x nv` grid and writes it to `output` as a closed mesh
/// in `format` (OBJ, STL, PLY or glTF: `--cap`): its poles closed by fans, its seams welded,
/// every open boundary loop closed by the triangles of its planar polygon and the whole
/// turned outwards (`karkas_io::mesh::body_mesh`); reports the caps and the enclosed volume.
/// A loop that is not planar, or no open loop, is an error naming `--cap`. `close_v` closes
/// the `v` direction first by the strip from the last sample column back to the first.
pub fn write_capped_mesh(
    surface: &(impl Surface<3> + Sync),
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
    mesh: &MeshOptions,
    close_v: bool,
) -> Result<()> {
    check_samples(output, format, (nu, nv), true)?;
    let (_, _, samples) = sample_surface(surface, nu, nv);
    let grid = if close_v {
        // The first sample column again after the last: the strip between them closes the
        // direction (a blunt trailing edge's flat face), and the seam is welded.
        let rows = samples.chunks(nv);
        let closed = rows.flat_map(|row| row.iter().chain(&row[..1]).copied());
        Grid::from_row_major(nu, nv + 1, closed.collect())?
    } else {
        Grid::from_row_major(nu, nv, samples)?
    };
    let (body, figures) = body_mesh(&grid, true).map_err(|e| anyhow!("--cap: {e}"))?;
    write_mesh_as(format, output, &body, mesh)?;
    record("caps", figures.caps.len());
    let closed = match figures.volume {
        Some(volume) => {
            record("volume", volume);
            format!(", closed mesh, enclosed volume {volume:.9e}")
        }
        None => String::new(),
    };
    note(format!(
        "karkas: wrote {} ({} triangles, {} planar cap{}{closed})",
        shown(output).display(),
        body.triangles.len(),
        figures.caps.len(),
        if figures.caps.len() == 1 { "" } else { "s" }
    ));
    Ok(())
}

/// Writes the sampled surface `samples` (row-major, `u` outer) at `output` in `format`, which
/// is any of [`super::formats::SURFACE_FORMATS`] but CSV. `title` captions pictures and the
/// page; `net` (the input grid or control net) is shown on the page; `mesh` says how meshes
/// are written.
pub fn write_surface(
    output: &Path,
    format: OutputFormat,
    samples: &Grid<Point3>,
    title: &str,
    net: Option<&Grid<Point3>>,
    mesh: &MeshOptions,
) -> Result<()> {
    let drawing = SurfaceDrawing {
        title,
        net,
        mesh: *mesh,
    };
    Ok(karkas_io::export::surface::write_surface(
        output, format, samples, &drawing,
    )?)
}
