//! The curve-point reader (CSV, whitespace columns, Selig and Lednicer `.dat`) on arbitrary
//! text: an error or points, every point finite, never a panic.
#![no_main]

use std::path::Path;

use karkas_io::airfoil::parse_airfoil;
use karkas_io::points::{parse_curve_points, CurvePoints};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let text = String::from_utf8_lossy(rest);
    let name = match selector % 3 {
        0 => "points.csv",
        1 => "profile.dat",
        _ => "points.txt",
    };
    let path = Path::new(name);
    match parse_curve_points(&text, path) {
        Ok(CurvePoints::Planar(p)) => {
            assert!(!p.is_empty() && p.iter().all(|q| q.is_finite()))
        }
        Ok(CurvePoints::Spatial(p)) => {
            assert!(!p.is_empty() && p.iter().all(|q| q.is_finite()))
        }
        Err(e) => assert!(!e.to_string().contains('\n') || text.contains('\n')),
    }
    if let Ok(a) = parse_airfoil(&text, path) {
        assert!(a.points.iter().all(|q| q.is_finite()));
    }
});
