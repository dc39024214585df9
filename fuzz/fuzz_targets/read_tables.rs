//! The table readers on arbitrary text: grid CSV `i,j,x,y,z`, tube skeletons `i,q,x,y,z` and
//! `j,p,x,y,z`, curve networks `curve,x,y,z`, cell masks `i,j`, OBJ vertices. An error or a
//! complete, finite result, never a panic.
#![no_main]

use std::path::Path;

use karkas_io::grid::parse_grid;
use karkas_io::mask::parse_cell_mask;
use karkas_io::network::parse_curve_family;
use karkas_io::pointset::parse_obj_vertices;
use karkas_io::skeleton::{parse_across_curves, parse_along_curves};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(rest);
    let path = Path::new("table.csv");
    match selector % 6 {
        0 => {
            if let Ok(g) = parse_grid(&text, path) {
                assert!(g.rows() >= 1 && g.as_slice().iter().all(|p| p.is_finite()));
            }
        }
        1 => {
            if let Ok(g) = parse_along_curves(&text, path) {
                assert!(g.as_slice().iter().all(|p| p.is_finite()));
            }
        }
        2 => {
            if let Ok(g) = parse_across_curves(&text, path) {
                assert!(g.as_slice().iter().all(|p| p.is_finite()));
            }
        }
        3 => {
            if let Ok(f) = parse_curve_family(&text, path) {
                assert!(f.curves.iter().flatten().all(|p| p.is_finite()));
            }
        }
        4 => {
            let rows = usize::from(rest.first().copied().unwrap_or(0) % 16);
            let cols = usize::from(rest.get(1).copied().unwrap_or(0) % 16);
            if let Ok(m) = parse_cell_mask(&text, path, rows, cols) {
                assert_eq!((m.rows(), m.cols()), (rows, cols));
            }
        }
        _ => {
            if let Ok(p) = parse_obj_vertices(&text, path) {
                assert!(p.iter().all(|q| q.is_finite()));
            }
        }
    }
});
