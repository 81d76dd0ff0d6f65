//! The simulator: scenes and runs.
//!
//! Owns the resolution of a scene (TOML file or built-in default, with `key=value`
//! overrides), `simulate` (progress callback, Ctrl-C) and the units of its time series.

use std::path::{Path, PathBuf};

use numpy::PyArray1;
use pyo3::prelude::*;

use pressridge::scene::Scene;
use pressridge::simulation;
use pressridge::simulation::series_columns;

use crate::errors::{BindError, detached, guarded, value_err};

/// The resolved scene: a TOML file (or the built-in default) with `key=value` overrides
/// ([`Scene::load`]).
fn load_scene(path: Option<&Path>, sets: &[String]) -> Result<Scene, BindError> {
    Ok(Scene::load(path, sets)?)
}

/// The resolved scene as TOML text.
#[pyfunction]
#[pyo3(signature = (scene, sets))]
pub(crate) fn scene_toml(scene: Option<PathBuf>, sets: Vec<String>) -> PyResult<String> {
    Ok(guarded(|| load_scene(scene.as_deref(), &sets))?.to_toml())
}

type SimOut<'py> = (String, String, Vec<(String, Bound<'py, PyArray1<f64>>)>);

/// Runs a scene; returns (summary JSON, resolved scene TOML, [(column, samples)]).
/// Ctrl-C stops the run at the next sample with `KeyboardInterrupt`.
#[pyfunction]
#[pyo3(signature = (scene, sets, progress=None, threads=1))]
pub(crate) fn simulate<'py>(
    py: Python<'py>,
    scene: Option<PathBuf>,
    sets: Vec<String>,
    progress: Option<Py<PyAny>>,
    threads: usize,
) -> PyResult<SimOut<'py>> {
    let sc = guarded(|| load_scene(scene.as_deref(), &sets))?;
    let duration = sc.duration;
    let out = detached(py, || {
        let mut interrupted: Option<PyErr> = None;
        // `progress(time, duration)` (s) at most every 0.2 s of wall time, and at the end.
        let mut last = std::time::Instant::now();
        let out = simulation::run_on(&sc, threads, &mut |w| {
            let t = w.time();
            let due = last.elapsed().as_secs_f64() >= 0.2 || t >= duration - 0.5 * w.dt();
            let r = Python::attach(|py| {
                py.check_signals()?;
                if let (Some(cb), true) = (&progress, due) {
                    cb.call1(py, (t, duration))?;
                }
                Ok::<(), PyErr>(())
            });
            if due {
                last = std::time::Instant::now();
            }
            match r {
                Ok(()) => true,
                Err(e) => {
                    interrupted = Some(e);
                    false
                }
            }
        })?;
        match interrupted {
            Some(e) => Err(BindError::Interrupted(e)),
            None => Ok(out),
        }
    })?;
    let summary = serde_json::to_string(&out.summary).map_err(value_err)?;
    let mut cols: Vec<Vec<f64>> =
        vec![Vec::with_capacity(out.series.len()); series_columns().len()];
    for s in &out.series {
        let row = s.row();
        for (c, x) in cols.iter_mut().zip(row) {
            c.push(x);
        }
    }
    let series = series_columns()
        .iter()
        .zip(cols)
        .map(|((name, _), c)| (name.to_string(), PyArray1::from_vec(py, c)))
        .collect();
    Ok((summary, sc.to_toml(), series))
}

/// Units of the time-series columns, as (name, unit) pairs.
#[pyfunction]
pub(crate) fn series_units() -> Vec<(&'static str, &'static str)> {
    series_columns().to_vec()
}
