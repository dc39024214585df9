//! The data of Aulchenko et al.'s examples (docs/methods.md §1.6), made here because the paper prints
//! only pictures: a closed contour of 53 points and an aircraft-like body of 15 sections of
//! 31 points. The repository ships the same data as `data/contour-53.csv` and
//! `data/aircraft-15x31.csv` (a test keeps them identical to these generators).

use karkas::{Grid, Point2, Point3};
use std::f64::consts::PI;

/// The closed contour of the paper's figure 3: 52 distinct points and the first repeated
/// (53 in all, the paper's `r_K = r_1`). Flat parts (the bottom and both walls: collinear,
/// equally spaced points), sharp corners (the bottom corners, a spike at the top) and a
/// round arc, so that both the straight-segment and the no-overshoot properties show.
pub fn contour_53() -> Vec<Point2> {
    let mut pts = Vec::with_capacity(53);
    // Bottom, left to right: 13 points 0.5 apart.
    pts.extend((0..=12).map(|k| Point2::new([-3.0 + 0.5 * k as f64, 0.0])));
    // Right wall, up: 4 points.
    pts.extend((1..=4).map(|k| Point2::new([3.0, 0.5 * k as f64])));
    // Top arc of radius 3 about (0, 2), 32 points, with a spike (radius 4) at the top.
    pts.extend((1..=32).map(|k| {
        let angle = PI * k as f64 / 32.0;
        let radius = if k == 16 { 4.0 } else { 3.0 };
        Point2::new([radius * angle.cos(), 2.0 + radius * angle.sin()])
    }));
    // Left wall, down: 3 points; the first point closes the contour.
    pts.extend((1..=3).rev().map(|k| Point2::new([-3.0, 0.5 * k as f64])));
    pts.push(pts[0]);
    pts
}

/// Fuselage radius at station `x` (0..14): elliptic nose, cylinder, tapered tail.
fn fuselage_radius(x: f64) -> f64 {
    if x < 3.0 {
        0.15 + 0.85 * (1.0 - (1.0 - x / 3.0).powi(2)).sqrt()
    } else if x <= 10.0 {
        1.0
    } else {
        1.0 - 0.6 * ((x - 10.0) / 4.0).powi(2)
    }
}

/// The aircraft-like body: `Kx = 15` sections `x = const` (rows, `x = 0..14`), each of
/// `Ky = 31` points around the right half (columns, from the keel `y = 0, z < 0` over the side
/// to the crown `y = 0, z > 0`). A wing grows out of the side between `x = 4` and `x = 10`
/// (span 5 at `x = 7`), a fin-like hump rises over the tail. `x` depends on the row only, as
/// in the paper.
pub fn aircraft_15x31() -> Grid<Point3> {
    Grid::from_fn(15, 31, |i, j| {
        let x = i as f64;
        let r = fuselage_radius(x);
        let theta = -PI / 2.0 + PI * j as f64 / 30.0;
        let (mut y, mut z) = (r * theta.cos(), r * theta.sin());
        // Wing band: columns 11..=19 blend from the circle to a thin wing section.
        let wing = if (4.0..=10.0).contains(&x) {
            (PI * (x - 4.0) / 6.0).sin().powi(2)
        } else {
            0.0
        };
        if (11..=19).contains(&j) && wing > 0.0 {
            let phi = PI * (j - 11) as f64 / 8.0;
            let span = 5.0 * wing;
            let wing_y = r + span * phi.sin();
            let wing_z = -0.12 * r * phi.cos() + 0.08 * span * phi.sin();
            y = (1.0 - wing) * y + wing * wing_y;
            z = (1.0 - wing) * z + wing * wing_z;
        }
        // Fin-like hump over the tail on the top columns.
        if x > 10.0 && j >= 27 {
            let fin = ((x - 10.0) / 4.0).powi(2);
            z += 1.6 * fin * (j - 26) as f64 / 4.0;
        }
        Point3::new([x, y, z])
    })
}

/// The contour as CSV text with header `x,y`.
pub fn contour_csv(points: &[Point2]) -> String {
    let mut s = String::from("x,y\n");
    for p in points {
        s.push_str(&format!("{},{}\n", p[0], p[1]));
    }
    s
}

/// A grid as CSV text with header `i,j,x,y,z` (row-major).
pub fn grid_csv(grid: &Grid<Point3>) -> String {
    let mut s = String::from("i,j,x,y,z\n");
    for i in 0..grid.rows() {
        for j in 0..grid.cols() {
            let p = grid.get(i, j);
            s.push_str(&format!("{i},{j},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn shipped(name: &str) -> String {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../data")
            .join(name);
        std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
    }

    #[test]
    fn contour_has_53_points_closed() {
        let c = contour_53();
        assert_eq!(c.len(), 53);
        assert_eq!(c[0], c[52]);
        let distinct = c[..52]
            .iter()
            .enumerate()
            .all(|(a, p)| c[..a].iter().all(|q| q != p));
        assert!(distinct, "the 52 contour points must be distinct");
    }

    #[test]
    fn aircraft_sections_have_constant_x() {
        let g = aircraft_15x31();
        assert_eq!((g.rows(), g.cols()), (15, 31));
        for i in 0..15 {
            assert!(g.row(i).iter().all(|p| p[0] == i as f64));
        }
    }

    #[test]
    fn shipped_data_matches_the_generators() {
        assert_eq!(shipped("contour-53.csv"), contour_csv(&contour_53()));
        assert_eq!(shipped("aircraft-15x31.csv"), grid_csv(&aircraft_15x31()));
    }
}
