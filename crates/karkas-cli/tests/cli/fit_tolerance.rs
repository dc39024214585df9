//! `karkas curve fit --tolerance`: an unreachable tolerance on noisy points ends with one
//! warning line naming the best fit reached, and the fit is still written.

use crate::common::{karkas, s, stderr, temp_dir, write};

#[test]
fn unreachable_tolerance_warns_with_the_best_fit() {
    // A circle of radius 1 with a deterministic wobble of up to 3e-3 across it.
    let mut text = String::from("x,y\n");
    for i in 0..400 {
        let a = 1.5 * i as f64 / 399.0;
        let wobble = 3e-3 * (((i * 7919) % 13) as f64 / 6.0 - 1.0);
        text.push_str(&format!(
            "{},{}\n",
            (1.0 + wobble) * a.cos(),
            (1.0 + wobble) * a.sin()
        ));
    }
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &text);
    let out = dir.path().join("fit.csv");
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--tolerance",
        "1e-5",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| l.starts_with("karkas: warning: tolerance 1e-5 not met"))
        .collect();
    assert_eq!(lines.len(), 1, "{err}");
    assert!(
        lines[0].contains("the best fit reached max deviation"),
        "{err}"
    );
    assert!(lines[0].contains("(stopped: "), "{err}");
    assert!(out.exists());
}
