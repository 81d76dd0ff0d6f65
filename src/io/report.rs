//! A campaign as a Markdown report: the ensemble statistics of every grid point
//! ([`crate::table::ensemble`]) and the fits of eqs (13)–(16) ([`crate::table::tabulate`]),
//! the tables `docs/validation.md` quotes.

use crate::table::ensemble::{PointStats, Stat};
use crate::table::rafting::PointRafting;
use crate::table::tabulate::RidgeTable;
use std::fmt::Write;

/// `mean ± std` of `s` scaled by `k`, with `prec` decimals; `mean (1 seed)` when one run
/// had a value (no spread to show); `–` when none had.
fn pm(s: Option<Stat>, k: f64, prec: usize) -> String {
    match s {
        Some(s) if s.n == 1 && s.mean.is_finite() => format!("{:.prec$} (1 seed)", s.mean * k),
        Some(s) if s.n > 0 && s.mean.is_finite() => {
            format!("{:.prec$} ± {:.prec$}", s.mean * k, s.std * k)
        }
        _ => "–".into(),
    }
}

/// A slope column: `mean ± std (n)` where fewer runs than the point has gave a slope.
fn slope(p: &PointStats, key: &str) -> String {
    let s = p.get(key);
    let mut t = pm(s, 1.0, 1);
    if let Some(s) = s
        && s.n > 0
        && s.n < p.seeds.len()
    {
        let _ = write!(t, " ({} run{})", s.n, if s.n == 1 { "" } else { "s" });
    }
    t
}

/// The report for campaign `name`, its grid points, its table and the rafting of its runs
/// at rafting reach `reach` (m; [`crate::table::rafting`]).
pub fn campaign_report(
    name: &str,
    points: &[PointStats],
    table: &RidgeTable,
    rafting: &[PointRafting],
    reach: f64,
) -> String {
    let mut o = String::new();
    let runs: usize = points.iter().map(|p| p.seeds.len()).sum();
    let _ = writeln!(
        o,
        "# Campaign `{name}`: {runs} runs tabulated, {} left out\n",
        table.excluded.len()
    );
    let _ = writeln!(
        o,
        "Means ± sample standard deviations over the seeds of each grid point, at the end of \
         the runs. Energies per metre of ridge.\n"
    );
    if !table.scaled_keys.is_empty() {
        let _ = writeln!(
            o,
            "## Scene keys scaled with the thickness\n\nWithin a set these vary with the sheet \
             thickness (`tabulate --scaled-with-thickness`); their values per set and \
             thickness:\n\n| set | thickness (m) | {} |\n|---|---|{}",
            table.scaled_keys.join(" | "),
            "---|".repeat(table.scaled_keys.len())
        );
        for (si, set) in table.sets.iter().enumerate() {
            for (hi, h) in table.thickness.iter().enumerate() {
                let v = &table.scaled_values[[si, hi]];
                if !v.is_empty() {
                    let _ = writeln!(o, "| {set} | {h} | {} |", v.join(" | "));
                }
            }
        }
        let _ = writeln!(o);
    }
    if !table.excluded.is_empty() {
        let _ = writeln!(
            o,
            "## Runs left out\n\nA dissipation cannot be negative: a run in which one is (below \
             −1e-6 of the work) booked a numerical energy source and went unstable. These runs \
             are in neither the statistics nor the table:\n"
        );
        for (id, why) in &table.excluded {
            let _ = writeln!(o, "- `{id}`: {why}");
        }
        let _ = writeln!(o);
    }
    budget_section(&mut o, points);
    metrics_section(&mut o, points);
    rafting_section(&mut o, rafting, reach);
    fits_section(&mut o, table);
    ratio_section(&mut o, table);
    ridged_section(&mut o, table);
    o
}

/// The simulated ridged ice per set and thickness (the table's `mu_rdg`, `h_star`,
/// `ridged_*` fields; [`crate::table::redistribution`]), when any run kept ridge columns.
fn ridged_section(o: &mut String, table: &RidgeTable) {
    if table.ridged.iter().all(Option::is_none) {
        return;
    }
    let ci = |s: &Stat, prec: usize| s.mean_ci95(prec);
    let _ = writeln!(
        o,
        "\n## Ridged ice: the thickness distribution of the final ridges\n\n\
         Per set and thickness, from the runs whose records keep the ridge columns (runs \
         recorded before they were kept are not counted here): the solid ice of each 1-m strip \
         of rubble, its mean and the porosity, Lipscomb's exponential (μ_rdg) and Hibler's \
         uniform (H*) fitted run by run (mean ± 95 % interval, Student t), and each shape's \
         Kolmogorov–Smirnov distance on the runs' strips together (docs/tables.md).\n"
    );
    let _ = writeln!(
        o,
        "| set | thickness (m) | runs with columns / runs | mean H (m) | porosity | μ_rdg (m^½) | KS exp. | H* (m) | KS unif. |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|");
    for (si, set) in table.sets.iter().enumerate() {
        let label = if set.is_empty() { "all" } else { set.as_str() };
        for (hi, h) in table.thickness.iter().enumerate() {
            let runs = table.cf_runs[[si, hi]];
            match &table.ridged[[si, hi]] {
                Some(e) => {
                    let _ = writeln!(
                        o,
                        "| {label} | {h} | {} / {runs} | {} | {} | {} | {:.2} | {} | {:.2} |",
                        e.mu_rdg.n,
                        ci(&e.mean_thickness, 2),
                        ci(&e.porosity, 2),
                        ci(&e.mu_rdg, 2),
                        e.fit.ks_exponential,
                        ci(&e.h_star, 1),
                        e.fit.ks_uniform,
                    );
                }
                None if runs > 0 => {
                    let _ = writeln!(o, "| {label} | {h} | 0 / {runs} | – | – | – | – | – | – |");
                }
                None => {}
            }
        }
    }
}

/// The energy budget of every grid point, with the contacts born overlapping.
fn budget_section(o: &mut String, points: &[PointStats]) {
    let _ = writeln!(
        o,
        "## Energy budget\n\n\"Born overlapping\" counts contacts that started with their \
         overlap forgiven (a joint severed with its blocks overlapping, or a sheet block grown \
         where rubble lay; docs/model.md): many of them mean the sheet rafted until its driven \
         end reached the ridge.\n"
    );
    let _ = writeln!(
        o,
        "| point | seeds | W (kJ/m) | ΔPE (kJ/m) | Φ_f/W | ΔPE/W | Φ_i/W | drag/W | abs(residual)/W | W/ΔPE | mean force (kN/m) | joints severed | born overlapping |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for p in points {
        let g = |k: &str| p.get(k);
        let _ = writeln!(
            o,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {:.1e} | {} | {} | {} | {} |",
            p.label,
            p.seeds.len(),
            pm(g("work"), 1e-3, 1),
            pm(g("potential_energy"), 1e-3, 1),
            pm(g("friction_fraction"), 1.0, 2),
            pm(g("pe_fraction"), 1.0, 3),
            pm(g("viscous_fraction"), 1.0, 3),
            pm(g("drag_fraction"), 1.0, 3),
            g("residual_fraction").map_or(f64::NAN, |s| s.mean),
            pm(g("ratio_work_to_pe"), 1.0, 1),
            pm(g("mean_force"), 1e-3, 2),
            pm(g("blocks_broken"), 1.0, 0),
            pm(g("handover_contacts"), 1.0, 1),
        );
    }
}

/// The ridge metrics of every grid point (final rubble profile in 1-m strips).
fn metrics_section(o: &mut String, points: &[PointStats]) {
    let _ = writeln!(
        o,
        "\n## Ridge metrics (final rubble profile in 1-m strips)\n"
    );
    let _ = writeln!(
        o,
        "| point | sail height (m) | keel depth (m) | sail area (m²/m) | keel area (m²/m) | θ₁ lead sail (°) | θ₂ floe sail (°) | φ₁ lead keel (°) | φ₂ floe keel (°) | L/h |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|---|");
    for p in points {
        let g = |k: &str| p.get(k);
        let _ = writeln!(
            o,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            p.label,
            pm(g("max_sail_height"), 1.0, 2),
            pm(g("max_keel_depth"), 1.0, 2),
            pm(g("sail_area"), 1.0, 1),
            pm(g("keel_area"), 1.0, 1),
            slope(p, "sail_slope_lead"),
            slope(p, "sail_slope_floe"),
            slope(p, "keel_slope_lead"),
            slope(p, "keel_slope_floe"),
            pm(g("length_to_thickness"), 1.0, 2),
        );
    }
}

/// The rafting of every grid point at reach `reach` (m).
fn rafting_section(o: &mut String, rafting: &[PointRafting], reach: f64) {
    let _ = writeln!(
        o,
        "\n## Rafting\n\nA run *rafted* when the leading edge of its intact lead sheet passed the \
         floe's nose by more than the rafting reach at some step (`sheet_overrun_max`; \
         docs/tables.md, \"Rafting\"): it slid over or under the floe instead of breaking \
         against it. The reach is {}. Runs made before the diagnostic existed are unknown. \
         The statistics above include rafted runs.\n",
        crate::table::rafting::reach_rule(reach)
    );
    let _ = writeln!(
        o,
        "| point | reach (m) | rafted / known | rafted runs (overrun, W/ΔPE) | largest overrun of the others (m) | W/ΔPE of the others |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|");
    for p in rafting {
        let runs: Vec<String> = p
            .rafted
            .iter()
            .map(|(id, x, q)| format!("`{id}` ({x:.1} m, {q:.1})"))
            .collect();
        let _ = writeln!(
            o,
            "| {} | {:.1} | {} / {} | {} | {} | {} |",
            p.label,
            p.reach,
            p.rafted.len(),
            p.known,
            if runs.is_empty() {
                "–".to_string()
            } else {
                runs.join(", ")
            },
            pm(Some(p.ridged_overrun), 1.0, 2),
            pm(Some(p.ridged_ratio), 1.0, 1),
        );
    }
}

/// The fits of eqs (13)–(14) per set and thickness, pooled per set, and their warnings.
fn fits_section(o: &mut String, table: &RidgeTable) {
    let _ = writeln!(
        o,
        "\n## Fits of eqs (13)–(14): W = V(a_W V + b_W), PE = V(a_P V + b_P)\n\n\
         Least squares through the origin over every sample (at the campaign's interval) of every run; ± one \
         standard error (which assumes independent residuals: see docs/tables.md).\n"
    );
    let _ = writeln!(
        o,
        "| set | thickness (m) | samples | a_W (J/m⁵) | b_W (J/m³) | R²(W) | a_P (J/m⁵) | b_P (J/m³) | R²(PE) |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|");
    let fit_row = |o: &mut String, set: &str, h: &str, f: &crate::table::tabulate::SetFits| {
        let (w, p) = (&f.work, &f.potential_energy);
        let (we, pe) = (w.standard_errors(), p.standard_errors());
        let _ = writeln!(
            o,
            "| {set} | {h} | {} | {:.0} ± {:.0} | {:.0} ± {:.0} | {:.3} | {:.1} ± {:.1} | {:.0} ± {:.0} | {:.3} |",
            w.n, w.a, we[0], w.b, we[1], w.r_squared, p.a, pe[0], p.b, pe[1], p.r_squared
        );
    };
    for (si, set) in table.sets.iter().enumerate() {
        let label = if set.is_empty() { "all" } else { set.as_str() };
        for (hi, h) in table.thickness.iter().enumerate() {
            if let Some(f) = &table.fits[[si, hi]] {
                fit_row(o, label, &format!("{h}"), f);
            }
        }
        if let Some(f) = &table.pooled[si] {
            fit_row(o, label, "pooled", f);
        }
    }
    let warnings = crate::table::tabulate::fit_warnings(table);
    if !warnings.is_empty() {
        let _ = writeln!(o, "\n**Warnings:**\n");
        for w in &warnings {
            let _ = writeln!(o, "- {w}");
        }
    }
}

/// Eq (16): dW/dPE from the pooled fits at a quarter, half, three quarters and all of the volume axis, and C_f per thickness.
fn ratio_section(o: &mut String, table: &RidgeTable) {
    let _ = writeln!(
        o,
        "\n## Eq (16): dW/dPE from the pooled fits, and C_f per thickness\n"
    );
    let nv = table.volume.len();
    let picks: Vec<usize> = [0.25, 0.5, 0.75, 1.0]
        .iter()
        .map(|f| ((nv - 1) as f64 * f).round() as usize)
        .collect();
    let _ = write!(o, "| set |");
    for &k in &picks {
        let _ = write!(o, " dW/dPE at V = {:.2} m³/m |", table.volume[k]);
    }
    let _ = writeln!(o, " C_f = mean final W/ΔPE ± s.d. per thickness |");
    let _ = writeln!(o, "|---|{}---|", "---|".repeat(picks.len()));
    for (si, set) in table.sets.iter().enumerate() {
        let label = if set.is_empty() { "all" } else { set.as_str() };
        let _ = write!(o, "| {label} |");
        for &k in &picks {
            let _ = write!(o, " {:.1} |", table.ratio_fit[[si, k]]);
        }
        let cf: Vec<String> = table
            .thickness
            .iter()
            .zip(table.cf_finals.row(si))
            .map(|(h, runs)| format!("{h} m: {}", pm(Some(Stat::of(runs)), 1.0, 1)))
            .collect();
        let _ = writeln!(o, " {} |", cf.join(", "));
    }
}
