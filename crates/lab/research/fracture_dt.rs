//! Joints broken against the time step (docs/notes/speed-vs-error-former-model.md, "Fracture
//! and the time
//! step"): reads a campaign of the fracture-dt kind (`data/campaigns/speed-vs-error/`) and
//! prints, per step (`numerics.time_step_safety` or a fixed `numerics.time_step`) and per
//! setting of its other axes, the joints broken by each seed, their mean with its 95 %
//! Student-t interval, and the mean's difference from the first row's with its 95 % Welch
//! interval (`table::ensemble::Stat`). With a second directory, the first row of that one is
//! the baseline instead (e.g. the finest step of fracture-dt for fracture-strength).
//! A second table gives, per row, the end of the energy budget against the baseline's:
//! the difference of the means of W, ΔPE and the dissipations (J/m) in % of the baseline's
//! mean, with its 95 % Welch interval.
//!
//! ```sh
//! cargo run --release --example fracture_dt -- [DIR [BASE_DIR]]   # default crates/lab/records/speed-vs-error/fracture-dt
//! ```

use pressridge::campaign::read_campaign;
use pressridge::table::ensemble::Stat;
use std::collections::BTreeMap;

/// Per run: seed, joints broken, then the budget's [`BUDGET`] terms at the end (J/m).
type Run = (u64, u64, [f64; 6]);
/// The first run's Δt (s) and every run.
type Point = (f64, Vec<Run>);
/// The energy-budget terms of the second table.
const BUDGET: [&str; 6] = [
    "W",
    "ΔPE",
    "Φ_f",
    "Φ_i (contact dashpot)",
    "joint dashpot",
    "drag",
];
/// A row: fixed Δt or not, the Δt or safety factor (as its bits, ordered like the value),
/// the settings of the other axes.
type Row = (bool, u64, String);

/// The rows of a campaign directory, in order.
fn rows(dir: &str) -> Result<BTreeMap<Row, Point>, Box<dyn std::error::Error>> {
    let c = read_campaign(std::path::Path::new(dir), true)?;
    // A safety factor gives each seed a slightly different Δt: the row keeps the first.
    let mut points: BTreeMap<Row, Point> = BTreeMap::new();
    for r in &c.records {
        let n = &r.scene.numerics;
        let fixed = n.time_step > 0.0;
        let key = if fixed {
            n.time_step
        } else {
            n.time_step_safety
        };
        let others: Vec<&str> = r
            .settings
            .iter()
            .map(String::as_str)
            .filter(|s| !s.starts_with("numerics.time_step"))
            .collect();
        let p = points
            .entry((fixed, key.to_bits(), others.join(", ")))
            .or_insert((r.summary.dt, vec![]));
        let m = r.summary.energy();
        p.1.push((
            r.seed,
            r.summary.blocks_broken,
            [
                m.work,
                m.potential_energy,
                m.friction_dissipation,
                m.viscous_dissipation,
                m.joint_dissipation,
                m.drag_dissipation,
            ],
        ));
    }
    if points.is_empty() {
        return Err(format!("no run records in {dir}").into());
    }
    Ok(points)
}

/// The mean and interval of a row's joints broken, and its runs sorted by seed.
fn stat(runs: &mut [Run]) -> Stat {
    runs.sort_by_key(|r| r.0);
    let xs: Vec<f64> = runs.iter().map(|r| r.1 as f64).collect();
    Stat::of(&xs)
}

/// The mean and interval of each budget term over a row's runs.
fn budget(runs: &[Run]) -> Vec<Stat> {
    (0..BUDGET.len())
        .map(|k| Stat::of(&runs.iter().map(|r| r.2[k]).collect::<Vec<_>>()))
        .collect()
}

/// `s`'s difference from `b` in % of `b`'s mean, with its 95 % Welch interval.
fn percent(b: &Stat, s: &Stat) -> String {
    let (d, h) = b.welch_difference(s);
    let pc = |x: f64| 100.0 * x / b.mean;
    format!("{:+.0} % [{:+.0}, {:+.0}]", pc(d), pc(d - h), pc(d + h))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = args
        .first()
        .cloned()
        .unwrap_or_else(|| "crates/lab/records/speed-vs-error/fracture-dt".into());
    let points = rows(&dir)?;
    let (mut base, mut base_budget) = match args.get(1) {
        Some(b) => {
            let (_, (_, mut runs)) = rows(b)?.into_iter().next().expect("rows() is not empty");
            (Some(stat(&mut runs)), Some(budget(&runs)))
        }
        None => (None, None),
    };
    let mut budget_rows = Vec::new();
    println!(
        "| Δt / stable limit | Δt (s) | other settings | runs | joints broken per seed | mean ± 95 % | vs baseline |"
    );
    println!("|---|---|---|---|---|---|---|");
    for ((fixed, bits, others), (dt, mut runs)) in points {
        let how = if fixed {
            "fixed".to_string()
        } else {
            f64::from_bits(bits).to_string()
        };
        let s = stat(&mut runs);
        let diff = base.as_ref().map_or("—".to_string(), |b| percent(b, &s));
        let e = budget(&runs);
        let cells: Vec<String> = match &base_budget {
            None => e.iter().map(|x| format!("{:.0}", x.mean)).collect(),
            Some(b) => b.iter().zip(&e).map(|(b, x)| percent(b, x)).collect(),
        };
        budget_rows.push(format!("| {how} | {} |", cells.join(" | ")));
        base_budget.get_or_insert(e);
        let seeds: Vec<String> = runs.iter().map(|r| r.1.to_string()).collect();
        println!(
            "| {how} | {dt:.3e} | {} | {} | {} | {:.1} ± {:.1} | {diff} |",
            if others.is_empty() { "—" } else { &others },
            s.n,
            seeds.join(", "),
            s.mean,
            s.half_width_95()
        );
        base.get_or_insert(s);
    }
    println!("\nEnergy budget at the end (J/m; against the baseline in %, 95 % Welch):\n");
    println!("| Δt / stable limit | {} |", BUDGET.join(" | "));
    println!("|---|{}", "---|".repeat(BUDGET.len()));
    for r in budget_rows {
        println!("{r}");
    }
    Ok(())
}
