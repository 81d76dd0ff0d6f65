//! Maps of ice strength P (N/m) on a 2-D grid, one panel per field, with a shared colour
//! scale and colour bar.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::layout::{Axis, Fonts, Layout, TICKS, text_size};
use super::{PlotError, draw_err, write_figure};

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

/// Default width of a strength-map figure of `panels` panels (px): 500 per panel and 160 for
/// the colour bar.
pub fn default_width(panels: usize) -> u32 {
    500 * panels.max(1) as u32 + 160
}

/// Draws the panels side by side into `path` (PNG, or SVG by the extension), `width_px`
/// wide, colour scale 0 ..= max over all panels (kN/m on the colour bar). Fonts scale with
/// the width (14-px tick labels at 900 px); the height follows the grid's aspect ratio.
/// `ny`, `nx`: grid shape.
pub fn draw_strength_maps(
    path: &Path,
    panels: &[Panel<'_>],
    ny: usize,
    nx: usize,
    width_px: u32,
) -> Result<(), PlotError> {
    write_figure(path, |tmp| {
        draw_strength_maps_at(tmp, panels, ny, nx, width_px)
    })
}

/// Where the panels and the colour bar of a strength-map figure go (px).
struct MapLayout {
    /// Canvas size.
    size: (u32, u32),
    /// Width of the colour bar's column.
    bar_w: u32,
    /// The layout of one map panel (all alike).
    panel: Layout,
    /// Axes of a panel: grid index i and j.
    x: Axis,
    y: Axis,
}

impl MapLayout {
    fn new(n: usize, ny: usize, nx: usize, width_px: u32) -> MapLayout {
        let fonts = Fonts::for_width(width_px);
        let bar_w = fonts.px(160.0);
        let panel_w = width_px.saturating_sub(bar_w) / n as u32;
        let x = Axis::new(0.0, nx as f64, "grid index i");
        let y = Axis::new(0.0, ny as f64, "grid index j");
        let probe = Layout::with_fonts(panel_w, fonts, &x, &y, "title");
        let plot_h = (probe.plot_width() as f64 * ny as f64 / nx as f64).round() as u32;
        let panel = probe.with_plot_height(plot_h.max(fonts.px(40.0)));
        MapLayout {
            size: (panel_w * n as u32 + bar_w, panel.height),
            bar_w,
            panel,
            x,
            y,
        }
    }
}

/// [`draw_strength_maps`] into the file `path` (a temporary file renamed by the caller).
fn draw_strength_maps_at(
    path: &Path,
    panels: &[Panel<'_>],
    ny: usize,
    nx: usize,
    width_px: u32,
) -> Result<(), PlotError> {
    if panels.is_empty() || ny == 0 || nx == 0 {
        return Err(PlotError::Draw("nothing to draw".into()));
    }
    if !(200..=20_000).contains(&width_px) {
        return Err(PlotError::Draw(format!(
            "--width must be 200 to 20000 px, not {width_px}"
        )));
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
    let m = MapLayout::new(panels.len(), ny, nx, width_px);
    to_file!(path, m.size, draw_maps(&m, panels, ny, nx))
}

fn draw_maps<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    m: &MapLayout,
    panels: &[Panel<'_>],
    ny: usize,
    nx: usize,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let vmax = panels
        .iter()
        .flat_map(|p| p.values.iter().copied())
        .filter(|v| v.is_finite())
        .fold(0.0f64, f64::max)
        .max(1e-9);
    root.fill(&WHITE).map_err(draw_err)?;
    let (maps, bar) = root.split_horizontally(m.size.0 - m.bar_w);
    let areas = maps.split_evenly((1, panels.len()));
    for (area, p) in areas.iter().zip(panels) {
        let mut chart = m.panel.chart(area, &m.x, &m.y, p.title, false)?;
        chart
            .draw_series((0..ny).flat_map(|j| {
                (0..nx).map(move |i| {
                    let v = p.values[j * nx + i];
                    let color = if v.is_finite() {
                        colormap(v / vmax)
                    } else {
                        RGBColor(160, 160, 160)
                    };
                    let (x, y) = (i as f64, j as f64);
                    Rectangle::new([(x, y), (x + 1.0, y + 1.0)], color.filled())
                })
            }))
            .map_err(draw_err)?;
    }
    // Colour bar: as high as a panel's plot area, its scale on the right.
    let f = m.panel.fonts;
    let top_k = vmax / 1e3;
    let scale = Axis::new(0.0, top_k, "P (kN/m)");
    let tick_w = scale
        .labels()
        .iter()
        .map(|l| text_size(l, f.tick).0)
        .max()
        .unwrap_or(0);
    let mut cb = ChartBuilder::on(&bar)
        .margin_top(m.panel.top)
        .margin_bottom(m.panel.bottom)
        .margin_left(f.px(12.0))
        .margin_right(f.px(8.0) + m.panel.desc_height + m.panel.pad)
        .right_y_label_area_size(tick_w + 3 * m.panel.tick_mark)
        .build_cartesian_2d(0.0..1.0, 0.0..top_k)
        .map_err(draw_err)?;
    let fmt = scale.format;
    let yf = move |v: &f64| fmt.label(*v);
    cb.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_labels(TICKS)
        .y_label_formatter(&yf)
        .set_all_tick_mark_size(m.panel.tick_mark)
        .axis_style(BLACK.stroke_width(f.px(1.0)))
        .label_style(("sans-serif", f.tick))
        .draw()
        .map_err(draw_err)?;
    let steps = 100;
    cb.draw_series((0..steps).map(|k| {
        let y0 = top_k * k as f64 / steps as f64;
        let y1 = top_k * (k + 1) as f64 / steps as f64;
        Rectangle::new(
            [(0.0, y0), (1.0, y1)],
            colormap((k as f64 + 0.5) / steps as f64).filled(),
        )
    }))
    .map_err(draw_err)?;
    // The bar's description, rotated, at the right edge.
    let style = TextStyle::from(("sans-serif", f.label).into_font())
        .transform(FontTransform::Rotate90)
        .pos(Pos::new(HPos::Center, VPos::Center));
    let x = (m.bar_w - m.panel.pad - m.panel.desc_height / 2) as i32;
    let y = (m.panel.top + m.panel.plot_height() / 2) as i32;
    bar.draw_text(&scale.desc, &style, (x, y))
        .map_err(draw_err)?;
    root.present().map_err(draw_err)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest `font-size` of an SVG (px).
    fn largest_font(svg: &str) -> f64 {
        svg.split("font-size=\"")
            .skip(1)
            .filter_map(|s| s.split('"').next()?.parse::<f64>().ok())
            .fold(0.0, f64::max)
    }

    /// Twice the width, twice the fonts; the canvas as wide as asked (to the panel
    /// rounding) and as high as the grid's aspect needs; SVG by the extension.
    #[test]
    fn fonts_scale_with_the_width_and_svg_by_extension() {
        let (ny, nx) = (6, 8);
        let v: Vec<f64> = (0..ny * nx).map(|k| 1e3 * k as f64).collect();
        let panels = [
            Panel {
                title: "a",
                values: &v,
            },
            Panel {
                title: "b",
                values: &v,
            },
        ];
        let dir = std::env::temp_dir().join(format!("pressridge-map-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut fonts = Vec::new();
        for w in [900, 1800] {
            let p = dir.join(format!("m{w}.svg"));
            draw_strength_maps(&p, &panels, ny, nx, w).unwrap();
            let svg = std::fs::read_to_string(&p).unwrap();
            assert!(svg.starts_with("<svg"), "not an SVG");
            fonts.push(largest_font(&svg));
            let m = MapLayout::new(2, ny, nx, w);
            assert!(m.size.0 <= w && m.size.0 + 2 >= w, "{:?}", m.size);
            let aspect = m.panel.plot_height() as f64 / m.panel.plot_width() as f64;
            assert!((aspect - 0.75).abs() < 0.02, "plot aspect {aspect}");
        }
        assert!((fonts[1] / fonts[0] - 2.0).abs() < 0.05, "{fonts:?}");
        let bad = draw_strength_maps(&dir.join("x.png"), &panels, ny, nx, 10);
        assert!(bad.unwrap_err().to_string().contains("--width"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
