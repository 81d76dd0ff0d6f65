//! Where the joints break in the first seconds of the Figure 5 scene, at several time steps
//! (docs/notes/speed-vs-error-former-model.md, "Fracture and the time step"): in the pushed
//! sheet (both blocks
//! still of the sheet when the joint severs), in the floe, or in rubble (a piece already broken
//! off). Prints, per time-step safety factor, the joints severed in each, summed over seeds,
//! and the contacts born overlapping (handed over from a severed joint or landing on a block
//! they already overlap; `World::handovers`).
//!
//! ```sh
//! cargo run --release --example fracture_where -- [DURATION_S] [SEEDS] [KEY=VALUE ...]
//! cargo run --release --example fracture_where -- 40 6 sheet.thickness=0.45 sheet.block_width=0.30
//! ```

use pressridge::dem::Role;
use pressridge::scene::Scene;

const SAFETIES: [f64; 3] = [0.125, 0.5, 0.8];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let duration: f64 = args.first().map_or(Ok(40.0), |s| s.parse())?;
    let seeds: u64 = args.get(1).map_or(Ok(6), |s| s.parse())?;
    let extra = args.get(2..).unwrap_or_default();
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes/figure5.toml");
    println!(
        "| Δt / limit | seeds | in the sheet | in the floe | in rubble | contacts born overlapping | per seed (sheet/floe/rubble) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for safety in SAFETIES {
        let (mut sheet, mut floe, mut rubble, mut born) = (0, 0, 0, 0);
        let mut per = vec![];
        for seed in 1..=seeds {
            let mut sets = vec![
                format!("numerics.time_step_safety={safety}"),
                format!("seed={seed}"),
            ];
            sets.extend(extra.iter().cloned());
            let mut w = Scene::load(Some(&path), &sets)?.build()?;
            let (mut s, mut f, mut r) = (0, 0, 0);
            while w.time() < duration {
                // Roles before the step: a severing may split a piece off within it.
                let intact: Vec<(bool, Role)> = w
                    .joints()
                    .iter()
                    .map(|j| (j.is_intact(), w.bodies().role[j.a as usize]))
                    .collect();
                w.step();
                for (j, (was, role)) in w.joints().iter().zip(intact) {
                    if was && !j.is_intact() {
                        match role {
                            Role::Sheet => s += 1,
                            Role::Floe => f += 1,
                            _ => r += 1,
                        }
                    }
                }
            }
            born += w.handovers().count;
            sheet += s;
            floe += f;
            rubble += r;
            per.push(format!("{s}/{f}/{r}"));
        }
        println!(
            "| {safety} | {seeds} | {sheet} | {floe} | {rubble} | {born} | {} |",
            per.join(", ")
        );
    }
    Ok(())
}
