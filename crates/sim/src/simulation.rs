//! Running a scene: step the world to the scene's duration, sample the energy budget and the
//! ridging force at the scene's interval, and summarise. No file formats here (they are
//! `pressridge::io`, in the crate above this one).

use crate::dem::{Role, Snapshot, World};
use crate::energy::{
    EnergyBudget, Keep, LEDGER_FILES, LEDGER_TERMS, N_TERMS, Sign, TermSet, Terms,
};
use crate::scene::{Scene, SceneError};
use serde::{Deserialize, Serialize};

/// The headline numbers of a run. Energies are in J per metre of ridge, changes since the
/// start of the run; the ledger's terms, kept by its table, are read through
/// [`Summary::energy`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Scene name.
    pub scene: String,
    /// Seed of the scene.
    pub seed: u64,
    /// Package version that produced the run.
    pub version: String,
    /// Model revision that produced the run ([`MODEL_REVISION`]); runs made before it was
    /// recorded are revision 1.
    #[serde(default = "first_revision")]
    pub model: u32,
    /// Simulated time (s).
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// Time step (s).
    pub dt: f64,
    /// Wall-clock time of the stepping (s).
    pub wall_seconds: f64,
    /// Number of bodies at the end.
    pub bodies: usize,
    /// The ledger's inputs at the end of the run (the [`Sign::Input`] terms of
    /// [`LEDGER_TERMS`], J/m), each under its name.
    #[serde(flatten)]
    pub inputs: Terms<SummaryInputs>,
    /// Work by eq (9) as the paper writes it: U·Δt·Σ F_x of the contact forces that other
    /// bodies exert on the sheet (J/m). It leaves out the sheet's own inertia, buoyancy and
    /// boundary forces, so it differs from `work` by those.
    pub work_eq9: f64,
    /// Every other term of the ledger at the end of the run (J/m), each under its name.
    #[serde(flatten)]
    pub sinks: Terms<SummarySinks>,
    /// Largest |residual| over all samples divided by the largest ledger term at that
    /// sample (dimensionless).
    pub max_relative_residual: f64,
    /// Work divided by ΔPE (dimensionless); 0 when ΔPE is 0.
    pub ratio_work_to_pe: f64,
    /// Ridged-ice volume V = U·h·t per metre of ridge (m³/m); 0 without a sheet.
    pub ridged_volume: f64,
    /// Number of joints severed (blocks broken from the sheet, floe or rubble).
    pub blocks_broken: u64,
    /// Severed joints whose two blocks overlapped at severance; their contacts were born
    /// with that overlap forgiven (see `dem::contact`). Absent in older runs.
    #[serde(default)]
    pub handover_contacts: u64,
    /// Largest overlap forgiven at a severance (m²).
    #[serde(default)]
    pub max_handover_overlap: f64,
    /// Largest distance by which the leading edge of the intact lead sheet passed the
    /// floe's nose, over every step (m; negative if it never reached it): the rafting
    /// diagnostic (`pressridge::table::rafting`). Absent without a sheet and a floe, and in runs
    /// made before it was recorded (2026-11-23).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sheet_overrun_max: Option<f64>,
    /// Length of every rubble piece at the end (m).
    pub rubble_block_lengths: Vec<f64>,
    /// The contacts' restitution at impacts and their damping ratios over the run; absent in
    /// runs made before it was recorded (model revision 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contacts: Option<ContactSummary>,
}

/// The revision of the simulator's physics: it changes whenever the same scene and seed give
/// other numbers, so that a campaign never pools or resumes runs of two models
/// (docs/model.md, "Model revisions"). 1: every run made before 2026-12-01; 2: the drag
/// moment on the body's own outline (`dem::water`).
pub const MODEL_REVISION: u32 = 2;

fn first_revision() -> u32 {
    1
}

/// The contacts of a run in numbers: restitution of the impacts and damping ratios of the
/// active contacts (dimensionless), each as its 10th, 50th and 90th percentile, read from
/// the histograms the world keeps ([`crate::dem::ContactTally`]; to the bin: 0.01 in e, a
/// hundredth of a decade in ζ).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ContactSummary {
    /// Impacts counted: contacts born by approach at ≥ 1 cm/s that ended within 0.1 s.
    pub impacts: u64,
    /// Restitution e = v_out/v_in of the impacts: 10th, 50th, 90th percentile (none without
    /// impacts).
    pub restitution: Option<[f64; 3]>,
    /// Contact-samples counted for ζ (active contacts at every sample of the run).
    pub contact_samples: u64,
    /// Damping ratio ζ = c·sqrt(κ)/(2·sqrt(k_ne·L)) of the contacts' dashpots: 10th, 50th,
    /// 90th percentile (none without contacts).
    pub damping_ratio: Option<[f64; 3]>,
}

impl ContactSummary {
    /// The summary of a world's contact tally.
    pub fn of(t: &crate::dem::ContactTally) -> ContactSummary {
        ContactSummary {
            impacts: t.restitution.iter().sum(),
            restitution: t.restitution_percentiles(),
            contact_samples: t.zeta.iter().sum(),
            damping_ratio: t.damping_ratio_percentiles(),
        }
    }
}

/// The terms of [`Summary::inputs`]: the inputs, which `summary.json` writes before
/// `work_eq9`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SummaryInputs;

impl TermSet for SummaryInputs {
    fn keep(k: usize) -> Keep {
        if LEDGER_TERMS[k].sign == Sign::Input {
            LEDGER_FILES[k].summary
        } else {
            Keep::No
        }
    }
}

/// The terms of [`Summary::sinks`]: every term but the inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SummarySinks;

impl TermSet for SummarySinks {
    fn keep(k: usize) -> Keep {
        if LEDGER_TERMS[k].sign == Sign::Input {
            Keep::No
        } else {
            LEDGER_FILES[k].summary
        }
    }
}

impl Summary {
    /// The ledger at the end of the run as an energy budget (J/m; its `time` is the
    /// simulated time, s).
    pub fn energy(&self) -> EnergyBudget {
        let mut values = [0.0; N_TERMS];
        self.inputs.write_into(&mut values);
        self.sinks.write_into(&mut values);
        EnergyBudget::from_values(self.time, values)
    }

    /// Replaces the ledger terms by those of `e` (J/m; its time is not used).
    pub fn set_energy(&mut self, e: &EnergyBudget) {
        self.inputs = Terms::of(e);
        self.sinks = Terms::of(e);
    }
}

/// One sample of a run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Sample {
    /// The energy budget (its `time` is the sample time, s).
    pub energy: EnergyBudget,
    /// The ridging force of eq (9) at that instant (N/m).
    pub ridging_force: f64,
    /// The mean force the driver exerted since the previous sample, Δwork/(U·Δt) (N/m);
    /// 0 without a sheet.
    pub mean_force: f64,
}

/// Number of columns of a [`Sample`] row: time, the ledger terms, two forces.
pub const SERIES_LEN: usize = LEDGER_TERMS.len() + 3;

/// Column names and units of a [`Sample`] as [`Sample::row`] lays it out (the CSV time
/// series and the Python `simulate` use this one list): time, every term of
/// [`LEDGER_TERMS`], the ridging force and the mean force.
pub fn series_columns() -> [(&'static str, &'static str); SERIES_LEN] {
    let mut out = [("time", "s"); SERIES_LEN];
    for (k, t) in LEDGER_TERMS.iter().enumerate() {
        out[k + 1] = (t.name, t.unit);
    }
    out[SERIES_LEN - 2] = ("ridging_force", "N/m");
    out[SERIES_LEN - 1] = ("mean_force", "N/m");
    out
}

impl Sample {
    /// The sample's values in the order and units of [`series_columns`].
    pub fn row(&self) -> [f64; SERIES_LEN] {
        let mut out = [0.0; SERIES_LEN];
        out[0] = self.energy.time;
        out[1..=LEDGER_TERMS.len()].copy_from_slice(&self.energy.values());
        out[SERIES_LEN - 2] = self.ridging_force;
        out[SERIES_LEN - 1] = self.mean_force;
        out
    }
}

/// Everything a run produces.
#[derive(Clone, Debug)]
pub struct RunOutput {
    /// Headline numbers.
    pub summary: Summary,
    /// Samples at the scene's interval, starting at t = 0.
    pub series: Vec<Sample>,
    /// The final state.
    pub final_state: Snapshot,
}

/// Builds the scene's world and runs it for the scene's duration. `observe` is called at
/// every sample with the world; it returns `false` to stop early (the output then covers
/// the time reached).
pub fn run(
    scene: &Scene,
    observe: &mut dyn FnMut(&World) -> bool,
) -> Result<RunOutput, SceneError> {
    run_on(scene, 1, observe)
}

/// [`run`] with each step's force phases on `threads` threads ([`World::set_threads`]): the
/// same output to the bit, sooner on several cores.
pub fn run_on(
    scene: &Scene,
    threads: usize,
    observe: &mut dyn FnMut(&World) -> bool,
) -> Result<RunOutput, SceneError> {
    let mut world = scene.build()?;
    scene.check_run_length(world.dt())?;
    world.set_threads(threads)?;
    run_world(&mut world, scene, observe)
}

/// Runs an already built world to the scene's duration (see [`run`]). A step that turns
/// the state non-finite ends the run at once with [`crate::dem::WorldError::NonFinite`].
pub fn run_world(
    world: &mut World,
    scene: &Scene,
    observe: &mut dyn FnMut(&World) -> bool,
) -> Result<RunOutput, SceneError> {
    let start = std::time::Instant::now();
    let interval = scene.numerics.sample_interval;
    let speed = scene.sheet.as_ref().map_or(0.0, |s| s.speed);
    let thickness = scene.sheet.as_ref().map_or(0.0, |s| s.thickness);
    let t0 = world.time();
    let sample = |w: &World, prev: Option<&Sample>| {
        let e = w.energy();
        let mean_force = match prev {
            Some(p) if speed > 0.0 && e.time > p.energy.time => {
                (e.work - p.energy.work) / (speed * (e.time - p.energy.time))
            }
            _ => 0.0,
        };
        Sample {
            energy: e,
            ridging_force: w.ridging_force(),
            mean_force,
        }
    };
    let mut series = vec![sample(world, None)];
    let mut next = t0 + interval;
    let mut max_rel: f64 = 0.0;
    let mut work_eq9 = 0.0;
    let mut keep_going = observe(world);
    let mut overrun = world.sheet_overrun();
    let end = scene.duration - 0.5 * world.dt();
    while keep_going && world.time() < end {
        // The steps to the next sample, in the world's thread pool (one hand-over for all).
        world.in_pool(|world| {
            while world.time() < end {
                world.step();
                if world.fault().is_some() {
                    return;
                }
                if let (Some(o), Some(x)) = (overrun.as_mut(), world.sheet_overrun()) {
                    *o = o.max(x);
                }
                if speed > 0.0 {
                    work_eq9 += speed * world.last_step() * world.ridging_force();
                }
                if world.time() >= next - 0.5 * world.dt() {
                    return;
                }
            }
        });
        if let Some(e) = world.fault() {
            return Err(SceneError::World(e.clone()));
        }
        if world.time() >= next - 0.5 * world.dt() {
            world.tally_contacts();
            let s = sample(world, series.last());
            max_rel = max_rel.max(relative_residual(&s.energy));
            series.push(s);
            next += interval;
            keep_going = observe(world);
        }
    }
    if series.last().map(|s| s.energy.time) != Some(world.time()) {
        let s = sample(world, series.last());
        series.push(s);
    }
    let e = series.last().expect("at least one sample").energy;
    max_rel = max_rel.max(relative_residual(&e));
    let summary = Summary {
        scene: scene.name.clone(),
        seed: scene.seed,
        version: env!("CARGO_PKG_VERSION").into(),
        model: MODEL_REVISION,
        time: world.time(),
        steps: world.steps(),
        dt: world.dt(),
        wall_seconds: start.elapsed().as_secs_f64(),
        bodies: world.bodies.len(),
        inputs: Terms::of(&e),
        work_eq9,
        sinks: Terms::of(&e),
        max_relative_residual: max_rel,
        ratio_work_to_pe: if e.potential_energy != 0.0 {
            e.work / e.potential_energy + 0.0
        } else {
            0.0
        },
        ridged_volume: speed * thickness * (world.time() - t0),
        blocks_broken: world.blocks_broken(),
        handover_contacts: world.handovers().count,
        max_handover_overlap: world.handovers().max_area,
        sheet_overrun_max: overrun,
        rubble_block_lengths: rubble_lengths(world),
        contacts: Some(ContactSummary::of(world.contact_tally())),
    };
    Ok(RunOutput {
        summary,
        series,
        final_state: world.snapshot(),
    })
}

/// Lengths (m) of the rubble pieces: blocks of role rubble joined by intact joints, the
/// length of a piece being the sum of its blocks' widths. Sorted by the piece's leftmost
/// block index, so the order is reproducible.
pub fn rubble_lengths(world: &World) -> Vec<f64> {
    let b = &world.bodies;
    let n = b.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(p: &mut [usize], mut i: usize) -> usize {
        while p[i] != i {
            p[i] = p[p[i]];
            i = p[i];
        }
        i
    }
    for j in world.joints() {
        let (a, c) = (j.a as usize, j.b as usize);
        if j.is_intact() && b.role[a] == Role::Rubble && b.role[c] == Role::Rubble {
            let (ra, rc) = (find(&mut parent, a), find(&mut parent, c));
            if ra != rc {
                parent[ra.max(rc)] = ra.min(rc);
            }
        }
    }
    let mut len = vec![0.0; n];
    let mut roots = Vec::new();
    for i in 0..n {
        if b.role[i] == Role::Rubble {
            let r = find(&mut parent, i);
            if len[r] == 0.0 {
                roots.push(r);
            }
            len[r] += b.block[i].map_or(0.0, |x| x.width);
        }
    }
    roots.sort_unstable();
    roots.iter().map(|&r| len[r]).collect()
}

fn relative_residual(e: &EnergyBudget) -> f64 {
    let scale = e.largest_term();
    if scale > 0.0 {
        e.residual.abs() / scale
    } else {
        0.0
    }
}

#[cfg(test)]
mod summary_fixture;
#[cfg(test)]
pub(crate) use summary_fixture::summary_without_ledger;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::energy::LedgerTerm;
    use crate::energy::files::check;

    /// `summary.json` keeps every ledger term of the table under its name, in the table's
    /// order, with `work_eq9` right after the inputs, between the run's head and tail.
    #[test]
    fn the_summary_keeps_the_ledger_by_the_table() {
        let text = check::file(
            summary_without_ledger(),
            |k| LEDGER_FILES[k].summary,
            Summary::energy,
        );
        assert!(LEDGER_FILES.iter().all(|f| f.summary != Keep::No));
        let at = |k: &str| check::key_at(&text, k);
        let inputs: Vec<&LedgerTerm> = LEDGER_TERMS
            .iter()
            .filter(|t| t.sign == Sign::Input)
            .collect();
        let (first, last) = (LEDGER_TERMS[0].name, LEDGER_TERMS[N_TERMS - 1].name);
        assert!(inputs.iter().all(|t| at(t.name) < at("work_eq9")));
        assert!(
            LEDGER_TERMS[inputs.len()..]
                .iter()
                .all(|t| at("work_eq9") < at(t.name))
        );
        assert!(at("bodies") < at(first) && at(last) < at("max_relative_residual"));
    }
}
