//! The command line end to end: simulate a short scene, render its state, reject bad input.

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_pressridge"))
}

#[test]
fn simulate_then_render() {
    let dir = std::env::temp_dir().join(format!("pressridge-cli-{}", std::process::id()));
    let out = bin()
        .args([
            "simulate",
            "--set",
            "duration=0.5",
            "--set",
            "pile.blocks=30",
        ])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for f in [
        "summary.json",
        "energy.csv",
        "state.json",
        "scene.toml",
        "final.png",
        "energy.png",
    ] {
        assert!(dir.join(f).is_file(), "missing {f}");
    }
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    for key in [
        "work",
        "potential_energy",
        "friction_dissipation",
        "viscous_dissipation",
        "kinetic_energy",
        "drag_dissipation",
        "other_dissipation",
        "residual",
        "steps",
        "dt",
        "wall_seconds",
        "seed",
    ] {
        assert!(summary.get(key).is_some(), "summary lacks {key}");
    }
    let csv = std::fs::read_to_string(dir.join("energy.csv")).unwrap();
    assert!(csv.starts_with("time [s],work [J/m]"));
    let png = dir.join("again.png");
    let out = bin()
        .arg("render")
        .arg(dir.join("state.json"))
        .arg("--out")
        .arg(&png)
        .args(["--window", "-3,3,-2,3"])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[1..4], b"PNG");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn bad_input_gives_a_clear_error_and_nonzero_exit() {
    let out = bin()
        .args(["simulate", "--set", "contact.muu=1", "--out", "/tmp/never"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("muu"), "{err}");
    let out = bin()
        .args(["render", "/nonexistent/state.json"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("/nonexistent/state.json"));
}
