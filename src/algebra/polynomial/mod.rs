//! Sparse multivariate polynomials with integer coefficients, `Σ cₖ x^eₖ` over numbered
//! generators `x₀ … xₙ₋₁`: the representation the rational functions of `cancel` are
//! reduced in.
//!
//! A polynomial is its list of terms, each an exponent vector and a non-zero integer
//! coefficient (a [`Q`] with denominator 1: machine words, big integers past them), sorted
//! by the lexicographic order of the exponent vectors, largest first: `x₀` weighs most, so
//! the first term is the leading term and its coefficient the leading coefficient. Every
//! operation keeps that form; those that can grow are charged to a [`Budget`].

mod arithmetic;
mod budget;
mod content;
mod conversion;
mod division;
mod gcd;
mod heuristic_gcd;

pub(in crate::algebra) use budget::Budget;
pub(in crate::algebra) use conversion::Generators;

use super::rational::Q;
use smallvec::SmallVec;

/// The exponents of a term, one per generator.
pub(in crate::algebra) type Exponents = SmallVec<[u32; 8]>;

/// One term `c x^e` (`c` a non-zero integer).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(in crate::algebra) struct Term {
    pub exponents: Exponents,
    pub coefficient: Q,
}

/// A polynomial in `generators` variables (see the module documentation).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(in crate::algebra) struct Polynomial {
    generators: usize,
    terms: Vec<Term>,
}

impl Polynomial {
    /// `0` in `generators` variables.
    pub fn zero(generators: usize) -> Polynomial {
        Polynomial {
            generators,
            terms: Vec::new(),
        }
    }

    /// The constant `c` (an integer).
    pub fn constant(generators: usize, c: Q) -> Polynomial {
        Polynomial::monomial(Exponents::from_elem(0, generators), c)
    }

    /// The term `c x^exponents` (zero when `c` is).
    pub fn monomial(exponents: Exponents, c: Q) -> Polynomial {
        let generators = exponents.len();
        let terms = if c.is_zero() {
            Vec::new()
        } else {
            vec![Term {
                exponents,
                coefficient: c,
            }]
        };
        Polynomial { generators, terms }
    }

    /// `x_i^k`.
    pub fn generator_power(generators: usize, i: usize, k: u32) -> Polynomial {
        let mut exponents = Exponents::from_elem(0, generators);
        exponents[i] = k;
        Polynomial::monomial(exponents, Q::ONE)
    }

    /// The polynomial of terms already in order, distinct and non-zero.
    fn from_sorted(generators: usize, terms: Vec<Term>) -> Polynomial {
        debug_assert!(terms.windows(2).all(|w| w[0].exponents > w[1].exponents));
        debug_assert!(terms.iter().all(|t| !t.coefficient.is_zero()));
        Polynomial { generators, terms }
    }

    /// The polynomial of terms in any order, like terms combined and zeros dropped.
    fn from_unsorted(generators: usize, mut terms: Vec<Term>) -> Polynomial {
        terms.sort_unstable_by(|a, b| b.exponents.cmp(&a.exponents));
        let mut out: Vec<Term> = Vec::with_capacity(terms.len());
        for t in terms {
            match out.last_mut() {
                Some(last) if last.exponents == t.exponents => {
                    last.coefficient = &last.coefficient + &t.coefficient;
                    if last.coefficient.is_zero() {
                        out.pop();
                    }
                }
                _ => out.push(t),
            }
        }
        Polynomial::from_sorted(generators, out)
    }

    pub fn generators(&self) -> usize {
        self.generators
    }

    pub fn terms(&self) -> &[Term] {
        &self.terms
    }

    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// A constant (zero included): no term holds a generator.
    pub fn is_constant(&self) -> bool {
        self.terms
            .iter()
            .all(|t| t.exponents.iter().all(|&e| e == 0))
    }

    /// The constant `1`.
    pub fn is_one(&self) -> bool {
        self.is_constant() && self.terms.len() == 1 && self.terms[0].coefficient.is_one()
    }

    /// The coefficient of the leading term (zero for zero).
    pub fn leading_coefficient(&self) -> Q {
        self.terms
            .first()
            .map_or(Q::ZERO, |t| t.coefficient.clone())
    }

    /// The largest sum of a term's exponents (0 for zero).
    pub fn total_degree(&self) -> u64 {
        self.terms
            .iter()
            .map(|t| t.exponents.iter().map(|&e| u64::from(e)).sum())
            .max()
            .unwrap_or(0)
    }

    /// The bits of the longest coefficient.
    pub fn coefficient_bits(&self) -> u64 {
        self.terms
            .iter()
            .map(|t| t.coefficient.bit_lengths().0)
            .max()
            .unwrap_or(0)
    }

    /// The largest exponent of generator `i` (0 for zero).
    pub fn degree_in(&self, i: usize) -> u32 {
        self.terms.iter().map(|t| t.exponents[i]).max().unwrap_or(0)
    }
}
