//! Campaigns and their tabulation.
//!
//! Owns running a campaign (in this process on threads, or prepared, run one planned run at
//! a time and adopted) and `tabulate`, the command line's `pressridge tabulate` pipeline
//! writing a NetCDF lookup table and returning what the command line prints.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use pyo3::prelude::*;
use pyo3::types::PyDict;

use pressridge::campaign::tabulation::{
    TabulateCampaignsError, TabulateOptions, tabulate_campaigns,
};
use pressridge::campaign::{
    CampaignSpec, PlannedRun, Progress, adopt_records, prepare_campaign, run_campaign, run_planned,
};
use pressridge::io::table_netcdf::write_ridge_table;
use pressridge::table::tabulate::fit_warnings;

use crate::errors::{BindError, detached, file_missing, guarded, value_err};

fn read_spec(spec: &Path) -> Result<(CampaignSpec, PathBuf), BindError> {
    let s = CampaignSpec::read(spec)?;
    let base = spec.parent().map(|p| p.to_path_buf()).unwrap_or_default();
    Ok((s, base))
}

/// Runs a campaign on `threads` threads in this process (`run_campaign`); returns
/// (skipped, done). Ctrl-C ends it after the runs in flight, with `KeyboardInterrupt`.
/// `progress`, if given, is called about once a second with a dict (skipped, done, total,
/// simulated seconds).
#[pyfunction]
#[pyo3(signature = (spec, out, threads, progress))]
pub(crate) fn campaign_local(
    py: Python<'_>,
    spec: PathBuf,
    out: PathBuf,
    threads: usize,
    progress: Option<Py<PyAny>>,
) -> PyResult<(usize, usize)> {
    let (spec_v, base) = guarded(|| read_spec(&spec))?;
    let stop = AtomicBool::new(false);
    let latest = std::sync::Mutex::new(None::<Progress>);
    let mut interrupted: Option<PyErr> = None;
    let mut callback_err: Option<PyErr> = None;
    let result = py.detach(|| {
        std::thread::scope(|s| {
            let worker = s.spawn(|| {
                guarded(|| {
                    run_campaign(
                        &spec_v,
                        &base,
                        &out,
                        threads,
                        &|p| *latest.lock().expect("progress lock") = Some(p),
                        &stop,
                    )
                    .map_err(BindError::from)
                })
            });
            let mut ticks = 0u32;
            while !worker.is_finished() {
                std::thread::sleep(Duration::from_millis(50));
                ticks += 1;
                Python::attach(|py| {
                    if interrupted.is_none()
                        && let Err(e) = py.check_signals()
                    {
                        interrupted = Some(e);
                        stop.store(true, Ordering::Relaxed);
                    }
                    if ticks % 20 == 0
                        && callback_err.is_none()
                        && let Some(cb) = &progress
                        && let Some(p) = *latest.lock().expect("progress lock")
                    {
                        let d = PyDict::new(py);
                        let r = d
                            .set_item("skipped", p.skipped)
                            .and_then(|_| d.set_item("done", p.done))
                            .and_then(|_| d.set_item("total", p.total))
                            .and_then(|_| d.set_item("simulated", p.simulated))
                            .and_then(|_| cb.call1(py, (d,)).map(|_| ()));
                        if let Err(e) = r {
                            callback_err = Some(e);
                            stop.store(true, Ordering::Relaxed);
                        }
                    }
                });
            }
            worker
                .join()
                .unwrap_or_else(|_| Err(BindError::Internal("campaign thread panicked".into())))
        })
    });
    if let Some(e) = interrupted {
        return Err(e);
    }
    if let Some(e) = callback_err {
        return Err(e);
    }
    Ok(result?)
}

/// Takes the finished runs of a campaign from an earlier result directory or records-only
/// archive into `out` (`campaign::adopt_records`); returns the number taken.
#[pyfunction]
pub(crate) fn campaign_adopt(
    py: Python<'_>,
    spec: PathBuf,
    out: PathBuf,
    archive: PathBuf,
) -> PyResult<usize> {
    detached(py, || {
        let (s, base) = read_spec(&spec)?;
        Ok(adopt_records(&s, &base, &out, &archive)?)
    })
}

/// Prepares a campaign directory (`prepare_campaign`); returns (spec JSON, [planned run
/// JSON] still to do, skipped, total).
#[pyfunction]
pub(crate) fn campaign_prepare(
    py: Python<'_>,
    spec: PathBuf,
    out: PathBuf,
) -> PyResult<(String, Vec<String>, usize, usize)> {
    detached(py, || {
        let (s, base) = read_spec(&spec)?;
        let prepared = prepare_campaign(&s, &base, &out)?;
        let todo = prepared
            .todo
            .iter()
            .map(|p| serde_json::to_string(p).map_err(value_err))
            .collect::<Result<Vec<_>, _>>()?;
        Ok((
            serde_json::to_string(&s).map_err(value_err)?,
            todo,
            prepared.skipped,
            prepared.plan.len(),
        ))
    })
}

/// Runs one planned run (JSON from `campaign_prepare`) and writes it into `out`
/// (`run_planned`); returns the run id. Meant to run on a dask worker.
#[pyfunction]
pub(crate) fn campaign_run_planned(
    py: Python<'_>,
    spec_json: &str,
    run_json: &str,
    out: PathBuf,
) -> PyResult<String> {
    let spec: CampaignSpec = serde_json::from_str(spec_json)
        .map_err(|e| value_err(format!("campaign spec JSON: {e}")))?;
    let run: PlannedRun =
        serde_json::from_str(run_json).map_err(|e| value_err(format!("planned run JSON: {e}")))?;
    detached(py, || {
        run_planned(&run, &spec, &out, &|_| {})?;
        Ok(run.id.clone())
    })
}

/// What a Python tabulation returns besides the table file: ([(set, thickness, C_f)],
/// [warning]).
type TabulateOut = (Vec<(String, f64, f64)>, Vec<String>);

/// Tabulates campaign directories into a NetCDF lookup table, as `pressridge tabulate`
/// (`campaign::tabulation::tabulate_campaigns`); returns one line per set and thickness with
/// its C_f, and the warnings and notes the command line prints.
#[pyfunction]
#[pyo3(signature = (campaign_dirs, out, points, command, date, allow_partial=false, rafting_reach=pressridge::table::rafting::RAFTING_REACH, exclude_rafted=false, scaled_keys=Vec::new()))]
#[allow(clippy::too_many_arguments)]
pub(crate) fn tabulate(
    py: Python<'_>,
    campaign_dirs: Vec<PathBuf>,
    out: PathBuf,
    points: usize,
    command: String,
    date: String,
    allow_partial: bool,
    rafting_reach: f64,
    exclude_rafted: bool,
    scaled_keys: Vec<String>,
) -> PyResult<TabulateOut> {
    detached(py, || {
        for d in &campaign_dirs {
            file_missing(d)?;
        }
        let opts = TabulateOptions {
            points,
            allow_partial,
            rafting_reach,
            exclude_rafted,
            scaled_keys,
        };
        let t =
            tabulate_campaigns(&campaign_dirs, &opts, &command, &date).map_err(|e| match e {
                TabulateCampaignsError::Campaign(c) => c.into(),
                other => value_err(other),
            })?;
        write_ridge_table(&out, &t.table, &t.provenance)?;
        let mut warnings: Vec<String> = t
            .partial
            .iter()
            .map(|(d, g)| format!("partial campaign {} (allow_partial): {g}", d.display()))
            .collect();
        warnings.extend(fit_warnings(&t.table));
        for (id, why) in &t.gate_excluded {
            warnings.push(format!(
                "run {id} left out: its {why}; a dissipation cannot be negative, so the run went numerically unstable"
            ));
        }
        for (id, why) in &t.rafted_out {
            warnings.push(format!("run {id} left out: its {why}"));
        }
        let table = t.table;
        let mut lines = Vec::new();
        for (si, set) in table.sets.iter().enumerate() {
            for (hi, &h) in table.thickness.iter().enumerate() {
                lines.push((set.clone(), h, table.cf[[si, hi]]));
            }
        }
        Ok((lines, warnings))
    })
}

/// One row of `redistribution`: the setting, the counts and each quantity's ensemble mean
/// with the half-width of its 95 % interval.
type RidgedRow = std::collections::BTreeMap<String, f64>;

/// The simulated ridged ice per (thickness, μ, μ_w) of campaign directories' records, as
/// `pressridge redistribution` (`table::redistribution::ensembles`); returns (rows, runs left
/// out for want of the ridge columns).
#[pyfunction]
pub(crate) fn redistribution(
    py: Python<'_>,
    campaign_dirs: Vec<PathBuf>,
) -> PyResult<(Vec<RidgedRow>, usize)> {
    detached(py, || {
        for d in &campaign_dirs {
            file_missing(d)?;
        }
        let records = pressridge::campaign::read_pooled(&campaign_dirs)?;
        let (rows, without) = pressridge::table::redistribution::ensembles(&records);
        let rows = rows
            .iter()
            .map(|(k, e)| {
                let mut m: RidgedRow = e.columns().into_iter().collect();
                m.insert("thickness".into(), k.thickness);
                m.insert("mu".into(), k.mu);
                m.insert("mu_w".into(), k.mu_water);
                m
            })
            .collect();
        Ok((rows, without))
    })
}
