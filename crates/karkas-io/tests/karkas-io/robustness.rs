//! Malformed input gives errors, never panics: the readers on many random texts.

use std::path::Path;

use karkas_io::airfoil::parse_airfoil;
use karkas_io::grid::parse_grid;
use karkas_io::network::parse_curve_family;
use karkas_io::points::parse_curve_points;
use karkas_io::skeleton::{parse_across_curves, parse_along_curves};

/// Deterministic pseudo-random texts over an alphabet of the characters that matter.
fn texts(count: usize) -> impl Iterator<Item = String> {
    const ALPHABET: &[u8] = b"0123456789.,-+e #\n\n\t xyzijXYZnaNinf\"\r";
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    (0..count).map(move |k| {
        let len = (next() % 120) as usize;
        let mut text: String = match k % 4 {
            0 => "x,y\n".into(),
            1 => "i,j,x,y,z\n".into(),
            2 => "FOIL\n".into(),
            _ => String::new(),
        };
        for _ in 0..len {
            text.push(ALPHABET[(next() % ALPHABET.len() as u64) as usize] as char);
        }
        text
    })
}

#[test]
fn random_text_never_panics() {
    let mut parsed = 0;
    for text in texts(4_000) {
        for name in ["r.csv", "r.dat"] {
            parsed += usize::from(parse_curve_points(&text, Path::new(name)).is_ok());
        }
        let _ = parse_airfoil(&text, Path::new("r.dat"));
        let _ = parse_grid(&text, Path::new("r.csv"));
        let _ = parse_along_curves(&text, Path::new("f.csv"));
        let _ = parse_across_curves(&text, Path::new("g.csv"));
        let _ = parse_curve_family(&text, Path::new("r.csv"));
        let _ = parse_curve_family(&format!("curve,x,y,z\n{text}"), Path::new("r.csv"));
    }
    // Some texts are valid, so the readers were not simply rejecting everything.
    assert!(parsed > 0);
}
