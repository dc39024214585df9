//! Point sets for distance measurements: the vertices of a Wavefront OBJ mesh, or the
//! `x,y,z` columns of a CSV file (a grid `i,j,x,y,z`, a sampled surface `u,v,x,y,z`, plain
//! points), chosen by the extension `.obj`.
//!
//! Only the `v x y z [w]` lines of an OBJ file are read (see
//! [`parse_obj_vertices`], which lives with the OBJ format in [`crate::mesh::obj`]).

use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError};
use crate::input::display_name;
use crate::lines::read_text;
pub use crate::mesh::obj::parse_obj_vertices;
use crate::points::{read_curve_points, CurvePoints};
use crate::range::check_coordinate_range;

/// Reads the points of `path`: OBJ vertices for `.obj`, otherwise CSV/whitespace columns
/// with `x`, `y`, `z` (see [`crate::points`]), read in one pass; `-` is standard input.
pub fn read_point_set(path: &Path) -> Result<Vec<Point3>, IoError> {
    let is_obj = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("obj"));
    if is_obj {
        let points = parse_obj_vertices(&read_text(path)?, path)?;
        check_coordinate_range(points.iter().flat_map(|p| p.0), path)?;
        return Ok(points);
    }
    match read_curve_points(path)? {
        CurvePoints::Spatial(points) => Ok(points),
        CurvePoints::Planar(_) => Err(data_error(
            &display_name(path),
            "the points have two coordinates; a point set in space needs x, y, z",
        )),
    }
}
