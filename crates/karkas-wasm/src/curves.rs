//! The curves of the workbench: LL (Aulchenko et al., docs/methods.md §1.2), interpolating
//! LL (§1.3), the cubic spline through the points, and Pavlov's fit with bounded
//! second-derivative jumps (§4), each built as the command line builds it, sampled for the
//! screen with its curvature, and exported by the command line's own writers.

use std::path::Path;

use karkas::bspline::ToBSplineCurve;
use karkas::fit::{fit_curve, fit_curve_adaptive, FitOptions, StartParameters, DEFAULT_FAIRNESS};
use karkas::geometry::{curvature, curvature_profile};
use karkas::ll::LlCurve;
use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use karkas::{Curve, PiecewiseCurve, Point};
use karkas_io::export::cad::cad_curve_text;
use karkas_io::export::curve::{render_curve_svg, CurveDrawing};
use karkas_io::export::samples::{default_curve_samples, sample_curve};
use karkas_io::write::render_curve_csv;
use karkas_io::OutputFormat;

/// What the page asks of a curve method (the command line's options of the same names).
#[derive(Clone, Debug, PartialEq)]
pub struct CurveRequest {
    /// `ll`, `ll-interpolate`, `spline` or `fit`.
    pub method: String,
    /// LL order L (`--order`).
    pub order: usize,
    /// A closed curve (`--closed`; the spline's periodic ends).
    pub closed: bool,
    /// The spline's ends when open (`--ends`): `not-a-knot` or `natural`.
    pub ends: String,
    /// The spline's parameters (`--param`): `uniform`, `chord` or `centripetal`.
    pub param: String,
    /// The fit's tolerance (`--tolerance`).
    pub tolerance: f64,
    /// The fit's bound on the second-derivative jumps (`--eps`; infinite for none).
    pub eps: f64,
    /// The fit's free inner knots (`--corner`).
    pub corners: Vec<f64>,
    /// The fit's knots (`--knots`), in place of the tolerance when not empty: the page keeps
    /// the knots of the last fit while a point is dragged.
    pub knots: Vec<f64>,
    /// The fit's starting parameters of the points (one each, from 0 to 1), with `knots`:
    /// the last fit's foot parameters, a start close to the answer after a small drag.
    pub start: Vec<f64>,
}

/// A built curve, whatever its kind and dimension.
pub trait BuiltCurve {
    /// `n` samples uniform in the parameter, 9 numbers each: `t, x, y, z, x', y', z', κ, s`
    /// (`z = 0` in the plane; `κ` signed in the plane; `s` the arc length along the samples'
    /// polygon).
    fn samples(&self, n: usize) -> Vec<f64>;
    /// The curvature against arc length, `per_piece` samples on every polynomial piece,
    /// 3 numbers each: `t, s, κ` (one-sided at the breakpoints, so jumps show).
    fn profile(&self, per_piece: usize) -> Vec<f64>;
    /// The degree and the number of control points of the exact B-spline form.
    fn bspline_size(&self) -> (usize, usize);
    /// The breakpoints of the curve's polynomial pieces, the domain's ends included.
    fn breaks(&self) -> Vec<f64>;
    /// A fit's foot parameters of the points (empty for the other methods).
    fn parameters(&self) -> Vec<f64>;
    /// The file the command line writes for this curve in `format` (STEP, IGES, DXF) to a
    /// file of stem `name`, the input named `input`.
    fn cad(&self, format: OutputFormat, name: &str, input: &str) -> Result<String, String>;
    /// The command line's CSV of the curve (`t,x,y[,z]`) at its default number of samples
    /// (10 per input point, at least 200).
    fn csv(&self) -> String;
    /// The command line's SVG picture of the curve over its points, with the curvature comb,
    /// titled `title`.
    fn svg(&self, title: &str) -> Result<String, String>;
}

struct Built<C, const D: usize> {
    curve: C,
    points: Vec<Point<D>>,
    parameters: Vec<f64>,
}

impl<C, const D: usize> BuiltCurve for Built<C, D>
where
    C: Curve<D> + PiecewiseCurve<D> + ToBSplineCurve<D>,
{
    fn samples(&self, n: usize) -> Vec<f64> {
        let n = n.max(2);
        let domain = self.curve.domain();
        let mut out = Vec::with_capacity(9 * n);
        let (mut s, mut last) = (0.0, None::<Point<D>>);
        for k in 0..n {
            let t = domain.start + domain.length() * (k as f64 / (n - 1) as f64);
            let (p, d) = (self.curve.eval(t), self.curve.deriv(t, 1));
            if let Some(q) = last {
                s += p.distance(q);
            }
            last = Some(p);
            out.push(t);
            out.extend((0..3).map(|c| if c < D { p[c] } else { 0.0 }));
            out.extend((0..3).map(|c| if c < D { d[c] } else { 0.0 }));
            out.push(curvature(&self.curve, t));
            out.push(s);
        }
        out
    }

    fn breaks(&self) -> Vec<f64> {
        self.curve.breakpoints()
    }

    fn parameters(&self) -> Vec<f64> {
        self.parameters.clone()
    }

    fn profile(&self, per_piece: usize) -> Vec<f64> {
        curvature_profile(&self.curve, per_piece)
            .iter()
            .flat_map(|c| [c.t, c.s, c.curvature])
            .collect()
    }

    fn bspline_size(&self) -> (usize, usize) {
        match self.curve.to_bspline() {
            Ok(b) => (b.degree(), b.control_points().len()),
            Err(_) => (0, 0),
        }
    }

    fn csv(&self) -> String {
        let n = default_curve_samples(self.points.len());
        let (ts, samples) = sample_curve(&self.curve, n);
        let mut out = Vec::new();
        // Writing into memory cannot fail.
        let _ = render_curve_csv(&ts, &samples, &mut out);
        String::from_utf8_lossy(&out).into_owned()
    }

    fn svg(&self, title: &str) -> Result<String, String> {
        let drawing = CurveDrawing {
            title,
            input: &self.points,
            closed_input: self.curve.is_closed(),
            comb: true,
        };
        render_curve_svg(
            &self.curve,
            default_curve_samples(self.points.len()),
            &drawing,
        )
        .map_err(|e| e.to_string())
    }

    fn cad(&self, format: OutputFormat, name: &str, input: &str) -> Result<String, String> {
        let bspline = self
            .curve
            .to_bspline()
            .map_err(|e| format!("{input}: {e}"))?;
        cad_curve_text(&bspline, &self.points, format, name, Path::new(input))
            .map(|(text, _)| text)
            .map_err(|e| e.to_string())
    }
}

/// Builds the curve `request` asks for through `points` (read from `input`, which errors
/// name as the command line does).
pub fn build_curve<const D: usize>(
    points: &[Point<D>],
    request: &CurveRequest,
    input: &str,
) -> Result<Box<dyn BuiltCurve>, String> {
    let context = |e: karkas::Error| format!("{input}: {e}");
    let kept = points.to_vec();
    Ok(match request.method.as_str() {
        "ll" | "ll-interpolate" => {
            let build = if request.method == "ll" {
                LlCurve::new
            } else {
                LlCurve::interpolating
            };
            let curve = build(points, request.order, request.closed).map_err(context)?;
            Box::new(Built {
                curve,
                points: kept,
                parameters: Vec::new(),
            })
        }
        "spline" => {
            let ends = if request.closed {
                SplineEnds::Periodic
            } else if request.ends == "natural" {
                SplineEnds::Natural
            } else {
                SplineEnds::NotAKnot
            };
            let param = match request.param.as_str() {
                "uniform" => CurveParameterization::Uniform,
                "centripetal" => CurveParameterization::Centripetal,
                _ => CurveParameterization::ChordLength,
            };
            let curve = CubicSpline::through(points, param, ends).map_err(context)?;
            Box::new(Built {
                curve,
                points: kept,
                parameters: Vec::new(),
            })
        }
        "fit" => {
            let mut options = FitOptions {
                eps: request.eps,
                corners: request.corners.clone(),
                fairness: DEFAULT_FAIRNESS,
                smoothing: None,
                ..Default::default()
            };
            let fit = if request.knots.is_empty() {
                fit_curve_adaptive(points, request.tolerance, &options)
                    .map_err(context)?
                    .fit
            } else {
                if request.start.len() == points.len() {
                    options.start = StartParameters::Given(request.start.clone());
                }
                fit_curve(points, &request.knots, &options).map_err(context)?
            };
            Box::new(Built {
                curve: fit.spline,
                points: kept,
                parameters: fit.parameters,
            })
        }
        other => return Err(format!("unknown method '{other}'")),
    })
}
