//! Figures of a tabulated campaign (cf. Hopkins 1994, Figures 8–12).

use super::layout::{Axis, Layout};
use super::{PlotError, draw_err, ensure_font};
use crate::observe::Profile;
use crate::table::tabulate::RidgeTable;
use plotters::prelude::*;
use std::path::Path;

const COLORS: [RGBColor; 8] = [
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

/// Work against ridged volume for set `s` (cf. Figures 9, 11, 12): the ensemble mean of each
/// thickness, the pooled fit of eq (13) and its 95 % confidence and prediction bands, in MJ/m.
pub fn plot_work(t: &RidgeTable, s: usize, path: &Path) -> Result<(), PlotError> {
    crate::io::write_atomic_with(path, |tmp| plot_work_at(t, s, tmp)).map_err(|e| e.at(path))
}

/// [`plot_work`] into the file `path` (a temporary file renamed by the caller).
fn plot_work_at(t: &RidgeTable, s: usize, path: &Path) -> Result<(), PlotError> {
    ensure_font()?;
    let vmax = t.volume.last().copied().unwrap_or(1.0).max(1e-9);
    let band = t.work_band[s].as_ref();
    let wmax = finite_max(
        t.work_mean[s]
            .iter()
            .flatten()
            .copied()
            .chain(band.into_iter().flat_map(|b| b.pred_hi.iter().copied())),
    ) / 1e6;
    let root = BitMapBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(draw_err)?;
    let title = if t.sets[s].is_empty() {
        "work against ridged volume".to_string()
    } else {
        format!("work against ridged volume ({})", t.sets[s])
    };
    let (x, y) = (
        Axis::new(0.0, vmax, "ridged volume V (m³/m)"),
        Axis::new(0.0, (wmax * 1.05).max(1e-9), "work (MJ/m)"),
    );
    let layout = Layout::new(900, &x, &y, &title).with_height(600);
    let mut chart = layout.chart(&root, &x, &y, &title, true)?;
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
        chart
            .draw_series(std::iter::once(Polygon::new(
                area(&b.pred_lo, &b.pred_hi),
                RGBColor(200, 200, 200).mix(0.5).filled(),
            )))
            .map_err(draw_err)?
            .label("95 % prediction band")
            .legend(move |(x, y)| {
                Rectangle::new(
                    [(x, y - key / 4), (x + key, y + key / 4)],
                    RGBColor(200, 200, 200).filled(),
                )
            });
        chart
            .draw_series(std::iter::once(Polygon::new(
                area(&b.conf_lo, &b.conf_hi),
                RGBColor(120, 120, 120).mix(0.6).filled(),
            )))
            .map_err(draw_err)?
            .label("95 % confidence band")
            .legend(move |(x, y)| {
                Rectangle::new(
                    [(x, y - key / 4), (x + key, y + key / 4)],
                    RGBColor(120, 120, 120).filled(),
                )
            });
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
        let pts: Vec<(f64, f64)> = t
            .volume
            .iter()
            .zip(&t.work_mean[s][hi])
            .filter(|(_, w)| w.is_finite())
            .map(|(v, w)| (*v, w / 1e6))
            .collect();
        chart
            .draw_series(LineSeries::new(pts, c.stroke_width(line)))
            .map_err(draw_err)?
            .label(format!("h = {th:.2} m, ensemble mean"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", layout.fonts.legend))
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(draw_err)?;
    root.present().map_err(draw_err)?;
    Ok(())
}

/// Ridging force against volume for set `s`: eq (15) from the pooled fit per thickness
/// (lines) and the ensemble mean of the runs' interval-mean force (dots), in kN/m.
pub fn plot_force(t: &RidgeTable, s: usize, path: &Path) -> Result<(), PlotError> {
    crate::io::write_atomic_with(path, |tmp| plot_force_at(t, s, tmp)).map_err(|e| e.at(path))
}

/// [`plot_force`] into the file `path` (a temporary file renamed by the caller).
fn plot_force_at(t: &RidgeTable, s: usize, path: &Path) -> Result<(), PlotError> {
    ensure_font()?;
    let vmax = t.volume.last().copied().unwrap_or(1.0).max(1e-9);
    let fmax = finite_max(
        t.force_fit[s]
            .iter()
            .chain(t.force_mean[s].iter())
            .flatten()
            .copied(),
    ) / 1e3;
    let root = BitMapBackend::new(path, (900, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(draw_err)?;
    let title = "ridging force against volume and thickness";
    let (x, y) = (
        Axis::new(0.0, vmax, "ridged volume V (m³/m)"),
        Axis::new(0.0, (fmax * 1.05).max(1e-9), "force (kN/m)"),
    );
    let layout = Layout::new(900, &x, &y, title).with_height(520);
    let mut chart = layout.chart(&root, &x, &y, title, true)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    for (hi, th) in t.thickness.iter().enumerate() {
        let c = COLORS[hi % COLORS.len()];
        chart
            .draw_series(LineSeries::new(
                t.volume
                    .iter()
                    .zip(&t.force_fit[s][hi])
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
                    .zip(&t.force_mean[s][hi])
                    .filter(|(_, f)| f.is_finite())
                    .map(|(v, f)| Circle::new((*v, f / 1e3), 3, c.filled())),
            )
            .map_err(draw_err)?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", layout.fonts.legend))
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(draw_err)?;
    root.present().map_err(draw_err)?;
    Ok(())
}

/// Averaged final profiles (cf. Figures 8 and 10): mean sail height up and keel depth down
/// in 1-m strips, one colour per label, all ice (solid) and rubble alone (dashed look: thin).
pub fn plot_profiles(profiles: &[(String, Profile)], path: &Path) -> Result<(), PlotError> {
    crate::io::write_atomic_with(path, |tmp| plot_profiles_at(profiles, tmp))
        .map_err(|e| e.at(path))
}

/// [`plot_profiles`] into the file `path` (a temporary file renamed by the caller).
fn plot_profiles_at(profiles: &[(String, Profile)], path: &Path) -> Result<(), PlotError> {
    ensure_font()?;
    let Some((_, first)) = profiles.first() else {
        return Ok(());
    };
    let x1 = first.x0 + first.dx * first.sail.len() as f64;
    let top = finite_max(profiles.iter().flat_map(|(_, p)| p.sail.iter().copied())).max(1.0);
    let bottom = finite_max(profiles.iter().flat_map(|(_, p)| p.keel.iter().copied())).max(1.0);
    let root = BitMapBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(draw_err)?;
    let title = "averaged final profiles (1-m strips)";
    let (x, y) = (
        Axis::new(first.x0, x1, "x (m), floe nose at 0"),
        Axis::new(-(bottom * 1.1), top * 1.8, "height (m)"),
    );
    let layout = Layout::new(900, &x, &y, title).with_height(560);
    let mut chart = layout.chart(&root, &x, &y, title, true)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    for (k, (label, p)) in profiles.iter().enumerate() {
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
        chart
            .draw_series(LineSeries::new(steps(&p.sail, 1.0), c.stroke_width(line)))
            .map_err(draw_err)?
            .label(label.clone())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + key, y)], c.stroke_width(line)));
        chart
            .draw_series(LineSeries::new(steps(&p.keel, -1.0), c.stroke_width(line)))
            .map_err(draw_err)?;
        chart
            .draw_series(LineSeries::new(
                steps(&p.rubble_sail, 1.0),
                c.mix(0.5).stroke_width(1),
            ))
            .map_err(draw_err)?;
        chart
            .draw_series(LineSeries::new(
                steps(&p.rubble_keel, -1.0),
                c.mix(0.5).stroke_width(1),
            ))
            .map_err(draw_err)?;
    }
    chart
        .draw_series(LineSeries::new(
            [(first.x0, 0.0), (x1, 0.0)],
            RGBColor(30, 90, 160),
        ))
        .map_err(draw_err)?;
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", layout.fonts.legend))
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(draw_err)?;
    root.present().map_err(draw_err)?;
    Ok(())
}
