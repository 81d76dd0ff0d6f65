//! JSON files: saved world states ([`Snapshot`]) and run summaries. Floating-point values
//! round-trip exactly, so a saved state resumes bit for bit.

use super::{IoError, write_atomic};
use crate::dem::Snapshot;
use serde::Serialize;
use serde::de::DeserializeOwned;
use std::path::Path;

/// Writes any serialisable value as pretty JSON, atomically.
pub fn write_json<T: Serialize>(path: &Path, value: &T) -> Result<(), IoError> {
    let text = serde_json::to_string_pretty(value).map_err(|e| IoError::format(path, e))?;
    write_atomic(path, text.as_bytes())
}

/// Reads a JSON file into a value, naming the file and the problem on failure: a run's
/// `summary.json` ([`crate::simulation::Summary`]), a campaign run's `run.json`
/// ([`crate::record::RunRecord`]); see [`load_state`] for an example.
pub fn read_json<T: DeserializeOwned>(path: &Path) -> Result<T, IoError> {
    let text = std::fs::read_to_string(path).map_err(|e| IoError::os(path, e))?;
    serde_json::from_str(&text).map_err(|e| IoError::format(path, e))
}

/// Saves a world state.
pub fn save_state(path: &Path, s: &Snapshot) -> Result<(), IoError> {
    write_json(path, s)
}

/// Loads a world state: a run's `state.json` or one of its `snapshots/t*.json`.
///
/// ```no_run
/// use pressridge::io::state::{load_state, read_json};
/// use pressridge::{observe, simulation::Summary};
/// use std::path::Path;
///
/// // What `pressridge simulate --out runs/default` wrote.
/// let summary: Summary = read_json(Path::new("runs/default/summary.json"))?;
/// let e = summary.energy(); // J/m
/// println!("work {:.3e} J/m, potential energy {:.3e} J/m", e.work, e.potential_energy);
/// let state = load_state(Path::new("runs/default/state.json"))?;
/// println!("{} bodies at t = {} s", state.bodies.len(), state.time);
/// let p = observe::profile(&state, -20.0, 1.0, 32, 10); // m
/// # Ok::<(), pressridge::io::IoError>(())
/// ```
pub fn load_state(path: &Path) -> Result<Snapshot, IoError> {
    read_json(path)
}
