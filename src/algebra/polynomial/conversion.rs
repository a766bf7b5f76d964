//! Expressions as rational functions `p/q` of polynomials, and polynomials back as
//! expressions.
//!
//! The generators are the expression's non-polynomial parts, as SymPy's `cancel` takes
//! them: symbols, functions (`sin θ`, opaque: their arguments are not looked into), powers
//! with a symbolic exponent, and for a rational exponent `p/q` the root `base^(1/q)`, of
//! which the power is the `p`-th (`x^(3/2) = (√x)³`, `x^(-1/2) = 1/√x`). A sum is a sum of
//! fractions, a product a product, an integer power of anything else a power of its
//! fraction (a negative one its reciprocal's; a power of a sum multiplied out by `expand`). Generators are numbered in the canonical
//! order of expressions, so the first weighs most in the polynomials' term order.

use super::budget::MAX_DEGREE;
use super::{Budget, Polynomial};
use crate::algebra::error::AlgebraError;
use crate::algebra::expr::{Expr, View};
use crate::algebra::rational::Q;
use std::collections::BTreeMap;

/// The generators of some expressions, numbered (module documentation).
pub(in crate::algebra) struct Generators {
    index: BTreeMap<Expr, usize>,
    list: Vec<Expr>,
}

/// `numerator / denominator`, the denominator not zero.
#[derive(Clone, Debug)]
pub(in crate::algebra) struct Fraction {
    pub numerator: Polynomial,
    pub denominator: Polynomial,
}

/// What an expression is to the conversion.
enum Piece<'a> {
    Number(&'a Q),
    Sum(&'a [Expr]),
    Product(&'a [Expr]),
    /// `base^k` for a base that is not a generator.
    Power(&'a Expr, i64),
    /// `generator^k`.
    Generator(Expr, i64),
    /// A power of a sum multiplied out, and whether it is the reciprocal's.
    MultipliedOut(Expr, bool),
}

fn piece(e: &Expr) -> Result<Piece<'_>, AlgebraError> {
    Ok(match e.view() {
        View::Num(q) => Piece::Number(q),
        View::Sym(_) | View::Func(..) => Piece::Generator(e.clone(), 1),
        View::Add(terms) => Piece::Sum(terms),
        View::Mul(factors) => Piece::Product(factors),
        View::Pow(base, exponent) => match exponent.as_num() {
            Some(n) => {
                let (p, q) = (n.numer().to_i64(), n.denom().to_i64());
                let (Some(p), Some(q)) = (p, q) else {
                    return Err(AlgebraError::ExponentOutOfRange(exponent.to_string()));
                };
                if p.unsigned_abs() > MAX_DEGREE {
                    return Err(AlgebraError::ExponentOutOfRange(exponent.to_string()));
                }
                if q == 1 && base.terms().len() > 1 && p.unsigned_abs() > 1 {
                    // A power of a sum by the multinomial theorem, as `expand` forms it.
                    let power = base.checked_pow(&Expr::int(p.abs()))?.expand()?;
                    Piece::MultipliedOut(power, p < 0)
                } else if q == 1 && base.as_symbol().is_none() {
                    Piece::Power(base, p)
                } else if q == 1 {
                    Piece::Generator(base.clone(), p)
                } else {
                    let root = base.checked_pow(&Expr::rational(1, q))?;
                    Piece::Generator(root, p)
                }
            }
            None => Piece::Generator(e.clone(), 1),
        },
    })
}

impl Generators {
    /// The generators of all the expressions, numbered in canonical order.
    pub fn of(exprs: &[&Expr]) -> Result<Generators, AlgebraError> {
        let mut found = BTreeMap::new();
        for e in exprs {
            collect(e, &mut found)?;
        }
        let list: Vec<Expr> = found.into_keys().collect();
        let index = list
            .iter()
            .cloned()
            .enumerate()
            .map(|(i, g)| (g, i))
            .collect();
        Ok(Generators { index, list })
    }

    /// `e` as a fraction of polynomials in these generators (not in lowest terms).
    /// Each piece is charged its generators: it makes at least one exponent vector of
    /// that length (50,000 different symbols in a sum would otherwise fill memory with
    /// 50,000 vectors of 50,000 exponents before any arithmetic is charged).
    pub fn fraction(&self, e: &Expr, budget: &mut Budget) -> Result<Fraction, AlgebraError> {
        let n = self.list.len();
        budget.spend(n as u64)?;
        let constant = |q: Q| Polynomial::constant(n, q);
        Ok(match piece(e)? {
            Piece::Number(q) => Fraction {
                numerator: constant(q.numer()),
                denominator: constant(q.denom()),
            },
            Piece::Generator(g, k) => {
                budget.check_degree(k.unsigned_abs())?;
                let power = Polynomial::generator_power(n, self.index[&g], k.unsigned_abs() as u32);
                let one = constant(Q::ONE);
                if k >= 0 {
                    Fraction::new(power, one)
                } else {
                    Fraction::new(one, power)
                }
            }
            Piece::Sum(terms) => {
                // The polynomial terms are gathered and sorted once; fractions are added.
                let mut polynomial_terms = Vec::new();
                let mut sum = Fraction::new(Polynomial::zero(n), constant(Q::ONE));
                for t in terms {
                    let f = self.fraction(t, budget)?;
                    if f.denominator.is_one() {
                        polynomial_terms.extend(f.numerator.terms);
                    } else {
                        sum = sum.add(&f, budget)?;
                    }
                }
                let polynomial = Polynomial::from_unsorted(n, polynomial_terms);
                sum.add(&Fraction::new(polynomial, constant(Q::ONE)), budget)?
            }
            Piece::Product(factors) if e.coefficient().is_integer() => match self.monomial(factors)
            {
                Some(exponents) => Fraction::new(
                    Polynomial::monomial(exponents, e.coefficient().clone()),
                    constant(Q::ONE),
                ),
                None => self.product(factors, budget)?,
            },
            Piece::Product(factors) => self.product(factors, budget)?,
            Piece::MultipliedOut(power, reciprocal) => {
                let f = self.fraction(&power, budget)?;
                if reciprocal {
                    f.reciprocal()?
                } else {
                    f
                }
            }
            Piece::Power(base, k) => {
                budget.check_degree(k.unsigned_abs())?;
                let f = self.fraction(base, budget)?;
                let f = if k < 0 { f.reciprocal()? } else { f };
                let k = k.unsigned_abs() as u32;
                Fraction::new(f.numerator.pow(k, budget)?, f.denominator.pow(k, budget)?)
            }
        })
    }

    /// The product of the factors' fractions.
    fn product(&self, factors: &[Expr], budget: &mut Budget) -> Result<Fraction, AlgebraError> {
        let n = self.list.len();
        let mut product = Fraction::new(
            Polynomial::constant(n, Q::ONE),
            Polynomial::constant(n, Q::ONE),
        );
        for f in factors {
            product = product.mul(&self.fraction(f, budget)?, budget)?;
        }
        Ok(product)
    }

    /// The exponents of a product of positive integer powers of symbols (its number left
    /// out), read at once; none for any other product.
    fn monomial(&self, factors: &[Expr]) -> Option<super::Exponents> {
        let mut exponents = super::Exponents::from_elem(0, self.list.len());
        for f in factors.iter().filter(|f| f.as_num().is_none()) {
            let (base, exponent) = f.base_and_exponent();
            let k = exponent.as_num()?.to_i64()?;
            if base.as_symbol().is_none() || k <= 0 || k.unsigned_abs() > MAX_DEGREE {
                return None;
            }
            exponents[self.index[base]] = k as u32;
        }
        Some(exponents)
    }

    /// The polynomial as an expression: the sum of its terms `c·Π gᵢ^eᵢ`.
    pub fn expr(&self, p: &Polynomial) -> Expr {
        Expr::add_all(p.terms().iter().map(|t| {
            let powers = t
                .exponents
                .iter()
                .zip(&self.list)
                .filter(|(&e, _)| e > 0)
                .map(|(&e, g)| g.powi(i64::from(e)));
            Expr::mul_all(std::iter::once(Expr::num(t.coefficient.clone())).chain(powers))
        }))
    }
}

/// Adds the generators of `e` to `found`.
fn collect(e: &Expr, found: &mut BTreeMap<Expr, ()>) -> Result<(), AlgebraError> {
    match piece(e)? {
        Piece::Number(_) => {}
        Piece::Generator(g, _) => {
            found.insert(g, ());
        }
        Piece::Sum(operands) | Piece::Product(operands) => {
            operands.iter().try_for_each(|x| collect(x, found))?;
        }
        Piece::Power(base, _) => collect(base, found)?,
        Piece::MultipliedOut(power, _) => collect(&power, found)?,
    }
    Ok(())
}

impl Fraction {
    pub fn new(numerator: Polynomial, denominator: Polynomial) -> Fraction {
        Fraction {
            numerator,
            denominator,
        }
    }

    /// `1 / self`, or an error when `self` is zero.
    fn reciprocal(self) -> Result<Fraction, AlgebraError> {
        if self.numerator.is_zero() {
            return Err(AlgebraError::DivisionByZero);
        }
        Ok(Fraction::new(self.denominator, self.numerator))
    }

    /// `a/b + c/d` over `lcm(b, d) = b·(d/g)` with `g = gcd(b, d)` (`b` itself when `b = d`).
    fn add(&self, other: &Fraction, budget: &mut Budget) -> Result<Fraction, AlgebraError> {
        if self.denominator == other.denominator {
            return Ok(Fraction::new(
                self.numerator.add(&other.numerator),
                self.denominator.clone(),
            ));
        }
        let g = self.denominator.gcd(&other.denominator, budget)?;
        let self_cofactor = self.denominator.divided_by_factor(&g, budget)?;
        let other_cofactor = other.denominator.divided_by_factor(&g, budget)?;
        let numerator = self
            .numerator
            .mul(&other_cofactor, budget)?
            .add(&other.numerator.mul(&self_cofactor, budget)?);
        Ok(Fraction::new(
            numerator,
            self.denominator.mul(&other_cofactor, budget)?,
        ))
    }

    fn mul(&self, other: &Fraction, budget: &mut Budget) -> Result<Fraction, AlgebraError> {
        Ok(Fraction::new(
            self.numerator.mul(&other.numerator, budget)?,
            self.denominator.mul(&other.denominator, budget)?,
        ))
    }

    /// The fraction in lowest terms: both parts divided by their gcd, the denominator's
    /// leading coefficient positive (`0/1` for zero).
    pub fn reduced(&self, budget: &mut Budget) -> Result<Fraction, AlgebraError> {
        let n = self.numerator.generators();
        if self.numerator.is_zero() {
            return Ok(Fraction::new(
                Polynomial::zero(n),
                Polynomial::constant(n, Q::ONE),
            ));
        }
        let g = self.numerator.gcd(&self.denominator, budget)?;
        let g = if self.denominator.leading_coefficient().is_negative() {
            g.neg()
        } else {
            g
        };
        Ok(Fraction::new(
            self.numerator.divided_by_factor(&g, budget)?,
            self.denominator.divided_by_factor(&g, budget)?,
        ))
    }
}
