//! Meshes in every format through the one entry that chooses the format by extension.

use karkas::{Grid, Point3};
use karkas_io::mesh::{glb, obj, ply, stl, vtk};
use karkas_io::mesh::{read_mesh, write_mesh, MeshOptions, TriangleMesh};
use karkas_io::IoError;

use crate::util::scratch;

/// Every format by its extension, the same bytes as its own writer; round trips of the
/// readable ones; the refused extension and the refused general mesh for `.vts`.
#[test]
fn extension_chooses_the_writer() {
    let (dir, _) = scratch("");
    let grid = Grid::from_fn(3, 4, |a, b| {
        Point3::new([a as f64, b as f64 * 0.5, (a * b) as f64 * 0.25])
    });
    let mesh = TriangleMesh::from_grid(&grid).unwrap();
    let file = |name: &str| dir.path().join(name);
    for ascii in [false, true] {
        let options = MeshOptions {
            ascii,
            ..MeshOptions::default()
        };
        for ext in ["obj", "stl", "ply", "vtk", "vts", "glb"] {
            let path = file(&format!("m.{ext}"));
            write_mesh(&path, &mesh, &options).unwrap();
            let mut own = Vec::new();
            match ext {
                "obj" => obj::render_mesh_obj(&mesh, &mut own).unwrap(),
                "stl" if ascii => stl::render_mesh_stl_ascii(&mesh, &mut own).unwrap(),
                "ply" => {
                    let encoding = if ascii {
                        ply::PlyEncoding::Ascii
                    } else {
                        ply::PlyEncoding::BinaryLittleEndian
                    };
                    ply::render_mesh_ply(&mesh, encoding, &mut own).unwrap()
                }
                "vtk" => vtk::render_mesh_vtk(&mesh, &mut own).unwrap(),
                "vts" => vtk::render_mesh_vts(&mesh, &mut own).unwrap(),
                "glb" => glb::render_mesh_glb(&mesh, &mut own).unwrap(),
                _ => {
                    stl::write_surface_stl(&file("own.stl"), 3, 4, grid.as_slice()).unwrap();
                    own = std::fs::read(file("own.stl")).unwrap();
                }
            }
            assert_eq!(std::fs::read(&path).unwrap(), own, "{ext}, ascii {ascii}");
            if matches!(ext, "obj" | "stl" | "ply") {
                let back = read_mesh(&path).unwrap();
                assert_eq!(back.triangles.len(), mesh.triangles.len());
            }
        }
    }
    let e = write_mesh(&file("m.csv"), &mesh, &MeshOptions::default()).unwrap_err();
    assert!(e
        .to_string()
        .ends_with("unknown output extension (use one of: .obj, .stl, .ply, .vtk, .vts, .glb)"));
    let general = TriangleMesh { grid: None, ..mesh };
    let e = write_mesh(&file("g.vts"), &general, &MeshOptions::default()).unwrap_err();
    assert!(matches!(e, IoError::InvalidMesh { .. }), "{e:?}");
    assert!(!file("g.vts").exists());
}
