//! `kinetics check` in-process: one claim read, decided (exactly and by evaluation in
//! double-double) and, when it differs, diagnosed. The claims are those of
//! `benches/compare/inputs/check_claims.txt`, which `benches/compare/check.py` gives SymPy's
//! `simplify(lhs - rhs)` (with the derived quantities substituted) for the ratio.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::check::context::Context;
use kinetics::check::verdict::check;

/// The allocator the `kinetics` binary ships with, as in `benches/algebra.rs`.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn bench(c: &mut Criterion) {
    let path = format!(
        "{}/benches/compare/inputs/check_claims.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    let claims = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let contexts = [
        (
            "general",
            Context::general(false, false).expect("the general body"),
        ),
        (
            "principal",
            Context::general(true, false).expect("the principal body"),
        ),
    ];
    for line in claims
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let (name, claim) = line.split_once(" | ").expect("CONTEXT | claim");
        let context = &contexts
            .iter()
            .find(|(n, _)| *n == name)
            .expect("a known context")
            .1;
        let verdict = check(context, "bench", claim)
            .unwrap_or_else(|d| panic!("{}", d.render()))
            .verdict;
        c.bench_function(&format!("check ({}): {claim}", verdict.word()), |b| {
            b.iter(|| black_box(check(context, "bench", black_box(claim)).unwrap()))
        });
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
