//! A wind-turbine blade's outer shape from a windIO turbine file (IEA Wind Task 37's YAML
//! ontology, version 2): the reference axis, chord, twist, `section_offset_y` (and
//! `section_offset_x` when given), the airfoils placed along the span and their coordinates.
//! The placement itself is the library's ([`karkas::loft::BladeShape`], docs/methods.md
//! §7.1); this module only reads.
//!
//! Read with `serde_norway`, a maintained fork of the deprecated `serde_yaml` (same serde
//! derive interface, anchors and aliases resolved, which windIO files use for shared grids,
//! errors with the line): the YAML crates that are not forks of it are either parse trees
//! without serde (`saphyr`) or ask for a newer compiler than karkas supports
//! (`serde-saphyr`). Fields karkas does not use (structure, polars, materials) are skipped.
//! A windIO 1 file (`outer_shape_bem`, `pitch_axis`) is refused with a message that names
//! the converter windIO ships.

use std::path::Path;

use karkas::loft::{BladeShape, Distribution};
use karkas::Point2;
use serde::Deserialize;

use crate::error::{data_error, IoError};
use crate::input::display_name;
use crate::lines::{read_text, strip_bom};

/// A blade read from a windIO file: its outer shape and its defined sections.
#[derive(Clone, Debug, PartialEq)]
pub struct WindioBlade {
    /// The turbine's `name`, when given.
    pub name: Option<String>,
    /// The distributions along the span.
    pub shape: BladeShape,
    /// The sections where the file places an airfoil, in span order.
    pub sections: Vec<BladeSection>,
}

/// One airfoil placed along a blade.
#[derive(Clone, Debug, PartialEq)]
pub struct BladeSection {
    /// The airfoil's name.
    pub airfoil: String,
    /// Its nondimensional position along the reference axis (`spanwise_position`).
    pub position: f64,
    /// Its coordinates in unit chord, as the file lists them.
    pub profile: Vec<Point2>,
}

#[derive(Deserialize)]
struct Turbine {
    name: Option<String>,
    components: Components,
    #[serde(default)]
    airfoils: Vec<Airfoil>,
}

#[derive(Deserialize)]
struct Components {
    blade: Blade,
}

#[derive(Deserialize)]
struct Blade {
    reference_axis: Option<Axis>,
    outer_shape: Option<OuterShape>,
    outer_shape_bem: Option<serde::de::IgnoredAny>,
}

#[derive(Deserialize)]
struct Axis {
    x: Pairs,
    y: Pairs,
    z: Pairs,
}

#[derive(Deserialize)]
struct Pairs {
    grid: Vec<f64>,
    values: Vec<f64>,
}

#[derive(Deserialize)]
struct OuterShape {
    chord: Pairs,
    twist: Pairs,
    section_offset_y: Pairs,
    section_offset_x: Option<Pairs>,
    airfoils: Vec<AirfoilAt>,
}

#[derive(Deserialize)]
struct AirfoilAt {
    name: String,
    spanwise_position: f64,
}

#[derive(Deserialize)]
struct Airfoil {
    name: String,
    coordinates: Coordinates,
}

#[derive(Deserialize)]
struct Coordinates {
    x: Vec<f64>,
    y: Vec<f64>,
}

/// Reads the blade of the windIO turbine file at `path`.
pub fn read_windio_blade(path: &Path) -> Result<WindioBlade, IoError> {
    parse_windio_blade(&read_text(path)?, &display_name(path))
}

/// Reads the blade of a windIO turbine file's `text`; `path` names it in messages.
///
/// Errors: YAML that does not parse or lacks a field the blade needs (the line when known),
/// a windIO 1 blade, a distribution whose arrays differ in length, have fewer than two
/// entries, a non-finite entry or a grid that does not increase, an airfoil placed along the
/// span that the file does not define, airfoil coordinates whose `x` and `y` differ in
/// length, no airfoils placed.
pub fn parse_windio_blade(text: &str, path: &Path) -> Result<WindioBlade, IoError> {
    let turbine = parse_turbine(text, path)?;
    let blade = turbine.components.blade;
    let (Some(axis), Some(outer)) = (blade.reference_axis, blade.outer_shape) else {
        return Err(data_error(
            path,
            if blade.outer_shape_bem.is_some() {
                "a windIO 1 blade (outer_shape_bem): convert the file to windIO 2 first, e.g. \
                 with windIO's converters/windIO2windIO.py"
            } else {
                "components.blade needs reference_axis and outer_shape (windIO 2)"
            },
        ));
    };
    let field = |name: &str, pairs: Pairs| {
        Distribution::new(pairs.grid, pairs.values)
            .map_err(|e| data_error(path, format!("components.blade.{name}: {e}")))
    };
    let shape = BladeShape {
        reference_axis: [
            field("reference_axis.x", axis.x)?,
            field("reference_axis.y", axis.y)?,
            field("reference_axis.z", axis.z)?,
        ],
        chord: field("outer_shape.chord", outer.chord)?,
        twist: field("outer_shape.twist", outer.twist)?,
        section_offset_y: field("outer_shape.section_offset_y", outer.section_offset_y)?,
        section_offset_x: outer
            .section_offset_x
            .map(|p| field("outer_shape.section_offset_x", p))
            .transpose()?,
    };
    if outer.airfoils.is_empty() {
        return Err(data_error(
            path,
            "components.blade.outer_shape.airfoils places no airfoil",
        ));
    }
    let sections = outer
        .airfoils
        .iter()
        .enumerate()
        .map(|(k, at)| blade_section(path, k, at, &turbine.airfoils))
        .collect::<Result<Vec<_>, IoError>>()?;
    Ok(WindioBlade {
        name: turbine.name,
        shape,
        sections,
    })
}

/// The turbine of a windIO file, a YAML error named by its line.
fn parse_turbine(text: &str, path: &Path) -> Result<Turbine, IoError> {
    serde_norway::from_str(strip_bom(text)).map_err(|e| match e.location() {
        Some(at) => IoError::Parse {
            path: path.to_path_buf(),
            line: at.line(),
            message: format!("not a windIO turbine: {e}"),
        },
        None => data_error(path, format!("not a windIO turbine: {e}")),
    })
}

/// The section of entry `k` of the blade's airfoil placements: the airfoil it names, among
/// the file's `airfoils`, at its spanwise position.
fn blade_section(
    path: &Path,
    k: usize,
    at: &AirfoilAt,
    airfoils: &[Airfoil],
) -> Result<BladeSection, IoError> {
    let Some(airfoil) = airfoils.iter().find(|a| a.name == at.name) else {
        return Err(data_error(
            path,
            format!(
                "components.blade.outer_shape.airfoils entry {} places the airfoil '{}', \
                 which the file's airfoils do not define",
                k + 1,
                at.name
            ),
        ));
    };
    let c = &airfoil.coordinates;
    if c.x.len() != c.y.len() {
        return Err(data_error(
            path,
            format!(
                "airfoil '{}': coordinates.x has {} entries and coordinates.y {}",
                at.name,
                c.x.len(),
                c.y.len()
            ),
        ));
    }
    Ok(BladeSection {
        airfoil: at.name.clone(),
        position: at.spanwise_position,
        profile: c
            .x
            .iter()
            .zip(&c.y)
            .map(|(&x, &y)| Point2::new([x, y]))
            .collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const BLADE: &str = "\
name: a test blade
components:
    blade:
        reference_axis:
            x: {grid: &g [0.0, 1.0], values: [0.0, -1.0]}
            y: {grid: *g, values: [0.0, 0.0]}
            z: {grid: *g, values: [0.0, 20.0]}
        outer_shape:
            chord: {grid: [0.0, 0.5, 1.0], values: [2.0, 2.5, 1.0]}
            twist: {grid: *g, values: [10.0, 0.0]}
            section_offset_y: {grid: *g, values: [1.0, 0.3]}
            airfoils:
              - {name: thin, spanwise_position: 0.0}
              - {name: thin, spanwise_position: 1.0}
airfoils:
    - name: thin
      coordinates:
          x: [1.0, 0.5, 0.0, 0.5, 1.0]
          y: [0.0, 0.05, 0.0, -0.05, 0.0]
      polars: []
";

    #[test]
    fn reads_a_blade_with_aliases() {
        let blade = parse_windio_blade(BLADE, Path::new("t.yaml")).unwrap();
        assert_eq!(blade.name.as_deref(), Some("a test blade"));
        assert_eq!(blade.sections.len(), 2);
        assert_eq!(blade.sections[1].position, 1.0);
        assert_eq!(blade.sections[0].profile[1], Point2::new([0.5, 0.05]));
        assert_eq!(blade.shape.reference_axis[2].at(1.0, 0), 20.0);
        assert_eq!(blade.shape.chord.at(0.5, 0), 2.5);
    }

    #[test]
    fn names_what_is_wrong() {
        let cases = [
            (
                BLADE.replace(
                    "name: thin, spanwise_position: 1.0",
                    "name: thick, spanwise_position: 1.0",
                ),
                "'thick'",
            ),
            (
                BLADE.replace("values: [2.0, 2.5, 1.0]", "values: [2.0, 1.0]"),
                "outer_shape.chord",
            ),
            (
                BLADE.replace("grid: [0.0, 0.5, 1.0]", "grid: [0.0, 0.5, 0.5]"),
                "increase",
            ),
            (
                BLADE.replace("outer_shape:", "outer_shape_bem:"),
                "windIO 1",
            ),
            (
                BLADE.replace("y: [0.0, 0.05, 0.0, -0.05, 0.0]", "y: [0.0, 0.05]"),
                "coordinates.y",
            ),
            (BLADE.replace("chord: {", "chord: [{"), "t.yaml:"),
            ("just: text".to_owned(), "components"),
        ];
        for (text, needle) in cases {
            let e = parse_windio_blade(&text, Path::new("t.yaml"))
                .unwrap_err()
                .to_string();
            assert!(e.contains(needle) && e.contains("t.yaml"), "{needle}: {e}");
        }
    }
}
