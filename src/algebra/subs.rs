//! `subs`: replace symbols by expressions and rebuild the canonical form.

use super::error::AlgebraError;
use super::expr::{Expr, View};
use super::symbol::Symbol;

impl Expr {
    /// Replaces each symbol for which `value` answers `Some` by that expression.
    /// Fails only when the replacement divides by zero (`1/x` with `x = 0`).
    ///
    /// ```
    /// use kinetics::algebra::{Expr, Symbol};
    /// let x = Symbol::new("x");
    /// let e = Expr::symbol("x").powi(2) + Expr::symbol("y");
    /// let two = Expr::int(2);
    /// let r = e.subs(&|s| (s == x).then(|| two.clone())).unwrap();
    /// assert_eq!(r, Expr::int(4) + Expr::symbol("y"));
    /// ```
    pub fn subs(&self, value: &dyn Fn(Symbol) -> Option<Expr>) -> Result<Expr, AlgebraError> {
        Ok(match self.view() {
            View::Num(_) => self.clone(),
            View::Sym(s) => value(s).unwrap_or_else(|| self.clone()),
            View::Add(terms) => Expr::add_all(
                terms
                    .iter()
                    .map(|t| t.subs(value))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Mul(factors) => Expr::mul_all(
                factors
                    .iter()
                    .map(|f| f.subs(value))
                    .collect::<Result<Vec<_>, _>>()?,
            ),
            View::Pow(b, e) => b.subs(value)?.checked_pow(&e.subs(value)?)?,
            View::Func(f, a) => Expr::func(f, a.subs(value)?),
        })
    }
}
