//! The sheet's first failure against the floe at several time steps
//! (docs/notes/speed-vs-error-former-model.md,
//! "Fracture and the time step"): is the step's effect on fracture in the loading or in the
//! failure itself?
//!
//! For each time-step safety factor (0.125 … 1.0 of the stable limit) the Figure 5 scene is
//! run twice for a short time: once with the joints made unbreakable (strengths 10 MPa, the
//! largest a scene accepts), printing the largest elastic tensile stress at either end of any
//! joint's intact span, the quantity the fracture test compares with the strength; and once
//! as it is, printing the time of each joint's severing. The first seconds are not yet
//! chaotic (one push against the floe), so differences between the rows are the step's own.
//!
//! ```sh
//! cargo run --release --example impact_stress -- [DURATION_S] [KEY=VALUE ...]
//! cargo run --release --example impact_stress -- 4 sheet.thickness=0.45 sheet.block_width=0.30
//! ```

use pressridge::dem::World;
use pressridge::scene::Scene;

const SAFETIES: [f64; 5] = [0.125, 0.25, 0.5, 0.8, 1.0];

fn world(
    safety: f64,
    extra: &[String],
    unbreakable: bool,
) -> Result<World, Box<dyn std::error::Error>> {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes/figure5.toml");
    let mut sets = vec![format!("numerics.time_step_safety={safety}")];
    if unbreakable {
        sets.push("sheet.strength_top=1e7".into());
        sets.push("sheet.strength_bottom=1e7".into());
    }
    sets.extend(extra.iter().cloned());
    Ok(Scene::load(Some(&path), &sets)?.build()?)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let duration: f64 = args.first().map_or(Ok(4.0), |s| s.parse())?;
    let extra = args.get(1..).unwrap_or_default();
    let intervals = 8;
    println!(
        "Unbreakable joints: largest elastic stress (kPa), overall and per {:.2} s\n",
        duration / intervals as f64
    );
    println!("| Δt / limit | Δt (s) | largest | per interval |\n|---|---|---|---|");
    for safety in SAFETIES {
        let mut w = world(safety, extra, true)?;
        let mut peaks = vec![0.0f64; intervals];
        while w.time() < duration {
            w.step();
            let k = ((w.time() / duration * intervals as f64) as usize).min(intervals - 1);
            for j in w.joints().iter().filter(|j| j.is_intact()) {
                peaks[k] = peaks[k].max(j.stress.top).max(j.stress.bottom);
            }
        }
        let max = peaks.iter().cloned().fold(0.0, f64::max);
        let per: Vec<String> = peaks.iter().map(|p| format!("{:.0}", p / 1e3)).collect();
        println!(
            "| {safety} | {:.3e} | {:.0} | {} |",
            w.dt(),
            max / 1e3,
            per.join(", ")
        );
    }
    println!("\nAs it is: the time (s) of each joint's severing\n");
    println!("| Δt / limit | joints severed | at (s) |\n|---|---|---|");
    for safety in SAFETIES {
        let mut w = world(safety, extra, false)?;
        let mut times = vec![];
        while w.time() < duration {
            w.step();
            while (times.len() as u64) < w.blocks_broken() {
                times.push(format!("{:.3}", w.time()));
            }
        }
        println!("| {safety} | {} | {} |", times.len(), times.join(", "));
    }
    Ok(())
}
