//! Invalid input to LL curves and surfaces is an error that names the problem
//! (docs/methods.md §1.2–1.3: K >= 3, finite points, L >= 1).

use karkas::ll::{LlCurve, LlSurface, MAX_ORDER};
use karkas::{Error, Grid, Point};

fn pts(n: usize) -> Vec<Point<2>> {
    (0..n).map(|i| Point([i as f64, (i * i) as f64])).collect()
}

type Build = fn(&[Point<2>], usize, bool) -> karkas::Result<LlCurve<2>>;
const BUILDERS: [(Build, &str); 2] = [
    (LlCurve::new, "approximating"),
    (LlCurve::interpolating, "interpolating"),
];

#[test]
fn curves_need_three_points() {
    for (build, name) in BUILDERS {
        for closed in [false, true] {
            for n in 0..3 {
                match build(&pts(n), 2, closed) {
                    Err(Error::TooFewPoints { needed: 3, got, .. }) => assert_eq!(got, n),
                    other => panic!("{name}, {n} points, closed {closed}: {other:?}"),
                }
            }
            assert!(
                build(&pts(3), 2, closed).is_ok(),
                "{name}: 3 points are enough"
            );
        }
    }
}

#[test]
fn closed_curves_need_three_distinct_points() {
    let a = Point([0.0, 0.0]);
    let b = Point([1.0, 2.0]);
    for (build, name) in BUILDERS {
        let e = build(&[a, b, a], 3, true).unwrap_err();
        assert!(
            matches!(
                e,
                Error::TooFewPoints {
                    needed: 3,
                    got: 2,
                    ..
                }
            ),
            "{name}: {e:?}"
        );
        // Open, the same three points are a valid curve.
        assert!(build(&[a, b, a], 3, false).is_ok());
        assert!(build(&[a, b, Point([2.0, 0.0]), a], 3, true).is_ok());
    }
}

#[test]
fn non_finite_points_are_named_by_index() {
    for (build, name) in BUILDERS {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for index in [0, 2, 4] {
                let mut p = pts(5);
                p[index][1] = bad;
                for closed in [false, true] {
                    let e = build(&p, 2, closed).unwrap_err();
                    assert_eq!(e, Error::NonFinitePoint { index }, "{name}");
                    assert!(e.to_string().contains(&format!("point {index}")), "{e}");
                }
            }
        }
    }
}

#[test]
fn order_must_be_in_range() {
    for (build, name) in BUILDERS {
        let e = build(&pts(5), 0, false).unwrap_err();
        assert!(
            matches!(e, Error::InvalidOrder { order: 0, .. }),
            "{name}: {e:?}"
        );
        assert!(e.to_string().contains('0'));
        let e = build(&pts(5), MAX_ORDER + 1, true).unwrap_err();
        assert!(matches!(e, Error::InvalidOrder { .. }), "{name}: {e:?}");
        assert!(build(&pts(5), MAX_ORDER, false).is_ok());
    }
    let g = Grid::from_fn(4, 4, |i, j| Point([i as f64, j as f64, 0.0]));
    assert!(matches!(
        LlSurface::new(&g, 0, false, false),
        Err(Error::InvalidOrder { order: 0, .. })
    ));
}

fn grid(rows: usize, cols: usize) -> Grid<Point<3>> {
    Grid::from_fn(rows, cols, |i, j| {
        Point([i as f64, j as f64, (i * j) as f64])
    })
}

#[test]
fn surfaces_need_three_rows_and_columns() {
    for (rows, cols) in [(2, 5), (5, 2), (1, 1), (2, 2), (0, 4)] {
        let g = grid(rows, cols);
        for cu in [false, true] {
            for cv in [false, true] {
                for e in [
                    LlSurface::new(&g, 2, cu, cv).unwrap_err(),
                    LlSurface::interpolating(&g, 2, cu, cv).unwrap_err(),
                ] {
                    assert!(
                        matches!(e, Error::TooFewPoints { needed: 3, got, .. } if got == rows.min(cols)),
                        "{rows} x {cols}: {e:?}"
                    );
                }
            }
        }
    }
    assert!(LlSurface::new(&grid(3, 3), 2, false, false).is_ok());
}

#[test]
fn closed_surface_directions_need_three_distinct_lines() {
    // 3 rows, the last repeating the first: only 2 distinct rows.
    let g = Grid::from_fn(3, 4, |i, j| Point([(i % 2) as f64, j as f64, 0.0]));
    assert!(matches!(
        LlSurface::new(&g, 2, true, false),
        Err(Error::TooFewPoints {
            needed: 3,
            got: 2,
            ..
        })
    ));
    assert!(LlSurface::new(&g, 2, false, false).is_ok());
    let t = g.transposed();
    assert!(matches!(
        LlSurface::new(&t, 2, false, true),
        Err(Error::TooFewPoints {
            needed: 3,
            got: 2,
            ..
        })
    ));
}

#[test]
fn non_finite_grid_points_are_named_by_cell() {
    for (row, col) in [(0, 0), (2, 3), (4, 1)] {
        let mut g = grid(5, 4);
        g.get_mut(row, col)[2] = f64::NAN;
        for e in [
            LlSurface::new(&g, 3, false, true).unwrap_err(),
            LlSurface::interpolating(&g, 3, true, false).unwrap_err(),
        ] {
            assert_eq!(e, Error::NonFiniteCell { row, col });
            assert!(e.to_string().contains(&format!("i={row}, j={col}")), "{e}");
        }
    }
}
