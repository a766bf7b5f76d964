//! How many terms multiplying out an expression could give, estimated from its shape before
//! any work: a sum has the sum of its terms' counts, a product the product of its factors',
//! a whole power `±n` of a sum of `t` terms `C(t + n − 1, n)` (the multinomial count; a
//! denominator is multiplied out too, by `cancel`), anything else one term. It overestimates
//! (like terms are not combined), so the checker can leave to its second opinion a claim
//! whose exact route would take seconds, and show such a form without simplifying it,
//! before starting the work. The multinomial count is `expand`'s own.

use super::expand::multinomial_terms;
use super::expr::{Expr, View};

/// Past this many terms of a base or this exponent (both), a power's count is taken as
/// infinite without counting it (the count would be astronomical; counting takes a factor
/// per unit of the smaller).
const COUNTED_UP_TO: f64 = 400.0;

impl Expr {
    /// The estimated number of terms of `self` multiplied out (module documentation; `f64`:
    /// huge counts do not overflow).
    pub fn estimated_expanded_terms(&self) -> f64 {
        match self.view() {
            View::Add(xs) => xs.iter().map(Expr::estimated_expanded_terms).sum(),
            View::Mul(xs) => xs.iter().map(Expr::estimated_expanded_terms).product(),
            View::Pow(base, exponent) => match exponent.as_num() {
                Some(n) if n.is_integer() => {
                    let (t, n) = (base.estimated_expanded_terms(), n.to_f64().abs());
                    if t.min(n) > COUNTED_UP_TO || t > 1e15 {
                        f64::INFINITY
                    } else {
                        // An exponent past 1e15 counts as 1e15: as many terms or more than any
                        // bound (a monomial's power stays one term), and no overflow.
                        multinomial_terms(t as usize, n.min(1e15) as u64)
                    }
                }
                _ => 1.0,
            },
            View::Num(_) | View::Sym(_) | View::Func(..) => 1.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_sums_products_and_powers_of_sums() {
        let estimated_terms = Expr::estimated_expanded_terms;
        let (a, b, c) = (Expr::symbol("a"), Expr::symbol("b"), Expr::symbol("c"));
        let sum = &(&a + &b) + &c;
        assert_eq!(estimated_terms(&a), 1.0);
        assert_eq!(estimated_terms(&sum), 3.0);
        assert_eq!(estimated_terms(&(&sum * &(&a + &b))), 6.0);
        // (a + b + c)^4 has C(6, 4) = 15 monomials.
        assert_eq!(estimated_terms(&sum.powi(4)), 15.0);
        assert_eq!(estimated_terms(&sum.powi(-4)), 15.0);
        assert!(estimated_terms(&sum.powi(1_000_000)) > 1e10);
        let huge = Expr::int(10).powi(30);
        assert_eq!(estimated_terms(&a.checked_pow(&huge).unwrap()), 1.0);
        assert!(estimated_terms(&sum.checked_pow(&huge).unwrap()) >= 1e15);
    }
}
