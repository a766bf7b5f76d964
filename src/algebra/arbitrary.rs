//! Arbitrary canonical expressions for property tests: numbers, a few symbols, and sums,
//! products, integer powers and sines of them, built through [`Expr::add_all`] and
//! [`Expr::mul_all`] only (so independently of the operators' merge paths).

use super::{Expr, Func};
use proptest::prelude::*;

/// An expression of depth at most three with at most 24 leaves.
pub(super) fn expr() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        (-3i64..4).prop_map(Expr::int),
        (1i64..4, 2i64..4).prop_map(|(p, q)| Expr::rational(p, q)),
        prop::sample::select(vec!["x", "y", "w_x", "I_xy", "a"]).prop_map(Expr::symbol),
    ];
    leaf.prop_recursive(3, 24, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 2..4).prop_map(Expr::add_all),
            prop::collection::vec(inner.clone(), 2..4).prop_map(Expr::mul_all),
            (inner.clone(), -2i64..4).prop_map(|(b, n)| {
                if b.is_zero() {
                    b
                } else {
                    b.powi(n)
                }
            }),
            inner.prop_map(|a| Func::Sin.apply(a)),
        ]
    })
}
