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
        match self.trivial_gcd(other) {
            Trivial::Answer(gcd) => return Ok(gcd),
            Trivial::WithoutMonomial(a, b, common) => {
                return Ok(a.gcd(&b, budget)?.times_term(&common, &Q::ONE))
            }
            Trivial::No => budget.spend(1)?,
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
        match self.heuristic_gcd(other, x, budget)? {
            Some(gcd) => Ok(gcd),
            None => self.primitive_remainder_gcd(other, x, budget),
        }
    }

    /// The gcd by the heuristic alone, all the way down (none when it finds none): the
    /// heuristic's own gcd of values, whose fallback would be a remainder sequence on the
    /// values' large integers.
    pub(super) fn heuristic_only_gcd(
        &self,
        other: &Polynomial,
        budget: &mut Budget,
    ) -> Result<Option<Polynomial>, AlgebraError> {
        match self.trivial_gcd(other) {
            Trivial::Answer(gcd) => Ok(Some(gcd)),
            Trivial::WithoutMonomial(a, b, common) => Ok(a
                .heuristic_only_gcd(&b, budget)?
                .map(|gcd| gcd.times_term(&common, &Q::ONE))),
            Trivial::No => {
                budget.spend(1)?;
                let x = (0..self.generators)
                    .find(|&x| self.degree_in(x) > 0 || other.degree_in(x) > 0)
                    .expect("a polynomial that is not constant holds a generator");
                self.heuristic_gcd(other, x, budget)
            }
        }
    }

    /// The gcd when a trivial case gives it: a zero or constant operand, a single-term
    /// one; or the monomial common to all terms, to take out first.
    fn trivial_gcd(&self, other: &Polynomial) -> Trivial {
        if self.is_zero() || other.is_zero() || self.is_constant() || other.is_constant() {
            return Trivial::Answer(if self.is_zero() {
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
        let common = least_exponents(self, other);
        if self.terms.len() == 1 || other.terms.len() == 1 {
            let c = self.integer_content().integer_gcd(&other.integer_content());
            return Trivial::Answer(Polynomial::monomial(common, c));
        }
        if common.iter().any(|&e| e > 0) {
            return Trivial::WithoutMonomial(
                self.without_monomial(&common),
                other.without_monomial(&common),
                common,
            );
        }
        Trivial::No
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

/// What the trivial cases make of a gcd.
enum Trivial {
    Answer(Polynomial),
    /// `gcd(a·m, b·m) = gcd(a, b)·m` for the monomial `m` common to all terms.
    WithoutMonomial(Polynomial, Polynomial, Exponents),
    No,
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

#[cfg(test)]
mod tests {
    use super::super::{Budget, Generators, Polynomial};
    use crate::algebra::{AlgebraError, Expr};
    use proptest::prelude::*;

    const NAMES: [&str; 4] = ["a", "b", "x", "y"];

    fn polynomial() -> impl Strategy<Value = Expr> {
        let term = (
            -5i64..=5,
            prop::collection::vec((0..NAMES.len(), 1i64..=2), 0..=3),
        )
            .prop_map(|(c, powers)| {
                Expr::mul_all(
                    std::iter::once(Expr::int(c)).chain(
                        powers
                            .into_iter()
                            .map(|(i, k)| Expr::symbol(NAMES[i]).powi(k)),
                    ),
                )
            });
        prop::collection::vec(term, 1..=5).prop_map(Expr::add_all)
    }

    fn polynomials(a: &Expr, b: &Expr, budget: &mut Budget) -> (Polynomial, Polynomial) {
        let generators = Generators::of(&[a, b]).unwrap();
        let mut numerator = |e| generators.fraction(e, budget).unwrap().numerator;
        (numerator(a), numerator(b))
    }

    proptest! {
        /// The fallback, which the heuristic leaves unused on most inputs, gives the same gcd.
        #[test]
        fn the_remainder_sequence_agrees_with_the_heuristic(
            p in polynomial(),
            q in polynomial(),
            g in polynomial(),
        ) {
            let mut budget = Budget::new("a test");
            let a = (&p * &g).expand().unwrap();
            let b = (&q * &g).expand().unwrap();
            let (a, b) = polynomials(&a, &b, &mut budget);
            let shared = (0..a.generators()).find(|&x| a.degree_in(x) > 0 && b.degree_in(x) > 0);
            prop_assume!(shared.is_some());
            // In four generators the sequence's coefficients can grow past the work bound
            // (a^4 + a^2 x − a + y + 1 and a^5 − a^2 b^3 + b y^2 + b times a b + a y^2 + x − 1
            // did): then it refuses, and must never answer with another gcd.
            match a.primitive_remainder_gcd(&b, shared.unwrap(), &mut budget) {
                Ok(by_remainders) => {
                    let heuristic = a.gcd(&b, &mut Budget::new("a test")).unwrap();
                    prop_assert_eq!(by_remainders, heuristic);
                }
                Err(AlgebraError::TooMuchWork { .. }) => {}
                Err(other) => prop_assert!(false, "the remainder sequence failed: {}", other),
            }
        }
    }
}
