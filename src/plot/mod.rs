//! Figures (PNG/SVG). Plotting lives here and only here: no physics module depends on it.
//!
//! Text needs a TrueType font: DejaVu Sans, registered once per process, looked up in the
//! environment variable `PRESSRIDGE_FONT` (a path to a `.ttf`) and then in Debian's
//! `fonts-dejavu-core` locations (`scripts/setup.sh` installs it).

/// Draws `$draw(root, args..)` into the file `$path` of `$size` px: SVG when its extension
/// is `svg`, else PNG.
macro_rules! to_file {
    ($path:expr, $size:expr, $draw:ident ( $($arg:expr),* )) => {{
        if $path.extension().is_some_and(|e| e == "svg") {
            $draw(SVGBackend::new($path, $size).into_drawing_area(), $($arg),*)
        } else {
            $draw(BitMapBackend::new($path, $size).into_drawing_area(), $($arg),*)
        }
    }};
}

pub mod animate;
#[cfg(test)]
mod figure_tests;
pub(crate) mod gif;
pub(crate) mod layout;
pub mod redistribution;
pub mod render;
pub mod series;
pub mod strength_map;
pub mod table;

use std::sync::OnceLock;

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
pub(crate) fn ensure_font() -> Result<(), PlotError> {
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

/// Writes the figure `path` atomically: registers the font, then `draw` writes into the
/// temporary file it is given (renamed to `path` on success, removed on error); a drawing
/// error names `path`. Every figure file of this module is written through here.
pub(crate) fn write_figure(
    path: &std::path::Path,
    draw: impl FnOnce(&std::path::Path) -> Result<(), PlotError>,
) -> Result<(), PlotError> {
    crate::io::write_atomic_with(path, |tmp| {
        ensure_font()?;
        draw(tmp)
    })
    .map_err(|e| e.at(path))
}

/// Converts any plotters drawing error into a [`PlotError`].
pub(crate) fn draw_err<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Draw(e.to_string())
}
