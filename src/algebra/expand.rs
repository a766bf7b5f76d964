//! `expand`: multiply out products of sums and positive integer powers of sums.
//!
//! The result is a sum of monomials with rational coefficients (functions and non-integer
//! powers stay as atoms, with their arguments expanded). It is the canonical form that
//! decides equality: two polynomials, or two expressions whose denominators are monomials,
//! are equal exactly when their expansions are identical. An expansion that would produce
//! more than [`MAX_EXPANDED_TERMS`] terms is refused before any work is done.

use super::error::{AlgebraError, MAX_EXPANDED_TERMS};
use super::expr::{Expr, View};

impl Expr {
    /// The fully expanded form (see the module documentation).
    ///
    /// ```
    /// use kinetics::algebra::Expr;
    /// let (a, b) = (Expr::symbol("a"), Expr::symbol("b"));
    /// let square = (&a + &b).powi(2).expand().unwrap();
    /// assert_eq!(square, a.powi(2) + Expr::int(2) * &a * &b + b.powi(2));
    /// assert!((&a + &b).powi(99_999_999).expand().is_err());
    /// ```
    pub fn expand(&self) -> Result<Expr, AlgebraError> {
        if is_expanded(self) {
            return Ok(self.clone());
        }
        match self.view() {
            View::Num(_) | View::Sym(_) => Ok(self.clone()),
            View::Add(terms) => {
                let mut expanded: Vec<Expr> = Vec::with_capacity(2 * terms.len());
                for t in terms {
                    expanded.extend_from_slice(t.expand()?.terms());
                }
                Ok(Expr::sum_of_terms(expanded))
            }
            View::Mul(factors) => {
                let expanded = factors
                    .iter()
                    .map(Expr::expand)
                    .collect::<Result<Vec<_>, _>>()?;
                let size = expanded
                    .iter()
                    .fold(1usize, |n, f| n.saturating_mul(f.terms().len()));
                check_size("the product", size as f64)?;
                Ok(expanded
                    .iter()
                    .skip(1)
                    .fold(expanded[0].clone(), |acc, f| multiply_out(&acc, f)))
            }
            View::Pow(base, exponent) => {
                let base = base.expand()?;
                let n = exponent.as_num().and_then(|q| q.to_i64());
                match n {
                    Some(n) if n > 1 && base.terms().len() > 1 => {
                        let t = base.terms().len();
                        check_size("the power", multinomial_terms(t, n as u64))?;
                        let mut result = base.clone();
                        for _ in 1..n {
                            result = multiply_out(&result, &base);
                        }
                        Ok(result)
                    }
                    _ => base.checked_pow(exponent),
                }
            }
            View::Func(f, arg) => Ok(Expr::func(f, arg.expand()?)),
        }
    }
}

/// Whether `e` is a sum of monomials in symbols (or a single one), which expands to itself.
fn is_expanded(e: &Expr) -> bool {
    match e.view() {
        View::Add(terms) => terms.iter().all(is_expanded_monomial),
        _ => is_expanded_monomial(e),
    }
}

/// A number, or a product of a number and numeric powers of symbols.
fn is_expanded_monomial(e: &Expr) -> bool {
    match e.view() {
        View::Mul(factors) => factors.iter().all(is_power_of_symbol),
        _ => is_power_of_symbol(e),
    }
}

/// A number, a symbol, or a symbol to a numeric power.
fn is_power_of_symbol(e: &Expr) -> bool {
    match e.view() {
        View::Num(_) | View::Sym(_) => true,
        View::Pow(base, exponent) => base.as_symbol().is_some() && exponent.as_num().is_some(),
        _ => false,
    }
}

/// The product of two expanded expressions, multiplied out term by term.
fn multiply_out(a: &Expr, b: &Expr) -> Expr {
    if a.terms().len() == 1 && b.terms().len() == 1 {
        return a * b;
    }
    let mut products = Vec::with_capacity(a.terms().len() * b.terms().len());
    for x in a.terms() {
        for y in b.terms() {
            products.push(x * y);
        }
    }
    Expr::sum_of_terms(products)
}

/// The number of monomials of degree `n` in `t` variables, C(t + n - 1, n), as a float
/// so that huge cases do not overflow.
fn multinomial_terms(t: usize, n: u64) -> f64 {
    let k = (t as u64 - 1).min(n);
    let top = n + t as u64 - 1;
    (0..k).fold(1.0, |acc, i| acc * (top - i) as f64 / (i + 1) as f64)
}

fn check_size(what: &str, size: f64) -> Result<(), AlgebraError> {
    if size > MAX_EXPANDED_TERMS as f64 {
        return Err(AlgebraError::TooLarge {
            what: format!("expanding {what}"),
            size: if size < 1e15 {
                format!("{size:.0}")
            } else {
                format!("{size:.1e}")
            },
            limit: MAX_EXPANDED_TERMS,
        });
    }
    Ok(())
}
