//! Figures of a tabulated campaign (cf. Hopkins 1994, Figures 8–12).

use super::layout::{Axis, Layout};
use super::{PlotError, draw_err, write_figure};
use crate::observe::Profile;
use crate::table::tabulate::RidgeTable;
use ndarray::s;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

pub(super) const COLORS: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
];

fn finite_max(xs: impl Iterator<Item = f64>) -> f64 {
    xs.filter(|x| x.is_finite()).fold(0.0, f64::max)
}

/// The largest number of runs behind a value of set `s` at thickness index `hi` (the runs
/// of that thickness, where all reached).
fn most_runs(t: &RidgeTable, s: usize, hi: usize) -> u32 {
    t.runs
        .slice(s![s, hi, ..])
        .iter()
        .copied()
        .max()
        .unwrap_or(0)
}

/// The ensemble-mean work curve of set `s` at thickness index `hi` (V in m³/m, W in MJ/m),
/// drawn only where at least half of its runs reached the volume: beyond, the mean of the
/// one or two runs that went farthest jumps about and is no ensemble mean.
fn mean_work_curve(t: &RidgeTable, s: usize, hi: usize) -> Vec<(f64, f64)> {
    let n = most_runs(t, s, hi);
    t.volume
        .iter()
        .zip(&t.work_mean.slice(s![s, hi, ..]))
        .zip(&t.runs.slice(s![s, hi, ..]))
        .filter(|((_, w), k)| w.is_finite() && 2 * **k >= n && **k > 0)
        .map(|((v, w), _)| (*v, w / 1e6))
        .collect()
}

/// Work against ridged volume for set `s` (cf. Figures 9, 11, 12): the ensemble mean of
/// each thickness (where at least half its runs reached), the pooled fit of eq (13) and its
/// 95 % confidence and prediction bands, in MJ/m.
pub fn plot_work(t: &RidgeTable, s: usize, path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 600), draw_work(t, s)))
}

fn draw_work<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    t: &RidgeTable,
    s: usize,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let vmax = t.volume.last().copied().unwrap_or(1.0).max(1e-9);
    let band = t.work_band[s].as_ref();
    let wmax = finite_max(
        t.work_mean
            .index_axis(ndarray::Axis(0), s)
            .iter()
            .copied()
            .chain(band.into_iter().flat_map(|b| b.pred_hi.iter().copied())),
    ) / 1e6;
    root.fill(&WHITE).map_err(draw_err)?;
    let title = if t.sets[s].is_empty() {
        "work against ridged volume".to_string()
    } else {
        format!("work against ridged volume ({})", set_display(&t.sets[s]))
    };
    let (x, y) = (
        Axis::new(0.0, vmax, "ridged volume V (m³/m)"),
        Axis::new(0.0, (wmax * 1.05).max(1e-9), "work (MJ/m)"),
    );
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, &title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    if let Some(b) = band {
        let area = |lo: &[f64], hi: &[f64]| -> Vec<(f64, f64)> {
            let mut p: Vec<(f64, f64)> = b.v.iter().zip(hi).map(|(v, y)| (*v, y / 1e6)).collect();
            p.extend(
                b.v.iter()
                    .zip(lo)
                    .rev()
                    .map(|(v, y)| (*v, y.max(0.0) / 1e6)),
            );
            p
        };
        // The prediction band, then the confidence band over it: (lower, upper, grey, alpha).
        let bands = [
            (&b.pred_lo, &b.pred_hi, 200, 0.5, "95 % prediction band"),
            (&b.conf_lo, &b.conf_hi, 120, 0.6, "95 % confidence band"),
        ];
        for (lo, hi, grey, alpha, label) in bands {
            let fill = RGBColor(grey, grey, grey);
            chart
                .draw_series(std::iter::once(Polygon::new(
                    area(lo, hi),
                    fill.mix(alpha).filled(),
                )))
                .map_err(draw_err)?
                .label(label)
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - key / 4), (x + key, y + key / 4)], fill.filled())
                });
        }
        chart
            .draw_series(LineSeries::new(
                b.v.iter().zip(&b.fit).map(|(v, y)| (*v, y / 1e6)),
                BLACK.stroke_width(line),
            ))
            .map_err(draw_err)?
            .label("eq (13), pooled fit")
            .legend(move |(x, y)| {
                PathElement::new([(x, y), (x + key, y)], BLACK.stroke_width(line))
            });
    }
    for (hi, th) in t.thickness.iter().enumerate() {
        let c = COLORS[hi % COLORS.len()];
        let pts = mean_work_curve(t, s, hi);
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(line)))
            .map_err(draw_err)?
            .label(format!("h = {th:.2} m, ensemble mean"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
    }
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperLeft)
}

/// Work against ridged volume at thickness index `hi` for every set that has runs there
/// (cf. Figure 9, the eight friction sets at 0.30 m): one ensemble-mean curve per set, in
/// MJ/m. PNG, or SVG by the extension.
pub fn plot_work_sets(t: &RidgeTable, hi: usize, path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 600), draw_work_sets(t, hi)))
}

/// The sets with at least one run at thickness index `hi`.
pub fn sets_at(t: &RidgeTable, hi: usize) -> Vec<usize> {
    (0..t.sets.len())
        .filter(|&s| t.runs.slice(s![s, hi, ..]).iter().any(|&n| n > 0))
        .collect()
}

fn draw_work_sets<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    t: &RidgeTable,
    hi: usize,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let sets = sets_at(t, hi);
    let vmax = t.volume.last().copied().unwrap_or(1.0).max(1e-9);
    let wmax = finite_max(
        sets.iter()
            .flat_map(|&s| t.work_mean.slice(s![s, hi, ..]).into_iter().copied()),
    ) / 1e6;
    root.fill(&WHITE).map_err(draw_err)?;
    let title = format!(
        "work against ridged volume, h = {:.2} m, ensemble means per set",
        t.thickness[hi]
    );
    let (x, y) = (
        Axis::new(0.0, vmax, "ridged volume V (m³/m)"),
        Axis::new(0.0, (wmax * 1.05).max(1e-9), "work (MJ/m)"),
    );
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, &title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    for (k, &s) in sets.iter().enumerate() {
        let c = COLORS[k % COLORS.len()];
        let pts = mean_work_curve(t, s, hi);
        let n = most_runs(t, s, hi) as usize;
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(line)))
            .map_err(draw_err)?
            .label(format!("{} {}", set_display(&t.sets[s]), seeds(n)))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
    }
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperLeft)
}

/// Ridging force against volume for set `s`: eq (15) from the pooled fit per thickness
/// (lines) and the ensemble mean of the runs' interval-mean force (dots), in kN/m.
pub fn plot_force(t: &RidgeTable, s: usize, path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 520), draw_force(t, s)))
}

fn draw_force<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    t: &RidgeTable,
    s: usize,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let vmax = t.volume.last().copied().unwrap_or(1.0).max(1e-9);
    let fmax = finite_max(
        t.force_fit
            .index_axis(ndarray::Axis(0), s)
            .iter()
            .chain(t.force_mean.index_axis(ndarray::Axis(0), s).iter())
            .copied(),
    ) / 1e3;
    root.fill(&WHITE).map_err(draw_err)?;
    let title = if t.sets[s].is_empty() {
        "ridging force against volume and thickness".to_string()
    } else {
        format!(
            "ridging force against volume and thickness ({})",
            set_display(&t.sets[s])
        )
    };
    let title = title.as_str();
    let (x, y) = (
        Axis::new(0.0, vmax, "ridged volume V (m³/m)"),
        Axis::new(0.0, (fmax * 1.05).max(1e-9), "force (kN/m)"),
    );
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    for (hi, th) in t.thickness.iter().enumerate() {
        let c = COLORS[hi % COLORS.len()];
        chart
            .draw_series(LineSeries::new(
                t.volume
                    .iter()
                    .zip(&t.force_fit.slice(s![s, hi, ..]))
                    .filter(|(_, f)| f.is_finite())
                    .map(|(v, f)| (*v, f / 1e3)),
                c.stroke_width(line),
            ))
            .map_err(draw_err)?
            .label(format!("h = {th:.2} m, eq (15)"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
        chart
            .draw_series(
                t.volume
                    .iter()
                    .zip(&t.force_mean.slice(s![s, hi, ..]))
                    .filter(|(_, f)| f.is_finite())
                    .map(|(v, f)| Circle::new((*v, f / 1e3), 3, c.filled())),
            )
            .map_err(draw_err)?;
    }
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperLeft)
}

/// One ensemble of final profiles: the strip-by-strip mean and sample standard deviation
/// over its runs ([`crate::observe::mean_profile`], [`crate::observe::profile_spread`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ProfileGroup {
    /// Legend label (e.g. `h = 0.30 m`).
    pub label: String,
    /// Mean profile (m).
    pub mean: Profile,
    /// Standard deviation over the runs (m).
    pub spread: Profile,
    /// Number of runs (seeds).
    pub runs: usize,
}

/// `(1 seed)` or `(n seeds)`.
pub fn seeds(n: usize) -> String {
    if n == 1 {
        "(1 seed)".into()
    } else {
        format!("({n} seeds)")
    }
}

/// Ensemble-averaged final profiles (cf. Hopkins 1994, Figures 8 and 10): per group, the
/// mean sail height (up) and keel depth (down) of all ice in 1-m strips as a thick line, the
/// mean ± one standard deviation over the seeds as a shaded band, the rubble-only mean as a
/// thin line; the water line at 0. PNG, or SVG by the extension.
pub fn plot_profiles(groups: &[ProfileGroup], path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 560), draw_profiles(groups)))
}

fn draw_profiles<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    groups: &[ProfileGroup],
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let Some(first) = groups.first().map(|g| &g.mean) else {
        return root.present().map_err(draw_err);
    };
    let x1 = first.x0 + first.dx * first.sail.len() as f64;
    let up = |g: &ProfileGroup| {
        g.mean
            .sail
            .iter()
            .zip(&g.spread.sail)
            .map(|(m, s)| m + s)
            .collect::<Vec<_>>()
    };
    let down = |g: &ProfileGroup| {
        g.mean
            .keel
            .iter()
            .zip(&g.spread.keel)
            .map(|(m, s)| m + s)
            .collect::<Vec<_>>()
    };
    let top = finite_max(groups.iter().flat_map(up)).max(1.0);
    let bottom = finite_max(groups.iter().flat_map(down)).max(1.0);
    let title = "ensemble-averaged final profiles (1-m strips, mean ± 1 s.d. over seeds)";
    // The legend goes in the upper left, above the level sheet: the axis rises until the
    // legend (about 18 px per line of a 440-px plot, a fraction `f` of the height) clears
    // the highest sail in the left half, (T − 1.15·top_left) ≥ f·(T + 1.1·bottom).
    let f = (18.0 * (groups.len() as f64 + 0.5) / 440.0).min(0.6);
    let half = first.x0 + 0.5 * (x1 - first.x0);
    let top_left = finite_max(groups.iter().flat_map(|g| {
        up(g)
            .into_iter()
            .enumerate()
            .filter(|&(i, _)| g.mean.x0 + i as f64 * g.mean.dx < half)
            .map(|(_, v)| v)
            .collect::<Vec<_>>()
    }))
    .max(0.0);
    let (x, y) = (
        Axis::new(first.x0, x1, "x (m), floe nose at 0"),
        Axis::new(
            -(bottom * 1.1),
            ((1.15 * top_left + f * 1.1 * bottom) / (1.0 - f)).max(top * 1.3),
            "sail height up, keel depth down (m)",
        ),
    );
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    let thin = layout.fonts.px(1.0);
    for (k, g) in groups.iter().enumerate() {
        let p = &g.mean;
        let c = COLORS[k % COLORS.len()];
        let steps = |vals: &[f64], sign: f64| -> Vec<(f64, f64)> {
            vals.iter()
                .enumerate()
                .flat_map(|(i, v)| {
                    let x = p.x0 + i as f64 * p.dx;
                    [(x, sign * v), (x + p.dx, sign * v)]
                })
                .collect()
        };
        for (mean, sd, sign) in [
            (&p.sail, &g.spread.sail, 1.0),
            (&p.keel, &g.spread.keel, -1.0),
        ] {
            let hi: Vec<f64> = mean.iter().zip(sd).map(|(m, s)| m + s).collect();
            let lo: Vec<f64> = mean.iter().zip(sd).map(|(m, s)| (m - s).max(0.0)).collect();
            let mut band = steps(&hi, sign);
            band.extend(steps(&lo, sign).into_iter().rev());
            chart
                .draw_series(std::iter::once(Polygon::new(band, c.mix(0.2).filled())))
                .map_err(draw_err)?;
        }
        chart
            .draw_series(LineSeries::new(steps(&p.sail, 1.0), c.stroke_width(line)))
            .map_err(draw_err)?
            .label(format!("{} {}", g.label, seeds(g.runs)))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
        chart
            .draw_series(LineSeries::new(steps(&p.keel, -1.0), c.stroke_width(line)))
            .map_err(draw_err)?;
        for (vals, sign) in [(&p.rubble_sail, 1.0), (&p.rubble_keel, -1.0)] {
            chart
                .draw_series(LineSeries::new(
                    steps(vals, sign),
                    c.mix(0.6).stroke_width(thin),
                ))
                .map_err(draw_err)?;
        }
    }
    chart
        .draw_series(LineSeries::new(
            [(first.x0, 0.0), (x1, 0.0)],
            RGBColor(30, 90, 160).stroke_width(thin),
        ))
        .map_err(draw_err)?;
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperLeft)
}

/// C_f (the final W/ΔPE) against sheet thickness: per set,
/// each run's value as a dot, the ensemble mean joined by a line with ± one standard
/// deviation over the seeds as whiskers, and CICE's default C_f = 17 dashed. The thickness
/// axis is logarithmic when the table spans a factor of [`CF_LOG_SPAN`] or more (the default
/// table's 0.10–6.00 m), so that the paper's range is not squeezed into its corner. PNG, or
/// SVG by the extension.
pub fn plot_cf(t: &RidgeTable, path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 560), draw_cf(t)))
}

/// Ratio of the largest to the smallest thickness from which [`plot_cf`] draws thickness on
/// a log axis (dimensionless).
pub const CF_LOG_SPAN: f64 = 10.0;

fn draw_cf<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    t: &RidgeTable,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let stat = |xs: &[f64]| crate::table::ensemble::Stat::of(xs);
    let hmin = t.thickness.first().copied().unwrap_or(0.0);
    let hmax = t.thickness.last().copied().unwrap_or(1.0);
    let cmax = finite_max(
        t.cf_finals
            .iter()
            .flatten()
            .copied()
            .chain(t.cf_finals.iter().map(|r| {
                let s = stat(r);
                s.mean + s.std
            }))
            .chain([17.0]),
    );
    let title =
        "C_f = W/ΔPE at the end of the runs against sheet thickness (× dashed: pooled fits)";
    let desc = "sheet thickness h (m)";
    let x = Axis::padded(hmin, hmax, desc, CF_LOG_SPAN);
    let y = Axis::new(0.0, cmax * 1.15, "C_f = W/ΔPE");
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    let dot = layout.fonts.px(3.0);
    let whisker = (x.hi - x.lo) * 0.012;
    let grey = RGBColor(90, 90, 90);
    chart
        .draw_series(DashedLineSeries::new(
            [(x.lo, 17.0), (x.hi, 17.0)],
            layout.fonts.px(8.0),
            layout.fonts.px(5.0),
            grey.stroke_width(layout.fonts.px(1.0)),
        ))
        .map_err(draw_err)?
        .label("C_f = 17 (CICE default)")
        .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], grey.stroke_width(1)));
    for (si, set) in t.sets.iter().enumerate() {
        let c = COLORS[si % COLORS.len()];
        let stats: Vec<(f64, crate::table::ensemble::Stat)> = t
            .thickness
            .iter()
            .zip(&t.cf_finals.row(si))
            .filter(|(_, r)| !r.is_empty())
            .map(|(h, r)| (*h, stat(r)))
            .collect();
        let n: usize = t.cf_finals.row(si).iter().map(Vec::len).max().unwrap_or(0);
        let name = if set.is_empty() {
            "ensemble mean".to_string()
        } else {
            set_display(set)
        };
        chart
            .draw_series(LineSeries::new(
                stats.iter().map(|(h, s)| (x.at(*h), s.mean)),
                c.stroke_width(line),
            ))
            .map_err(draw_err)?
            .label(format!("{name} ± 1 s.d. {}", seeds(n)))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
        for (h, s) in &stats {
            let (h, lo, hi) = (x.at(*h), s.mean - s.std, s.mean + s.std);
            chart
                .draw_series([
                    PathElement::new([(h, lo), (h, hi)], c.stroke_width(line)),
                    PathElement::new([(h - whisker, lo), (h + whisker, lo)], c.stroke_width(line)),
                    PathElement::new([(h - whisker, hi), (h + whisker, hi)], c.stroke_width(line)),
                ])
                .map_err(draw_err)?;
        }
        chart
            .draw_series(
                t.thickness
                    .iter()
                    .zip(&t.cf_finals.row(si))
                    .flat_map(|(h, r)| {
                        let h = x.at(*h);
                        r.iter().map(move |v| {
                            Circle::new((h + 2.0 * whisker, *v), dot, c.mix(0.6).filled())
                        })
                    }),
            )
            .map_err(draw_err)?;
        // The fit: W/ΔPE of the set's pooled fits, eqs (13)–(14), at each thickness's final
        // volume (the largest one its runs reached), dashed; a cross where the set has one
        // thickness.
        if let Some(f) = &t.pooled[si] {
            let fitted: Vec<(f64, f64)> = t
                .thickness
                .iter()
                .enumerate()
                .filter_map(|(hi, &h)| {
                    let v_end = t
                        .runs
                        .slice(s![si, hi, ..])
                        .iter()
                        .rposition(|&n| n > 0)
                        .map(|k| t.volume[k])?;
                    let r = f.work.eval(v_end) / f.potential_energy.eval(v_end);
                    (v_end > 0.0 && r.is_finite()).then_some((x.at(h), r))
                })
                .collect();
            let dash = c.stroke_width(layout.fonts.px(1.5));
            chart
                .draw_series(DashedLineSeries::new(
                    fitted.clone(),
                    layout.fonts.px(6.0),
                    layout.fonts.px(4.0),
                    dash,
                ))
                .map_err(draw_err)?;
            chart
                .draw_series(fitted.iter().map(|&(h, r)| {
                    Cross::new(
                        (h - 2.0 * whisker, r),
                        dot + 1,
                        c.stroke_width(layout.fonts.px(1.5)),
                    )
                }))
                .map_err(draw_err)?;
        }
    }
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperRight)
}

/// A set's label as a legend or title shows it: `mu=1, mu_w=0.6` becomes
/// `μ = 1, μ_w = 0.6`; the scene settings of the paper's sets read as quantities in the
/// paper's units (`sheet.e_top=400000000.0` as `E top = 0.4 GPa`, `floe.thickness=3.0` as
/// `floe 3 m`, `sheet.speed=0.0625` as `U = 6.25 cm/s`, `duration=1600.0` as `1600 s`);
/// other settings keep their key, with spaces around `=`.
pub fn set_display(set: &str) -> String {
    // (key, text before the value, scale from SI, unit)
    const NAMED: [(&str, &str, f64, &str); 7] = [
        ("sheet.e_top", "E top = ", 1e-9, " GPa"),
        ("sheet.e_bottom", "E bottom = ", 1e-9, " GPa"),
        ("floe.thickness", "floe ", 1.0, " m"),
        ("sheet.speed", "U = ", 100.0, " cm/s"),
        ("sheet.length", "sheet ", 1.0, " m"),
        ("sheet.thickness", "h = ", 1.0, " m"),
        ("duration", "", 1.0, " s"),
    ];
    set.split(", ")
        .map(|part| match part.split_once('=') {
            Some(("mu", v)) => format!("μ = {v}"),
            Some(("mu_w", v)) => format!("μ_w = {v}"),
            Some((k, v)) => match (NAMED.iter().find(|n| n.0 == k), v.parse::<f64>()) {
                // Four decimals of the scaled value: 2.67e8 Pa shows as 0.267 GPa.
                (Some((_, name, scale, unit)), Ok(x)) => {
                    format!("{name}{}{unit}", (x * scale * 1e4).round() / 1e4)
                }
                _ => format!("{k} = {v}"),
            },
            None => part.to_string(),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

#[cfg(test)]
mod tests {
    use super::set_display;

    #[test]
    fn set_labels_read_as_symbols() {
        assert_eq!(set_display("mu=1, mu_w=0.6"), "μ = 1, μ_w = 0.6");
        assert_eq!(
            set_display("mu=0.4, mu_w=0.3, sheet.youngs_modulus=1e8"),
            "μ = 0.4, μ_w = 0.3, sheet.youngs_modulus = 1e8"
        );
        assert_eq!(set_display(""), "");
        assert_eq!(
            set_display("mu=1, mu_w=0.6, sheet.e_top=400000000.0, sheet.e_bottom=267000000.0"),
            "μ = 1, μ_w = 0.6, E top = 0.4 GPa, E bottom = 0.267 GPa"
        );
        assert_eq!(
            set_display("mu=1, mu_w=0.6, sheet.speed=0.0625, duration=1600.0, floe.thickness=3.0"),
            "μ = 1, μ_w = 0.6, U = 6.25 cm/s, 1600 s, floe 3 m"
        );
        assert_eq!(set_display("sheet.speed=fast"), "sheet.speed = fast");
    }
}
