//! The surfaces of the workbench: the LL surface of a grid (docs/methods.md §1.4), the
//! bicubic surface of a grid with not-a-knot ends (§5) and the Coons and Gordon surfaces of a
//! curve network (§2), built as the command line builds them, sampled for the 3-D view, cut by
//! planes, and exported by the command line's own writers.

use karkas::bspline::ToBSplineSurface;
use karkas::coons::{
    CoonsKind, CurveFit, PointNetwork, CROSSING_TOLERANCE, POINT_NETWORK_TOLERANCE,
};
use karkas::ll::LlSurface;
use karkas::param::{BicubicSurface, GridParameterization};
use karkas::section::{plane_section, Plane, SectionOptions};
use karkas::{Grid, Point3, Surface};
use karkas_io::export::cad::cad_surface_text;
use karkas_io::export::samples::{default_surface_samples, sample_surface};
use karkas_io::mesh::TriangleMesh;
use karkas_io::network::CurveFamily;
use karkas_io::obj::render_surface_obj;
use karkas_io::stl::render_mesh_stl_ascii;
use karkas_io::OutputFormat;

/// A built surface, whatever its kind.
pub trait BuiltSurface {
    /// `nu x nv` samples uniform over the domain, row after row (`v` fastest), 3 numbers each.
    fn samples(&self, nu: usize, nv: usize) -> Vec<f64>;
    /// The section by the plane `normal . x = offset`: polylines of 3 numbers a point, each
    /// ended by a NaN triple.
    fn section(&self, normal: [f64; 3], offset: f64) -> Result<Vec<f64>, String>;
    /// The command line's STEP or IGES file of this surface, to a file of stem `name`.
    fn cad(&self, format: OutputFormat, name: &str, input: &str) -> Result<String, String>;
    /// The command line's OBJ (`obj`) or ASCII STL (`stl`) mesh of the surface at its
    /// default samples.
    fn mesh(&self, format: &str) -> Result<String, String>;
}

/// A surface and its default sample counts (as the command line's).
struct Built<S>(S, (usize, usize));

impl<S: Surface<3> + ToBSplineSurface<3>> BuiltSurface for Built<S> {
    fn samples(&self, nu: usize, nv: usize) -> Vec<f64> {
        let (du, dv) = (self.0.domain_u(), self.0.domain_v());
        let (nu, nv) = (nu.max(2), nv.max(2));
        let mut out = Vec::with_capacity(3 * nu * nv);
        for i in 0..nu {
            let u = du.start + du.length() * (i as f64 / (nu - 1) as f64);
            for j in 0..nv {
                let v = dv.start + dv.length() * (j as f64 / (nv - 1) as f64);
                out.extend(self.0.eval(u, v).0);
            }
        }
        out
    }

    fn section(&self, normal: [f64; 3], offset: f64) -> Result<Vec<f64>, String> {
        let plane = Plane::new(Point3::new(normal), offset).map_err(|e| e.to_string())?;
        let section = plane_section(&self.0, &plane, &SectionOptions::default())
            .map_err(|e| e.to_string())?;
        let mut out = Vec::new();
        for curve in &section.curves {
            for p in &curve.points {
                out.extend(p.0);
            }
            if curve.closed {
                if let Some(first) = curve.points.first() {
                    out.extend(first.0);
                }
            }
            out.extend([f64::NAN; 3]);
        }
        Ok(out)
    }

    fn cad(&self, format: OutputFormat, name: &str, input: &str) -> Result<String, String> {
        let bspline = self.0.to_bspline().map_err(|e| format!("{input}: {e}"))?;
        cad_surface_text(&bspline, format, name).map_err(|e| e.to_string())
    }

    fn mesh(&self, format: &str) -> Result<String, String> {
        let (nu, nv) = self.1;
        let (_, _, samples) = sample_surface(&self.0, nu, nv);
        let mut out = Vec::new();
        match format {
            "obj" => render_surface_obj(nu, nv, &samples, &mut out),
            "stl" => {
                let grid = Grid::from_row_major(nu, nv, samples).map_err(|e| e.to_string())?;
                let mesh = TriangleMesh::from_grid(&grid).map_err(|e| e.to_string())?;
                render_mesh_stl_ascii(&mesh, &mut out)
            }
            other => return Err(format!("a surface mesh is obj or stl, not '{other}'")),
        }
        .map_err(|e| e.to_string())?;
        Ok(String::from_utf8_lossy(&out).into_owned())
    }
}

/// The LL surface of order `order` (`interpolate`: through every point) or, for `order` 0,
/// the bicubic surface with chord-length parameters, of `grid` (read from `input`).
pub fn grid_surface(
    grid: &Grid<Point3>,
    method: &str,
    order: usize,
    input: &str,
) -> Result<Box<dyn BuiltSurface>, String> {
    let context = |e: karkas::Error| format!("{input}: {e}");
    let samples = (
        default_surface_samples(grid.rows()),
        default_surface_samples(grid.cols()),
    );
    Ok(match method {
        "ll" => Box::new(Built(
            LlSurface::new(grid, order, false, false).map_err(context)?,
            samples,
        )),
        "ll-interpolate" => Box::new(Built(
            LlSurface::interpolating(grid, order, false, false).map_err(context)?,
            samples,
        )),
        "bicubic" => {
            let param = GridParameterization::Chord {
                origin_row: 0,
                origin_col: 0,
            };
            Box::new(Built(
                BicubicSurface::new(grid, param, false, false).map_err(context)?,
                samples,
            ))
        }
        other => return Err(format!("unknown surface method '{other}'")),
    })
}

/// The surface of a loft, its default sample counts `samples` (along the span, along the
/// sections).
pub fn loft_surface(loft: karkas::loft::Loft, samples: (usize, usize)) -> Box<dyn BuiltSurface> {
    Box::new(Built(loft, samples))
}

/// The Gordon surface (`kind` `gordon`, or `bilinear` Coons) of the network of `u` curves
/// (lines `v = const`, in order of `v`) and `v` curves, each interpolated by a cubic spline.
pub fn network_surface(
    u: &CurveFamily,
    v: &CurveFamily,
    kind: &str,
    input: &str,
) -> Result<Box<dyn BuiltSurface>, String> {
    let context = |e: karkas::Error| format!("{input}: {e}");
    let kind = match kind {
        "bilinear" => CoonsKind::Bilinear,
        "gordon-spline" => CoonsKind::GordonSpline,
        _ => CoonsKind::Gordon,
    };
    let network = PointNetwork::new(
        &v.curves,
        &u.curves,
        CurveFit::CubicSpline,
        CROSSING_TOLERANCE,
    )
    .map_err(context)?;
    let surface = kind
        .build(network.network(), None, POINT_NETWORK_TOLERANCE)
        .map_err(context)?;
    let longest = |f: &CurveFamily| f.curves.iter().map(Vec::len).max().unwrap_or(0);
    let samples = (
        default_surface_samples(longest(u)),
        default_surface_samples(longest(v)),
    );
    Ok(Box::new(Built(surface, samples)))
}
