//! The `impulse` binary: the sandbox window by default, headless commands as
//! subcommands. Errors are one line on stderr and a non-zero exit code.
//!
//! The same code builds for the browser (`scripts/build-web.sh`): there the
//! page loads it and [`main`] opens the sandbox, with no command line, no
//! lab and no threads; [`web`] is its bridge to the page.

mod app;
mod cli;
mod files;
#[cfg(not(target_arch = "wasm32"))]
mod headless;
#[cfg(not(target_arch = "wasm32"))]
mod lab;
#[cfg(not(target_arch = "wasm32"))]
mod progress;
#[cfg(target_arch = "wasm32")]
mod web;

#[cfg(not(target_arch = "wasm32"))]
use clap::{Parser, Subcommand};
#[cfg(not(target_arch = "wasm32"))]
use std::process::ExitCode;

/// Counts live heap bytes, for `bench`'s bytes per disc, and puts large
/// blocks on huge pages.
#[global_allocator]
static ALLOC: impulse::alloc_count::Counting = impulse::alloc_count::Counting;

/// In the browser: the sandbox, on the scene the page's address carries.
#[cfg(target_arch = "wasm32")]
fn main() {
    app::run_in_browser();
}

/// Impulse: a sandbox for 2D disc collisions.
#[cfg(not(target_arch = "wasm32"))]
#[derive(Parser, Debug)]
#[command(
    name = "impulse",
    version,
    args_conflicts_with_subcommands = true,
    allow_negative_numbers = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    window: app::WindowOptions,
}

#[cfg(not(target_arch = "wasm32"))]
#[derive(Subcommand, Debug)]
enum Command {
    /// Simulate a scene without a window and print a summary.
    // Negative numbers are values, so that `--time -1` gets the value's own
    // message ("must be positive"), not "unexpected argument".
    #[command(allow_negative_numbers = true)]
    Run(headless::RunArgs),
    /// Time a step per disc for every broad phase and method against n.
    Bench(lab::bench::BenchArgs),
    /// Chart speed against accuracy for every method, against `exact`.
    Accuracy(lab::accuracy::AccuracyArgs),
    /// Run the stability suite under every method: where each one fails.
    Stress(lab::stress::StressArgs),
    /// Print the state hashes of the shipped scenes after a fixed number of
    /// steps, as JSON (the browser test compares the web build's with them).
    #[command(hide = true)]
    Fingerprint,
}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return parse_error(&e),
    };
    let result = match cli.command {
        Some(Command::Run(args)) => headless::run(&args),
        Some(Command::Bench(args)) => lab::bench::run(&args),
        Some(Command::Accuracy(args)) => lab::accuracy::run(&args),
        Some(Command::Stress(args)) => lab::stress::run(&args),
        Some(Command::Fingerprint) => {
            println!("{}", impulse::fingerprint::fingerprints_json());
            Ok(())
        }
        None => app::run(cli.window),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.is::<headless::FellBehind>() => {
            eprintln!("impulse: warning: {e}");
            ExitCode::from(headless::EXIT_FELL_BEHIND)
        }
        Err(e) => {
            eprintln!("impulse: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// Reports a command-line error in one line (clap's own message, its lines
/// joined, without the usage block) with exit code 2; `--help` and
/// `--version` print in full and succeed.
#[cfg(not(target_arch = "wasm32"))]
fn parse_error(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    if matches!(
        e.kind(),
        ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        let _ = e.print();
        return if e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand {
            ExitCode::from(2)
        } else {
            ExitCode::SUCCESS
        };
    }
    let text = e.render().to_string();
    let message: Vec<&str> = text
        .lines()
        .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    let message = message.join(" ");
    let message = message.strip_prefix("error: ").unwrap_or(&message);
    eprintln!("impulse: {message} (see impulse --help)");
    ExitCode::from(2)
}
