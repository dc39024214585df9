//! A self-contained HTML page that shows surfaces and curves in 3-D: shaded surfaces with
//! their normals, curves as polylines, input points, control nets and isolines, each group
//! switched on and off by a checkbox; orbit (left drag), zoom (wheel) and pan (right drag).
//!
//! The page needs no network and no server: three.js (r170, [`THREE_VERSION`], MIT, vendored in
//! `vendor/three/` with its license) and its `OrbitControls` are compiled into this crate with
//! `include_str!` and placed in the page's import map as `data:` URLs, and the scene is embedded
//! as JSON with the bulk arrays as base64 little-endian `Float32` / `Uint32` (about 16 bytes per
//! surface sample, 12 per curve point). Coordinates are shifted so that the scene's bounding box
//! is centred at the origin before they are rounded to `f32` (WebGL's precision), so a model
//! far from the origin loses no detail; the page shows the shift in its footer.
//!
//! Surfaces are the triangle meshes of their sample grids ([`TriangleMesh::from_grid`]: one
//! normal per sample, smooth shading); general triangle meshes can be added as
//! [`ViewerMesh`]es. The z axis points up.

use std::fmt::Write as _;
use std::path::Path;

use base64::Engine as _;
use karkas::{Grid, Point3};
use serde_json::{json, Value};

use crate::error::IoError;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::picture::budget::check_output_memory;
use crate::picture::scene::escape;
use crate::write::write_atomic;

/// The vendored three.js release (npm package version).
pub const THREE_VERSION: &str = "0.170.0";

const THREE_JS: &str = include_str!("../vendor/three/three.module.min.js");
const ORBIT_CONTROLS_JS: &str = include_str!("../vendor/three/OrbitControls.js");
const PAGE_SCRIPT: &str = include_str!("viewer.js");

/// What the page shows.
#[derive(Clone, Debug, Default)]
pub struct ViewerScene {
    /// The page title and heading.
    pub title: String,
    /// Sampled surfaces.
    pub surfaces: Vec<ViewerSurface>,
    /// Curves, drawn as polylines (a closed curve repeats its first point at the end).
    pub curves: Vec<ViewerCurve>,
    /// Input points (shown as dots, toggle "input points").
    pub points: Vec<Point3>,
    /// General triangle meshes (e.g. read from a mesh file), shown like surfaces.
    pub meshes: Vec<ViewerMesh>,
}

/// A sampled surface with what belongs to it.
#[derive(Clone, Debug)]
pub struct ViewerSurface {
    /// Its name (shown in the panel).
    pub name: String,
    /// The samples, row-major, `u` outer (as
    /// [`Surface::sample_grid_into`](karkas::Surface::sample_grid_into) writes them).
    pub samples: Grid<Point3>,
    /// The control net or input grid, drawn as the polylines of its rows and columns
    /// (toggle "control net").
    pub control_net: Option<Grid<Point3>>,
    /// Isolines or sections on the surface (toggle "isolines").
    pub isolines: Vec<Vec<Point3>>,
}

/// A curve.
#[derive(Clone, Debug)]
pub struct ViewerCurve {
    /// Its name (shown in the panel).
    pub name: String,
    /// Its samples, in order.
    pub points: Vec<Point3>,
}

/// A triangle mesh shown as a surface.
#[derive(Clone, Debug)]
pub struct ViewerMesh {
    /// Its name (shown in the panel).
    pub name: String,
    /// The mesh (normals averaged over the faces when it has none).
    pub mesh: TriangleMesh,
}

/// Bytes per surface sample while a page is built: the triangle mesh of the grid (position,
/// normal, two triangles), its `f32`/`u32` arrays, their base64 text and the copies of the
/// scene's JSON and of the page (measured on the release build, rounded up).
pub const PAGE_SURFACE_SAMPLE: u128 = 480;
/// Bytes per vertex of a mesh shown on a page (its normal computed, arrays, text).
pub const PAGE_MESH_VERTEX: u128 = 300;
/// Bytes per triangle of a mesh shown on a page.
pub const PAGE_MESH_TRIANGLE: u128 = 150;
/// Bytes per point of a curve, an isoline, a control net or the input points on a page.
pub const PAGE_POINT: u128 = 150;

/// What building and writing the page of `scene` takes in memory, the scene included: the
/// bundled scripts (three times: text, base64, page) and [`PAGE_SURFACE_SAMPLE`] and the
/// like per item shown.
pub fn page_bytes(scene: &ViewerScene) -> u128 {
    let scripts = page_scripts_bytes();
    let n = |k: usize| k as u128;
    let mut bytes = scripts + n(scene.points.len()) * PAGE_POINT;
    for s in &scene.surfaces {
        let net = s.control_net.as_ref().map_or(0, |g| g.rows() * g.cols());
        let isolines: usize = s.isolines.iter().map(Vec::len).sum();
        bytes += n(s.samples.rows() * s.samples.cols()) * PAGE_SURFACE_SAMPLE
            + n(2 * net + isolines) * PAGE_POINT;
    }
    for c in &scene.curves {
        bytes += n(c.points.len()) * PAGE_POINT;
    }
    for m in &scene.meshes {
        bytes += n(m.mesh.positions.len()) * PAGE_MESH_VERTEX
            + n(m.mesh.triangles.len()) * PAGE_MESH_TRIANGLE;
    }
    bytes
}

/// What the scripts bundled into every page take while it is built (text, base64, page).
pub fn page_scripts_bytes() -> u128 {
    3 * (THREE_JS.len() + ORBIT_CONTROLS_JS.len() + PAGE_SCRIPT.len()) as u128
}

/// Writes the viewer page of `scene` at `path`, atomically; refuses (before building it) a
/// page that would take more memory than the cap ([`page_bytes`]).
pub fn write_viewer_html(path: &Path, scene: &ViewerScene) -> Result<(), IoError> {
    check_output_memory(path, "the viewer page", page_bytes(scene))?;
    let page = render_viewer_html(scene);
    write_atomic(path, |out| out.write_all(page.as_bytes()))
}

/// The viewer page of `scene` as one HTML document.
pub fn render_viewer_html(scene: &ViewerScene) -> String {
    let centre = scene_centre(scene);
    let data = scene_json(scene, centre).to_string().replace("</", "<\\/");
    let b64 = |s: &str| base64::engine::general_purpose::STANDARD.encode(s.as_bytes());
    let title = escape(if scene.title.is_empty() {
        "karkas"
    } else {
        &scene.title
    });
    let mut page = String::with_capacity(THREE_JS.len() * 4 / 3 + data.len() + 16_384);
    let _ = write!(
        page,
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="karkas, three.js {THREE_VERSION}">
<title>{title}</title>
<style>
html, body {{ margin: 0; height: 100%; overflow: hidden; background: #ffffff; font: 14px sans-serif; color: #222; }}
#view {{ position: absolute; inset: 0; }}
#panel {{ position: absolute; top: 10px; left: 10px; background: rgba(255,255,255,0.9); border: 1px solid #ccc; border-radius: 4px; padding: 8px 12px; max-width: 40%; }}
#panel h1 {{ font-size: 16px; margin: 0 0 6px 0; }}
#panel label {{ display: block; margin: 2px 0; cursor: pointer; }}
#panel .names {{ color: #555; font-size: 12px; margin-top: 6px; }}
#foot {{ position: absolute; bottom: 6px; left: 10px; font-size: 12px; color: #666; }}
</style>
<link rel="icon" href="data:,">
<script type="importmap">{{"imports": {{"three": "data:text/javascript;base64,{three}", "three/addons/controls/OrbitControls.js": "data:text/javascript;base64,{orbit}"}}}}</script>
<script type="application/json" id="karkas-scene">{data}</script>
</head>
<body>
<div id="view"></div>
<div id="panel"><h1>{title}</h1><div id="toggles"></div><div class="names" id="names"></div></div>
<div id="foot">drag: orbit &middot; wheel: zoom &middot; right drag: pan &middot; <span id="shift"></span></div>
<script type="module">
{script}
</script>
</body>
</html>
"#,
        three = b64(THREE_JS),
        orbit = b64(ORBIT_CONTROLS_JS),
        script = PAGE_SCRIPT,
    );
    page
}

/// The centre of the bounding box of everything in `scene` (zero when it is empty).
fn scene_centre(scene: &ViewerScene) -> Point3 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    let surfaces = scene.surfaces.iter().flat_map(|s| {
        s.samples
            .as_slice()
            .iter()
            .chain(s.control_net.iter().flat_map(|g| g.as_slice()))
            .chain(s.isolines.iter().flatten())
    });
    let all = surfaces
        .chain(scene.curves.iter().flat_map(|c| &c.points))
        .chain(&scene.points)
        .chain(scene.meshes.iter().flat_map(|m| &m.mesh.positions));
    for p in all.filter(|p| p.is_finite()) {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    if lo[0] > hi[0] {
        return Point3::ZERO;
    }
    Point3::new([0, 1, 2].map(|c| 0.5 * (lo[c] + hi[c])))
}

/// The scene as the page script reads it.
fn scene_json(scene: &ViewerScene, centre: Point3) -> Value {
    let mut surfaces: Vec<Value> = Vec::new();
    for s in &scene.surfaces {
        let mesh = TriangleMesh::from_grid(&s.samples).unwrap_or_default();
        let net = s.control_net.as_ref().map(grid_lines).unwrap_or_default();
        surfaces.push(json!({
            "name": s.name,
            "mesh": mesh_json(&mesh, centre),
            "net": lines_json(&net, centre),
            "isolines": lines_json(&s.isolines, centre),
        }));
    }
    for m in &scene.meshes {
        let mesh = if m.mesh.validate().is_ok() {
            m.mesh.clone()
        } else {
            TriangleMesh::default()
        };
        surfaces.push(json!({
            "name": m.name,
            "mesh": mesh_json(&mesh, centre),
            "net": [],
            "isolines": [],
        }));
    }
    let curves: Vec<Value> = scene
        .curves
        .iter()
        .map(|c| json!({"name": c.name, "points": floats(&c.points, centre)}))
        .collect();
    json!({
        "title": scene.title,
        "centre": [centre[0], centre[1], centre[2]],
        "surfaces": surfaces,
        "curves": curves,
        "points": floats(&scene.points, centre),
    })
}

/// The polylines of the rows and the columns of `grid`.
fn grid_lines(grid: &Grid<Point3>) -> Vec<Vec<Point3>> {
    let rows = (0..grid.rows()).map(|i| grid.row(i).to_vec());
    let cols = (0..grid.cols()).map(|j| (0..grid.rows()).map(|i| *grid.get(i, j)).collect());
    rows.chain(cols).collect()
}

/// A mesh as base64 arrays: positions and normals `Float32`, indices `Uint32`.
fn mesh_json(mesh: &TriangleMesh, centre: Point3) -> Value {
    let normals = mesh.vertex_normals();
    let mut indices = Vec::with_capacity(12 * mesh.triangles.len());
    for t in &mesh.triangles {
        for k in t {
            indices.extend_from_slice(&k.to_le_bytes());
        }
    }
    json!({
        "positions": floats(&mesh.positions, centre),
        "normals": floats(&normals, Point3::ZERO),
        "indices": base64::engine::general_purpose::STANDARD.encode(indices),
    })
}

/// Polylines as base64 `Float32` arrays (a non-finite point is left out).
fn lines_json(lines: &[Vec<Point3>], centre: Point3) -> Value {
    Value::Array(
        lines
            .iter()
            .filter(|l| l.len() >= 2)
            .map(|l| floats(l, centre))
            .collect(),
    )
}

/// `points - centre` as base64 little-endian `Float32` triples; non-finite points left out.
fn floats(points: &[Point3], centre: Point3) -> Value {
    let mut bytes = Vec::with_capacity(12 * points.len());
    for p in points.iter().filter(|p| p.is_finite()) {
        for c in 0..3 {
            bytes.extend_from_slice(&((p[c] - centre[c]) as f32).to_le_bytes());
        }
    }
    Value::String(base64::engine::general_purpose::STANDARD.encode(bytes))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode_f32(value: &Value) -> Vec<f32> {
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(value.as_str().unwrap())
            .unwrap();
        bytes
            .chunks(4)
            .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
            .collect()
    }

    fn scene() -> ViewerScene {
        let samples = Grid::from_fn(3, 4, |a, b| Point3::new([a as f64, b as f64, 10.0]));
        ViewerScene {
            title: "a </script> & <b>".into(),
            surfaces: vec![ViewerSurface {
                name: "plane </script>".into(),
                samples: samples.clone(),
                control_net: Some(samples),
                isolines: vec![vec![
                    Point3::new([0.0, 1.0, 10.0]),
                    Point3::new([2.0, 1.0, 10.0]),
                ]],
            }],
            curves: vec![ViewerCurve {
                name: "c".into(),
                points: vec![Point3::ZERO, Point3::new([2.0, 3.0, 20.0])],
            }],
            points: vec![Point3::new([1.0, 1.0, 1.0])],
            meshes: Vec::new(),
        }
    }

    #[test]
    fn page_is_self_contained_and_escaped() {
        let page = render_viewer_html(&scene());
        assert!(page.starts_with("<!DOCTYPE html>"));
        // No fetches: every script is inline, the modules are data: URLs.
        assert!(!page.contains("src=\"http") && !page.contains("href=\"http"));
        assert!(!page.contains("<script src"));
        assert!(page.contains(r#""three": "data:text/javascript;base64,"#));
        // The title is escaped in HTML, and no "</script>" leaks out of the JSON.
        assert!(page.contains("<title>a &lt;/script&gt; &amp; &lt;b&gt;</title>"));
        assert_eq!(page.matches("</script>").count(), 3);
        let json_text = page
            .split(r#"<script type="application/json" id="karkas-scene">"#)
            .nth(1)
            .unwrap()
            .split("</script>")
            .next()
            .unwrap();
        let data: Value = serde_json::from_str(json_text).unwrap();
        assert_eq!(data["surfaces"][0]["name"], "plane </script>");
    }

    #[test]
    fn data_is_centred_and_complete() {
        let data = scene_json(&scene(), scene_centre(&scene()));
        // Bounding box x 0..2, y 0..3, z 0..20: centre (1, 1.5, 10).
        assert_eq!(data["centre"], json!([1.0, 1.5, 10.0]));
        let s = &data["surfaces"][0];
        let positions = decode_f32(&s["mesh"]["positions"]);
        assert_eq!(positions.len(), 3 * 12);
        assert_eq!(&positions[..3], &[-1.0, -1.5, 0.0]);
        let indices = base64::engine::general_purpose::STANDARD
            .decode(s["mesh"]["indices"].as_str().unwrap())
            .unwrap();
        assert_eq!(indices.len(), 4 * 3 * 2 * 2 * 3);
        // Control net: 3 rows and 4 columns.
        assert_eq!(s["net"].as_array().unwrap().len(), 7);
        assert_eq!(decode_f32(&s["net"][3]).len(), 3 * 3);
        assert_eq!(s["isolines"].as_array().unwrap().len(), 1);
        assert_eq!(decode_f32(&data["curves"][0]["points"]).len(), 6);
        assert_eq!(decode_f32(&data["points"]), vec![0.0, -0.5, -9.0]);
    }

    #[test]
    fn vendored_library_is_the_pinned_release() {
        assert!(THREE_JS.contains(r#"const t="170""#));
        assert!(ORBIT_CONTROLS_JS.contains("class OrbitControls"));
        assert!(include_str!("../vendor/three/LICENSE").contains("MIT License"));
    }
}
