//! The record of one finished ridging run (`run.json`): its settings, seed and resolved
//! scene, the run summary, the ledger sampled at the campaign's interval, the final profile
//! and ridge metrics. `campaign` writes and checks it, `table` reads it: it sits below both,
//! so that no import runs upward (docs/architecture.md). How a record is found on disk and
//! verified against its files stays in `pressridge::campaign`, in the crate above this one.

use crate::energy::{EnergyBudget, Keep, LEDGER_FILES, TermSet, Terms};
use crate::observe::{Profile, RidgeMetrics, RidgeSummary, ridged_strips};
use crate::scene::Scene;
use crate::simulation::{self, Summary};
use serde::{Deserialize, Serialize};

/// A sample of a run at the campaign's interval.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RunSample {
    /// Time (s).
    pub time: f64,
    /// Ridged-ice volume V = U·h·t (m³/m).
    pub volume: f64,
    /// The ledger terms a sample keeps ([`crate::energy::TermFile::sample`]: work and ΔPE, which the
    /// tables fit, and every dissipation, which their gate checks), each under its name
    /// (J/m).
    #[serde(flatten)]
    pub ledger: Terms<Sampled>,
    /// Mean ridging force over the interval ending here, Δwork/(U·Δt) (N/m).
    pub mean_force: f64,
    /// The ridged ice at this time, from the profile on the campaign's strips; absent
    /// without rubble and in records written before it was kept (2026-11-28).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ridge: Option<RidgeSummary>,
    /// The ridged strips at this time, `[solid, column]` (m, to the millimetre), in strip
    /// order: the strips of the campaign's profile that hold rubble ([`ridged_strips`]),
    /// whose area-weighted thicknesses are the ridged ice's distribution at this time. Empty
    /// without rubble and in records written before it was kept (2026-11-28).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub ridge_strips: Vec<[f64; 2]>,
}

/// The terms of [`RunSample::ledger`]: the column [`crate::energy::TermFile::sample`] of the files' table.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Sampled;

impl TermSet for Sampled {
    fn keep(k: usize) -> Keep {
        LEDGER_FILES[k].sample
    }
}

impl RunSample {
    /// The campaign's record of sample `x` of a run, with ridged volume `volume` (m³/m).
    pub fn of(x: &simulation::Sample, volume: f64) -> RunSample {
        RunSample {
            time: x.energy.time,
            volume,
            ledger: Terms::of(&x.energy),
            mean_force: x.mean_force,
            ridge: None,
            ridge_strips: Vec::new(),
        }
    }

    /// The ridged strips of profile `p` as a sample keeps them ([`RunSample::ridge_strips`]):
    /// `[solid, column]` rounded to the millimetre.
    pub fn strips_of(p: &Profile) -> Vec<[f64; 2]> {
        let mm = |x: f64| (x * 1e3).round() / 1e3;
        ridged_strips(p)
            .into_iter()
            .map(|(s, c)| [mm(s), mm(c)])
            .collect()
    }

    /// The sample as an energy budget (J/m): the terms a sample keeps, the others zero.
    pub fn energy(&self) -> EnergyBudget {
        self.ledger.energy(self.time)
    }

    /// Replaces the kept ledger terms by those of `e` (J/m; its time is not used).
    pub fn set_energy(&mut self, e: &EnergyBudget) {
        self.ledger = Terms::of(e);
    }
}

/// What one run of a campaign leaves behind (`run.json`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunRecord {
    /// Run id.
    pub id: String,
    /// Axis settings, `key=value`.
    pub settings: Vec<String>,
    /// Seed.
    pub seed: u64,
    /// The resolved scene.
    pub scene: Scene,
    /// Summary of the run.
    pub summary: Summary,
    /// Samples at the campaign interval.
    pub samples: Vec<RunSample>,
    /// Final profile.
    pub profile: Profile,
    /// Final ridge metrics.
    pub metrics: RidgeMetrics,
    /// Digests of what the run is and what it wrote, checked by
    /// `pressridge::campaign::read_campaign` and `pressridge::campaign::prepare_campaign`. Absent
    /// in records written before digests were introduced.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub digest: Option<RunDigest>,
}

/// Digests (SHA-256, hexadecimal) that tie a run record to its run: a record copied from
/// another run directory, edited, or left without the files it wrote no longer matches.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunDigest {
    /// Digest of the run id, the seed and the resolved scene
    /// (`pressridge::campaign::scene_digest`).
    pub scene: String,
    /// The files the run wrote beside its record (file name, digest of its content).
    pub files: Vec<(String, String)>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::energy::LEDGER_TERMS;
    use crate::energy::files::check;

    /// A campaign's sample keeps the terms of the table's `sample` column under their names,
    /// in the table's order, between the volume and the mean force.
    #[test]
    fn a_sample_keeps_its_ledger_terms_by_the_table() {
        let json = serde_json::json!({"time": 1.0, "volume": 2.0, "mean_force": 3.0});
        let text = check::file(json, |k| LEDGER_FILES[k].sample, RunSample::energy);
        let at = |k: &str| check::key_at(&text, k);
        for (t, _) in LEDGER_TERMS
            .iter()
            .zip(&LEDGER_FILES)
            .filter(|(_, f)| f.sample != Keep::No)
        {
            assert!(at("volume") < at(t.name) && at(t.name) < at("mean_force"));
        }
    }

    /// A sample records every dissipation of the ledger ([`crate::energy::LEDGER_TERMS`]),
    /// so the dissipation gate of the tables sees them all.
    #[test]
    fn run_sample_keeps_every_dissipation() {
        let e = EnergyBudget {
            friction_dissipation: 1.0,
            viscous_dissipation: 2.0,
            drag_dissipation: 3.0,
            joint_dissipation: 4.0,
            boundary_dissipation: 5.0,
            fracture_dissipation: 6.0,
            plastic_dissipation: 7.0,
            ..Default::default()
        };
        let x = simulation::Sample {
            energy: e,
            ..Default::default()
        };
        let kept: Vec<_> = RunSample::of(&x, 0.0).energy().dissipations().collect();
        let all: Vec<_> = e.dissipations().collect();
        assert_eq!(kept, all);
        assert!(all.iter().all(|&(_, v)| v > 0.0), "{all:?}");
    }
}
