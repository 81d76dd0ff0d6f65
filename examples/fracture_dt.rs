//! Joints broken against the time step (docs/speed-vs-error.md, "Fracture and the time
//! step"): reads a campaign over `numerics.time_step_safety` (the fracture-dt campaigns of
//! `data/campaigns/speed-vs-error/`) and prints, per safety factor, the step, the joints
//! broken by each seed, their mean with its 95 % Student-t interval, and the mean's difference
//! from the smallest step's with its 95 % Welch interval (`table::ensemble::Stat`).
//!
//! ```sh
//! cargo run --release --example fracture_dt -- [DIR]   # default data/speed-vs-error/fracture-dt
//! ```

use pressridge::campaign::read_campaign;
use pressridge::table::ensemble::Stat;
use std::collections::BTreeMap;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "data/speed-vs-error/fracture-dt".into());
    let c = read_campaign(std::path::Path::new(&dir), true)?;
    // Safety factor (as its bits, ordered like the value) -> (Δt, [(seed, joints broken)]).
    let mut points: BTreeMap<u64, (f64, Vec<(u64, u64)>)> = BTreeMap::new();
    for r in &c.records {
        let safety = r.scene.numerics.time_step_safety;
        let p = points
            .entry(safety.to_bits())
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
    for (bits, (dt, mut runs)) in points {
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
            "| {} | {dt:.3e} | {} | {} | {:.1} ± {:.1} | {diff} |",
            f64::from_bits(bits),
            s.n,
            seeds.join(", "),
            s.mean,
            s.half_width_95()
        );
        base.get_or_insert(s);
    }
    Ok(())
}
