//! The exact real roots of the cubics and quartics of `tests/data/polynomial_roots.txt` by
//! `solve_system` (`benches/support/polynomial_roots.rs`: the values of a case's other
//! symbols are its sign oracle), in three groups, each timed as the total for all its cases:
//! the numeric cubics, the numeric quartics, and the cases with letters for coefficients.
//! Before timing, each case's solve is checked to give as many real roots as the file lists,
//! so that what is timed is the whole work.
//! `python3 benches/compare/polynomial_roots_timing.py` times SymPy's `roots` (and
//! SymEngine's `solve`) on the same groups and prints the ratios to these figures.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::algebra::Expr;

/// The allocator the `kinetics` binary ships with, as in `benches/algebra.rs`.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

#[path = "support/polynomial_roots.rs"]
mod polynomial_roots;

use polynomial_roots::{corpus, Case};

/// The groups, in the order the comparison script prints them.
const GROUPS: [&str; 3] = [
    "numeric cubics",
    "numeric quartics",
    "symbolic coefficients",
];

/// The highest power of the unknown in the expanded polynomial.
fn degree(case: &Case) -> i64 {
    let expanded = case
        .polynomial
        .expand()
        .unwrap_or_else(|e| panic!("line {}: {e}", case.line));
    let power_of_unknown = |factor: &Expr| {
        let (base, exponent) = factor.base_and_exponent();
        match base.as_symbol() {
            Some(s) if s == case.unknown => exponent.as_num().and_then(|q| q.to_i64()),
            _ => Some(0),
        }
    };
    expanded
        .terms()
        .iter()
        .flat_map(|term| term.factors().iter().map(power_of_unknown))
        .map(|power| power.unwrap_or_else(|| panic!("line {}: a power of x", case.line)))
        .max()
        .unwrap_or(0)
}

/// A case's group: letters for coefficients, else its degree.
fn group(case: &Case) -> &'static str {
    match (case.values.is_empty(), degree(case)) {
        (false, _) => GROUPS[2],
        (true, 3) => GROUPS[0],
        (true, 4) => GROUPS[1],
        (true, d) => panic!("line {}: a numeric case of degree {d}", case.line),
    }
}

/// Panics unless the case's solve gives as many real roots as the file lists.
fn check_solves(case: &Case) {
    let found = match case.solve() {
        Ok(solved) => solved.branches.len(),
        Err(e) => panic!("line {} ({}) {}: {e}", case.line, case.kind, case.text),
    };
    assert_eq!(
        found,
        case.roots.len(),
        "line {} ({}) {}: real roots found",
        case.line,
        case.kind,
        case.text
    );
}

fn bench(c: &mut Criterion) {
    let cases = corpus();
    cases.iter().for_each(check_solves);
    let mut timed = c.benchmark_group("polynomial roots");
    for name in GROUPS {
        let members: Vec<&Case> = cases.iter().filter(|case| group(case) == name).collect();
        timed.bench_function(name, |b| {
            b.iter(|| {
                for case in &members {
                    black_box(black_box(case).solve().unwrap());
                }
            })
        });
    }
    timed.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
