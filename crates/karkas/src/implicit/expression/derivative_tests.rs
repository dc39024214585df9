//! Derivatives of the forward-mode evaluation against closed forms and finite differences,
//! and the parser's depth bound.

use super::function::FUNCTIONS;
use super::*;

/// The inner function of the composition tests, with its gradient and Hessian: a quadratic
/// with a Hessian that is not zero, between -1 and 1 near the test point.
fn inner(p: Point3) -> (f64, [f64; 3], Matrix3) {
    let (x, y, z) = (p[0], p[1], p[2]);
    let u = 0.2 + 0.3 * x - 0.2 * y * z + 0.1 * x * z;
    let gradient = [0.3 + 0.1 * z, -0.2 * z, -0.2 * y + 0.1 * x];
    let hessian = [[0.0, 0.0, 0.1], [0.0, 0.0, -0.2], [0.1, -0.2, 0.0]];
    (u, gradient, hessian)
}

const INNER: &str = "0.2 + 0.3*x - 0.2*y*z + 0.1*x*z";

/// `[g, g', g'']` of every function, written independently of the library.
fn closed_form(name: &str, u: f64) -> [f64; 3] {
    let ln10 = 10f64.ln();
    let ln2 = 2f64.ln();
    match name {
        "sin" => [u.sin(), u.cos(), -u.sin()],
        "cos" => [u.cos(), -u.sin(), -u.cos()],
        "tan" => [
            u.tan(),
            1.0 / u.cos().powi(2),
            2.0 * u.sin() / u.cos().powi(3),
        ],
        "asin" => [
            u.asin(),
            (1.0 - u * u).powf(-0.5),
            u * (1.0 - u * u).powf(-1.5),
        ],
        "acos" => [
            u.acos(),
            -(1.0 - u * u).powf(-0.5),
            -u * (1.0 - u * u).powf(-1.5),
        ],
        "atan" => [
            u.atan(),
            1.0 / (1.0 + u * u),
            -2.0 * u / (1.0 + u * u).powi(2),
        ],
        "sinh" => [u.sinh(), u.cosh(), u.sinh()],
        "cosh" => [u.cosh(), u.sinh(), u.cosh()],
        "tanh" => [
            u.tanh(),
            1.0 / u.cosh().powi(2),
            -2.0 * u.sinh() / u.cosh().powi(3),
        ],
        "exp" => [u.exp(), u.exp(), u.exp()],
        "ln" | "log" => [u.ln(), 1.0 / u, -1.0 / (u * u)],
        "log2" => [u.log2(), 1.0 / (u * ln2), -1.0 / (u * u * ln2)],
        "log10" => [u.log10(), 1.0 / (u * ln10), -1.0 / (u * u * ln10)],
        "sqrt" => [u.sqrt(), 0.5 * u.powf(-0.5), -0.25 * u.powf(-1.5)],
        _ => panic!("no closed form for {name}"),
    }
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * (1.0 + b.abs())
}

/// Checks `F` at `p` against central differences: the gradient from values, the Hessian
/// from gradients (both `O(h^2)`).
fn check_finite_differences(f: &ExpressionSurface, p: Point3) {
    let h = 1e-5;
    let g = f.gradient(p);
    let hessian = f.hessian(p);
    for a in 0..3 {
        let mut e = Point3::ZERO;
        e[a] = h;
        let slope = (f.value(p + e) - f.value(p - e)) / (2.0 * h);
        assert!(
            close(g[a], slope, 1e-7),
            "{}: F_{a} {} vs {slope}",
            f.text(),
            g[a]
        );
        let (gp, gm) = (f.gradient(p + e), f.gradient(p - e));
        for b in 0..3 {
            let second = (gp[b] - gm[b]) / (2.0 * h);
            assert!(
                close(hessian[a][b], second, 1e-7),
                "{}: F_{a}{b} {} vs {second}",
                f.text(),
                hessian[a][b]
            );
        }
    }
}

#[test]
fn every_function_matches_its_closed_form_and_finite_differences() {
    let p = Point3::new([0.5, 0.6, 0.7]);
    let (u, du, hu) = inner(p);
    for name in FUNCTIONS {
        let f = ExpressionSurface::parse(&format!("{name}({INNER})")).unwrap();
        let [g, g1, g2] = closed_form(name, u);
        assert!(close(f.value(p), g, 1e-14), "{name}: value");
        let gradient = f.gradient(p);
        let hessian = f.hessian(p);
        for a in 0..3 {
            assert!(close(gradient[a], g1 * du[a], 1e-14), "{name}: F_{a}");
            for b in 0..3 {
                let expected = g1 * hu[a][b] + g2 * du[a] * du[b];
                assert!(close(hessian[a][b], expected, 1e-14), "{name}: F_{a}{b}");
            }
        }
        check_finite_differences(&f, p);
    }
}

#[test]
fn arithmetic_and_powers_match_closed_forms() {
    let p = Point3::new([1.3, 0.7, -0.4]);
    let (x, y, z) = (p[0], p[1], p[2]);
    // x^y: y x^(y-1) and x^y ln x, and the second derivatives.
    let f = ExpressionSurface::parse("x^y").unwrap();
    let v = x.powf(y);
    let g = f.gradient(p);
    assert!(close(g[0], y * x.powf(y - 1.0), 1e-14));
    assert!(close(g[1], v * x.ln(), 1e-14));
    let h = f.hessian(p);
    assert!(close(h[0][0], y * (y - 1.0) * x.powf(y - 2.0), 1e-14));
    assert!(close(h[0][1], x.powf(y - 1.0) * (1.0 + y * x.ln()), 1e-14));
    assert!(close(h[1][1], v * x.ln().powi(2), 1e-14));
    // x/y*z and 2^z.
    let f = ExpressionSurface::parse("x/y*z + 2^z").unwrap();
    let g = f.gradient(p);
    let expected = [z / y, -x * z / (y * y), x / y + 2f64.powf(z) * 2f64.ln()];
    for a in 0..3 {
        assert!(close(g[a], expected[a], 1e-14), "F_{a}");
    }
    let h = f.hessian(p);
    assert!(close(h[1][1], 2.0 * x * z / y.powi(3), 1e-14));
    assert!(close(h[1][2], -x / (y * y), 1e-14));
    assert!(close(h[2][2], 2f64.powf(z) * 2f64.ln().powi(2), 1e-14));
    for text in [
        "x^y",
        "x/y*z + 2^z",
        "-(x*y)^3/(1 + z^2)",
        "(x - y)^-2 * sqrt(x)",
    ] {
        check_finite_differences(&ExpressionSurface::parse(text).unwrap(), p);
    }
}

#[test]
fn constant_powers_are_smooth_at_zero_and_below() {
    let origin = Point3::ZERO;
    let f = ExpressionSurface::parse("x^2 + y^1 + z^0").unwrap();
    assert_eq!(f.value(origin), 1.0);
    assert_eq!(f.gradient(origin).0, [0.0, 1.0, 0.0]);
    assert_eq!(
        f.hessian(origin),
        [[2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    );
    // An integer power of a negative base.
    let f = ExpressionSurface::parse("x^3").unwrap();
    let p = Point3::new([-1.5, 0.0, 0.0]);
    assert_eq!(f.gradient(p)[0], 3.0 * 1.5 * 1.5);
    assert_eq!(f.hessian(p)[0][0], -6.0 * 1.5);
}

#[test]
fn value_and_jet_agree_to_the_last_bit() {
    let p = Point3::new([0.3, -0.8, 1.9]);
    let f = ExpressionSurface::parse("sin(x)*exp(y/z) - log10(z^2 + 1)^-1.5 + atan(x*y)").unwrap();
    assert_eq!(f.value(p), f.jet(p).value);
}

#[test]
fn no_nesting_overflows_the_stack() {
    // Far beyond the length limit: refused before parsing.
    let deep = "(".repeat(100_000);
    assert!(matches!(
        ExpressionSurface::parse(&deep),
        Err(Error::ExpressionParse { position: 1001, .. })
    ));
    // The parser on its own stops at the depth bound whatever the length.
    for text in [deep.clone(), "-".repeat(100_000), "sin(".repeat(100_000)] {
        match parse::parse(&text) {
            Err(Error::ExpressionParse { position, message }) => {
                assert!(position <= 4 * parse::MAX_DEPTH + 4, "{position}");
                assert!(message.contains("nested deeper"), "{message}");
            }
            other => panic!("{other:?}"),
        }
    }
    // Long chains and repeated signs are loops, not recursion.
    let chain = vec!["x"; 50_000].join("+");
    let signs = format!("{}x", "+".repeat(100_000));
    let p = Point3::new([1.0, 0.0, 0.0]);
    assert_eq!(parse::parse(&chain).unwrap().eval::<f64>(p), 50_000.0);
    assert_eq!(
        parse::parse(&signs).unwrap().eval::<Jet>(p).gradient[0],
        1.0
    );
}
