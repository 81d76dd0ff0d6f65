//! Maps of ice strength P (N/m) on a 2-D grid, one panel per field, with a shared colour
//! scale and colour bar.

use std::path::Path;

use plotters::prelude::*;

use super::{PlotError, draw_err, ensure_font};

/// One panel: a title and `ny × nx` values in C order (row `j` = grid row, `x` fastest).
/// Non-finite values are drawn grey.
#[derive(Debug, Clone, Copy)]
pub struct Panel<'a> {
    /// Panel title.
    pub title: &'a str,
    /// Values (N/m), length `ny * nx`.
    pub values: &'a [f64],
}

/// Viridis-like colour for t in [0, 1] (piecewise-linear through five anchors).
fn colormap(t: f64) -> RGBColor {
    const ANCHORS: [(f64, [f64; 3]); 5] = [
        (0.0, [68.0, 1.0, 84.0]),
        (0.25, [59.0, 82.0, 139.0]),
        (0.5, [33.0, 145.0, 140.0]),
        (0.75, [94.0, 201.0, 98.0]),
        (1.0, [253.0, 231.0, 37.0]),
    ];
    let t = t.clamp(0.0, 1.0);
    let k = ANCHORS.iter().position(|a| a.0 >= t).unwrap_or(4).max(1);
    let (t0, c0) = ANCHORS[k - 1];
    let (t1, c1) = ANCHORS[k];
    let w = (t - t0) / (t1 - t0);
    let ch = |i: usize| (c0[i] + w * (c1[i] - c0[i])).round() as u8;
    RGBColor(ch(0), ch(1), ch(2))
}

/// Draws the panels side by side into a PNG at `path`, colour scale 0 ..= max over all panels
/// (kN/m on the colour bar). `ny`, `nx`: grid shape.
pub fn draw_strength_maps(
    path: &Path,
    panels: &[Panel<'_>],
    ny: usize,
    nx: usize,
) -> Result<(), PlotError> {
    crate::io::write_atomic_with(path, |tmp| draw_strength_maps_at(tmp, panels, ny, nx))
        .map_err(|e| e.at(path))
}

/// [`draw_strength_maps`] into the file `path` (a temporary file renamed by the caller).
fn draw_strength_maps_at(
    path: &Path,
    panels: &[Panel<'_>],
    ny: usize,
    nx: usize,
) -> Result<(), PlotError> {
    ensure_font()?;
    if panels.is_empty() || ny == 0 || nx == 0 {
        return Err(PlotError::Draw("nothing to draw".into()));
    }
    for p in panels {
        if p.values.len() != ny * nx {
            return Err(PlotError::Draw(format!(
                "panel `{}` has {} values, grid is {ny} x {nx}",
                p.title,
                p.values.len()
            )));
        }
    }
    let vmax = panels
        .iter()
        .flat_map(|p| p.values.iter().copied())
        .filter(|v| v.is_finite())
        .fold(0.0f64, f64::max)
        .max(1e-9);
    let panel_w = 420u32;
    let panel_h = (panel_w as f64 * ny as f64 / nx as f64) as u32 + 60;
    let bar_w = 110u32;
    let width = panel_w * panels.len() as u32 + bar_w;
    let root = BitMapBackend::new(path, (width, panel_h + 10)).into_drawing_area();
    root.fill(&WHITE).map_err(draw_err)?;
    let (maps, bar) = root.split_horizontally(panel_w * panels.len() as u32);
    let areas = maps.split_evenly((1, panels.len()));
    for (area, p) in areas.iter().zip(panels) {
        let mut chart = ChartBuilder::on(area)
            .caption(p.title, ("sans-serif", 18))
            .margin(8)
            .x_label_area_size(22)
            .y_label_area_size(30)
            .build_cartesian_2d(0..nx, 0..ny)
            .map_err(draw_err)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("i")
            .y_desc("j")
            .label_style(("sans-serif", 11))
            .draw()
            .map_err(draw_err)?;
        chart
            .draw_series((0..ny).flat_map(|j| {
                (0..nx).map(move |i| {
                    let v = p.values[j * nx + i];
                    let color = if v.is_finite() {
                        colormap(v / vmax)
                    } else {
                        RGBColor(160, 160, 160)
                    };
                    Rectangle::new([(i, j), (i + 1, j + 1)], color.filled())
                })
            }))
            .map_err(draw_err)?;
    }
    // Colour bar.
    let mut cb = ChartBuilder::on(&bar)
        .caption("P (kN/m)", ("sans-serif", 14))
        .margin(12)
        .margin_right(50)
        .y_label_area_size(0)
        .right_y_label_area_size(40)
        .build_cartesian_2d(0.0..1.0, 0.0..vmax / 1e3)
        .map_err(draw_err)?;
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .label_style(("sans-serif", 11))
        .draw()
        .map_err(draw_err)?;
    let steps = 100;
    cb.draw_series((0..steps).map(|k| {
        let y0 = vmax / 1e3 * k as f64 / steps as f64;
        let y1 = vmax / 1e3 * (k + 1) as f64 / steps as f64;
        Rectangle::new(
            [(0.0, y0), (1.0, y1)],
            colormap((k as f64 + 0.5) / steps as f64).filled(),
        )
    }))
    .map_err(draw_err)?;
    root.present().map_err(draw_err)?;
    Ok(())
}
