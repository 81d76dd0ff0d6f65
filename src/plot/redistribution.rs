//! The thickness distribution of the simulated ridged ice, with the shapes host models
//! redistribute it by (`crate::table::redistribution`).

use super::layout::{Axis, Layout};
use super::{PlotError, draw_err, write_figure};
use crate::table::ensemble::Stat;
use crate::table::redistribution::{RidgedEnsemble, Setting};
use crate::table::tabulate::RidgeTable;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;

/// The ridged-ice thickness distribution of ensemble `e` at setting `k`: the pooled strips'
/// solid thickness as a probability density (bars, 1/m), the exponential and the uniform
/// fitted to it, and Lipscomb's exponential with Icepack's μ_rdg = 3 m^½.
pub fn plot_redistribution(k: &Setting, e: &RidgedEnsemble, path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 560), draw(k, e)))
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    k: &Setting,
    e: &RidgedEnsemble,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let f = &e.fit;
    let h = k.thickness;
    let top = e
        .pooled
        .ice
        .iter()
        .copied()
        .fold(f.h_max, f64::max)
        .max(f.h_min + 3.0 * f.lambda.max(0.0))
        * 1.05;
    let bins = 20usize;
    let width = top / bins as f64;
    let edges: Vec<f64> = (0..=bins).map(|i| i as f64 * width).collect();
    let density: Vec<f64> = e
        .pooled
        .histogram(&edges)
        .into_iter()
        .map(|p| p / width)
        .collect();
    let exponential = |x: f64, lambda: f64| {
        if x < f.h_min || lambda <= 0.0 {
            0.0
        } else {
            (-(x - f.h_min) / lambda).exp() / lambda
        }
    };
    let uniform_height = if f.h_max > f.h_min {
        1.0 / (f.h_max - f.h_min)
    } else {
        0.0
    };
    // Icepack's default μ_rdg (m^½), drawn for comparison.
    let icepack_mu_rdg = crate::itd::ItdParams::default().mu_rdg;
    let icepack_lambda = icepack_mu_rdg * h.sqrt();
    let ymax = density
        .iter()
        .copied()
        .chain([
            exponential(f.h_min, f.lambda),
            uniform_height,
            exponential(f.h_min, icepack_lambda),
        ])
        .filter(|x| x.is_finite())
        .fold(0.0, f64::max)
        * 1.15;
    let title = format!(
        "Ridged ice, h = {h} m, μ = {}, μ_w = {}: {} strips of {} runs",
        k.mu,
        k.mu_water,
        e.pooled.ice.len(),
        e.lambda.n
    );
    let x = Axis::new(0.0, top, "solid ridged-ice thickness H (m)");
    let y = Axis::new(0.0, ymax.max(1e-3), "probability density (1/m)");
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, &title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    let bar = RGBColor(150, 170, 200);
    chart
        .draw_series(
            edges
                .windows(2)
                .zip(&density)
                .map(|(w, d)| Rectangle::new([(w[0], 0.0), (w[1], *d)], bar.mix(0.7).filled())),
        )
        .map_err(draw_err)?
        .label(format!(
            "simulated, porosity {:.2}, mean H {:.2} m",
            e.pooled.porosity(),
            f.mean
        ))
        .legend(move |(x, y)| Rectangle::new([(x, y - 4), (x + key, y + 4)], bar.filled()));
    let n = 200;
    let curve = |lambda: f64| -> Vec<(f64, f64)> {
        (0..=n)
            .map(|i| {
                let xv = top * i as f64 / n as f64;
                (xv, exponential(xv, lambda))
            })
            .collect()
    };
    let blue = RGBColor(31, 119, 180);
    let orange = RGBColor(255, 127, 14);
    let grey = RGBColor(90, 90, 90);
    chart
        .draw_series(LineSeries::new(curve(f.lambda), blue.stroke_width(line)))
        .map_err(draw_err)?
        .label(format!(
            "exponential fit, μ_rdg = {:.2} m^½ (KS {:.2})",
            f.mu_rdg, f.ks_exponential
        ))
        .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], blue.stroke_width(2)));
    chart
        .draw_series(LineSeries::new(
            [
                (f.h_min, 0.0),
                (f.h_min, uniform_height),
                (f.h_max, uniform_height),
                (f.h_max, 0.0),
            ],
            orange.stroke_width(line),
        ))
        .map_err(draw_err)?
        .label(format!(
            "uniform fit, H* = {:.1} m (KS {:.2})",
            f.h_star, f.ks_uniform
        ))
        .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], orange.stroke_width(2)));
    chart
        .draw_series(DashedLineSeries::new(
            curve(icepack_lambda),
            layout.fonts.px(8.0),
            layout.fonts.px(5.0),
            grey.stroke_width(layout.fonts.px(1.5)),
        ))
        .map_err(draw_err)?
        .label(format!("Icepack default, μ_rdg = {icepack_mu_rdg} m^½"))
        .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], grey.stroke_width(1)));
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperRight)
}

/// Lipscomb's μ_rdg (m^½) of a ridging table's simulated ridged ice against the lead-ice
/// thickness (m), one curve per set: the mean of the runs' own fits with its 95 % interval
/// (Student t), beside Icepack's default 3 m^½ and the 4 m^½ its science guide gives. Thickness
/// on a log axis when the table spans [`super::table::CF_LOG_SPAN`] or more.
pub fn plot_mu_rdg(t: &RidgeTable, path: &Path) -> Result<(), PlotError> {
    write_figure(path, |tmp| to_file!(tmp, (900, 560), draw_mu_rdg(t)))
}

fn draw_mu_rdg<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    t: &RidgeTable,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let hmin = t.thickness.first().copied().unwrap_or(0.0);
    let hmax = t.thickness.last().copied().unwrap_or(1.0);
    let band = |s: &Stat| {
        let w = s.half_width_95();
        if w.is_finite() { w } else { 0.0 }
    };
    let top = t
        .ridged
        .iter()
        .flatten()
        .map(|e| e.mu_rdg.mean + band(&e.mu_rdg))
        .filter(|v| v.is_finite())
        .fold(4.0, f64::max);
    let desc = "lead-ice thickness h (m)";
    let x = Axis::padded(hmin, hmax, desc, super::table::CF_LOG_SPAN);
    let y = Axis::new(0.0, top * 1.2, "μ_rdg (m^½)");
    let title =
        "Lipscomb's μ_rdg of the simulated ridged ice (mean of the runs' fits, 95 % interval)";
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    let whisker = (x.hi - x.lo) * 0.012;
    let dot = layout.fonts.px(3.0);
    let grey = RGBColor(90, 90, 90);
    for (mu, what) in [(3.0, "Icepack default"), (4.0, "Icepack science guide")] {
        let dash = if mu == 3.0 { 8.0 } else { 3.0 };
        chart
            .draw_series(DashedLineSeries::new(
                [(x.lo, mu), (x.hi, mu)],
                layout.fonts.px(dash),
                layout.fonts.px(4.0),
                grey.stroke_width(layout.fonts.px(1.0)),
            ))
            .map_err(draw_err)?
            .label(format!("μ_rdg = {mu} m^½ ({what})"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], grey.stroke_width(1)));
    }
    for (si, set) in t.sets.iter().enumerate() {
        let points: Vec<(f64, &Stat)> = t
            .thickness
            .iter()
            .zip(t.ridged.row(si))
            .filter_map(|(h, e)| Some((x.at(*h), &e.as_ref()?.mu_rdg)))
            .filter(|(_, s)| s.mean.is_finite())
            .collect();
        if points.is_empty() {
            continue;
        }
        let c = super::table::COLORS[si % super::table::COLORS.len()];
        let runs = points.iter().map(|(_, s)| s.n).max().unwrap_or(0);
        let name = if set.is_empty() {
            "simulated".to_string()
        } else {
            super::table::set_display(set)
        };
        chart
            .draw_series(LineSeries::new(
                points.iter().map(|(h, s)| (*h, s.mean)),
                c.stroke_width(line),
            ))
            .map_err(draw_err)?
            .label(format!("{name} {}", super::table::seeds(runs)))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
        for (h, s) in &points {
            let (lo, hi) = (s.mean - band(s), s.mean + band(s));
            chart
                .draw_series([
                    PathElement::new([(*h, lo), (*h, hi)], c.stroke_width(line)),
                    PathElement::new([(h - whisker, lo), (h + whisker, lo)], c.stroke_width(line)),
                    PathElement::new([(h - whisker, hi), (h + whisker, hi)], c.stroke_width(line)),
                ])
                .map_err(draw_err)?;
            chart
                .draw_series([Circle::new((*h, s.mean), dot, c.filled())])
                .map_err(draw_err)?;
        }
    }
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperRight)
}
