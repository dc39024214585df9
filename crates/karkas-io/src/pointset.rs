//! Point sets for distance measurements: the vertices of a Wavefront OBJ mesh, or the
//! `x,y,z` columns of a CSV file (a grid `i,j,x,y,z`, a sampled surface `u,v,x,y,z`, plain
//! points), chosen by the extension `.obj`.
//!
//! Only the `v x y z [w]` lines of an OBJ file are read (faces, normals and texture
//! coordinates are not needed to measure distances between sampled surfaces and are skipped).

use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError, Location};
use crate::lines::{parse_coordinate, read_text, strip_bom};
use crate::points::{parse_curve_points, CurvePoints};

/// Reads the points of `path`: OBJ vertices for `.obj`, otherwise CSV/whitespace columns
/// with `x`, `y`, `z` (see [`crate::points`]).
pub fn read_point_set(path: &Path) -> Result<Vec<Point3>, IoError> {
    let text = read_text(path)?;
    let is_obj = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("obj"));
    if is_obj {
        return parse_obj_vertices(&text, path);
    }
    match parse_curve_points(&text, path)? {
        CurvePoints::Spatial(points) => Ok(points),
        CurvePoints::Planar(_) => Err(data_error(
            path,
            "the points have two coordinates; a point set in space needs x, y, z",
        )),
    }
}

/// The vertices (`v` lines) of OBJ `text`; `path` names the file in errors.
pub fn parse_obj_vertices(text: &str, path: &Path) -> Result<Vec<Point3>, IoError> {
    let mut points = Vec::new();
    for (k, line) in strip_bom(text).lines().enumerate() {
        let line = line.split('#').next().unwrap_or("");
        let mut fields = line.split_whitespace();
        if fields.next() != Some("v") {
            continue;
        }
        let at = Location::new(path, k + 1);
        let coords: Vec<&str> = fields.collect();
        if !(3..=4).contains(&coords.len()) {
            return Err(at.error(format!(
                "a vertex needs 3 coordinates (x y z [w]), found {}",
                coords.len()
            )));
        }
        let mut p = Point3::ZERO;
        for c in 0..3 {
            p[c] = parse_coordinate(coords[c], c + 2, at)?;
        }
        points.push(p);
    }
    if points.is_empty() {
        return Err(data_error(path, "no vertices ('v x y z' lines) found"));
    }
    Ok(points)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vertices_are_read_and_errors_name_the_line() {
        let text = "# a mesh\nv 0 0 0\nvn 0 0 1\nv 1 2 3 1.0\nf 1 2 1\n";
        let pts = parse_obj_vertices(text, Path::new("m.obj")).unwrap();
        assert_eq!(pts, vec![Point3::ZERO, Point3::new([1.0, 2.0, 3.0])]);
        let e = parse_obj_vertices("v 1 2\n", Path::new("m.obj")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "m.obj:1: a vertex needs 3 coordinates (x y z [w]), found 2"
        );
        let e = parse_obj_vertices("v 1 2 nan\n", Path::new("m.obj")).unwrap_err();
        assert_eq!(e.to_string(), "m.obj:1: non-finite value 'nan' in column 4");
        assert!(parse_obj_vertices("f 1 2 3\n", Path::new("m.obj")).is_err());
    }
}
