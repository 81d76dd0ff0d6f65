//! Energy budget against time (cf. Hopkins 1994, Figure 7).

use super::layout::{Axis, Layout};
use super::{PlotError, draw_err, write_figure};
use crate::energy::EnergyBudget;
use crate::simulation::Sample;
use plotters::prelude::*;
use std::path::Path;

/// Draws every ledger term against time into a PNG (or SVG, by the file extension), in kJ
/// per metre.
pub fn plot_energy(samples: &[Sample], path: &Path, title: &str) -> Result<(), PlotError> {
    write_figure(path, |tmp| plot_energy_at(samples, tmp, title))
}

/// [`plot_energy`] into the file `path` (a temporary file renamed by the caller).
fn plot_energy_at(samples: &[Sample], path: &Path, title: &str) -> Result<(), PlotError> {
    let series: Vec<EnergyBudget> = samples.iter().map(|s| s.energy).collect();
    let series = &series[..];
    let lines: [(&str, Getter, RGBColor); 10] = [
        ("work", |e| e.work, RGBColor(0, 0, 0)),
        ("ΔPE", |e| e.potential_energy, RGBColor(31, 119, 180)),
        (
            "friction Φ_f",
            |e| e.friction_dissipation,
            RGBColor(214, 39, 40),
        ),
        (
            "viscous Φ_i",
            |e| e.viscous_dissipation,
            RGBColor(44, 160, 44),
        ),
        ("drag", |e| e.drag_dissipation, RGBColor(148, 103, 189)),
        ("ΔKE", |e| e.kinetic_energy, RGBColor(255, 127, 14)),
        (
            "joints+fracture",
            |e| e.joint_dissipation + e.fracture_dissipation,
            RGBColor(23, 190, 207),
        ),
        (
            "boundary",
            |e| e.boundary_dissipation,
            RGBColor(188, 189, 34),
        ),
        ("elastic held", |e| e.elastic_energy, RGBColor(140, 86, 75)),
        ("residual", |e| e.residual, RGBColor(127, 127, 127)),
    ];
    let t1 = series.last().map_or(1.0, |e| e.time).max(1e-9);
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for e in series {
        for (_, f, _) in &lines {
            lo = lo.min(f(e) / 1e3);
            hi = hi.max(f(e) / 1e3);
        }
    }
    let pad = 0.05 * (hi - lo).max(1e-9);
    let (lo, hi) = (lo - pad, hi + pad);
    to_file!(
        path,
        (900, 560),
        draw_energy(series, &lines, title, t1, lo, hi)
    )
}

type Getter = fn(&EnergyBudget) -> f64;

fn draw_energy<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    series: &[EnergyBudget],
    lines: &[(&str, Getter, RGBColor)],
    title: &str,
    t1: f64,
    y0: f64,
    y1: f64,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let (x, y) = (
        Axis::new(0.0, t1, "time (s)"),
        Axis::new(y0, y1, "energy (kJ/m)"),
    );
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, title)?;
    let (line, key) = (layout.fonts.px(2.0), layout.fonts.px(18.0) as i32);
    for &(name, f, color) in lines {
        chart
            .draw_series(LineSeries::new(
                series.iter().map(|e| (e.time, f(e) / 1e3)),
                color.stroke_width(line),
            ))
            .map_err(draw_err)?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new([(x, y), (x + key, y)], color.stroke_width(line))
            });
    }
    layout.finish(&root, &mut chart, SeriesLabelPosition::UpperLeft)
}

/// Draws the ridging force of eq (9) against time (cf. Hopkins 1994, Figure 6) in kN per
/// metre, sampled at the scene's interval (0.2 s by default, as in the paper); PNG, or SVG
/// by the file extension.
pub fn plot_force(samples: &[Sample], path: &Path, title: &str) -> Result<(), PlotError> {
    write_figure(path, |tmp| plot_force_at(samples, tmp, title))
}

/// [`plot_force`] into the file `path` (a temporary file renamed by the caller).
fn plot_force_at(samples: &[Sample], path: &Path, title: &str) -> Result<(), PlotError> {
    let t1 = samples.last().map_or(1.0, |s| s.energy.time).max(1e-9);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for s in samples {
        lo = lo.min(s.ridging_force / 1e3);
        hi = hi.max(s.ridging_force / 1e3);
    }
    to_file!(path, (900, 420), draw_force(samples, title, t1, lo, hi))
}

fn draw_force<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    samples: &[Sample],
    title: &str,
    t1: f64,
    lo: f64,
    hi: f64,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let (x, y) = (
        Axis::new(0.0, t1, "time (s)"),
        Axis::new(lo, hi * 1.05, "ridging force (kN/m)"),
    );
    let (layout, mut chart) = Layout::canvas_chart(&root, &x, &y, title)?;
    chart
        .draw_series(LineSeries::new(
            samples
                .iter()
                .map(|s| (s.energy.time, s.ridging_force / 1e3)),
            RGBColor(31, 119, 180).stroke_width(layout.fonts.px(1.0)),
        ))
        .map_err(draw_err)?;
    root.present().map_err(draw_err)?;
    Ok(())
}
