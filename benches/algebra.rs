//! The algebra pipeline for a general body (six inertia components, ω, α): build,
//! canonicalise and print as LaTeX `H = [I]ω`, `T = ½ ωᵀ[I]ω` and `[I]α + ω × ([I]ω)`,
//! as a whole and stage by stage.
//! For scale, `python3 benches/compare/general_body.py` does the same work in SymPy and
//! SymEngine (about 0.1 ms in SymEngine and 7–25 ms in SymPy, from the issue).

use criterion::{black_box, criterion_group, criterion_main, Criterion};

/// The allocator the `kinetics` binary ships with (`src/main.rs`), so that the figures are
/// the command's. `examples/print_general_body.rs` keeps the system allocator, as a library
/// user's program has by default.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "support/general_body.rs"]
mod general_body;

fn bench(c: &mut Criterion) {
    c.bench_function("general body: H, T, Euler built, canonical, LaTeX", |b| {
        b.iter(|| black_box(general_body::pipeline()))
    });
    c.bench_function("general body: build", |b| {
        b.iter(|| black_box(general_body::build()))
    });
    let built = general_body::build();
    c.bench_function("general body: canonicalise", |b| {
        b.iter(|| black_box(general_body::canonical(black_box(&built))))
    });
    let canonical = general_body::canonical(&built);
    c.bench_function("general body: LaTeX", |b| {
        b.iter(|| black_box(general_body::latex(black_box(&canonical))))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
