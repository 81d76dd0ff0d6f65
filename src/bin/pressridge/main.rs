//! `pressridge`: the command-line face of the library. No physics lives here.

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(name = "pressridge", version, about = "Pressure-ridge simulator and sea-ice strength tools")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {}

fn main() {
    let _cli = Cli::parse();
}
