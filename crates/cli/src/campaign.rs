//! `pressridge campaign`: a seeded ensemble over a parameter grid, resumable.

use crate::BoxError;
use pressridge::campaign::{CampaignSpec, adopt_records, run_campaign};
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;

#[derive(clap::Args)]
pub struct Args {
    /// Campaign spec (TOML). A path in it (`scene = "..."`) is resolved relative to the
    /// directory of the spec file, not to the working directory. The paper's sets
    /// (data/campaigns/thickness.toml and the others) are 14-56 runs of 100-400 s each,
    /// hours on a few cores; data/campaigns/tiny.toml is 4 runs of 3 s.
    #[arg(long)]
    spec: PathBuf,
    /// Result directory; re-running into the same directory skips finished runs.
    #[arg(long)]
    out: PathBuf,
    /// Worker threads (one run each); all cores by default.
    #[arg(long)]
    threads: Option<usize>,
    /// Take the finished runs of this campaign from an earlier result directory or a
    /// records-only archive of it (e.g. `crates/lab/records/paper/<set>` committed from an interrupted
    /// campaign) instead of running them again: their records are copied into `--out`
    /// (without final states). Repeatable.
    #[arg(long, value_name = "DIR")]
    resume_from: Vec<PathBuf>,
}

pub fn run(a: Args) -> Result<(), BoxError> {
    let spec = CampaignSpec::read(&a.spec)?;
    let base_dir = a.spec.parent().map(|p| p.to_path_buf()).unwrap_or_default();
    let plan = spec.plan(&base_dir)?;
    for dir in &a.resume_from {
        let n = adopt_records(&spec, &base_dir, &a.out, dir)?;
        eprintln!("{n} finished runs taken from {}", dir.display());
    }
    let total_sim: f64 = plan.iter().map(|p| p.scene.duration).sum();
    let threads = a
        .threads
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let progress = crate::progress::Progress::new(
        total_sim,
        "s simulated",
        pressridge::eta::Model::ConstantRate,
    );
    // Runs already on disk count as done for the bar.
    let skipped_sim = std::sync::Mutex::new(None::<f64>);
    let stop = AtomicBool::new(false);
    let (skipped, done) = run_campaign(
        &spec,
        &base_dir,
        &a.out,
        threads,
        &|p| {
            let mut s = skipped_sim.lock().expect("lock");
            let base = *s.get_or_insert(p.skipped as f64 / p.total.max(1) as f64 * total_sim);
            let done = base + p.simulated;
            progress.update_resumed(done, || {
                (
                    format!(
                        "{} of {} runs done, {done:.0} of {total_sim:.0} s simulated",
                        p.skipped + p.done,
                        p.total
                    ),
                    format!("{} skipped (already on disk), {threads} threads", p.skipped),
                )
            });
        },
        &stop,
    )?;
    progress.finish();
    println!(
        "{}: {} runs ({} already done, {} run now) in {}",
        spec.name,
        plan.len(),
        skipped,
        done,
        a.out.display()
    );
    Ok(())
}
