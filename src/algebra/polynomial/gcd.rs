//! The greatest common divisor of two polynomials over the integers, by the recursive
//! primitive polynomial remainder sequence (Collins; Knuth, TAOCP vol. 2, 4.6.1,
//! Algorithm E generalised to several variables):
//!
//! `gcd(a, b) = gcd(cont_x a, cont_x b) · pp_x(last non-zero r)` for the sequence
//! `r₀ = pp_x a`, `r₁ = pp_x b`, `rᵢ₊₁ = pp_x prem_x(rᵢ₋₁, rᵢ)`, where `x` is a generator
//! both hold, `cont_x` the gcd of the coefficients in `x` (a gcd in one generator fewer,
//! so the recursion ends) and `pp_x` the primitive part (Gauss's lemma makes the primitive
//! parts of the sequence the primitive part of the gcd). It is exact on every input and
//! ends after at most `deg_x` remainders per level; the [`Budget`] bounds its work.
//!
//! Trivial cases first, without any remainder: a zero or constant operand (an integer
//! gcd), a single-term operand (a monomial gcd: the least exponents of every term), a
//! monomial common to all terms (taken out first), and a generator only one operand holds
//! (`gcd(a, b) = gcd(cont_x a, b)` when `x` is not in `b`). The result is normalised: its
//! leading coefficient is positive, and `gcd(0, 0) = 0`.

use super::{Budget, Exponents, Polynomial};
use crate::algebra::error::AlgebraError;
use crate::algebra::rational::Q;

impl Polynomial {
    /// `gcd(self, other)`, normalised (module documentation).
    pub fn gcd(&self, other: &Polynomial, budget: &mut Budget) -> Result<Polynomial, AlgebraError> {
        if self.is_zero() || other.is_zero() || self.is_constant() || other.is_constant() {
            return Ok(if self.is_zero() {
                other.normalised()
            } else if other.is_zero() {
                self.normalised()
            } else {
                Polynomial::constant(
                    self.generators,
                    self.integer_content().integer_gcd(&other.integer_content()),
                )
            });
        }
        budget.spend(1)?;
        let common = least_exponents(self, other);
        if self.terms.len() == 1 || other.terms.len() == 1 {
            let c = self.integer_content().integer_gcd(&other.integer_content());
            return Ok(Polynomial::monomial(common, c));
        }
        if common.iter().any(|&e| e > 0) {
            let (a, b) = (
                self.without_monomial(&common),
                other.without_monomial(&common),
            );
            return Ok(a.gcd(&b, budget)?.times_term(&common, &Q::ONE));
        }
        for x in 0..self.generators {
            match (self.degree_in(x) > 0, other.degree_in(x) > 0) {
                (true, false) => return self.content_in(x, budget)?.gcd(other, budget),
                (false, true) => return self.gcd(&other.content_in(x, budget)?, budget),
                _ => {}
            }
        }
        let x = (0..self.generators)
            .filter(|&x| self.degree_in(x) > 0)
            .min_by_key(|&x| self.degree_in(x).max(other.degree_in(x)))
            .expect("two non-constant polynomials share a generator here");
        self.primitive_remainder_gcd(other, x, budget)
    }

    /// The gcd by the primitive remainder sequence in generator `x`, which both hold.
    fn primitive_remainder_gcd(
        &self,
        other: &Polynomial,
        x: usize,
        budget: &mut Budget,
    ) -> Result<Polynomial, AlgebraError> {
        let (content_a, content_b) = (self.content_in(x, budget)?, other.content_in(x, budget)?);
        let content = content_a.gcd(&content_b, budget)?;
        let mut a = self.divided_by_factor(&content_a, budget)?;
        let mut b = other.divided_by_factor(&content_b, budget)?;
        if a.degree_in(x) < b.degree_in(x) {
            std::mem::swap(&mut a, &mut b);
        }
        loop {
            let r = a.pseudo_remainder(&b, x, budget)?;
            if r.is_zero() {
                break;
            }
            if r.degree_in(x) == 0 {
                b = Polynomial::constant(self.generators, Q::ONE);
                break;
            }
            let r_content = r.content_in(x, budget)?;
            a = b;
            b = r.divided_by_factor(&r_content, budget)?;
        }
        Ok(content.mul(&b, budget)?.normalised())
    }

    /// `±self` with a positive leading coefficient.
    pub fn normalised(&self) -> Polynomial {
        if self.leading_coefficient().is_negative() {
            self.neg()
        } else {
            self.clone()
        }
    }

    /// `self / x^e` for a monomial `x^e` dividing every term.
    fn without_monomial(&self, e: &Exponents) -> Polynomial {
        let terms = self
            .terms
            .iter()
            .map(|t| super::Term {
                exponents: t.exponents.iter().zip(e).map(|(a, b)| a - b).collect(),
                coefficient: t.coefficient.clone(),
            })
            .collect();
        Polynomial::from_sorted(self.generators, terms)
    }
}

/// The least exponent of each generator over all terms of `a` and `b`: the monomial part
/// of their gcd.
fn least_exponents(a: &Polynomial, b: &Polynomial) -> Exponents {
    let mut least = a.terms[0].exponents.clone();
    for t in a.terms.iter().chain(&b.terms) {
        for (l, e) in least.iter_mut().zip(&t.exponents) {
            *l = (*l).min(*e);
        }
    }
    least
}
