//! Errors carry what caused them as their source: the geometry library's error, a mesh check.

use std::error::Error as _;

use karkas::{Grid, Point3};
use karkas_io::cad::CadError;
use karkas_io::mesh::{write_mesh, MeshError, MeshOptions, TriangleMesh};
use karkas_io::IoError;

use crate::util::scratch;

/// An error of the geometry library: a grid whose size does not match its points.
fn library_error() -> karkas::Error {
    Grid::from_row_major(2, 2, vec![Point3::ZERO; 3]).unwrap_err()
}

/// Whether the source chain of `e` (from `e` itself) holds an error of type `T`.
fn chain_has<T: std::error::Error + 'static>(e: &(dyn std::error::Error + 'static)) -> bool {
    let mut next = Some(e);
    while let Some(e) = next {
        if e.downcast_ref::<T>().is_some() {
            return true;
        }
        next = e.source();
    }
    false
}

#[test]
fn geometry_errors_carry_the_library_error() {
    let library = library_error();
    let text = library.to_string();
    let e = IoError::geometry(std::path::Path::new("g.csv"), library);
    assert_eq!(e.to_string(), format!("g.csv: {text}"));
    let source = e.source().expect("a source");
    assert!(
        source.downcast_ref::<karkas::Error>().is_some(),
        "{source:?}"
    );
    assert!(chain_has::<karkas::Error>(&e));
}

#[test]
fn cad_errors_carry_the_library_error() {
    let e = CadError::Geometry(library_error());
    assert!(e
        .source()
        .unwrap()
        .downcast_ref::<karkas::Error>()
        .is_some());
    let e = CadError::TooManyDimensions { dimensions: 4 };
    assert_eq!(
        e.to_string(),
        "a curve in 4 dimensions cannot be written to a CAD file (at most 3)"
    );
    assert!(e.source().is_none());
}

#[test]
fn mesh_errors_carry_the_failed_check() {
    let (_dir, path) = scratch("m.ply");
    let mut mesh = TriangleMesh::from_grid(&Grid::from_fn(2, 2, |a, b| {
        Point3::new([a as f64, b as f64, 0.0])
    }))
    .unwrap();
    mesh.triangles.push([0, 1, 7]);
    let e = write_mesh(&path, &mesh, &MeshOptions::default()).unwrap_err();
    assert!(matches!(e, IoError::InvalidMesh { .. }), "{e:?}");
    let check = e.source().unwrap().downcast_ref::<MeshError>().unwrap();
    assert_eq!(
        *check,
        MeshError::IndexOutOfRange {
            triangle: 2,
            corners: [0, 1, 7],
            vertices: 4
        }
    );
    assert!(e.to_string().starts_with("cannot write "), "{e}");
    assert!(e
        .to_string()
        .ends_with(": triangle 2 has vertex index [0, 1, 7] out of range (0..4)"));
    assert!(!path.exists());

    // A file whose face names a missing vertex: the same check, reported as the file's fault.
    let (_dir, path) = scratch("bad.ply");
    let ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
               property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
               end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n";
    std::fs::write(&path, ply).unwrap();
    let e = karkas_io::mesh::read_mesh(&path).unwrap_err();
    assert!(matches!(e, IoError::MalformedMesh { .. }), "{e:?}");
    assert!(chain_has::<MeshError>(&e));
    assert!(
        e.to_string()
            .ends_with("bad.ply: triangle 0 has vertex index [0, 1, 5] out of range (0..3)"),
        "{e}"
    );
}

#[test]
fn undecodable_stl_keeps_the_decoder_error() {
    let (_dir, path) = scratch("bad.stl");
    std::fs::write(&path, b"solid x\nfacet nonsense\n").unwrap();
    let e = karkas_io::mesh::read_mesh(&path).unwrap_err();
    assert!(matches!(e, IoError::Decode { format: "STL", .. }), "{e:?}");
    assert!(e.to_string().contains("not a readable STL file"), "{e}");
    assert!(chain_has::<std::io::Error>(&e));
}

#[test]
fn picture_errors_carry_the_renderer_error() {
    let (_dir, path) = scratch("p.png");
    let e = karkas_io::png::write_svg_as_png(&path, "not svg").unwrap_err();
    assert!(matches!(e, IoError::Picture { .. }), "{e:?}");
    assert!(e.to_string().starts_with("cannot write "), "{e}");
    let picture = e.source().unwrap();
    assert!(matches!(
        picture.downcast_ref::<karkas_io::picture::PictureError>(),
        Some(karkas_io::picture::PictureError::Svg(_))
    ));
    // The renderer's own error is one step further down the chain.
    assert!(picture.source().is_some());
    assert!(!path.exists());
}
