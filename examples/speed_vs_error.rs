//! Speed against error of the ridging simulation (docs/performance.md).
//!
//! Runs a 60-s ridging scene at time-step safety factors of 1, 1/2 and 1/4 of the default,
//! for block widths W and W/2, and reports the wall time and the relative difference of the
//! work W, ΔPE and Φ_f from the finest run of the same width. For scale it also runs the
//! default configuration with other seeds: a ridge is a chaotic pile, so differences smaller
//! than the seed-to-seed spread are not resolved by any time step.
//!
//! `cargo run --release --example speed_vs_error [-- DURATION]`

use pressridge::scene::Scene;
use pressridge::simulation::{self, Summary};

fn run(sets: &[String]) -> Summary {
    let scene = Scene::default().with_overrides(sets).unwrap();
    simulation::run(&scene, &mut |_| true).unwrap().summary
}

fn main() {
    let duration: f64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(60.0);
    let base = Scene::default();
    let safety = base.numerics.time_step_safety;
    let w0 = base.sheet.as_ref().unwrap().block_width;
    println!(
        "| W (m) | safety | Δt (s) | steps | wall (s) | work (kJ/m) | ΔPE (kJ/m) | Φ_f (kJ/m) | err work | err ΔPE | err Φ_f |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for width in [w0, w0 / 2.0] {
        let rows: Vec<(f64, Summary)> = [1.0, 0.5, 0.25]
            .iter()
            .map(|f| {
                let s = run(&[
                    format!("duration={duration}"),
                    format!("sheet.block_width={width}"),
                    format!("numerics.time_step_safety={}", safety * f),
                ]);
                eprintln!("W {width} safety×{f}: {:.1} s wall", s.wall_seconds);
                (safety * f, s)
            })
            .collect();
        let fine = &rows.last().unwrap().1;
        let rel = |a: f64, b: f64| format!("{:+.1} %", 100.0 * (a - b) / b);
        for (sf, s) in &rows {
            println!(
                "| {width} | {sf} | {:.2e} | {} | {:.1} | {:.2} | {:.2} | {:.2} | {} | {} | {} |",
                s.dt,
                s.steps,
                s.wall_seconds,
                s.work / 1e3,
                s.potential_energy / 1e3,
                s.friction_dissipation / 1e3,
                rel(s.work, fine.work),
                rel(s.potential_energy, fine.potential_energy),
                rel(s.friction_dissipation, fine.friction_dissipation)
            );
        }
    }
    println!();
    println!("Seed-to-seed spread at the default W and Δt (seeds 1–4):");
    println!();
    println!("| seed | work (kJ/m) | ΔPE (kJ/m) | Φ_f (kJ/m) |");
    println!("|---|---|---|---|");
    for seed in 1..=4 {
        let s = run(&[format!("duration={duration}"), format!("seed={seed}")]);
        println!(
            "| {seed} | {:.2} | {:.2} | {:.2} |",
            s.work / 1e3,
            s.potential_energy / 1e3,
            s.friction_dissipation / 1e3
        );
    }
}
