//! The option groups several commands share, each flattened into the commands' arguments
//! (`#[command(flatten)]`) with its parsing and its checks, so that an option means and
//! reports the same everywhere.
//!
//! A command whose option says something of its own (a different default of `--samples`)
//! keeps the group and overrides the help text with `#[command(mut_arg(..))]`.

use crate::output::console::note;
use crate::output::curve::curvature_comb;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::MAX_SAMPLES;
use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::dps::MAX_ORDER;
use karkas::ll::{LlKernel, LlSurface};
use karkas::param::GridParameterization;
use karkas::{Curve, Grid, Point2, Point3};
use karkas_io::dialect::{ColumnChoice, ReadOptions};
use karkas_io::export::cad::{CadUnits, LengthUnit};
use karkas_io::export::samples::{default_curve_samples, unbounded_curve_samples};
use karkas_io::grid::read_grid;
use karkas_io::mesh::MeshOptions;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};

/// `--samples N` of the curve commands.
#[derive(Debug, Args)]
pub struct CurveSamples {
    /// Number of samples, uniform in t over the curve's domain, ends included
    /// [default: 10 per input point, at least 200].
    #[arg(long, value_parser = parse_count)]
    pub samples: Option<usize>,
}

impl CurveSamples {
    /// Refuses more than [`MAX_SAMPLES`] samples.
    pub fn check(&self) -> Result<()> {
        if self.samples.is_some_and(|n| n > MAX_SAMPLES) {
            bail!("--samples: at most {MAX_SAMPLES} samples can be written");
        }
        Ok(())
    }

    /// The count given, else the default for `k` points (10 a point, at least 200, at most
    /// [`karkas_io::export::samples::DEFAULT_CURVE_SAMPLES_BOUND`]: a note says so when the
    /// bound applies).
    pub fn resolve(&self, k: usize) -> usize {
        self.samples.unwrap_or_else(|| {
            let n = default_curve_samples(k);
            let full = unbounded_curve_samples(k);
            if full > n {
                note(format!(
                    "karkas: note: {n} samples, the default's bound (10 a point would be \
                     {full}); --samples N writes N"
                ));
            }
            n
        })
    }
}

/// `--units`, `--scale` of the commands that write STEP, IGES or DXF.
#[derive(Clone, Debug, Default, Args)]
pub struct CadOptions {
    /// STEP, IGES, DXF: the length unit the file states, mm, cm, m or in [default: mm in STEP
    /// and IGES, none in DXF]. The coordinates are written as they are (times --scale): a
    /// unit chord with --units m is one metre.
    #[arg(long, value_name = "UNIT", value_parser = parse_unit)]
    pub units: Option<LengthUnit>,
    /// STEP, IGES, DXF: multiply every coordinate by S (e.g. --units mm --scale 1000 writes
    /// points given in metres in millimetres) [default: 1].
    #[arg(long, value_name = "S", value_parser = parse_finite, allow_hyphen_values = true)]
    pub scale: Option<f64>,
}

impl CadOptions {
    /// The unit and scale the CAD writers take.
    pub fn units(&self) -> CadUnits {
        CadUnits {
            unit: self.units,
            scale: self.scale.unwrap_or(1.0),
        }
    }

    /// Refuses a scale that is not positive, and either option when none of the `formats`
    /// written is STEP, IGES or DXF.
    pub fn check(&self, formats: &[OutputFormat]) -> Result<()> {
        self.units().check().map_err(anyhow::Error::msg)?;
        let given = if self.units.is_some() {
            Some("--units")
        } else if self.scale.is_some() {
            Some("--scale")
        } else {
            None
        };
        if let Some(option) = given {
            if !formats.iter().any(|f| f.is_cad()) {
                bail!(
                    "{option}: only STEP, IGES and DXF outputs state a unit and take a scale, \
                     not .{}",
                    formats.first().map_or("csv", |f| f.extension())
                );
            }
        }
        Ok(())
    }
}

/// Parses a length unit of `--units`.
pub fn parse_unit(text: &str) -> Result<LengthUnit, String> {
    text.parse()
}

/// `--columns`, `--decimal-comma` of the commands that read curve points.
#[derive(Clone, Debug, Default, Args)]
pub struct CurveInputOptions {
    /// The x, y (and z) columns of the input, by header name or by position counted from 1:
    /// --columns 2,3, --columns 'Абсцисса,Ордината' (for headers that name no x and y, or
    /// files with more columns).
    #[arg(long, value_name = "A,B[,C]", value_parser = parse_columns)]
    pub columns: Option<ColumnChoice>,
    /// Numbers are written with a decimal comma (0,5): the comma never separates fields.
    /// Detected without it in files separated by ';', tabs or spaces.
    #[arg(long)]
    pub decimal_comma: bool,
}

impl CurveInputOptions {
    /// The reader's options.
    pub fn read_options(&self) -> ReadOptions {
        ReadOptions {
            columns: self.columns.clone(),
            decimal_comma: self.decimal_comma,
        }
    }
}

/// Parses `--columns A,B[,C]`.
pub fn parse_columns(text: &str) -> Result<ColumnChoice, String> {
    text.parse()
}

/// `--samples NU,NV` of the surface commands.
#[derive(Debug, Args)]
pub struct GridSamples {
    /// Samples NU,NV, uniform over the domain, ends included
    /// [default: 4 per grid line in each direction, at least 50].
    #[arg(long, value_parser = parse_pair)]
    pub samples: Option<(usize, usize)>,
}

impl GridSamples {
    /// Refuses more than [`MAX_SAMPLES`] samples in all.
    pub fn check(&self) -> Result<()> {
        if self
            .samples
            .is_some_and(|(nu, nv)| nu.saturating_mul(nv) > MAX_SAMPLES)
        {
            bail!("--samples: at most {MAX_SAMPLES} samples can be written");
        }
        Ok(())
    }
}

/// The input grid of the commands that build on a grid of points.
#[derive(Debug, Args)]
pub struct GridInput {
    /// Input grid: CSV with header i,j,x,y,z (indices from 0, rows in any order).
    pub input: PathBuf,
}

impl GridInput {
    /// Reads the grid, after refusing an `output` that would overwrite it.
    pub fn read_for(&self, output: &Path) -> Result<Grid<Point3>> {
        read_grid_for(&self.input, output)
    }

    /// Reads the grid, after refusing any of `outputs` that would overwrite it.
    pub fn read_for_all(&self, outputs: &[PathBuf]) -> Result<Grid<Point3>> {
        for output in outputs {
            ensure_distinct(&self.input, output)?;
        }
        Ok(read_grid(&self.input)?)
    }
}

/// Reads the grid at `input`, after refusing an `output` that would overwrite it.
pub fn read_grid_for(input: &Path, output: &Path) -> Result<Grid<Point3>> {
    ensure_distinct(input, output)?;
    Ok(read_grid(input)?)
}

/// `--closed-u`, `--closed-v` of the commands that build a surface from a grid.
#[derive(Debug, Args)]
pub struct ClosedUv {
    /// Close the surface in u (across rows, index i): periodic ends.
    #[arg(long)]
    pub closed_u: bool,
    /// Close the surface in v (along rows, index j): periodic ends.
    #[arg(long)]
    pub closed_v: bool,
}

/// The options of an LL surface (`surface ll`, `section --method ll`).
#[derive(Debug, Args)]
pub struct LlSurfaceOptions {
    /// LL order L (at least 1): the surface is C^L in each variable [default: 3].
    #[arg(long)]
    pub order: Option<usize>,
    #[command(flatten)]
    pub closed: ClosedUv,
    /// Pass through every grid point instead of approximating the grid.
    #[arg(long)]
    pub interpolate: bool,
}

impl LlSurfaceOptions {
    /// The order given, else [`karkas::ll::DEFAULT_ORDER`].
    pub fn order(&self) -> usize {
        self.order.unwrap_or(karkas::ll::DEFAULT_ORDER)
    }

    /// Refuses an order the LL kernel does not have.
    pub fn check(&self) -> Result<()> {
        check_ll_order(self.order())
    }

    /// The LL surface of `grid` (read from `input`, which errors name).
    pub fn build(&self, grid: &Grid<Point3>, input: &Path) -> Result<LlSurface<3>> {
        let build = if self.interpolate {
            LlSurface::interpolating
        } else {
            LlSurface::new
        };
        build(
            grid,
            self.order(),
            self.closed.closed_u,
            self.closed.closed_v,
        )
        .with_context(|| input.display().to_string())
    }
}

/// The parameterizations of `--param`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ParamKind {
    /// u_i = i, v_j = j.
    Uniform,
    /// Chord lengths along the row and the column through node (0, 0) (Kuznetsov and Filatov's rule).
    Chord,
    /// Chord lengths averaged over all rows and columns (also spelled averaged-chord).
    #[value(alias = "averaged-chord")]
    Averaged,
    /// Square roots of chord lengths averaged over all rows and columns.
    Centripetal,
}

impl ParamKind {
    /// The library's parameterization, by the library's parser of names (the one Python's
    /// `parameterization=` uses).
    pub fn to_library(self) -> GridParameterization {
        let name = self.to_possible_value().map(|v| v.get_name().to_owned());
        name.and_then(|n| n.parse().ok()).unwrap_or_default()
    }
}

/// `--param` of the bicubic interpolant of a grid (`surface bicubic`, `section --method
/// bicubic`).
#[derive(Debug, Args)]
pub struct GridParamOption {
    /// Parameters of the grid nodes [default: chord] (--parameterization is the same option,
    /// by Python's name).
    #[arg(long, value_enum, visible_alias = "parameterization")]
    pub param: Option<ParamKind>,
}

impl GridParamOption {
    /// The parameterization given, else chord lengths.
    pub fn kind(&self) -> ParamKind {
        self.param.unwrap_or(ParamKind::Chord)
    }
}

/// `--flip-normals` of the commands that write a surface mesh.
#[derive(Debug, Args)]
pub struct MeshOutput {
    /// Meshes (.obj .stl .ply .vtk .vts .glb): turn the mesh over, reversing the triangles'
    /// winding and the normals (for a surface whose normals point inwards).
    #[arg(long)]
    pub flip_normals: bool,
}

impl MeshOutput {
    /// Refuses `--flip-normals` when none of the outputs in `formats` is a mesh.
    pub fn check_all(&self, formats: &[OutputFormat]) -> Result<()> {
        match formats.iter().find(|f| OutputFormat::MESHES.contains(f)) {
            Some(&mesh) => self.check(mesh),
            None => formats.first().map_or(Ok(()), |&f| self.check(f)),
        }
    }

    /// Refuses `--flip-normals` for an output in `format` that is not a mesh.
    pub fn check(&self, format: OutputFormat) -> Result<()> {
        if self.flip_normals && !OutputFormat::MESHES.contains(&format) {
            bail!(
                "--flip-normals: only meshes (.obj .stl .ply .vtk .vts .glb) have normals to \
                 flip, not .{}",
                format.extension()
            );
        }
        Ok(())
    }

    /// The mesh writer's options: these, text STL and PLY when `ascii`.
    pub fn options(&self, ascii: bool) -> MeshOptions {
        MeshOptions {
            ascii,
            flip_normals: self.flip_normals,
        }
    }
}

/// `--crease-u`, `--crease-v` of the surface commands that close a direction with a C^0 seam
/// (`surface ll`, `surface bicubic`).
#[derive(Debug, Args)]
pub struct CreaseUv {
    /// Close the surface in u with a crease: the first row is appended after the last (unless
    /// the last repeats it) and the direction is interpolated as an open one, so the seam is
    /// C^0 (a sharp trailing edge stays sharp). Not with --closed-u.
    #[arg(long, conflicts_with = "closed_u")]
    pub crease_u: bool,
    /// Close the surface in v with a crease (the first column appended), as --crease-u. Not
    /// with --closed-v.
    #[arg(long, conflicts_with = "closed_v")]
    pub crease_v: bool,
}

impl CreaseUv {
    /// `grid` closed with a crease in the directions asked: the first row (column) appended
    /// after the last unless the last repeats it (within `1e-12` of the largest coordinate),
    /// with a warning when the last nearly repeats it. A direction of fewer than 3 distinct
    /// lines cannot close: an error naming the option.
    pub fn apply(&self, grid: Grid<Point3>) -> Result<Grid<Point3>> {
        let mut grid = grid;
        if self.crease_v {
            grid = close_columns(&grid, "--crease-v", "columns")?;
        }
        if self.crease_u {
            grid = close_columns(&grid.transposed(), "--crease-u", "rows")?.transposed();
        }
        Ok(grid)
    }
}

/// `grid` with its first column appended after the last unless the last repeats it (the rule
/// of [`CreaseUv::apply`]); `option` and `lines` name them in messages.
fn close_columns(grid: &Grid<Point3>, option: &str, lines: &str) -> Result<Grid<Point3>> {
    let (rows, cols) = (grid.rows(), grid.cols());
    let scale = grid
        .as_slice()
        .iter()
        .fold(0.0f64, |m, p| m.max(p.max_abs()));
    let gap = |i: usize| grid.get(i, 0).distance(*grid.get(i, cols - 1));
    let repeats = (0..rows).all(|i| gap(i) <= 1e-12 * scale);
    let distinct = cols - usize::from(repeats);
    if distinct < 3 {
        bail!(
            "{option}: a closed direction needs at least 3 {lines} besides a repeated first \
             one, got {distinct}"
        );
    }
    if repeats {
        return Ok(grid.clone());
    }
    // The line whose ends lie farthest apart says whether they nearly meet.
    let worst = (0..rows)
        .max_by(|&a, &b| gap(a).total_cmp(&gap(b)))
        .unwrap_or(0);
    crate::output::console::warn_near_miss(option, grid.row(worst));
    Ok(Grid::from_fn(rows, cols + 1, |i, j| *grid.get(i, j % cols)))
}

/// `--cap` of the surface commands that write bodies.
#[derive(Debug, Args)]
pub struct CapOption {
    /// Close every open boundary loop of the surface that lies in a plane (a wing's root and
    /// tip, a tube's ends) with a planar face: STEP then holds a closed solid, IGES the faces
    /// and the caps, meshes are closed; the enclosed volume is reported. An open boundary
    /// that is not a planar loop is an error.
    #[arg(long)]
    pub cap: bool,
}

impl CapOption {
    /// Refuses `--cap` for an output among `formats` that holds no body (CSV, pictures, pages,
    /// the VTK structured grids), and with `--mesh-tolerance` (`mesh_tolerance`): capped
    /// meshes are sampled uniformly.
    pub fn check(&self, formats: &[OutputFormat], mesh_tolerance: Option<f64>) -> Result<()> {
        if !self.cap {
            return Ok(());
        }
        if mesh_tolerance.is_some() {
            bail!(
                "--cap: capped meshes are sampled uniformly (--samples), not to --mesh-tolerance"
            );
        }
        let no_body = formats.iter().find(|format| {
            !(format.is_cad()
                || matches!(
                    format,
                    OutputFormat::Obj | OutputFormat::Stl | OutputFormat::Ply | OutputFormat::Glb
                ))
        });
        if let Some(format) = no_body {
            bail!(
                "--cap: only STEP, IGES and the triangle meshes (.step .iges .obj .stl .ply .glb) \
                 hold caps, not .{}",
                format.extension()
            );
        }
        Ok(())
    }
}

/// `--mesh-tolerance` of the commands that mesh a surface they build.
#[derive(Clone, Debug, Default, Args)]
pub struct MeshTolerance {
    /// Meshes (.obj .stl .ply .vtk .vts .glb): sample the surface densely where it bends and
    /// sparsely where it does not, so that the mesh lies within T (model units) of it,
    /// instead of the uniform --samples.
    #[arg(long, value_name = "T", value_parser = parse_finite)]
    pub mesh_tolerance: Option<f64>,
}

impl MeshTolerance {
    /// Refuses a tolerance that is not positive, or given without a mesh among `formats`.
    pub fn check(&self, formats: &[OutputFormat]) -> Result<()> {
        let Some(t) = self.mesh_tolerance else {
            return Ok(());
        };
        if t <= 0.0 {
            bail!("--mesh-tolerance: the tolerance must be positive (model units), got {t}");
        }
        if !formats.iter().any(|f| OutputFormat::MESHES.contains(f)) {
            bail!(
                "--mesh-tolerance: only meshes (.obj .stl .ply .vtk .vts .glb) are made to a \
                 tolerance, not .{}",
                formats.first().map_or("csv", |f| f.extension())
            );
        }
        Ok(())
    }
}

/// `--close-te` of the curve commands: the straight segment from the curve's end back to its
/// start (a blunt trailing edge), written with the curve as one closed wire.
#[derive(Debug, Args)]
pub struct CloseTeOption {
    /// STEP, IGES, DXF: close the curve with the straight segment from its end back to its
    /// start (a blunt trailing edge), written as one closed B-spline curve with a corner at
    /// each end of the segment (a planar face's boundary). Other outputs keep the open curve.
    #[arg(long)]
    pub close_te: bool,
}

impl CloseTeOption {
    /// Refuses `--close-te` when none of the `formats` written is STEP, IGES or DXF, or
    /// with `closing` (an option of the command that closes the curve itself, when given).
    pub fn check(&self, formats: &[OutputFormat], closing: Option<&str>) -> Result<()> {
        if !self.close_te {
            return Ok(());
        }
        if let Some(other) = closing {
            bail!("--close-te: the curve is already closed by {other}");
        }
        if !formats.iter().any(|f| f.is_cad()) {
            bail!(
                "--close-te: only STEP, IGES and DXF outputs carry the closing segment, not .{}",
                formats.first().map_or("csv", |f| f.extension())
            );
        }
        Ok(())
    }

    /// Refuses `--close-te` on `points` whose first and last points coincide (within
    /// [`karkas::fit::SHARED_END_TOLERANCE`] of their size: a sharp trailing edge, where the
    /// curve closes without a segment); `input` names the points.
    pub fn check_points<const D: usize>(
        &self,
        points: &[karkas::Point<D>],
        input: &Path,
    ) -> Result<()> {
        if self.close_te && karkas::fit::shared_end(points).is_some() {
            bail!(
                "{}: --close-te: the first and last points coincide (within {:e} of the \
                 size): the curve closes there without a segment",
                input.display(),
                karkas::fit::SHARED_END_TOLERANCE
            );
        }
        Ok(())
    }
}

/// `--comb` of the curve pictures.
#[derive(Debug, Args)]
pub struct CombOption {
    /// Pictures: draw the curvature comb of the curve.
    #[arg(long)]
    pub comb: bool,
}

impl CombOption {
    /// The comb's teeth at the parameters `ts`, or none when not asked for.
    pub fn teeth<const D: usize>(&self, curve: &impl Curve<D>, ts: &[f64]) -> Vec<[Point2; 2]> {
        if self.comb {
            curvature_comb(curve, ts)
        } else {
            Vec::new()
        }
    }
}

/// Refuses an LL order the kernel does not have, as an error of `--order`.
pub fn check_ll_order(order: usize) -> Result<()> {
    LlKernel::new(order).context("--order")?;
    Ok(())
}

/// Refuses a discrete spline order outside `1..=MAX_ORDER`, naming the option.
pub fn check_dps_order(option: &str, order: usize) -> Result<()> {
    if order == 0 || order > MAX_ORDER {
        bail!("{option}: the order must be between 1 and {MAX_ORDER}, got {order}");
    }
    Ok(())
}

/// Refuses a discrete spline step below 2, naming the option.
pub fn check_dps_step(option: &str, step: usize) -> Result<()> {
    if step < 2 {
        bail!("{option}: the number of values per point must be at least 2, got {step}");
    }
    Ok(())
}

/// Parses `NU,NV` sample counts (each at least 2).
pub fn parse_pair(text: &str) -> Result<(usize, usize), String> {
    parse_pair_with(text, parse_count)
}

/// Parses `NU,NV`, each count (trimmed) by `count`.
pub fn parse_pair_with(
    text: &str,
    count: impl Fn(&str) -> Result<usize, String>,
) -> Result<(usize, usize), String> {
    let (a, b) = text
        .split_once(',')
        .ok_or_else(|| format!("expected NU,NV (two counts separated by a comma), got '{text}'"))?;
    Ok((count(a.trim())?, count(b.trim())?))
}

/// Parses a whole number, naming the text when it is not one.
pub fn parse_whole(text: &str) -> Result<usize, String> {
    text.parse()
        .map_err(|_| format!("'{text}' is not a whole number"))
}

/// Parses a finite number (surrounding spaces allowed).
pub fn parse_finite(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(format!("'{}' is not a finite number", text.trim())),
    }
}

/// Parses `N` finite numbers separated by commas; `expected` describes the form for the
/// error, e.g. `X,Y,Z (three numbers separated by commas)`.
pub fn parse_finite_list<const N: usize>(text: &str, expected: &str) -> Result<[f64; N], String> {
    let values: Vec<&str> = text.split(',').collect();
    if values.len() != N {
        return Err(format!("expected {expected}, got '{text}'"));
    }
    let mut out = [0.0; N];
    for (slot, v) in out.iter_mut().zip(values) {
        *slot = parse_finite(v)?;
    }
    Ok(out)
}

/// Parses the name of an output format for `--format`: an extension without the dot (`csv`,
/// `svg`, `png`, `html`, `obj`, `stl`, `ply`, `vtk`, `vts`, `glb`, `step`/`stp`, `iges`/`igs`),
/// in any case.
pub fn parse_format(text: &str) -> Result<OutputFormat, String> {
    let name = text.trim();
    let known = |f: &OutputFormat| {
        name.eq_ignore_ascii_case(f.extension())
            || f.alias().is_some_and(|a| name.eq_ignore_ascii_case(a))
    };
    OutputFormat::ALL
        .iter()
        .copied()
        .find(known)
        .ok_or_else(|| {
            let names: Vec<&str> = OutputFormat::ALL.iter().map(|f| f.extension()).collect();
            format!(
                "'{name}' is not an output format (one of {})",
                names.join(", ")
            )
        })
}

/// Parses one sample count (at least 2).
pub fn parse_count(text: &str) -> Result<usize, String> {
    let n = parse_whole(text)?;
    if n < 2 {
        return Err(format!("at least 2 samples are needed, got {n}"));
    }
    Ok(n)
}

/// Parses `H` or `HU,HV` (positive).
pub fn parse_steps(text: &str) -> Result<(f64, f64), String> {
    let positive = |s: &str| match parse_finite(s)? {
        h if h > 0.0 => Ok(h),
        h => Err(format!("the step must be positive, got {h}")),
    };
    match text.split_once(',') {
        Some((a, b)) => Ok((positive(a)?, positive(b)?)),
        None => {
            let h = positive(text)?;
            Ok((h, h))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_and_counts() {
        assert_eq!(parse_pair("10, 20"), Ok((10, 20)));
        assert!(parse_pair("10").is_err());
        assert!(parse_pair("1,5").is_err());
        assert!(parse_count("x").is_err());
        assert_eq!(parse_format("PNG"), Ok(OutputFormat::Png));
        assert_eq!(parse_format("stp"), Ok(OutputFormat::Step));
        assert!(parse_format("docx").is_err());
        assert_eq!(parse_finite(" -2.5 "), Ok(-2.5));
        assert!(parse_finite("inf").is_err());
        assert_eq!(parse_finite_list::<2>("1, 2", "A,B"), Ok([1.0, 2.0]));
        assert_eq!(
            parse_finite_list::<2>("1", "A,B (two numbers)"),
            Err("expected A,B (two numbers), got '1'".to_owned())
        );
    }

    /// Every name of `--param` is one of the library's, and means the same rule.
    #[test]
    fn param_names_are_the_library_names() {
        let expected = [
            (ParamKind::Uniform, GridParameterization::Uniform),
            (ParamKind::Chord, GridParameterization::default()),
            (ParamKind::Averaged, GridParameterization::AveragedChord),
            (ParamKind::Centripetal, GridParameterization::Centripetal),
        ];
        for (kind, rule) in expected {
            assert_eq!(kind.to_library(), rule);
            let name = kind.to_possible_value().map(|v| v.get_name().to_owned());
            assert!(GridParameterization::NAMES.contains(&name.as_deref().unwrap_or("")));
        }
        assert_eq!(
            ParamKind::from_str("averaged-chord", false),
            Ok(ParamKind::Averaged)
        );
        assert_eq!(
            ParamKind::Chord.to_library().name(),
            GridParameterization::DEFAULT_NAME
        );
    }
}
