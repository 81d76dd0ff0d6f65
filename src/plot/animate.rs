//! Animations of a run: its snapshots (`snapshots/t*.json`) drawn with the state renderer
//! ([`super::render`]) in one fixed window and encoded as a looping GIF (the crate's own encoder),
//! and as MP4 through `ffmpeg` where it is on the PATH.

use super::PlotError;
use super::render::{Window, render_state_rgb};
use crate::dem::Snapshot;
use crate::io::IoError;
use crate::io::state::load_state;
use std::path::{Path, PathBuf};

/// Margin around the drawn bodies (m).
const MARGIN: f64 = 1.0;
/// How far from the rubble the sheet and the floe are drawn (m), see [`Window::fit_ridge`].
const REACH: f64 = 3.0;

/// The snapshots of the run directory `run_dir` (`snapshots/t*.json`), in time order.
/// An error naming the directory when there are none.
pub(crate) fn load_snapshots(run_dir: &Path) -> Result<Vec<Snapshot>, IoError> {
    let dir = run_dir.join("snapshots");
    let none = || {
        IoError::format(
            run_dir,
            "no snapshots in this run directory (snapshots/t*.json): run `pressridge simulate` \
             with output.snapshot_interval > 0 and a duration of at least one interval",
        )
    };
    let entries = match std::fs::read_dir(&dir) {
        Ok(it) => it,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Err(none()),
        Err(e) => return Err(IoError::os(&dir, e)),
    };
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with('t') && n.ends_with(".json"))
        })
        .collect();
    paths.sort();
    if paths.is_empty() {
        return Err(none());
    }
    let mut snaps = paths
        .iter()
        .map(|p| load_state(p))
        .collect::<Result<Vec<_>, _>>()?;
    snaps.sort_by(|a, b| a.time.total_cmp(&b.time));
    Ok(snaps)
}

/// One window for every frame: the union of the ridge windows ([`Window::fit_ridge`]) of
/// the snapshots that hold rubble, else the union of their free bodies' windows.
pub(crate) fn common_window(snaps: &[Snapshot]) -> Window {
    snaps
        .iter()
        .filter_map(|s| Window::fit_ridge(s, REACH, MARGIN))
        .reduce(Window::union)
        .unwrap_or_else(|| {
            snaps
                .iter()
                .map(|s| Window::fit(s, MARGIN))
                .reduce(Window::union)
                .unwrap_or(Window {
                    x0: -5.0,
                    x1: 5.0,
                    y0: -5.0,
                    y1: 5.0,
                })
        })
}

/// What [`animate`] wrote.
#[derive(Debug)]
pub struct Animation {
    /// Frames (one per snapshot).
    pub frames: usize,
    /// Size of a frame (px).
    pub size: (u32, u32),
    /// The window drawn (m).
    pub window: Window,
    /// The MP4 written, if asked and `ffmpeg` was found.
    pub mp4: Option<PathBuf>,
}

/// Options of [`animate`].
#[derive(Clone, Debug)]
pub struct AnimateOptions {
    /// Frames per second (1–100).
    pub fps: u32,
    /// Frame width (px).
    pub width_px: u32,
    /// Also write an MP4 here (needs `ffmpeg` on the PATH; skipped with a warning without).
    pub mp4: Option<PathBuf>,
}

/// Draws every snapshot of `run_dir` in one window and writes the looping GIF `gif`
/// atomically (and the MP4 of [`AnimateOptions::mp4`] through `ffmpeg`, when found).
pub fn animate(run_dir: &Path, gif: &Path, opts: &AnimateOptions) -> Result<Animation, PlotError> {
    if !(1..=100).contains(&opts.fps) {
        return Err(PlotError::Io(IoError::format(
            gif,
            format!("--fps must be 1 to 100 frames per second, not {}", opts.fps),
        )));
    }
    let snaps = load_snapshots(run_dir)?;
    let window = common_window(&snaps);
    let mut frames = Vec::with_capacity(snaps.len());
    let mut size = (0, 0);
    for s in &snaps {
        let (rgb, w, h) =
            render_state_rgb(s, window, opts.width_px, &format!("t = {:.0} s", s.time))?;
        size = (w, h);
        frames.push(rgb);
    }
    // GIF delays are in hundredths of a second.
    let delay = (100 / opts.fps).max(1) as u16;
    crate::io::write_atomic_with(gif, |tmp| -> Result<(), PlotError> {
        let f = std::fs::File::create(tmp).map_err(|e| IoError::os(gif, e))?;
        let mut w = std::io::BufWriter::new(f);
        super::gif::encode(&mut w, size.0, size.1, &frames, delay)
            .and_then(|_| std::io::Write::flush(&mut w))
            .map_err(|e| IoError::os(gif, e))?;
        Ok(())
    })?;
    let mp4 = match &opts.mp4 {
        Some(p) if ffmpeg_found() => {
            write_mp4(p, size, &frames, opts.fps)?;
            Some(p.clone())
        }
        Some(p) => {
            eprintln!(
                "pressridge: warning: ffmpeg is not on the PATH: {} not written (the GIF is)",
                p.display()
            );
            None
        }
        None => None,
    };
    Ok(Animation {
        frames: frames.len(),
        size,
        window,
        mp4,
    })
}

/// Whether an `ffmpeg` program runs.
pub(crate) fn ffmpeg_found() -> bool {
    std::process::Command::new("ffmpeg")
        .arg("-version")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

/// Pipes the frames as raw RGB into `ffmpeg` (H.264, yuv420p, even sizes), atomically.
fn write_mp4(path: &Path, size: (u32, u32), frames: &[Vec<u8>], fps: u32) -> Result<(), PlotError> {
    use std::io::Write;
    use std::process::{Command, Stdio};
    crate::io::write_atomic_with(path, |tmp| -> Result<(), PlotError> {
        let mut child = Command::new("ffmpeg")
            .args([
                "-y",
                "-loglevel",
                "error",
                "-f",
                "rawvideo",
                "-pix_fmt",
                "rgb24",
            ])
            .args(["-s", &format!("{}x{}", size.0, size.1)])
            .args(["-r", &fps.to_string(), "-i", "-"])
            .args([
                "-vf",
                "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                "-pix_fmt",
                "yuv420p",
            ])
            .args(["-f", "mp4"])
            .arg(tmp)
            .stdin(Stdio::piped())
            .spawn()
            .map_err(|e| IoError::os(path, e))?;
        let mut stdin = child.stdin.take().expect("piped stdin");
        for f in frames {
            stdin.write_all(f).map_err(|e| IoError::os(path, e))?;
        }
        drop(stdin);
        let status = child.wait().map_err(|e| IoError::os(path, e))?;
        if !status.success() {
            return Err(PlotError::Io(IoError::format(
                path,
                format!("ffmpeg failed ({status})"),
            )));
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `ffprobe`'s answer for the video stream of `path`: (codec, width, height, frames).
    fn probe(path: &Path) -> (String, u32, u32, usize) {
        let out = std::process::Command::new("ffprobe")
            .args(["-v", "error", "-count_frames", "-select_streams", "v:0"])
            .args([
                "-show_entries",
                "stream=codec_name,width,height,nb_read_frames",
            ])
            .args(["-of", "csv=p=0"])
            .arg(path)
            .output()
            .expect("ffprobe runs (it comes with ffmpeg)");
        let text = String::from_utf8_lossy(&out.stdout);
        let f: Vec<&str> = text.trim().split(',').collect();
        assert_eq!(f.len(), 4, "ffprobe said {text:?}");
        (
            f[0].to_string(),
            f[1].parse().unwrap(),
            f[2].parse().unwrap(),
            f[3].parse().unwrap(),
        )
    }

    /// Three frames of an odd size become an H.264 MP4 of three frames, padded to even
    /// sizes, written atomically. ffmpeg is installed by `scripts/setup.sh`; without it this
    /// test fails rather than passing unexercised.
    #[test]
    fn mp4_of_odd_sized_frames() {
        assert!(
            ffmpeg_found(),
            "ffmpeg is not on the PATH: run scripts/setup.sh (it installs ffmpeg)"
        );
        let (w, h) = (33_u32, 21_u32);
        let frames: Vec<Vec<u8>> = (0..3_u8)
            .map(|k| {
                (0..w * h)
                    .flat_map(|i| [(i % 251) as u8, 80 * k, 255 - (i % 199) as u8])
                    .collect()
            })
            .collect();
        let dir = std::env::temp_dir().join(format!("pressridge-mp4-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("a.mp4");
        write_mp4(&path, (w, h), &frames, 5).unwrap();
        assert_eq!(probe(&path), ("h264".to_string(), 34, 22, 3));
        let names: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names, ["a.mp4"], "no temporary file left");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
