//! `pressridge render`: draw a saved state.

use crate::BoxError;
use pressridge::io::refuse_output_over_input;
use pressridge::io::state::load_state;
use pressridge::plot::render::{Window, render_state};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// A saved state (state.json from `simulate`).
    state: PathBuf,
    /// Output image (.png or .svg).
    #[arg(long, default_value = "state.png")]
    out: PathBuf,
    /// Window x0,x1,y0,y1 in metres; fitted to the free blocks when omitted.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    window: Option<Vec<f64>>,
    /// Image width in pixels (200 to 8000); fonts, lines and margins scale with it.
    #[arg(long, default_value_t = 1000)]
    width: u32,
}

pub fn run(a: Args) -> Result<(), BoxError> {
    refuse_output_over_input(&a.out, "--out", &[("state", &a.state)])?;
    let s = load_state(&a.state)?;
    let window = match a.window.as_deref() {
        Some(&[x0, x1, y0, y1]) if x1 > x0 && y1 > y0 => Window { x0, x1, y0, y1 },
        Some(_) => return Err("--window needs x0,x1,y0,y1 with x1 > x0 and y1 > y0".into()),
        None => Window::fit(&s, 1.0),
    };
    render_state(
        &s,
        &a.out,
        window,
        a.width.clamp(200, 8000),
        &format!("t = {:.1} s", s.time),
    )?;
    println!("wrote {}", a.out.display());
    Ok(())
}
