//! Speed against error of the ridging simulation, judged on ensembles
//! (docs/speed-vs-error.md).
//!
//! A ridge is chaotic: two runs that differ in the last bit diverge, so a numerical change
//! (time step, dashpot scheme) is judged by the difference of ensemble means from the
//! reference configuration, with a 95 % confidence interval. Each configuration is a
//! campaign directory (`pressridge campaign`, specs in `data/campaigns/speed-vs-error/`)
//! over the same thicknesses and seeds; the first is the reference.
//!
//! For each thickness and configuration the table gives the runs, the steps and the mean
//! wall time of a run, and for W, ΔPE, W/ΔPE, Φ_i/W, Φ_f/W, L/h, blocks broken (joints
//! severed), the elastic energy released per break, sail height and keel depth the
//! difference of the configuration's mean from the reference mean, in % of the reference
//! mean, with its 95 % interval by Welch's t (unequal
//! variances, Welch–Satterthwaite degrees of freedom; the reference mean in the denominator
//! is taken as exact), and the worst closure residual |W − sinks| / largest term over all
//! samples of all runs.
//!
//! The quantities the step's equivalence test judges (W, ΔPE, W/ΔPE, Φ_i/W, L/h, joints
//! broken, energy per break and the share of runs that rafted) are marked ✓ where the 95 %
//! interval spans zero and its centre lies within ±0.3 σ of the reference's seed-to-seed
//! spread, ✗ where not; below each thickness's table a line says whether each configuration
//! passes the test (every judged quantity ✓, at least 41 seeds in each arm), the test that
//! half the stable limit passed and any larger default step must pass.
//!
//! A second table per thickness counts the rubble pieces at the end of a run by their length
//! in blocks (1, 2, 3, 4, 5–6, 7 or more): per run, the reference's mean ± σ and each other
//! configuration's difference from it with its 95 % Welch interval. It says which breaks a
//! configuration adds: a joint severed in the sheet or in a long piece moves several classes,
//! one that chips a single block off a piece's end adds to the first.
//!
//! ```sh
//! cargo run --release --example speed_vs_error -- \
//!     reference=runs/sve-reference implicit-0.8=runs/sve-implicit-0.8 > table.md
//! ```
//!
//! `NAME=DIR1+DIR2` pools the runs of several campaign directories into one configuration
//! (e.g. seeds 13–26 run later under a spec of their own). `NAME=DIR@SETTING` takes only
//! the runs of one point of a campaign's axis (`SETTING` as the run's settings write it,
//! e.g. `numerics.time_step_safety=1.0`) and leaves that setting out of the point, so that two
//! points of one campaign can be compared:
//!
//! ```sh
//! cargo run --release --example speed_vs_error -- \
//!     quarter=crates/lab/records/speed-vs-error/chord-steps@numerics.time_step_safety=0.25 \
//!     full=crates/lab/records/speed-vs-error/chord-steps@numerics.time_step_safety=1.0
//! ```

use pressridge::campaign::read_campaign;
use pressridge::record::RunRecord;
use pressridge::table::ensemble::{Stat, quantity};
use pressridge::table::rafting;
use std::collections::BTreeMap;
use std::path::Path;

/// The quantities compared: key of [`quantity`] (or `normal_contact_fraction`, Φ_i/W, eq
/// (12)'s net normal contact work over W; `fracture_per_break`, the elastic energy released
/// by cracks over the joints broken, J/m per joint; `rafted`, 1 for a run whose intact sheet
/// rode over the floe by more than the rafting reach, 0 for one that broke at it, so that its
/// mean is the share of runs that rafted), label, and whether the step's equivalence test
/// judges it (W, ΔPE, W/ΔPE, Φ_i/W, L/h, joints broken, energy per break and the ride-over
/// count).
const QUANTITIES: [(&str, &str, bool); 11] = [
    ("work", "W", true),
    ("potential_energy", "ΔPE", true),
    ("ratio_work_to_pe", "W/ΔPE", true),
    ("normal_contact_fraction", "Φ_i/W", true),
    ("friction_fraction", "Φ_f/W", false),
    ("length_to_thickness", "L/h", true),
    ("blocks_broken", "broken", true),
    ("fracture_per_break", "E_f/break", true),
    ("rafted", "rafted", true),
    ("max_sail_height", "sail", false),
    ("max_keel_depth", "keel", false),
];

/// The step's equivalence test (docs/speed-vs-error.md, "The equivalence test"): at least
/// this many seeds per arm, and for every judged quantity a 95 % interval across zero with its
/// centre within [`EQUIVALENCE_CENTRE`] of the reference's seed-to-seed σ.
const EQUIVALENCE_SEEDS: usize = 41;

/// The largest centre of a judged shift the test allows, in units of the reference's σ.
const EQUIVALENCE_CENTRE: f64 = 0.3;

type Groups = BTreeMap<String, Vec<RunRecord>>;

/// The classes of the pieces table: length in blocks, from and to (inclusive).
const PIECE_CLASSES: [(u32, u32, &str); 6] = [
    (1, 1, "1 block"),
    (2, 2, "2"),
    (3, 3, "3"),
    (4, 4, "4"),
    (5, 6, "5–6"),
    (7, u32::MAX, "≥ 7"),
];

/// Per class of [`PIECE_CLASSES`], then all: the run's rubble pieces at the end, counted by
/// their length in blocks of the sheet's width.
fn piece_counts(r: &RunRecord) -> Option<[f64; PIECE_CLASSES.len() + 1]> {
    let w = r.scene.sheet.as_ref()?.block_width;
    let mut n = [0.0; PIECE_CLASSES.len() + 1];
    for &len in &r.summary.rubble_block_lengths {
        let blocks = (len / w).round().max(1.0) as u32;
        if let Some(k) = PIECE_CLASSES
            .iter()
            .position(|&(lo, hi, _)| (lo..=hi).contains(&blocks))
        {
            n[k] += 1.0;
        }
        n[PIECE_CLASSES.len()] += 1.0;
    }
    Some(n)
}

/// The pieces table of one point: see the module's doc.
fn print_pieces(point: &str, configs: &[(String, Groups)], ref_runs: &[RunRecord]) {
    let column = |runs: &[RunRecord], k: usize| {
        let xs: Vec<f64> = runs.iter().filter_map(piece_counts).map(|n| n[k]).collect();
        Stat::of(&xs)
    };
    println!("\nRubble pieces per run by length in blocks, {point}:\n");
    print!("| configuration | runs |");
    for (_, _, label) in PIECE_CLASSES {
        print!(" {label} |");
    }
    println!(" all |");
    println!("|{}", "---|".repeat(3 + PIECE_CLASSES.len()));
    for (name, g) in configs {
        let Some(runs) = g.get(point) else { continue };
        print!("| {name} | {} |", runs.len());
        for k in 0..=PIECE_CLASSES.len() {
            let (a, b) = (column(ref_runs, k), column(runs, k));
            if std::ptr::eq(runs.as_slice(), ref_runs) {
                print!(" {:.1} ± {:.1} |", a.mean, a.std);
            } else if a.n < 2 || b.n < 2 {
                print!(" — |");
            } else {
                let (d, h) = a.welch_difference(&b);
                print!(" {d:+.1} [{:+.1}, {:+.1}] |", d - h.abs(), d + h.abs());
            }
        }
        println!();
    }
}

/// The runs of campaign `dir` by point; with `only`, just the runs whose settings hold it,
/// keyed without it.
fn groups(dir: &Path, only: Option<&str>) -> Result<Groups, Box<dyn std::error::Error>> {
    // A campaign still running is read as far as it got: the table gives n per row.
    let c = read_campaign(dir, true)?;
    if !c.missing.is_empty() {
        eprintln!(
            "{}: {} of {} runs so far",
            dir.display(),
            c.records.len(),
            c.planned
        );
    }
    let records = c.records;
    let mut g = Groups::new();
    for r in records {
        let mut point = r.settings.clone();
        if let Some(only) = only {
            let Some(k) = point.iter().position(|s| s == only) else {
                continue;
            };
            point.remove(k);
        }
        g.entry(point.join(", ")).or_default().push(r);
    }
    if let Some(only) = only
        && g.is_empty()
    {
        return Err(format!("{}: no run has the setting {only}", dir.display()).into());
    }
    Ok(g)
}

fn stat(runs: &[RunRecord], key: &str) -> Stat {
    let value = |r: &RunRecord| match key {
        "normal_contact_fraction" => {
            Some(quantity(r, "normal_contact_work")? / quantity(r, "work")?)
        }
        "fracture_per_break" => {
            let n = quantity(r, "blocks_broken")?;
            (n > 0.0).then_some(quantity(r, "fracture_dissipation")? / n)
        }
        "rafted" => match rafting::outcome(r, rafting::RAFTING_REACH) {
            rafting::Outcome::Rafted(_) => Some(1.0),
            rafting::Outcome::Ridged => Some(0.0),
            rafting::Outcome::Unknown => None,
        },
        _ => quantity(r, key),
    };
    let xs: Vec<f64> = runs.iter().filter_map(value).collect();
    Stat::of(&xs)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let configs: Vec<(String, Groups)> = std::env::args()
        .skip(1)
        .map(|a| {
            let (name, dir) = a
                .split_once('=')
                .ok_or("arguments are NAME=CAMPAIGN_DIR[+DIR...][@SETTING], the reference first")?;
            let (dir, only) = match dir.split_once('@') {
                Some((d, s)) => (d, Some(s)),
                None => (dir, None),
            };
            // One configuration may be spread over several archives (extra seeds run
            // later under their own spec): `NAME=DIR1+DIR2` pools their runs per point.
            let mut pooled = Groups::new();
            for d in dir.split('+') {
                for (point, runs) in groups(Path::new(d), only)? {
                    let all = pooled.entry(point.clone()).or_default();
                    for r in runs {
                        if all.iter().any(|o| o.seed == r.seed) {
                            return Err(format!(
                                "{name}: seed {} of {point} is in more than one of {dir}",
                                r.seed
                            )
                            .into());
                        }
                        all.push(r);
                    }
                }
            }
            Ok((name.to_string(), pooled))
        })
        .collect::<Result<_, Box<dyn std::error::Error>>>()?;
    let Some((ref_name, reference)) = configs.first() else {
        return Err(
            "usage: speed_vs_error NAME=CAMPAIGN_DIR[+DIR...][@SETTING] ... (the reference first)"
                .into(),
        );
    };
    for (point, ref_runs) in reference {
        println!("\n### {point}\n");
        print!("| configuration | runs | Δt (s) | steps | wall (s) |");
        for (_, label, _) in QUANTITIES {
            print!(" {label} |");
        }
        println!(" worst closure |");
        println!("|{}", "---|".repeat(6 + QUANTITIES.len()));
        let mut verdicts = vec![];
        for (name, g) in &configs {
            let Some(runs) = g.get(point) else { continue };
            let dt = runs.first().map_or(f64::NAN, |r| r.summary.dt);
            let steps = Stat::of(
                &runs
                    .iter()
                    .map(|r| r.summary.steps as f64)
                    .collect::<Vec<_>>(),
            );
            let wall = Stat::of(
                &runs
                    .iter()
                    .map(|r| r.summary.wall_seconds)
                    .collect::<Vec<_>>(),
            );
            let worst = runs
                .iter()
                .map(|r| r.summary.max_relative_residual)
                .fold(0.0f64, f64::max);
            print!(
                "| {name} | {} | {dt:.3e} | {:.0} | {:.0} |",
                runs.len(),
                steps.mean,
                wall.mean
            );
            let mut passes = name == ref_name
                || (runs.len() >= EQUIVALENCE_SEEDS && ref_runs.len() >= EQUIVALENCE_SEEDS);
            for (key, _, judged) in QUANTITIES {
                let a = stat(ref_runs, key);
                let b = stat(runs, key);
                if name == ref_name {
                    print!(" {:.4} ± {:.4} |", a.mean, a.std);
                    continue;
                }
                if a.n < 2 || b.n < 2 {
                    passes &= !judged;
                    print!(" — |");
                    continue;
                }
                let (d, h) = a.welch_difference(&b);
                // In % of the reference mean; the rafted share in percentage points (its
                // reference mean may be zero).
                let (pd, ph, unit) = if key == "rafted" {
                    (100.0 * d, 100.0 * h.abs(), "pp")
                } else {
                    (100.0 * d / a.mean, 100.0 * (h / a.mean).abs(), "%")
                };
                // The shift in units of the reference's seed-to-seed σ (of both arms pooled
                // where the reference's runs all agree, as every run ridging does), with its
                // interval, judged by the step's test.
                let sigma = if a.std > 0.0 {
                    a.std
                } else {
                    (0.5 * (a.std.powi(2) + b.std.powi(2))).sqrt()
                };
                let (sd, sh) = if sigma > 0.0 {
                    (d / sigma, (h / sigma).abs())
                } else {
                    (0.0, 0.0)
                };
                let ok = (sd - sh) <= 0.0 && (sd + sh) >= 0.0 && sd.abs() <= EQUIVALENCE_CENTRE;
                passes &= !judged || ok;
                let flag = match (judged, ok) {
                    (false, _) => "",
                    (true, true) => " ✓",
                    (true, false) => " ✗",
                };
                print!(
                    " {pd:+.1} {unit} [{:+.1}, {:+.1}]; {sd:+.2} σ [{:+.2}, {:+.2}]{flag} |",
                    pd - ph,
                    pd + ph,
                    sd - sh,
                    sd + sh
                );
            }
            if name != ref_name {
                verdicts.push(format!(
                    "{name}: {}",
                    if passes {
                        "equivalent to the reference by the step's test"
                    } else if runs.len() < EQUIVALENCE_SEEDS || ref_runs.len() < EQUIVALENCE_SEEDS {
                        "not judged yet (fewer than 41 seeds in an arm)"
                    } else {
                        "not equivalent (a judged shift fails the test)"
                    }
                ));
            }
            println!(" {worst:.1e} |");
        }
        for v in verdicts {
            println!("\n{v}.");
        }
        print_pieces(point, &configs, ref_runs);
    }
    println!(
        "\nReference row: mean ± standard deviation σ over seeds (W, ΔPE in J/m; E_f/break, \
         the elastic energy released by cracks per joint broken, in J/m; sail and keel in \
         m). Other rows: difference of the mean from the reference mean in % of the \
         reference mean and in units of the reference's σ, each with its 95 % Welch \
         interval (rafted: the share of runs whose intact sheet rode over the floe, its shift in \
         percentage points); for the \
         quantities the step's equivalence test judges, ✓: the interval spans zero and its \
         centre lies within ±0.3 σ, ✗: not; a configuration is equivalent when every judged \
         quantity passes with at least 41 seeds in each arm. Pieces tables: the reference's \
         mean ± σ of the pieces per run, the others' difference in pieces per run with its \
         95 % Welch interval."
    );
    Ok(())
}
