//! Progress on stderr when it is not a terminal (here: a pipe): lines with the elapsed
//! time, the rate and an ETA every --progress-interval seconds; none with --quiet.

#[path = "../../../tests/common/mod.rs"]
mod common;
use common::{bin, scratch};

fn simulate(dir: &std::path::Path, extra: &[&str]) -> String {
    let out = bin()
        .args(["simulate", "--set", "duration=1", "--no-figures"])
        .args(["--set", "output.snapshot_interval=0"])
        .arg("--out")
        .arg(dir)
        .args(extra)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{err}");
    err
}

#[test]
fn lines_with_an_eta_when_not_a_terminal() {
    let dir = scratch("progress-lines");
    let err = simulate(&dir, &["--progress-interval", "0.02", "-v"]);
    let lines: Vec<&str> = err.lines().filter(|l| l.contains("ETA")).collect();
    assert!(!lines.is_empty(), "no progress line in: {err}");
    for l in &lines {
        assert!(l.contains("elapsed") && l.contains("s simulated/s"), "{l}");
        assert!(l.contains("step "), "-v detail missing: {l}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn quiet_prints_no_progress() {
    let dir = scratch("progress-quiet");
    let err = simulate(&dir, &["--progress-interval", "0", "--quiet"]);
    assert!(!err.contains("ETA"), "{err}");
    assert!(err.trim().is_empty(), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_bad_interval_is_named() {
    let out = bin()
        .args(["simulate", "--print-scene", "--progress-interval=-1"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--progress-interval"));
}
