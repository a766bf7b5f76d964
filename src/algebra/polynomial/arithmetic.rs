//! Ring operations on sparse polynomials: `p + q` and `p − q` by merging the two sorted
//! term lists, `c·x^e·p` term by term (a monomial factor keeps the order), `p·q` as a
//! sum of merged copies of the longer operand when the shorter is short, else as all
//! products of terms sorted once with like terms combined, and `pⁿ` by repeated
//! multiplication. Products are charged to the [`Budget`] and their size checked.

use super::{Budget, Exponents, Polynomial, Term};
use crate::algebra::error::AlgebraError;
use crate::algebra::rational::Q;
use std::cmp::Ordering;

/// Up to this many terms, a product is formed as a sum of the long operand's shifted copies
/// (each a merge, keeping the order), not as all products of terms sorted once.
const MERGED_MULTIPLIER_TERMS: usize = 8;

impl Polynomial {
    /// `self + sign·other`, by one merge of the two ordered term lists.
    fn merged(&self, other: &Polynomial, sign: &Q) -> Polynomial {
        let (a, b) = (&self.terms, &other.terms);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a[i].exponents.cmp(&b[j].exponents) {
                Ordering::Greater => {
                    out.push(a[i].clone());
                    i += 1;
                }
                Ordering::Less => {
                    out.push(b[j].scaled(sign));
                    j += 1;
                }
                Ordering::Equal => {
                    let c = &a[i].coefficient + &(sign * &b[j].coefficient);
                    if !c.is_zero() {
                        out.push(Term {
                            exponents: a[i].exponents.clone(),
                            coefficient: c,
                        });
                    }
                    i += 1;
                    j += 1;
                }
            }
        }
        out.extend(a[i..].iter().cloned());
        out.extend(b[j..].iter().map(|t| t.scaled(sign)));
        Polynomial::from_sorted(self.generators, out)
    }

    pub fn add(&self, other: &Polynomial) -> Polynomial {
        self.merged(other, &Q::ONE)
    }

    pub fn sub(&self, other: &Polynomial) -> Polynomial {
        self.merged(other, &Q::MINUS_ONE)
    }

    pub fn neg(&self) -> Polynomial {
        self.scaled(&Q::MINUS_ONE)
    }

    /// `c·self` for an integer `c`.
    pub fn scaled(&self, c: &Q) -> Polynomial {
        self.times_term(&Exponents::from_elem(0, self.generators), c)
    }

    /// `c·x^e·self`: every term moves alike, so the order is kept.
    pub fn times_term(&self, exponents: &Exponents, c: &Q) -> Polynomial {
        if c.is_zero() {
            return Polynomial::zero(self.generators);
        }
        let terms = self
            .terms
            .iter()
            .map(|t| Term {
                exponents: t
                    .exponents
                    .iter()
                    .zip(exponents)
                    .map(|(a, b)| a + b)
                    .collect(),
                coefficient: c * &t.coefficient,
            })
            .collect();
        Polynomial::from_sorted(self.generators, terms)
    }

    /// `self · other`, charged `|self|·|other|` term operations.
    pub fn mul(&self, other: &Polynomial, budget: &mut Budget) -> Result<Polynomial, AlgebraError> {
        let (short, long) = if self.terms.len() <= other.terms.len() {
            (self, other)
        } else {
            (other, self)
        };
        budget.check_degrees(self, other)?;
        let products = (short.terms.len() as u64).saturating_mul(long.terms.len() as u64);
        budget.check_products(products)?;
        budget.spend_on(products, self.coefficient_bits(), other.coefficient_bits())?;
        let product = match short.terms.as_slice() {
            [] => Polynomial::zero(self.generators),
            [t] => long.times_term(&t.exponents, &t.coefficient),
            _ if short.terms.len() <= MERGED_MULTIPLIER_TERMS => short
                .terms
                .iter()
                .fold(Polynomial::zero(self.generators), |sum, t| {
                    sum.add(&long.times_term(&t.exponents, &t.coefficient))
                }),
            _ => {
                let mut terms = Vec::with_capacity(short.terms.len() * long.terms.len());
                for s in &short.terms {
                    for l in &long.terms {
                        terms.push(Term {
                            exponents: s
                                .exponents
                                .iter()
                                .zip(&l.exponents)
                                .map(|(a, b)| a + b)
                                .collect(),
                            coefficient: &s.coefficient * &l.coefficient,
                        });
                    }
                }
                Polynomial::from_unsorted(self.generators, terms)
            }
        };
        budget.check_size(&product)?;
        Ok(product)
    }

    /// `selfⁿ`.
    pub fn pow(&self, n: u32, budget: &mut Budget) -> Result<Polynomial, AlgebraError> {
        let mut power = Polynomial::constant(self.generators, Q::ONE);
        if n > 1 && !self.is_constant() {
            budget.check_degree(self.total_degree().saturating_mul(u64::from(n)))?;
            budget.check_term_count(self.power_terms_bound(n))?;
        }
        for _ in 0..n {
            power = power.mul(self, budget)?;
        }
        Ok(power)
    }
}

impl Polynomial {
    /// An upper bound on the terms of `selfⁿ`: the number of multisets of `n` of its `t`
    /// terms, `C(t + n − 1, n)`, and the number of exponent vectors below `n` times its
    /// degrees, `Π (n·degᵢ + 1)`, whichever is smaller.
    fn power_terms_bound(&self, n: u32) -> f64 {
        let n = f64::from(n);
        let multisets = (1..=self.terms.len().saturating_sub(1))
            .map(|k| (n + k as f64) / k as f64)
            .product::<f64>();
        let dense = (0..self.generators)
            .map(|i| n * f64::from(self.degree_in(i)) + 1.0)
            .product::<f64>();
        multisets.min(dense)
    }
}

impl Term {
    fn scaled(&self, c: &Q) -> Term {
        Term {
            exponents: self.exponents.clone(),
            coefficient: c * &self.coefficient,
        }
    }
}
