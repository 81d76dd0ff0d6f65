//! `pressridge simulate`: run a scene and write its results.

use crate::BoxError;
use pressridge::dem::World;
use pressridge::io::{series::write_series_csv, state, write_atomic};
use pressridge::plot::{render, series};
use pressridge::scene::Scene;
use pressridge::simulation;
use pressridge::table::rafting;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene (the paper's Figure 5 experiment) when
    /// omitted.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// Override a scene parameter, e.g. --set contact.mu=0.4 (repeatable).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    sets: Vec<String>,
    /// Output directory.
    #[arg(long, default_value = "runs/default")]
    out: PathBuf,
    /// Print the resolved scene as TOML and exit.
    #[arg(long)]
    print_scene: bool,
    /// Skip the figures (and the animation).
    #[arg(long)]
    no_figures: bool,
    /// Also write the final state, energy and force figures as SVG (final.svg, energy.svg,
    /// force.svg) beside the PNGs.
    #[arg(long)]
    svg: bool,
    /// Replace an earlier run in `--out`: remove the files a run writes there (and only
    /// those) before starting. Without it a non-empty `--out` is refused.
    #[arg(long)]
    overwrite: bool,
    /// Threads each time step's force phases run on (outlines, water, joints, contact
    /// geometry); the results are the same to the bit on any number. Default: one.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=256))]
    threads: u32,
}

/// The files a run writes directly in its directory; `snapshots/` holds `t*.json` and
/// `t*.png`.
const RUN_FILES: &[&str] = &[
    "scene.toml",
    "summary.json",
    "series.csv",
    "state.json",
    "final.png",
    "energy.png",
    "force.png",
    "final.svg",
    "energy.svg",
    "force.svg",
    "ridge.gif",
];

/// Whether `name` is a file a run writes into `snapshots/` (or a temporary of one).
fn is_snapshot_file(name: &str) -> bool {
    (name.starts_with('t') && (name.ends_with(".json") || name.ends_with(".png")))
        || name.starts_with(".tmp-")
}

/// Makes `dir` ready for a new run: created if missing; refused if it holds anything unless
/// `overwrite`, which removes what a run writes there (other files are left alone), so the
/// directory never holds a mix of an old and a new run.
fn prepare_out_dir(dir: &Path, overwrite: bool) -> Result<(), BoxError> {
    let shown = dir.display();
    if dir.exists() && !dir.is_dir() {
        return Err(format!("--out {shown} is a file, not a directory").into());
    }
    let entries = |d: &Path| -> Result<Vec<String>, BoxError> {
        match std::fs::read_dir(d) {
            Ok(it) => Ok(it
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Vec::new()),
            Err(e) => Err(format!("{}: {e}", d.display()).into()),
        }
    };
    let present = entries(dir)?;
    if !present.is_empty() && !overwrite {
        return Err(format!(
            "--out {shown} is not empty (it holds {}): pass --overwrite to replace the run there, or choose a new directory",
            present.join(", ")
        )
        .into());
    }
    let remove = |p: &Path| -> Result<(), BoxError> {
        match std::fs::remove_file(p) {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(()),
            Err(e) => Err(format!("--overwrite: {}: {e}", p.display()).into()),
        }
    };
    for name in &present {
        if RUN_FILES.contains(&name.as_str()) || name.starts_with(".tmp-") {
            remove(&dir.join(name))?;
        }
    }
    let snaps = dir.join("snapshots");
    if snaps.is_dir() {
        for name in entries(&snaps)? {
            if is_snapshot_file(&name) {
                remove(&snaps.join(&name))?;
            }
        }
        // Gone when it held only snapshots.
        let _ = std::fs::remove_dir(&snaps);
    }
    std::fs::create_dir_all(dir).map_err(|e| format!("{shown}: {e}"))?;
    Ok(())
}

/// The window of a snapshot of a ridging scene: the scene's `output.frame`, grown where
/// needed to hold every rubble block and the sheet and floe within 3 m of the rubble, with
/// a 1 m margin ([`render::Window::fit_ridge`]), so that a sail or keel past the frame is
/// never clipped.
fn ridge_window(frame: render::Window, s: &pressridge::dem::Snapshot) -> render::Window {
    match render::Window::fit_ridge(s, 3.0, 1.0) {
        Some(w) => frame.union(w),
        None => frame,
    }
}

/// Loads a scene file (or the default) and applies the overrides ([`Scene::load`]).
pub fn load_scene(path: Option<&Path>, sets: &[String]) -> Result<Scene, BoxError> {
    Ok(Scene::load(path, sets)?)
}

pub fn run(a: Args) -> Result<(), BoxError> {
    let scene = load_scene(a.scene.as_deref(), &a.sets)?;
    if a.print_scene {
        print!("{}", scene.to_toml());
        return Ok(());
    }
    // Everything that can refuse the scene is checked before the directory is touched:
    // building the world checks its parameters, and the run must take at least one step.
    scene.check_run_length(scene.build()?.dt())?;
    prepare_out_dir(&a.out, a.overwrite)?;
    write_atomic(&a.out.join("scene.toml"), scene.to_toml().as_bytes())?;

    let progress = crate::progress::Progress::new(
        scene.duration,
        "s simulated",
        pressridge::eta::Model::GrowingCost,
    );
    let snap_dir = a.out.join("snapshots");
    let interval = scene.output.snapshot_interval;
    let mut next_snap = 0.0;
    let mut snap_err: Option<BoxError> = None;
    let frame = scene.output.frame;
    let window = render::Window {
        x0: frame[0],
        x1: frame[1],
        y0: frame[2],
        y1: frame[3],
    };
    let figures = !a.no_figures;
    let mut observe = |w: &World| {
        let t = w.time();
        progress.update(t, || {
            (
                format!("{t:.1} of {:.1} s simulated", scene.duration),
                format!("step {}, dt {:.3e} s", w.steps(), w.dt()),
            )
        });
        if interval > 0.0 && t >= next_snap - 0.5 * w.dt() {
            next_snap += interval;
            let s = w.snapshot();
            let stem = format!("t{:05.0}", t);
            let r = state::save_state(&snap_dir.join(format!("{stem}.json")), &s)
                .map_err(BoxError::from)
                .and_then(|_| {
                    if figures {
                        render::render_state(
                            &s,
                            &snap_dir.join(format!("{stem}.png")),
                            ridge_window(window, &s),
                            800,
                            &format!("t = {t:.0} s"),
                        )
                        .map_err(BoxError::from)
                    } else {
                        Ok(())
                    }
                });
            if let Err(e) = r {
                snap_err = Some(e);
                return false;
            }
        }
        true
    };
    let out = simulation::run_on(&scene, a.threads as usize, &mut observe)?;
    progress.finish();
    if let Some(e) = snap_err {
        return Err(e);
    }

    state::write_json(&a.out.join("summary.json"), &out.summary)?;
    write_series_csv(&a.out.join("series.csv"), &out.series)?;
    state::save_state(&a.out.join("state.json"), &out.final_state)?;
    if figures {
        let s = &out.final_state;
        let title = format!("{} at t = {:.1} s", scene.name, s.time);
        let win = if scene.sheet.is_some() {
            ridge_window(window, s)
        } else {
            render::Window::fit(s, 1.0)
        };
        let formats: &[&str] = if a.svg { &["png", "svg"] } else { &["png"] };
        for ext in formats {
            render::render_state(s, &a.out.join(format!("final.{ext}")), win, 1000, &title)?;
            series::plot_energy(
                &out.series,
                &a.out.join(format!("energy.{ext}")),
                &format!("{}: energy budget", scene.name),
            )?;
            if scene.sheet.is_some() {
                series::plot_force(
                    &out.series,
                    &a.out.join(format!("force.{ext}")),
                    &format!("{}: ridging force", scene.name),
                )?;
            }
        }
    }
    if figures && interval > 0.0 {
        // The animation of the snapshots (`pressridge animate` on this run).
        let gif = a.out.join("ridge.gif");
        let opts = pressridge::plot::animate::AnimateOptions {
            fps: 4,
            width_px: 800,
            mp4: None,
        };
        pressridge::plot::animate::animate(&a.out, &gif, &opts)?;
    }
    let sm = &out.summary;
    let e = sm.energy();
    println!(
        "{}: {:.1} s simulated in {} steps of {:.3e} s ({:.1} s wall, {:.0} steps/s), {} blocks broken",
        sm.scene,
        sm.time,
        sm.steps,
        sm.dt,
        sm.wall_seconds,
        sm.steps as f64 / sm.wall_seconds.max(1e-9),
        sm.blocks_broken
    );
    println!(
        "work {:.4e} J/m, ΔPE {:.4e} J/m (ratio {:.2}), friction {:.4e}, viscous {:.4e}, drag {:.4e}, other {:.4e}, residual {:.2e} J/m (max relative {:.1e})",
        e.work,
        e.potential_energy,
        sm.ratio_work_to_pe,
        e.friction_dissipation,
        e.viscous_dissipation,
        e.drag_dissipation,
        e.other_dissipation,
        e.residual,
        sm.max_relative_residual
    );
    if let Some(x) = sm.sheet_overrun_max {
        let reach = rafting::reach_in(&scene, rafting::RAFTING_REACH);
        println!("{}", rafting::verdict(x, reach));
    }
    println!("wrote {}", a.out.display());
    Ok(())
}
