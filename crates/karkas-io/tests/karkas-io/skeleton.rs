//! Reading the skeleton curves of a tube: `i,q,x,y,z` (along) and `j,p,x,y,z` (across).

use std::path::Path;

use karkas::Point;
use karkas_io::skeleton::{parse_across_curves, parse_along_curves, read_along_curves};
use karkas_io::IoError;

use crate::util::scratch;

/// Two curves along, three samples each: f_i(q) = (i, q, i + 10 q).
const ALONG: &str = "i,q,x,y,z
0,0,0,0,0
0,1,0,1,10
0,2,0,2,20
1,0,1,0,1
1,1,1,1,11
1,2,1,2,21
";

fn along_error(text: &str) -> String {
    parse_along_curves(text, Path::new("f.csv"))
        .unwrap_err()
        .to_string()
}

#[test]
fn curves_are_rows_in_any_order() {
    let g = parse_along_curves(ALONG, Path::new("f.csv")).unwrap();
    assert_eq!((g.rows(), g.cols()), (2, 3));
    assert_eq!(*g.get(1, 2), Point([1.0, 2.0, 21.0]));
    let shuffled = "# across\nZ,p,J,x,y\n21,2,1,1,2\n0,0,0,0,0\n20,2,0,0,2\n1,0,1,1,0\n10,1,0,0,1\n11,1,1,1,1\n";
    let (_dir, path) = scratch("g.csv");
    std::fs::write(&path, ALONG).unwrap();
    assert_eq!(read_along_curves(&path).unwrap(), g);
    assert_eq!(
        parse_across_curves(shuffled, Path::new("g.csv")).unwrap(),
        g
    );
}

#[test]
fn errors_name_the_file_and_the_sample_or_line() {
    let missing = ALONG.replace("1,1,1,1,11\n", "");
    assert_eq!(along_error(&missing), "f.csv: i=1, q=1: missing");
    let e = parse_along_curves(&missing, Path::new("f.csv")).unwrap_err();
    assert!(
        matches!(
            e,
            IoError::Sample {
                curve: 1,
                sample: 1,
                ..
            }
        ),
        "{e:?}"
    );
    let twice = format!("{ALONG}0,2,5,5,5\n");
    assert_eq!(
        along_error(&twice),
        "f.csv: i=0, q=2: given twice, on lines 4 and 8"
    );
    assert_eq!(
        along_error(&ALONG.replace("0,1,0,1,10", "0,1,0,nan,10")),
        "f.csv:3: non-finite value 'nan' in column 4"
    );
    assert_eq!(
        along_error(&ALONG.replace("i,q,", "i,j,")),
        "f.csv:1: the header has no column 'q' (expected i,q,x,y,z)"
    );
    assert_eq!(
        along_error("0,0,0,0,0\n"),
        "f.csv:1: missing header: expected the columns i,q,x,y,z"
    );
    assert_eq!(
        along_error("i,q,x,y,z\n"),
        "f.csv: no skeleton points (along) found"
    );
    let across = parse_across_curves(ALONG, Path::new("g.csv")).unwrap_err();
    assert_eq!(
        across.to_string(),
        "g.csv:1: the header has no column 'j' (expected j,p,x,y,z)"
    );
    let across = parse_across_curves("j,p,x,y,z\n0,1,0,0,0\n", Path::new("g.csv")).unwrap_err();
    assert_eq!(across.to_string(), "g.csv: j=0, p=0: missing");
}
