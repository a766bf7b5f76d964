//! The nodes `x^n` of a symbol `x` to a small integer power `n` (`-4 ≤ n ≤ 4`, `n ≠ 0, 1`),
//! each made once per symbol and then shared.
//!
//! Squares and reciprocals of symbols are the most common powers (`ω_x²` in every kinetic
//! energy, `1/m`); a power node is an allocation, so each one a symbol needs is kept with the
//! symbol (interned for the life of the process) and handed out as a cheap clone of the same
//! node. The node is exactly the one [`Expr`] would otherwise build.

use super::expr::Expr;
use std::sync::OnceLock;

/// Smallest and largest exponents kept.
const LOWEST: i64 = -4;
const HIGHEST: i64 = 4;
/// One slot for each exponent in `LOWEST..=HIGHEST`; those for 0 and 1 stay empty.
const SLOTS: usize = (HIGHEST - LOWEST + 1) as usize;

/// The small integer powers of one symbol, each made on first use.
#[derive(Debug, Default)]
pub(super) struct SymbolPowers([OnceLock<Expr>; SLOTS]);

impl SymbolPowers {
    /// `x^n` for a small `n` other than 0 and 1: the shared node, made by `make` the first
    /// time; `None` for any other exponent.
    pub(super) fn get(&self, n: i64, make: impl FnOnce() -> Expr) -> Option<Expr> {
        if !(LOWEST..=HIGHEST).contains(&n) || n == 0 || n == 1 {
            return None;
        }
        Some(self.0[(n - LOWEST) as usize].get_or_init(make).clone())
    }
}

#[cfg(test)]
mod tests {
    use crate::algebra::{Expr, View};
    use proptest::prelude::*;

    proptest! {
        /// Shared nodes and freshly built ones (exponents outside the kept range) agree:
        /// `x^a · x^b = x^(a+b)` and each power is the node `x^n` itself.
        #[test]
        fn shared_powers_are_the_built_powers(a in -7i64..8, b in -7i64..8) {
            let x = Expr::symbol("x");
            let product = &x.powi(a) * &x.powi(b);
            prop_assert_eq!(&product, &x.powi(a + b));
            match (a + b, product.view()) {
                (0, View::Num(q)) => prop_assert!(q.is_one()),
                (1, View::Sym(s)) => prop_assert_eq!(s.name(), "x"),
                (n, View::Pow(base, exponent)) => {
                    prop_assert_eq!(base, &x);
                    prop_assert_eq!(exponent, &Expr::int(n));
                }
                (n, other) => prop_assert!(false, "x^{n} is {other:?}"),
            }
        }
    }
}
