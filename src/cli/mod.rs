//! The command line: argument parsing (clap) and one module per command.

mod bench;
mod check;
mod derivation;
mod derive;
mod error;
mod figure;
mod input;
mod mark;
#[cfg(feature = "plot")]
mod plot;
mod progress;
mod sample_rows;
mod show;
mod simplify;
mod simulate;
mod simulate_flags;
mod simulate_top;
mod solve;

use clap::{Parser, Subcommand};
use error::CliError;
use std::io::Write;
use std::process::ExitCode;

/// Kinetics of rigid bodies in three dimensions: derive, print, evaluate.
#[derive(Parser)]
#[command(
    name = "kinetics",
    version,
    about,
    long_about = None,
    after_help = "Example:\n  kinetics latex \"-a^2 + 1/2 m v^2\""
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Print an expression or equation as LaTeX (or text or JSON).
    Latex(show::Args),
    /// Bring an expression to canonical form, optionally expanded.
    Simplify(simplify::Args),
    /// Derive the chapter's equations for a general body.
    Derive(derive::Args),
    /// Solve a scene file and write the worked solution.
    Solve(solve::Args),
    /// Check hand-written claims against the derivations: holds, differs (and what is
    /// wrong), or undecided.
    Check(check::Args),
    /// Mark a class: a scheme's questions, a CSV of answers; grades, feedback and a summary.
    Mark(mark::Args),
    /// Show which derivations a scene's requests pull, in order.
    Plan(solve::PlanArgs),
    /// Draw a scene's figure: the body, its axes and loads (SVG or TikZ).
    Figure(figure::Args),
    /// Integrate Euler's equations and the orientation for a scene's body.
    Simulate(simulate::Args),
    /// Benchmarks that print tables.
    #[command(
        subcommand,
        after_help = "Example:\n  kinetics bench work-precision --until 10 --budget-ms 5"
    )]
    Bench(bench::Bench),
}

/// Runs the command line: the command's output on standard output, or its failure's
/// message on standard error and exit code 1 (see [`CliError`]).
///
/// No message shows a character a reader cannot see as itself: an ESC sequence or a
/// right-to-left override in an argument, a path or an input is written as its escape
/// (`\u{1b}`, [`kinetics::visible`]), so an error never drives the terminal. clap's own
/// refusals of a command line are escaped too (and lose their colours); `--help` and
/// `--version` are printed as clap prints them.
pub fn run() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            tell(&e.render().to_string());
            return ExitCode::from(u8::try_from(e.exit_code()).unwrap_or(2));
        }
    };
    match execute(cli.command) {
        Ok(code) => code,
        Err(e) => {
            tell(&e.to_string());
            ExitCode::FAILURE
        }
    }
}

/// Writes `message` on standard error as one or more whole lines, each character a reader
/// cannot see as its escape.
pub fn tell(message: &str) {
    let mut message = kinetics::visible::escaped(message).into_owned();
    if !message.ends_with('\n') {
        message.push('\n');
    }
    // With standard error closed there is no one left to tell.
    let _ = std::io::stderr().write_all(message.as_bytes());
}

/// Runs one command and writes its output, if any, as a line. `check` writes its own and
/// sets its own exit status (a verdict per claim).
fn execute(command: Command) -> Result<ExitCode, CliError> {
    let output = match command {
        Command::Check(args) => return Ok(check::run(args)),
        Command::Latex(args) => show::run(args),
        Command::Simplify(args) => simplify::run(args),
        Command::Derive(args) => derive::run(args),
        Command::Solve(args) => solve::run(args),
        Command::Plan(args) => solve::plan(args),
        Command::Mark(args) => mark::run(args),
        Command::Figure(args) => figure::run(args),
        Command::Simulate(args) => simulate::run(args),
        Command::Bench(b) => bench::run(b),
    }?;
    if output.is_empty() {
        return Ok(ExitCode::SUCCESS);
    }
    let mut stdout = std::io::stdout().lock();
    writeln!(stdout, "{output}")
        .and_then(|()| stdout.flush())
        .map_err(CliError::io("write"))?;
    Ok(ExitCode::SUCCESS)
}
