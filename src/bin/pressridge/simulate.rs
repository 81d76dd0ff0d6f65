//! `pressridge simulate`: run a scene and write its results.

use crate::BoxError;
use indicatif::{ProgressBar, ProgressStyle};
use pressridge::io::{series::write_energy_csv, state, write_atomic};
use pressridge::plot::{render, series::plot_energy};
use pressridge::scene::Scene;
use pressridge::simulation;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// Scene file (TOML); the built-in default scene when omitted.
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
    /// Skip the figures.
    #[arg(long)]
    no_figures: bool,
}

pub fn run(a: Args) -> Result<(), BoxError> {
    let base = match &a.scene {
        Some(p) => Scene::from_toml(
            &std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?,
        )
        .map_err(|e| format!("{}: {e}", p.display()))?,
        None => Scene::default(),
    };
    let scene = base.with_overrides(&a.sets)?;
    if a.print_scene {
        print!("{}", scene.to_toml());
        return Ok(());
    }
    std::fs::create_dir_all(&a.out).map_err(|e| format!("{}: {e}", a.out.display()))?;
    write_atomic(&a.out.join("scene.toml"), scene.to_toml().as_bytes())?;

    let bar = ProgressBar::new((scene.duration * 1000.0).round() as u64);
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {bar:40} {msg} simulated, ETA {eta}",
        )?
        .progress_chars("=> "),
    );
    let out = simulation::run(&scene, &mut |t| {
        bar.set_position((t * 1000.0) as u64);
        bar.set_message(format!("{t:.1} s"));
        true
    })?;
    bar.finish_and_clear();

    state::write_json(&a.out.join("summary.json"), &out.summary)?;
    write_energy_csv(&a.out.join("energy.csv"), &out.series)?;
    state::save_state(&a.out.join("state.json"), &out.final_state)?;
    if !a.no_figures {
        let s = &out.final_state;
        let title = format!("{} at t = {:.1} s", scene.name, s.time);
        render::render_state(
            s,
            &a.out.join("final.png"),
            render::Window::fit(s, 1.0),
            1000,
            &title,
        )?;
        plot_energy(
            &out.series,
            &a.out.join("energy.png"),
            &format!("{}: energy budget", scene.name),
        )?;
    }
    let sm = &out.summary;
    println!(
        "{}: {:.1} s simulated in {} steps of {:.3e} s ({:.1} s wall, {:.0} steps/s)",
        sm.scene,
        sm.time,
        sm.steps,
        sm.dt,
        sm.wall_seconds,
        sm.steps as f64 / sm.wall_seconds.max(1e-9)
    );
    println!(
        "work {:.4e} J/m, ΔPE {:.4e} J/m, friction {:.4e}, viscous {:.4e}, drag {:.4e}, residual {:.2e} J/m (max relative {:.1e})",
        sm.work,
        sm.potential_energy,
        sm.friction_dissipation,
        sm.viscous_dissipation,
        sm.drag_dissipation,
        sm.residual,
        sm.max_relative_residual
    );
    println!("wrote {}", a.out.display());
    Ok(())
}
