//! How often the step's equivalence test passes a change that changes nothing
//! (docs/speed-vs-error.md, "What the test can tell").
//!
//! Draws two arms of `n` runs each, with replacement, from the runs of one configuration (so
//! both arms come from one distribution: an A/A comparison) or, given a second
//! configuration, the second arm from its runs (A/B: how often the test passes that
//! configuration's true shift), judges every quantity the test
//! judges (`pressridge_lab::equivalence`) and counts the draws that pass, per quantity, per
//! point of the campaign's axis and at all points at once. With the test's 41 seeds this is
//! the chance that a change as good as its reference passes; `--n` asks how many seeds a
//! reliable test would need.
//!
//! ```sh
//! cargo run --release --example equivalence_power -- \
//!     crates/lab/records/speed-vs-error/r2-refine-load@numerics.time_step_safety=1.0 \
//!     [--n 41] [--draws 4000] [--seed 1] [--rule standard|bonferroni|tost]
//! ```
//!
//! `--rule` judges by the standing rule (default), by the same with Bonferroni intervals
//! over all judged shifts at all points, or by two one-sided tests (the 90 % interval inside
//! ±0.3 σ): the alternatives docs/speed-vs-error.md weighs.
//!
//! The draws are deterministic (xoshiro256++ from `--seed`). Resampling one ensemble of m
//! runs stands for the seed-to-seed distribution by its m runs (the bootstrap's reading): the
//! rates are estimates, each with a binomial 95 % interval of about ±2·√(p(1−p)/draws).

use pressridge::record::RunRecord;
use pressridge::table::ensemble::Stat;
use pressridge_lab::equivalence::{QUANTITIES, Rule, SEEDS, points, shift_by, value};
use rand_xoshiro::Xoshiro256PlusPlus;
use rand_xoshiro::rand_core::{Rng, SeedableRng};
use std::path::Path;

/// A flag's value, or its default.
fn flag<T: std::str::FromStr>(args: &[String], name: &str, default: T) -> Result<T, String> {
    match args.iter().position(|a| a == name) {
        None => Ok(default),
        Some(i) => args
            .get(i + 1)
            .and_then(|v| v.parse().ok())
            .ok_or_else(|| format!("{name} needs a value")),
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: equivalence_power DIR[@SETTING] [OTHER_DIR[@SETTING]] [--n N] \
                 [--draws D] [--seed S] [--rule standard|bonferroni|tost]";
    let spec = args.first().filter(|a| !a.starts_with("--")).ok_or(usage)?;
    let other = args.get(1).filter(|a| !a.starts_with("--"));
    let n: usize = flag(&args, "--n", SEEDS)?;
    let draws: usize = flag(&args, "--draws", 4000)?;
    let seed: u64 = flag(&args, "--seed", 1)?;
    let rule_name: String = flag(&args, "--rule", "standard".to_string())?;
    if n < 2 || draws == 0 {
        return Err(format!("--n must be at least 2 and --draws at least 1 ({usage})").into());
    }
    let read = |spec: &str| {
        let (dir, only) = match spec.split_once('@') {
            Some((d, s)) => (d, Some(s)),
            None => (spec, None),
        };
        points(Path::new(dir), only)
    };
    let groups = read(spec)?;
    // The second arm's runs: the same configuration's (A/A), or another's (A/B: how often
    // the test passes that configuration's true shift).
    let groups_b = match other {
        Some(o) => read(o)?,
        None => groups.clone(),
    };
    let judged: Vec<(&str, &str)> = QUANTITIES
        .iter()
        .filter(|q| q.2)
        .map(|q| (q.0, q.1))
        .collect();
    let rule = match rule_name.as_str() {
        "standard" => Rule::Standard,
        // Every judged shift at every point: the family the test passes or fails.
        "bonferroni" => Rule::Bonferroni(judged.len() * groups.len()),
        "tost" => Rule::Tost,
        other => {
            return Err(
                format!("--rule is standard, bonferroni or tost, not {other} ({usage})").into(),
            );
        }
    };
    let mut rng = Xoshiro256PlusPlus::seed_from_u64(seed);
    // Per draw, whether every judged quantity passed at every point so far.
    let mut all_points = vec![true; draws];
    println!(
        "{} draws of two arms of {n} runs (with replacement), {draws} draws: the share of draws \
         in which the equivalence test passes ({rule:?}).\n",
        if other.is_some() { "A/B" } else { "A/A" }
    );
    let values = |runs: &[RunRecord]| -> Vec<Vec<Option<f64>>> {
        judged
            .iter()
            .map(|(k, _)| runs.iter().map(|r| value(r, k)).collect())
            .collect()
    };
    for (point, runs) in &groups {
        let Some(runs_b) = groups_b.get(point) else {
            return Err(format!("{point}: no runs of the second configuration there").into());
        };
        let (va, vb) = (values(runs), values(runs_b));
        let mut pass = vec![0usize; judged.len()];
        let mut pass_all = 0usize;
        let (ma, mb) = (runs.len() as u64, runs_b.len() as u64);
        for ok_all in all_points.iter_mut() {
            let mut pick =
                |m: u64| -> Vec<usize> { (0..n).map(|_| (rng.next_u64() % m) as usize).collect() };
            let (a, b) = (pick(ma), pick(mb));
            let mut every = true;
            for (q, (xa, xb)) in va.iter().zip(&vb).enumerate() {
                let arm = |vals: &[Option<f64>], idx: &[usize]| {
                    let xs: Vec<f64> = idx.iter().filter_map(|&i| vals[i]).collect();
                    Stat::of(&xs)
                };
                let (sa, sb) = (arm(xa, &a), arm(xb, &b));
                let ok = sa.n >= 2 && sb.n >= 2 && shift_by(&sa, &sb, rule).passes;
                pass[q] += usize::from(ok);
                every &= ok;
            }
            pass_all += usize::from(every);
            *ok_all &= every;
        }
        println!(
            "### {point} ({} and {} runs drawn from)\n",
            runs.len(),
            runs_b.len()
        );
        println!("| quantity | passes |\n|---|---|");
        for ((_, label), p) in judged.iter().zip(&pass) {
            println!("| {label} | {:.1} % |", 100.0 * *p as f64 / draws as f64);
        }
        println!(
            "| all {} at once | {:.1} % |\n",
            judged.len(),
            100.0 * pass_all as f64 / draws as f64
        );
    }
    let both = all_points.iter().filter(|&&x| x).count();
    println!(
        "Every judged quantity at all {} points at once: {:.1} % of the draws.",
        groups.len(),
        100.0 * both as f64 / draws as f64
    );
    Ok(())
}
