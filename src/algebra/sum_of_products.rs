//! `Σ aᵢ bᵢ` built as one canonical sum.
//!
//! A chain of binary operations, `a₁b₁ + a₂b₂ + a₃b₃`, builds a sum node for every partial
//! sum and throws all but the last away. Here each product `aᵢ bᵢ` is formed by one merge
//! of the two factor lists (see `merge`), the products are gathered on the stack, and one
//! sort combines like terms and builds the single sum node. The result is the same
//! canonical expression the operators give. A difference `a b − c d` (a component of a
//! cross product, a 2 × 2 determinant) is formed the same way, the sign taken into the
//! coefficient of `c d` rather than built as a separate negation.
//!
//! ```
//! use kinetics::algebra::Expr;
//! let s = Expr::symbol;
//! let (ix, ixy, wx, wy) = (s("I_x"), -s("I_xy"), s("w_x"), s("w_y"));
//! let h_x = Expr::sum_of_products(&[(&ix, &wx), (&ixy, &wy)]);
//! assert_eq!(h_x, &ix * &wx + &ixy * &wy);
//! let det = Expr::difference_of_products((&ix, &wy), (&ixy, &wx));
//! assert_eq!(det, &ix * &wy - &ixy * &wx);
//! ```

use super::expr::{Expr, Operands};
use super::merge;
use super::rational::Q;

impl Expr {
    /// `a₁ b₁ + a₂ b₂ + …` in canonical form.
    pub fn sum_of_products(pairs: &[(&Expr, &Expr)]) -> Expr {
        weighted_sum_of_products(pairs.iter().map(|&(a, b)| (Q::ONE, a, b)))
    }

    /// `a b − c d` in canonical form.
    pub fn difference_of_products(plus: (&Expr, &Expr), minus: (&Expr, &Expr)) -> Expr {
        weighted_sum_of_products([(Q::ONE, plus.0, plus.1), (Q::MINUS_ONE, minus.0, minus.1)])
    }
}

/// `Σ wᵢ aᵢ bᵢ` for rational weights `wᵢ`: each weighted product is one merge, and the
/// products (or, where a number multiplied a sum, its distributed terms) are summed once.
fn weighted_sum_of_products<'a>(terms: impl IntoIterator<Item = (Q, &'a Expr, &'a Expr)>) -> Expr {
    let mut products = Operands::new();
    for (weight, a, b) in terms {
        let product = merge::scaled_product(&(&weight * a.coefficient()), a.monomial(), b);
        if product.terms().len() > 1 {
            products.extend(product.terms().iter().cloned());
        } else {
            products.push(product);
        }
    }
    Expr::sum_of_terms(&mut products)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::arbitrary::expr;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn one_sum_equals_the_chain_of_operators(
            pairs in prop::collection::vec((expr(), expr()), 0..5),
        ) {
            let refs: Vec<(&Expr, &Expr)> = pairs.iter().map(|(a, b)| (a, b)).collect();
            let gathered = Expr::sum_of_products(&refs);
            let chained = pairs.iter().fold(Expr::zero(), |sum, (a, b)| sum + a * b);
            prop_assert_eq!(format!("{gathered:?}"), format!("{chained:?}"));
            prop_assert_eq!(gathered, chained);
        }

        #[test]
        fn difference_equals_the_operators(a in expr(), b in expr(), c in expr(), d in expr()) {
            let gathered = Expr::difference_of_products((&a, &b), (&c, &d));
            let operators = &a * &b - &c * &d;
            prop_assert_eq!(format!("{gathered:?}"), format!("{operators:?}"));
            prop_assert_eq!(gathered, operators);
        }
    }
}
