//! Rewriting the square of one factor in every term of a sum: `u² → p + q g`.
//!
//! A term `R · uⁿ` (`n` a positive integer, `n = 2j + r`, `r ∈ {0, 1}`) becomes
//!
//! ```text
//! R · uʳ · (p + q g)ʲ = Σᵢ C(j, i) p^(j−i) qⁱ · R · uʳ · gⁱ      (i = 0 … j)
//! ```
//!
//! and the terms are summed once. The trigonometric forms are all of this shape:
//! `cos²θ → 1 − sin²θ` and `sin²θ → 1 − cos²θ` (the Pythagorean normal forms),
//! `sin²θ → ½ − ½ cos 2θ` and `cos²θ → ½ + ½ cos 2θ` (the double angle).
//! Bounded like `expand`: more than [`MAX_EXPANDED_TERMS`] terms are refused before they
//! are formed; powers past [`MAX_REWRITTEN_EXPONENT`] are left as they are.

use super::error::{AlgebraError, MAX_EXPANDED_TERMS};
use super::expr::Expr;
use super::rational::Q;

/// Largest power `uⁿ` rewritten: the identities shorten the low powers people write
/// (`sin⁴θ + 2 sin²θ cos²θ + cos⁴θ = 1`); `cos⁸⁰⁰θ` would become 401 terms with
/// 240-digit coefficients, tried and thrown away at the cost of seconds.
pub(super) const MAX_REWRITTEN_EXPONENT: i64 = 12;

/// `u² → p + q g`, with `u` the base whose square is rewritten.
pub(super) struct SquareRule<'a> {
    pub(super) base: &'a Expr,
    pub(super) p: Q,
    pub(super) q: Q,
    pub(super) g: Expr,
}

impl SquareRule<'_> {
    /// `sum` with every `uⁿ` (`2 ≤ n ≤` [`MAX_REWRITTEN_EXPONENT`]) of its terms rewritten (see the module documentation).
    pub(super) fn rewrite(&self, sum: &Expr) -> Result<Expr, AlgebraError> {
        let halves: Vec<(&Expr, Option<(usize, i64)>)> = sum
            .terms()
            .iter()
            .map(|term| (term, self.square_in(term)))
            .collect();
        let count = halves
            .iter()
            .map(|(_, h)| h.map_or(1, |(_, j)| j as usize + 1))
            .fold(0usize, usize::saturating_add);
        if count > MAX_EXPANDED_TERMS {
            return Err(AlgebraError::TooLarge {
                what: "the trigonometric rewriting".into(),
                size: count.to_string(),
                limit: MAX_EXPANDED_TERMS,
            });
        }
        let mut out = Vec::with_capacity(count);
        for (term, half) in halves {
            match half {
                None => out.push(term.clone()),
                Some((at, j)) => self.expand_term(term, at, j, &mut out)?,
            }
        }
        Ok(Expr::add_all(out))
    }

    /// Where `uⁿ` (`n ≥ 2` an integer) stands among the term's factors, and `j = ⌊n/2⌋`.
    fn square_in(&self, term: &Expr) -> Option<(usize, i64)> {
        term.factors().iter().enumerate().find_map(|(at, factor)| {
            let (base, exponent) = factor.base_and_exponent();
            let n = exponent.as_num()?.to_i64()?;
            (base == self.base && (2..=MAX_REWRITTEN_EXPONENT).contains(&n)).then_some((at, n / 2))
        })
    }

    /// Pushes the terms `C(j, i) p^(j−i) qⁱ · R · uʳ · gⁱ` of a term `R · u^(2j + r)`.
    fn expand_term(
        &self,
        term: &Expr,
        at: usize,
        j: i64,
        out: &mut Vec<Expr>,
    ) -> Result<(), AlgebraError> {
        let factors = term.factors();
        let (_, exponent) = factors[at].base_and_exponent();
        // j ≤ MAX_REWRITTEN_EXPONENT / 2: the binomial coefficients are small numbers.
        let r = exponent.as_num().and_then(Q::to_i64).unwrap_or(0) % 2;
        let rest: Vec<Expr> = factors
            .iter()
            .enumerate()
            .filter(|&(k, _)| k != at)
            .map(|(_, f)| f.clone())
            .chain([self.base.powi(r)])
            .collect();
        let mut coefficient = self.p.checked_pow(j).expect("p is not zero");
        let ratio = self.q.checked_div(&self.p).expect("p is not zero");
        for i in 0..=j {
            let power = self.g.powi(i);
            let factors = rest
                .iter()
                .cloned()
                .chain([power, Expr::num(coefficient.clone())]);
            out.push(Expr::mul_all(factors));
            let step = Q::new(j - i, i + 1).expect("i + 1 is positive");
            coefficient = &(&coefficient * &step) * &ratio;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Func;

    /// `a c⁴ + b` with `c² → 1 − s²`: `a (1 − s²)² + b = a − 2a s² + a s⁴ + b`.
    #[test]
    fn a_fourth_power_becomes_a_square_of_a_binomial() {
        let x = Expr::symbol("x");
        let (s, c) = (Func::Sin.apply(x.clone()), Func::Cos.apply(x));
        let (a, b) = (Expr::symbol("a"), Expr::symbol("b"));
        let rule = SquareRule {
            base: &c,
            p: Q::ONE,
            q: Q::MINUS_ONE,
            g: s.powi(2),
        };
        let got = rule.rewrite(&(&a * &c.powi(4) + b.clone())).unwrap();
        let want = &a - Expr::int(2) * &a * s.powi(2) + &a * s.powi(4) + b;
        assert_eq!(got, want);
    }

    #[test]
    fn a_power_past_the_largest_rewritten_is_left_as_it_is() {
        let c = Func::Cos.apply(Expr::symbol("x"));
        let rule = SquareRule {
            base: &c,
            p: Q::ONE,
            q: Q::MINUS_ONE,
            g: Func::Sin.apply(Expr::symbol("x")).powi(2),
        };
        for n in [MAX_REWRITTEN_EXPONENT + 1, 1_000_000] {
            let power = c.powi(n);
            assert_eq!(rule.rewrite(&power).unwrap(), power);
        }
        let largest = c.powi(MAX_REWRITTEN_EXPONENT);
        assert_ne!(rule.rewrite(&largest).unwrap(), largest);
    }
}
