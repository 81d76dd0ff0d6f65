//! `pressridge animate`: a GIF (and an MP4 where ffmpeg is found) of a run's snapshots.

use crate::BoxError;
use pressridge::plot::animate::{AnimateOptions, animate};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// A run directory written by `simulate` (its snapshots/t*.json are the frames).
    run_dir: PathBuf,
    /// Output GIF; RUN_DIR/ridge.gif when omitted.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Frames per second (1–100).
    #[arg(long, default_value_t = 4)]
    fps: u32,
    /// Frame width in pixels (200–4000).
    #[arg(long, default_value_t = 800)]
    width: u32,
    /// Also write an MP4 beside the GIF (same name, .mp4) when ffmpeg is on the PATH.
    #[arg(long)]
    mp4: bool,
}

pub fn run(a: Args) -> Result<(), BoxError> {
    let gif = a.out.unwrap_or_else(|| a.run_dir.join("ridge.gif"));
    if !(200..=4000).contains(&a.width) {
        return Err(format!("--width must be 200 to 4000 pixels, not {}", a.width).into());
    }
    let opts = AnimateOptions {
        fps: a.fps,
        width_px: a.width,
        mp4: a.mp4.then(|| gif.with_extension("mp4")),
    };
    let made = animate(&a.run_dir, &gif, &opts)?;
    println!(
        "wrote {} ({} frames, {}x{} px, x {:.1}..{:.1} m, y {:.1}..{:.1} m)",
        gif.display(),
        made.frames,
        made.size.0,
        made.size.1,
        made.window.x0,
        made.window.x1,
        made.window.y0,
        made.window.y1
    );
    if let Some(p) = made.mp4 {
        println!("wrote {}", p.display());
    }
    Ok(())
}
