//! A STEP file read whole: its instances ([`step_syntax`](super::step_syntax)), units
//! ([`step_units`](super::step_units)) and shape ([`step_topology`](super::step_topology)),
//! and what was not read.

use std::io::BufRead;
use std::path::Path;

use super::model::{CadFormat, CadModel, Unread};
use super::{step_cycles, step_geometry, step_syntax, step_topology, step_units};
use crate::error::IoError;

/// Reads a STEP file.
pub(crate) fn read_step(name: &Path, reader: &mut dyn BufRead) -> Result<CadModel, IoError> {
    let wanted = |n: &str| {
        step_geometry::CURVE_TYPES.contains(&n)
            || step_geometry::SURFACE_TYPES.contains(&n)
            || step_topology::TOPOLOGY_TYPES.contains(&n)
            || step_units::UNIT_TYPES.contains(&n)
    };
    let exchange = step_syntax::read_exchange(name, reader, &wanted)?;
    step_cycles::refuse_cycles(name, &exchange)?;
    let units = step_units::units(name, &exchange)?;
    let mut topology = step_topology::Topology::new(name, &exchange, units.radians);
    let shape = topology.shape()?;
    let mut unread: Vec<Unread> = topology
        .unread
        .iter()
        .map(|(u, &count)| Unread {
            what: u.entity.clone(),
            count,
            reason: u.reason.to_owned(),
        })
        .collect();
    // Geometry of types karkas does not read that no face used (free items).
    for (kind, &count) in &exchange.others {
        for part in kind.split('+') {
            if step_geometry::UNREAD_GEOMETRY.contains(&part)
                && !unread.iter().any(|u| u.what == part)
            {
                unread.push(Unread {
                    what: part.to_owned(),
                    count,
                    reason: "entity type not read".into(),
                });
            }
        }
    }
    let mut notes = Vec::new();
    if !units.other_lengths.is_empty() {
        notes.push(format!(
            "other length units ({}) in parts of the file; coordinates kept as written in {}",
            units.other_lengths.join(", "),
            units.length.name
        ));
    }
    let placements: usize = exchange
        .others
        .iter()
        .filter(|(k, _)| {
            k.contains("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION")
                || k.as_str() == "MAPPED_ITEM"
        })
        .map(|(_, &c)| c)
        .sum();
    if placements > 0 {
        notes.push(format!(
            "{placements} assembly placements (REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION, \
             MAPPED_ITEM): components kept in their own coordinates"
        ));
    }
    let entities = exchange.instances.len() + exchange.others.values().sum::<usize>();
    Ok(CadModel {
        path: name.to_path_buf(),
        format: CadFormat::Step,
        shape,
        unit: units.length,
        unread,
        notes,
        entities,
    })
}
