//! The heuristic gcd (GCDHEU; Char, Geddes and Gonnet 1989, as SymPy's `heugcd`): a gcd of
//! integers standing for one of polynomials.
//!
//! With the integer contents taken out (their gcd `c` put back at the end), evaluate both
//! polynomials at `x = ξ` for one generator `x`, take the gcd `γ` of the two values (a gcd
//! in one generator fewer, by this heuristic again: its failure is the whole one's), and read `γ`'s integer coefficients
//! as numbers in base `ξ` with digits in `(−ξ/2, ξ/2]`: the digit of `ξᵏ` is the
//! coefficient of `xᵏ`. For `ξ ≥ 2·min(|a|∞, |b|∞) + 2`, that polynomial's primitive part
//! `h` is the gcd if it divides both `a` and `b` (the theorem of the paper), which exact
//! division checks; otherwise a larger `ξ` is tried, six times at most. A failure (or
//! values past [`MAX_VALUE_BITS`]) is no answer, and the caller falls back to the
//! remainder sequence, so the result is always the gcd.

use super::{Budget, Polynomial, Term};
use crate::algebra::error::AlgebraError;
use crate::algebra::rational::Q;

/// Largest values tried, in bits (of the point's largest power times a coefficient): past
/// it the integers cost more than the remainder sequence would.
pub const MAX_VALUE_BITS: u64 = 32_768;

/// Evaluation points tried before giving up.
const ATTEMPTS: usize = 6;

impl Polynomial {
    /// The gcd of two polynomials, evaluated at generator `x`, or none when the heuristic
    /// found none (module documentation).
    pub(super) fn heuristic_gcd(
        &self,
        other: &Polynomial,
        x: usize,
        budget: &mut Budget,
    ) -> Result<Option<Polynomial>, AlgebraError> {
        let (content_a, content_b) = (self.integer_content(), other.integer_content());
        let content = content_a.integer_gcd(&content_b);
        let a = self.integer_quotient(&content_a);
        let b = other.integer_quotient(&content_b);
        let norm = a.max_norm().min(b.max_norm());
        let mut point = &(&Q::int(2) * &norm) + &Q::int(29);
        for _ in 0..ATTEMPTS {
            let degree = u64::from(a.degree_in(x).max(b.degree_in(x)));
            let norm_bits = a.max_norm().max(b.max_norm()).bit_lengths().0;
            if point.bit_lengths().0 * degree + norm_bits > MAX_VALUE_BITS {
                return Ok(None);
            }
            let (value_a, value_b) = (
                a.evaluated(x, &point, budget)?,
                b.evaluated(x, &point, budget)?,
            );
            if !value_a.is_zero() && !value_b.is_zero() {
                let Some(gamma) = value_a.heuristic_only_gcd(&value_b, budget)? else {
                    return Ok(None);
                };
                // γ is not zero, nor then is its interpolation.
                let h = gamma.interpolated(x, &point, budget)?;
                let h = h.integer_quotient(&h.integer_content()).normalised();
                if a.exact_quotient(&h, budget)?.is_some()
                    && b.exact_quotient(&h, budget)?.is_some()
                {
                    return Ok(Some(h.scaled(&content)));
                }
            }
            point = &(&Q::int(4) * &point) + &Q::int(3);
        }
        Ok(None)
    }

    /// The largest magnitude of a coefficient.
    fn max_norm(&self) -> Q {
        self.terms
            .iter()
            .map(|t| t.coefficient.abs())
            .max()
            .unwrap_or(Q::ZERO)
    }

    /// `self / c` for an integer `c ≠ 0` dividing every coefficient.
    fn integer_quotient(&self, c: &Q) -> Polynomial {
        let inverse = c
            .recip()
            .expect("a content of a non-zero polynomial is not zero");
        self.scaled(&inverse)
    }

    /// `self` with generator `x` replaced by the integer `point`.
    fn evaluated(
        &self,
        x: usize,
        point: &Q,
        budget: &mut Budget,
    ) -> Result<Polynomial, AlgebraError> {
        budget.spend_on(
            self.terms.len() as u64,
            self.coefficient_bits(),
            point.bit_lengths().0 * u64::from(self.degree_in(x)),
        )?;
        let degree = self.degree_in(x) as usize;
        let mut powers = vec![Q::ONE];
        for k in 1..=degree {
            powers.push(&powers[k - 1] * point);
        }
        let terms = self
            .terms
            .iter()
            .map(|t| {
                let mut exponents = t.exponents.clone();
                exponents[x] = 0;
                Term {
                    exponents,
                    coefficient: &t.coefficient * &powers[t.exponents[x] as usize],
                }
            })
            .collect();
        Ok(Polynomial::from_unsorted(self.generators, terms))
    }

    /// The polynomial in `x` whose value at `point` is `self`, each coefficient read in
    /// base `point` with digits in `(−point/2, point/2]`.
    fn interpolated(
        &self,
        x: usize,
        point: &Q,
        budget: &mut Budget,
    ) -> Result<Polynomial, AlgebraError> {
        let half = point.checked_div(&Q::int(2)).expect("two is not zero");
        let mut terms = Vec::new();
        for t in &self.terms {
            let mut rest = t.coefficient.clone();
            let mut k = 0u32;
            while !rest.is_zero() {
                budget.spend_on(1, rest.bit_lengths().0, point.bit_lengths().0)?;
                let mut digit = rest.integer_rem_euclid(point);
                if digit > half {
                    digit = &digit - point;
                }
                rest = (&rest - &digit)
                    .checked_div(point)
                    .expect("the point is not zero");
                if !digit.is_zero() {
                    let mut exponents = t.exponents.clone();
                    exponents[x] = k;
                    terms.push(Term {
                        exponents,
                        coefficient: digit,
                    });
                }
                k += 1;
            }
        }
        Ok(Polynomial::from_unsorted(self.generators, terms))
    }
}
