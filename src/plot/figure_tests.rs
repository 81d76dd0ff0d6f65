//! Figures fit for a paper: fonts scale with the figure, no label is clipped at the canvas
//! edge or overprints another, at the smallest and a large supported size, PNG and SVG.
//! Unit tests, since they measure the figure against its layout ([`super::layout`]), which
//! is crate-private.

use super::layout::{Fonts, MIN_TICK_PX};
use super::render::{Window, render_state, render_state_rgb, state_layout};
use crate::scene::Scene;

/// The Figure 5 window of the paper's snapshots (m).
const WINDOW: Window = Window {
    x0: -14.0,
    x1: 6.0,
    y0: -8.0,
    y1: 4.0,
};

fn state() -> crate::dem::Snapshot {
    Scene::default().build().unwrap().snapshot()
}

fn dark(buf: &[u8], w: u32, x: u32, y: u32) -> bool {
    let i = 3 * (y as usize * w as usize + x as usize);
    buf[i..i + 3].iter().map(|&c| c as u32).sum::<u32>() < 3 * 160
}

/// Columns (x0, x1) holding dark pixels in rows `rows` and columns `cols`.
fn ink_columns(
    buf: &[u8],
    w: u32,
    cols: std::ops::Range<u32>,
    rows: std::ops::Range<u32>,
) -> Vec<u32> {
    cols.filter(|&x| rows.clone().any(|y| dark(buf, w, x, y)))
        .collect()
}

#[test]
fn state_figure_labels_inside_the_canvas_and_apart_at_two_sizes() {
    let s = state();
    let mut desc_heights = Vec::new();
    for width in [200u32, 400, 1600] {
        let title = "t = 400 s";
        let (buf, w, h) = render_state_rgb(&s, WINDOW, width, title).unwrap();
        let l = state_layout(WINDOW, width, title);
        assert_eq!((w, h), (l.width, l.height));
        // Nothing touches the canvas edge: a clipped label would.
        for x in 0..w {
            for y in [0, 1, h - 2, h - 1] {
                assert!(!dark(&buf, w, x, y), "{width} px: ink at ({x}, {y})");
            }
        }
        for y in 0..h {
            for x in [0, 1, w - 2, w - 1] {
                assert!(!dark(&buf, w, x, y), "{width} px: ink at ({x}, {y})");
            }
        }
        // Left of the axis: the rotated "y (m)" lies in its own column, the tick labels in
        // theirs, and the two do not meet.
        let ((d0, d1), (t0, t1)) = l.y_columns();
        assert!(
            d1 < t0,
            "{width} px: description {d0}..{d1}, ticks {t0}..{t1}"
        );
        let rows = l.top..l.top + l.plot_height();
        let ink = ink_columns(&buf, w, 0..l.left - l.tick_mark - 1, rows.clone());
        let desc: Vec<u32> = ink.iter().copied().filter(|&x| x < t0).collect();
        assert!(!desc.is_empty(), "{width} px: no y-axis description drawn");
        assert!(
            desc.iter().all(|&x| x >= d0 && x <= d1),
            "{width} px: description ink at {desc:?}, column {d0}..{d1}"
        );
        assert!(
            ink.iter().all(|&x| x <= d1 || (x >= t0 && x <= t1 + 1)),
            "{width} px: ink outside the label columns: {ink:?} {l:?}"
        );
        // The description's ink height (its length, rotated) scales with the font.
        let desc_rows: Vec<u32> = (0..h)
            .filter(|&y| (d0..=d1).any(|x| dark(&buf, w, x, y)))
            .collect();
        desc_heights.push(desc_rows.last().unwrap() - desc_rows[0]);
        // Under the plot: tick labels then "x (m)", both above the bottom edge.
        let below = l.top + l.plot_height() + 2 * l.tick_mark;
        assert!(below + l.x_tick_height + l.desc_height < h, "{width} px");
    }
    let scale = Fonts::for_width(1600).tick / Fonts::for_width(400).tick;
    let seen = desc_heights[2] as f64 / desc_heights[1] as f64;
    assert!(
        (seen / scale - 1.0).abs() < 0.2,
        "y label grew {seen:.2}x for fonts {scale:.2}x ({desc_heights:?})"
    );
    assert!(Fonts::for_width(200).tick >= MIN_TICK_PX);
}

/// The `<text>` elements of an SVG: their anchor (x, y) and content.
fn svg_texts(svg: &str) -> Vec<(f64, f64, String)> {
    let attr = |tag: &str, name: &str| -> f64 {
        let k = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
        tag[k..k + tag[k..].find('"').unwrap()].parse().unwrap()
    };
    svg.split("<text")
        .skip(1)
        .map(|t| {
            let open = &t[..t.find('>').unwrap()];
            let body = &t[t.find('>').unwrap() + 1..t.find("</text>").unwrap()];
            (attr(open, "x"), attr(open, "y"), body.trim().to_string())
        })
        .collect()
}

#[test]
fn svg_state_text_lies_inside_the_canvas_at_two_sizes() {
    let s = state();
    let dir = std::env::temp_dir().join(format!("pressridge-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut sizes = Vec::new();
    for width in [400u32, 1600] {
        let path = dir.join(format!("state{width}.svg"));
        render_state(&s, &path, WINDOW, width, "t = 0 s").unwrap();
        let l = state_layout(WINDOW, width, "t = 0 s");
        let svg = std::fs::read_to_string(&path).unwrap();
        let texts = svg_texts(&svg);
        for want in ["x (m)", "y (m)", "t = 0 s", "-10", "0"] {
            assert!(texts.iter().any(|t| t.2 == want), "{width} px: no `{want}`");
        }
        let f = Fonts::for_width(width);
        for (x, y, text) in &texts {
            // Anchors at least half a font size from every edge: the glyphs fit.
            let m = 0.5 * f.tick;
            assert!(
                *x >= m && *x <= l.width as f64 - m && *y >= m && *y <= l.height as f64 - m,
                "{width} px: `{text}` at ({x}, {y}) on {}x{}",
                l.width,
                l.height
            );
        }
        // The smallest font (the tick labels) scales with the width (to the whole pixel).
        let smallest = svg
            .split("font-size=\"")
            .skip(1)
            .map(|t| t[..t.find('"').unwrap()].parse::<f64>().unwrap())
            .fold(f64::INFINITY, f64::min);
        sizes.push(smallest);
    }
    let want = Fonts::for_width(1600).tick / Fonts::for_width(400).tick;
    assert!(
        (sizes[1] / sizes[0] / want - 1.0).abs() < 0.05,
        "tick fonts {sizes:?}, want a ratio of {want}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The ridged-ice figure draws the simulated density and the three shapes, each named with
/// its parameter in the legend, as SVG and PNG.
#[test]
fn ridged_ice_figure_names_its_fits() {
    use crate::table::redistribution::{RidgedEnsemble, RidgedIce, Setting};
    let run = |ice: Vec<f64>| RidgedIce {
        parent_thickness: 0.3,
        strip_width: 1.0,
        column: ice.iter().map(|x| x / 0.7).collect(),
        ice,
    };
    let e = RidgedEnsemble::of(&[run(vec![0.4, 0.9, 1.3, 2.0]), run(vec![0.7, 1.1, 2.6])]).unwrap();
    let k = Setting {
        thickness: 0.3,
        mu: 1.0,
        mu_water: 0.6,
    };
    let dir = std::env::temp_dir().join(format!("pressridge-ridged-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("ridged.svg");
    crate::plot::redistribution::plot_redistribution(&k, &e, &svg).unwrap();
    let text = std::fs::read_to_string(&svg).unwrap();
    for want in [
        "μ_rdg = ",
        "H* = ",
        "Icepack default",
        "porosity 0.30",
        "7 strips of 2 runs",
    ] {
        assert!(text.contains(want), "{want}");
    }
    let png = dir.join("ridged.png");
    crate::plot::redistribution::plot_redistribution(&k, &e, &png).unwrap();
    assert!(std::fs::metadata(&png).unwrap().len() > 10_000);
    std::fs::remove_dir_all(&dir).unwrap();
}
