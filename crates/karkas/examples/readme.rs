//! The library example of the README, kept compiling.

use karkas::{ll::LlCurve, Curve, Point};

fn main() -> Result<(), karkas::Error> {
    let pts = [
        Point([0.0, 0.0]),
        Point([1.0, 1.0]),
        Point([2.0, 0.0]),
        Point([3.0, 1.0]),
    ];
    let curve = LlCurve::new(&pts, 5, false)?; // order 5, open
    let mid = curve.eval(0.5); // a point
    let tangent = curve.deriv(0.5, 1); // d/dt
    let ts: Vec<f64> = (0..1000).map(|k| curve.domain().uniform(k, 1000)).collect();
    let mut out = vec![Point::ZERO; 1000];
    curve.eval_into(&ts, &mut out); // batch evaluation into your buffer
    println!("{mid:?} {tangent:?} {:?}", out[999]);
    Ok(())
}
