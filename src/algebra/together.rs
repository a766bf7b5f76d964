//! `together`: one fraction over a common denominator, without multiplying out what needs
//! no multiplying out (SymPy's `together`).
//!
//! Each term of a sum is split into numerator and denominator factors (a number's
//! denominator, powers with negative exponents); the common denominator `D` is the product
//! of every denominator base to the largest power any term has it (the integers' lcm for
//! the numbers), and `Σ nᵢ/dᵢ = (Σ nᵢ·(D/dᵢ)) / D`, the numerator with its common factors
//! pulled out (`common_factor.rs`), so that a factor it shares with `D` cancels in the
//! canonical product: `1/a + 1/b = (a + b)/(a b)`,
//! `m₁d/(m₁+m₂) + m₂d/(m₁+m₂) = d(m₁+m₂)/(m₁+m₂) = d`. Sums inside products, powers and
//! functions are brought together first.

use super::common_factor::common_factor_out;
use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::rational::Q;

impl Expr {
    /// One fraction over a common denominator (module documentation).
    ///
    /// ```
    /// use kinetics::parse_expression;
    /// let e = parse_expression("", "1/(1/a + 1/b)").unwrap();
    /// assert_eq!(e.together().unwrap(), parse_expression("", "a*b/(a + b)").unwrap());
    /// ```
    pub fn together(&self) -> Result<Expr, AlgebraError> {
        Ok(match self.view() {
            View::Num(_) | View::Sym(_) => self.clone(),
            View::Add(terms) => {
                let terms = terms
                    .iter()
                    .map(Expr::together)
                    .collect::<Result<Vec<_>, _>>()?;
                over_common_denominator(&terms)?
            }
            View::Mul(factors) => Expr::mul_all(
                factors
                    .iter()
                    .map(Expr::together)
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Pow(base, exponent) => base.together()?.checked_pow(exponent)?,
            View::Func(f, arg) => Expr::func(f, arg.together()?),
        })
    }

    /// [`Expr::together`] as its numerator and denominator: below the line the number's
    /// denominator and its powers with a negative exponent (as for each term of a sum), above
    /// it the fraction times that denominator, in which they cancel.
    pub fn together_parts(&self) -> Result<(Expr, Expr), AlgebraError> {
        let fraction = self.together()?;
        let below = Expr::mul_all(
            std::iter::once(Expr::num(fraction.coefficient().denom())).chain(
                denominator(&fraction)
                    .iter()
                    .map(|d| power(&d.base, &d.exponent)),
            ),
        );
        let above = &fraction * &below;
        Ok((above, below))
    }
}

/// A denominator factor: `base^exponent` with a positive number `exponent`, or a whole
/// power with a symbolic exponent (exponent 1).
struct DenominatorFactor {
    base: Expr,
    exponent: Q,
}

/// `Σ terms` as one fraction (module documentation).
fn over_common_denominator(terms: &[Expr]) -> Result<Expr, AlgebraError> {
    let sum = Expr::add_all(terms.iter().cloned());
    let denominators: Vec<Vec<DenominatorFactor>> = sum.terms().iter().map(denominator).collect();
    if denominators.iter().all(Vec::is_empty)
        && sum.terms().iter().all(|t| t.coefficient().is_integer())
    {
        return Ok(sum);
    }
    let mut common: Vec<DenominatorFactor> = Vec::new();
    for d in denominators.iter().flatten() {
        match common.iter_mut().find(|c| c.base == d.base) {
            Some(c) if c.exponent < d.exponent => c.exponent = d.exponent.clone(),
            Some(_) => {}
            None => common.push(DenominatorFactor {
                base: d.base.clone(),
                exponent: d.exponent.clone(),
            }),
        }
    }
    let integers = sum.terms().iter().fold(Q::ONE, |lcm, t| {
        let d = t.coefficient().denom();
        let g = lcm.integer_gcd(&d);
        &lcm * &d
            .checked_div(&g)
            .expect("a gcd of denominators is not zero")
    });
    // The factors of the denominator stay apart: a number times one sum would be
    // distributed, and the sum would no longer cancel with the terms' powers of it.
    let factors: Vec<Expr> = std::iter::once(Expr::num(integers))
        .chain(common.iter().map(|c| power(&c.base, &c.exponent)))
        .collect();
    let times = |x: &Expr, exponent: &Q| {
        Expr::mul_all(std::iter::once(x.clone()).chain(factors.iter().map(|f| {
            f.checked_pow(&Expr::num(exponent.clone()))
                .expect("a denominator factor is not zero")
        })))
    };
    let numerator_terms: Vec<Expr> = sum.terms().iter().map(|t| times(t, &Q::ONE)).collect();
    let numerator = common_factor_out(&numerator_terms)?;
    Ok(times(&numerator, &Q::MINUS_ONE))
}

/// The denominator factors of a term: its powers with a negative exponent.
fn denominator(term: &Expr) -> Vec<DenominatorFactor> {
    term.monomial()
        .iter()
        .filter_map(|f| {
            let (base, exponent) = f.base_and_exponent();
            match exponent.as_num() {
                Some(e) if e.is_negative() => Some(DenominatorFactor {
                    base: base.clone(),
                    exponent: -e,
                }),
                Some(_) => None,
                None if exponent.coefficient().is_negative() => Some(DenominatorFactor {
                    base: base.checked_pow(&-&exponent).ok()?,
                    exponent: Q::ONE,
                }),
                None => None,
            }
        })
        .collect()
}

fn power(base: &Expr, exponent: &Q) -> Expr {
    base.checked_pow(&Expr::num(exponent.clone()))
        .expect("a denominator base is not zero")
}
