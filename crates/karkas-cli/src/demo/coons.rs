//! Chashnikov (generalized Coons surfaces): the two-by-two-patch network of the paper's figure 3
//! and a 7 x 5 fuselage network, each from a closed-form reference body. Lagrange against
//! spline Gordon surfaces side by side, the composite Coons surfaces as meshes, and the
//! distance of every surface to its body (foot-point projection onto the closed form).

use super::common::{write_text, write_viewer, Finding, Output};
use super::coons_data::{
    body_line, curve_family_csv, figure_3_sheet, fuselage, fuselage_point_lists, Body,
    FUSELAGE_STATIONS, FUSELAGE_STRINGERS,
};
use crate::output::samples::sample_surface;
use anyhow::Result;
use karkas::coons::{
    Along, BlendingFamily, CoonsSurface, CrossDerivatives, CurveFit, CurveNetwork, NetworkAxis,
    PiecewiseHermiteBlending, PointNetwork, SplineEnds, DEFAULT_TOLERANCE,
};
use karkas::{Point2, Point3, Surface};
use karkas_io::obj::write_surface_obj;
use karkas_io::scene::direction_name;
use karkas_io::svg::{write_lines_svg, LineGroup, LinesPlot};
use std::f64::consts::TAU;
use std::path::Path;

/// Samples per direction when measuring the distance to the body.
const MEASURE: usize = 81;

/// The network of `body` on the nodes: v-curves at the `u` nodes, u-curves at the `v` nodes.
fn network_of(body: Body, u_axis: &NetworkAxis, v_axis: &NetworkAxis) -> Result<CurveNetwork<3>> {
    let v_curves = u_axis
        .nodes()
        .iter()
        .map(|&u| body_line(body, Along::V, u, 0))
        .collect();
    let u_curves = v_axis
        .nodes()
        .iter()
        .map(|&v| body_line(body, Along::U, v, 0))
        .collect();
    Ok(CurveNetwork::new(
        u_axis.clone(),
        v_curves,
        v_axis.clone(),
        u_curves,
    )?)
}

pub fn figure_3(out: &Output) -> Result<Vec<Finding>> {
    let body = figure_3_sheet();
    let axis = NetworkAxis::uniform(3, false)?; // the paper's nodes 0, 1, 2 (m = n = 2)
    let net = network_of(body, &axis, &axis)?;
    let exact = CrossDerivatives {
        v_curves: (0..3)
            .map(|i| body_line(body, Along::V, i as f64, 1))
            .collect(),
        u_curves: (0..3)
            .map(|j| body_line(body, Along::U, j as f64, 1))
            .collect(),
    };
    let lagrange = CoonsSurface::gordon(&net, DEFAULT_TOLERANCE)?;
    let natural = CoonsSurface::gordon_spline(&net, SplineEnds::Natural, DEFAULT_TOLERANCE)?;
    let composite = CoonsSurface::composite(&net, Some(&exact), DEFAULT_TOLERANCE)?;
    let derived = CoonsSurface::composite(&net, None, DEFAULT_TOLERANCE)?;

    let sample = |along: Along, at: f64| -> Vec<Point3> {
        (0..=40)
            .map(|k| {
                let t = 2.0 * k as f64 / 40.0;
                match along {
                    Along::U => body.eval(t, at),
                    Along::V => body.eval(at, t),
                }
            })
            .collect()
    };
    let u_lists: Vec<_> = (0..3).map(|j| sample(Along::U, j as f64)).collect();
    let v_lists: Vec<_> = (0..3).map(|i| sample(Along::V, i as f64)).collect();
    write_network(out, "coons-fig3", &u_lists, &v_lists)?;

    let panels = [&lagrange, &natural, &composite];
    let width = 11.0;
    let pictures: Vec<Wireframe> = panels
        .iter()
        .enumerate()
        .map(|(k, s)| wireframe(s, 13, 13, Point2::new([width * k as f64, 0.0]), sheet_view))
        .collect();
    write_panels(
        &out.file("coons-fig3-gordon-vs-spline.svg"),
        "Chashnikov's fig. 3 network: Lagrange Gordon | natural-spline Gordon | composite Coons",
        &pictures,
        axonometric_axes(SHEET_VIEW),
    )?;
    write_mesh(
        out,
        "coons-fig3-composite",
        "Chashnikov's fig. 3 network: composite Coons surface",
        &composite,
        81,
        81,
    )?;

    body_findings(
        out,
        "001 fig. 3 network, 3 x 3 curves",
        (
            "coons-fig3-deviation.svg",
            "fig. 3, distance to the body",
            "u",
        ),
        body,
        &[
            ("Lagrange Gordon", &lagrange),
            ("natural-spline Gordon", &natural),
            ("composite Coons (exact A, B)", &composite),
            ("composite Coons (derived A, B)", &derived),
        ],
        3,
    )
    .and_then(|mut findings| {
        findings.extend(blending_figures(out)?);
        Ok(findings)
    })
}

/// Chashnikov's figures 1 and 2: the piecewise Hermite blending functions `H^u_{2i}` and
/// `H^u_{2i+1}` of (17) (the library's family of the composite Coons surface) on the integer
/// nodes `0..4`, drawn for `i = 2`, with their extreme values as rows: `H_{2i}` peaks at 1 at
/// its node, `H_{2i+1}` at `4/27` (`u = i -+ 1/3`, where the Hermite cubics `s (1 - s)^2` and
/// `-s^2 (1 - s)` peak).
fn blending_figures(out: &Output) -> Result<Vec<Finding>> {
    const NODES: [f64; 5] = [0.0, 1.0, 2.0, 3.0, 4.0];
    const I: usize = 2;
    const SAMPLES: usize = 801;
    let family = PiecewiseHermiteBlending::new(&NODES)?;
    let mut weights = vec![0.0; family.len()];
    let (mut value, mut slope) = (Vec::new(), Vec::new());
    for k in 0..SAMPLES {
        let t = NODES[4] * k as f64 / (SAMPLES - 1) as f64;
        let nonzero = family.eval_into(t, 0, &mut weights);
        let weight = |j: usize| {
            if nonzero.contains(&j) {
                weights[j]
            } else {
                0.0
            }
        };
        value.push(Point2::new([t, weight(2 * I)]));
        slope.push(Point2::new([t, weight(2 * I + 1)]));
    }
    let axis = vec![vec![Point2::new([0.0, 0.0]), Point2::new([NODES[4], 0.0])]];
    let mut findings = Vec::new();
    for (figure, name, file, line, measure) in [
        (
            1,
            "H_2i",
            "coons-blending-fig1.svg",
            &value,
            "largest value (1 at its node u = i)",
        ),
        (
            2,
            "H_2i+1",
            "coons-blending-fig2.svg",
            &slope,
            "largest |value| (4/27 at u = i -+ 1/3)",
        ),
    ] {
        let title = format!(
            "Chashnikov, fig. {figure}: the blending function {name} of (17) for i = {I} on the \
             nodes 0..4 (cubic Hermite pieces)"
        );
        write_lines_svg(
            &out.file(file),
            &LinesPlot {
                title: &title,
                axes: ("u", name),
                groups: &[
                    LineGroup {
                        lines: &axis,
                        rgb: (150, 150, 150),
                        width: 1,
                    },
                    LineGroup {
                        lines: std::slice::from_ref(line),
                        rgb: (20, 60, 200),
                        width: 2,
                    },
                ],
            },
        )?;
        let peak = line.iter().map(|p| p[1].abs()).fold(0.0, f64::max);
        findings.push(Finding::new(
            format!("001 fig. {figure}: blending function {name}, i = {I}"),
            measure,
            peak,
        ));
    }
    Ok(findings)
}

/// The checks of surfaces through a network cut from `body`: the largest miss of a network
/// curve over all of them (Prop. 1), then the distance of each `(name, surface)` to the body;
/// the distance profiles of the first `profiled` are drawn into `file` (title, axis name).
fn body_findings(
    out: &Output,
    example: &str,
    (file, title, axis): (&str, &str, &str),
    body: Body,
    surfaces: &[(&str, &CoonsSurface<3>)],
    profiled: usize,
) -> Result<Vec<Finding>> {
    let miss = surfaces
        .iter()
        .map(|(_, s)| network_miss(s, body))
        .fold(0.0, f64::max);
    let same = |u: f64, v: f64| (u, v);
    let measured: Vec<Deviation> = surfaces
        .iter()
        .map(|(_, s)| Deviation::measure(s, body, &same))
        .collect();
    write_profiles(
        &out.file(file),
        title,
        (axis, "distance"),
        &measured[..profiled],
    )?;
    let mut findings = vec![Finding::new(
        example,
        "largest miss of a network curve (Prop. 1)",
        miss,
    )];
    for ((name, _), deviation) in surfaces.iter().zip(&measured) {
        let measure = format!("distance to the body, {name}");
        findings.push(Finding::new(example, measure, deviation.max()));
    }
    Ok(findings)
}

pub fn fuselage_network(out: &Output) -> Result<Vec<Finding>> {
    let body = fuselage();
    let u_axis = NetworkAxis::open(FUSELAGE_STATIONS.to_vec())?;
    let angles: Vec<f64> = (0..FUSELAGE_STRINGERS)
        .map(|j| TAU * j as f64 / FUSELAGE_STRINGERS as f64)
        .collect();
    let v_axis = NetworkAxis::closed(angles, TAU)?;
    let net = network_of(body, &u_axis, &v_axis)?;
    let lagrange = CoonsSurface::gordon(&net, DEFAULT_TOLERANCE)?;
    let spline = CoonsSurface::gordon_spline(&net, SplineEnds::NotAKnot, DEFAULT_TOLERANCE)?;
    let composite = CoonsSurface::composite(&net, None, DEFAULT_TOLERANCE)?;

    // The same network as point lists, through the command line's path.
    let (frames, stringers) = fuselage_point_lists();
    write_network(out, "fuselage", &stringers, &frames)?;
    let points = PointNetwork::new(&frames, &stringers, CurveFit::CubicSpline, 1e-6)?;
    let from_points =
        CoonsSurface::gordon_spline(points.network(), SplineEnds::NotAKnot, DEFAULT_TOLERANCE)?;
    // Its parameters: u runs 0..1 uniformly per span between frames, v = angle / 2 pi.
    let nodes = points.network().u_axis().nodes().to_vec();
    let station = move |u: f64| {
        let l = nodes.partition_point(|&x| x <= u).clamp(1, nodes.len() - 1) - 1;
        let s = (u - nodes[l]) / (nodes[l + 1] - nodes[l]);
        FUSELAGE_STATIONS[l] + s * (FUSELAGE_STATIONS[l + 1] - FUSELAGE_STATIONS[l])
    };

    let above = wireframe(&lagrange, 49, 21, Point2::new([0.0, 0.0]), body_view);
    let below = wireframe(&spline, 49, 21, Point2::new([0.0, -3.6]), body_view);
    write_panels(
        &out.file("fuselage-gordon-vs-spline.svg"),
        "Chashnikov, 7 frames x 5 stringers: Lagrange Gordon (top), spline Gordon (bottom)",
        &[above, below],
        axonometric_axes(BODY_VIEW),
    )?;
    write_mesh(
        out,
        "fuselage-composite",
        "Chashnikov, 7 frames x 5 stringers: composite Coons surface",
        &composite,
        145,
        73,
    )?;

    let example = "001 fuselage, 7 x 5 curves";
    let mut findings = body_findings(
        out,
        example,
        (
            "fuselage-deviation.svg",
            "fuselage, distance to the body",
            "x",
        ),
        body,
        &[
            ("Lagrange Gordon", &lagrange),
            ("spline Gordon", &spline),
            ("composite Coons (derived A, B)", &composite),
        ],
        2,
    )?;
    findings.push(Finding::new(
        example,
        "distance to the body, spline Gordon from points",
        Deviation::measure(&from_points, body, &|u, v| (station(u), TAU * v)).max(),
    ));
    Ok(findings)
}

/// Writes the curves of a network as `{stem}-u-curves.csv` and `{stem}-v-curves.csv`.
fn write_network(out: &Output, stem: &str, u: &[Vec<Point3>], v: &[Vec<Point3>]) -> Result<()> {
    write_text(
        &out.file(format!("{stem}-u-curves.csv")),
        &curve_family_csv(u),
    )?;
    write_text(
        &out.file(format!("{stem}-v-curves.csv")),
        &curve_family_csv(v),
    )
}

/// Writes the OBJ mesh `{stem}.obj` and the viewer page `{stem}.html` of `surface`.
fn write_mesh(
    out: &Output,
    stem: &str,
    title: &str,
    surface: &CoonsSurface<3>,
    nu: usize,
    nv: usize,
) -> Result<()> {
    let (_, _, mesh) = sample_surface(surface, nu, nv);
    write_surface_obj(&out.file(format!("{stem}.obj")), nu, nv, &mesh)?;
    write_viewer(
        out,
        &format!("{stem}.html"),
        title,
        (nu, nv),
        &mesh,
        None,
        Vec::new(),
    )
}

/// The largest distance between the network curves and the surface along its node lines.
fn network_miss(surface: &CoonsSurface<3>, body: Body) -> f64 {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let mut worst: f64 = 0.0;
    for k in 0..MEASURE {
        let (u, v) = (du.uniform(k, MEASURE), dv.uniform(k, MEASURE));
        for f in surface
            .u_family()
            .functionals()
            .iter()
            .filter(|l| l.order() == 0)
        {
            worst = worst.max(surface.eval(f.at(), v).distance(body.eval(f.at(), v)));
        }
        for f in surface
            .v_family()
            .functionals()
            .iter()
            .filter(|l| l.order() == 0)
        {
            worst = worst.max(surface.eval(u, f.at()).distance(body.eval(u, f.at())));
        }
    }
    worst
}

/// The distances from a surface's samples (`MEASURE x MEASURE`, uniform over the domain) to
/// the body: each sample projected onto the body by Gauss–Newton from the parameters
/// `to_body(u, v)`.
struct Deviation {
    /// The body's `u` of each sample row.
    along: Vec<f64>,
    /// The largest distance in each sample row (over `v`).
    row_max: Vec<f64>,
}

impl Deviation {
    fn measure(
        surface: &CoonsSurface<3>,
        body: Body,
        to_body: &dyn Fn(f64, f64) -> (f64, f64),
    ) -> Deviation {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let mut along = Vec::with_capacity(MEASURE);
        let mut row_max = Vec::with_capacity(MEASURE);
        for a in 0..MEASURE {
            let u = du.uniform(a, MEASURE);
            along.push(to_body(u, dv.start).0);
            let worst = (0..MEASURE)
                .map(|b| {
                    let v = dv.uniform(b, MEASURE);
                    let (bu, bv) = to_body(u, v);
                    foot_point_distance(body, surface.eval(u, v), bu, bv)
                })
                .fold(0.0, f64::max);
            row_max.push(worst);
        }
        Deviation { along, row_max }
    }

    fn max(&self) -> f64 {
        self.row_max.iter().copied().fold(0.0, f64::max)
    }
}

/// The deviation profiles in one picture, magnified by a round factor (1, 2 or 5 times a power
/// of ten, named in the axis) so that the largest is about a third of the length of the
/// range: red, blue, green in order.
fn write_profiles(
    path: &Path,
    title: &str,
    axes: (&str, &str),
    profiles: &[Deviation],
) -> Result<()> {
    let largest = profiles.iter().map(Deviation::max).fold(0.0, f64::max);
    let range = profiles
        .iter()
        .flat_map(|p| p.along.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &x| {
            (lo.min(x), hi.max(x))
        });
    let length = range.1 - range.0;
    let factor = if largest > 0.0 && length > 0.0 {
        let target = 0.35 * length / largest;
        let decade = 10f64.powf(target.log10().floor());
        [5.0, 2.0, 1.0]
            .into_iter()
            .map(|m| m * decade)
            .find(|&f| f <= target)
            .unwrap_or(decade)
    } else {
        1.0
    };
    let colours = [(200, 30, 30), (30, 70, 200), (20, 150, 60)];
    let lines: Vec<Vec<Vec<Point2>>> = profiles
        .iter()
        .map(|p| {
            vec![p
                .along
                .iter()
                .zip(&p.row_max)
                .map(|(&x, &d)| Point2::new([x, d * factor]))
                .collect()]
        })
        .collect();
    let axis = vec![vec![
        Point2::new([range.0, 0.0]),
        Point2::new([range.1, 0.0]),
    ]];
    let mut groups = vec![LineGroup {
        lines: &axis,
        rgb: (150, 150, 150),
        width: 1,
    }];
    groups.extend(lines.iter().zip(colours).map(|(l, rgb)| LineGroup {
        lines: l,
        rgb,
        width: 2,
    }));
    let legend = match profiles.len() {
        2 => format!("{title}: red Lagrange, blue spline"),
        _ => format!("{title}: red Lagrange, blue spline, green composite"),
    };
    let y_axis = format!("{} (x {factor})", axes.1);
    write_lines_svg(
        path,
        &LinesPlot {
            title: &legend,
            axes: (axes.0, &y_axis),
            groups: &groups,
        },
    )?;
    Ok(())
}

/// The distance from `p` to the body near the parameters `(u, v)`.
fn foot_point_distance(body: Body, p: Point3, mut u: f64, mut v: f64) -> f64 {
    for _ in 0..40 {
        let r = p - body.eval(u, v);
        let (su, sv) = (body.deriv(u, v, 1, 0), body.deriv(u, v, 0, 1));
        let (a, b, c) = (su.dot(su), su.dot(sv), sv.dot(sv));
        let det = a * c - b * b;
        if det.abs() <= 1e-300 {
            break;
        }
        let (ru, rv) = (su.dot(r), sv.dot(r));
        let step_u = (c * ru - b * rv) / det;
        let step_v = (a * rv - b * ru) / det;
        u = body.u.clamp(u + step_u);
        v = if body.closed_v {
            v + step_v
        } else {
            body.v.clamp(v + step_v)
        };
        if step_u.abs() + step_v.abs() < 1e-14 {
            break;
        }
    }
    p.distance(body.eval(u, v))
}

/// The view of the sheet (azimuth and elevation in degrees): from the front left, above.
const SHEET_VIEW: (f64, f64) = (-35.0, 30.0);
/// The view of the fuselage: from the side, a little ahead of the nose, above.
const BODY_VIEW: (f64, f64) = (18.0, 22.0);

/// The view of the sheet.
fn sheet_view(p: Point3) -> Point2 {
    axonometric(p, SHEET_VIEW.0, SHEET_VIEW.1)
}

/// The view of the fuselage.
fn body_view(p: Point3) -> Point2 {
    axonometric(p, BODY_VIEW.0, BODY_VIEW.1)
}

/// The names of [`axonometric`]'s picture directions (across, up) in model terms.
fn axonometric_axes((azimuth, elevation): (f64, f64)) -> (String, String) {
    let (az, el) = (azimuth.to_radians(), elevation.to_radians());
    let right = Point3::new([az.cos(), az.sin(), 0.0]);
    let up = Point3::new([az.sin() * el.sin(), -az.cos() * el.sin(), el.cos()]);
    (direction_name(right), direction_name(up))
}

/// An axonometric projection: the camera turned `azimuth` degrees about z from the -y side
/// and raised `elevation` degrees.
fn axonometric(p: Point3, azimuth: f64, elevation: f64) -> Point2 {
    let (az, el) = (azimuth.to_radians(), elevation.to_radians());
    let right = p[0] * az.cos() + p[1] * az.sin();
    let depth = p[0] * az.sin() - p[1] * az.cos();
    let up = depth * el.sin() + p[2] * el.cos();
    Point2::new([right, up])
}

/// A wireframe in the view: iso-lines of the surface and its network curves.
struct Wireframe {
    lines: Vec<Vec<Point2>>,
    network: Vec<Vec<Point2>>,
}

/// `nu` lines `u = const` and `nv` lines `v = const` (ends included), and the network curves
/// (the node lines of value functionals), projected with `view` and moved by `offset`.
fn wireframe(
    surface: &CoonsSurface<3>,
    nu: usize,
    nv: usize,
    offset: Point2,
    view: fn(Point3) -> Point2,
) -> Wireframe {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let line = |fixed_u: Option<f64>, fixed_v: Option<f64>| -> Vec<Point2> {
        (0..=160)
            .map(|k| {
                let u = fixed_u.unwrap_or_else(|| du.uniform(k, 161));
                let v = fixed_v.unwrap_or_else(|| dv.uniform(k, 161));
                view(surface.eval(u, v)) + offset
            })
            .collect()
    };
    let mut lines: Vec<Vec<Point2>> = (0..nu)
        .map(|k| line(Some(du.uniform(k, nu)), None))
        .collect();
    lines.extend((0..nv).map(|k| line(None, Some(dv.uniform(k, nv)))));
    let values = |f: &karkas::coons::FamilyRef| -> Vec<f64> {
        f.functionals()
            .iter()
            .filter(|l| l.order() == 0)
            .map(|l| l.at())
            .collect()
    };
    let mut network: Vec<Vec<Point2>> = values(surface.u_family())
        .into_iter()
        .map(|u| line(Some(u), None))
        .collect();
    network.extend(
        values(surface.v_family())
            .into_iter()
            .map(|v| line(None, Some(v))),
    );
    Wireframe { lines, network }
}

/// The wireframes in one picture: iso-lines thin and grey-blue, network curves red.
fn write_panels(
    path: &Path,
    title: &str,
    panels: &[Wireframe],
    (across, up): (String, String),
) -> Result<()> {
    let lines: Vec<Vec<Point2>> = panels.iter().flat_map(|p| p.lines.clone()).collect();
    let network: Vec<Vec<Point2>> = panels.iter().flat_map(|p| p.network.clone()).collect();
    write_lines_svg(
        path,
        &LinesPlot {
            title,
            axes: (&across, &up),
            groups: &[
                LineGroup {
                    lines: &lines,
                    rgb: (90, 120, 190),
                    width: 1,
                },
                LineGroup {
                    lines: &network,
                    rgb: (200, 30, 30),
                    width: 2,
                },
            ],
        },
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_demo_shows_what_it_claims() {
        let dir = tempfile::tempdir().unwrap();
        let out = Output::new(dir.path());
        let mut findings = figure_3(&out).unwrap();
        findings.extend(fuselage_network(&out).unwrap());
        let value = |example: &str, measure: &str| {
            findings
                .iter()
                .find(|f| f.example.starts_with(example) && f.measure.contains(measure))
                .unwrap_or_else(|| panic!("no finding {example} / {measure}"))
                .value
        };
        for example in ["001 fig. 3", "001 fuselage"] {
            assert!(value(example, "Prop. 1") < 1e-12);
            // Spline blending beats Lagrange blending against the body.
            let lagrange = value(example, "Lagrange Gordon");
            assert!(
                value(example, "spline Gordon") < 0.2 * lagrange,
                "{example}"
            );
        }
        // Exact cross-derivatives bring the composite surface closer than the Gordon ones.
        assert!(
            value("001 fig. 3", "composite Coons (exact")
                < value("001 fig. 3", "natural-spline Gordon")
        );
        // The point-list path lands within 10% of the closed-form curves' result.
        let from_points = value("001 fuselage", "from points");
        assert!(from_points < 1.1 * value("001 fuselage", "distance to the body, spline Gordon"));
        for name in [
            "coons-fig3-gordon-vs-spline.svg",
            "coons-fig3-deviation.svg",
            "coons-fig3-composite.obj",
            "fuselage-gordon-vs-spline.svg",
            "fuselage-deviation.svg",
            "fuselage-composite.obj",
            "fuselage-u-curves.csv",
            "fuselage-v-curves.csv",
        ] {
            assert!(dir.path().join(name).exists(), "{name}");
        }
    }
}
