//! The record of one finished ridging run (`run.json`): its settings, seed and resolved
//! scene, the run summary, the ledger sampled at the campaign's interval, the final profile
//! and ridge metrics. `campaign` writes and checks it, `table` reads it: it sits below both,
//! so that no import runs upward (docs/architecture.md). How a record is found on disk and
//! verified against its files stays in [`crate::campaign`].

use crate::dem::EnergyBudget;
use crate::observe::{Profile, RidgeMetrics};
use crate::scene::Scene;
use crate::simulation::{self, Summary};
use serde::{Deserialize, Serialize};

/// A sample of a run at the campaign's interval.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RunSample {
    /// Time (s).
    pub time: f64,
    /// Ridged-ice volume V = U·h·t (m³/m).
    pub volume: f64,
    /// Work W, eq (9) (J/m).
    pub work: f64,
    /// ΔPE, eq (10) (J/m).
    pub potential_energy: f64,
    /// Frictional dissipation Φ_f, eq (11) (J/m).
    pub friction_dissipation: f64,
    /// Viscous contact dissipation Φ_i, eq (12) (J/m).
    pub viscous_dissipation: f64,
    /// Drag dissipation (J/m).
    #[serde(default)]
    pub drag_dissipation: f64,
    /// Joint viscous dissipation (J/m).
    #[serde(default)]
    pub joint_dissipation: f64,
    /// Boundary dashpot dissipation (J/m).
    #[serde(default)]
    pub boundary_dissipation: f64,
    /// Fracture dissipation (J/m).
    #[serde(default)]
    pub fracture_dissipation: f64,
    /// Mean ridging force over the interval ending here, Δwork/(U·Δt) (N/m).
    pub mean_force: f64,
}

impl RunSample {
    /// The campaign's record of sample `x` of a run, with ridged volume `volume` (m³/m).
    pub fn of(x: &simulation::Sample, volume: f64) -> RunSample {
        let e = &x.energy;
        RunSample {
            time: e.time,
            volume,
            work: e.work,
            potential_energy: e.potential_energy,
            friction_dissipation: e.friction_dissipation,
            viscous_dissipation: e.viscous_dissipation,
            drag_dissipation: e.drag_dissipation,
            joint_dissipation: e.joint_dissipation,
            boundary_dissipation: e.boundary_dissipation,
            fracture_dissipation: e.fracture_dissipation,
            mean_force: x.mean_force,
        }
    }

    /// The sample as an energy budget (J/m): the terms a sample records (work, ΔPE and
    /// every dissipation), the others zero.
    pub fn energy(&self) -> EnergyBudget {
        EnergyBudget {
            time: self.time,
            work: self.work,
            potential_energy: self.potential_energy,
            friction_dissipation: self.friction_dissipation,
            viscous_dissipation: self.viscous_dissipation,
            drag_dissipation: self.drag_dissipation,
            joint_dissipation: self.joint_dissipation,
            boundary_dissipation: self.boundary_dissipation,
            fracture_dissipation: self.fracture_dissipation,
            ..EnergyBudget::default()
        }
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
    /// [`crate::campaign::read_campaign`] and [`crate::campaign::prepare_campaign`]. Absent
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
    /// ([`crate::campaign::scene_digest`]).
    pub scene: String,
    /// The files the run wrote beside its record (file name, digest of its content).
    pub files: Vec<(String, String)>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sample records every dissipation of the ledger ([`crate::dem::ledger::LEDGER_TERMS`]),
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
