//! Where the model disagrees with the paper, what the open choices give (issue 30, item 2:
//! "where a finding cannot be met by any defensible choice, the table says so with the
//! evidence"). The evidence is the register of open choices (`docs/choices.md`): probe
//! campaigns that move one choice each from the model's default, run at μ = 0.4 and μ = 1.0
//! (μ_w = 0.6). For each statement the model disagrees with, the closest any choice comes.

use super::{
    FIGURE5, Finding, OTHER_SINKS_BOUND, Point, Verdict, interval, records_step, select, stat,
};
use crate::choices::{at, by_setting, other_sinks_fraction, rafted_count};
use pressridge::record::RunRecord;
use pressridge::scene::{Scene, StepScheme};
use pressridge::table::ensemble::Stat;
use pressridge::table::rafting::{Outcome, RAFTING_REACH, outcome};
use std::fmt::Write as _;

/// The probes of the register that take the experiment apart instead of reading a choice the
/// paper leaves open, with the reason: they are left out of the evidence.
pub const NOT_CHOICES: [(&str, &str); 2] = [
    (
        "floe.pin=false",
        "without the pin nothing holds the floe and the sheet pushes it away",
    ),
    (
        "sheet.clamp_driven_end=false",
        "without the clamp the sheet's far end sinks and ΔPE turns negative",
    ),
];

/// The name of the modulus row whose disagreement the evidence takes up (item e: "no
/// significant differences between the final profiles", read on the sail).
pub(super) const SAIL_AT_MODULUS: &str = "max sail height (m)";

/// The register's runs: the baseline (the model's default scene at the probes' friction
/// pairs) and the probe campaigns, each as (name, runs).
pub struct Register<'a> {
    /// The baseline's runs.
    pub baseline: &'a [RunRecord],
    /// The probes' runs, by campaign.
    pub probes: &'a [(String, Vec<RunRecord>)],
}

/// The register's choice settings at friction `f`, the probes of [`NOT_CHOICES`] left out.
fn choices_at<'a>(reg: &'a Register, f: (f64, f64)) -> Vec<(String, Vec<&'a RunRecord>)> {
    by_setting(reg.probes, f)
        .into_iter()
        .filter(|(label, _)| !NOT_CHOICES.iter().any(|(n, _)| n == label))
        .collect()
}

/// The evidence section for the rows of `rows` that disagree, or `None` when none does or
/// when the register is not of this model (its baseline holds no run of `base`'s Figure 5
/// scene at any one step). The register is read at the step its baseline was made with,
/// which may differ from the table's (`docs/notes/choices-revision1.md`, "At which step": each effect is a
/// difference between arms at one step), and the section then says so. `records` are the
/// statement table's runs; `source` names where the register's records are, for the
/// section's text.
pub fn evidence(
    rows: &[Finding],
    records: &[RunRecord],
    base: &Scene,
    reg: &Register,
    source: &str,
) -> Option<String> {
    let disagrees = |item: &str, prefix: &str| {
        rows.iter()
            .any(|r| r.item == item && r.verdict == Verdict::Disagree && r.ours.starts_with(prefix))
    };
    let mut reg_base = base.clone();
    reg_base
        .numerics
        .set_step_scheme(records_step(reg.baseline, base).ok().flatten()?);
    select(reg.baseline, &reg_base, FIGURE5, 2).ok()?;
    let mut lines = Vec::new();
    if disagrees("a", "") {
        lines.push(other_sinks(reg));
    }
    if disagrees("c1", "") {
        lines.push(ride_over(reg));
    }
    if disagrees("e", SAIL_AT_MODULUS) {
        lines.extend(sail_at_modulus(records, base));
    }
    if lines.is_empty() {
        return None;
    }
    let mut s = format!(
        "\n**Where the model disagrees: the closest any open choice comes.** Each choice of \
         the register (`docs/choices.md`) moved alone on this model, at μ = 0.4 and μ = 1.0 \
         (μ_w = 0.6), from the records in `{source}`.{step} Left out, because they take \
         the experiment apart: ",
        step = step_note(reg_base.numerics.step_scheme(), base.numerics.step_scheme())
    );
    let left_out: Vec<String> = NOT_CHOICES
        .iter()
        .map(|(n, why)| format!("`{n}` ({why})"))
        .collect();
    let _ = writeln!(s, "{}.\n", left_out.join("; "));
    s.push_str("| item | the paper | the model's default | the closest choice | so |\n");
    s.push_str("|---|---|---|---|---|\n");
    for l in lines {
        let _ = writeln!(s, "{l}");
    }
    Some(s)
}

/// The sentence saying that the register was made at another step than the table's runs
/// (both as fractions of the stable limit), or nothing when they agree.
fn step_note(register: StepScheme, table: StepScheme) -> String {
    if register == table {
        return String::new();
    }
    format!(
        " The register's runs (its baseline and its probes) were made at {register}, the \
         table's above at {table}: where a row reads the register, its default and its \
         closest choice are both runs at that step \
         (`docs/notes/choices-revision1.md`, \"At which step\")."
    )
}

/// Item a: the other sinks' share of W at the Figure 5 point under each choice.
fn other_sinks(reg: &Register) -> String {
    let f = (FIGURE5.mu, FIGURE5.mu_w);
    let q = |r: &RunRecord| Some(other_sinks_fraction(r));
    let base = stat(&at(reg.baseline, f), q);
    let stats: Vec<(String, Stat)> = choices_at(reg, f)
        .into_iter()
        .map(|(label, runs)| (label, stat(&runs, q)))
        .filter(|(_, s)| s.n >= 2)
        .collect();
    let lowest = stats.iter().min_by(|a, b| a.1.mean.total_cmp(&b.1.mean));
    let reach = stats
        .iter()
        .map(|(l, s)| (l, s.mean - s.half_width_95()))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let closest = lowest.map_or("no choice was probed".into(), |(l, s)| {
        format!("`{l}`: {}", interval(s, 100.0, 1, " %"))
    });
    let so = match reach {
        Some((l, lo)) if lo > OTHER_SINKS_BOUND => format!(
            "no choice meets it: every choice's interval lies above 5 % (the lowest lower \
             bound {:.1} %, `{l}`)",
            100.0 * lo
        ),
        Some((l, lo)) => format!(
            "`{l}`'s interval reaches {:.1} %: more seeds would decide",
            100.0 * lo
        ),
        None => "not probed".into(),
    };
    format!(
        "| a | the other sinks \"less than 5%\" of W (Figure 5 point) | {} | {closest} | {so} |",
        interval(&base, 100.0, 1, " %")
    )
}

/// Item c1: the runs at μ = 0.4 whose intact sheet rode over the floe, under each choice.
fn ride_over(reg: &Register) -> String {
    let f = (0.4, FIGURE5.mu_w);
    let base = at(reg.baseline, f);
    let counts: Vec<(String, usize, usize)> = choices_at(reg, f)
        .into_iter()
        .map(|(label, runs)| (label, rafted_count(&runs), runs.len()))
        .collect();
    let fewest = counts
        .iter()
        .min_by(|a, b| (a.1 as f64 / a.2 as f64).total_cmp(&(b.1 as f64 / b.2 as f64)));
    let (closest, so) = match fewest {
        Some((l, k, n)) if *k > 0 => (
            format!("`{l}`: {k} of {n} rode over"),
            format!(
                "no choice meets it: under every choice at least {k} of {n} runs' intact sheet \
                 rode over the floe (the {RAFTING_REACH}-m reach)"
            ),
        ),
        Some((l, _, n)) => (
            format!("`{l}`: 0 of {n} rode over"),
            format!("`{l}` meets it in its {n} runs"),
        ),
        None => ("no choice was probed".into(), "not probed".into()),
    };
    format!(
        "| c1 | at μ = 0.4 the sheet fails at the floe and builds a ridge (Figure 6a) | {} of {} \
         rode over | {closest} | {so} |",
        rafted_count(&base),
        base.len()
    )
}

/// Item e (the sail): the modulus is the paper's own parameter, not a choice; whether the
/// lower sail at 1 GPa is the ride-over's (the stiff sheet never rides over) is read from
/// the Figure 5 runs that broke at the floe.
fn sail_at_modulus(records: &[RunRecord], base: &Scene) -> Option<String> {
    let fig5 = select(records, base, FIGURE5, 2).ok()?;
    let stiff = select(
        records,
        base,
        Point {
            e_top: 1.0e9,
            e_bottom: 6.7e8,
            ..FIGURE5
        },
        2,
    )
    .ok()?;
    let broke: Vec<&RunRecord> = fig5
        .iter()
        .copied()
        .filter(|r| outcome(r, RAFTING_REACH) == Outcome::Ridged)
        .collect();
    let sail = |r: &RunRecord| Some(r.metrics.max_sail_height);
    let (a, b) = (stat(&broke, sail), stat(&stiff, sail));
    if a.n < 2 {
        return None;
    }
    let (d, h) = a.welch_difference(&b);
    let so = if d + h < 0.0 || d - h > 0.0 {
        "not the ride-over: the sail is lower at 1 GPa also against the runs that broke at the \
         floe; the register moves no choice at 1 GPa"
    } else {
        "the difference is the ride-over's: against the runs that broke at the floe it is not \
         resolved"
    };
    Some(format!(
        "| e | \"no significant differences between the final profiles\" (max sail height) | \
         1 GPa minus 0.1 GPa, all runs: see the row above | against the {} of {} runs at \
         0.1 GPa that broke at the floe: {d:+.2} m [{:+.2}, {:+.2}] ({:.2} against {:.2}; \
         n = {}, {}) | {so} |",
        broke.len(),
        fig5.len(),
        d - h,
        d + h,
        b.mean,
        a.mean,
        b.n,
        a.n
    ))
}
