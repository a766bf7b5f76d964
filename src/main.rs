//! The `kinetics` command line.

mod cli;

/// The derivations build and drop many small nodes (an `Arc` per sum, product and power);
/// mimalloc serves those from thread-local free lists, which takes the general-body
/// pipeline from about 15 µs to about 13 µs (see `benches/algebra.rs`).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> std::process::ExitCode {
    cli::run()
}
