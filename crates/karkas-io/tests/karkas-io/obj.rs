//! The OBJ mesh writer.

use karkas::{Point, Point3};
use karkas_io::obj::{render_surface_obj, write_surface_obj};
use karkas_io::IoError;

use crate::util::scratch;

/// The flat grid z = 0 with x = a along u and y = b along v.
fn flat(nu: usize, nv: usize) -> Vec<Point3> {
    (0..nu)
        .flat_map(|a| (0..nv).map(move |b| Point([a as f64, b as f64, 0.0])))
        .collect()
}

fn render(nu: usize, nv: usize, points: &[Point3]) -> String {
    let mut out = Vec::new();
    render_surface_obj(nu, nv, points, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

fn numbers(line: &str) -> Vec<f64> {
    line.split_whitespace()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect()
}

/// The vertex indices (1-based) of each face, checking that `a//a` pairs agree.
fn faces(text: &str) -> Vec<[usize; 3]> {
    text.lines()
        .filter(|l| l.starts_with("f "))
        .map(|l| {
            let idx: Vec<usize> = l
                .split_whitespace()
                .skip(1)
                .map(|c| {
                    let (v, n) = c.split_once("//").unwrap();
                    assert_eq!(v, n, "vertex and normal indices differ in {l}");
                    v.parse().unwrap()
                })
                .collect();
            [idx[0], idx[1], idx[2]]
        })
        .collect()
}

#[test]
fn counts_and_index_range_for_3_by_4() {
    let text = render(3, 4, &flat(3, 4));
    assert_eq!(text.lines().next(), Some("# karkas surface, 3 x 4 samples"));
    let count = |prefix: &str| text.lines().filter(|l| l.starts_with(prefix)).count();
    assert_eq!((count("v "), count("vn "), count("f ")), (12, 12, 12));
    let faces = faces(&text);
    assert!(faces.iter().flatten().all(|&k| (1..=12).contains(&k)));
    // Every cell is used: all 12 vertices appear in some face.
    let mut used: Vec<usize> = faces.iter().flatten().copied().collect();
    used.sort_unstable();
    used.dedup();
    assert_eq!(used.len(), 12);
}

#[test]
fn flat_grid_normals_point_up_and_faces_are_ccw_from_above() {
    let points = flat(3, 4);
    let text = render(3, 4, &points);
    for line in text.lines().filter(|l| l.starts_with("vn ")) {
        assert_eq!(numbers(line), [0.0, 0.0, 1.0], "{line}");
    }
    let vertices: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| l.starts_with("v "))
        .map(numbers)
        .collect();
    assert_eq!(vertices[5], [1.0, 1.0, 0.0]); // (a, b) = (1, 1) is vertex 1 * 4 + 1 + 1
    for [p, q, r] in faces(&text) {
        let (p, q, r) = (&vertices[p - 1], &vertices[q - 1], &vertices[r - 1]);
        let signed_area = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
        assert!(signed_area > 0.0, "clockwise face {p:?} {q:?} {r:?}");
    }
}

#[test]
fn degenerate_normal_is_written_as_z() {
    // All points of a row equal: a pole. The normal there vanishes.
    let points = vec![Point([0.0, 0.0, 0.0]); 4];
    let text = render(2, 2, &points);
    assert!(text
        .lines()
        .filter(|l| l.starts_with("vn "))
        .all(|l| l == "vn 0 0 1"));
}

#[test]
fn wrong_point_count_is_rejected() {
    let mut out = Vec::new();
    assert!(render_surface_obj(3, 4, &flat(3, 3), &mut out).is_err());
    let (_dir, path) = scratch("m.obj");
    let e = write_surface_obj(&path, 3, 4, &flat(3, 3)).unwrap_err();
    assert!(matches!(e, IoError::InvalidMesh { .. }), "{e:?}");
    assert!(!path.exists());
    write_surface_obj(&path, 3, 3, &flat(3, 3)).unwrap();
    assert!(std::fs::read_to_string(&path).unwrap().contains("f 1//1"));
}
