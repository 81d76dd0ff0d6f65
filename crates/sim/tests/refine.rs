//! The step refined around fracture (`numerics.refine_window`, docs/speed-vs-error.md):
//! off, nothing changes; at a fraction of 1 it is the one step to the bit (the kick
//! ½·(Δt + Δt) is Δt exactly); on, the run takes more steps where the sheet breaks, its
//! ledger still closes to round-off, and its distance pushed is the time run times U. The
//! default refines (window, load and impacts on); "off" switches each off, in TOML, JSON and
//! `--set` alike.

use pressridge_sim::scene::Scene;
use pressridge_sim::simulation::{self, RunOutput};

/// 8 s of the Figure 5 scene at the full limit, every refinement off unless `sets` turns it
/// on: its first breaks come after about 5.6 s.
fn run(sets: &[&str]) -> RunOutput {
    let mut all = vec![
        "duration=8",
        "numerics.time_step_safety=1.0",
        "numerics.refine_window=off",
        "numerics.refine_load=off",
        "numerics.refine_impact=off",
    ];
    all.extend_from_slice(sets);
    let scene = Scene::default().with_overrides(&all).unwrap();
    simulation::run(&scene, &mut |_| true).unwrap()
}

#[test]
fn a_refined_step_of_the_whole_step_changes_no_bit() {
    let plain = run(&[]);
    let same = run(&["numerics.refine_window=0.02", "numerics.refine_fraction=1"]);
    assert!(plain.summary.blocks_broken > 0, "no break to refine around");
    assert_eq!(plain.summary.steps, same.summary.steps);
    assert_eq!(
        serde_json::to_string(&plain.final_state.bodies).unwrap(),
        serde_json::to_string(&same.final_state.bodies).unwrap()
    );
    assert_eq!(
        plain.summary.energy().work.to_bits(),
        same.summary.energy().work.to_bits()
    );
}

#[test]
fn a_refined_step_takes_more_steps_and_its_ledger_closes() {
    let plain = run(&[]);
    let refined = run(&["numerics.refine_window=0.02"]);
    let (p, r) = (&plain.summary, &refined.summary);
    assert!(r.blocks_broken > 0);
    // Each break refines at least the 20 ms after it to a quarter of the step: 3 extra
    // steps per plain step there.
    let per_window = 0.02 / p.dt * 3.0;
    assert!(
        r.steps as f64 >= p.steps as f64 + per_window,
        "{} steps refined against {} plain",
        r.steps,
        p.steps
    );
    // The refined windows are a small part of the run.
    assert!(r.steps < 2 * p.steps, "{} against {}", r.steps, p.steps);
    assert!(
        r.max_relative_residual < 1e-9,
        "the ledger does not close across step changes: {}",
        r.max_relative_residual
    );
    // Eq (9)'s work sums U·Δt·F over the steps taken: the pushed distance is U times the
    // time run, whatever the steps.
    assert!((r.ridged_volume - 0.25 * 0.30 * r.time).abs() < 1e-9);
    assert!((r.time - 8.0).abs() < p.dt);
}

#[test]
fn a_refined_step_is_checked() {
    for (set, key) in [
        ("numerics.refine_window=-1", "numerics.refine_window"),
        ("numerics.refine_load=0", "numerics.refine_load"),
        ("numerics.refine_load=1.5", "numerics.refine_load"),
        ("numerics.refine_window=of", "numerics.refine_window"),
        ("numerics.refine_load=\"none\"", "numerics.refine_load"),
    ] {
        let e = Scene::default()
            .with_overrides(&[set])
            .and_then(|s| s.validate().map(|_| s))
            .unwrap_err()
            .to_string();
        assert!(e.contains(key), "{set}: {e}");
    }
    let e = Scene::default()
        .with_overrides(&[
            "numerics.refine_window=off",
            "numerics.refine_load=off",
            "numerics.refine_impact=off",
            "numerics.refine_fraction=0.5",
        ])
        .and_then(|s| s.validate().map(|_| s))
        .unwrap_err()
        .to_string();
    assert!(e.contains("numerics.refine_fraction"), "{e}");
    let e = Scene::default()
        .with_overrides(&[
            "numerics.refine_window=0.02",
            "numerics.refine_fraction=1.5",
        ])
        .and_then(|s| s.validate().map(|_| s))
        .unwrap_err()
        .to_string();
    assert!(e.contains("numerics.refine_fraction"), "{e}");
}

#[test]
fn a_restart_inside_a_refined_window_repeats_the_bits() {
    use pressridge_sim::dem::World;
    let scene = Scene::default()
        .with_overrides(&[
            "duration=8",
            "numerics.time_step_safety=1.0",
            "numerics.refine_window=0.02",
            "numerics.refine_load=0.9",
        ])
        .unwrap();
    let mut w = scene.build().unwrap();
    // Step to the first break, then into its refined window.
    while w.blocks_broken() == 0 {
        w.step();
        assert!(w.time() < 8.0, "no break in 8 s");
    }
    for _ in 0..10 {
        w.step();
    }
    let saved = serde_json::to_string(&w.snapshot()).unwrap();
    let mut restored = World::from_snapshot(&serde_json::from_str(&saved).unwrap()).unwrap();
    assert_eq!(w.last_step(), restored.last_step());
    for _ in 0..2000 {
        w.step();
        restored.step();
    }
    assert_eq!(w.time().to_bits(), restored.time().to_bits());
    assert_eq!(
        serde_json::to_string(&w.snapshot()).unwrap(),
        serde_json::to_string(&restored.snapshot()).unwrap()
    );
}

#[test]
fn a_step_refined_ahead_of_fracture_refines_where_a_joint_nears_its_strength() {
    let window = run(&["numerics.refine_window=0.02"]);
    let ahead = run(&["numerics.refine_window=0.02", "numerics.refine_load=0.8"]);
    let (w, a) = (&window.summary, &ahead.summary);
    // The sheet is loaded towards its strength before its first break (about 5.6 s): the
    // steps there are refined too.
    assert!(
        a.steps > w.steps,
        "{} steps ahead against {}",
        a.steps,
        w.steps
    );
    assert!(
        a.max_relative_residual < 1e-9,
        "{}",
        a.max_relative_residual
    );
    assert!((a.time - 8.0).abs() < w.dt);
    // At a load of 1 nothing is refined before a crack starts: the window's run exactly.
    let none = run(&["numerics.refine_window=0.02", "numerics.refine_load=1"]);
    assert_eq!(none.summary.steps, w.steps);
    assert_eq!(
        serde_json::to_string(&none.final_state.bodies).unwrap(),
        serde_json::to_string(&window.final_state.bodies).unwrap()
    );
}

/// An impact refines the step like a break: with `numerics.refine_impact` below the speed at
/// which the first blocks meet, the run takes more steps than the window alone, its ledger
/// still closes; above every approach speed it changes no bit. A speed without the window,
/// or not positive, is refused by name.
#[test]
fn an_impact_refines_the_step_for_the_window() {
    let window = run(&["numerics.refine_window=0.02"]);
    let impacts = run(&["numerics.refine_window=0.02", "numerics.refine_impact=0.05"]);
    let never = run(&["numerics.refine_window=0.02", "numerics.refine_impact=1000"]);
    assert!(
        impacts.summary.steps > window.summary.steps,
        "{} steps with impacts against {}",
        impacts.summary.steps,
        window.summary.steps
    );
    assert!(impacts.summary.max_relative_residual < 1e-9);
    assert_eq!(never.summary.steps, window.summary.steps);
    assert_eq!(
        serde_json::to_string(&never.final_state.bodies).unwrap(),
        serde_json::to_string(&window.final_state.bodies).unwrap()
    );
    for set in [
        &["numerics.refine_window=off", "numerics.refine_impact=0.1"][..],
        &["numerics.refine_window=0.02", "numerics.refine_impact=0"][..],
    ] {
        let e = Scene::default()
            .with_overrides(set)
            .and_then(|s| s.validate().map(|_| s))
            .unwrap_err()
            .to_string();
        assert!(e.contains("numerics.refine_impact"), "{set:?}: {e}");
    }
}

/// The default step is the full limit refined around fracture and impacts, and the scene
/// says so: its TOML and JSON name every refinement, "off" where one is switched off, and
/// read back to the same scene.
#[test]
fn the_default_step_refines_and_says_so() {
    use pressridge_sim::dem::{
        DEFAULT_REFINE_IMPACT, DEFAULT_REFINE_LOAD, DEFAULT_REFINE_WINDOW, DEFAULT_TIME_STEP_SAFETY,
    };
    let d = Scene::default();
    assert_eq!(d.numerics.time_step_safety, DEFAULT_TIME_STEP_SAFETY);
    assert_eq!(d.numerics.refine_window, Some(DEFAULT_REFINE_WINDOW));
    assert_eq!(d.numerics.refine_load, Some(DEFAULT_REFINE_LOAD));
    assert_eq!(d.numerics.refine_impact, Some(DEFAULT_REFINE_IMPACT));
    let toml = d.to_toml();
    assert!(toml.contains("refine_window = 0.05"), "{toml}");
    // A scene file that does not name the numerics gets the default step.
    let bare = Scene::from_toml("name = \"bare\"").unwrap();
    assert_eq!(bare.numerics, d.numerics);
    let off = d
        .with_overrides(&[
            "numerics.refine_window=off",
            "numerics.refine_load=off",
            "numerics.refine_impact=off",
        ])
        .unwrap();
    assert_eq!(off.numerics.refine_window, None);
    let toml = off.to_toml();
    for k in ["refine_window", "refine_load", "refine_impact"] {
        assert!(toml.contains(&format!("{k} = \"off\"")), "{toml}");
    }
    assert_eq!(Scene::from_toml(&toml).unwrap(), off);
    let json = serde_json::to_string(&off).unwrap();
    assert!(json.contains("\"refine_load\":\"off\""), "{json}");
    assert_eq!(serde_json::from_str::<Scene>(&json).unwrap(), off);
    off.validate().unwrap();
}
