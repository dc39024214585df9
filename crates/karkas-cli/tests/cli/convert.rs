//! The CLI contract of `karkas convert IN OUT`: which pairs convert, what the outputs hold, and
//! exit code 2 with a clear message and no output for a pair that makes no sense.

use crate::common::{grid_csv, karkas, s, stderr, temp_dir, write};
use std::path::Path;

/// A 3 x 4 grid frame `i,j,x,y,z` on the plane z = i j / 10.
fn grid_file(dir: &Path) -> std::path::PathBuf {
    let text = grid_csv(3, 4, |i, j| [i as f64, j as f64, (i * j) as f64 / 10.0]);
    write(dir, "grid.csv", &text)
}

#[test]
fn grid_converts_to_every_mesh_format_with_the_right_counts() {
    let dir = temp_dir();
    let grid = grid_file(dir.path());
    for ext in [
        "obj", "stl", "ply", "vtk", "vts", "glb", "html", "svg", "png", "csv",
    ] {
        let out = dir.path().join(format!("m.{ext}"));
        let o = karkas(&["convert", s(&grid), s(&out)]);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
        assert!(std::fs::metadata(&out).unwrap().len() > 0, "{ext}");
    }
    let text = |name: &str| std::fs::read_to_string(dir.path().join(name)).unwrap();
    // 12 vertices, 2 * 2 * 3 = 12 triangles.
    let obj = text("m.obj");
    assert_eq!(obj.lines().filter(|l| l.starts_with("v ")).count(), 12);
    assert_eq!(obj.lines().filter(|l| l.starts_with("vn ")).count(), 12);
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 12);
    let ply = std::fs::read(dir.path().join("m.ply")).unwrap();
    let header = String::from_utf8_lossy(&ply[..300]);
    assert!(header.starts_with("ply\nformat binary_little_endian 1.0\n"));
    assert!(header.contains("element vertex 12\n") && header.contains("element face 12\n"));
    let vtk = text("m.vtk");
    assert!(vtk.contains("DATASET STRUCTURED_GRID\nDIMENSIONS 4 3 1\nPOINTS 12 double\n"));
    assert!(text("m.vts").contains("WholeExtent=\"0 3 0 2 0 0\""));
    let stl = std::fs::read(dir.path().join("m.stl")).unwrap();
    assert_eq!(stl.len(), 84 + 12 * 50);
    assert_eq!(u32::from_le_bytes(stl[80..84].try_into().unwrap()), 12);
    let glb = std::fs::read(dir.path().join("m.glb")).unwrap();
    assert_eq!(&glb[..4], b"glTF");
    assert_eq!(
        u32::from_le_bytes(glb[8..12].try_into().unwrap()) as usize,
        glb.len()
    );
    assert!(text("m.html").contains("<title>grid.csv</title>"));
    assert!(text("m.svg").starts_with("<svg"));
    assert_eq!(
        &std::fs::read(dir.path().join("m.png")).unwrap()[1..4],
        b"PNG"
    );
    // The grid CSV round-trips.
    assert_eq!(text("m.csv"), text("grid.csv"));
}

#[test]
fn meshes_convert_between_formats_and_ascii_is_an_option() {
    let dir = temp_dir();
    let grid = grid_file(dir.path());
    let obj = dir.path().join("a.obj");
    assert!(karkas(&["convert", s(&grid), s(&obj)]).status.success());
    let stl = dir.path().join("b.stl");
    let o = karkas(&["convert", "--ascii", s(&obj), s(&stl)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&stl).unwrap();
    assert!(text.starts_with("solid karkas\n"));
    assert_eq!(text.matches("facet normal").count(), 12);
    // STL back to PLY (ASCII): corners merged into the 12 grid points.
    let ply = dir.path().join("c.ply");
    let o = karkas(&["convert", "--ascii", s(&stl), s(&ply)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&ply).unwrap();
    assert!(text.contains("format ascii 1.0\n"));
    assert!(text.contains("element vertex 12\n") && text.contains("element face 12\n"));
    // PLY to VTK: a general mesh is an unstructured grid of triangles.
    let vtk = dir.path().join("d.vtk");
    assert!(karkas(&["convert", s(&ply), s(&vtk)]).status.success());
    let text = std::fs::read_to_string(&vtk).unwrap();
    assert!(text.contains("DATASET UNSTRUCTURED_GRID\n") && text.contains("CELLS 12 48\n"));
    // A mesh to the viewer page and to glTF.
    for ext in ["html", "glb"] {
        let out = dir.path().join(format!("e.{ext}"));
        assert!(karkas(&["convert", s(&ply), s(&out)]).status.success());
    }
}

#[test]
fn curves_convert_to_pictures_and_the_page() {
    let dir = temp_dir();
    let pts = write(dir.path(), "pts.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n");
    for ext in ["svg", "png", "html"] {
        let out = dir.path().join(format!("c.{ext}"));
        let o = karkas(&["convert", s(&pts), s(&out)]);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
    }
    // Sampled surface CSV (u,v,x,y,z), as the surface commands write it, reads as a grid.
    let samples = dir.path().join("s.csv");
    let o = karkas(&[
        "surface",
        "ll",
        "--samples",
        "5,6",
        s(&grid_file(dir.path())),
        "-o",
        s(&samples),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let vtk = dir.path().join("s.vtk");
    assert!(karkas(&["convert", s(&samples), s(&vtk)]).status.success());
    assert!(std::fs::read_to_string(&vtk)
        .unwrap()
        .contains("DIMENSIONS 6 5 1\n"));
}

#[test]
fn bad_pairs_exit_2_with_a_clear_message_and_no_output() {
    let dir = temp_dir();
    let pts = write(dir.path(), "pts.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n");
    let out = dir.path().join("c.obj");
    let o = karkas(&["convert", s(&pts), s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(
        stderr(&o).trim(),
        format!(
            "karkas: error: cannot convert {} (a curve) to .obj: a curve converts to .svg, .png, .html",
            s(&pts)
        )
    );
    assert!(!out.exists());
    // A general mesh has no grid: no structured grid, no picture.
    let grid = grid_file(dir.path());
    let obj = dir.path().join("a.obj");
    assert!(karkas(&["convert", s(&grid), s(&obj)]).status.success());
    for ext in ["vts", "svg"] {
        let out = dir.path().join(format!("b.{ext}"));
        let o = karkas(&["convert", s(&obj), s(&out)]);
        assert_eq!(o.status.code(), Some(2));
        assert!(
            stderr(&o).contains("(a triangle mesh) to ."),
            "{}",
            stderr(&o)
        );
        assert!(!out.exists());
    }
    // Unknown output extension, input equal to output, unreadable mesh.
    let o = karkas(&["convert", s(&grid), s(&dir.path().join("x.dxf"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("unknown output extension"));
    let o = karkas(&["convert", s(&obj), s(&obj)]);
    assert_eq!(o.status.code(), Some(2));
    let bad = write(dir.path(), "bad.obj", "v 0 0 0\nf 1 2 3\n");
    let o = karkas(&["convert", s(&bad), s(&dir.path().join("bad.ply"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.obj:2: index 2"), "{}", stderr(&o));
    assert!(!dir.path().join("bad.ply").exists());
}
