//! CSV time series of the energy budget, with units in the header.

use super::{IoError, write_atomic};
use crate::simulation::{Sample, series_columns};
use std::path::Path;

/// Writes the samples of a run (energy budget, ridging force of eq (9) and mean driver
/// force) as CSV. The header names each column with its unit, e.g. `work [J/m]`.
pub fn write_series_csv(path: &Path, series: &[Sample]) -> Result<(), IoError> {
    let mut s = String::new();
    let header: Vec<String> = series_columns()
        .iter()
        .map(|(n, u)| format!("{n} [{u}]"))
        .collect();
    s.push_str(&header.join(","));
    s.push('\n');
    for x in series {
        let row: Vec<String> = x.row().iter().map(f64::to_string).collect();
        s.push_str(&row.join(","));
        s.push('\n');
    }
    write_atomic(path, s.as_bytes())
}
