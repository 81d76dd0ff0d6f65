//! What a simulated second costs as the ridge grows (docs/performance.md, "Cost against
//! work"): runs the Figure 5 scene (`data/scenes/figure5.toml`, with `KEY=VALUE` overrides)
//! and, for every `INTERVAL` of simulated time, measures the wall time the steps took and
//! the work they held: the steps, the bodies and the contacts (means over the interval's
//! steps, counted every 64 steps). Writes one CSV row per interval and prints the run's
//! totals: wall seconds, steps per second and nanoseconds per body-step.
//!
//! The clock reads only the steps (no output is written while they run); run it on an idle
//! core (`taskset -c 0`) and give the machine and its load beside the numbers.
//!
//! ```sh
//! cargo run --release --example cost_vs_work -- DURATION_S INTERVAL_S OUT.csv [KEY=VALUE ...]
//! cargo run --release --example cost_vs_work -- 400 25 runs/cost-030.csv sheet.thickness=0.30
//! ```

use pressridge::scene::Scene;
use std::fmt::Write as _;
use std::time::Instant;

/// Steps between two counts of the bodies and contacts.
const COUNT_EVERY: u64 = 64;

/// One interval of simulated time.
struct Interval {
    /// End of the interval (s, simulated).
    time: f64,
    /// Wall time of its steps (s).
    wall: f64,
    steps: u64,
    /// Mean number of bodies and of contacts over the interval's counted steps.
    bodies: f64,
    contacts: f64,
}

impl Interval {
    /// Nanoseconds of wall time per body and step.
    fn ns_per_body_step(&self) -> f64 {
        1e9 * self.wall / (self.steps as f64 * self.bodies)
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 3 {
        return Err("usage: cost_vs_work DURATION_S INTERVAL_S OUT.csv [KEY=VALUE ...]".into());
    }
    let duration: f64 = args[0].parse()?;
    let interval: f64 = args[1].parse()?;
    if !(duration > 0.0 && interval > 0.0) {
        return Err("DURATION_S and INTERVAL_S must be positive (s)".into());
    }
    let out = std::path::PathBuf::from(&args[2]);
    let sets = args[3..].to_vec();
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes/figure5.toml");
    let scene = Scene::load(Some(&path), &sets)?;
    let mut w = scene.build()?;
    let mut rows: Vec<Interval> = vec![];
    let mut next = interval;
    while w.time() < duration - 0.5 * w.dt() {
        let (mut steps, mut counted, mut bodies, mut contacts) = (0u64, 0u64, 0.0, 0.0);
        let start = Instant::now();
        while w.time() < next.min(duration) - 0.5 * w.dt() {
            w.step();
            steps += 1;
            if steps % COUNT_EVERY == 1 {
                counted += 1;
                bodies += w.bodies().len() as f64;
                contacts += w.contacts().len() as f64;
            }
        }
        let wall = start.elapsed().as_secs_f64();
        if let Some(e) = w.fault() {
            return Err(e.to_string().into());
        }
        let n = counted.max(1) as f64;
        let row = Interval {
            time: w.time(),
            wall,
            steps,
            bodies: bodies / n,
            contacts: contacts / n,
        };
        eprintln!(
            "t = {:6.1} s: {:6.2} s wall, {} steps, {:.0} bodies, {:.0} contacts, {:.0} ns/body-step",
            row.time,
            row.wall,
            row.steps,
            row.bodies,
            row.contacts,
            row.ns_per_body_step()
        );
        rows.push(row);
        next += interval;
    }
    let mut csv =
        String::from("time_s,wall_s,steps,bodies,contacts,wall_per_simulated_s,ns_per_body_step\n");
    let mut t0 = 0.0;
    for r in &rows {
        writeln!(
            csv,
            "{:.3},{:.4},{},{:.1},{:.1},{:.5},{:.1}",
            r.time,
            r.wall,
            r.steps,
            r.bodies,
            r.contacts,
            r.wall / (r.time - t0),
            r.ns_per_body_step()
        )?;
        t0 = r.time;
    }
    // Written beside and renamed, so that a stopped program leaves no half-written file.
    let tmp = out.with_extension("csv.partial");
    std::fs::write(&tmp, csv)?;
    std::fs::rename(&tmp, &out)?;
    let wall: f64 = rows.iter().map(|r| r.wall).sum();
    let steps: u64 = rows.iter().map(|r| r.steps).sum();
    let body_steps: f64 = rows.iter().map(|r| r.steps as f64 * r.bodies).sum();
    println!(
        "{}: {:.1} s wall, {} steps, {:.0} steps/s, {:.0} ns per body-step, {:.0} bodies at the end",
        sets.join(" "),
        wall,
        steps,
        steps as f64 / wall,
        1e9 * wall / body_steps,
        rows.last().map_or(0.0, |r| r.bodies)
    );
    Ok(())
}
