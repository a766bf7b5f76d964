//! Arbitrary canonical expressions for property tests: integers and rationals of either
//! sign, a few symbols, and sums, products, integer and rational powers (square roots
//! among them) and the functions `sin cos tan abs` of them, built through
//! [`Expr::add_all`], [`Expr::mul_all`], [`Expr::checked_pow`] and [`Func::apply`] only
//! (so independently of the operators' merge paths).

use super::{Expr, Func};
use proptest::prelude::*;

/// An expression of depth at most three with at most 24 leaves.
pub(super) fn expr() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        (-3i64..4).prop_map(Expr::int),
        (
            prop_oneof![-7i64..=-1, 1i64..=7],
            prop::sample::select(vec![2i64, 3, 4, 10])
        )
            .prop_map(|(p, q)| Expr::rational(p, q)),
        prop::sample::select(vec!["x", "y", "w_x", "I_xy", "a"]).prop_map(Expr::symbol),
    ];
    leaf.prop_recursive(3, 24, 4, |inner| {
        let exponent = prop_oneof![
            (-2i64..4).prop_map(Expr::int),
            prop::sample::select(vec![(1i64, 2i64), (-1, 2), (3, 2), (1, 3)])
                .prop_map(|(p, q)| Expr::rational(p, q)),
        ];
        prop_oneof![
            prop::collection::vec(inner.clone(), 2..4).prop_map(Expr::add_all),
            prop::collection::vec(inner.clone(), 2..4).prop_map(Expr::mul_all),
            // Zero to a negative power has no value; zero stays zero.
            (inner.clone(), exponent).prop_map(|(b, n)| b.checked_pow(&n).unwrap_or(b)),
            (
                prop::sample::select(vec![Func::Sin, Func::Cos, Func::Tan, Func::Abs]),
                inner
            )
                .prop_map(|(f, a)| f.apply(a)),
        ]
    })
}
