//! Kuznetsov and Filatov (Theorem 2.1; docs/methods.md §5): turned frames re-laid along the
//! lines of curvature of their own bicubic interpolants (`karkas surface relay`), with the
//! Hausdorff errors of the turned, re-laid and principal frames side by side. Writes every
//! re-laid frame's nodes (grid CSV).
//!
//! Two inputs per turned frame: the table's own 5 x 9 frame, and a frame along the same lines
//! [`DENSITY`] times denser and [`REACH`] times longer in every open direction (the surface
//! known by more points), re-laid onto 5 x 9 nodes with the principal frame's arc-length
//! steps (shrunk by [`STEP_FACTORS`] until the net fits the input's domain). The re-laid nodes
//! lie on the input's interpolant, so they are only as accurate as it is: from the coarse
//! input the error stays at the turned frame's level, from the dense input it falls to that
//! of the principal frame of the same region (the nodes at the re-laid rows' heights and
//! columns' angles, on the exact surface).

use super::common::{Finding, Output};
use super::param_experiment::{seed_experiments, ExperimentOutcome, SeedExperiment, SeedSurface};
use crate::output::samples::sample_surface;
use anyhow::{Context, Result};
use karkas::implicit::{Cylinder, Hyperboloid, ImplicitSurface, NetDirections};
use karkas::measure::hausdorff_surface_implicit;
use karkas::param::{relay_grid, BicubicSurface, GridParameterization, RelaidGrid, RelayOptions};
use karkas::{Grid, Point3};
use karkas_io::scene::{write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::write::write_grid_csv;
use std::f64::consts::{PI, TAU};

/// Samples of the interpolant in the Hausdorff distance (as the frames of the table).
const SAMPLES: (usize, usize) = (64, 160);

/// The cylinder's frames turned by 30 and 45 degrees (plane sections, as in the table) and
/// the hyperboloid's nets turned by 30 and 45 degrees (both families, open lines), each
/// beside the principal frame of its surface.
pub fn run(out: &Output) -> Result<Vec<Finding>> {
    let table = seed_experiments();
    let cylinder_principal = table[0].run().context("the cylinder's principal frame")?;
    let hyperboloid_principal = table[5]
        .run()
        .context("the hyperboloid's principal frame")?;
    let mut cases: Vec<(SeedExperiment, f64, &SeedExperiment)> = vec![
        (
            table[1].clone(),
            cylinder_principal.error.distance,
            &table[0],
        ),
        (
            table[2].clone(),
            cylinder_principal.error.distance,
            &table[0],
        ),
    ];
    for (degrees, label) in [
        (30.0f64, "hyperboloid, both axes turned 30 deg"),
        (45.0, "hyperboloid, both axes turned 45 deg"),
    ] {
        let mut net = table[5].net;
        net.directions = NetDirections::Turned {
            angle: degrees.to_radians(),
        };
        net.closed_v = false;
        let row = SeedExperiment {
            label,
            paper_error: None,
            surface: SeedSurface::Hyperboloid,
            net,
        };
        cases.push((row, hyperboloid_principal.error.distance, &table[5]));
    }
    let mut findings = Vec::new();
    for (row, principal, principal_net) in cases {
        let turned = row
            .run()
            .with_context(|| format!("Kuznetsov and Filatov, {}", row.label))?;
        let (m, n) = row.net.nodes;
        for density in [1, DENSITY] {
            let input = if density == 1 {
                turned.clone()
            } else {
                let mut dense = row.clone();
                // Twice the extent in every open direction, so that the principal frame's
                // region fits inside; a closed direction already runs round the surface.
                let v_reach = if row.net.closed_v { 1 } else { REACH };
                dense.net.nodes = (
                    (m - 1) * density * REACH + 1,
                    (n - 1) * density * v_reach + 1,
                );
                dense.net.steps = (
                    row.net.steps.0 / density as f64,
                    row.net.steps.1 / density as f64,
                );
                dense
                    .run()
                    .with_context(|| format!("Kuznetsov and Filatov, {}, dense", row.label))?
            };
            relay_case(
                out,
                &row,
                &turned,
                &input,
                principal,
                principal_net,
                &mut findings,
            )?;
        }
    }
    Ok(findings)
}

/// How many times denser (in each direction) the dense input frames are than the table's.
const DENSITY: usize = 2;

/// How many times the table frame's extent the dense input frames span in an open direction.
const REACH: usize = 3;

/// Re-lays `input` (the turned frame of `row` itself, or a denser frame along the same lines)
/// onto a frame of the table's size and records the three errors.
fn relay_case(
    out: &Output,
    row: &SeedExperiment,
    turned: &ExperimentOutcome,
    input: &ExperimentOutcome,
    principal: f64,
    principal_net: &SeedExperiment,
    findings: &mut Vec<Finding>,
) -> Result<()> {
    let dense = input.nodes.rows() != turned.nodes.rows();
    let options = RelayOptions {
        size: Some((turned.nodes.rows(), turned.nodes.cols())),
        closed: (false, row.net.closed_v),
        ..RelayOptions::default()
    };
    let relaid = if dense {
        relay_on_principal_steps(input, &options, principal_net)
    } else {
        relay_grid(&input.nodes, &options).map_err(anyhow::Error::from)
    }
    .with_context(|| format!("re-laying {}", row.label))?;
    let (relaid_error, same_region) = match row.surface {
        SeedSurface::Cylinder => relaid_error(&relaid.nodes, &Cylinder { radius: 1.0 }, |_| 1.0),
        SeedSurface::Hyperboloid => {
            relaid_error(&relaid.nodes, &Hyperboloid { neck_radius: 1.0 }, |z| {
                (1.0 + z * z).sqrt()
            })
        }
    }?;
    // A dense input's re-laid frame lies elsewhere on the surface than the table's
    // principal frame: it is compared with the principal frame of its own region.
    let principal = if dense { same_region } else { principal };
    let (name, example, label) = case_names(row, input, dense);
    write_grid_csv(&out.file(format!("{name}-nodes.csv")), &relaid.nodes)?;
    write_picture(out, &name, &label, &relaid.nodes, relaid_error)?;
    findings.push(
        Finding::new(
            &example,
            "turned frame: Hausdorff error",
            turned.error.distance,
        )
        .detail(),
    );
    if dense {
        findings.push(
            Finding::new(
                &example,
                "dense turned input frame: Hausdorff error",
                input.error.distance,
            )
            .detail(),
        );
    }
    findings.push(Finding::new(
        &example,
        "re-laid along lines of curvature: Hausdorff error",
        relaid_error,
    ));
    let measure = if dense {
        "principal frame of the same region: Hausdorff error"
    } else {
        "principal frame: Hausdorff error"
    };
    findings.push(Finding::new(&example, measure, principal).detail());
    Ok(())
}

/// The file name, the report's example and the picture's label of a case: the row's
/// label, with the input's size when dense.
fn case_names(
    row: &SeedExperiment,
    input: &ExperimentOutcome,
    dense: bool,
) -> (String, String, String) {
    let words: Vec<&str> = row
        .label
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    let (rows, cols) = (input.nodes.rows(), input.nodes.cols());
    if dense {
        (
            format!("004-relaid-{}-from-{rows}x{cols}", words.join("-")),
            format!("004 {}, re-laid from {rows} x {cols}", row.label),
            format!("{}, re-laid from {rows} x {cols} nodes", row.label),
        )
    } else {
        (
            format!("004-relaid-{}", words.join("-")),
            format!("004 {}", row.label),
            row.label.to_string(),
        )
    }
}

/// Re-lays a dense input with the principal frame's arc-length steps, or when its net does not
/// fit the input's domain with steps shrunk by [`STEP_FACTORS`].
fn relay_on_principal_steps(
    input: &ExperimentOutcome,
    options: &RelayOptions,
    principal_net: &SeedExperiment,
) -> Result<RelaidGrid> {
    // The principal frame's rows are its circles; the re-laid frame's rows are circles when
    // its `v` lines (rows) are, else its steps are taken the other way round.
    let (mut hu, mut hv) = principal_net.net.steps;
    let trial = relay_grid(&input.nodes, options)?;
    if !rows_are_circles(&trial.nodes) {
        (hu, hv) = (hv, hu);
    }
    let mut last = None;
    for factor in STEP_FACTORS {
        let steps = (hu * factor, hv * factor);
        match relay_grid(
            &input.nodes,
            &RelayOptions {
                steps: Some(steps),
                ..*options
            },
        ) {
            Ok(relaid) => return Ok(relaid),
            Err(e) => last = Some(e),
        }
    }
    Err(last.map_or_else(|| anyhow::anyhow!("no step factor"), anyhow::Error::from))
}

/// The factors the principal frame's steps are tried with on a dense input, largest first.
const STEP_FACTORS: [f64; 6] = [1.0, 0.95, 0.9, 0.8, 0.7, 0.6];

/// The two-sided Hausdorff error of the bicubic interpolant (the paper's chord parameters,
/// not-a-knot) of a re-laid frame of a surface of revolution about `z` (radius `rho(z)`)
/// against the exact patch it covers: the heights of its rows (circles) and the angles of its
/// columns (meridians), or the other way round, sampled in closed form four times denser.
///
/// Returns that error and the error, measured the same way, of the principal frame of the same
/// region: the nodes at the re-laid rows' heights and columns' angles, on the exact surface.
fn relaid_error<I: ImplicitSurface>(
    nodes: &Grid<Point3>,
    implicit: &I,
    rho: impl Fn(f64) -> f64,
) -> Result<(f64, f64)> {
    let surface = BicubicSurface::new(nodes, GridParameterization::default(), false, false)?;
    let circles = if rows_are_circles(nodes) {
        nodes.clone()
    } else {
        nodes.transposed()
    };
    let (m, n) = (circles.rows(), circles.cols());
    let centre = circles.get(m / 2, n / 2);
    let base = centre[1].atan2(centre[0]);
    let angle = |p: &Point3| {
        let a = p[1].atan2(p[0]) - base;
        a - TAU * ((a + PI) / TAU).floor()
    };
    let column_angle = |j: usize| (0..m).map(|i| angle(circles.get(i, j))).sum::<f64>() / m as f64;
    let row_height = |i: usize| (0..n).map(|j| circles.get(i, j)[2]).sum::<f64>() / n as f64;
    let (a0, a1) = (column_angle(0), column_angle(n - 1));
    let (z0, z1) = (row_height(0), row_height(m - 1));
    let (pu, pv) = (4 * (m - 1) + 1, 4 * (n - 1) + 1);
    let mut patch = Vec::with_capacity(pu * pv);
    for a in 0..pu {
        let z = z0 + (z1 - z0) * a as f64 / (pu - 1) as f64;
        let r = rho(z);
        for b in 0..pv {
            let t = base + a0 + (a1 - a0) * b as f64 / (pv - 1) as f64;
            patch.push(Point3::new([r * t.cos(), r * t.sin(), z]));
        }
    }
    let relaid = hausdorff_surface_implicit(&surface, implicit, &patch, SAMPLES)?.distance;
    let mut exact = Vec::with_capacity(m * n);
    for i in 0..m {
        let z = row_height(i);
        for j in 0..n {
            let t = base + column_angle(j);
            exact.push(Point3::new([rho(z) * t.cos(), rho(z) * t.sin(), z]));
        }
    }
    let exact = Grid::from_row_major(m, n, exact)?;
    let principal = BicubicSurface::new(&exact, GridParameterization::default(), false, false)?;
    let principal = hausdorff_surface_implicit(&principal, implicit, &patch, SAMPLES)?.distance;
    Ok((relaid, principal))
}

/// Whether the rows of a frame of a surface of revolution about `z` are its circles: a row
/// keeps its height better than a column does.
fn rows_are_circles(nodes: &Grid<Point3>) -> bool {
    let row_spread = (0..nodes.rows())
        .map(|i| spread((0..nodes.cols()).map(|j| nodes.get(i, j)[2])))
        .fold(0.0, f64::max);
    let col_spread = (0..nodes.cols())
        .map(|j| spread((0..nodes.rows()).map(|i| nodes.get(i, j)[2])))
        .fold(0.0, f64::max);
    row_spread <= col_spread
}

/// `max - min` of the values.
fn spread(values: impl Iterator<Item = f64>) -> f64 {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    hi - lo
}

/// A picture of the re-laid frame's interpolant with its grid lines (lines of curvature).
fn write_picture(
    out: &Output,
    name: &str,
    label: &str,
    nodes: &Grid<Point3>,
    error: f64,
) -> Result<()> {
    let surface = BicubicSurface::new(nodes, GridParameterization::default(), false, false)?;
    let (nu, nv) = (33, 65);
    let (_, _, mesh) = sample_surface(&surface, nu, nv);
    let mut lines: Vec<Vec<Point3>> = (0..nodes.rows()).map(|i| nodes.row(i).to_vec()).collect();
    lines.extend((0..nodes.cols()).map(|j| (0..nodes.rows()).map(|i| *nodes.get(i, j)).collect()));
    let title = format!(
        "Kuznetsov and Filatov: {label}, re-laid along the lines of curvature, Hausdorff error {error:.4}"
    );
    write_scene_svg(
        &out.file(format!("{name}.svg")),
        &Scene {
            title: &title,
            mesh: SceneMesh {
                rows: nu,
                cols: nv,
                points: &mesh,
            },
            curves: &[SceneCurves {
                label: "the re-laid grid's rows and columns",
                lines: &lines,
                rgb: (200, 60, 20),
                width: 1.4,
            }],
            view: View {
                azimuth: 30.0,
                elevation: 25.0,
            },
        },
    )?;
    Ok(())
}
