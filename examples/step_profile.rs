//! Steps a saved state (a `state.json` or a snapshot of `pressridge simulate`) for a number
//! of steps and reports the cost per step, the bodies, the candidate pairs (overlapping
//! bounding boxes) and the contacts: the workload of `perf record` profiles.
//!
//! ```sh
//! cargo run --release --example step_profile -- runs/default/snapshots/t00250.json 20000
//! ```

use pressridge::dem::World;
use pressridge::io::state::load_state;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let path = args
        .get(1)
        .ok_or("usage: step_profile STATE.json [STEPS]")?;
    let steps: u64 = args.get(2).map_or(Ok(20_000), |s| s.parse())?;
    let snap = load_state(std::path::Path::new(path))?;
    let mut w = World::from_snapshot(&snap)?;
    let n = w.bodies().len();
    let mut candidates = 0;
    for a in 0..n {
        for b in a + 1..n {
            if w.bodies().aabb[a].overlaps(&w.bodies().aabb[b]) {
                candidates += 1;
            }
        }
    }
    let t0 = std::time::Instant::now();
    for _ in 0..steps {
        w.step();
    }
    let s = t0.elapsed().as_secs_f64();
    println!(
        "{n} bodies, {} joints, {} contacts, ~{candidates} box pairs at the start; \
         {steps} steps of {:.3e} s in {s:.2} s: {:.1} µs/step",
        w.joints().len(),
        w.contacts().len(),
        w.dt(),
        1e6 * s / steps as f64
    );
    if let Some(e) = w.fault() {
        println!("fault: {e}");
    }
    Ok(())
}
