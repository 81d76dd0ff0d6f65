//! `pressridge redistribution`: the thickness distribution of the simulated ridged ice per
//! ensemble, with Lipscomb's μ_rdg and Hibler's H* fitted to it
//! (`pressridge::table::redistribution`, docs/tables.md).

use crate::BoxError;
use crate::findings::{pooled_records, write};
use pressridge::plot::redistribution::plot_redistribution;
use pressridge::table::redistribution::{ensembles, markdown};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct Args {
    /// A campaign directory, or a directory of campaign directories; repeatable. Runs are
    /// grouped by lead-ice thickness and friction; a run two directories share is counted
    /// once, and runs whose records predate the ridge columns are counted and left out.
    #[arg(long, required = true)]
    records: Vec<PathBuf>,
    /// Write the table here (Markdown) instead of to standard output.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Draw each ensemble's distribution with the fitted shapes into this directory, as
    /// `ridged-h<h>-mu<μ>-muw<μ_w>.png` and `.svg`.
    #[arg(long, value_name = "DIR")]
    figures: Option<PathBuf>,
}

pub fn run(a: Args) -> Result<(), BoxError> {
    let (records, dirs) = pooled_records(&a.records)?;
    let (rows, without) = ensembles(&records);
    if rows.is_empty() {
        return Err(format!(
            "--records: no run with ridge columns among {} ({} written before they were kept: run them again)",
            records.len(),
            without
        )
        .into());
    }
    let text = format!(
        "{}\nFrom {} runs of: {}{}.\n",
        markdown(&rows),
        records.len() - without,
        dirs.join(", "),
        if without > 0 {
            format!(" ({without} runs without ridge columns left out)")
        } else {
            String::new()
        }
    );
    if let Some(dir) = &a.figures {
        std::fs::create_dir_all(dir).map_err(|e| format!("--figures {}: {e}", dir.display()))?;
        for (k, e) in &rows {
            for ext in ["png", "svg"] {
                let name = format!("ridged-h{}-mu{}-muw{}.{ext}", k.thickness, k.mu, k.mu_water);
                plot_redistribution(k, e, &dir.join(name))?;
            }
        }
    }
    write(&text, a.out)
}
