//! `pressridge tabulate`: a campaign directory to a NetCDF lookup table.

use crate::BoxError;
use pressridge::campaign::tabulation::{
    TabulateCampaignsError, TabulateOptions, Tabulated, tabulate_campaigns,
};
use pressridge::io::table_netcdf::write_ridge_table;
use pressridge::observe::{Profile, mean_profile, profile_spread};
use pressridge::plot;
use pressridge::plot::table::ProfileGroup;
use pressridge::record::RunRecord;
use pressridge::table::tabulate::RidgeTable;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Campaign result directory (from `pressridge campaign`); repeat it to tabulate several
    /// campaigns into one table (e.g. the thickness and the friction sets). Runs are grouped
    /// into sets by their scenes, and a run two campaigns share is counted once.
    #[arg(long, required = true)]
    campaign: Vec<PathBuf>,
    /// Output NetCDF table.
    #[arg(long)]
    out: PathBuf,
    /// Points of the ridged-volume grid.
    #[arg(long, default_value_t = 41)]
    points: usize,
    /// Also draw figures into this directory, each as PNG and SVG: work against volume with
    /// the fit and its bands and force against volume and thickness (per set:
    /// work_set<k>, force_set<k>), C_f against thickness with each seed's value and the
    /// spread (cf), ensemble-averaged final profiles with the spread over the seeds
    /// (profiles; with several sets profiles_set<k> per set and, for each thickness several
    /// sets share, profiles_h<h> and work_sets_h<h>: one curve per set, cf. Figures 8, 9).
    #[arg(long)]
    figures: Option<PathBuf>,
    /// Also write a Markdown report: per grid point the mean and spread over the seeds of
    /// the energy budget, W/ΔPE and the ridge metrics; the fits of eqs (13)–(16).
    #[arg(long)]
    report: Option<PathBuf>,
    /// Tabulate the complete runs of an incomplete campaign (interrupted, or with runs whose
    /// records do not match their files). The table's attributes `runs_planned`,
    /// `runs_tabulated` and `partial` say what was left out. Without it such a campaign is
    /// refused, naming the missing and inconsistent runs.
    #[arg(long)]
    allow_partial: bool,
    /// A run counts as rafted when its intact lead sheet passed the floe's nose by more than
    /// this (m) in a scene of the paper's size, and by the scene's scale in a scene scaled
    /// with the sheet (`rafting::reach_in`); the report gives the rafting
    /// frequency per grid point.
    #[arg(long, default_value_t = pressridge::table::rafting::RAFTING_REACH)]
    rafting_reach: f64,
    /// Scene keys that vary with the sheet thickness within a set (comma-separated or
    /// repeated), e.g. `floe.thickness,floe.length` for campaigns that scale the floe with
    /// the sheet (data/campaigns/thickness-scaled.toml): runs that differ only in these
    /// (besides thickness, block width and seed) make one set, the runs of one set and
    /// thickness must agree in them, and the table records their values per thickness
    /// (global attributes `scaled_keys`, `scaled_values`).
    #[arg(long, value_delimiter = ',')]
    scaled_with_thickness: Vec<String>,
    /// Leave rafted runs (see --rafting-reach) out of the table, as the consistency gate
    /// leaves out unstable ones: a table of ridging alone. They are listed in the table's
    /// `excluded_runs` attribute and on stderr; the report's rafting section still counts
    /// them. Off by default: the default table keeps every sound run.
    #[arg(long)]
    exclude_rafted: bool,
}

/// Today's date (UTC) as YYYY-MM-DD, from the system clock.
fn today() -> String {
    pressridge::io::utc_now()[..10].to_string()
}

pub fn run(a: Args) -> Result<(), BoxError> {
    let opts = TabulateOptions {
        points: a.points,
        allow_partial: a.allow_partial,
        rafting_reach: a.rafting_reach,
        exclude_rafted: a.exclude_rafted,
        scaled_keys: a.scaled_with_thickness.clone(),
    };
    let command = std::env::args().collect::<Vec<_>>().join(" ");
    let t =
        tabulate_campaigns(&a.campaign, &opts, &command, &today()).map_err(|e| -> BoxError {
            match e {
                TabulateCampaignsError::NoCampaign => "no --campaign given".into(),
                TabulateCampaignsError::RaftingReach(r) => {
                    format!("--rafting-reach must be a finite length >= 0 m, not {r}").into()
                }
                other => other.into(),
            }
        })?;
    for (dir, g) in &t.partial {
        eprintln!(
            "pressridge: warning: partial campaign {} (--allow-partial): {g}",
            dir.display()
        );
    }
    let Tabulated {
        table,
        provenance: prov,
        specs,
        records,
        all_records,
        gate_excluded,
        rafted_out,
        ..
    } = t;
    let spec = &specs[0];
    write_ridge_table(&a.out, &table, &prov)?;
    if let Some(dir) = &a.figures {
        write_figures(dir, &table, &records)?;
    }
    for w in pressridge::table::tabulate::fit_warnings(&table) {
        eprintln!("pressridge: warning: {w}");
    }
    for (id, why) in &gate_excluded {
        eprintln!(
            "pressridge: warning: run {id} left out: its {why}; a dissipation cannot be negative, so the run went numerically unstable"
        );
    }
    for (id, why) in &rafted_out {
        eprintln!("pressridge: note: run {id} left out: its {why}");
    }
    if let Some(path) = &a.report {
        let report = Report {
            name: &spec.name,
            table: &table,
            records: &records,
            all_records: &all_records,
            gate_excluded: &gate_excluded,
            reach: a.rafting_reach,
        };
        write_report(path, &report)?;
    }
    let rafting = pressridge::table::rafting::by_point(&all_records, a.rafting_reach);
    let (rafted, known) = rafting
        .iter()
        .fold((0, 0), |(r, k), p| (r + p.rafted.len(), k + p.known));
    println!(
        "rafting: {rafted} of {known} runs with the diagnostic rafted (intact sheet past the floe's nose by more than the reach: {})",
        pressridge::table::rafting::reach_rule(a.rafting_reach)
    );
    if !table.duplicates.is_empty() {
        eprintln!(
            "pressridge: note: {} runs were in more than one campaign and are counted once",
            table.duplicates.len()
        );
    }
    println!(
        "{}: {} runs ({} left out), {} sets × {} thicknesses × {} volumes -> {}",
        spec.name,
        all_records.len() - table.excluded.len() - table.duplicates.len(),
        table.excluded.len(),
        table.sets.len(),
        table.thickness.len(),
        table.volume.len(),
        a.out.display()
    );
    for (si, set) in table.sets.iter().enumerate() {
        for (hi, h) in table.thickness.iter().enumerate() {
            if table.cf_runs[[si, hi]] > 0 {
                println!(
                    "  [{set}] h = {h} m: C_f = {:.2} ({} runs)",
                    table.cf[[si, hi]],
                    table.cf_runs[[si, hi]]
                );
            }
        }
    }
    Ok(())
}

/// The ensemble figures of a table: work, force and C_f per set, work per thickness that
/// several sets share, μ_rdg, and the ensemble final profiles (PNG and SVG) into `dir`.
fn write_figures(dir: &Path, table: &RidgeTable, records: &[RunRecord]) -> Result<(), BoxError> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    // Ensemble final profiles per grid point (all seeds of a set and thickness), runs
    // left out by the gate and second copies of runs shared by two campaigns excepted.
    let mut points: Vec<(usize, f64, Vec<Profile>)> = Vec::new();
    for r in records.iter() {
        let (Some(si), Some(h)) = (
            table.set_of(&r.id),
            r.scene.sheet.as_ref().map(|s| s.thickness),
        ) else {
            continue;
        };
        match points.iter_mut().find(|(s, hh, _)| *s == si && *hh == h) {
            Some((.., v)) => v.push(r.profile.clone()),
            None => points.push((si, h, vec![r.profile.clone()])),
        }
    }
    let group = |label: String, ps: &[Profile]| {
        Some(ProfileGroup {
            label,
            mean: mean_profile(ps)?,
            spread: profile_spread(ps)?,
            runs: ps.len(),
        })
    };
    // One set: every thickness in `profiles` (cf. Figure 10). Several sets: per set
    // (`profiles_set<k>`, its thicknesses) and per thickness that several sets share
    // (`profiles_h<h>`, one curve per set, cf. Figure 8).
    let mut profile_figures: Vec<(String, Vec<ProfileGroup>)> = Vec::new();
    for s in 0..table.sets.len() {
        let mut groups: Vec<ProfileGroup> = points
            .iter()
            .filter(|p| p.0 == s)
            .filter_map(|(_, h, ps)| group(format!("h = {h:.2} m"), ps))
            .collect();
        groups.sort_by(|a, b| a.label.cmp(&b.label));
        let name = if table.sets.len() == 1 {
            "profiles".to_string()
        } else {
            format!("profiles_set{s}")
        };
        profile_figures.push((name, groups));
    }
    let mut shared = Vec::new();
    if table.sets.len() > 1 {
        for (hi, h) in table.thickness.iter().enumerate() {
            if plot::table::sets_at(table, hi).len() < 2 {
                continue;
            }
            shared.push(hi);
            let groups: Vec<ProfileGroup> = points
                .iter()
                .filter(|p| p.1 == *h)
                .filter_map(|(s, _, ps)| group(plot::table::set_display(&table.sets[*s]), ps))
                .collect();
            profile_figures.push((format!("profiles_h{h:.2}"), groups));
        }
    }
    for ext in ["png", "svg"] {
        for s in 0..table.sets.len() {
            plot::table::plot_work(table, s, &dir.join(format!("work_set{s}.{ext}")))?;
            plot::table::plot_force(table, s, &dir.join(format!("force_set{s}.{ext}")))?;
        }
        for &hi in &shared {
            let h = table.thickness[hi];
            plot::table::plot_work_sets(table, hi, &dir.join(format!("work_sets_h{h:.2}.{ext}")))?;
        }
        plot::table::plot_cf(table, &dir.join(format!("cf.{ext}")))?;
        if table.ridged.iter().any(Option::is_some) {
            plot::redistribution::plot_mu_rdg(table, &dir.join(format!("mu_rdg.{ext}")))?;
        }
        for (name, groups) in &profile_figures {
            plot::table::plot_profiles(groups, &dir.join(format!("{name}.{ext}")))?;
        }
    }
    Ok(())
}

/// What the report of a tabulation is made from.
struct Report<'a> {
    name: &'a str,
    table: &'a RidgeTable,
    records: &'a [RunRecord],
    all_records: &'a [RunRecord],
    gate_excluded: &'a [(String, String)],
    reach: f64,
}

/// The campaign report (Markdown) of a tabulation into `path`: the ensembles of the runs
/// kept, and the rafting of every sound run.
fn write_report(path: &Path, r: &Report<'_>) -> Result<(), BoxError> {
    let kept: Vec<_> = r
        .records
        .iter()
        .filter(|run| !r.table.excluded.iter().any(|(id, _)| *id == run.id))
        .cloned()
        .collect();
    let points = pressridge::table::ensemble::summarise(&kept);
    let sound: Vec<_> = r
        .all_records
        .iter()
        .filter(|run| !r.gate_excluded.iter().any(|(id, _)| *id == run.id))
        .cloned()
        .collect();
    let rafting = pressridge::table::rafting::by_point(&sound, r.reach);
    let text = pressridge::io::report::campaign_report(r.name, &points, r.table, &rafting, r.reach);
    pressridge::io::write_atomic(path, text.as_bytes())?;
    Ok(())
}
