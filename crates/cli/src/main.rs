//! `pressridge`: the command-line face of the library, the crate `pressridge-cli`
//! (`crates/cli`), whose binary keeps the name `pressridge`. No physics lives here: each
//! subcommand parses its arguments, calls the library (`pressridge`, with its `plot` feature
//! for the figures) and writes files. The commands are documented in `docs/cli.md`.
//!
//! Pattern: one file per subcommand (`simulate.rs`, `render.rs`, ...), each with an
//! `Args` struct (clap `Args`) and `pub fn run(args: Args) -> Result<(), BoxError>`.

#![warn(missing_docs)]

use clap::{Parser, Subcommand};

mod animate;
mod campaign;
mod findings;
mod params;
mod plot_strength;
mod progress;
mod redistribution;
mod render;
mod ridge_step;
mod simulate;
mod strength;
mod tabulate;

/// Error type of the subcommands: any error with a readable message.
pub type BoxError = Box<dyn std::error::Error + Send + Sync>;

#[derive(Parser)]
#[command(
    name = "pressridge",
    version,
    about = "Pressure-ridge simulator and sea-ice strength tools"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// No progress reports on stderr (errors and warnings still appear).
    #[arg(long, short, global = true)]
    quiet: bool,
    /// More detail in the progress reports (steps, step size); repeatable.
    #[arg(short, long, action = clap::ArgAction::Count, global = true)]
    verbose: u8,
    /// Seconds between progress lines when stderr is not a terminal (a log, CI, a pipe).
    #[arg(long, global = true, default_value_t = 5.0, value_name = "SECONDS")]
    progress_interval: f64,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene (the built-in default unless --scene is given) and write its results.
    Simulate(simulate::Args),
    /// Draw a saved state as a PNG or SVG.
    Render(render::Args),
    /// A GIF (and MP4 with --mp4 where ffmpeg is found) of a run's snapshots.
    Animate(animate::Args),
    /// Run a seeded ensemble over a parameter grid (resumable).
    Campaign(campaign::Args),
    /// Tabulate a campaign into a NetCDF lookup table (fits, bands, C_f).
    Tabulate(tabulate::Args),
    /// The paper's stated findings tested on campaign records (a Markdown table).
    Findings(findings::Args),
    /// The thickness distribution of the simulated ridged ice, with μ_rdg and H* fitted.
    Redistribution(redistribution::Args),
    /// Ice strength P (N/m) of a gridded thickness distribution (NetCDF in and out).
    Strength(strength::Args),
    /// One ridging step on a gridded thickness distribution (NetCDF in and out).
    RidgeStep(ridge_step::Args),
    /// PNG map of ice strength on a 2-D grid.
    PlotStrength(plot_strength::Args),
}

fn main() {
    let cli = Cli::parse();
    if !(cli.progress_interval.is_finite() && cli.progress_interval >= 0.0) {
        eprintln!(
            "pressridge: error: --progress-interval must be a non-negative number of seconds, not {}",
            cli.progress_interval
        );
        std::process::exit(1);
    }
    progress::configure(progress::Options {
        quiet: cli.quiet,
        verbose: cli.verbose,
        interval: cli.progress_interval,
    });
    let result = match cli.command {
        Command::Simulate(a) => simulate::run(a),
        Command::Render(a) => render::run(a),
        Command::Animate(a) => animate::run(a),
        Command::Campaign(a) => campaign::run(a),
        Command::Tabulate(a) => tabulate::run(a),
        Command::Findings(a) => findings::run(a),
        Command::Redistribution(a) => redistribution::run(a),
        Command::Strength(a) => strength::run(a),
        Command::RidgeStep(a) => ridge_step::run(a),
        Command::PlotStrength(a) => plot_strength::run(a),
    };
    if let Err(e) = result {
        eprintln!("pressridge: error: {e}");
        std::process::exit(1);
    }
}
