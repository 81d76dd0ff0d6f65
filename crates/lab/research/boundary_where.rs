//! Where the sheet's eq (7)–(8) dashpots dissipate (issue 30, finding (a); docs/choices.md,
//! "The other sinks"). Steps the Figure 5 scene and books k′·|v − U·x̂|²·Δt of every free
//! sheet block after each step, split by direction (x: along the push, relative to U; y:
//! heave), by distance from the sheet's tip, by time, and into a slow part (the dashpot
//! acting on each block's velocity averaged over a window) and the fast rest (vibration).
//! The total is printed beside the ledger's `boundary_dissipation` as a check.
//!
//! ```sh
//! cargo run --release --example boundary_where -- [DURATION_S] [WINDOW_S] [KEY=VALUE ...]
//! cargo run --release --example boundary_where -- 400 1.0 seed=7 contact.mu=0.4
//! ```

use pressridge::dem::Role;
use pressridge::scene::Scene;
use std::collections::HashMap;

/// Upper edges of the distance-from-tip bins (m).
const BINS: [f64; 5] = [1.0, 3.0, 6.0, 12.0, f64::INFINITY];

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let duration: f64 = args.first().map_or(Ok(400.0), |s| s.parse())?;
    let window: f64 = args.get(1).map_or(Ok(1.0), |s| s.parse())?;
    let sets = args.get(2..).unwrap_or_default().to_vec();
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes/figure5.toml");
    let scene = Scene::load(Some(&path), &sets)?;
    let sh = scene.sheet.clone().ok_or("the scene has no sheet")?;
    let visc = sh.boundary_viscosity(&scene.contact, scene.ice.density);
    let (u, decay) = (sh.speed, sh.viscous_decay);
    let mut w = scene.build()?;
    let dt = w.dt();
    let (mut bx, mut by) = ([0.0; BINS.len()], [0.0; BINS.len()]);
    // Per body over the current window: (Σ k′, Σ (u − U), Σ v, steps).
    let mut acc: HashMap<usize, (f64, f64, f64, f64)> = HashMap::new();
    let (mut slow, mut next_window) = (0.0, window);
    let mut next_print = 25.0;
    println!(
        "| t (s) | eq (7) total (kJ/m) | ledger boundary (kJ/m) | x part | y part | slow part (window {window} s) |"
    );
    println!("|---|---|---|---|---|---|");
    let flush = |acc: &mut HashMap<usize, (f64, f64, f64, f64)>, slow: &mut f64| {
        for (_, (k, du, v, n)) in acc.drain() {
            // Mean k′ times the squared mean relative velocity, over the window's steps.
            *slow += (k / n) * ((du / n).powi(2) + (v / n).powi(2)) * n * dt;
        }
    };
    while w.time() < duration {
        w.step();
        let b = w.bodies();
        let sheet: Vec<usize> = (0..b.pos.len())
            .filter(|&i| b.role[i] == Role::Sheet)
            .collect();
        let x1 = sheet
            .iter()
            .map(|&i| b.pos[i].x)
            .fold(f64::INFINITY, f64::min);
        let xn = sheet
            .iter()
            .map(|&i| b.pos[i].x)
            .fold(f64::NEG_INFINITY, f64::max);
        let span = xn - x1;
        for &i in &sheet {
            let frac = if span > 0.0 {
                (b.pos[i].x - x1) / span
            } else {
                0.0
            };
            let k = visc * (-decay * frac).exp();
            let (du, v) = (b.vel[i].x - u, b.vel[i].y);
            let bin = BINS
                .iter()
                .position(|&e| xn - b.pos[i].x < e)
                .unwrap_or(BINS.len() - 1);
            bx[bin] += k * du * du * dt;
            by[bin] += k * v * v * dt;
            let e = acc.entry(i).or_insert((0.0, 0.0, 0.0, 0.0));
            *e = (e.0 + k, e.1 + du, e.2 + v, e.3 + 1.0);
        }
        if w.time() >= next_window {
            flush(&mut acc, &mut slow);
            next_window += window;
        }
        if w.time() >= next_print || w.time() >= duration {
            let (x, y): (f64, f64) = (bx.iter().sum(), by.iter().sum());
            println!(
                "| {:.0} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} |",
                w.time(),
                (x + y) / 1e3,
                w.energy().boundary_dissipation / 1e3,
                x / 1e3,
                y / 1e3,
                slow / 1e3
            );
            next_print += 25.0;
        }
    }
    println!("\n| distance from the tip (m) | x part (kJ/m) | y part (kJ/m) |\n|---|---|---|");
    let mut lo = 0.0;
    for (k, e) in BINS.iter().enumerate() {
        println!("| {lo}–{e} | {:.1} | {:.1} |", bx[k] / 1e3, by[k] / 1e3);
        lo = *e;
    }
    let e = w.energy();
    println!(
        "\nW {:.1} kJ/m, frame work {:.1} kJ/m, drag {:.1} kJ/m, joints {:.1} kJ/m",
        e.work / 1e3,
        e.frame_work / 1e3,
        e.drag_dissipation / 1e3,
        e.joint_dissipation / 1e3
    );
    Ok(())
}
