//! Same scene + same seed ⇒ bit-identical results; a saved state resumes bit for bit.

mod common;

use pressridge::dem::World;
use pressridge::io::state::{load_state, save_state};
use pressridge::scene::Scene;
use pressridge::simulation;

fn small_pile(seed: u64) -> Scene {
    Scene::rubble_pile()
        .with_overrides(&[
            "duration=1.5".to_string(),
            "pile.blocks=60".into(),
            "pile.columns=6".into(),
            "pile.basin_width=2.5".into(),
            format!("seed={seed}"),
        ])
        .unwrap()
}

fn state_json(w: &World) -> String {
    serde_json::to_string(&w.snapshot()).unwrap()
}

#[test]
fn same_scene_and_seed_give_bit_identical_runs() {
    let a = simulation::run(&small_pile(7), &mut |_| true).unwrap();
    let b = simulation::run(&small_pile(7), &mut |_| true).unwrap();
    let mut sa = a.summary.clone();
    let mut sb = b.summary.clone();
    sa.wall_seconds = 0.0;
    sb.wall_seconds = 0.0;
    assert_eq!(sa, sb);
    assert_eq!(a.series, b.series);
    assert_eq!(
        serde_json::to_string(&a.final_state).unwrap(),
        serde_json::to_string(&b.final_state).unwrap()
    );
    let c = simulation::run(&small_pile(8), &mut |_| true).unwrap();
    assert_ne!(
        serde_json::to_string(&a.final_state.bodies).unwrap(),
        serde_json::to_string(&c.final_state.bodies).unwrap(),
        "a different seed must give a different pile"
    );
}

#[test]
fn saved_state_resumes_bit_for_bit() {
    let scene = small_pile(3);
    let mut w = scene.build().unwrap();
    for _ in 0..4000 {
        w.step();
    }
    let dir = common::scratch("det");
    let path = dir.join("state.json");
    save_state(&path, &w.snapshot()).unwrap();
    let mut r = World::from_snapshot(&load_state(&path).unwrap()).unwrap();
    assert_eq!(state_json(&w), state_json(&r));
    for _ in 0..4000 {
        w.step();
        r.step();
    }
    assert_eq!(state_json(&w), state_json(&r));
    assert_eq!(w.energy(), r.energy());
}

#[test]
fn corrupt_state_files_give_clear_errors() {
    let dir = common::scratch("bad");
    let path = dir.join("bad.json");
    std::fs::write(&path, "{\"format\": 1, \"time\": 0.0}").unwrap();
    let e = load_state(&path).unwrap_err().to_string();
    assert!(e.contains("bad.json") && e.contains("missing field"), "{e}");
    let e = load_state(&dir.join("absent.json"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("absent.json"), "{e}");
}

/// The same seed gives the same bits on any number of threads (`World::set_threads`): six
/// seconds of the Figure 5 scene (158 bodies, 6 joints broken, the sheet against the floe and
/// its first rubble, in water) on 1, 2 and 4 threads, and a rubble pile in water on 3.
#[test]
fn the_same_seed_gives_the_same_bits_on_any_number_of_threads() {
    let figure5 = Scene::default().with_overrides(&["duration=6"]).unwrap();
    for scene in [figure5, small_pile(5)] {
        let counts: &[usize] = if scene.pile.is_some() {
            &[1, 3]
        } else {
            &[1, 2, 4]
        };
        let runs: Vec<_> = counts
            .iter()
            .map(|&t| simulation::run_on(&scene, t, &mut |_| true).unwrap())
            .collect();
        let one = &runs[0];
        assert!(one.summary.blocks_broken > 0 || scene.pile.is_some());
        for r in &runs[1..] {
            assert_eq!(r.series, one.series);
            assert_eq!(
                serde_json::to_string(&r.final_state).unwrap(),
                serde_json::to_string(&one.final_state).unwrap()
            );
        }
    }
}
