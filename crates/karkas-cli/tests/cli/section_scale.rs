//! Sections by general planes (`--plane NX,NY,NZ,C`, traced by continuation) at every scale
//! the readers accept: the grid and the offset times `s` give the unit-scale sections times
//! `s`, the same pieces with the same points, for `s` from 1e-150 to 1e150.

use crate::common::{karkas_in, read_csv, stderr, temp_dir, write};

/// An ellipsoid-like closed body, 12 x 16 nodes, scaled by `s`: with its poles (the rows
/// i = 0 and 11 one point each), or the band between 0.15 pi and 0.85 pi of latitude.
fn body(s: f64, poles: bool) -> String {
    let mut text = String::from("i,j,x,y,z\n");
    let (from, span) = if poles { (0.0, 1.0) } else { (0.15, 0.7) };
    for i in 0..12 {
        for j in 0..16 {
            let (u, v) = (
                std::f64::consts::PI * (from + span * i as f64 / 11.0),
                std::f64::consts::TAU * j as f64 / 15.0,
            );
            let p = [
                v.cos() * u.sin(),
                0.7 * v.sin() * u.sin(),
                1.3 * u.cos() + 0.1 * (2.0 * v).cos() * u.sin(),
            ];
            text.push_str(&format!(
                "{i},{j},{:?},{:?},{:?}\n",
                p[0] * s,
                p[1] * s,
                p[2] * s
            ));
        }
    }
    text
}

#[test]
fn sections_by_general_planes_scale_with_the_data() {
    let dir = temp_dir();
    // LL on the body through its poles; the bicubic interpolant on a band (chord parameters
    // need rows of distinct points).
    for (method, poles) in [("ll", true), ("bicubic", false)] {
        let section = |s: f64| {
            write(dir.path(), "g.csv", &body(s, poles));
            let planes = [
                format!("0.6,0.3,1,{:?}", 0.2 * s),
                format!("-1,2,0.5,{:?}", -0.1 * s),
            ];
            let o = karkas_in(
                dir.path(),
                &[
                    "section",
                    "g.csv",
                    "--method",
                    method,
                    "--closed-v",
                    "--plane",
                    &planes[0],
                    "--plane",
                    &planes[1],
                    "-o",
                    "s.csv",
                ],
            );
            assert_eq!(o.status.code(), Some(0), "{method} at {s}: {}", stderr(&o));
            read_csv(&dir.path().join("s.csv")).1
        };
        let unit = section(1.0);
        // Both planes cut the body in one closed piece each (the band in three pieces).
        let pieces: std::collections::BTreeSet<u64> = unit.iter().map(|r| r[0] as u64).collect();
        assert_eq!(pieces.len(), if poles { 2 } else { 3 }, "{method}");
        for s in [1e-150, 1e-80, 1e-20, 3e-7, 1e20, 1e80, 1e150] {
            let scaled = section(s);
            assert_eq!(
                scaled.len(),
                unit.len(),
                "{method} at {s}: another number of points"
            );
            for (a, b) in scaled.iter().zip(&unit) {
                assert_eq!(a[0], b[0], "{method} at {s}: another piece");
                for c in 1..5 {
                    // t is the length along the piece: it scales too.
                    let (x, y) = (a[c] / s, b[c]);
                    assert!((x - y).abs() <= 1e-12 * 2.0, "{method} at {s}: {x} vs {y}");
                }
            }
        }
    }
}
