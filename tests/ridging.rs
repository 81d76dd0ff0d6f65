//! The intact lead-ice ridging experiment in short runs: the budget closes, the sheet breaks,
//! hard cases stay finite, and runs are reproducible.

use pressridge::scene::Scene;
use pressridge::simulation::{self, RunOutput};

fn run(sets: &[&str]) -> RunOutput {
    let scene = Scene::default().with_overrides(sets).unwrap();
    simulation::run(&scene, &mut |_| true).unwrap()
}

fn check_finite_and_closed(out: &RunOutput, what: &str) {
    let s = &out.summary;
    for b in &out.final_state.bodies {
        assert!(
            b.pos.x.is_finite() && b.pos.y.is_finite() && b.theta.is_finite(),
            "{what}: non-finite body"
        );
    }
    for x in &out.series {
        assert!(x.ridging_force.is_finite(), "{what}: non-finite force");
    }
    assert!(s.work > 0.0, "{what}: no work done: {s:?}");
    assert!(
        s.max_relative_residual < 0.01 && s.residual.abs() < 0.01 * s.work,
        "{what}: budget does not close: {s:?}"
    );
    assert!(s.blocks_broken > 0, "{what}: the sheet never broke");
}

/// A 20-s ridging run (5 m of sheet) closes its budget within 1 % of the work, breaks the
/// sheet into rubble, and books energy where the paper says it goes: mostly friction and
/// potential energy, little in kinetic energy.
#[test]
fn short_ridging_run_closes_its_budget_and_breaks_blocks() {
    let out = run(&["duration=20"]);
    check_finite_and_closed(&out, "default 20 s");
    let s = &out.summary;
    assert!(s.potential_energy > 0.0, "{s:?}");
    assert!(s.friction_dissipation > 0.0 && s.viscous_dissipation > 0.0);
    assert!(s.kinetic_energy.abs() < 0.05 * s.work, "{s:?}");
    assert!(!s.rubble_block_lengths.is_empty());
    assert!(s.rubble_block_lengths.iter().all(|&l| l >= 0.25 - 1e-9));
    assert!((s.ridged_volume - 0.25 * 0.30 * 20.0).abs() < 0.01);
    // The force of eq (9) is the resistance of the ridge: on average positive.
    let mean: f64 =
        out.series.iter().map(|x| x.ridging_force).sum::<f64>() / out.series.len() as f64;
    assert!(mean > 0.0, "mean ridging force {mean} N/m");
}

#[test]
fn hard_case_thin_sheet() {
    check_finite_and_closed(&run(&["duration=8", "sheet.thickness=0.10"]), "h = 0.10 m");
}

#[test]
fn hard_case_thick_sheet() {
    check_finite_and_closed(
        &run(&[
            "duration=8",
            "sheet.thickness=0.45",
            "sheet.block_width=0.30",
        ]),
        "h = 0.45 m",
    );
}

#[test]
fn hard_case_fast_push() {
    check_finite_and_closed(&run(&["duration=5", "sheet.speed=1.0"]), "U = 1 m/s");
}

#[test]
fn hard_case_stiff_sheet() {
    check_finite_and_closed(
        &run(&["duration=8", "sheet.e_top=1.0e9", "sheet.e_bottom=6.7e8"]),
        "E = 1 GPa",
    );
}

#[test]
fn hard_case_frictionless() {
    check_finite_and_closed(
        &run(&["duration=8", "contact.mu=0.0", "contact.mu_water=0.0"]),
        "μ = 0",
    );
}

#[test]
fn hard_case_high_friction() {
    check_finite_and_closed(&run(&["duration=8", "contact.mu=1.2"]), "μ = 1.2");
}

/// Same scene and seed ⇒ bit-identical summary and series; another seed ⇒ other rubble.
#[test]
fn ridging_is_reproducible_and_seed_dependent() {
    let a = run(&["duration=12"]);
    let b = run(&["duration=12"]);
    let c = run(&["duration=12", "seed=2"]);
    let strip = |o: &RunOutput| {
        let mut s = o.summary.clone();
        s.wall_seconds = 0.0;
        s
    };
    assert_eq!(strip(&a), strip(&b));
    assert_eq!(a.series, b.series);
    assert_ne!(
        serde_json::to_string(&a.final_state.bodies).unwrap(),
        serde_json::to_string(&c.final_state.bodies).unwrap(),
        "a different seed must give different rubble"
    );
}
