//! Running a scene: step the world to the scene's duration, sample the energy budget at the
//! scene's interval, and summarise. No file formats here (see [`crate::io`]).

use crate::dem::{EnergyBudget, Snapshot, World};
use crate::scene::{Scene, SceneError};
use serde::{Deserialize, Serialize};

/// The headline numbers of a run. Energies are in J per metre of ridge, changes since the
/// start of the run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Scene name.
    pub scene: String,
    /// Seed of the scene.
    pub seed: u64,
    /// Package version that produced the run.
    pub version: String,
    /// Simulated time (s).
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// Time step (s).
    pub dt: f64,
    /// Wall-clock time of the stepping (s).
    pub wall_seconds: f64,
    /// Number of bodies.
    pub bodies: usize,
    /// Work done by prescribed motions, eq (9) (J/m).
    pub work: f64,
    /// Change of potential energy, eq (10) (J/m).
    pub potential_energy: f64,
    /// Change of kinetic energy (J/m).
    pub kinetic_energy: f64,
    /// Frictional dissipation Φ_f, eq (11) (J/m).
    pub friction_dissipation: f64,
    /// Viscous contact dissipation Φ_i, eq (12) (J/m).
    pub viscous_dissipation: f64,
    /// Drag dissipation (J/m).
    pub drag_dissipation: f64,
    /// Elastic energy held in contacts at the end (J/m).
    pub elastic_energy: f64,
    /// Other dissipation (J/m).
    pub other_dissipation: f64,
    /// Work minus all sinks (J/m).
    pub residual: f64,
    /// Largest |residual| over all samples divided by the largest ledger term at that
    /// sample (dimensionless).
    pub max_relative_residual: f64,
    /// Work divided by ΔPE (dimensionless); NaN-free: 0 when ΔPE is 0.
    pub ratio_work_to_pe: f64,
}

/// Everything a run produces.
#[derive(Clone, Debug)]
pub struct RunOutput {
    /// Headline numbers.
    pub summary: Summary,
    /// The energy budget at every sample, starting at t = 0.
    pub series: Vec<EnergyBudget>,
    /// The final state.
    pub final_state: Snapshot,
}

/// Builds the scene's world and runs it for the scene's duration. `progress` is called at
/// every sample with the simulated time (s); it returns `false` to stop early (the output
/// then covers the time reached).
pub fn run(scene: &Scene, progress: &mut dyn FnMut(f64) -> bool) -> Result<RunOutput, SceneError> {
    let mut world = scene.build()?;
    Ok(run_world(&mut world, scene, progress))
}

/// Runs an already built world to the scene's duration (see [`run`]).
pub fn run_world(
    world: &mut World,
    scene: &Scene,
    progress: &mut dyn FnMut(f64) -> bool,
) -> RunOutput {
    let start = std::time::Instant::now();
    let interval = scene.numerics.sample_interval;
    let mut series = vec![world.energy()];
    let mut next = world.time() + interval;
    let mut max_rel: f64 = 0.0;
    let mut keep_going = progress(world.time());
    while keep_going && world.time() < scene.duration - 0.5 * world.dt() {
        world.step();
        if world.time() >= next - 0.5 * world.dt() {
            let e = world.energy();
            max_rel = max_rel.max(relative_residual(&e));
            series.push(e);
            next += interval;
            keep_going = progress(world.time());
        }
    }
    let e = world.energy();
    max_rel = max_rel.max(relative_residual(&e));
    if series.last().map(|s| s.time) != Some(e.time) {
        series.push(e);
    }
    let summary = Summary {
        scene: scene.name.clone(),
        seed: scene.seed,
        version: env!("CARGO_PKG_VERSION").into(),
        time: world.time(),
        steps: world.steps(),
        dt: world.dt(),
        wall_seconds: start.elapsed().as_secs_f64(),
        bodies: world.bodies.len(),
        work: e.work,
        potential_energy: e.potential_energy,
        kinetic_energy: e.kinetic_energy,
        friction_dissipation: e.friction_dissipation,
        viscous_dissipation: e.viscous_dissipation,
        drag_dissipation: e.drag_dissipation,
        elastic_energy: e.elastic_energy,
        other_dissipation: e.other_dissipation,
        residual: e.residual,
        max_relative_residual: max_rel,
        ratio_work_to_pe: if e.potential_energy != 0.0 {
            e.work / e.potential_energy + 0.0
        } else {
            0.0
        },
    };
    RunOutput {
        summary,
        series,
        final_state: world.snapshot(),
    }
}

fn relative_residual(e: &EnergyBudget) -> f64 {
    let scale = e.largest_term();
    if scale > 0.0 {
        e.residual.abs() / scale
    } else {
        0.0
    }
}
