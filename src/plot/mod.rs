//! Figures (PNG/SVG). Plotting lives here and only here: no physics module depends on it.
//!
//! Text needs a TrueType font. [`ensure_font`] registers DejaVu Sans once, looked up in the
//! environment variable `PRESSRIDGE_FONT` (a path to a `.ttf`) and then in Debian's
//! `fonts-dejavu-core` locations (`scripts/setup.sh` installs it).

pub mod animate;
pub mod gif;
pub mod render;
pub mod series;
pub mod table;

use std::sync::OnceLock;

pub mod strength_map;

/// An error while drawing or writing a figure.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// No usable font was found.
    #[error(
        "no TrueType font found: install fonts-dejavu-core or set PRESSRIDGE_FONT to a .ttf file"
    )]
    NoFont,
    /// The drawing backend failed (message from plotters).
    #[error("drawing failed: {0}")]
    Draw(String),
    /// The figure could not be written.
    #[error(transparent)]
    Io(#[from] crate::io::IoError),
}

impl PlotError {
    /// The error with the figure's path in a drawing message.
    pub(crate) fn at(self, path: &std::path::Path) -> PlotError {
        match self {
            PlotError::Draw(m) => PlotError::Draw(format!("{}: {m}", path.display())),
            other => other,
        }
    }
}

const FONT_PATHS: &[&str] = &[
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
];

/// Registers a sans-serif font with plotters under the family name `"sans-serif"`.
/// Safe to call many times and from several threads; the font file is read once.
pub fn ensure_font() -> Result<(), PlotError> {
    static FONT: OnceLock<bool> = OnceLock::new();
    let ok = *FONT.get_or_init(|| {
        let env = std::env::var("PRESSRIDGE_FONT").ok();
        let candidates = env
            .iter()
            .map(String::as_str)
            .chain(FONT_PATHS.iter().copied());
        for path in candidates {
            if let Ok(bytes) = std::fs::read(path) {
                let bytes: &'static [u8] = Box::leak(bytes.into_boxed_slice());
                if plotters::style::register_font(
                    "sans-serif",
                    plotters::style::FontStyle::Normal,
                    bytes,
                )
                .is_ok()
                {
                    return true;
                }
            }
        }
        false
    });
    if ok { Ok(()) } else { Err(PlotError::NoFont) }
}

/// A tick label without needless decimals: `900` rather than `900.0`, `0.25`, `-1.5`
/// (at most 3 decimals, trailing zeros dropped, never `-0`).
pub(crate) fn tick(v: &f64) -> String {
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

/// Converts any plotters drawing error into a [`PlotError`].
pub(crate) fn draw_err<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Draw(e.to_string())
}

#[cfg(test)]
mod tests {
    #[test]
    fn ticks_drop_needless_decimals() {
        for (v, t) in [
            (900.0, "900"),
            (0.25, "0.25"),
            (-1.5, "-1.5"),
            (-0.0, "0"),
            (2.0, "2"),
            (0.1 + 0.2, "0.3"),
        ] {
            assert_eq!(super::tick(&v), t);
        }
    }
}
