//! Seeded ensembles over a parameter grid (Hopkins 1994, "Numerical Ridge Growth
//! Experiments": sets of seven experiments per parameter combination, differing only in the
//! ±1 % modulus variation).
//!
//! A campaign spec (TOML) names a base scene, overrides, axes and a number of seeds:
//!
//! ```toml
//! name = "thickness"
//! seeds = 7                 # seeds first_seed .. first_seed + seeds - 1
//! sample_interval = 25.0    # s, the paper's
//! scene = "../scenes/figure5.toml"   # optional, relative to the spec file
//! set = ["duration=400"]    # optional overrides of the base scene
//!
//! [[axis]]                  # one key ...
//! key = "contact.mu"
//! values = [0.4, 1.0]
//!
//! [[axis]]                  # ... or several keys varied together
//! keys = ["sheet.thickness", "sheet.block_width"]
//! values = [[0.20, 0.20], [0.45, 0.30]]
//! ```
//!
//! The runs are the Cartesian product of the axes times the seeds. Each finished run is
//! written atomically to `runs/<point>/seed-NN/run.json` (with its final state beside it), so
//! an interrupted campaign loses only the runs in flight, and running the same command again
//! skips every run already written. A run is identified by its full resolved scene: if the
//! spec changed so that a written run would now mean something else, the campaign stops with
//! an error rather than mixing the two.

use crate::dem::Snapshot;
use crate::io::IoError;
use crate::io::state::{read_json, save_state, write_json};
use crate::observe::{self, RidgeSummary};
use crate::record::{RunDigest, RunRecord, RunSample};

mod read;
mod spec;
pub use read::{CampaignRecords, read_campaign, read_pooled, read_records};
pub use spec::{Axis, CampaignSpec, PlannedRun, ProfileSpec};
pub mod tabulation;
use crate::scene::{Scene, SceneError};
use crate::simulation;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// An error in a campaign.
#[derive(Debug, thiserror::Error)]
pub enum CampaignError {
    /// The spec is malformed.
    #[error("campaign spec: {0}")]
    Spec(String),
    /// A scene of the grid is invalid.
    #[error("run {run}: {source}")]
    Scene {
        /// The run.
        run: String,
        /// The cause.
        source: SceneError,
    },
    /// A file could not be read or written.
    #[error(transparent)]
    Io(#[from] IoError),
    /// A result directory holds runs of another spec.
    #[error("{0}")]
    Mismatch(String),
    /// Planned runs are missing or their records do not match their scene or files.
    #[error("{0}")]
    Incomplete(String),
}

/// The file that marks a campaign directory as a records-only archive: its run records
/// (`run.json`, with the summary, samples, final profile and metrics tabulate needs)
/// without the final states the runs wrote, e.g. a finished campaign committed under
/// `crates/lab/records/paper/`. Its records are checked for their id and scene digest only (not for the
/// files their digest lists, which it does not hold); it is never resumed into (a campaign
/// run there refuses the directory).
pub const RECORDS_ONLY: &str = "RECORDS-ONLY";

/// Whether `out` is a records-only archive ([`RECORDS_ONLY`]).
pub(crate) fn is_records_only(out: &Path) -> bool {
    out.join(RECORDS_ONLY).is_file()
}

/// The digest of what a run is: its id, seed and resolved scene (as TOML).
pub fn scene_digest(id: &str, seed: u64, scene: &Scene) -> String {
    crate::io::digest::sha256_hex(format!("{id}\n{seed}\n{}", scene.to_toml()).as_bytes())
}

/// Checks the record `r`, read from the run directory of planned run `id`, against that
/// id, its own scene and seed, and the files its digest lists; `Err` says what does not
/// match. A record without a digest (older versions) is checked for its id and its
/// `state.json` only. In a records-only archive ([`RECORDS_ONLY`] in `out`) the files
/// are not there: the id and the scene digest are checked.
pub(crate) fn verify_record(r: &RunRecord, out: &Path, id: &str) -> Result<(), String> {
    let files = !is_records_only(out);
    if r.id != id {
        return Err(format!(
            "its record names run `{}` (copied from another run directory?)",
            r.id
        ));
    }
    let record = record_path(out, id);
    let dir = record.parent().unwrap_or(out);
    let Some(d) = &r.digest else {
        return if !files || dir.join("state.json").is_file() {
            Ok(())
        } else {
            Err("its state.json is missing".into())
        };
    };
    if d.scene != scene_digest(&r.id, r.seed, &r.scene) {
        return Err("its record's scene or seed does not match its digest (edited?)".into());
    }
    for (name, want) in d.files.iter().filter(|_| files) {
        let path = dir.join(name);
        if !path.is_file() {
            return Err(format!("its {name} is missing"));
        }
        match crate::io::digest::sha256_file(&path) {
            Ok(got) if got == *want => {}
            Ok(_) => return Err(format!("its {name} does not match the record's digest")),
            Err(e) => return Err(e.to_string()),
        }
    }
    Ok(())
}

/// Progress of a campaign, reported as runs finish.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// Runs found already written when the campaign started.
    pub skipped: usize,
    /// Runs finished by this invocation so far.
    pub done: usize,
    /// Runs in the campaign.
    pub total: usize,
    /// Simulated seconds completed in this invocation, across runs in flight (s).
    pub simulated: f64,
}

/// Runs one planned run and makes its record.
pub(crate) fn run_one(
    plan: &PlannedRun,
    spec: &CampaignSpec,
    progress: &dyn Fn(f64),
) -> Result<(RunRecord, Snapshot), CampaignError> {
    let mut last = 0.0;
    let ps = &spec.profile;
    let profile_of =
        |s: &Snapshot| observe::profile(s, ps.x0, ps.dx, ps.strips, ps.lines_per_strip);
    // The ridged ice at each sample: the run calls back at the start and after each sample
    // it takes, so the i-th call is the i-th sample (all but a last one off the interval,
    // which the final profile gives).
    let mut ridge: Vec<(Option<RidgeSummary>, Vec<[f64; 2]>)> = Vec::new();
    let out = simulation::run(&plan.scene, &mut |w| {
        progress(w.time() - last);
        last = w.time();
        let p = profile_of(&w.snapshot());
        ridge.push((RidgeSummary::of(&p), RunSample::strips_of(&p)));
        true
    })
    .map_err(|e| CampaignError::Scene {
        run: plan.id.clone(),
        source: e,
    })?;
    let (speed, h) = plan
        .scene
        .sheet
        .as_ref()
        .map_or((0.0, 0.0), |s| (s.speed, s.thickness));
    let profile = profile_of(&out.final_state);
    let samples = out
        .series
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let (ridge, ridge_strips) = match ridge.get_mut(i) {
                Some(r) => (r.0, std::mem::take(&mut r.1)),
                None => (RidgeSummary::of(&profile), RunSample::strips_of(&profile)),
            };
            RunSample {
                ridge,
                ridge_strips,
                ..RunSample::of(x, speed * h * x.energy.time)
            }
        })
        .collect();
    let metrics = observe::metrics(
        &profile,
        Some((&out.final_state, &out.summary.rubble_block_lengths, h)),
    );
    Ok((
        RunRecord {
            id: plan.id.clone(),
            settings: plan.settings.clone(),
            seed: plan.seed,
            scene: plan.scene.clone(),
            summary: out.summary,
            samples,
            profile,
            metrics,
            digest: None,
        },
        out.final_state,
    ))
}

/// Path of a run's record in a campaign directory.
pub(crate) fn record_path(out: &Path, id: &str) -> PathBuf {
    out.join("runs").join(id).join("run.json")
}

/// A campaign directory made ready by [`prepare_campaign`]: the whole plan and the runs it
/// still lacks.
#[derive(Clone, Debug)]
pub struct PreparedCampaign {
    /// Every planned run, in plan order.
    pub plan: Vec<PlannedRun>,
    /// The runs without a record yet, in plan order.
    pub todo: Vec<PlannedRun>,
    /// Runs whose record was already written (and matches the plan).
    pub skipped: usize,
}

/// Prepares the result directory `out` of a campaign: plans the runs (`base_dir` resolves a
/// relative scene path), refuses a directory that holds another grid or runs of another
/// scene, writes `campaign.json` and `plan.json` (atomically), and returns the runs still to
/// do. Running each of them with [`run_planned`], in any order, on any machine that sees
/// `out`, completes the campaign; calling this again then finds nothing to do.
pub fn prepare_campaign(
    spec: &CampaignSpec,
    base_dir: &Path,
    out: &Path,
) -> Result<PreparedCampaign, CampaignError> {
    let plan = spec.plan(base_dir)?;
    if is_records_only(out) {
        return Err(CampaignError::Mismatch(format!(
            "{} is a records-only archive ({RECORDS_ONLY}): tabulate it, do not run into it; \
             use a new output directory",
            out.display()
        )));
    }
    check_same_grid(spec, out)?;
    write_json(&out.join("campaign.json"), spec)?;
    write_json(
        &out.join("plan.json"),
        &plan.iter().map(|p| p.id.clone()).collect::<Vec<_>>(),
    )?;
    let mut todo = Vec::new();
    let mut skipped = 0;
    for p in &plan {
        let path = record_path(out, &p.id);
        // A record that is unreadable, copied from another run, or lacks its files is not a
        // finished run: the run is done again (its files are replaced atomically).
        if let Some(r) = finished_record(out, &p.id) {
            if r.scene != p.scene {
                return Err(CampaignError::Mismatch(format!(
                    "{} was made with another scene than the spec now gives; use a new output directory",
                    path.display()
                )));
            }
            check_model(&r, &path)?;
            skipped += 1;
        } else {
            todo.push(p.clone());
        }
    }
    Ok(PreparedCampaign {
        plan,
        todo,
        skipped,
    })
}

/// Refuses the record `r` at `path` when an older model revision made it
/// ([`crate::simulation::MODEL_REVISION`]): the same scene and seed no longer give its
/// numbers, so it is no run of this campaign.
fn check_model(r: &RunRecord, path: &Path) -> Result<(), CampaignError> {
    let now = crate::simulation::MODEL_REVISION;
    if r.summary.model == now {
        return Ok(());
    }
    Err(CampaignError::Mismatch(format!(
        "{} was made by model revision {} and this binary is revision {now} (the same scene \
         and seed give other numbers now, docs/model.md \"Model revisions\"): run into a new \
         output directory",
        path.display(),
        r.summary.model
    )))
}

/// Refuses a result directory whose `campaign.json` holds another grid than `spec`.
fn check_same_grid(spec: &CampaignSpec, out: &Path) -> Result<(), CampaignError> {
    let spec_path = out.join("campaign.json");
    if spec_path.is_file() {
        let old: CampaignSpec = read_json(&spec_path)?;
        if old.axis != spec.axis
            || old.set != spec.set
            || old.sample_interval != spec.sample_interval
        {
            return Err(CampaignError::Mismatch(format!(
                "{} holds a campaign with another grid; use a new output directory",
                out.display()
            )));
        }
    }
    Ok(())
}

/// The record of planned run `id` in `out` when it is a finished run: readable, and
/// consistent with its id, scene and files ([`verify_record`]).
fn finished_record(out: &Path, id: &str) -> Option<RunRecord> {
    let path = record_path(out, id);
    path.is_file()
        .then(|| read_json::<RunRecord>(&path).ok())
        .flatten()
        .filter(|r| verify_record(r, out, id).is_ok())
}

/// Takes the finished runs of this campaign from `archive` (e.g. a records-only archive of an
/// interrupted campaign committed under `crates/lab/records/paper/`) into `out`, so that resuming the
/// campaign in `out` runs only what the archive lacks. A run is taken when the archive holds
/// a record of the same planned run (same id) that passes the check of [`read_campaign`] there and
/// has the planned scene and seed, or else a record of another id with the planned scene and
/// seed (the same run planned by another campaign, e.g. a probe whose setting became the
/// default): a run is its scene and seed, and its record takes this campaign's id and
/// settings. Its record is written into `out` (atomically) without its final state: the
/// record's digest then lists no files, so `out` tabulates like the archive. Runs `out`
/// already holds are left alone; an archive record of the same id with another scene or seed
/// is an error, and so is one an older model revision made. Returns the number of runs
/// taken.
pub fn adopt_records(
    spec: &CampaignSpec,
    base_dir: &Path,
    out: &Path,
    archive: &Path,
) -> Result<usize, CampaignError> {
    if is_records_only(out) {
        return Err(CampaignError::Mismatch(format!(
            "{} is a records-only archive ({RECORDS_ONLY}): resume into a new output directory",
            out.display()
        )));
    }
    check_same_grid(spec, out)?;
    let mut taken = 0;
    let mut by_run: Option<Vec<(PathBuf, RunRecord)>> = None;
    for p in spec.plan(base_dir)? {
        if finished_record(out, &p.id).is_some() {
            continue;
        }
        let from = record_path(archive, &p.id);
        let (from, mut r) = if from.is_file() {
            let r: RunRecord = read_json(&from)?;
            if let Err(why) = verify_record(&r, archive, &p.id) {
                return Err(CampaignError::Mismatch(format!(
                    "{}: {why}",
                    from.display()
                )));
            }
            if r.scene != p.scene || r.seed != p.seed {
                return Err(CampaignError::Mismatch(format!(
                    "{} was made with another scene or seed than the spec now gives",
                    from.display()
                )));
            }
            (from, r)
        } else {
            let all = match &mut by_run {
                Some(all) => all,
                None => by_run.insert(archive_records(archive)?),
            };
            let Some((from, r)) = all
                .iter()
                .find(|(_, r)| r.seed == p.seed && r.scene == p.scene)
            else {
                continue;
            };
            let mut r = r.clone();
            r.id = p.id.clone();
            r.settings = p.settings.clone();
            (from.clone(), r)
        };
        check_model(&r, &from)?;
        r.digest = Some(RunDigest {
            scene: scene_digest(&r.id, r.seed, &r.scene),
            files: Vec::new(),
        });
        write_json(&record_path(out, &p.id), &r)?;
        taken += 1;
    }
    Ok(taken)
}

/// Every record of the campaign archived in `archive` that passes the check of
/// [`read_campaign`] there, with its path.
fn archive_records(archive: &Path) -> Result<Vec<(PathBuf, RunRecord)>, CampaignError> {
    let ids: Vec<String> = read_json(&archive.join("plan.json"))?;
    let mut all = Vec::new();
    for id in ids {
        let path = record_path(archive, &id);
        if let Ok(r) = read_json::<RunRecord>(&path)
            && verify_record(&r, archive, &id).is_ok()
        {
            all.push((path, r));
        }
    }
    Ok(all)
}

/// Runs one planned run of a campaign prepared by [`prepare_campaign`] and writes it into
/// `out`: `runs/<id>/state.json` first, then `runs/<id>/run.json`, each atomically, so a
/// record on disk is always complete and always has its state. `progress` gets the simulated
/// seconds since its previous call. Runs are deterministic: the same planned run gives the
/// same record (but for `summary.wall_seconds`) wherever it is run.
pub fn run_planned(
    plan: &PlannedRun,
    spec: &CampaignSpec,
    out: &Path,
    progress: &dyn Fn(f64),
) -> Result<(), CampaignError> {
    let (mut rec, state) = run_one(plan, spec, progress)?;
    let path = record_path(out, &plan.id);
    // The state first: a record on disk always has its state, and the digest of it.
    let state_path = path.with_file_name("state.json");
    save_state(&state_path, &state)?;
    rec.digest = Some(RunDigest {
        scene: scene_digest(&rec.id, rec.seed, &rec.scene),
        files: vec![(
            "state.json".into(),
            crate::io::digest::sha256_file(&state_path)?,
        )],
    });
    write_json(&path, &rec)?;
    Ok(())
}

/// Runs a campaign into `out` on `threads` worker threads, skipping runs already written
/// ([`prepare_campaign`], then [`run_planned`] for each run still to do, seed by seed over
/// the grid).
/// `progress` is called from the workers (it must be cheap and thread-safe). `stop` ends the
/// campaign after the runs in flight when set. Returns the number of runs (skipped, done).
pub fn run_campaign(
    spec: &CampaignSpec,
    base_dir: &Path,
    out: &Path,
    threads: usize,
    progress: &(dyn Fn(Progress) + Sync),
    stop: &AtomicBool,
) -> Result<(usize, usize), CampaignError> {
    let PreparedCampaign {
        plan,
        mut todo,
        skipped,
    } = prepare_campaign(spec, base_dir, out)?;
    // Seed by seed over the grid: a campaign stopped part-way leaves every point with about
    // as many seeds as every other, an ensemble that can be compared point with point. Each
    // run is its own, so the order changes no result.
    todo.sort_by_key(|p| (p.seed, p.point));
    let total = plan.len();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let simulated = Mutex::new(0.0f64);
    let first_error: Mutex<Option<CampaignError>> = Mutex::new(None);
    let report = |d: usize| {
        let s = *simulated.lock().expect("progress lock");
        progress(Progress {
            skipped,
            done: d,
            total,
            simulated: s,
        });
    };
    report(0);
    std::thread::scope(|scope| {
        for _ in 0..threads.max(1).min(todo.len().max(1)) {
            scope.spawn(|| {
                loop {
                    if stop.load(Ordering::Relaxed) || first_error.lock().expect("lock").is_some() {
                        return;
                    }
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(p) = todo.get(k) else {
                        return;
                    };
                    let tick = |dt: f64| {
                        *simulated.lock().expect("progress lock") += dt;
                        report(done.load(Ordering::Relaxed));
                    };
                    let result = run_planned(p, spec, out, &tick);
                    match result {
                        Ok(()) => {
                            let d = done.fetch_add(1, Ordering::Relaxed) + 1;
                            report(d);
                        }
                        Err(e) => {
                            first_error.lock().expect("lock").get_or_insert(e);
                            return;
                        }
                    }
                }
            });
        }
    });
    if let Some(e) = first_error.into_inner().expect("lock") {
        return Err(e);
    }
    Ok((skipped, done.load(Ordering::Relaxed)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A planned run survives JSON exactly, so it can be run in another process.
    #[test]
    fn planned_run_round_trips_through_json() {
        let spec = CampaignSpec::from_toml(
            "name = \"x\"\nseeds = 2\n[[axis]]\nkey = \"contact.mu\"\nvalues = [0.4, 1.0]",
        )
        .unwrap();
        let plan = spec.plan(Path::new(".")).unwrap();
        assert_eq!(plan.len(), 4);
        for p in &plan {
            let text = serde_json::to_string(p).unwrap();
            let back: PlannedRun = serde_json::from_str(&text).unwrap();
            assert_eq!(&back, p);
        }
    }
}
