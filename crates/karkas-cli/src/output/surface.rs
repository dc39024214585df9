//! A sampled surface in any format: the `u,v,x,y,z` CSV, meshes (`.obj .stl .ply .vtk .vts
//! .glb`), pictures (`.svg .png`: the shaded surface with isoparametric lines, hidden parts
//! removed) and the 3-D viewer page (`.html`).

use super::cad::write_cad_surface;
use super::console::{note, record};
use super::memory::{check_memory, surface_output_bytes};
use super::samples::{default_surface_samples, report_samples};
use super::target::shown;
use anyhow::{anyhow, Result};
use karkas::bspline::ToBSplineSurface;
use karkas::{Grid, Point3, Surface};
use karkas_io::export::samples::sample_surface;
use karkas_io::export::stream;
use karkas_io::export::surface::SurfaceDrawing;
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
    check_memory(
        &format!(
            "{}: {nu} x {nv} samples as {}",
            shown(output).display(),
            format.extension()
        ),
        surface_output_bytes(format, nu, nv) + (nu as u128 + nv as u128) * 8,
    )?;
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

/// Writes a surface built from `grid` (read from `input`, which errors name) in the format of
/// `output`: its exact B-spline form as STEP or IGES, else `samples` (default
/// [`default_surface_samples`] per grid line) as [`write_sampled_surface`] writes them; `cap`
/// closes the open planar boundary loops (`--cap`).
pub fn write_grid_surface(
    surface: &(impl Surface<3> + ToBSplineSurface<3> + Sync),
    format: OutputFormat,
    output: &Path,
    (input, grid): (&Path, &Grid<Point3>),
    samples: Option<(usize, usize)>,
    title: &str,
    (mesh, cap): (&MeshOptions, bool),
) -> Result<()> {
    if format.is_cad() {
        return write_cad_surface(surface, format, output, input.display(), cap);
    }
    let samples = samples.unwrap_or((
        default_surface_samples(grid.rows()),
        default_surface_samples(grid.cols()),
    ));
    if cap {
        return write_capped_mesh(surface, samples, format, output, mesh);
    }
    write_sampled_surface(surface, samples, format, output, title, Some(grid), mesh)
}

/// Samples `surface` on a uniform `nu x nv` grid and writes it to `output` as a closed mesh
/// in `format` (OBJ, STL, PLY or glTF: `--cap`): its poles closed by fans, its seams welded,
/// every open boundary loop closed by the triangles of its planar polygon and the whole
/// turned outwards (`karkas_io::mesh::body_mesh`); reports the caps and the enclosed volume.
/// A loop that is not planar, or no open loop, is an error naming `--cap`.
pub fn write_capped_mesh(
    surface: &(impl Surface<3> + Sync),
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
    mesh: &MeshOptions,
) -> Result<()> {
    check_memory(
        &format!(
            "{}: {nu} x {nv} samples as {}",
            shown(output).display(),
            format.extension()
        ),
        surface_output_bytes(format, nu, nv) + (nu as u128 + nv as u128) * 8,
    )?;
    let (_, _, samples) = sample_surface(surface, nu, nv);
    let grid = Grid::from_row_major(nu, nv, samples)?;
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
