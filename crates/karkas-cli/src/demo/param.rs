//! Kuznetsov and Filatov (parameterization and bicubic interpolation): the table of Hausdorff errors of
//! frames laid along the lines of curvature or turned away from them (docs/methods.md §5), with
//! the paper's figures beside ours. Writes every frame's nodes (grid CSV) and interpolant
//! (OBJ mesh).

use super::common::{write_viewer, Finding, Output};
use super::param_experiment::{helix_experiment, seed_experiments, SeedExperiment};
use crate::output::samples::sample_surface;
use anyhow::{Context, Result};
use karkas::param::BicubicSurface;
use karkas::{Point3, Surface};
use karkas_io::obj::write_surface_obj;
use karkas_io::scene::{write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::write::write_grid_csv;

/// Runs the seven rows of the paper's table and the extra helix frame into `out`.
pub fn run(out: &Output) -> Result<Vec<Finding>> {
    let mut findings = Vec::new();
    for row in seed_experiments()
        .into_iter()
        .chain(std::iter::once(helix_experiment()))
    {
        findings.push(experiment(out, &row)?);
    }
    Ok(findings)
}

/// A file name from a label: `cylinder, both axes turned 30 deg` -> `004-cylinder-both-axes-turned-30-deg`.
fn slug(label: &str) -> String {
    let words: Vec<&str> = label
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    format!("004-{}", words.join("-"))
}

fn experiment(out: &Output, row: &SeedExperiment) -> Result<Finding> {
    let outcome = row
        .run()
        .with_context(|| format!("Kuznetsov and Filatov, {}", row.label))?;
    let name = slug(row.label);
    write_grid_csv(&out.file(format!("{name}-nodes.csv")), &outcome.nodes)?;
    let (nu, nv) = (41, 121);
    let (_, _, mesh) = sample_surface(&outcome.surface, nu, nv);
    write_surface_obj(&out.file(format!("{name}.obj")), nu, nv, &mesh)?;
    let frame = frame_lines(&outcome.surface);
    write_viewer(
        out,
        &format!("{name}.html"),
        &format!(
            "Kuznetsov and Filatov: {}, bicubic interpolant of the 5 x 9 frame",
            row.label
        ),
        (nu, nv),
        &mesh,
        Some(outcome.nodes.clone()),
        vec![("parameter lines through the nodes", frame.clone())],
    )?;
    let title = format!(
        "Kuznetsov and Filatov: {}, bicubic interpolant of the 5 x 9 frame, Hausdorff error {:.4}",
        row.label, outcome.error.distance
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
                label: "parameter lines through the nodes",
                lines: &frame,
                rgb: (20, 60, 200),
                width: 1.4,
            }],
            view: View {
                azimuth: 30.0,
                elevation: 25.0,
            },
        },
    )?;
    Ok(Finding {
        example: format!("004 {}", row.label),
        measure: "two-sided Hausdorff error, 5 x 9 frame".into(),
        value: outcome.error.distance,
        paper: row.paper_error,
        detail: false,
    })
}

/// The interpolant's lines through the nodes: the parameter lines at every knot, sampled
/// densely so that they lie on the surface.
fn frame_lines(surface: &BicubicSurface<3>) -> Vec<Vec<Point3>> {
    const SAMPLES: usize = 97;
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let along_v = surface.knots_u().iter().map(|&u| {
        (0..SAMPLES)
            .map(|k| surface.eval(u, dv.uniform(k, SAMPLES)))
            .collect()
    });
    let along_u = surface.knots_v().iter().map(|&v| {
        (0..SAMPLES)
            .map(|k| surface.eval(du.uniform(k, SAMPLES), v))
            .collect()
    });
    along_v.chain(along_u).collect()
}
