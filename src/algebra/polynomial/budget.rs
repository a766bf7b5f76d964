//! The bound on the work of polynomial arithmetic: every product, division step and
//! remainder is charged its number of term operations (weighted by the length of long
//! coefficients), and the total may not pass
//! [`MAX_TERM_OPERATIONS`] (a few tenths of a second); no result may hold more than
//! [`MAX_EXPANDED_TERMS`] terms or a coefficient of more than [`MAX_DIGITS`] digits. Past
//! either bound the operation is refused with an [`AlgebraError`], never left to run.
//! Every operation is charged to the command's work budget ([`crate::algebra::work`]) too.

use crate::algebra::digit_bound::MAX_DIGITS;
use crate::algebra::error::{AlgebraError, MAX_EXPANDED_TERMS};

use super::Polynomial;

/// Largest number of term operations (a product of two terms, a term merged or compared in
/// a division step) one cancellation or gcd may take.
pub const MAX_TERM_OPERATIONS: u64 = 2_000_000;

/// Largest degree of a polynomial in any generator (and of a power's total degree): far
/// past any product a person writes, and far from overflowing an exponent.
pub const MAX_DEGREE: u64 = 100_000;

/// Largest number of products of two terms one multiplication may form before like terms
/// are combined (as `expand` allows).
pub const MAX_UNCOMBINED_PRODUCTS: u64 = 4 * MAX_EXPANDED_TERMS as u64;

/// The work left to an operation (see the module documentation).
#[derive(Debug)]
pub(in crate::algebra) struct Budget {
    what: &'static str,
    left: u64,
}

impl Budget {
    /// A full budget for the named operation (`"the cancellation"`, named in its error).
    pub fn new(what: &'static str) -> Budget {
        Budget {
            what,
            left: MAX_TERM_OPERATIONS,
        }
    }

    /// Charges `operations` term operations, or refuses when too few are left.
    pub fn spend(&mut self, operations: u64) -> Result<(), AlgebraError> {
        crate::algebra::work::spend(operations)?;
        match self.left.checked_sub(operations) {
            Some(left) => {
                self.left = left;
                Ok(())
            }
            None => Err(AlgebraError::TooMuchWork {
                what: self.what.to_string(),
                limit: MAX_TERM_OPERATIONS,
            }),
        }
    }

    /// Charges `operations` term operations on coefficients of `bits_a` and `bits_b` bits:
    /// each counts once more per sixteen products of the numbers' machine words (a
    /// product of long integers costs about the product of their lengths).
    pub fn spend_on(
        &mut self,
        operations: u64,
        bits_a: u64,
        bits_b: u64,
    ) -> Result<(), AlgebraError> {
        let words = |bits: u64| bits / 64 + 1;
        let weight = 1 + words(bits_a).saturating_mul(words(bits_b)) / 16;
        self.spend(operations.saturating_mul(weight))
    }

    /// Refuses a product whose degree in some generator would pass [`MAX_DEGREE`].
    pub fn check_degrees(&self, a: &Polynomial, b: &Polynomial) -> Result<(), AlgebraError> {
        (0..a.generators()).try_for_each(|i| {
            self.check_degree(u64::from(a.degree_in(i)) + u64::from(b.degree_in(i)))
        })
    }

    /// Refuses a degree past [`MAX_DEGREE`].
    pub fn check_degree(&self, degree: u64) -> Result<(), AlgebraError> {
        if degree > MAX_DEGREE {
            return Err(AlgebraError::ExponentOutOfRange(format!(
                "{degree} (a power in {}, past the degree {MAX_DEGREE})",
                self.what
            )));
        }
        Ok(())
    }

    /// Refuses a result estimated to hold more than [`MAX_EXPANDED_TERMS`] terms.
    pub fn check_term_count(&self, terms: f64) -> Result<(), AlgebraError> {
        if terms > MAX_EXPANDED_TERMS as f64 {
            return Err(self.too_many_terms(format!("about {terms:.0}")));
        }
        Ok(())
    }

    /// Refuses a product of more than [`MAX_UNCOMBINED_PRODUCTS`] pairs of terms.
    pub fn check_products(&self, products: u64) -> Result<(), AlgebraError> {
        if products > MAX_UNCOMBINED_PRODUCTS {
            return Err(self.too_many_terms(format!("up to {products}")));
        }
        Ok(())
    }

    fn too_many_terms(&self, size: String) -> AlgebraError {
        AlgebraError::TooLarge {
            what: format!("a polynomial in {}", self.what),
            size,
            limit: MAX_EXPANDED_TERMS,
        }
    }

    /// Refuses a polynomial with too many terms or too long a coefficient.
    pub fn check_size(&self, p: &Polynomial) -> Result<(), AlgebraError> {
        if p.terms().len() > MAX_EXPANDED_TERMS {
            return Err(self.too_many_terms(p.terms().len().to_string()));
        }
        let max_bits = (MAX_DIGITS as f64 * std::f64::consts::LOG2_10) as u64;
        let bits = p.coefficient_bits();
        if bits > max_bits {
            return Err(AlgebraError::NumberTooLarge {
                what: format!("a coefficient in {}", self.what),
                digits: (bits as f64 / std::f64::consts::LOG2_10) as u64,
                limit: MAX_DIGITS,
            });
        }
        Ok(())
    }
}
