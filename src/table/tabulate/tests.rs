//! The volume axis: every setting's final volume holds all its runs.

use super::*;
use crate::energy::EnergyBudget;
use crate::record::RunSample;

/// The time step of the synthetic runs (s), about the shipped runs' 2.6e-4 s.
const DT: f64 = 2.5e-4;

/// A run of seed `seed` pushing a sheet `h` m thick at 0.25 m/s for 400 s, sampled every
/// 100 s, its last sample `late` s after 400 s (the run stops within half a step of T):
/// V = U·h·t, W = V(10·V + 2000), ΔPE = V(V + 100) (J/m).
fn run(h: f64, seed: u64, late: f64) -> RunRecord {
    let mut scene = crate::scene::Scene {
        duration: 400.0,
        ..Default::default()
    };
    let sheet = scene.sheet.as_mut().expect("a sheet");
    (sheet.thickness, sheet.speed) = (h, 0.25);
    let mut json = crate::table::summary_without_ledger();
    for t in crate::energy::LEDGER_TERMS {
        json[t.name] = 0.0.into();
    }
    json["dt"] = DT.into();
    let samples = [0.0, 100.0, 200.0, 300.0, 400.0 + late]
        .iter()
        .map(|&t| {
            let v = 0.25 * h * t;
            let mut s = RunSample {
                time: t,
                volume: v,
                mean_force: 1.0e3 * h,
                ..Default::default()
            };
            s.set_energy(&EnergyBudget {
                work: v * (10.0 * v + 2000.0),
                potential_energy: v * (v + 100.0),
                ..Default::default()
            });
            s
        })
        .collect();
    RunRecord {
        id: format!("h{h}-s{seed}"),
        settings: vec![],
        seed,
        scene,
        summary: serde_json::from_value(json).unwrap(),
        samples,
        profile: Default::default(),
        metrics: Default::default(),
        digest: None,
    }
}

/// Every setting's final volume U·h·T holds every run of that setting, whether its last
/// sample lies short of T or past it (by under half a step) and even where U·h·T misses
/// its grid point by roundoff (114.99999999999999 m³/m at 1.15 m against the point 115
/// of the 0–600 m³/m axis in 241 points); the point after it, which no run reached,
/// holds none. On a grid to the largest sample's volume (the table until 2026-12-01) the
/// runs that stop short of T missed every final volume, and on the grid to U·h·T without
/// the tolerance the 1.15 m runs missed theirs.
#[test]
fn every_run_counts_at_its_final_volume() {
    let hs = [0.3, 1.15, 6.0];
    assert!(
        nominal_volume(&run(1.15, 1, 0.0)) < 115.0,
        "the roundoff this test is about"
    );
    let mut records = Vec::new();
    for &h in &hs {
        for (seed, late) in [(1, -0.4 * DT), (2, 0.4 * DT), (3, 0.0)] {
            records.push(run(h, seed, late));
        }
    }
    let t = tabulate(&records, 241).unwrap();
    assert!(
        t.volume
            .iter()
            .enumerate()
            .all(|(k, &v)| v == 2.5 * k as f64)
    );
    for (hi, &h) in t.thickness.iter().enumerate() {
        let k = (100.0 * h / 2.5f64).round() as usize;
        let c = [0, hi, k];
        assert_eq!(t.runs[c], 3, "h = {h} m at {} m³/m", t.volume[k]);
        let v = t.volume[k];
        let w = v * (10.0 * v + 2000.0);
        // The runs that stopped short of T (by 0.4 of a step) give their last sample there.
        assert!(
            (t.work_mean[c] - w).abs() <= 1e-6 * w,
            "{} {w}",
            t.work_mean[c]
        );
        assert!(t.force_mean[c] == 1.0e3 * h);
        if k + 1 < t.volume.len() {
            assert_eq!(t.runs[[0, hi, k + 1]], 0);
            assert!(t.work_mean[[0, hi, k + 1]].is_nan());
        }
    }
}

/// A grid point counts at a run's end within half the volume one step ridges past it,
/// and not beyond: the record says nothing about volumes it did not reach.
#[test]
fn the_end_tolerance_is_half_a_step() {
    let r = RunOnAxis::of(&run(0.3, 1, -0.4 * DT));
    assert_eq!(*r.volume.last().unwrap(), 0.25 * 0.3 * 400.0);
    assert_eq!(r.tol, 0.5 * 0.25 * 0.3 * DT);
    let end = 30.0;
    let last = *r.work.last().unwrap();
    assert_eq!(r.at(&r.work, end), last);
    assert_eq!(r.at(&r.work, end + 0.9 * r.tol), last);
    assert!(r.at(&r.work, end + 1.1 * r.tol).is_nan());
    assert!(r.at(&r.work, -1e-12).is_nan());
    // A run that stopped well short of T keeps its last sample's volume.
    let short = RunOnAxis::of(&run(0.3, 1, -2.0 * DT));
    assert_eq!(
        *short.volume.last().unwrap(),
        0.25 * 0.3 * (400.0 - 2.0 * DT)
    );
    assert!(short.at(&short.work, end).is_nan());
}
