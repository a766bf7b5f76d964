//! `factor_terms`: the factors common to all terms of a sum pulled out in front, in every
//! sum of the expression, inner ones first (SymPy's `factor_terms`):
//!
//! `Σ cᵢ Πⱼ bⱼ^eᵢⱼ = g · Π bⱼ^eⱼ · Σ (cᵢ/g) Πⱼ bⱼ^(eᵢⱼ−eⱼ)`
//!
//! where `g` is the content of the coefficients (the gcd of their numerators over the lcm
//! of their denominators, negative when every coefficient is) and `eⱼ` the exponent of a
//! base every term holds: the one nearest zero when all its exponents are numbers of one
//! sign, the common one when they are equal. So
//! `-1/12 m b² - 1/12 m c² = -1/12 m (b² + c²)`, `x/a + y/a = (x + y)/a`, and a fraction's
//! numerator and denominator are each so factored. A sum whose only common factor is a
//! number stays a sum (a number times a sum is distributed in canonical form).
//!
//! A sum whose terms hold sums has, besides, the gcd of its terms as polynomials pulled
//! out when that is shorter by [`Expr::operation_count`]: `a(b² − c²) + d(b + c) =
//! (b + c)(a b − a c + d)`; one work bound (`polynomial/budget.rs`) for the whole
//! expression, past which the sums stay as they are.

use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::polynomial::{Budget, Generators};
use super::rational::Q;

impl Expr {
    /// The expression with the common factors of every sum pulled out (module
    /// documentation).
    ///
    /// ```
    /// use kinetics::parse_expression;
    /// let e = parse_expression("", "-1/12*m*b^2 - 1/12*m*c^2").unwrap();
    /// let factored = parse_expression("", "-1/12*m*(b^2 + c^2)").unwrap();
    /// assert_eq!(e.factor_terms().unwrap(), factored);
    /// ```
    pub fn factor_terms(&self) -> Result<Expr, AlgebraError> {
        factored(self, &mut Budget::new("the common factors"))
    }
}

/// `factor_terms` of `e`, every polynomial gcd charged to one budget.
fn factored(e: &Expr, budget: &mut Budget) -> Result<Expr, AlgebraError> {
    Ok(match e.view() {
        View::Num(_) | View::Sym(_) => e.clone(),
        View::Add(terms) => {
            let terms = terms
                .iter()
                .map(|t| factored(t, budget))
                .collect::<Result<Vec<_>, _>>()?;
            let out = common_factor_out(&terms)?;
            match out.view() {
                View::Add(_) => polynomial_factor_out(&out, budget),
                View::Mul(factors) => Expr::mul_all(
                    factors
                        .iter()
                        .map(|f| match f.view() {
                            View::Add(_) => Ok(polynomial_factor_out(f, budget)),
                            _ => Ok(f.clone()),
                        })
                        .collect::<Result<Vec<_>, _>>()?,
                ),
                _ => out,
            }
        }
        View::Mul(factors) => Expr::mul_all(
            factors
                .iter()
                .map(|f| factored(f, budget))
                .collect::<Result<Vec<_>, _>>()?,
        ),
        View::Pow(base, exponent) => factored(base, budget)?.checked_pow(exponent)?,
        View::Func(f, arg) => Expr::func(f, factored(arg, budget)?),
    })
}

/// A sum whose terms hold sums, with the gcd `g` of its terms as polynomials in front,
/// `g · Σ (tᵢ/g)` (`a(b² − c²) + d(b + c) = (b + c)(a b − a c + d)`), when that has fewer
/// operations ([`Expr::operation_count`]); else the sum as it is. Terms with a denominator
/// that is not a number are left as they are, as is a sum past the work bound.
fn polynomial_factor_out(sum: &Expr, budget: &mut Budget) -> Expr {
    let holds_sums = |t: &Expr| t.monomial().iter().any(|f| f.base().terms().len() > 1);
    if !sum.terms().iter().any(holds_sums) {
        return sum.clone();
    }
    match with_polynomial_gcd_out(sum, budget) {
        Ok(Some(candidate)) if candidate.operation_count() < sum.operation_count() => candidate,
        _ => sum.clone(),
    }
}

/// `g · Σ (tᵢ/g)` for the gcd `g` of the terms as polynomials; none when a term has a
/// denominator that is not a number or `g` is a number.
fn with_polynomial_gcd_out(sum: &Expr, budget: &mut Budget) -> Result<Option<Expr>, AlgebraError> {
    let generators = Generators::of(&[sum])?;
    let mut polynomials = Vec::new();
    for t in sum.terms() {
        let f = generators.fraction(t, budget)?;
        if !f.denominator.is_one() {
            return Ok(None);
        }
        polynomials.push(f.numerator);
    }
    let mut gcd = polynomials[0].clone();
    for p in &polynomials[1..] {
        gcd = gcd.gcd(p, budget)?;
        if gcd.is_constant() {
            return Ok(None);
        }
    }
    let mut quotients = Vec::new();
    for p in &polynomials {
        quotients.push(generators.expr(&p.divided_by_factor(&gcd, budget)?));
    }
    let factor = common_factor_out(generators.expr(&gcd).terms())?;
    Ok(Some(Expr::mul_all([factor, Expr::add_all(quotients)])))
}

/// `Σ terms` with their common factor in front (module documentation).
pub(in crate::algebra) fn common_factor_out(terms: &[Expr]) -> Result<Expr, AlgebraError> {
    let sum = Expr::add_all(terms.iter().cloned());
    let terms = sum.terms();
    if terms.len() < 2 {
        return Ok(sum);
    }
    let common =
        Expr::mul_all(std::iter::once(Expr::num(content(terms))).chain(common_powers(terms)));
    if common.is_one() {
        return Ok(sum);
    }
    let inverse = common.checked_pow(&Expr::int(-1))?;
    let rest = Expr::add_all(
        terms
            .iter()
            .map(|t| Expr::mul_all([t.clone(), inverse.clone()])),
    );
    Ok(Expr::mul_all([common, rest]))
}

/// A sum's terms as their numeric content and the primitive sum,
/// `12 m₁ + 12 m₂ = 12 · (m₁ + m₂)`: kept apart, because the canonical product of a number
/// and one sum multiplies the number in again.
pub(in crate::algebra) fn content_and_primitive(terms: &[Expr]) -> (Q, Expr) {
    let c = content(terms);
    let inverse = Expr::num(
        c.recip()
            .expect("a sum's terms are not zero, nor their content"),
    );
    (c, Expr::add_all(terms.iter().map(|t| t * &inverse)))
}

/// The content of the terms' coefficients: gcd of numerators over lcm of denominators,
/// negative when all coefficients are.
fn content(terms: &[Expr]) -> Q {
    let mut numerators = Q::ZERO;
    let mut denominators = Q::ONE;
    for t in terms {
        let c = t.coefficient();
        numerators = numerators.integer_gcd(&c.numer());
        let d = c.denom();
        let g = denominators.integer_gcd(&d);
        denominators = &denominators
            * &d.checked_div(&g)
                .expect("a gcd of denominators is not zero");
    }
    let content = numerators
        .checked_div(&denominators)
        .expect("a denominator is not zero");
    if terms.iter().all(|t| t.coefficient().is_negative()) {
        -&content
    } else {
        content
    }
}

/// The powers of the bases every term holds, each to its common exponent.
fn common_powers(terms: &[Expr]) -> Vec<Expr> {
    terms[0]
        .monomial()
        .iter()
        .filter_map(|factor| {
            let base = factor.base();
            let exponents: Option<Vec<Expr>> = terms
                .iter()
                .map(|t| {
                    t.monomial()
                        .iter()
                        .find(|f| f.base() == base)
                        .map(|f| f.base_and_exponent().1)
                })
                .collect();
            common_exponent(&exponents?).map(|e| power(base, &e))
        })
        .collect()
}

/// The exponent to pull out of powers of one base with these exponents: the one nearest
/// zero of numbers of one sign, or the exponent all share.
fn common_exponent(exponents: &[Expr]) -> Option<Expr> {
    let numbers: Option<Vec<&Q>> = exponents.iter().map(Expr::as_num).collect();
    match numbers {
        Some(ns) if ns.iter().all(|n| !n.is_negative()) => {
            ns.into_iter().min().cloned().map(Expr::num)
        }
        Some(ns) if ns.iter().all(|n| n.is_negative()) => {
            ns.into_iter().max().cloned().map(Expr::num)
        }
        Some(_) => None,
        None => exponents[1..]
            .iter()
            .all(|e| *e == exponents[0])
            .then(|| exponents[0].clone()),
    }
}

fn power(base: &Expr, exponent: &Expr) -> Expr {
    base.checked_pow(exponent)
        .expect("a base held by a term is not zero")
}
