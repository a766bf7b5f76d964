//! How many terms multiplying out an expression could give, estimated from its shape before
//! any work: a sum has the sum of its terms' counts, a product the product of its factors',
//! a whole power `±n` of a sum of `t` terms `C(t + n − 1, n)` (the multinomial count; a
//! denominator is multiplied out too, by `cancel`), anything else one term. It overestimates
//! (like terms are not combined), so the checker can leave to its second opinion a claim
//! whose exact route would take seconds, and show such a form without simplifying it,
//! before starting the work.

use crate::algebra::{Expr, View};

/// The estimated number of terms of `e` multiplied out (`f64`: huge counts do not overflow).
pub fn estimated_terms(e: &Expr) -> f64 {
    match e.view() {
        View::Add(xs) => xs.iter().map(estimated_terms).sum(),
        View::Mul(xs) => xs.iter().map(estimated_terms).product(),
        View::Pow(base, exponent) => match exponent.as_num() {
            Some(n) if n.is_integer() => multinomial_terms(estimated_terms(base), n.to_f64().abs()),
            _ => 1.0,
        },
        View::Num(_) | View::Sym(_) | View::Func(..) => 1.0,
    }
}

/// `C(t + n − 1, n)`: the monomials of degree `n` in `t` terms; infinite once it is
/// astronomically large (both `t` and `n` over a few hundred).
fn multinomial_terms(t: f64, n: f64) -> f64 {
    let k = (t - 1.0).min(n);
    if k > 400.0 {
        return f64::INFINITY;
    }
    let top = t + n - 1.0;
    (0..k as u64).fold(1.0, |acc, i| acc * (top - i as f64) / (i + 1) as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_sums_products_and_powers_of_sums() {
        let (a, b, c) = (Expr::symbol("a"), Expr::symbol("b"), Expr::symbol("c"));
        let sum = &(&a + &b) + &c;
        assert_eq!(estimated_terms(&a), 1.0);
        assert_eq!(estimated_terms(&sum), 3.0);
        assert_eq!(estimated_terms(&(&sum * &(&a + &b))), 6.0);
        // (a + b + c)^4 has C(6, 4) = 15 monomials.
        assert_eq!(estimated_terms(&sum.powi(4)), 15.0);
        assert_eq!(estimated_terms(&sum.powi(-4)), 15.0);
        assert!(estimated_terms(&sum.powi(1_000_000)) > 1e10);
    }
}
