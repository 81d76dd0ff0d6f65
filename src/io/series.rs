//! CSV time series of the energy budget, with units in the header.

use super::{IoError, write_atomic};
use crate::dem::EnergyBudget;
use std::fmt::Write;
use std::path::Path;

/// Column names and units of [`write_energy_csv`].
pub const ENERGY_COLUMNS: &[(&str, &str)] = &[
    ("time", "s"),
    ("work", "J/m"),
    ("potential_energy", "J/m"),
    ("kinetic_energy", "J/m"),
    ("friction_dissipation", "J/m"),
    ("viscous_dissipation", "J/m"),
    ("drag_dissipation", "J/m"),
    ("elastic_energy", "J/m"),
    ("other_dissipation", "J/m"),
    ("residual", "J/m"),
];

/// Writes the energy budget samples as CSV. The header names each column with its unit,
/// e.g. `work [J/m]`.
pub fn write_energy_csv(path: &Path, series: &[EnergyBudget]) -> Result<(), IoError> {
    let mut s = String::new();
    let header: Vec<String> = ENERGY_COLUMNS
        .iter()
        .map(|(n, u)| format!("{n} [{u}]"))
        .collect();
    s.push_str(&header.join(","));
    s.push('\n');
    for e in series {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{}",
            e.time,
            e.work,
            e.potential_energy,
            e.kinetic_energy,
            e.friction_dissipation,
            e.viscous_dissipation,
            e.drag_dissipation,
            e.elastic_energy,
            e.other_dissipation,
            e.residual
        );
    }
    write_atomic(path, s.as_bytes())
}
