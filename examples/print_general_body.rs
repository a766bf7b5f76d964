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
//! given number of times (default 1000): the printers alone; `text` does the same in plain
//! text. `pipeline` runs the whole pipeline (build, canonicalise, print) each time. Subtract
//! a run with 0 rounds for the start-up cost.

#[path = "../benches/support/general_body.rs"]
mod general_body;

use kinetics::print;

/// `H_x, H_y, H_z, T, M_x, M_y, M_z` in plain text, as [`general_body::latex`] in LaTeX.
fn text(c: &general_body::Canonical) -> Vec<String> {
    let mut out: Vec<String> = c.h.iter().map(print::text).collect();
    out.push(print::text(&c.t));
    let euler = c.euler.iter().zip(general_body::AXES);
    out.extend(euler.map(|(m, axis)| print::text_about(m, axis)));
    out
}

fn main() {
    let mut args = std::env::args().skip(1);
    let stage = args.next().unwrap_or_else(|| "latex".to_string());
    let rounds: usize = args.next().and_then(|n| n.parse().ok()).unwrap_or(1000);
    let canonical = general_body::canonical(&general_body::build());
    let mut bytes = 0;
    for _ in 0..rounds {
        let printed = match stage.as_str() {
            "pipeline" => general_body::pipeline(),
            "text" => text(std::hint::black_box(&canonical)),
            _ => general_body::latex(std::hint::black_box(&canonical)),
        };
        bytes += printed.iter().map(String::len).sum::<usize>();
    }
    println!("{stage}: {rounds} rounds, {bytes} bytes printed");
}
