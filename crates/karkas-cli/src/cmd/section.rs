//! `karkas section`: plane sections of a surface (Aulchenko et al., docs/methods.md §1.4): the
//! LL surface of a grid, the bicubic interpolant of a grid (Kuznetsov and Filatov,
//! docs/methods.md §5) or the Coons / Gordon surface of a curve network (Chashnikov,
//! docs/methods.md §2), each built as the `surface` command of the same name builds it.
//!
//! The planes come from `--plane nx,ny,nz,c` (the plane `nx x + ny y + nz z = c`) and the
//! shorthands `--x X`, `--y Y`, `--z Z` (each repeatable, each taking a comma list). Sections
//! are numbered from 0 over all pieces, planes taken in this order: every `--plane` as given,
//! then the `--x` values, the `--y` values, the `--z` values.

use super::convert::is_cad;
use super::section_model::cut_model;
use super::surface_coons::{network_surface, Kind, NetworkFiles};
use crate::args::{
    parse_finite_list, parse_pair_with, parse_whole, read_grid_for, GridParamOption,
    LlSurfaceOptions,
};
use crate::input::grid_points;
use crate::output::console::note;
use crate::output::samples::sample_surface;
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::param::BicubicSurface;
use karkas::section::{cells_for_grid, Plane, Section, SectionOptions, Sectioner, MAX_CELLS};
use karkas::{Point3, Surface};
use karkas_io::cad::read::{read_cad, read_cad_if_model, CadModel};
use karkas_io::input::display_name;
use karkas_io::scene::{write_scene_png, write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::write::write_sections_csv;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};

/// The surface methods a section can be taken of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SurfaceMethod {
    /// LL-approximation (Aulchenko et al.) of INPUT_GRID, as `karkas surface ll` builds it.
    Ll,
    /// Bicubic interpolation (Kuznetsov and Filatov) of INPUT_GRID, as `karkas surface
    /// bicubic` builds it.
    Bicubic,
    /// Coons or Gordon surface of the curve network of --u-curves and --v-curves (no
    /// INPUT_GRID), as `karkas surface coons` builds it.
    Coons,
}

impl SurfaceMethod {
    /// The name of `--method`.
    fn name(self) -> &'static str {
        match self {
            SurfaceMethod::Ll => "ll",
            SurfaceMethod::Bicubic => "bicubic",
            SurfaceMethod::Coons => "coons",
        }
    }
}

/// Arguments of `karkas section`.
#[derive(Debug, Args)]
pub struct SectionArgs {
    /// Input grid (--method ll and bicubic): CSV with header i,j,x,y,z (indices from 0, rows
    /// in any order); or a CAD model (STEP or IGES), whose faces are cut within their trims.
    #[arg(value_name = "INPUT_GRID")]
    input: Option<PathBuf>,
    /// The surface to cut (needed for a grid or a curve network; a CAD model, INPUT_GRID
    /// ending in .step, .stp, .p21, .iges or .igs, or without --method any input that
    /// starts as STEP or IGES does, such as a pipe, takes none: its faces are cut).
    #[arg(long, value_enum)]
    method: Option<SurfaceMethod>,
    /// --method ll: --order, --interpolate; --method ll and bicubic: --closed-u, --closed-v.
    #[command(flatten)]
    ll: LlSurfaceOptions,
    /// --method bicubic only.
    #[command(flatten)]
    param: GridParamOption,
    /// --method coons: the surface to build, as `surface coons --kind` takes it.
    #[arg(long, value_enum)]
    kind: Option<Kind>,
    /// --method coons: the curves running along u, as `surface coons --u-curves` takes them.
    #[arg(long, value_name = "U.csv")]
    u_curves: Option<PathBuf>,
    /// --method coons: the curves running along v, as `surface coons --v-curves` takes them.
    #[arg(long, value_name = "V.csv")]
    v_curves: Option<PathBuf>,
    /// A cutting plane nx,ny,nz,c: the plane nx*x + ny*y + nz*z = c (repeatable).
    #[arg(long = "plane", value_name = "NX,NY,NZ,C", value_parser = parse_plane,
          allow_hyphen_values = true)]
    planes: Vec<[f64; 4]>,
    /// Sections x = X (repeatable; a comma list gives several).
    #[arg(
        long = "x",
        value_name = "X",
        value_delimiter = ',',
        allow_hyphen_values = true
    )]
    xs: Vec<f64>,
    /// Sections y = Y (repeatable; a comma list gives several).
    #[arg(
        long = "y",
        value_name = "Y",
        value_delimiter = ',',
        allow_hyphen_values = true
    )]
    ys: Vec<f64>,
    /// Sections z = Z (repeatable; a comma list gives several).
    #[arg(
        long = "z",
        value_name = "Z",
        value_delimiter = ',',
        allow_hyphen_values = true
    )]
    zs: Vec<f64>,
    /// Largest distance between a section polyline and the true curve (every chord is measured
    /// and split until within it), in model units [default: 1e-4 of the diagonal of the
    /// surface's bounding box].
    #[arg(long, allow_hyphen_values = true)]
    tolerance: Option<f64>,
    /// Cells NU,NV of the grid on which sections are looked for: a closed piece smaller than a
    /// cell may be missed [default: 2 per grid line, at least 16, in each direction].
    #[arg(long, value_name = "NU,NV", value_parser = parse_cells)]
    cells: Option<(usize, usize)>,
    /// Camera of the .svg/.png picture: azimuth and elevation in degrees.
    #[arg(long, value_name = "AZ,EL", value_parser = parse_view, allow_hyphen_values = true,
          default_value = "45,30")]
    view: (f64, f64),
    /// Output file: .csv with header section,t,x,y,z (one block per piece: section = piece
    /// number from 0 in plane order, t = length along the piece; a closed piece repeats its
    /// first point), or .svg / .png (the shaded surface with its sections, hidden parts
    /// removed).
    #[arg(short, long)]
    output: PathBuf,
}

/// One plane to cut, with the group it belongs to in the picture and how the user wrote it.
struct Cut {
    plane: Plane<3>,
    group: usize,
    label: String,
}

/// Picture groups: custom planes, x, y, z sections.
const GROUPS: [(&str, (u8, u8, u8)); 4] = [
    ("planes", (20, 140, 60)),
    ("x = const", (20, 60, 200)),
    ("y = const", (200, 40, 30)),
    ("z = const", (200, 120, 0)),
];

/// The smallest `--tolerance`, relative to the diagonal of the grid's bounding box: a chord
/// error below it is under the rounding of the points themselves (about `1e-16` of their size)
/// times the conditioning of the continuation, and asks for steps that round to nothing.
const MIN_RELATIVE_TOLERANCE: f64 = 1e-12;

/// The diagonal of the bounding box of `points`.
fn diagonal(points: &[Point3]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in points {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (0..3).map(|c| hi[c] - lo[c]).fold(0.0, f64::hypot)
}

/// What the sections are cut from: the defaults it gives and how the picture names it.
struct Source {
    /// The diagonal of the bounding box of its points (grid or curve points).
    diagonal: f64,
    /// Points along u and v (grid lines, or the longest curve of each family): the default
    /// cells and the picture's mesh follow them.
    lines: (usize, usize),
    /// The surface, for the picture's title: "the LL surface (L = 3) of sphere.csv".
    title: String,
}

/// Runs `karkas section`.
pub fn run(args: &SectionArgs) -> Result<()> {
    let format = output_format(
        &args.output,
        &[OutputFormat::Csv, OutputFormat::Svg, OutputFormat::Png],
    )?;
    check_method_options(args)?;
    args.ll.check()?;
    if let Some(t) = args.tolerance {
        if !(t.is_finite() && t > 0.0) {
            bail!("--tolerance: must be a positive number, got {t}");
        }
    }
    let cuts = planes(args)?;
    if let Some((path, model)) = model_input(args, format)? {
        let planes: Vec<(Plane<3>, String)> =
            cuts.into_iter().map(|c| (c.plane, c.label)).collect();
        return cut_model(path, &model, &args.output, args.tolerance, &planes);
    }
    let Some(method) = args.method else {
        bail!(
            "--method is needed: ll or bicubic for a grid, coons for a curve network (a CAD \
             model, STEP or IGES, takes none{})",
            args.input.as_deref().map_or_else(String::new, |p| format!(
                "; {} is neither",
                display_name(p).display()
            ))
        );
    };
    match (method, &args.input) {
        (SurfaceMethod::Coons, _) => cut_network(args, format, &cuts),
        (method, Some(input)) => cut_grid(args, format, &cuts, method, input),
        (method, None) => bail!(
            "--method {} needs INPUT_GRID, the grid CSV to build the surface from",
            method.name()
        ),
    }
}

/// The CAD model INPUT names, read: a model by its extension (the model options checked
/// first), or, without `--method`, any input whose first bytes are STEP or IGES (standard
/// input, a pipe, a file named otherwise); `None` for a grid or a network.
fn model_input(args: &SectionArgs, format: OutputFormat) -> Result<Option<(&Path, CadModel)>> {
    let Some(path) = args.input.as_deref() else {
        return Ok(None);
    };
    if is_cad(path) {
        check_model_options(args, format)?;
        return Ok(Some((path, read_cad(path)?)));
    }
    if args.method.is_some() {
        return Ok(None);
    }
    match read_cad_if_model(path)? {
        Some(model) => {
            check_model_options(args, format)?;
            Ok(Some((path, model)))
        }
        None => Ok(None),
    }
}

/// `--method coons`: builds the surface of the network `--u-curves`, `--v-curves` and cuts it.
fn cut_network(args: &SectionArgs, format: OutputFormat, cuts: &[Cut]) -> Result<()> {
    let (Some(u_curves), Some(v_curves), Some(kind)) = (&args.u_curves, &args.v_curves, args.kind)
    else {
        bail!("--method coons needs --kind, --u-curves U.csv and --v-curves V.csv");
    };
    let files = NetworkFiles {
        u_curves,
        v_curves,
        u_derivs: None,
        v_derivs: None,
        twists: None,
        tolerance: None,
        repair: false,
        creases: (false, false),
    };
    let (surface, u_family, v_family) =
        network_surface(kind, &files, std::slice::from_ref(&args.output))?;
    let points: Vec<Point3> = u_family
        .curves
        .iter()
        .chain(&v_family.curves)
        .flatten()
        .copied()
        .collect();
    let longest = |curves: &[Vec<Point3>]| curves.iter().map(Vec::len).max().unwrap_or(0);
    let kind_name = kind
        .to_possible_value()
        .map_or_else(String::new, |v| v.get_name().to_owned());
    let source = Source {
        diagonal: diagonal(&points),
        lines: (longest(&u_family.curves), longest(&v_family.curves)),
        title: format!(
            "the {kind_name} surface of {}, {}",
            file_name(u_curves),
            file_name(v_curves)
        ),
    };
    cut(args, format, cuts, &surface, &source)
}

/// `--method ll` and `--method bicubic`: builds the surface of the grid `input` and cuts it.
fn cut_grid(
    args: &SectionArgs,
    format: OutputFormat,
    cuts: &[Cut],
    method: SurfaceMethod,
    input: &Path,
) -> Result<()> {
    let grid = read_grid_for(input, &args.output)?;
    grid_points(input, grid.as_slice())?;
    let source = Source {
        diagonal: diagonal(grid.as_slice()),
        lines: (grid.rows(), grid.cols()),
        title: String::new(),
    };
    if method == SurfaceMethod::Bicubic {
        let (closed_u, closed_v) = (args.ll.closed.closed_u, args.ll.closed.closed_v);
        let param = args.param.kind();
        let surface = BicubicSurface::new(&grid, param.to_library(), closed_u, closed_v)
            .with_context(|| input.display().to_string())?;
        let param_name = param
            .to_possible_value()
            .map_or_else(String::new, |v| v.get_name().to_owned());
        let title = format!(
            "the bicubic surface ({param_name} parameters) of {}",
            file_name(input)
        );
        cut(args, format, cuts, &surface, &Source { title, ..source })
    } else {
        let surface = args.ll.build(&grid, input)?;
        let title = format!(
            "the LL surface (L = {}) of {}",
            args.ll.order(),
            file_name(input)
        );
        cut(args, format, cuts, &surface, &Source { title, ..source })
    }
}

/// Refuses the options the chosen `--method` does not use, and a grid given to `--method
/// coons`, naming them.
fn check_method_options(args: &SectionArgs) -> Result<()> {
    let Some(method) = args.method else {
        return Ok(());
    };
    let groups = [
        (
            SurfaceMethod::Ll,
            vec![
                (args.ll.order.is_some(), "--order"),
                (args.ll.interpolate, "--interpolate"),
            ],
        ),
        (
            SurfaceMethod::Bicubic,
            vec![(args.param.param.is_some(), "--param")],
        ),
        (
            SurfaceMethod::Coons,
            vec![
                (args.kind.is_some(), "--kind"),
                (args.u_curves.is_some(), "--u-curves"),
                (args.v_curves.is_some(), "--v-curves"),
            ],
        ),
    ];
    for (user, options) in groups {
        let given: Vec<&str> = options
            .iter()
            .filter(|(given, _)| *given)
            .map(|(_, name)| *name)
            .collect();
        if user != method && !given.is_empty() {
            let verb = if given.len() == 1 { "is" } else { "are" };
            bail!(
                "{} {verb} used only by --method {}, not --method {}",
                given.join(", "),
                user.name(),
                method.name()
            );
        }
    }
    if method == SurfaceMethod::Coons {
        if args.ll.closed.closed_u || args.ll.closed.closed_v {
            bail!(
                "--closed-u / --closed-v are not used by --method coons: a curve whose last \
                 point repeats its first closes its direction"
            );
        }
        if let Some(input) = &args.input {
            bail!(
                "--method coons takes no INPUT_GRID (got {}): the network is read from \
                 --u-curves and --v-curves",
                input.display()
            );
        }
    }
    Ok(())
}

/// Refuses, for a CAD model, the options that build a surface and the pictures, naming them.
fn check_model_options(args: &SectionArgs, format: OutputFormat) -> Result<()> {
    let given = [
        (args.method.is_some(), "--method"),
        (args.ll.order.is_some(), "--order"),
        (args.ll.interpolate, "--interpolate"),
        (args.ll.closed.closed_u, "--closed-u"),
        (args.ll.closed.closed_v, "--closed-v"),
        (args.param.param.is_some(), "--param"),
        (args.kind.is_some(), "--kind"),
        (args.u_curves.is_some(), "--u-curves"),
        (args.v_curves.is_some(), "--v-curves"),
        (args.cells.is_some(), "--cells"),
    ];
    let named: Vec<&str> = given.iter().filter(|g| g.0).map(|g| g.1).collect();
    if !named.is_empty() {
        bail!(
            "{} {} not used with a CAD model: its faces are cut as they are",
            named.join(", "),
            if named.len() == 1 { "is" } else { "are" }
        );
    }
    if format != OutputFormat::Csv {
        bail!("the sections of a CAD model are written as CSV only (section,t,x,y,z)");
    }
    Ok(())
}

/// The file name of `path`, for titles.
fn file_name(path: &Path) -> String {
    path.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}

/// Cuts `surface` by every plane of `cuts` and writes the sections in `format`.
fn cut<S: Surface<3>>(
    args: &SectionArgs,
    format: OutputFormat,
    cuts: &[Cut],
    surface: &S,
    source: &Source,
) -> Result<()> {
    if let Some(t) = args.tolerance {
        let floor = MIN_RELATIVE_TOLERANCE * source.diagonal;
        if t < floor {
            bail!(
                "--tolerance: {t:e} is below what floating point resolves on this surface \
                 ({MIN_RELATIVE_TOLERANCE:e} of its size): give at least {floor:.3e}"
            );
        }
    }
    let (rows, cols) = source.lines;
    let options = SectionOptions {
        tolerance: args.tolerance,
        cells: args.cells.unwrap_or_else(|| cells_for_grid(rows, cols)),
        ..SectionOptions::default()
    };
    let sectioner = Sectioner::new(surface, &options)?;

    let mut lines: Vec<Vec<Point3>> = Vec::new();
    let mut groups: [Vec<Vec<Point3>>; 4] = Default::default();
    for (k, cut) in cuts.iter().enumerate() {
        let section = sectioner.plane(&cut.plane);
        report_section(k, cut, &section, lines.len());
        for curve in &section.curves {
            let mut line = curve.points.clone();
            if curve.closed {
                line.push(curve.points[0]);
            }
            groups[cut.group].push(line.clone());
            lines.push(line);
        }
    }
    match format {
        OutputFormat::Csv => write_sections_csv(&args.output, &lines)?,
        _ => write_picture(args, format, surface, source, (cuts.len(), &groups))?,
    }
    crate::output::console::record("pieces", lines.len());
    crate::output::console::record("planes", cuts.len());
    note(format!(
        "karkas: wrote {} ({} section pieces from {} planes)",
        shown(&args.output).display(),
        lines.len(),
        cuts.len()
    ));
    Ok(())
}

/// Draws the sections `groups` of `planes` planes over `surface` as the picture `format`.
fn write_picture<S: Surface<3>>(
    args: &SectionArgs,
    format: OutputFormat,
    surface: &S,
    source: &Source,
    (planes, groups): (usize, &[Vec<Vec<Point3>>; 4]),
) -> Result<()> {
    let (nu, nv) = (mesh_samples(source.lines.0), mesh_samples(source.lines.1));
    let (_, _, mesh) = sample_surface(surface, nu, nv);
    let labels: Vec<String> = groups
        .iter()
        .zip(GROUPS)
        .map(|(g, (name, _))| match g.len() {
            1 => format!("{name} (1 piece)"),
            n => format!("{name} ({n} pieces)"),
        })
        .collect();
    let curves: Vec<SceneCurves<'_>> = groups
        .iter()
        .zip(GROUPS)
        .zip(&labels)
        .filter(|((g, _), _)| !g.is_empty())
        .map(|((g, (_, rgb)), label)| SceneCurves {
            label,
            lines: g,
            rgb,
            width: 1.6,
        })
        .collect();
    let title = format!("{planes} sections of {}", source.title);
    let scene = Scene {
        title: &title,
        mesh: SceneMesh {
            rows: nu,
            cols: nv,
            points: &mesh,
        },
        curves: &curves,
        view: View {
            azimuth: args.view.0,
            elevation: args.view.1,
        },
    };
    if format == OutputFormat::Png {
        write_scene_png(&args.output, &scene)?;
    } else {
        write_scene_svg(&args.output, &scene)?;
    }
    Ok(())
}

/// Mesh samples of the picture along a direction with `k` grid lines.
fn mesh_samples(k: usize) -> usize {
    (4 * k).clamp(50, 240)
}

/// The planes of the command line, in section order.
fn planes(args: &SectionArgs) -> Result<Vec<Cut>> {
    let mut cuts = Vec::new();
    for p in &args.planes {
        let plane = Plane::new(Point3::new([p[0], p[1], p[2]]), p[3])
            .with_context(|| format!("--plane {},{},{},{}", p[0], p[1], p[2], p[3]))?;
        cuts.push(Cut {
            plane,
            group: 0,
            label: format!("{}x + {}y + {}z = {}", p[0], p[1], p[2], p[3]),
        });
    }
    for (axis, (name, values)) in [("--x", &args.xs), ("--y", &args.ys), ("--z", &args.zs)]
        .into_iter()
        .enumerate()
    {
        for &value in values {
            let plane = Plane::coordinate(axis, value)
                .with_context(|| format!("{name} {value}: not a finite number"))?;
            cuts.push(Cut {
                plane,
                group: axis + 1,
                label: format!("{} = {value}", &name[2..]),
            });
        }
    }
    if cuts.is_empty() {
        bail!("no plane given: use --plane NX,NY,NZ,C or --x / --y / --z");
    }
    Ok(cuts)
}

/// Prints what one plane gave, and its warnings.
fn report_section(k: usize, cut: &Cut, section: &Section<3>, first: usize) {
    let pieces = section.curves.len();
    let closed = section.curves.iter().filter(|c| c.closed).count();
    let what = match (pieces, closed) {
        (0, _) => "no section".to_owned(),
        (1, 1) => format!("1 closed piece, section {first}"),
        (1, _) => format!("1 open piece, section {first}"),
        (n, c) => format!(
            "{n} pieces ({c} closed), sections {first}-{}",
            first + n - 1
        ),
    };
    let how = if section.fast_path {
        " (lines of constant parameter)"
    } else {
        ""
    };
    note(format!(
        "karkas: plane {} ({}): {what}{how}",
        k + 1,
        cut.label
    ));
    for w in &section.warnings {
        note(format!(
            "karkas: warning: plane {} ({}): {w}",
            k + 1,
            cut.label
        ));
    }
}

/// Parses `nx,ny,nz,c`.
fn parse_plane(text: &str) -> Result<[f64; 4], String> {
    parse_finite_list(text, "NX,NY,NZ,C (four numbers separated by commas)")
}

/// Parses `NU,NV` cell counts.
fn parse_cells(text: &str) -> Result<(usize, usize), String> {
    parse_pair_with(text, |s| match parse_whole(s)? {
        n if (3..=MAX_CELLS).contains(&n) => Ok(n),
        n => Err(format!("cells must be 3 to {MAX_CELLS}, got {n}")),
    })
}

/// Parses `AZ,EL` in degrees.
fn parse_view(text: &str) -> Result<(f64, f64), String> {
    let [azimuth, elevation] = parse_finite_list(text, "AZ,EL (two angles in degrees)")?;
    Ok((azimuth, elevation))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn option_values_parse() {
        assert_eq!(parse_plane("0, 0,1,-2.5"), Ok([0.0, 0.0, 1.0, -2.5]));
        assert!(parse_plane("0,0,1").is_err());
        assert!(parse_plane("0,0,1,nan").is_err());
        assert_eq!(parse_cells("16,40"), Ok((16, 40)));
        assert!(parse_cells("2,40").is_err());
        assert_eq!(parse_view("-60,25"), Ok((-60.0, 25.0)));
        assert!(parse_view("10").is_err());
    }
}
