//! A fuzzer for issue 14's promises, on stable Rust: no panic, no stack overflow, no hang,
//! no `inf`/`NaN` in any output, and every error located in the user's input.
//!
//! ```text
//! cargo run --release --example fuzz -- expr --seconds 600 --jobs 2
//! cargo run --release --example fuzz -- scene --seconds 600 --jobs 2 --seed 7
//! cargo run --release --example fuzz -- check --seconds 600 --jobs 2
//! ```
//!
//! Targets: `expr` (expressions through `simplify`, `simplify --expand` and `latex`),
//! `scene` (scenes through `solve` and `simulate --until 1`) and `check` (claims through
//! `check --claim` in the general body, `--principal`, `--fixed-axis` and a scene's
//! context), each input run in-process through the library functions those commands call
//! (see `target.rs`, `check.rs`). Inputs come from a seeded generator of the grammar
//! (expressions, or claims) and from mutations of the seed corpus (`tests/reproducers/`,
//! `examples/scenes/`, `tests/bad_scenes/`, the claims of `tests/data/check_corpus.txt`). Findings are kept in
//! `target/fuzz/<target>/findings/`, one file per kind of failure, in the format of
//! `tests/reproducers/`; the run prints inputs run, inputs per second and every finding,
//! and exits with 1 when there is one.
//!
//! An example, not a binary: `cargo install` leaves it out, and `cargo test --release`
//! compiles it (so it cannot rot) with the dependencies already built for the tests.

mod check;
mod corpus;
mod finding;
mod generate;
mod generate_claim;
mod hostile;
mod mutate;
mod random;
mod supervisor;
mod target;
mod worker;

use clap::Parser;
use std::path::PathBuf;
use std::time::{Duration, Instant};

/// Fuzz `kinetics` with generated and mutated input.
#[derive(Parser)]
pub struct Options {
    /// What to fuzz: expressions, scenes or claims.
    #[arg(value_enum)]
    pub target: target::Target,
    /// How long to run (s).
    #[arg(long, default_value_t = 60)]
    pub seconds: u64,
    /// The seed of the inputs: the same seed, the same inputs (per job).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker processes (one per core).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u64).range(1..=64))]
    pub jobs: u64,
    /// Where the findings and the workers' current inputs go.
    #[arg(long, default_value = "target/fuzz")]
    pub out: PathBuf,
    /// (internal) Run as worker number JOB of the supervisor.
    #[arg(long, hide = true)]
    job: Option<u64>,
    /// (internal) The worker's restart count: its stream of inputs.
    #[arg(long, hide = true, default_value_t = 0)]
    generation: u64,
    /// (internal) When the campaign ends, in milliseconds since the Unix epoch.
    #[arg(long, hide = true, default_value_t = 0)]
    end_ms: u64,
}

fn main() {
    let options = Options::parse();
    let dir = options.out.join(options.target.name());
    let Some(job) = options.job else {
        std::process::exit(supervisor::run(&options, &dir));
    };
    worker::run(worker::Work {
        target: options.target,
        seed: options.seed,
        job,
        generation: options.generation,
        findings: dir.join("findings"),
        current: supervisor::current_file(&dir, job),
        end: Instant::now()
            + Duration::from_millis(options.end_ms.saturating_sub(supervisor::unix_ms())),
    })
}
