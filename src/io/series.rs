//! CSV time series of the energy budget, with units in the header.

use super::{IoError, write_atomic};
use crate::simulation::Sample;
use std::fmt::Write;
use std::path::Path;

/// Column names and units of [`write_series_csv`].
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
    ("ridging_force", "N/m"),
    ("mean_force", "N/m"),
];

/// Writes the samples of a run (energy budget, ridging force of eq (9) and mean driver
/// force) as CSV. The header names each column with its unit, e.g. `work [J/m]`.
pub fn write_series_csv(path: &Path, series: &[Sample]) -> Result<(), IoError> {
    let mut s = String::new();
    let header: Vec<String> = ENERGY_COLUMNS
        .iter()
        .map(|(n, u)| format!("{n} [{u}]"))
        .collect();
    s.push_str(&header.join(","));
    s.push('\n');
    for x in series {
        let e = &x.energy;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{}",
            e.time,
            e.work,
            e.potential_energy,
            e.kinetic_energy,
            e.friction_dissipation,
            e.viscous_dissipation,
            e.drag_dissipation,
            e.elastic_energy,
            e.other_dissipation,
            e.residual,
            x.ridging_force,
            x.mean_force
        );
    }
    write_atomic(path, s.as_bytes())
}
