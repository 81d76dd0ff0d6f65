//! When the breaks a larger step adds happen (docs/speed-vs-error.md, "When the added breaks
//! happen"): reads a break log of `fracture_pieces` (`OUT.csv`: one row per severed joint,
//! with its step's safety factor, seed, time and the pieces it leaves) and splits each run's
//! breaks by whether another joint of the same run severed within `WINDOW` seconds before it
//! ("after": the second and later breaks of a cascade) or not ("alone"), and by whether the
//! smaller piece it leaves is a single block; a second table splits them by where the joint
//! was (the sheet, the rubble, the floe). Prints, per class, the reference's mean per run
//! (the first safety factor of the log, or `REF`) and each other factor's difference with its
//! 95 % Welch interval; and the share of the run's time that windows from `LEAD` seconds before
//! each break to `WINDOW` after it cover (what a step refined only there would cost).
//!
//! ```sh
//! cargo run --release --example break_windows -- crates/lab/records/speed-vs-error/pieces-r2/breaks.csv [WINDOW_S] [LEAD_S] [REF]
//! cargo run --release --example break_windows -- crates/lab/records/speed-vs-error/pieces-r2/breaks.csv 0.010 0.006 0.25
//! cargo run --release --example break_windows -- LOG[+NAME=LOG ...] [WINDOW_S] [LEAD_S] [REF]
//! ```
//!
//! Several logs joined by `+` are read each by its own header; a log given as `NAME=LOG` has
//! its runs labelled NAME instead of by their safety factor (the refined step's logs at the
//! full limit beside the plain full limit's):
//!
//! ```sh
//! cargo run --release --example break_windows -- crates/lab/records/speed-vs-error/pieces-r2/breaks.csv+refine-10ms=crates/lab/records/speed-vs-error/pieces-r2/breaks-refine10.csv+refine-50ms=crates/lab/records/speed-vs-error/pieces-r2/breaks-refine50.csv 0.010 0.006 0.25
//! ```

use pressridge::table::fit::student_t_quantile;
use std::collections::BTreeMap;

/// One severed joint: its time (s), whether it leaves a single block, and where it was
/// (sheet, floe or rubble, as the log names it).
struct Break {
    time: f64,
    single: bool,
    place: String,
}

/// The classes of the second table: where the joint was and what it leaves.
const PLACES: [&str; 5] = [
    "sheet, single block",
    "sheet, longer",
    "rubble, single block",
    "rubble, longer",
    "floe",
];

/// Per-run counts of each class of `PLACES`.
fn by_place(run: &[Break]) -> [f64; 5] {
    let mut n = [0.0; 5];
    for b in run {
        let k = match (b.place.as_str(), b.single) {
            ("sheet", true) => 0,
            ("sheet", false) => 1,
            ("rubble", true) => 2,
            ("rubble", false) => 3,
            _ => 4,
        };
        n[k] += 1.0;
    }
    n
}

/// The classes of a run's breaks, in print order.
const CLASSES: [&str; 5] = [
    "single block, after",
    "single block, alone",
    "longer, after",
    "longer, alone",
    "all",
];

/// Per-run counts of each class of `CLASSES` and the windows' share of the time (%).
fn classify(run: &mut [Break], window: f64, lead: f64, duration: f64) -> ([f64; 5], f64) {
    run.sort_by(|a, b| a.time.total_cmp(&b.time));
    let mut n = [0.0; 5];
    for (i, b) in run.iter().enumerate() {
        let after = i > 0 && b.time - run[i - 1].time <= window;
        let k = match (b.single, after) {
            (true, true) => 0,
            (true, false) => 1,
            (false, true) => 2,
            (false, false) => 3,
        };
        n[k] += 1.0;
        n[4] += 1.0;
    }
    // The union of [t − lead, t + window] over the breaks, as a share of the run.
    let (mut covered, mut end) = (0.0, f64::NEG_INFINITY);
    for b in run.iter() {
        let (s, e) = (b.time - lead, b.time + window);
        covered += (e - s.max(end)).max(0.0).min(e - s);
        end = end.max(e);
    }
    (n, 100.0 * covered / duration)
}

fn mean_var(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let m = x.iter().sum::<f64>() / n;
    (
        m,
        x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0),
    )
}

/// Difference of means b − a with its 95 % Welch interval.
fn welch(a: &[f64], b: &[f64]) -> String {
    let ((ma, va), (mb, vb)) = (mean_var(a), mean_var(b));
    let (sa, sb) = (va / a.len() as f64, vb / b.len() as f64);
    let se = (sa + sb).sqrt();
    let dof =
        (sa + sb).powi(2) / (sa * sa / (a.len() as f64 - 1.0) + sb * sb / (b.len() as f64 - 1.0));
    let t = if se > 0.0 {
        student_t_quantile(0.975, dof)
    } else {
        0.0
    };
    let d = mb - ma;
    format!("{d:+.1} [{:+.1}, {:+.1}]", d - t * se, d + t * se)
}

/// Reads one break log (its own header names the columns) into `runs`, each row under its
/// safety factor as written or under `name`.
fn read_log(
    path: &str,
    name: Option<&str>,
    runs: &mut BTreeMap<(String, u32), Vec<Break>>,
    order: &mut Vec<String>,
) -> Result<(), Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path)?;
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().ok_or("empty file")?.split(',').collect();
    let col = |c: &str| {
        header
            .iter()
            .position(|h| *h == c)
            .ok_or(format!("{path}: no column {c}"))
    };
    let (c_safety, c_seed, c_time, c_small, c_place) = (
        col("safety")?,
        col("seed")?,
        col("time_s")?,
        col("small_side")?,
        col("place")?,
    );
    for line in lines.filter(|l| !l.trim().is_empty()) {
        let f: Vec<&str> = line.split(',').collect();
        let label = name.map_or_else(|| f[c_safety].to_string(), str::to_string);
        if !order.contains(&label) {
            order.push(label.clone());
        }
        runs.entry((label, f[c_seed].parse()?))
            .or_default()
            .push(Break {
                time: f[c_time].parse()?,
                single: f[c_small] == "1",
                place: f[c_place].to_string(),
            });
    }
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: break_windows LOG[+NAME=LOG ...] [WINDOW_S] [LEAD_S] [REF]";
    let path = args.first().ok_or(usage)?;
    let window: f64 = args.get(1).map_or(Ok(0.010), |s| s.parse())?;
    let lead: f64 = args.get(2).map_or(Ok(0.006), |s| s.parse())?;
    // Runs by (label, seed): the label is the safety factor as written, or NAME for a log
    // given as NAME=PATH; labels in order of first appearance.
    let mut runs: BTreeMap<(String, u32), Vec<Break>> = BTreeMap::new();
    let mut order: Vec<String> = Vec::new();
    for part in path.split('+') {
        let (name, file) = match part.split_once('=') {
            Some((n, f)) => (Some(n), f),
            None => (None, part),
        };
        read_log(file, name, &mut runs, &mut order)?;
    }
    let reference = args.get(3).cloned().unwrap_or_else(|| order[0].clone());
    if !order.contains(&reference) {
        return Err(format!("{path}: no runs labelled {reference}").into());
    }
    // The runs' duration: the scene's 400 s unless a break comes later.
    let last = runs.values().flatten().map(|b| b.time).fold(0.0, f64::max);
    let duration = last.max(400.0);
    let mut per: BTreeMap<String, (Vec<[f64; 5]>, Vec<f64>)> = BTreeMap::new();
    let mut places: BTreeMap<String, Vec<[f64; 5]>> = BTreeMap::new();
    for ((safety, _), run) in runs.iter_mut() {
        let (n, share) = classify(run, window, lead, duration);
        let e = per.entry(safety.clone()).or_default();
        e.0.push(n);
        e.1.push(share);
        places
            .entry(safety.clone())
            .or_default()
            .push(by_place(run));
    }
    println!(
        "breaks per run, by whether another severed within {:.0} ms before (after) or not \
         (alone); windows from {:.0} ms before each break to {:.0} ms after it",
        window * 1e3,
        lead * 1e3,
        window * 1e3
    );
    println!();
    let (rn, rs) = &per[&reference];
    print!("| safety | runs |");
    for c in CLASSES {
        print!(" {c} |");
    }
    println!(" windows' share of the run |");
    println!("|---|---|{}---|", "---|".repeat(CLASSES.len()));
    let cell = |x: &[[f64; 5]], k: usize| x.iter().map(|n| n[k]).collect::<Vec<_>>();
    print!("| {reference} | {} |", rn.len());
    for k in 0..CLASSES.len() {
        let (m, v) = mean_var(&cell(rn, k));
        print!(" {m:.1} ± {:.1} |", v.sqrt());
    }
    println!(" {:.2} % |", mean_var(rs).0);
    for s in order.iter().filter(|s| **s != reference) {
        let (n, share) = &per[s];
        print!("| {s} | {} |", n.len());
        for k in 0..CLASSES.len() {
            print!(" {} |", welch(&cell(rn, k), &cell(n, k)));
        }
        println!(" {:.2} % |", mean_var(share).0);
    }
    println!();
    println!("breaks per run, by where the joint was and whether it leaves a single block");
    println!();
    print!("| safety | runs |");
    for c in PLACES {
        print!(" {c} |");
    }
    println!();
    println!("|---|---|{}", "---|".repeat(PLACES.len()));
    let rp = &places[&reference];
    print!("| {reference} | {} |", rp.len());
    for k in 0..PLACES.len() {
        let (m, v) = mean_var(&cell(rp, k));
        print!(" {m:.1} ± {:.1} |", v.sqrt());
    }
    println!();
    for s in order.iter().filter(|s| **s != reference) {
        let n = &places[s];
        print!("| {s} | {} |", n.len());
        for k in 0..PLACES.len() {
            print!(" {} |", welch(&cell(rp, k), &cell(n, k)));
        }
        println!();
    }
    println!();
    println!(
        "Reference rows: mean ± standard deviation over its runs; other rows: difference of \
         the means per run with its 95 % Welch interval."
    );
    Ok(())
}
