//! Which breaks a larger time step adds (docs/speed-vs-error.md, "Which joints the step
//! adds"): the committed step study's records show the extra joints of 0.8 and the full
//! limit all in single-block rubble pieces. This program runs the Figure 5 scene at several
//! steps and logs every severed joint: where (in the sheet, the floe or a rubble piece,
//! by the role of its blocks just before), the sizes in blocks of the two pieces it leaves
//! (the sheet counts as one long piece), when and under which elastic surface stresses
//! its crack started, the height of the joint above the water line and its distance from the floe's
//! nose, and the contacts on the smaller side's blocks at that moment.
//!
//! Prints per step the breaks per seed by where and by the smaller side's size (1, 2, 3,
//! ≥ 4 blocks), and writes every break to `OUT.csv`. Runs are spread over `THREADS`
//! threads, one run per thread; same seed ⇒ same bits whatever the thread count.
//!
//! ```sh
//! cargo run --release --example fracture_pieces -- DURATION_S SEEDS SAFETY[,SAFETY...] THREADS OUT.csv [KEY=VALUE ...]
//! cargo run --release --example fracture_pieces -- 400 8 0.25,1.0 2 runs/pieces.csv
//! ```

use pressridge::dem::{Role, World};
use pressridge::scene::Scene;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

/// One severed joint.
struct Break {
    time: f64,
    /// When its crack started (s).
    started: f64,
    /// "sheet", "floe" or "rubble".
    place: &'static str,
    /// Sizes in blocks of the pieces on the joint's two sides after the break (the smaller
    /// first); the sheet's side counts as `u32::MAX`.
    sides: (u32, u32),
    /// Elastic stresses (Pa) at the step the crack started: top, bottom.
    stress: (f64, f64),
    /// Height of the joint's centre above the water line (m) and its distance from the
    /// floe's nose (m, positive over the floe).
    y: f64,
    x_nose: f64,
    /// Contacts on the smaller side's blocks at the break.
    contacts: usize,
}

/// The blocks joined to `start` by intact joints.
fn piece(w: &World, start: u32) -> Vec<u32> {
    let mut seen = vec![start];
    let mut k = 0;
    while k < seen.len() {
        let x = seen[k];
        for j in w.joints().iter().filter(|j| j.is_intact()) {
            let other = if j.a == x {
                j.b
            } else if j.b == x {
                j.a
            } else {
                continue;
            };
            if !seen.contains(&other) {
                seen.push(other);
            }
        }
        k += 1;
    }
    seen
}

fn run(path: &std::path::Path, sets: &[String], duration: f64) -> Result<Vec<Break>, String> {
    let scene = Scene::load(Some(path), sets).map_err(|e| e.to_string())?;
    let mut w = scene.build().map_err(|e| e.to_string())?;
    // The floe's nose: the left face of its first block at the start.
    let b = w.bodies();
    let nose = (0..b.len())
        .filter(|&i| b.role[i] == Role::Floe)
        .map(|i| b.pos[i].x - 0.5 * b.block[i].map_or(0.0, |k| k.width))
        .fold(f64::INFINITY, f64::min);
    let level = w.params().water.as_ref().map_or(0.0, |x| x.level);
    let mut roles: Vec<Role> = w.bodies().role.clone();
    let mut started: Vec<(f64, f64)> = vec![(0.0, 0.0); w.joints().len()];
    let mut intact: Vec<bool> = w.joints().iter().map(|j| j.is_intact()).collect();
    let mut broken = w.blocks_broken();
    let mut out = vec![];
    while w.time() < duration {
        w.step();
        if let Some(e) = w.fault() {
            return Err(e.to_string());
        }
        let joints = w.joints();
        started.resize(joints.len(), (0.0, 0.0));
        intact.resize(joints.len(), true);
        for (k, j) in joints.iter().enumerate() {
            // The stresses at the step a crack starts (`crack_started` is that step's time).
            if j.crack_started >= 0.0 && started[k] == (0.0, 0.0) && intact[k] {
                started[k] = (j.stress.top, j.stress.bottom);
            }
        }
        if w.blocks_broken() == broken {
            continue;
        }
        broken = w.blocks_broken();
        for k in 0..joints.len() {
            let j = joints[k];
            if !intact[k] || j.is_intact() {
                continue;
            }
            intact[k] = false;
            let place = match roles[j.a as usize] {
                Role::Sheet if roles[j.b as usize] == Role::Sheet => "sheet",
                Role::Floe => "floe",
                _ => "rubble",
            };
            let size = |x: u32| {
                let p = piece(&w, x);
                if p.iter()
                    .any(|&i| w.bodies().role[i as usize] == Role::Sheet)
                {
                    (u32::MAX, p)
                } else {
                    (p.len() as u32, p)
                }
            };
            let (na, pa) = size(j.a);
            let (nb, pb) = size(j.b);
            let small = if na <= nb { &pa } else { &pb };
            let contacts = w
                .contacts()
                .iter()
                .filter(|c| {
                    small.contains(&((c.key >> 32) as u32)) || small.contains(&(c.key as u32))
                })
                .count();
            let bd = w.bodies();
            let centre = bd.pos[j.a as usize]
                + j.pa
                    .rotate(bd.theta[j.a as usize].cos(), bd.theta[j.a as usize].sin());
            out.push(Break {
                time: w.time(),
                started: j.crack_started,
                place,
                sides: (na.min(nb), na.max(nb)),
                stress: started[k],
                y: centre.y - level,
                x_nose: centre.x - nose,
                contacts,
            });
        }
        roles.clone_from(&w.bodies().role);
    }
    Ok(out)
}

/// The CSV's header line.
const HEADER: &str = "safety,seed,time_s,crack_started_s,place,small_side,large_side,stress_top_pa,stress_bottom_pa,y_m,x_from_nose_m,contacts\n";

/// The CSV rows of one run's breaks.
fn rows(safety: f64, seed: u64, breaks: &[Break]) -> String {
    let mut text = String::new();
    for b in breaks {
        let large = if b.sides.1 == u32::MAX {
            "sheet".to_string()
        } else {
            b.sides.1.to_string()
        };
        let _ = writeln!(
            text,
            "{safety},{seed},{:.4},{:.5},{},{},{large},{:.0},{:.0},{:.3},{:.3},{}",
            b.time,
            b.started,
            b.place,
            b.sides.0,
            b.stress.0,
            b.stress.1,
            b.y,
            b.x_nose,
            b.contacts
        );
    }
    text
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: fracture_pieces DURATION_S SEEDS SAFETY[,SAFETY...] THREADS OUT.csv [KEY=VALUE ...]";
    if args.len() < 5 {
        return Err(usage.into());
    }
    let duration: f64 = args[0].parse()?;
    let seeds: u64 = args[1].parse()?;
    let safeties: Vec<f64> = args[2]
        .split(',')
        .map(|s| s.parse())
        .collect::<Result<_, _>>()?;
    let threads: usize = args[3].parse()?;
    let csv = std::path::PathBuf::from(&args[4]);
    let extra = &args[5..];
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/scenes/figure5.toml");
    // Seed by seed over the steps, each run's rows appended to OUT.csv.partial as it ends,
    // so that a stopped study keeps its finished runs.
    let jobs: Vec<(f64, u64)> = (1..=seeds)
        .flat_map(|seed| safeties.iter().map(move |&s| (s, seed)))
        .collect();
    let partial = csv.with_extension("csv.partial");
    std::fs::write(&partial, HEADER)?;
    let partial_lock = Mutex::new(());
    let results: Mutex<BTreeMap<usize, Result<Vec<Break>, String>>> = Mutex::default();
    let next = AtomicUsize::new(0);
    std::thread::scope(|sc| {
        for _ in 0..threads.max(1) {
            sc.spawn(|| {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(&(safety, seed)) = jobs.get(k) else {
                        break;
                    };
                    let mut sets = vec![
                        format!("numerics.time_step_safety={safety}"),
                        format!("seed={seed}"),
                    ];
                    sets.extend(extra.iter().cloned());
                    let r = run(&path, &sets, duration);
                    eprintln!(
                        "safety {safety} seed {seed}: {}",
                        match &r {
                            Ok(b) => format!("{} breaks", b.len()),
                            Err(e) => e.clone(),
                        }
                    );
                    if let Ok(b) = &r {
                        let _guard = partial_lock.lock().expect("no worker panics");
                        let append = std::fs::OpenOptions::new()
                            .append(true)
                            .open(&partial)
                            .and_then(|mut f| {
                                std::io::Write::write_all(&mut f, rows(safety, seed, b).as_bytes())
                            });
                        if let Err(e) = append {
                            eprintln!("{}: {e}", partial.display());
                        }
                    }
                    results.lock().expect("no worker panics").insert(k, r);
                }
            });
        }
    });
    let results = results.into_inner()?;
    let mut text = String::from(HEADER);
    // Per safety: breaks per seed by place and by the smaller side's size.
    let mut table: BTreeMap<(u64, &str), f64> = BTreeMap::new();
    for (k, r) in results {
        let (safety, seed) = jobs[k];
        let breaks = r?;
        text.push_str(&rows(safety, seed, &breaks));
        for b in &breaks {
            let size = match b.sides.0 {
                1 => "1",
                2 => "2",
                3 => "3",
                _ => "≥ 4",
            };
            *table.entry((safety.to_bits(), b.place)).or_default() += 1.0;
            *table.entry((safety.to_bits(), size)).or_default() += 1.0;
        }
    }
    std::fs::write(&csv, text)?;
    let cols = ["sheet", "floe", "rubble", "1", "2", "3", "≥ 4"];
    println!(
        "| Δt / limit | seeds | in the sheet | in the floe | in rubble | smaller side 1 block | 2 | 3 | ≥ 4 |"
    );
    println!("|---|---|---|---|---|---|---|---|---|");
    for &s in &safeties {
        print!("| {s} | {seeds} |");
        for c in cols {
            let n = table.get(&(s.to_bits(), c)).copied().unwrap_or(0.0);
            print!(" {:.1} |", n / seeds as f64);
        }
        println!();
    }
    println!("\nBreaks per seed; every break in {}.", csv.display());
    Ok(())
}
