//! The rational-function algebra of issue 15, on the inputs `benches/compare/
//! simplification.py` gives SymPy (read from the same files, so the ratios compare like
//! with like): the gcd of two random polynomials in four symbols of degree 6 sharing a
//! factor of degree 2, and `cancel` of their quotient; `cancel` of the free box's six
//! solved unknowns and of every input of the corpus `tests/data/cancel_corpus.txt`;
//! `factor_terms` of the free box's cancelled `w_z`; and `simplify` (the shortest form,
//! the chapter's domains) of the free box's unknowns and of the corpus, beside SymPy's
//! `simplify` on the same inputs.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::algebra::{polynomial_gcd, Domains, Expr};
use kinetics::parse_expression;

/// The allocator the `kinetics` binary ships with, as in `benches/algebra.rs`.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn read(path: &str) -> String {
    let path = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn parse(text: &str) -> Expr {
    parse_expression("benchmark input", text).unwrap_or_else(|d| panic!("{}", d.render()))
}

fn bench(c: &mut Criterion) {
    let pair: Vec<Expr> = read("benches/compare/inputs/gcd_4_symbols_degree_6.txt")
        .lines()
        .map(parse)
        .collect();
    let (first, second) = (&pair[0], &pair[1]);
    c.bench_function("gcd 4 symbols degree 6: gcd", |b| {
        b.iter(|| black_box(polynomial_gcd(black_box(first), black_box(second)).unwrap()))
    });
    let quotient = first / second;
    c.bench_function("gcd 4 symbols degree 6: cancel", |b| {
        b.iter(|| black_box(black_box(&quotient).cancel().unwrap()))
    });

    let free_box: Vec<Expr> = read("benches/compare/inputs/free_box_unknowns.txt")
        .lines()
        .map(|line| parse(line.split_once(" = ").expect("name = expression").1))
        .collect();
    c.bench_function("free-box unknowns: cancel", |b| {
        b.iter(|| {
            for e in &free_box {
                black_box(black_box(e).cancel().unwrap());
            }
        })
    });
    let domains = Domains::chapter_defaults();
    c.bench_function("free-box unknowns: simplify", |b| {
        b.iter(|| {
            for e in &free_box {
                black_box(black_box(e).simplify(&domains).unwrap());
            }
        })
    });
    let w_z = free_box[5].cancel().unwrap();
    c.bench_function("free-box w_z cancelled: factor_terms", |b| {
        b.iter(|| black_box(black_box(&w_z).factor_terms().unwrap()))
    });

    let corpus: Vec<Expr> = read("tests/data/cancel_corpus.txt")
        .lines()
        .filter_map(|line| line.strip_prefix("input: "))
        .map(parse)
        .collect();
    c.bench_function("corpus (all cases): cancel", |b| {
        b.iter(|| {
            for e in &corpus {
                black_box(black_box(e).cancel().unwrap());
            }
        })
    });
    c.bench_function("corpus (all cases): simplify", |b| {
        b.iter(|| {
            for e in &corpus {
                black_box(black_box(e).simplify(&domains).unwrap());
            }
        })
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
