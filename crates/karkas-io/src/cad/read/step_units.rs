//! The units of a STEP file (ISO 10303-41): the length unit its coordinates are in and the
//! plane-angle unit of its angles, from the `GLOBAL_UNIT_ASSIGNED_CONTEXT` of its
//! representations (SI units with a prefix, or conversion-based units such as the inch and
//! the degree).

use std::path::Path;

use super::model::LengthUnit;
use super::step_args::{real_of, Args};
use super::step_syntax::{Exchange, Value};
use crate::error::IoError;

/// The entity types the units need.
pub(crate) const UNIT_TYPES: &[&str] = &[
    "GLOBAL_UNIT_ASSIGNED_CONTEXT",
    "LENGTH_UNIT",
    "PLANE_ANGLE_UNIT",
    "SI_UNIT",
    "CONVERSION_BASED_UNIT",
    "LENGTH_MEASURE_WITH_UNIT",
    "PLANE_ANGLE_MEASURE_WITH_UNIT",
];

/// The units found: the length unit of the first context that has one (and whether others
/// differ), and the radians in one plane-angle unit.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Units {
    pub length: LengthUnit,
    pub radians: f64,
    /// The names of other length units met in other contexts.
    pub other_lengths: Vec<String>,
}

/// The SI prefix's factor.
fn prefix(p: Option<&str>) -> Option<(f64, &'static str)> {
    Some(match p {
        None => (1.0, ""),
        Some("EXA") => (1e18, "exa"),
        Some("PETA") => (1e15, "peta"),
        Some("TERA") => (1e12, "tera"),
        Some("GIGA") => (1e9, "giga"),
        Some("MEGA") => (1e6, "mega"),
        Some("KILO") => (1e3, "kilo"),
        Some("HECTO") => (1e2, "hecto"),
        Some("DECA") => (1e1, "deca"),
        Some("DECI") => (1e-1, "deci"),
        Some("CENTI") => (1e-2, "centi"),
        Some("MILLI") => (1e-3, "milli"),
        Some("MICRO") => (1e-6, "micro"),
        Some("NANO") => (1e-9, "nano"),
        Some("PICO") => (1e-12, "pico"),
        Some("FEMTO") => (1e-15, "femto"),
        Some("ATTO") => (1e-18, "atto"),
        _ => return None,
    })
}

/// The value of the unit instance `id` in its SI base (metres or radians) and its name;
/// `None` when it is not a unit karkas knows. `depth` bounds conversion chains.
fn unit_value(
    path: &Path,
    exchange: &Exchange,
    id: u64,
    depth: usize,
) -> Result<Option<(f64, String)>, IoError> {
    let Some(instance) = exchange.instances.get(&id) else {
        return Ok(None);
    };
    if depth > 8 {
        return Ok(None);
    }
    if let Some(si) = instance.part("SI_UNIT") {
        let a = Args::of(path, id, instance, si);
        if a.params.len() != 2 {
            return Ok(None);
        }
        let Some((factor, pre)) = prefix(a.enumeration(0)?) else {
            return Err(a.error("an SI prefix karkas does not know"));
        };
        let name = a.enumeration(1)?.unwrap_or("").to_ascii_lowercase();
        return Ok(Some((factor, format!("{pre}{name}"))));
    }
    if let Some(conversion) = instance.part("CONVERSION_BASED_UNIT") {
        let a = Args::of(path, id, instance, conversion);
        if a.params.len() != 2 {
            return Ok(None);
        }
        let name = match &a.params[0] {
            Value::Str(s) => s.to_ascii_lowercase(),
            _ => String::new(),
        };
        let measure = a.reference(1)?;
        let Some(m) = exchange.instances.get(&measure) else {
            return Err(a.error(format!(
                "refers to #{measure}, which the file does not define"
            )));
        };
        let Some(part) = m
            .parts
            .iter()
            .find(|p| p.name.ends_with("_MEASURE_WITH_UNIT"))
        else {
            return Ok(None);
        };
        let b = Args::of(path, measure, m, part);
        b.count(2)?;
        let Some(value) = real_of(&b.params[0]) else {
            return Err(b.error("the conversion factor is not a number"));
        };
        let base = unit_value(path, exchange, b.reference(1)?, depth + 1)?;
        return Ok(base.map(|(f, _)| (value * f, name)));
    }
    Ok(None)
}

/// Reads the units of `exchange`: millimetres and radians when the file names none.
pub(crate) fn units(path: &Path, exchange: &Exchange) -> Result<Units, IoError> {
    let mut ids: Vec<u64> = exchange
        .instances
        .iter()
        .filter(|(_, i)| i.part("GLOBAL_UNIT_ASSIGNED_CONTEXT").is_some())
        .map(|(&id, _)| id)
        .collect();
    ids.sort_unstable();
    let mut length: Option<LengthUnit> = None;
    let mut radians: Option<f64> = None;
    let mut others: Vec<String> = Vec::new();
    for id in ids {
        let instance = &exchange.instances[&id];
        let Some(part) = instance.part("GLOBAL_UNIT_ASSIGNED_CONTEXT") else {
            continue;
        };
        let a = Args::of(path, id, instance, part);
        for unit in a.references(0)? {
            let Some(u) = exchange.instances.get(&unit) else {
                return Err(a.error(format!("refers to #{unit}, which the file does not define")));
            };
            let is_length = u.part("LENGTH_UNIT").is_some();
            let is_angle = u.part("PLANE_ANGLE_UNIT").is_some();
            if !(is_length || is_angle) {
                continue;
            }
            let Some((value, name)) = unit_value(path, exchange, unit, 0)? else {
                continue;
            };
            if !(value.is_finite() && value > 0.0) {
                return Err(a.error(format!("the unit #{unit} has the factor {value}")));
            }
            if is_length {
                match &length {
                    None => {
                        length = Some(LengthUnit {
                            name,
                            metres: value,
                        })
                    }
                    Some(l) if l.metres != value && !others.contains(&name) => others.push(name),
                    Some(_) => {}
                }
            } else if radians.is_none() {
                radians = Some(value);
            }
        }
    }
    Ok(Units {
        length: length.unwrap_or(LengthUnit {
            name: "millimetre".into(),
            metres: 1e-3,
        }),
        radians: radians.unwrap_or(1.0),
        other_lengths: others,
    })
}
