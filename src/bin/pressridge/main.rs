//! `pressridge`: the command-line face of the library. No physics lives here: each
//! subcommand parses its arguments, calls the library and writes files.
//!
//! Pattern: one file per subcommand (`simulate.rs`, `render.rs`, ...), each with an
//! `Args` struct (clap `Args`) and `pub fn run(args: Args) -> Result<(), BoxError>`.

use clap::{Parser, Subcommand};

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
enum Command {}

fn main() {
    let cli = Cli::parse();
    let result: Result<(), BoxError> = match cli.command {};
    if let Err(e) = result {
        eprintln!("pressridge: error: {e}");
        std::process::exit(1);
    }
}
