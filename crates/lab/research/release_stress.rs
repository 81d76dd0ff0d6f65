//! One joint released at the same moment at several time steps
//! (docs/notes/speed-vs-error-former-model.md,
//! "Fracture and the time step"): how far does the stress in the other joints overshoot when
//! a joint lets go, and does the overshoot depend on the step?
//!
//! For each time-step safety factor (0.125 … 1.0 of the stable limit) the Figure 5 scene is
//! run with unbreakable joints (strengths 10 MPa) up to the release time, where the loading has
//! converged in the step (`crates/lab/research/impact_stress.rs`). There the joint nearest to failure
//! (largest elastic stress over the scene's strength, top or bottom) is given a strength of
//! 1 Pa, so that its crack starts at once and runs across it at the crack speed, while every
//! other joint stays unbreakable. Printed: the joints' largest high-frequency stress over the
//! 0.1 s before the release (each surface stress less its 5-ms exponential average), that
//! joint, the others' largest stress over strength just before the release, and their largest
//! afterwards within the window, with its time. A ratio above 1 is a joint the release would
//! have broken.
//!
//! ```sh
//! cargo run --release --example release_stress -- [RELEASE_S] [WINDOW_S] [KEY=VALUE ...]
//! cargo run --release --example release_stress -- 2.5 0.2 sheet.thickness=0.45 sheet.block_width=0.30
//! ```

use pressridge::dem::{Snapshot, World};
use pressridge::scene::Scene;

const SAFETIES: [f64; 5] = [0.125, 0.25, 0.5, 0.8, 1.0];
/// Time over which the joints' stresses are averaged to split off their high-frequency part
/// (s): long against the top joint modes (≈ 1.6–1.9 ms), short against the flexure (≈ 0.1 s).
const SMOOTHING: f64 = 5e-3;

/// Largest elastic stress over strength among the intact joints other than `skip`, and the
/// joint that has it.
fn nearest(w: &World, strength: (f64, f64), skip: Option<usize>) -> (f64, usize) {
    let mut best = (f64::NEG_INFINITY, 0);
    for (k, j) in w.joints().iter().enumerate() {
        if Some(k) == skip || !j.is_intact() {
            continue;
        }
        let r = (j.stress.top / strength.0).max(j.stress.bottom / strength.1);
        if r > best.0 {
            best = (r, k);
        }
    }
    best
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let release: f64 = args.first().map_or(Ok(2.5), |s| s.parse())?;
    let window: f64 = args.get(1).map_or(Ok(0.2), |s| s.parse())?;
    let extra = args.get(2..).unwrap_or_default();
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes/figure5.toml");
    println!(
        "| Δt / limit | Δt (s) | high-frequency stress before (kPa) | joint released | others before (σ/S) | others after, largest (σ/S) | at (s) | released joint severed at (s) |"
    );
    println!("|---|---|---|---|---|---|---|---|");
    for safety in SAFETIES {
        let mut sets = vec![format!("numerics.time_step_safety={safety}")];
        sets.extend(extra.iter().cloned());
        let scene = Scene::load(Some(&path), &sets)?;
        let sheet = scene.sheet.ok_or("the scene has no sheet")?;
        let strength = (sheet.strength_top, sheet.strength_bottom);
        sets.push("sheet.strength_top=1e7".into());
        sets.push("sheet.strength_bottom=1e7".into());
        let mut w = Scene::load(Some(&path), &sets)?.build()?;
        // The joints' high-frequency stress over the last 0.1 s before the release: each
        // surface stress less its exponential average over `SMOOTHING` (s).
        let mut smooth: Vec<[f64; 2]> = vec![];
        let mut vibration: f64 = 0.0;
        while w.time() < release {
            w.step();
            let a = 1.0 - (-w.dt() / SMOOTHING).exp();
            smooth.resize(w.joints().len(), [f64::NAN; 2]);
            for (j, m) in w.joints().iter().zip(smooth.iter_mut()) {
                for (x, y) in [j.stress.top, j.stress.bottom]
                    .into_iter()
                    .zip(m.iter_mut())
                {
                    *y = if y.is_nan() { x } else { *y + a * (x - *y) };
                    if w.time() > release - 0.1 && j.is_intact() {
                        vibration = vibration.max((x - *y).abs());
                    }
                }
            }
        }
        let (_, k) = nearest(&w, strength, None);
        let (before, _) = nearest(&w, strength, Some(k));
        // Release joint k: its strengths to 1 Pa, through the state (the one public door).
        let mut state = serde_json::to_value(w.snapshot())?;
        for side in ["strength_top", "strength_bottom"] {
            state["joints"][k]["mat"][side] = serde_json::json!(1.0);
        }
        let snap: Snapshot = serde_json::from_value(state)?;
        let mut w = World::from_snapshot(&snap)?;
        let (mut peak, mut at, mut severed) = (f64::NEG_INFINITY, 0.0, f64::NAN);
        while w.time() < release + window {
            w.step();
            let (r, _) = nearest(&w, strength, Some(k));
            if r > peak {
                (peak, at) = (r, w.time());
            }
            if severed.is_nan() && !w.joints()[k].is_intact() {
                severed = w.time();
            }
        }
        println!(
            "| {safety} | {:.3e} | {:.1} | {k} | {before:.3} | {peak:.3} | {at:.4} | {severed:.4} |",
            w.dt(),
            vibration / 1e3
        );
    }
    Ok(())
}
