//! A driver for instruction-count profiling of the general-body pipeline
//! (`benches/support/general_body.rs`), repeatable under load where wall-clock benchmarks
//! are not:
//!
//! ```text
//! cargo build --release --example print_general_body
//! valgrind --tool=callgrind target/release/examples/print_general_body latex 1000
//! ```
//!
//! `latex` (the default) canonicalises once and prints the seven expressions as LaTeX the
//! given number of times (default 1000): the printers alone. `pipeline` runs the whole
//! pipeline (build, canonicalise, print) each time. Subtract a run with 0 rounds for the
//! start-up cost.

#[path = "../benches/support/general_body.rs"]
mod general_body;

fn main() {
    let mut args = std::env::args().skip(1);
    let stage = args.next().unwrap_or_else(|| "latex".to_string());
    let rounds: usize = args.next().and_then(|n| n.parse().ok()).unwrap_or(1000);
    let canonical = general_body::canonical(&general_body::build());
    let mut bytes = 0;
    for _ in 0..rounds {
        let printed = match stage.as_str() {
            "pipeline" => general_body::pipeline(),
            _ => general_body::latex(std::hint::black_box(&canonical)),
        };
        bytes += printed.iter().map(String::len).sum::<usize>();
    }
    println!("{stage}: {rounds} rounds, {bytes} bytes of LaTeX");
}
