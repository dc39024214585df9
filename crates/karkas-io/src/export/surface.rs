//! A sampled surface or a grid of points in any format: the CSV (`u,v,x,y,z` samples, or
//! `i,j,x,y,z` for a grid), meshes (`.obj .stl .ply .vtk .vts .glb`), pictures (`.svg .png`:
//! the shaded surface with isoparametric lines, hidden parts removed) and the 3-D viewer page
//! (`.html`).

use super::formats::SURFACE_FORMATS;
use super::samples::sample_surface;
use crate::mesh::closed::GridPoles;
use crate::mesh::triangulate::GridSeams;
use crate::mesh::{write_surface_mesh_as, MeshOptions};
use crate::obj::write_surface_obj;
use crate::scene::{
    render_scene_svg, write_scene_png, write_scene_svg, Scene, SceneCurves, SceneMesh, View,
};
use crate::viewer::{render_viewer_html, write_viewer_html, ViewerScene, ViewerSurface};
use crate::write::{write_grid_csv, write_surface_csv};
use crate::{IoError, OutputFormat};
use karkas::{Grid, Point3, Surface};
use std::path::Path;

/// How many isoparametric lines per direction the pictures and the page draw (at most).
pub const ISOLINES: usize = 11;

/// The default view of the surface pictures (azimuth, elevation in degrees).
pub const DEFAULT_VIEW: View = View {
    azimuth: 45.0,
    elevation: 30.0,
};

/// What a picture or page of a surface shows besides it: the title, the input grid or control
/// net (on the page), and how meshes are written.
#[derive(Debug, Clone, Copy)]
pub struct SurfaceDrawing<'a> {
    /// The caption of pictures and the page.
    pub title: &'a str,
    /// The input grid or control net, shown on the page.
    pub net: Option<&'a Grid<Point3>>,
    /// How meshes are written (ASCII STL and PLY, turned over).
    pub mesh: MeshOptions,
}

/// Samples `surface` on a uniform `nu x nv` grid over its whole domain and writes the samples
/// to `output` in `format`, one of [`SURFACE_FORMATS`]: the `u,v,x,y,z` CSV, or as
/// [`write_surface`] writes a grid.
pub fn write_sampled_surface(
    surface: &impl Surface<3>,
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
    drawing: &SurfaceDrawing<'_>,
) -> Result<(), IoError> {
    let format = format.allowed_for(output, &SURFACE_FORMATS)?;
    let (us, vs, mut samples) = sample_surface(surface, nu, nv);
    match format {
        // A body (poles or a closed direction) goes through the general mesh writer, which
        // closes its poles with fans and turns it outwards (`mesh/closed.rs`).
        OutputFormat::Obj if !is_body(nu, nv, &samples) => {
            if drawing.mesh.flip_normals && nv > 0 {
                // Turned over in place: each row backwards, as `flip_orientation` does.
                samples.chunks_mut(nv).for_each(<[Point3]>::reverse);
            }
            write_surface_obj(output, nu, nv, &samples)
        }
        OutputFormat::Csv => write_surface_csv(output, &us, &vs, &samples),
        _ => {
            let grid = Grid::from_row_major(nu, nv, samples).map_err(|source| {
                IoError::Geometry(Box::new(crate::GeometryError {
                    path: output.to_path_buf(),
                    source,
                }))
            })?;
            write_surface(output, format, &grid, drawing)
        }
    }
}

/// True when the `nu x nv` samples `samples` have a pole line or a closed direction.
fn is_body(nu: usize, nv: usize, samples: &[Point3]) -> bool {
    let seams = GridSeams::detect(nu, nv, samples);
    seams.closed_u || seams.closed_v || GridPoles::detect(nu, nv, samples).any()
}

/// Samples `surface` at the parameters `us` x `vs` (e.g. those of
/// [`karkas::geometry::mesh_parameters()`], for a mesh within a tolerance) and writes the
/// samples at `output` in `format` as [`write_surface`] writes a grid.
pub fn write_surface_at(
    surface: &impl Surface<3>,
    (us, vs): (&[f64], &[f64]),
    format: OutputFormat,
    output: &Path,
    drawing: &SurfaceDrawing<'_>,
) -> Result<(), IoError> {
    let mut points = vec![Point3::ZERO; us.len() * vs.len()];
    surface.eval_grid_into(us, vs, &mut points);
    let grid = Grid::from_row_major(us.len(), vs.len(), points).map_err(|source| {
        IoError::Geometry(Box::new(crate::GeometryError {
            path: output.to_path_buf(),
            source,
        }))
    })?;
    write_surface(output, format, &grid, drawing)
}

/// Writes the grid of points `samples` (row-major, `u` outer) at `output` in `format`, one of
/// [`SURFACE_FORMATS`]: the `i,j,x,y,z` CSV, a mesh of its quads (split into triangles), a
/// picture of the shaded surface with its isoparametric lines, or the viewer page.
pub fn write_surface(
    output: &Path,
    format: OutputFormat,
    samples: &Grid<Point3>,
    drawing: &SurfaceDrawing<'_>,
) -> Result<(), IoError> {
    match format.allowed_for(output, &SURFACE_FORMATS)? {
        OutputFormat::Svg | OutputFormat::Png => {
            let lines = isoparametric_lines(samples);
            let curves = surface_curves(&lines);
            let scene = surface_scene(drawing.title, samples, &curves);
            if format == OutputFormat::Png {
                write_scene_png(output, &scene)
            } else {
                write_scene_svg(output, &scene)
            }
        }
        OutputFormat::Html => write_viewer_html(output, &viewer_scene(samples, drawing)),
        OutputFormat::Csv => write_grid_csv(output, samples),
        format => write_surface_mesh_as(format, output, samples, &drawing.mesh),
    }
}

/// The viewer page [`write_surface`] writes as `.html`, in memory.
pub fn render_surface_html(samples: &Grid<Point3>, drawing: &SurfaceDrawing<'_>) -> String {
    render_viewer_html(&viewer_scene(samples, drawing))
}

/// The picture [`write_surface`] writes as `.svg`, in memory.
pub fn render_surface_svg(samples: &Grid<Point3>, title: &str) -> String {
    let lines = isoparametric_lines(samples);
    let curves = surface_curves(&lines);
    render_scene_svg(&surface_scene(title, samples, &curves))
}

/// The isoparametric lines of a picture, in one colour.
fn surface_curves(lines: &[Vec<Point3>]) -> [SceneCurves<'_>; 1] {
    [SceneCurves {
        label: "isoparametric lines",
        lines,
        rgb: (40, 70, 140),
        width: 1.0,
    }]
}

/// The picture's scene: the shaded grid and its lines, in the default view.
fn surface_scene<'a>(
    title: &'a str,
    samples: &'a Grid<Point3>,
    curves: &'a [SceneCurves<'a>],
) -> Scene<'a> {
    Scene {
        title,
        mesh: SceneMesh {
            rows: samples.rows(),
            cols: samples.cols(),
            points: samples.as_slice(),
        },
        curves,
        view: DEFAULT_VIEW,
    }
}

/// The page's scene: the surface, its net and its isoparametric lines.
fn viewer_scene(samples: &Grid<Point3>, drawing: &SurfaceDrawing<'_>) -> ViewerScene {
    ViewerScene {
        title: drawing.title.to_owned(),
        surfaces: vec![ViewerSurface {
            name: drawing.title.to_owned(),
            samples: samples.clone(),
            control_net: drawing.net.cloned(),
            isolines: isoparametric_lines(samples),
        }],
        ..ViewerScene::default()
    }
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
