//! A driver for instruction-count profiling of the algebra stages of the general-body
//! pipeline (`benches/support/general_body.rs`), without the printers:
//!
//! ```text
//! cargo build --release --example algebra_general_body
//! valgrind --tool=callgrind target/release/examples/algebra_general_body algebra 2000
//! ```
//!
//! `build` forms the expressions the given number of times (default 1000) and drops them;
//! `canonical` builds once and canonicalises each time; `algebra` (the default) does both
//! each time, as the pipeline does before printing. Subtract a run with 0 rounds for the
//! start-up cost.

#[path = "../benches/support/general_body.rs"]
#[allow(dead_code)] // the printing half of the shared module is not used here
mod general_body;

use std::hint::black_box;

fn main() {
    let mut args = std::env::args().skip(1);
    let stage = args.next().unwrap_or_else(|| "algebra".to_string());
    let rounds: usize = args.next().and_then(|n| n.parse().ok()).unwrap_or(1000);
    let built = general_body::build();
    let mut terms = 0;
    for _ in 0..rounds {
        let canonical = match stage.as_str() {
            "build" => {
                black_box(general_body::build());
                continue;
            }
            "canonical" => general_body::canonical(black_box(&built)),
            _ => general_body::canonical(&general_body::build()),
        };
        terms += canonical.t.terms().len();
    }
    println!("{stage}: {rounds} rounds, {terms} terms of T");
}
