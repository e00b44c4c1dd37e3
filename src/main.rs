//! The `impulse` binary: the sandbox window by default, headless commands as
//! subcommands. Errors are one line on stderr and a non-zero exit code.

mod app;
mod files;
mod headless;
mod lab;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Counts live heap bytes, for `bench`'s bytes per disc.
#[global_allocator]
static ALLOC: impulse::alloc_count::Counting = impulse::alloc_count::Counting;

/// Impulse: a sandbox for 2D disc collisions.
#[derive(Parser, Debug)]
#[command(name = "impulse", version, args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    window: app::WindowOptions,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Simulate a scene without a window and print a summary.
    Run(headless::RunArgs),
    /// Time a step per disc for every broad phase and method against n.
    Bench(lab::bench::BenchArgs),
    /// Chart speed against accuracy for every method, against `exact`.
    Accuracy(lab::accuracy::AccuracyArgs),
    /// Run the stability suite under every method: where each one fails.
    Stress(lab::stress::StressArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Run(args)) => headless::run(&args),
        Some(Command::Bench(args)) => lab::bench::run(&args),
        Some(Command::Accuracy(args)) => lab::accuracy::run(&args),
        Some(Command::Stress(args)) => lab::stress::run(&args),
        None => app::run(cli.window),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("impulse: {e:#}");
            ExitCode::FAILURE
        }
    }
}
