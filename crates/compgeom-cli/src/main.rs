//! The `compgeom` command-line tool: a thin shell over the `compgeom` library.
//!
//! `main` parses the arguments (clap: usage errors exit 2), calls [`run`], and turns its
//! error into one `error: …` line on stderr and an exit code (2 bad input, 1 other failure).
//! See `cli.rs` for the command list and how a command adds itself.

mod cli;
mod commands;
mod demo;
mod error;
mod input;
mod output;
mod progress;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    // Usage errors print clap's message and exit with 2; --help / --version exit 0.
    let cli = cli::Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", e.message);
            ExitCode::from(e.kind.code())
        }
    }
}

/// Run one command.
fn run(cli: cli::Cli) -> Result<(), error::CliError> {
    match cli.command {
        cli::Command::Hull(args) => commands::hull::run(&args),
        cli::Command::Intersect(args) => commands::intersect::run(&args),
        cli::Command::Range(args) => commands::range::run(&args),
        cli::Command::Locate(args) => commands::locate::run(&args),
        cli::Command::Window(args) => commands::window::run(&args),
        cli::Command::Halfplanes(args) => commands::halfplanes::run(&args),
        cli::Command::Lp(args) => commands::lp::run(&args),
        cli::Command::Enclose(args) => commands::enclose::run(&args),
        cli::Command::Cast(args) => commands::cast::run(&args),
        cli::Command::Delaunay(args) => commands::delaunay::run(&args),
        cli::Command::Interpolate(args) => commands::interpolate::run(&args),
        cli::Command::Voronoi(args) => commands::voronoi::run(&args),
        cli::Command::Overlay(args) => commands::overlay::run(&args),
        cli::Command::Boolean(args) => commands::boolean::run(&args),
        cli::Command::MakeValid(args) => commands::boolean::run_make_valid(&args),
        cli::Command::Validate(args) => commands::boolean::run_validate(&args),
        cli::Command::Triangulate(args) => commands::triangulate::run(&args),
        cli::Command::Guard(args) => commands::guard::run(&args),
        cli::Command::Demo(args) => demo::run(&args),
    }
}
