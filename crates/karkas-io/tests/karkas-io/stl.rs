//! The binary STL writer: the exact bytes of a small mesh, a round trip through `stl_io`'s
//! reader, and errors that leave the destination alone.

use karkas::{Point, Point3};
use karkas_io::stl::write_surface_stl;
use karkas_io::IoError;

use crate::util::scratch;

/// Little-endian `f32`s.
fn floats(values: &[f32]) -> Vec<u8> {
    values.iter().flat_map(|v| v.to_le_bytes()).collect()
}

#[test]
fn one_cell_gives_the_expected_bytes() {
    // A 2 x 2 grid in the plane z = 1: u along x, v along y, so the normals are +z.
    let points = [
        Point([0.0, 0.0, 1.0]),
        Point([0.0, 2.0, 1.0]),
        Point([1.0, 0.0, 1.0]),
        Point([1.0, 2.0, 1.0]),
    ];
    let (_dir, path) = scratch("cell.stl");
    write_surface_stl(&path, 2, 2, &points).unwrap();
    let bytes = std::fs::read(&path).unwrap();

    let mut expected = vec![0u8; 80];
    expected.extend(2u32.to_le_bytes());
    // (a,b) (a+1,b) (a+1,b+1), then (a,b) (a+1,b+1) (a,b+1).
    for corners in [[0, 2, 3], [0, 3, 1]] {
        expected.extend(floats(&[0.0, 0.0, 1.0]));
        for k in corners {
            let p: Point3 = points[k];
            expected.extend(floats(&[p[0] as f32, p[1] as f32, p[2] as f32]));
        }
        expected.extend([0u8, 0u8]);
    }
    assert_eq!(bytes.len(), 84 + 2 * 50);
    assert_eq!(bytes, expected);
}

#[test]
fn a_closed_grid_round_trips_as_a_closed_mesh() {
    // A cylinder, first column repeated at the end: 4 x 9 samples, 3 x 8 cells.
    let (nu, nv) = (4, 9);
    let points: Vec<Point3> = (0..nu)
        .flat_map(|a| {
            (0..nv).map(move |b| {
                let phi = std::f64::consts::TAU * (b % (nv - 1)) as f64 / (nv - 1) as f64;
                Point([phi.cos(), phi.sin(), a as f64])
            })
        })
        .collect();
    let (_dir, path) = scratch("cyl.stl");
    write_surface_stl(&path, nu, nv, &points).unwrap();
    let mut file = std::fs::File::open(&path).unwrap();
    let mesh = stl_io::read_stl(&mut file).unwrap();
    assert_eq!(mesh.faces.len(), 2 * 3 * 8);
    // Welded by coordinates, the seam disappears: 4 rings of 8 distinct vertices.
    assert_eq!(mesh.vertices.len(), 4 * 8);
    for face in &mesh.faces {
        // The facet normal is d/du x d/dv: with u along z and v counter-clockwise about z,
        // that is z x tangent, which points towards the axis.
        let n = face.normal.0;
        let centre: [f32; 3] = (0..3)
            .map(|c| {
                face.vertices
                    .iter()
                    .map(|&v| mesh.vertices[v].0[c])
                    .sum::<f32>()
                    / 3.0
            })
            .collect::<Vec<_>>()
            .try_into()
            .unwrap();
        let radial = n[0] * centre[0] + n[1] * centre[1];
        assert!(radial < 0.0 && n[2].abs() < 1e-6, "{n:?} at {centre:?}");
    }
}

#[test]
fn wrong_point_count_writes_nothing() {
    let (_dir, path) = scratch("bad.stl");
    let e = write_surface_stl(&path, 3, 3, &[Point3::ZERO; 8]).unwrap_err();
    assert!(matches!(e, IoError::InvalidMesh { .. }));
    assert!(
        e.to_string().contains("8 points do not form a 3 x 3 grid"),
        "{e}"
    );
    assert!(!path.exists());
}
