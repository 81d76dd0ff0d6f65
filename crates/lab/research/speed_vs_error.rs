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
//! A third table per thickness splits Φ_i/W into its parts and gives the other sinks, each
//! per W (not judged): the viscous part, the elastic part (the normal contact forces' net
//! elastic work), the contact hysteresis (elastic work left at separation: zero for a
//! conservative contact law, so a step that integrates the contact spring less exactly shows
//! here), and the joint, boundary and drag dissipation. It says where a shift of Φ_i/W sits.
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

use pressridge::record::RunRecord;
use pressridge::table::ensemble::{Stat, quantity};
use pressridge_lab::equivalence::{
    QUANTITIES, SEEDS as EQUIVALENCE_SEEDS, points as groups, shift, stat,
};
use std::collections::BTreeMap;
use std::path::Path;

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

/// The ledger terms of the sinks table (a key of [`quantity`], its label), each per W.
const SINKS: [(&str, &str); 6] = [
    ("viscous_dissipation", "Φ_i viscous"),
    ("normal_elastic_work", "Φ_i elastic"),
    ("contact_hysteresis", "contact hysteresis"),
    ("joint_dissipation", "joints"),
    ("boundary_dissipation", "boundaries"),
    ("drag_dissipation", "drag"),
];

/// One table of a point: a row per configuration, a column per quantity that `column`
/// gives for a set of runs (by index, `headers.len()` of them); the reference's row holds
/// `reference(stat)`, the others `shifted(reference, difference, half-width)` of Welch's
/// 95 % interval, or — where an arm has fewer than two runs.
fn print_table(
    title: &str,
    headers: &[&str],
    (configs, ref_runs): (&[(String, Groups)], &[RunRecord]),
    point: &str,
    column: impl Fn(&[RunRecord], usize) -> Stat,
    reference: impl Fn(&Stat) -> String,
    shifted: impl Fn(&Stat, f64, f64) -> String,
) {
    println!("\n{title}, {point}:\n");
    print!("| configuration | runs |");
    for label in headers {
        print!(" {label} |");
    }
    println!();
    println!("|{}", "---|".repeat(2 + headers.len()));
    for (name, g) in configs {
        let Some(runs) = g.get(point) else { continue };
        print!("| {name} | {} |", runs.len());
        for k in 0..headers.len() {
            let (a, b) = (column(ref_runs, k), column(runs, k));
            if std::ptr::eq(runs.as_slice(), ref_runs) {
                print!(" {} |", reference(&a));
            } else if a.n < 2 || b.n < 2 {
                print!(" — |");
            } else {
                let (d, h) = a.welch_difference(&b);
                print!(" {} |", shifted(&a, d, h.abs()));
            }
        }
        println!();
    }
}

/// The sinks table of one point: see the module's doc.
fn print_sinks(point: &str, configs: &[(String, Groups)], ref_runs: &[RunRecord]) {
    let labels: Vec<&str> = SINKS.iter().map(|&(_, label)| label).collect();
    print_table(
        "Sinks per W (Φ_i/W in its parts and the others)",
        &labels,
        (configs, ref_runs),
        point,
        |runs, k| {
            let xs: Vec<f64> = runs
                .iter()
                .filter_map(|r| Some(quantity(r, SINKS[k].0)? / quantity(r, "work")?))
                .collect();
            Stat::of(&xs)
        },
        |a| format!("{:.5} ± {:.5}", a.mean, a.std),
        |a, d, h| {
            format!(
                "{:+.1} % [{:+.1}, {:+.1}]; {:+.2} σ",
                100.0 * d / a.mean,
                100.0 * (d - h) / a.mean,
                100.0 * (d + h) / a.mean,
                d / a.std
            )
        },
    );
}

/// The pieces table of one point: see the module's doc.
fn print_pieces(point: &str, configs: &[(String, Groups)], ref_runs: &[RunRecord]) {
    let mut labels: Vec<&str> = PIECE_CLASSES.iter().map(|&(_, _, label)| label).collect();
    labels.push("all");
    print_table(
        "Rubble pieces per run by length in blocks",
        &labels,
        (configs, ref_runs),
        point,
        |runs, k| {
            let xs: Vec<f64> = runs.iter().filter_map(piece_counts).map(|n| n[k]).collect();
            Stat::of(&xs)
        },
        |a| format!("{:.1} ± {:.1}", a.mean, a.std),
        |_, d, h| format!("{d:+.1} [{:+.1}, {:+.1}]", d - h, d + h),
    );
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
                let sh = shift(&a, &b);
                let (d, h, ok) = (sh.diff, sh.half, sh.passes);
                // In % of the reference mean; the rafted share in percentage points (its
                // reference mean may be zero); and in units of the reference's σ.
                let (pd, ph, unit) = if key == "rafted" {
                    (100.0 * d, 100.0 * h.abs(), "pp")
                } else {
                    (100.0 * d / a.mean, 100.0 * (h / a.mean).abs(), "%")
                };
                let (sd, sh) = (sh.sigmas, sh.sigmas_half);
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
        print_sinks(point, &configs, ref_runs);
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
         95 % Welch interval. Sinks tables: each sink over W, the reference's mean ± σ, the \
         others' difference in % of the reference mean with its 95 % Welch interval and in \
         units of the reference's σ."
    );
    Ok(())
}
