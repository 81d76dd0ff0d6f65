//! Ridge snapshots: blocks, the water, axes in metres (cf. Hopkins 1994, Figure 5).

use super::layout::{Axis, Layout};
use super::{PlotError, draw_err, ensure_font, write_figure};
use crate::dem::{Role, Snapshot};
use plotters::prelude::*;
use std::path::Path;

/// A window of the plane to draw (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Left edge (m).
    pub x0: f64,
    /// Right edge (m).
    pub x1: f64,
    /// Bottom edge (m).
    pub y0: f64,
    /// Top edge (m).
    pub y1: f64,
}

impl Window {
    /// The smallest window holding every free (not held) body, with a margin (m).
    /// Held bodies (walls, supports) are drawn but do not set the window.
    pub fn fit(s: &Snapshot, margin: f64) -> Window {
        let mut w = Window {
            x0: f64::INFINITY,
            x1: f64::NEG_INFINITY,
            y0: f64::INFINITY,
            y1: f64::NEG_INFINITY,
        };
        for b in s.bodies.iter().filter(|b| !b.drive.is_kinematic()) {
            for &p in b.world_outline().verts() {
                w.x0 = w.x0.min(p.x);
                w.x1 = w.x1.max(p.x);
                w.y0 = w.y0.min(p.y);
                w.y1 = w.y1.max(p.y);
            }
        }
        if !w.x0.is_finite() {
            return Window {
                x0: -5.0,
                x1: 5.0,
                y0: -5.0,
                y1: 5.0,
            };
        }
        Window {
            x0: w.x0 - margin,
            x1: w.x1 + margin,
            y0: w.y0 - margin,
            y1: w.y1 + margin,
        }
    }
}

impl Window {
    /// The smallest window holding both (m).
    pub fn union(self, o: Window) -> Window {
        Window {
            x0: self.x0.min(o.x0),
            x1: self.x1.max(o.x1),
            y0: self.y0.min(o.y0),
            y1: self.y1.max(o.y1),
        }
    }

    /// The window around the ridge: every rubble block (free blocks of role `Rubble` or
    /// `Block`) and, of the sheet, the floe and any other body, the part within `reach` (m)
    /// of the rubble's bounding box, all with a `margin` (m). `None` when the state holds
    /// no rubble. Metres stay square when drawn ([`render_state`]), whatever the shape.
    pub fn fit_ridge(s: &Snapshot, reach: f64, margin: f64) -> Option<Window> {
        let bbox = |b: &crate::dem::BodyState| {
            let mut w = Window {
                x0: f64::INFINITY,
                x1: f64::NEG_INFINITY,
                y0: f64::INFINITY,
                y1: f64::NEG_INFINITY,
            };
            for &p in b.world_outline().verts() {
                w.x0 = w.x0.min(p.x);
                w.x1 = w.x1.max(p.x);
                w.y0 = w.y0.min(p.y);
                w.y1 = w.y1.max(p.y);
            }
            w
        };
        let is_rubble = |b: &crate::dem::BodyState| {
            matches!(b.role, Role::Rubble | Role::Block) && !b.drive.is_kinematic()
        };
        let rubble = s
            .bodies
            .iter()
            .filter(|b| is_rubble(b))
            .map(bbox)
            .reduce(Window::union)?;
        let near = Window {
            x0: rubble.x0 - reach,
            x1: rubble.x1 + reach,
            y0: rubble.y0 - reach,
            y1: rubble.y1 + reach,
        };
        let mut w = rubble;
        for b in s.bodies.iter().filter(|b| !is_rubble(b)) {
            let o = bbox(b);
            let part = Window {
                x0: o.x0.max(near.x0),
                x1: o.x1.min(near.x1),
                y0: o.y0.max(near.y0),
                y1: o.y1.min(near.y1),
            };
            if part.x0 <= part.x1 && part.y0 <= part.y1 {
                w = w.union(part);
            }
        }
        Some(Window {
            x0: w.x0 - margin,
            x1: w.x1 + margin,
            y0: w.y0 - margin,
            y1: w.y1 + margin,
        })
    }
}

/// Draws a saved state into a PNG (or SVG, by the file extension) of `width_px` pixels
/// wide, height from the window's aspect ratio so that metres are square. Fonts and margins
/// scale with the width (14-px tick labels at 900 px, never below 9 px).
pub fn render_state(
    s: &Snapshot,
    path: &Path,
    window: Window,
    width_px: u32,
    title: &str,
) -> Result<(), PlotError> {
    write_figure(path, |tmp| render_state_at(s, tmp, window, width_px, title))
}

/// [`render_state`] into the file `path` (a temporary file renamed by the caller).
fn render_state_at(
    s: &Snapshot,
    path: &Path,
    window: Window,
    width_px: u32,
    title: &str,
) -> Result<(), PlotError> {
    let layout = state_layout(window, width_px, title);
    let size = (layout.width, layout.height);
    to_file!(path, size, draw(s, window, title, &layout))
}

/// The axes of a state figure: x and y in metres over the window.
fn axes(window: Window) -> (Axis, Axis) {
    (
        Axis::new(window.x0, window.x1, "x (m)"),
        Axis::new(window.y0, window.y1, "y (m)"),
    )
}

/// The layout of a state figure of `window` drawn `width_px` wide (at least 200 px) with
/// `title` (may be empty): margins measured from its labels, the height following from the
/// window's aspect ratio so that the plot area keeps metres square.
pub(crate) fn state_layout(window: Window, width_px: u32, title: &str) -> Layout {
    let (x, y) = axes(window);
    let l = Layout::new(width_px.max(200), &x, &y, title);
    let aspect = (window.y1 - window.y0) / (window.x1 - window.x0);
    let plot_w = l.plot_width().max(100);
    let mut l = l;
    l.width = plot_w + l.left + l.right;
    l.with_plot_height((plot_w as f64 * aspect).round().max(1.0) as u32)
}

/// Draws a state into memory: RGB bytes (3 a pixel, row by row) of the size
/// [`state_layout`] gives, returned with that size.
pub(crate) fn render_state_rgb(
    s: &Snapshot,
    window: Window,
    width_px: u32,
    title: &str,
) -> Result<(Vec<u8>, u32, u32), PlotError> {
    ensure_font()?;
    let layout = state_layout(window, width_px, title);
    let (w, h) = (layout.width, layout.height);
    let mut buf = vec![0u8; 3 * w as usize * h as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
        draw(root, s, window, title, &layout)?;
    }
    Ok((buf, w, h))
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    s: &Snapshot,
    win: Window,
    title: &str,
    layout: &Layout,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let (x, y) = axes(win);
    let mut chart = layout.chart(&root, &x, &y, title, false)?;
    let line = layout.fonts.px(1.0);
    if let Some(w) = &s.params.water {
        let water = RGBColor(198, 226, 245);
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(win.x0, win.y0), (win.x1, w.level.min(win.y1))],
                water.filled(),
            )))
            .map_err(draw_err)?;
    }
    let held = RGBColor(150, 150, 150);
    let ice = RGBColor(250, 250, 252);
    let sheet = RGBColor(214, 236, 250);
    let floe = RGBColor(205, 205, 215);
    for b in &s.bodies {
        let o = b.world_outline();
        let v = o.verts();
        let pts: Vec<(f64, f64)> = v
            .iter()
            .map(|p| (p.x.clamp(win.x0, win.x1), p.y.clamp(win.y0, win.y1)))
            .collect();
        let fill = match b.role {
            Role::Wall => held,
            Role::Sheet => sheet,
            Role::Floe => floe,
            _ if b.drive.is_kinematic() => held,
            _ => ice,
        };
        chart
            .draw_series(std::iter::once(Polygon::new(pts.clone(), fill.filled())))
            .map_err(draw_err)?;
        let mut outline = pts;
        outline.push(outline[0]);
        chart
            .draw_series(std::iter::once(PathElement::new(
                outline,
                BLACK.stroke_width(line),
            )))
            .map_err(draw_err)?;
    }
    if let Some(w) = &s.params.water {
        chart
            .draw_series(LineSeries::new(
                [(win.x0, w.level), (win.x1, w.level)],
                RGBColor(30, 90, 160).stroke_width(2 * line),
            ))
            .map_err(draw_err)?;
    }
    root.present().map_err(draw_err)?;
    Ok(())
}
