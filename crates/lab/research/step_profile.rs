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
    // Bounding boxes (x0, x1, y0, y1) of the bodies' outlines (m).
    let boxes: Vec<[f64; 4]> = snap
        .bodies
        .iter()
        .map(|b| {
            let o = b.world_outline();
            o.verts().iter().fold(
                [
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                ],
                |[x0, x1, y0, y1], p| [x0.min(p.x), x1.max(p.x), y0.min(p.y), y1.max(p.y)],
            )
        })
        .collect();
    let mut candidates = 0;
    for (a, p) in boxes.iter().enumerate() {
        for q in &boxes[a + 1..] {
            if p[0] <= q[1] && q[0] <= p[1] && p[2] <= q[3] && q[2] <= p[3] {
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
