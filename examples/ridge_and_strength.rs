//! The Rust face in one program: a short ridging run of the Figure 5 scene, then the ice
//! strength of one column with C_f from the shipped ridging table.
//!
//! ```sh
//! cargo run --release --example ridge_and_strength -- [DURATION_S]
//! ```

use pressridge::itd::{Cf, StrengthOptions, Workspace, strength_column};
use pressridge::scene::Scene;
use pressridge::simulation;
use pressridge::table::lookup::RidgeLookup;
use std::path::Path;
use std::sync::Arc;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let duration: f64 = std::env::args().nth(1).map_or(Ok(20.0), |s| s.parse())?;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));

    // The paper's Figure 5 scene (0.30 m sheet, 2 m floe, mu = 1.0, mu_w = 0.6), shortened.
    let scene = Scene::load(
        Some(&root.join("data/scenes/figure5.toml")),
        &[format!("duration={duration}")],
    )?;
    let out = simulation::run(&scene, &mut |_world| true)?;
    let (s, e) = (&out.summary, out.summary.energy());
    println!(
        "{:.0} s: W = {:.1} kJ/m, dPE = {:.2} kJ/m, W/dPE = {:.1}, {} joints broken",
        s.time,
        e.work / 1e3,
        e.potential_energy / 1e3,
        s.ratio_work_to_pe,
        s.blocks_broken
    );

    // Rothrock's strength of one five-category column (areas 1, volumes m) with C_f from
    // the simulator's table at mu = 1.0, mu_w = 0.6.
    let table = RidgeLookup::open(&root.join("data/ridging_table.nc"))?;
    let set = table.friction_set(1.0, 0.6)?;
    let opts = StrengthOptions {
        cf: Cf::Table(Arc::new(table.cf_table(set)?)),
        ..StrengthOptions::default()
    };
    let (aicen, vicen) = ([0.2, 0.3, 0.2, 0.15, 0.05], [0.06, 0.3, 0.38, 0.45, 0.2]);
    let p = strength_column(&aicen, &vicen, None, &opts, &mut Workspace::new(5))?;
    println!(
        "P = {:.0} N/m (C_f clamped to the table: {})",
        p.strength, p.cf_clamped
    );
    Ok(())
}
