//! Division of polynomials with integer coefficients.
//!
//! - Exact division `a / b`: in the lexicographic order the leading term of a multiple of
//!   `b` is the leading term of `b` times that of the quotient, so dividing leading terms
//!   (`lt(r)/lt(b)`, which must be a monomial with an integer coefficient) and subtracting
//!   decides divisibility: a remainder that cannot be divided so means `b ∤ a`.
//! - The pseudo-remainder of `a` by `b` in the generator `x`: with `l = lc_x(b)` and
//!   `d = deg_x(b)`, while `deg_x(r) ≥ d`, `r ← l·r − lc_x(r)·x^(deg_x(r)−d)·b`; so
//!   `l^k·a = q·b + r` with `deg_x(r) < d`, all over the integers (no fractions).

use super::{Budget, Exponents, Polynomial};
use crate::algebra::error::AlgebraError;

impl Polynomial {
    /// `self / divisor` when the division is exact, `None` when it is not. `divisor ≠ 0`.
    pub fn exact_quotient(
        &self,
        divisor: &Polynomial,
        budget: &mut Budget,
    ) -> Result<Option<Polynomial>, AlgebraError> {
        debug_assert!(!divisor.is_zero());
        if divisor.is_one() {
            return Ok(Some(self.clone()));
        }
        let lead = &divisor.terms[0];
        let divisor_bits = divisor.coefficient_bits();
        let mut quotient = Vec::new();
        let mut rest = self.clone();
        while let Some(top) = rest.terms.first() {
            budget.spend_on(
                (rest.terms.len() + divisor.terms.len()) as u64,
                top.coefficient.bit_lengths().0,
                divisor_bits,
            )?;
            let Some(exponents) = top
                .exponents
                .iter()
                .zip(&lead.exponents)
                .map(|(a, b)| a.checked_sub(*b))
                .collect::<Option<Exponents>>()
            else {
                return Ok(None);
            };
            let c = match top.coefficient.checked_div(&lead.coefficient) {
                Some(c) if c.is_integer() => c,
                _ => return Ok(None),
            };
            rest = rest.sub(&divisor.times_term(&exponents, &c));
            quotient.push(super::Term {
                exponents,
                coefficient: c,
            });
        }
        Ok(Some(Polynomial::from_sorted(self.generators, quotient)))
    }

    /// The pseudo-remainder of `self` by `divisor` in generator `x` (module documentation);
    /// `divisor` has a positive degree in `x`.
    pub fn pseudo_remainder(
        &self,
        divisor: &Polynomial,
        x: usize,
        budget: &mut Budget,
    ) -> Result<Polynomial, AlgebraError> {
        let d = divisor.degree_in(x);
        let lead = divisor.coefficient_in(x, d);
        let mut rest = self.clone();
        while !rest.is_zero() && rest.degree_in(x) >= d {
            let k = rest.degree_in(x);
            let mut shift = Exponents::from_elem(0, self.generators);
            shift[x] = k - d;
            let top = rest
                .coefficient_in(x, k)
                .times_term(&shift, &crate::algebra::Q::ONE);
            budget.spend_on(rest.terms.len() as u64, rest.coefficient_bits(), 64)?;
            let scaled = if lead.is_one() {
                rest
            } else {
                lead.mul(&rest, budget)?
            };
            rest = scaled.sub(&top.mul(divisor, budget)?);
        }
        Ok(rest)
    }
}
