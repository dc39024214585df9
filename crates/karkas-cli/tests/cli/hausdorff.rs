//! The CLI contract of `karkas hausdorff`: two point sets, or a point set and `--expr`;
//! prints the distance and where it is attained.

use crate::common::{karkas, s, stderr, stdout, temp_dir, write};

/// The number after `label` on its line of the output, and the rest of the line.
fn field(out: &str, label: &str) -> (f64, String) {
    let line = out.lines().find(|l| l.starts_with(label)).unwrap();
    let rest = line[label.len()..].trim();
    let value = rest.split_whitespace().next().unwrap().parse().unwrap();
    (value, rest.to_owned())
}

#[test]
fn two_point_sets() {
    let dir = temp_dir();
    let a = write(dir.path(), "a.csv", "x,y,z\n0,0,0\n1,0,0\n");
    let b = write(dir.path(), "b.obj", "v 0 0 0\nv 1 0 0\nv 1 3 4\nf 1 2 3\n");
    let o = karkas(&["hausdorff", s(&a), s(&b)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert_eq!(field(&out, "hausdorff").0, 5.0);
    assert_eq!(field(&out, "A -> B").0, 0.0);
    let (d, rest) = field(&out, "B -> A");
    assert_eq!(d, 5.0);
    assert!(rest.ends_with("at 1,3,4 nearest 1,0,0"), "{rest}");
}

#[test]
fn point_set_against_an_implicit_surface() {
    let dir = temp_dir();
    // Points at radius 1.25 around the cylinder of radius 1, and one on it.
    let a = write(
        dir.path(),
        "a.csv",
        "i,j,x,y,z\n0,0,1.25,0,0\n0,1,0,1.25,3\n1,0,1,0,0\n1,1,0,1,1\n",
    );
    let o = karkas(&["hausdorff", s(&a), "--expr", "x^2+y^2-1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert!((field(&out, "hausdorff").0 - 0.25).abs() < 1e-12);
    let (d, rest) = field(&out, "A -> B");
    assert!((d - 0.25).abs() < 1e-12);
    assert!(rest.contains("at 1.25,0,0 nearest 1,0,0"), "{rest}");
}

#[test]
fn errors_exit_2() {
    let dir = temp_dir();
    let a = write(dir.path(), "a.csv", "x,y,z\n0,0,0\n");
    let o = karkas(&["hausdorff", s(&a), s(&dir.path().join("none.csv"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("none.csv"));
    let o = karkas(&["hausdorff", s(&a), s(&a), "--expr", "x"]);
    assert_eq!(o.status.code(), Some(2));
    let o = karkas(&["hausdorff", s(&a)]);
    assert_eq!(o.status.code(), Some(2));
    let o = karkas(&["hausdorff", s(&a), "--expr", "x^^2"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("character 3"), "{}", stderr(&o));
    let bad = write(dir.path(), "bad.obj", "v 0 0\n");
    let o = karkas(&["hausdorff", s(&a), s(&bad)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.obj:1:"), "{}", stderr(&o));
}
