//! Contents and primitive parts.
//!
//! - The integer content of `p` is the gcd of its coefficients.
//! - Seen as a polynomial in one generator `x` with coefficients polynomials in the
//!   others, `p = Σ cₖ(…) xᵏ`; its content in `x` is `gcd(cₖ)` (integer content included),
//!   and its primitive part in `x` is `p / content` (exact).

use super::{Budget, Polynomial, Term};
use crate::algebra::error::AlgebraError;
use crate::algebra::rational::Q;
use std::collections::BTreeMap;

impl Polynomial {
    /// The gcd of the coefficients, non-negative (`0` for zero).
    pub fn integer_content(&self) -> Q {
        let mut g = Q::ZERO;
        for t in &self.terms {
            g = g.integer_gcd(&t.coefficient);
            if g.is_one() {
                break;
            }
        }
        g
    }

    /// The coefficient of `xᵏ` for generator `x`, a polynomial without `x`.
    pub fn coefficient_in(&self, x: usize, k: u32) -> Polynomial {
        // Terms with one exponent of `x` keep their order once it is set to zero.
        let terms = self
            .terms
            .iter()
            .filter(|t| t.exponents[x] == k)
            .map(|t| without(t, x))
            .collect();
        Polynomial::from_sorted(self.generators, terms)
    }

    /// The non-zero coefficients in generator `x`, each a polynomial without `x`.
    pub fn coefficients_in(&self, x: usize) -> Vec<Polynomial> {
        let mut by_degree: BTreeMap<u32, Vec<Term>> = BTreeMap::new();
        for t in &self.terms {
            by_degree
                .entry(t.exponents[x])
                .or_default()
                .push(without(t, x));
        }
        by_degree
            .into_values()
            .map(|terms| Polynomial::from_sorted(self.generators, terms))
            .collect()
    }

    /// The content in generator `x`: the gcd of the coefficients in `x`, the smallest first
    /// (a gcd of `1` ends the search).
    pub fn content_in(&self, x: usize, budget: &mut Budget) -> Result<Polynomial, AlgebraError> {
        let mut coefficients = self.coefficients_in(x);
        coefficients.sort_by_key(|c| c.terms.len());
        let mut g = Polynomial::zero(self.generators);
        for c in &coefficients {
            g = g.gcd(c, budget)?;
            if g.is_one() {
                break;
            }
        }
        Ok(g)
    }

    /// `self / content`, for a content that divides `self`.
    pub fn divided_by_factor(
        &self,
        factor: &Polynomial,
        budget: &mut Budget,
    ) -> Result<Polynomial, AlgebraError> {
        Ok(self
            .exact_quotient(factor, budget)?
            .expect("a content or gcd divides the polynomial"))
    }
}

/// The term with the exponent of generator `x` set to zero.
fn without(t: &Term, x: usize) -> Term {
    let mut exponents = t.exponents.clone();
    exponents[x] = 0;
    Term {
        exponents,
        coefficient: t.coefficient.clone(),
    }
}
