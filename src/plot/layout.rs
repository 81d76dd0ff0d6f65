//! Figure layout: font sizes that scale with the figure, margins computed from the text
//! they must hold, tick labels with a sensible number of decimals.
//!
//! Every figure of [`super`] is drawn through a [`Layout`]: the fonts are a fixed fraction
//! of the figure's width ([`Fonts::for_width`]: 14-px tick labels at 900 px, 28 px at
//! 1800 px, never below [`MIN_TICK_PX`]), so a figure drawn larger is the same figure at a
//! finer resolution, as a paper's figure is. The margins around the plot area are measured
//! from the tick labels the axes will carry and the axis descriptions
//! ([`Layout::new`]), so no label is clipped at the canvas edge and none overprints another,
//! whatever the size. Titles and axis descriptions are drawn here ([`Layout::draw_text`]),
//! not by plotters, whose rotated y-axis description sat half outside the canvas.

use super::{PlotError, draw_err};
use plotters::coord::Shift;
use plotters::coord::ranged1d::Ranged;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A chart with linear f64 axes, as every figure draws.
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Reference figure width (px) at which the base font sizes apply.
pub const REFERENCE_WIDTH: f64 = 900.0;
/// Smallest tick-label font (px): below it text stops being legible on screen.
pub const MIN_TICK_PX: f64 = 9.0;
/// Colour of the grid lines at the ticks.
const GRID: RGBColor = RGBColor(215, 215, 215);
/// Number of ticks asked of an axis (plotters takes it as an upper bound).
pub const TICKS: usize = 8;

/// Font sizes (px) of one figure.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fonts {
    /// Title.
    pub title: f64,
    /// Axis descriptions ("x (m)").
    pub label: f64,
    /// Tick labels.
    pub tick: f64,
    /// Legend entries.
    pub legend: f64,
    /// Scale against the reference width (dimensionless): also the unit of line widths,
    /// tick marks and paddings.
    pub scale: f64,
}

impl Fonts {
    /// The fonts of a figure `width_px` wide: 18/15/14/13 px (title, axis, ticks, legend) at
    /// [`REFERENCE_WIDTH`], proportional to the width, the tick font at least
    /// [`MIN_TICK_PX`] (the others keep their ratio to it).
    pub fn for_width(width_px: u32) -> Fonts {
        let scale = (width_px as f64 / REFERENCE_WIDTH).max(MIN_TICK_PX / 14.0);
        Fonts {
            title: 18.0 * scale,
            label: 15.0 * scale,
            tick: 14.0 * scale,
            legend: 13.0 * scale,
            scale,
        }
    }

    /// A length of `px` pixels at the reference width, scaled (at least 1 px).
    pub fn px(&self, px: f64) -> u32 {
        (px * self.scale).round().max(1.0) as u32
    }
}

/// Tick positions plotters draws on an axis from `lo` to `hi` with [`TICKS`] asked.
pub fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo {
        return Vec::new();
    }
    RangedCoordf64::from(lo..hi).key_points(TICKS)
}

/// Decimals a tick label needs on an axis whose ticks are `step` apart: none for a step of
/// 1 or more, one for 0.5, two for 0.25 or 0.05, at most 6.
pub fn decimals(step: f64) -> usize {
    if !(step.is_finite() && step > 0.0) {
        return 0;
    }
    for d in 0..=6 {
        let scaled = step * 10f64.powi(d as i32);
        if (scaled - scaled.round()).abs() < 1e-6 * scaled.max(1.0) {
            return d;
        }
    }
    6
}

/// The tick labels of an axis from `lo` to `hi`: all with the same number of decimals, the
/// fewest the tick step needs (`0.0, 0.5, 1.0`; `0, 200, 400`), never `-0`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TickFormat {
    /// Decimals shown.
    pub decimals: usize,
}

impl TickFormat {
    /// The format of an axis from `lo` to `hi`.
    pub fn of(lo: f64, hi: f64) -> TickFormat {
        let t = ticks(lo, hi);
        let step = t
            .windows(2)
            .map(|w| (w[1] - w[0]).abs())
            .fold(f64::INFINITY, f64::min);
        let decimals = if step.is_finite() {
            decimals(step)
        } else {
            t.first().map_or(0, |v| decimals(v.abs()))
        };
        TickFormat { decimals }
    }

    /// The label of `v`.
    pub fn label(&self, v: f64) -> String {
        let s = format!("{v:.*}", self.decimals);
        if s.trim_start_matches('-')
            .chars()
            .all(|c| c == '0' || c == '.')
        {
            s.trim_start_matches('-').to_string()
        } else {
            s
        }
    }
}

/// One axis: its range, its description and the format of its tick labels.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    /// Lower end (axis units).
    pub lo: f64,
    /// Upper end (axis units).
    pub hi: f64,
    /// Description with units, e.g. `"x (m)"`.
    pub desc: String,
    /// Tick-label format.
    pub format: TickFormat,
    /// Logarithmic: `lo`, `hi` and the data drawn on it are log10 of the quantity, and the
    /// ticks are the quantity's 1, 2, 5 × 10^k ([`log_ticks`]).
    pub log: bool,
}

impl Axis {
    /// An axis from `lo` to `hi` described by `desc`.
    pub fn new(lo: f64, hi: f64, desc: &str) -> Axis {
        Axis {
            lo,
            hi,
            desc: desc.to_string(),
            format: TickFormat::of(lo, hi),
            log: false,
        }
    }

    /// A logarithmic axis from `lo` to `hi` (> 0, in the quantity's units) described by
    /// `desc`: its coordinate is log10 of the quantity ([`Axis::at`]).
    pub fn log10(lo: f64, hi: f64, desc: &str) -> Axis {
        let (lo, hi) = (lo.log10(), hi.log10());
        Axis {
            lo,
            hi,
            desc: desc.to_string(),
            format: TickFormat::of(lo, hi),
            log: true,
        }
    }

    /// An axis over the data range `lo..=hi` (in the quantity's units) with a tenth of the
    /// span as margin on each side: logarithmic when `lo > 0` and `hi ≥ log_span·lo`,
    /// linear (not below 0) otherwise.
    pub fn padded(lo: f64, hi: f64, desc: &str, log_span: f64) -> Axis {
        if lo > 0.0 && hi >= log_span * lo {
            let pad = 0.1 * (hi / lo).log10();
            Axis::log10(lo / 10f64.powf(pad), hi * 10f64.powf(pad), desc)
        } else {
            let pad = 0.1 * (hi - lo).max(0.1);
            Axis::new((lo - pad).max(0.0), hi + pad, desc)
        }
    }

    /// The coordinate of the quantity `v` on this axis: `v`, or log10 `v` on a log axis.
    pub fn at(&self, v: f64) -> f64 {
        if self.log { v.log10() } else { v }
    }

    /// The tick labels it will carry.
    pub fn labels(&self) -> Vec<String> {
        if self.log {
            return log_ticks(self.lo, self.hi)
                .into_iter()
                .map(log_label)
                .collect();
        }
        ticks(self.lo, self.hi)
            .into_iter()
            .map(|v| self.format.label(v))
            .collect()
    }
}

/// The ticks of a log axis from 10^`lo` to 10^`hi` (values of the quantity, not their logs):
/// 1, 2 and 5 × 10^k within the range.
pub fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo {
        return Vec::new();
    }
    let eps = 1e-9 * (hi - lo);
    (lo.floor() as i32..=hi.ceil() as i32)
        .flat_map(|k| [1.0, 2.0, 5.0].map(|m| m * 10f64.powi(k)))
        .filter(|v| (lo - eps..=hi + eps).contains(&v.log10()))
        .collect()
}

/// A log-axis tick's label: the value with the decimals it needs (`0.1`, `2`, `50`).
fn log_label(v: f64) -> String {
    format!("{v:.*}", decimals(v))
}

/// Width and height (px) of `text` in the sans-serif font at `size` px (an estimate of
/// `size`-based boxes when no font is registered).
pub fn text_size(text: &str, size: f64) -> (u32, u32) {
    let font = ("sans-serif", size).into_font();
    match font.box_size(text) {
        Ok((w, h)) => (w, h.max(size.round() as u32)),
        Err(_) => (
            (0.6 * size * text.chars().count() as f64).ceil() as u32,
            size.round() as u32,
        ),
    }
}

/// Where everything of a one-chart figure goes (px).
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Canvas width.
    pub width: u32,
    /// Canvas height.
    pub height: u32,
    /// Fonts.
    pub fonts: Fonts,
    /// Margins around the plot area: left (y tick labels and description), bottom (x tick
    /// labels and description), top (title), right (half the last x tick label).
    pub left: u32,
    /// See `left`.
    pub bottom: u32,
    /// See `left`.
    pub top: u32,
    /// See `left`.
    pub right: u32,
    /// Tick-mark length.
    pub tick_mark: u32,
    /// Gap between a tick mark and its label (plotters draws labels at twice the tick mark).
    pub pad: u32,
    /// Widest y tick label.
    pub y_tick_width: u32,
    /// Height of the tallest x tick label.
    pub x_tick_height: u32,
    /// Height of the axis-description line.
    pub desc_height: u32,
    /// Height of the title line (0 without a title).
    pub title_height: u32,
}

impl Layout {
    /// The margins of a figure `width` wide with axes `x` and `y` and a title (empty: none);
    /// the height is set by [`Layout::with_height`] or [`Layout::with_plot_height`].
    pub fn new(width: u32, x: &Axis, y: &Axis, title: &str) -> Layout {
        Layout::with_fonts(width, Fonts::for_width(width), x, y, title)
    }

    /// As [`Layout::new`] for one chart `width` px wide of a larger figure whose fonts are
    /// `fonts` (a row of panels keeps the fonts of the whole figure).
    pub fn with_fonts(width: u32, fonts: Fonts, x: &Axis, y: &Axis, title: &str) -> Layout {
        let tick_mark = fonts.px(5.0);
        let pad = fonts.px(8.0);
        let y_tick_width = y
            .labels()
            .iter()
            .map(|l| text_size(l, fonts.tick).0)
            .max()
            .unwrap_or(0);
        let x_labels = x.labels();
        let x_tick_height = (fonts.tick * 1.2).ceil() as u32;
        let last_half = x_labels
            .last()
            .map_or(0, |l| text_size(l, fonts.tick).0.div_ceil(2));
        let desc_height = (fonts.label * 1.25).ceil() as u32;
        let title_height = if title.is_empty() {
            0
        } else {
            (fonts.title * 1.3).ceil() as u32
        };
        // Labels start 2 tick marks from the axis (plotters' label distance).
        let label_dist = 2 * tick_mark;
        Layout {
            width,
            height: 0,
            fonts,
            left: pad + desc_height + pad + y_tick_width + label_dist,
            bottom: label_dist + x_tick_height + pad + desc_height + pad,
            top: pad + title_height + pad,
            right: (last_half + pad).max(fonts.px(20.0)),
            tick_mark,
            pad,
            y_tick_width,
            x_tick_height,
            desc_height,
            title_height,
        }
    }

    /// With the canvas `height` px high.
    pub fn with_height(mut self, height: u32) -> Layout {
        self.height = height;
        self
    }

    /// With the canvas as high as a plot area of `plot_height` px needs.
    pub fn with_plot_height(mut self, plot_height: u32) -> Layout {
        self.height = plot_height + self.top + self.bottom;
        self
    }

    /// Width of the plot area (px).
    pub fn plot_width(&self) -> u32 {
        self.width.saturating_sub(self.left + self.right)
    }

    /// Height of the plot area (px).
    pub fn plot_height(&self) -> u32 {
        self.height.saturating_sub(self.top + self.bottom)
    }

    /// The x range of the y-axis description's line (px from the left edge) and of the y
    /// tick labels: the first ends before the second starts. For the figure tests.
    #[cfg(test)]
    pub fn y_columns(&self) -> ((u32, u32), (u32, u32)) {
        let desc = (self.pad, self.pad + self.desc_height);
        let ticks_end = self.left - 2 * self.tick_mark;
        (desc, (ticks_end - self.y_tick_width, ticks_end))
    }

    /// The chart on `root` with this layout's margins and axes, its mesh (without grid
    /// lines when `grid` is false) drawn with scaled fonts, and the title and both axis
    /// descriptions drawn.
    pub fn chart<'a, DB: DrawingBackend>(
        &self,
        root: &'a DrawingArea<DB, Shift>,
        x: &Axis,
        y: &Axis,
        title: &str,
        grid: bool,
    ) -> Result<Chart<'a, DB>, PlotError>
    where
        DB::ErrorType: 'static,
    {
        let mut chart = ChartBuilder::on(root)
            .margin_top(self.top)
            .margin_right(self.right)
            .x_label_area_size(self.bottom)
            .y_label_area_size(self.left)
            .build_cartesian_2d(x.lo..x.hi, y.lo..y.hi)
            .map_err(draw_err)?;
        let (fx, fy) = (x.format, y.format);
        let xf = move |v: &f64| fx.label(*v);
        let yf = move |v: &f64| fy.label(*v);
        let mut mesh = chart.configure_mesh();
        // A log x axis gets its ticks, labels and grid lines from `draw_log_x` instead.
        mesh.x_labels(if x.log { 0 } else { TICKS })
            .y_labels(TICKS)
            .x_label_formatter(&xf)
            .y_label_formatter(&yf)
            .set_all_tick_mark_size(self.tick_mark)
            .axis_style(BLACK.stroke_width(self.fonts.px(1.0)))
            .label_style(("sans-serif", self.fonts.tick));
        if grid {
            mesh.light_line_style(RGBColor(240, 240, 240))
                .bold_line_style(GRID);
        } else {
            mesh.disable_mesh();
        }
        mesh.draw().map_err(draw_err)?;
        if x.log {
            self.draw_log_x(root, &chart, x, y, grid)?;
        }
        self.draw_text(root, title, &x.desc, &y.desc)?;
        Ok(chart)
    }

    /// The ticks, labels and (with `grid`) grid lines of a log x axis, in the style plotters
    /// gives a linear one: a mark below the axis and the label two marks from it.
    fn draw_log_x<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &Chart<'_, DB>,
        x: &Axis,
        y: &Axis,
        grid: bool,
    ) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let style = TextStyle::from(("sans-serif", self.fonts.tick).into_font())
            .pos(Pos::new(HPos::Center, VPos::Top));
        for v in log_ticks(x.lo, x.hi) {
            let (px, bottom) = chart.backend_coord(&(v.log10(), y.lo));
            let (_, top) = chart.backend_coord(&(v.log10(), y.hi));
            if grid {
                root.draw(&PathElement::new([(px, top), (px, bottom - 1)], GRID))
                    .map_err(draw_err)?;
            }
            let mark = self.tick_mark as i32;
            root.draw(&PathElement::new(
                [(px, bottom), (px, bottom + mark)],
                BLACK.stroke_width(self.fonts.px(1.0)),
            ))
            .map_err(draw_err)?;
            root.draw_text(&log_label(v), &style, (px, bottom + 2 * mark))
                .map_err(draw_err)?;
        }
        Ok(())
    }

    /// The layout of the whole canvas `root` (its size, axes `x` and `y`, `title`) and its
    /// chart with grid lines ([`Layout::chart`]): how every single-chart figure starts.
    pub fn canvas_chart<'a, DB: DrawingBackend>(
        root: &'a DrawingArea<DB, Shift>,
        x: &Axis,
        y: &Axis,
        title: &str,
    ) -> Result<(Layout, Chart<'a, DB>), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let (w, h) = root.dim_in_pixel();
        let layout = Layout::new(w, x, y, title).with_height(h);
        let chart = layout.chart(root, x, y, title, true)?;
        Ok((layout, chart))
    }

    /// Finishes a figure made by [`Layout::chart`]: the legend of its labelled series in the
    /// figures' one style (white box at 85 %, black border, the legend font) at `position`,
    /// then the drawing flushed to its file.
    pub fn finish<'a, DB: DrawingBackend + 'a>(
        &self,
        root: &DrawingArea<DB, Shift>,
        chart: &mut Chart<'a, DB>,
        position: SeriesLabelPosition,
    ) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", self.fonts.legend))
            .position(position)
            .draw()
            .map_err(draw_err)?;
        root.present().map_err(draw_err)
    }

    /// Draws the title (centred over the canvas, `pad` from the top), the x-axis
    /// description (centred under the plot area, `pad` from the bottom) and the y-axis
    /// description (rotated, centred beside the plot area, `pad` from the left edge).
    pub fn draw_text<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        title: &str,
        x_desc: &str,
        y_desc: &str,
    ) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let f = self.fonts;
        if !title.is_empty() {
            let style = TextStyle::from(("sans-serif", f.title).into_font())
                .pos(Pos::new(HPos::Center, VPos::Center));
            let y = self.pad + self.title_height / 2;
            root.draw_text(title, &style, ((self.width / 2) as i32, y as i32))
                .map_err(draw_err)?;
        }
        let plot_cx = self.left + self.plot_width() / 2;
        let plot_cy = self.top + self.plot_height() / 2;
        if !x_desc.is_empty() {
            let style = TextStyle::from(("sans-serif", f.label).into_font())
                .pos(Pos::new(HPos::Center, VPos::Center));
            let y = self.height - self.pad - self.desc_height / 2;
            root.draw_text(x_desc, &style, (plot_cx as i32, y as i32))
                .map_err(draw_err)?;
        }
        if !y_desc.is_empty() {
            let style = TextStyle::from(("sans-serif", f.label).into_font())
                .transform(FontTransform::Rotate270)
                .pos(Pos::new(HPos::Center, VPos::Center));
            let x = self.pad + self.desc_height / 2;
            root.draw_text(y_desc, &style, (x as i32, plot_cy as i32))
                .map_err(draw_err)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimals_follow_the_step() {
        assert_eq!(decimals(200.0), 0);
        assert_eq!(decimals(1.0), 0);
        assert_eq!(decimals(0.5), 1);
        assert_eq!(decimals(0.25), 2);
        assert_eq!(decimals(0.05), 2);
        assert_eq!(decimals(0.1 + 0.2 - 0.2), 1);
        let f = TickFormat::of(-14.0, 6.0);
        assert_eq!(f.label(-14.0), "-14");
        let f = TickFormat::of(0.0, 1.0);
        assert_eq!(f.decimals, 1);
        assert_eq!(f.label(0.0), "0.0");
        assert_eq!(f.label(-0.0), "0.0");
        assert_eq!(TickFormat { decimals: 0 }.label(-0.2), "0");
    }

    #[test]
    fn log_axis_ticks_are_one_two_five_per_decade() {
        let a = Axis::log10(0.08, 7.0, "h (m)");
        assert_eq!(a.at(1.0), 0.0);
        assert_eq!(a.labels(), ["0.1", "0.2", "0.5", "1", "2", "5"]);
        assert_eq!(
            log_ticks(0.0, 2.0),
            [1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0]
        );
        assert!(log_ticks(1.0, 0.0).is_empty());
    }

    #[test]
    fn fonts_scale_with_the_width() {
        let a = Fonts::for_width(900);
        let b = Fonts::for_width(1800);
        assert_eq!(a.tick, 14.0);
        assert_eq!(b.tick, 28.0);
        assert_eq!(b.title / a.title, 2.0);
        assert!(Fonts::for_width(100).tick >= MIN_TICK_PX);
    }
}
