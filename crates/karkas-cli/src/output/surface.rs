//! A sampled surface in any format: the `u,v,x,y,z` CSV, meshes (`.obj .stl .ply .vtk .vts
//! .glb`), pictures (`.svg .png`: the shaded surface with isoparametric lines, hidden parts
//! removed) and the 3-D viewer page (`.html`).

use super::cad::write_cad_surface;
use super::memory::{check_memory, surface_output_bytes};
use super::samples::{default_surface_samples, report_samples, sample_surface};
use super::target::shown;
use anyhow::{bail, Result};
use karkas::bspline::ToBSplineSurface;
use karkas::{Grid, Point3, Surface};
use karkas_io::mesh::{write_surface_mesh_as, MeshOptions};
use karkas_io::obj::write_surface_obj;
use karkas_io::scene::{write_scene_png, write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::viewer::{write_viewer_html, ViewerScene, ViewerSurface};
use karkas_io::write::write_surface_csv;
use karkas_io::OutputFormat;
use std::path::Path;

/// How many isoparametric lines per direction the pictures and the page draw (at most).
const ISOLINES: usize = 11;

/// The default view of the surface pictures (azimuth, elevation in degrees).
pub const DEFAULT_VIEW: View = View {
    azimuth: 45.0,
    elevation: 30.0,
};

/// Samples `surface` on a uniform `nu x nv` grid over its whole domain and writes the samples
/// to `output` as a `u,v,x,y,z` CSV or any mesh, picture or page format of
/// [`super::formats::SURFACE_FORMATS`], by `format`; then reports what was written. `title`
/// captions pictures and the page; `net` (the input grid) is shown on the page; `mesh` says
/// how meshes are written.
pub fn write_sampled_surface(
    surface: &impl Surface<3>,
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
    let (us, vs, mut samples) = sample_surface(surface, nu, nv);
    match format {
        OutputFormat::Obj => {
            if mesh.flip_normals && nv > 0 {
                // Turned over in place: each row backwards, as `flip_orientation` does.
                samples.chunks_mut(nv).for_each(<[Point3]>::reverse);
            }
            write_surface_obj(output, nu, nv, &samples)?
        }
        OutputFormat::Csv => write_surface_csv(output, &us, &vs, &samples)?,
        _ => {
            let grid = Grid::from_row_major(nu, nv, samples)?;
            write_surface(output, format, &grid, title, net, mesh)?;
        }
    }
    report_samples(output, nu * nv);
    Ok(())
}

/// Writes a surface built from `grid` (read from `input`, which errors name) in the format of
/// `output`: its exact B-spline form as STEP or IGES, else `samples` (default
/// [`default_surface_samples`] per grid line) as [`write_sampled_surface`] writes them.
pub fn write_grid_surface(
    surface: &(impl Surface<3> + ToBSplineSurface<3>),
    format: OutputFormat,
    output: &Path,
    (input, grid): (&Path, &Grid<Point3>),
    samples: Option<(usize, usize)>,
    title: &str,
    mesh: &MeshOptions,
) -> Result<()> {
    if format.is_cad() {
        return write_cad_surface(surface, format, output, input.display());
    }
    let samples = samples.unwrap_or((
        default_surface_samples(grid.rows()),
        default_surface_samples(grid.cols()),
    ));
    write_sampled_surface(surface, samples, format, output, title, Some(grid), mesh)
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
    match format {
        OutputFormat::Svg | OutputFormat::Png => {
            let lines = isoparametric_lines(samples);
            let curves = [SceneCurves {
                label: "isoparametric lines",
                lines: &lines,
                rgb: (40, 70, 140),
                width: 1.0,
            }];
            let scene = Scene {
                title,
                mesh: SceneMesh {
                    rows: samples.rows(),
                    cols: samples.cols(),
                    points: samples.as_slice(),
                },
                curves: &curves,
                view: DEFAULT_VIEW,
            };
            if format == OutputFormat::Png {
                write_scene_png(output, &scene)?;
            } else {
                write_scene_svg(output, &scene)?;
            }
        }
        OutputFormat::Html => {
            let scene = ViewerScene {
                title: title.to_owned(),
                surfaces: vec![ViewerSurface {
                    name: title.to_owned(),
                    samples: samples.clone(),
                    control_net: net.cloned(),
                    isolines: isoparametric_lines(samples),
                }],
                ..ViewerScene::default()
            };
            write_viewer_html(output, &scene)?;
        }
        OutputFormat::Csv => bail!("internal: CSV is written by the command"),
        _ => write_surface_mesh_as(format, output, samples, mesh)?,
    }
    Ok(())
}

/// Up to [`ISOLINES`] evenly spread sample rows (lines of constant `u`) and as many columns
/// (constant `v`) of `samples`, ends included.
pub fn isoparametric_lines(samples: &Grid<Point3>) -> Vec<Vec<Point3>> {
    let (nu, nv) = (samples.rows(), samples.cols());
    let picks = |n: usize| -> Vec<usize> {
        if n == 0 {
            return Vec::new();
        }
        let k = ISOLINES.min(n);
        let mut v: Vec<usize> = (0..k)
            .map(|i| if k == 1 { 0 } else { i * (n - 1) / (k - 1) })
            .collect();
        v.dedup();
        v
    };
    let rows = picks(nu).into_iter().map(|i| samples.row(i).to_vec());
    let cols = picks(nv)
        .into_iter()
        .map(|j| (0..nu).map(|i| *samples.get(i, j)).collect());
    rows.chain(cols).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn isolines_are_spread_with_ends() {
        let g = Grid::from_fn(21, 3, |a, b| Point3::new([a as f64, b as f64, 0.0]));
        let lines = isoparametric_lines(&g);
        assert_eq!(lines.len(), 11 + 3);
        assert_eq!(lines[0][0][0], 0.0);
        assert_eq!(lines[10][0][0], 20.0);
        assert_eq!(lines[11].len(), 21);
    }
}
