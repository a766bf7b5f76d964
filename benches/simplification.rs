//! The rational-function algebra of issue 15: the gcd of two random polynomials in four
//! symbols of degree 6 with a common factor of degree 2 (fixed seed), and `cancel` of the
//! free box's solved rate `w_x = F_2 Dt b/(2(-1/12 m b² - 1/12 m c²))`.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use kinetics::algebra::{polynomial_gcd, Expr};
use kinetics::parse_expression;

/// The allocator the `kinetics` binary ships with, as in `benches/algebra.rs`.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// A fixed-seed xorshift generator: the same polynomials on every run.
struct Random(u64);

impl Random {
    fn below(&mut self, n: u64) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0 % n
    }

    /// `terms` random terms in `a, b, c, d` of total degree at most `degree` (one of them
    /// of exactly that degree), coefficients in -9..=9 without 0.
    fn polynomial(&mut self, terms: usize, degree: u64) -> Expr {
        let symbols: Vec<Expr> = ["a", "b", "c", "d"]
            .iter()
            .map(|s| Expr::symbol(s))
            .collect();
        Expr::add_all((0..terms).map(|i| {
            let total = if i == 0 {
                degree
            } else {
                self.below(degree + 1)
            };
            let coefficient = (self.below(18) as i64) - 9;
            let coefficient = if coefficient >= 0 {
                coefficient + 1
            } else {
                coefficient
            };
            Expr::mul_all(
                std::iter::once(Expr::int(coefficient))
                    .chain((0..total).map(|_| symbols[self.below(4) as usize].clone())),
            )
        }))
    }
}

fn bench(c: &mut Criterion) {
    let mut random = Random(0xdead_beef);
    let common = random.polynomial(4, 2);
    let a = (&random.polynomial(8, 4) * &common).expand().unwrap();
    let b = (&random.polynomial(8, 4) * &common).expand().unwrap();
    c.bench_function("gcd of two 4-symbol polynomials of degree 6", |bench| {
        bench.iter(|| black_box(polynomial_gcd(black_box(&a), black_box(&b)).unwrap()))
    });
    let free_box = parse_expression("", "F_2*Dt*b/(2*(-1/12*m*b^2 - 1/12*m*c^2))").unwrap();
    c.bench_function("cancel of the free box's w_x", |bench| {
        bench.iter(|| black_box(black_box(&free_box).cancel().unwrap()))
    });
    c.bench_function("factor_terms of the free box's cancelled w_x", |bench| {
        let cancelled = free_box.cancel().unwrap();
        bench.iter(|| black_box(black_box(&cancelled).factor_terms().unwrap()))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
