//! `pressridge`: the command-line face of the library. No physics lives here: each
//! subcommand parses its arguments, calls the library and writes files.
//!
//! Pattern: one file per subcommand (`simulate.rs`, `render.rs`, ...), each with an
//! `Args` struct (clap `Args`) and `pub fn run(args: Args) -> Result<(), BoxError>`.

use clap::{Parser, Subcommand};

mod campaign;
mod plot_strength;
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
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene (the built-in default unless --scene is given) and write its results.
    Simulate(simulate::Args),
    /// Draw a saved state as a PNG or SVG.
    Render(render::Args),
    /// Run a seeded ensemble over a parameter grid (resumable).
    Campaign(campaign::Args),
    /// Tabulate a campaign into a NetCDF lookup table (fits, bands, C_f).
    Tabulate(tabulate::Args),
    /// Ice strength P (N/m) of a gridded thickness distribution (NetCDF in and out).
    Strength(strength::Args),
    /// One ridging step on a gridded thickness distribution (NetCDF in and out).
    RidgeStep(ridge_step::Args),
    /// PNG map of ice strength on a 2-D grid.
    PlotStrength(plot_strength::Args),
}

fn main() {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Simulate(a) => simulate::run(a),
        Command::Render(a) => render::run(a),
        Command::Campaign(a) => campaign::run(a),
        Command::Tabulate(a) => tabulate::run(a),
        Command::Strength(a) => strength::run(a),
        Command::RidgeStep(a) => ridge_step::run(a),
        Command::PlotStrength(a) => plot_strength::run(a),
    };
    if let Err(e) = result {
        eprintln!("pressridge: error: {e}");
        std::process::exit(1);
    }
}
