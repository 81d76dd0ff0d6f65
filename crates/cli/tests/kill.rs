//! Kill tests (issue 16, docs/failure.md): `simulate`, `campaign`, `tabulate` and a large
//! `strength` killed (SIGKILL) at pseudo-random moments leave at their target paths either
//! the old file (or none) or a complete new one, never a partial one; a campaign resumed
//! after kills completes with results identical to an uninterrupted one.

#[path = "../../../tests/common/mod.rs"]
mod common;

use common::*;
use pressridge::campaign::{read_campaign, read_records};
use pressridge::record::RunRecord;
use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

/// Runs `cmd` to completion and returns how long it took.
fn timed(cmd: &mut Command) -> Duration {
    let t = Instant::now();
    succeeds(&cmd.output().unwrap());
    t.elapsed()
}

/// Starts `cmd`, kills it with SIGKILL after `delay` (if still running) and reaps it.
fn kill_after(cmd: &mut Command, delay: Duration) {
    let mut child = cmd
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(delay);
    let _ = child.kill();
    child.wait().unwrap();
}

/// Runs `cmd` to completion watching `dir`: returns when the first new file appeared in it
/// (the output being written) and how long the whole run took.
fn write_window(cmd: &mut Command, dir: &Path) -> (Duration, Duration) {
    let before = names_in(dir);
    let t = Instant::now();
    let mut child = cmd
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let mut appeared = None;
    loop {
        if appeared.is_none() && names_in(dir) != before {
            appeared = Some(t.elapsed());
        }
        if let Some(status) = child.try_wait().unwrap() {
            assert!(status.success());
            break;
        }
        std::thread::sleep(Duration::from_micros(200));
    }
    let full = t.elapsed();
    (appeared.unwrap_or(full), full)
}

/// A delay in [0.9 × start, 1.1 × end) from `rng`: kills that land while the output is
/// being written, and some just before or after.
fn delay_in(rng: &mut Rng, (start, end): (Duration, Duration)) -> Duration {
    let a = start.mul_f64(0.9);
    let b = end.mul_f64(1.1);
    a + (b - a).mul_f64(rng.below(1000) as f64 / 1000.0)
}

/// A delay in [0, 1.2 × full) from `rng`, so that most kills land mid-run.
fn delay(rng: &mut Rng, full: Duration) -> Duration {
    full.mul_f64(1.2 * rng.below(1000) as f64 / 1000.0)
}

/// A PNG is complete when it ends with its IEND chunk.
fn png_complete(p: &Path) -> bool {
    std::fs::read(p).is_ok_and(|b| b.ends_with(&[0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82]))
}

#[test]
fn killed_strength_leaves_the_old_output_or_a_complete_new_one() {
    let d = scratch("kill-strength");
    // 5 categories on 300 × 300 columns: long enough to be killed while writing.
    let (ny, nx) = (300, 300);
    let n = ny * nx;
    let cat = [("nc", 5), ("y", ny), ("x", nx)];
    let mut aicen = Vec::with_capacity(5 * n);
    let mut vicen = Vec::with_capacity(5 * n);
    for k in 0..5 {
        for c in 0..n {
            aicen.push(0.18);
            vicen.push(0.18 * (0.3 + k as f64 + (c % 7) as f64 * 0.05));
        }
    }
    let input = d.join("in.nc");
    write_nc(
        &input,
        &[
            Var::f64("aicen", &cat, aicen),
            Var::f64("vicen", &cat, vicen),
            Var::f64("aice0", &[("y", ny), ("x", nx)], vec![0.1; n]),
        ],
    );
    let cmd = |out: &Path| {
        let mut c = bin();
        c.arg("strength")
            .arg("--input")
            .arg(&input)
            .arg("--output")
            .arg(out);
        c
    };
    let reference = d.join("ref.nc");
    timed(&mut cmd(&reference));
    let target = d.join("out.nc");
    // When the output starts to appear, and when the run ends.
    let window = write_window(&mut cmd(&target), &d);
    std::fs::remove_file(&target).unwrap();
    let want: Vec<f64> = netcdf::open(&reference)
        .unwrap()
        .variable("strength")
        .unwrap()
        .get_values(..)
        .unwrap();
    let mut rng = Rng(0x5111);
    let (mut old, mut new) = (0, 0);
    for i in 0..16 {
        let had_old = i % 2 == 0;
        if had_old {
            std::fs::write(&target, b"old file").unwrap();
        } else {
            let _ = std::fs::remove_file(&target);
        }
        kill_after(&mut cmd(&target), delay_in(&mut rng, window));
        match std::fs::read(&target) {
            Err(_) => assert!(!had_old, "kill {i}: the old output vanished"),
            Ok(b) if b == b"old file" => old += 1,
            Ok(_) => {
                let got: Vec<f64> = netcdf::open(&target)
                    .unwrap_or_else(|e| panic!("kill {i}: partial output: {e}"))
                    .variable("strength")
                    .unwrap_or_else(|| panic!("kill {i}: no strength"))
                    .get_values(..)
                    .unwrap();
                assert_eq!(got, want, "kill {i}: incomplete values");
                new += 1;
            }
        }
    }
    eprintln!("strength kills: {old} left the old file, {new} a complete new one");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn killed_simulate_leaves_only_complete_files() {
    let d = scratch("kill-simulate");
    let out = d.join("run");
    let cmd = || {
        let mut c = bin();
        c.args(["simulate", "--overwrite", "--scene"])
            .arg(common::repo().join("data/scenes/rubble-pile.toml"))
            .args(["--set", "pile.blocks=20", "--set", "pile.columns=5"])
            .args([
                "--set",
                "duration=0.4",
                "--set",
                "output.snapshot_interval=0.05",
            ])
            .arg("--out")
            .arg(&out);
        c
    };
    let full = timed(&mut cmd());
    let mut rng = Rng(0x51b);
    for i in 0..8 {
        kill_after(&mut cmd(), delay(&mut rng, full));
        for name in names_in(&out) {
            let p = out.join(&name);
            let ctx = format!("kill {i}: {name}");
            match name.as_str() {
                // Temporaries of the killed writer: never at a target path, cleared by the
                // next --overwrite.
                n if n.starts_with(".tmp-") => {}
                "summary.json" | "state.json" => {
                    serde_json::from_slice::<serde_json::Value>(&std::fs::read(&p).unwrap())
                        .unwrap_or_else(|e| panic!("{ctx}: {e}"));
                }
                "scene.toml" => {
                    pressridge::scene::Scene::from_toml(&std::fs::read_to_string(&p).unwrap())
                        .unwrap_or_else(|e| panic!("{ctx}: {e}"));
                }
                "series.csv" => {
                    let t = std::fs::read_to_string(&p).unwrap();
                    assert!(t.ends_with('\n'), "{ctx}");
                    let cols = t.lines().next().unwrap().split(',').count();
                    assert!(t.lines().all(|l| l.split(',').count() == cols), "{ctx}");
                }
                n if n.ends_with(".png") => assert!(png_complete(&p), "{ctx}"),
                "ridge.gif" => {
                    // Complete: the header, then the trailer byte last.
                    let b = std::fs::read(&p).unwrap();
                    assert!(b.starts_with(b"GIF89a") && b.last() == Some(&0x3B), "{ctx}");
                }
                "snapshots" => {
                    for s in names_in(&p) {
                        let q = p.join(&s);
                        if s.ends_with(".json") && !s.starts_with(".tmp-") {
                            serde_json::from_slice::<serde_json::Value>(
                                &std::fs::read(&q).unwrap(),
                            )
                            .unwrap_or_else(|e| panic!("{ctx}/{s}: {e}"));
                        } else if s.ends_with(".png") && !s.starts_with(".tmp-") {
                            assert!(png_complete(&q), "{ctx}/{s}");
                        }
                    }
                }
                other => panic!("{ctx}: unexpected file {other}"),
            }
        }
    }
    let _ = std::fs::remove_dir_all(&d);
}

const SPEC: &str = r#"
name = "kill"
seeds = 3
sample_interval = 0.5
set = ["duration=1.0", "sheet.length=4.0"]
"#;

/// Records without their wall-clock time, which is all that may differ between runs.
fn strip(rs: Vec<RunRecord>) -> Vec<RunRecord> {
    rs.into_iter()
        .map(|mut r| {
            r.summary.wall_seconds = 0.0;
            r
        })
        .collect()
}

#[test]
fn killed_campaign_and_tabulate_resume_to_identical_results() {
    let d = scratch("kill-campaign");
    let spec = d.join("kill.toml");
    std::fs::write(&spec, SPEC).unwrap();
    let campaign = |out: &Path| {
        let mut c = bin();
        c.args(["campaign", "--threads", "2", "--spec"])
            .arg(&spec)
            .arg("--out")
            .arg(out);
        c
    };
    let reference = d.join("ref");
    let full = timed(&mut campaign(&reference));
    let want = strip(read_records(&reference).unwrap().1);
    let out = d.join("out");
    let mut rng = Rng(0xca);
    for i in 0..6 {
        kill_after(&mut campaign(&out), delay(&mut rng, full));
        if out.join("plan.json").is_file() {
            // Every record present is complete and matches its files.
            let c = read_campaign(&out, true);
            if let Ok(c) = c {
                assert!(c.inconsistent.is_empty(), "kill {i}: {:?}", c.inconsistent);
            }
        }
    }
    succeeds(&campaign(&out).output().unwrap());
    assert_eq!(
        strip(read_records(&out).unwrap().1),
        want,
        "resumed results differ"
    );

    // tabulate killed at random moments: the old table or a complete new one.
    let table = d.join("table.nc");
    let tabulate = || {
        let mut c = bin();
        c.args(["tabulate", "--points", "5", "--campaign"])
            .arg(&out)
            .arg("--out")
            .arg(&table);
        c
    };
    timed(&mut tabulate());
    let window = write_window(&mut tabulate(), &d);
    let cf: Vec<f64> = netcdf::open(&table)
        .unwrap()
        .variable("cf")
        .unwrap()
        .get_values(..)
        .unwrap();
    for i in 0..6 {
        let had_old = i % 2 == 0;
        if had_old {
            std::fs::write(&table, b"old table").unwrap();
        } else {
            let _ = std::fs::remove_file(&table);
        }
        kill_after(&mut tabulate(), delay_in(&mut rng, window));
        match std::fs::read(&table) {
            Err(_) => assert!(!had_old, "kill {i}: the old table vanished"),
            Ok(b) if b == b"old table" => {}
            Ok(_) => {
                let got: Vec<f64> = netcdf::open(&table)
                    .unwrap_or_else(|e| panic!("kill {i}: partial table: {e}"))
                    .variable("cf")
                    .unwrap()
                    .get_values(..)
                    .unwrap();
                assert_eq!(got.len(), cf.len(), "kill {i}");
                for (a, b) in got.iter().zip(&cf) {
                    assert!(a.to_bits() == b.to_bits(), "kill {i}: {got:?} vs {cf:?}");
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&d);
}
