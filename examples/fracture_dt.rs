//! Joints broken against the time step (docs/speed-vs-error.md, "Fracture and the time
//! step"): reads a campaign over `numerics.time_step_safety` or `numerics.time_step` (the
//! fracture-dt campaigns of `data/campaigns/speed-vs-error/`) and prints, per step, the joints
//! broken by each seed, their mean with its 95 % Student-t interval, and the mean's difference
//! from the smallest step's with its 95 % Welch interval (`table::ensemble::Stat`).
//!
//! ```sh
//! cargo run --release --example fracture_dt -- [DIR]   # default data/speed-vs-error/fracture-dt
//! ```

use pressridge::campaign::read_campaign;
use pressridge::table::ensemble::Stat;
use std::collections::BTreeMap;

/// The first run's Δt (s) and every run's (seed, joints broken).
type Point = (f64, Vec<(u64, u64)>);

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "data/speed-vs-error/fracture-dt".into());
    let c = read_campaign(std::path::Path::new(&dir), true)?;
    // Fixed Δt or safety factor (as its bits, ordered like the value) -> (the first run's Δt,
    // [(seed, joints broken)]). A safety factor gives each seed a slightly different Δt.
    let mut points: BTreeMap<(bool, u64), Point> = BTreeMap::new();
    for r in &c.records {
        let n = &r.scene.numerics;
        let fixed = n.time_step > 0.0;
        let key = if fixed {
            n.time_step
        } else {
            n.time_step_safety
        };
        let p = points
            .entry((fixed, key.to_bits()))
            .or_insert((r.summary.dt, vec![]));
        p.1.push((r.seed, r.summary.blocks_broken));
    }
    if points.is_empty() {
        return Err(format!("no run records in {dir}").into());
    }
    println!(
        "| Δt / stable limit | Δt (s) | runs | joints broken per seed | mean ± 95 % | vs smallest Δt |"
    );
    println!("|---|---|---|---|---|---|");
    let mut base: Option<Stat> = None;
    for ((fixed, bits), (dt, mut runs)) in points {
        let how = if fixed {
            "fixed".to_string()
        } else {
            f64::from_bits(bits).to_string()
        };
        runs.sort();
        let xs: Vec<f64> = runs.iter().map(|r| r.1 as f64).collect();
        let s = Stat::of(&xs);
        let diff = match &base {
            None => "—".to_string(),
            Some(b) => {
                let (d, h) = b.welch_difference(&s);
                let pc = |x: f64| 100.0 * x / b.mean;
                format!("{:+.0} % [{:+.0}, {:+.0}]", pc(d), pc(d - h), pc(d + h))
            }
        };
        let seeds: Vec<String> = runs.iter().map(|r| r.1.to_string()).collect();
        println!(
            "| {how} | {dt:.3e} | {} | {} | {:.1} ± {:.1} | {diff} |",
            s.n,
            seeds.join(", "),
            s.mean,
            s.half_width_95()
        );
        base.get_or_insert(s);
    }
    Ok(())
}
