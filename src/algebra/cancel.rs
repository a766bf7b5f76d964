//! `cancel`: a rational function in lowest terms, and the gcd of two polynomials.
//!
//! The expression is brought over one denominator as a fraction `p/q` of polynomials in
//! its generators (`polynomial/conversion.rs`: symbols, functions, roots), and both parts
//! are divided by `g = gcd(p, q)` (`polynomial/gcd.rs`): then `gcd(p, q) = 1`, the integer
//! contents of `p` and `q` are coprime (the gcd is over the integers) and the leading
//! coefficient of `q` is positive, its leading term the first in the lexicographic order of
//! the generators taken in canonical order. Like SymPy's `cancel`. Bounded like `expand`:
//! past the bounds of `polynomial/budget.rs` an error, never a hang.

use super::error::AlgebraError;
use super::expr::Expr;
use super::polynomial::{Budget, Generators};

impl Expr {
    /// `p/q` in lowest terms: the expression over one denominator, numerator and
    /// denominator expanded and divided by their gcd. Non-polynomial parts (functions,
    /// powers with a non-integer exponent, e.g. `sin(x)`, `(a^2+b^2)^(1/2)`) are opaque
    /// generators; a symbol to a negative integer power is a denominator.
    ///
    /// ```
    /// use kinetics::parse_expression;
    /// let e = parse_expression("", "(a^2-b^2)/(a-b)").unwrap();
    /// assert_eq!(e.cancel().unwrap(), parse_expression("", "a + b").unwrap());
    /// ```
    pub fn cancel(&self) -> Result<Expr, AlgebraError> {
        let (p, q) = self.cancelled_parts()?;
        p.checked_div(&q)
    }

    /// The same as [`Expr::cancel`], as its two parts `(p, q)`: expanded, integer
    /// coefficients, `gcd(p, q) = 1`, the integer contents of `p` and `q` coprime, `q`'s
    /// leading term positive (see the module documentation).
    pub fn cancelled_parts(&self) -> Result<(Expr, Expr), AlgebraError> {
        let mut budget = Budget::new("the cancellation");
        let generators = Generators::of(&[self])?;
        let f = generators
            .fraction(self, &mut budget)?
            .reduced(&mut budget)?;
        Ok((
            generators.expr(&f.numerator),
            generators.expr(&f.denominator),
        ))
    }
}

/// The gcd of two polynomials given as expressions (expanded or not; rational coefficients
/// allowed), as an expanded expression with integer coefficients and a positive leading
/// term; `gcd(0, 0) = 0`. An expression with a denominator that is not a number is refused.
///
/// ```
/// use kinetics::algebra::polynomial_gcd;
/// use kinetics::parse_expression;
/// let a = parse_expression("", "x^2 - y^2").unwrap();
/// let b = parse_expression("", "x^2 + 2*x*y + y^2").unwrap();
/// assert_eq!(polynomial_gcd(&a, &b).unwrap(), parse_expression("", "x + y").unwrap());
/// ```
pub fn polynomial_gcd(a: &Expr, b: &Expr) -> Result<Expr, AlgebraError> {
    let mut budget = Budget::new("the polynomial gcd");
    let generators = Generators::of(&[a, b])?;
    let numerator = |e: &Expr, budget: &mut Budget| {
        let f = generators.fraction(e, budget)?;
        if f.denominator.is_constant() {
            Ok(f.numerator)
        } else {
            Err(AlgebraError::NotAPolynomial(e.to_string()))
        }
    };
    let (p, q) = (numerator(a, &mut budget)?, numerator(b, &mut budget)?);
    Ok(generators.expr(&p.gcd(&q, &mut budget)?))
}
