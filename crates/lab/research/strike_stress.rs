//! A rubble piece struck by a block, at several time steps
//! (docs/notes/speed-vs-error-former-model.md, "Fracture
//! and the time step"): does the peak stress a contact impact puts into a piece's joints depend
//! on the step?
//!
//! A free piece of three 0.30 m × 0.45 m blocks joined end to end (the Figure 5 sheet's
//! material, unbreakable; no gravity or water) is struck on its middle block from above by a
//! fourth block at `SPEED`. For each time-step safety factor the largest elastic stress of
//! either joint over the impact is printed, averaged over eight phases of the contact's start
//! within a step (the striker set back by eighths of the distance it closes in one step), with
//! the smallest and largest of the eight; also the largest elastic contact force k_ne·A per
//! metre, averaged the same way.
//!
//! ```sh
//! cargo run --release --example strike_stress -- [CONTACT_STIFFNESS_N_PER_M3]
//! ```

use pressridge::dem::{Block, ContactParams, Drive, JointMaterial, Role, V2, World, WorldParams};

const SAFETIES: [f64; 5] = [0.125, 0.25, 0.5, 0.8, 1.0];
/// Striker speed (m/s), of the order of the rubble's speeds in a ridge.
const SPEED: f64 = 0.5;

fn world(k_ne: f64, lift: f64) -> Result<World, Box<dyn std::error::Error>> {
    let mut w = World::new(WorldParams {
        gravity: 0.0,
        water: None,
        contact: ContactParams {
            normal_stiffness: k_ne,
            ..ContactParams::default()
        },
        ..WorldParams::default()
    })?;
    let block = Block {
        width: 0.30,
        thickness: 0.45,
        bevel: [0.02; 4],
        bevel_run: None,
    };
    let mat = JointMaterial {
        e_top: 1.0e8,
        e_bottom: 6.7e7,
        poisson: 0.3,
        damping_fraction: 0.1,
        strength_top: f64::INFINITY,
        strength_bottom: f64::INFINITY,
    };
    let mut prev = None;
    for k in 0..3 {
        let id = w.add_rect(
            block,
            V2::new(0.30 * k as f64, 0.0),
            0.0,
            Drive::FREE,
            Role::Rubble,
        )?;
        if let Some(p) = prev {
            w.join(p, id, 0.06, mat)?;
        }
        prev = Some(id);
    }
    // The striker, tilted so that a corner strikes, 1 mm above the middle block plus `lift`.
    let s = w.add_rect(
        Block {
            width: 0.30,
            thickness: 0.45,
            bevel: [0.02; 4],
            bevel_run: None,
        },
        V2::new(0.32, 0.45 + 0.001 + lift + 0.06),
        0.3,
        Drive::FREE,
        Role::Rubble,
    )?;
    w.set_velocity(s, V2::new(0.0, -SPEED), 0.0);
    Ok(w)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let k_ne: f64 = std::env::args()
        .nth(1)
        .map_or(Ok(ContactParams::default().normal_stiffness), |s| s.parse())?;
    let limit = {
        let w = world(k_ne, 0.0)?;
        w.dt() / w.params().time_step_safety
    };
    println!("contact stiffness {k_ne:e} N/m³, stable limit {limit:.3e} s\n");
    println!(
        "| Δt / limit | Δt (s) | joint stress, mean of 8 phases (kPa) | smallest, largest | elastic contact force k_ne·A, mean (kN/m) |"
    );
    println!("|---|---|---|---|---|");
    for safety in SAFETIES {
        // The full limit less a rounding margin (set_time_step refuses anything above it).
        let dt = safety * limit * (1.0 - 1e-12);
        let (mut sum, mut lo, mut hi, mut fsum) = (0.0, f64::INFINITY, f64::NEG_INFINITY, 0.0);
        for k in 0..8 {
            let mut w = world(k_ne, SPEED * dt * k as f64 / 8.0)?;
            w.set_time_step(dt)?;
            let (mut peak, mut fpeak): (f64, f64) = (0.0, 0.0);
            while w.time() < 0.1 {
                w.step();
                for j in w.joints() {
                    peak = peak.max(j.stress.top.abs()).max(j.stress.bottom.abs());
                }
                for c in w.contacts() {
                    fpeak = fpeak.max(k_ne * c.area);
                }
            }
            sum += peak;
            fsum += fpeak;
            lo = lo.min(peak);
            hi = hi.max(peak);
        }
        println!(
            "| {safety} | {dt:.3e} | {:.1} | {:.1}, {:.1} | {:.2} |",
            sum / 8e3,
            lo / 1e3,
            hi / 1e3,
            fsum / 8e3
        );
    }
    Ok(())
}
