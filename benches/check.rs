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

/// A class: 1000 claims of one scene (the corpus's claims about SP 18.3, right and wrong,
/// repeated), the context analysed once and the claims checked in parallel as `kinetics
/// check --claims` does; the slipped contexts are derived once, when a claim first differs.
fn class(c: &mut Criterion) {
    use rayon::prelude::*;
    let corpus = include_str!("../tests/data/check_corpus.txt");
    let scene_path = "examples/scenes/sp18_3_rotating_rod.scene";
    let claims: Vec<&str> = corpus
        .lines()
        .filter(|l| l.starts_with(scene_path))
        .filter_map(|l| l.splitn(4, '|').nth(3).map(str::trim))
        .cycle()
        .take(1000)
        .collect();
    let path = format!("{}/{scene_path}", env!("CARGO_MANIFEST_DIR"));
    let source = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let scene = kinetics::parse_scene(&path, &source).expect("SP 18.3 reads");
    c.bench_function(
        "check a class: 1000 claims of SP 18.3, context included",
        |b| {
            b.iter(|| {
                let context = Context::scene(&scene);
                let verdicts: Vec<_> = claims
                    .par_iter()
                    .map(|claim| check(&context, "class", claim).ok().map(|r| r.verdict))
                    .collect();
                black_box(verdicts)
            })
        },
    );
}

criterion_group!(benches, bench, class);
criterion_main!(benches);
